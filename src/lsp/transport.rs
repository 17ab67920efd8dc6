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
    serde_json::from_slice(&body)
        .map(Some)
        .map_err(|e| invalid(format!("a message that is not JSON-RPC: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_text(text: &[u8]) -> io::Result<Option<Message>> {
        read(&mut io::Cursor::new(text))
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
