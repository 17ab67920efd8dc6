//! Messages in and out over stdin and stdout, framed as the protocol says
//! (`Content-Length: n`, a blank line, n bytes of JSON). lsp-server's own
//! stdio transport allocates the length a header announces before a byte of
//! it has come, so one bad header aborts the process; here a message's
//! bytes are read as they arrive, and a header the protocol does not allow
//! ends the session with an error instead.

use std::io::{self, BufRead, Read, Write};
use std::thread::JoinHandle;

use crossbeam_channel::{bounded, Receiver, Sender};
use lsp_server::{Connection, Message};

/// A header line longer than this is no header.
const HEADER_LINE: u64 = 1024;

/// The threads that read stdin and write stdout.
pub struct Transport {
    reader: JoinHandle<io::Result<()>>,
    writer: JoinHandle<io::Result<()>>,
}

pub fn stdio() -> (Connection, Transport) {
    let (to_server, from_client) = bounded::<Message>(0);
    let (to_client, from_server) = bounded::<Message>(0);
    let reader = std::thread::spawn(move || read_all(&mut io::stdin().lock(), &to_server));
    let writer = std::thread::spawn(move || write_all(&mut io::stdout().lock(), &from_server));
    let connection = Connection {
        sender: to_client,
        receiver: from_client,
    };
    (connection, Transport { reader, writer })
}

impl Transport {
    /// Waits for the writer to write what it was given (the connection must
    /// be dropped first), and for the reader if it has stopped: a reader
    /// still waiting for a client that keeps its end open is not waited
    /// for. The first error of either, if any.
    pub fn join(self) -> io::Result<()> {
        let joined = |thread: JoinHandle<io::Result<()>>| {
            thread
                .join()
                .unwrap_or_else(|_| Err(io::Error::other("a transport thread failed")))
        };
        let written = joined(self.writer);
        let read = match self.reader.is_finished() {
            true => joined(self.reader),
            false => Ok(()),
        };
        read.and(written)
    }
}

fn read_all(input: &mut impl BufRead, to_server: &Sender<Message>) -> io::Result<()> {
    while let Some(message) = read(input)? {
        let exit = matches!(&message, Message::Notification(n) if n.method == "exit");
        if to_server.send(message).is_err() || exit {
            break;
        }
    }
    Ok(())
}

fn write_all(output: &mut impl Write, from_server: &Receiver<Message>) -> io::Result<()> {
    from_server
        .iter()
        .try_for_each(|message| message.write(output))
}

fn invalid(what: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, what)
}

/// The next message; `None` at the end of the input.
pub fn read(input: &mut impl BufRead) -> io::Result<Option<Message>> {
    let mut length = None;
    loop {
        let mut line = Vec::new();
        input
            .by_ref()
            .take(HEADER_LINE)
            .read_until(b'\n', &mut line)?;
        if line.is_empty() && length.is_none() {
            return Ok(None);
        }
        let Some(header) = line.strip_suffix(b"\r\n") else {
            return Err(invalid(format!(
                "a header line must end with CRLF: {:?}",
                String::from_utf8_lossy(&line)
            )));
        };
        if header.is_empty() {
            break;
        }
        let header = String::from_utf8_lossy(header);
        let (name, value) = header
            .split_once(": ")
            .ok_or_else(|| invalid(format!("not a header: {header:?}")))?;
        if name.eq_ignore_ascii_case("Content-Length") {
            let value = value.trim().parse::<u64>();
            length = Some(value.map_err(|e| invalid(format!("Content-Length: {e}")))?);
        }
    }
    let length = length.ok_or_else(|| invalid("a message without Content-Length".to_string()))?;
    let mut body = Vec::new();
    input.by_ref().take(length).read_to_end(&mut body)?;
    if body.len() as u64 != length {
        return Err(invalid(format!(
            "the input ended {} bytes into a message of {length}",
            body.len()
        )));
    }
    let parsed = serde_json::from_slice(&body).or_else(|error| {
        // A lone UTF-16 surrogate (`\ud800`) is valid JSON text that no
        // Rust string holds: an editor sends one when a buffer holds half
        // a pair. It becomes U+FFFD, as undecodable bytes do elsewhere.
        match replace_lone_surrogates(&body) {
            Some(mended) => serde_json::from_slice(&mended),
            None => Err(error),
        }
    });
    parsed
        .map(Some)
        .map_err(|e| invalid(format!("a message that is not JSON-RPC: {e}")))
}

/// `body` with every `\uXXXX` escape of a surrogate that is not half of a
/// pair written `\ufffd`; `None` when there is none.
fn replace_lone_surrogates(body: &[u8]) -> Option<Vec<u8>> {
    let escape_at = |at: usize| -> Option<u16> {
        let hex = body.get(at..at + 6)?;
        if hex[0] != b'\\' || hex[1] != b'u' {
            return None;
        }
        u16::from_str_radix(std::str::from_utf8(&hex[2..]).ok()?, 16).ok()
    };
    let mut out = Vec::with_capacity(body.len());
    let mut replaced = false;
    let mut at = 0;
    while at < body.len() {
        if body[at] != b'\\' {
            out.push(body[at]);
            at += 1;
            continue;
        }
        match escape_at(at) {
            Some(0xD800..=0xDBFF)
                if escape_at(at + 6).is_some_and(|low| (0xDC00..=0xDFFF).contains(&low)) =>
            {
                out.extend_from_slice(&body[at..at + 12]);
                at += 12;
            }
            Some(0xD800..=0xDFFF) => {
                out.extend_from_slice(b"\\ufffd");
                replaced = true;
                at += 6;
            }
            // Any other escape, `\\` among them, is copied whole.
            _ => {
                out.extend_from_slice(&body[at..(at + 2).min(body.len())]);
                at += 2;
            }
        }
    }
    replaced.then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_text(text: &[u8]) -> io::Result<Option<Message>> {
        read(&mut io::Cursor::new(text))
    }

    #[test]
    fn a_lone_surrogate_becomes_the_replacement_character() {
        let body = br#"{"jsonrpc":"2.0","method":"m","params":{"text":"a\ud800b \ud83d\ude00 \\ud800 \udc00"}}"#;
        let framed = [
            format!("Content-Length: {}\r\n\r\n", body.len()).as_bytes(),
            body,
        ]
        .concat();
        let message = read_text(&framed).expect("read").expect("a message");
        let Message::Notification(n) = message else {
            panic!("a notification");
        };
        assert_eq!(n.params["text"], "a\u{fffd}b \u{1f600} \\ud800 \u{fffd}");
    }

    #[test]
    fn a_message_is_read_as_framed() {
        let body = br#"{"jsonrpc":"2.0","method":"exit"}"#;
        let framed = [
            format!("Content-Length: {}\r\n\r\n", body.len()).as_bytes(),
            body,
        ]
        .concat();
        let message = read_text(&framed).expect("read").expect("a message");
        assert!(matches!(message, Message::Notification(n) if n.method == "exit"));
        assert!(read_text(b"").expect("read").is_none());
    }

    #[test]
    fn a_bad_frame_is_an_error_not_an_abort() {
        for framed in [
            &b"Content-Length: 99999999999999999\r\n\r\n{}"[..],
            b"Content-Length: 18446744073709551616\r\n\r\n{}",
            b"Content-Length: 2\n\n{}",
            b"Content-Type: x\r\n\r\n{}",
            b"Content-Length: 10\r\n\r\n{ not json",
            b"Content-Length: 2\r\n\r\n[]",
        ] {
            assert!(
                read_text(framed).is_err(),
                "{:?}",
                String::from_utf8_lossy(framed)
            );
        }
        let long_header = [&[b'x'; 5000][..], b"\r\n\r\n"].concat();
        assert!(read_text(&long_header).is_err());
    }
}
