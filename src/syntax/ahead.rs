//! The lines of a program read on a thread of their own, ahead of the
//! analysis that takes them: scanning a line and parsing it into its tree
//! need nothing of the lines before it but the parser's little state (see
//! [`LineParser`]), while the analysis of a line (what it defines, the
//! rules) needs all of them. On two cores the two halves run side by side.
//!
//! The trees made there are dropped there too ([`ReadLines::spent`]): a
//! tree freed by another thread than the one that made it takes the lock of
//! the allocator's arena it came from, which the thread making the next trees
//! holds as often, and the two threads took turns at that lock.
//!
//! Until a program defines a macro: a `DEFINE` changes how the next lines
//! read, which only the analysis knows. The thread stops after the line that
//! writes one and hands its parser over, and the lines after it are read by
//! the analysis itself, as without this module.

use std::sync::mpsc::{channel, sync_channel, Receiver, Sender, SyncSender};
use std::thread::{Scope, ScopedJoinHandle};

use super::plain::{scanned_lines_from, Plain, PlainScanner, Scanned, ScannedLines};
use super::tree::{Line, LineKind, StatementKind};
use super::LineParser;
use crate::diagnostic::Diagnostic;

/// A line as the analysis takes it.
// Not boxed: most lines read ahead are parsed ones (see `pays`), and a box
// would be made on one thread and freed on the other.
#[allow(clippy::large_enum_variant)]
pub enum Read {
    /// A plain line, scanned, not parsed.
    Plain(Plain),
    /// A line the analysis parses itself (read here, not ahead).
    Other(super::lines::RawLine),
    /// A line parsed ahead: its tree and its syntax error.
    Parsed(Line, Option<Diagnostic>),
    /// The lines read ahead end here: the next ones are read by the
    /// analysis, with this parser (the state the lines read so far left).
    Handover(LineParser),
}

/// Lines read ahead in a batch: a channel message a line would cost more
/// than the line's parse.
const BATCH: usize = 256;

/// Bytes of parsed lines in a batch, at most (give or take a line): a tree
/// is some 50 bytes a byte of its line, and a batch of 256 long lines
/// would otherwise hold hundreds of megabytes.
const BATCH_BYTES: usize = 16 * 1024;

/// Batches read ahead and not yet taken, at most: enough to cover the
/// analysis's slower lines, few enough to hold little memory.
const BATCHES_AHEAD: usize = 8;

/// The size from which a program is read ahead ([`pays`]): below it, the
/// thread costs more than it gives back.
pub const AHEAD_FROM: usize = 256 * 1024;

/// Whether reading `source` ahead pays: it is large, and enough of its
/// lines are parsed (read from a few samples across it). The lines of a CAM
/// program are nearly all plain: their scan is quick, and moving each to the
/// other thread would cost more than it saves (1.8 times the time of 10 MB
/// read here, where hand-written cycles take 0.68 times: whole-process
/// timings of `check` on the throughput bench's inputs, the two builds in
/// alternation).
pub fn pays(source: &[u8]) -> bool {
    const SAMPLES: usize = 4;
    const LINES: usize = 256;
    if source.len() < AHEAD_FROM || !has_a_core_to_spare() {
        return false;
    }
    let (mut parsed, mut lines) = (0, 0);
    for sample in 0..SAMPLES {
        let from = source.len() / SAMPLES * sample;
        // From the next line's start.
        let Some(start) = memchr::memchr2(b'\n', b'\r', &source[from..]).map(|n| from + n + 1)
        else {
            continue;
        };
        for line in scanned_lines_from(source, start, PlainScanner::Scan).take(LINES) {
            lines += 1;
            parsed += usize::from(matches!(line, Scanned::Other(_)));
        }
    }
    parsed * 4 >= lines && lines > 0
}

/// Whether this machine has a second core for the lines read ahead; asked
/// once (it reads the scheduler's and the cgroup's limits).
fn has_a_core_to_spare() -> bool {
    static SPARE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *SPARE.get_or_init(|| std::thread::available_parallelism().is_ok_and(|n| n.get() > 1))
}

/// The lines of `source`, in order, as [`Read`]s.
pub struct ReadLines<'src, 'scope> {
    source: &'src [u8],
    scan: PlainScanner,
    from: From<'src, 'scope>,
}

enum From<'src, 'scope> {
    /// Read here, line by line.
    Here(ScannedLines<'src>),
    /// Read ahead: the batch being taken, and the channel of the next ones.
    Ahead {
        batch: std::vec::IntoIter<Read>,
        next: Receiver<Message>,
        /// The trees taken and done with, sent back to be dropped.
        spent: Vec<Line>,
        back: Sender<Vec<Line>>,
        /// The thread, joined once its channel closes: a panic there is
        /// raised again here, with its message.
        thread: Option<ScopedJoinHandle<'scope, ()>>,
    },
}

/// What the thread sends: lines, then, after a line that defines a macro,
/// its parser and where the next line starts.
enum Message {
    Lines(Vec<Read>),
    Handover { parser: LineParser, at: usize },
}

impl<'src, 'scope> ReadLines<'src, 'scope> {
    /// Every line read here, by the analysis.
    pub fn here(source: &'src [u8], scan: PlainScanner) -> Self {
        Self {
            source,
            scan,
            from: From::Here(scanned_lines_from(source, 0, scan)),
        }
    }

    /// The lines read ahead on a thread of `scope` (here, where no thread
    /// can be made). The thread ends when the lines do, or soon after this
    /// is dropped (an analysis stopped).
    pub fn ahead(scope: &'scope Scope<'scope, '_>, source: &'src [u8], scan: PlainScanner) -> Self
    where
        'src: 'scope,
    {
        let (sender, next) = sync_channel(BATCHES_AHEAD);
        let (back, spent) = channel();
        let thread = std::thread::Builder::new()
            .name("sinuprep-lines-ahead".into())
            .spawn_scoped(scope, move || read_ahead(source, scan, &sender, &spent));
        let Ok(thread) = thread else {
            return Self::here(source, scan);
        };
        Self {
            source,
            scan,
            from: From::Ahead {
                batch: Vec::new().into_iter(),
                next,
                spent: Vec::with_capacity(BATCH),
                back,
                thread: Some(thread),
            },
        }
    }

    /// Takes a tree the analysis is done with: dropped on the thread that
    /// made it.
    pub fn spent(&mut self, line: Line) {
        if let From::Ahead { spent, back, .. } = &mut self.from {
            spent.push(line);
            if spent.len() == BATCH {
                // The thread gone (the lines all read), the trees are dropped here.
                let _ = back.send(std::mem::replace(spent, Vec::with_capacity(BATCH)));
            }
        }
    }
}

impl Iterator for ReadLines<'_, '_> {
    type Item = Read;

    // Inlined into the line pass, so that a CAM program's millions of
    // plain lines are built where they are read, not copied there.
    #[inline(always)]
    fn next(&mut self) -> Option<Read> {
        match &mut self.from {
            From::Here(lines) => lines.next().map(|line| match line {
                Scanned::Plain(plain) => Read::Plain(plain),
                Scanned::Other(raw) => Read::Other(raw),
            }),
            From::Ahead {
                batch,
                next,
                thread,
                ..
            } => loop {
                if let Some(read) = batch.next() {
                    return Some(read);
                }
                let Ok(message) = next.recv() else {
                    // A closed channel: every line was sent, or the thread
                    // panicked.
                    if let Some(Err(panic)) = thread.take().map(ScopedJoinHandle::join) {
                        std::panic::resume_unwind(panic);
                    }
                    return None;
                };
                match message {
                    Message::Lines(lines) => *batch = lines.into_iter(),
                    Message::Handover { parser, at } => {
                        self.from = From::Here(scanned_lines_from(self.source, at, self.scan));
                        return Some(Read::Handover(parser));
                    }
                }
            },
        }
    }
}

/// The thread's work: every line scanned, those not plain parsed, sent in
/// batches; after a line that defines a macro, the parser, and no more.
fn read_ahead(
    source: &[u8],
    scan: PlainScanner,
    sender: &SyncSender<Message>,
    spent: &Receiver<Vec<Line>>,
) {
    let mut parser = LineParser::default();
    let mut batch = Vec::with_capacity(BATCH);
    let mut bytes = 0;
    for line in scanned_lines_from(source, 0, scan) {
        match line {
            Scanned::Plain(plain) => {
                parser.pass_plain_line();
                batch.push(Read::Plain(plain));
            }
            Scanned::Other(raw) => {
                bytes += raw.content.len();
                let (line, error) = parser.parse_line(source, raw);
                let defines = defines_a_macro(&line);
                batch.push(Read::Parsed(line, error));
                if defines {
                    let at = raw.full().end;
                    // The receiver gone, the analysis was stopped: nothing to do.
                    if sender.send(Message::Lines(batch)).is_ok() {
                        let _ = sender.send(Message::Handover { parser, at });
                    }
                    return;
                }
            }
        }
        if batch.len() == BATCH || bytes >= BATCH_BYTES {
            bytes = 0;
            spent.try_iter().for_each(drop);
            let full = std::mem::replace(&mut batch, Vec::with_capacity(BATCH));
            if sender.send(Message::Lines(full)).is_err() {
                return;
            }
        }
    }
    if !batch.is_empty() {
        let _ = sender.send(Message::Lines(batch));
    }
}

/// Whether the line writes a `DEFINE`: the lines after it may read
/// otherwise (whether the name is one a macro may take is the model's
/// business; the lines are read here either way).
fn defines_a_macro(line: &Line) -> bool {
    match &line.kind {
        LineKind::Block(block) => block
            .statements
            .iter()
            .any(|statement| matches!(statement.kind, StatementKind::Define { .. })),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What each line was read as: `P` plain, `T` parsed ahead, `O` left
    /// to the analysis, `H` the hand-over; with the lines' starts.
    fn read(source: &[u8]) -> (String, Vec<usize>) {
        std::thread::scope(|scope| {
            let mut kinds = String::new();
            let mut starts = Vec::new();
            for read in ReadLines::ahead(scope, source, PlainScanner::Scan) {
                let start = match &read {
                    Read::Plain(plain) => Some(plain.raw.content.start),
                    Read::Parsed(line, _) => Some(line.raw.content.start),
                    Read::Other(raw) => Some(raw.content.start),
                    Read::Handover(_) => None,
                };
                kinds.push(match read {
                    Read::Plain(_) => 'P',
                    Read::Parsed(..) => 'T',
                    Read::Other(_) => 'O',
                    Read::Handover(_) => 'H',
                });
                starts.extend(start);
            }
            (kinds, starts)
        })
    }

    #[test]
    fn every_line_comes_once_in_order_over_many_batches() {
        let source = "G1 X1\nR1=2\n".repeat(BATCH * 3 + 7);
        let (kinds, starts) = read(source.as_bytes());
        assert_eq!(kinds, "PT".repeat(BATCH * 3 + 7));
        let expected: Vec<usize> = (0..(BATCH * 3 + 7) * 2)
            .map(|line| line / 2 * 11 + line % 2 * 6)
            .collect();
        assert_eq!(starts, expected);
    }

    #[test]
    fn after_a_define_the_lines_are_left_to_the_analysis() {
        let before = "G1 X1\nR1=2\n".repeat(BATCH);
        let after = "G1 X1\nR1=_A\n".repeat(3);
        let source = format!("{before}DEFINE _A AS 1\n{after}M30");
        let (kinds, starts) = read(source.as_bytes());
        assert_eq!(
            kinds,
            format!("{}TH{}P", "PT".repeat(BATCH), "PO".repeat(3))
        );
        assert_eq!(starts.len(), BATCH * 2 + 1 + 6 + 1);
        assert_eq!(
            starts[BATCH * 2 + 1],
            before.len() + "DEFINE _A AS 1\n".len()
        );
        assert!(starts.windows(2).all(|pair| pair[0] < pair[1]));
    }

    #[test]
    fn lines_longer_than_a_batch_holds_all_come_in_order() {
        let line = format!("R1={}\n", "1+".repeat(2_000) + "1");
        let source = line.repeat(40);
        let (kinds, starts) = read(source.as_bytes());
        assert_eq!(kinds, "T".repeat(40));
        let expected: Vec<usize> = (0..40).map(|n| n * line.len()).collect();
        assert_eq!(starts, expected);
    }

    #[test]
    fn large_programs_of_parsed_lines_pay_and_cam_programs_do_not() {
        let hand_written = "IF R1>2\nR2=R1*2\nENDIF\nG1 X1\n".repeat(20_000);
        let cam = "N10 G1 X1.234 Y5.678 Z-1\n".repeat(20_000);
        let spare = has_a_core_to_spare();
        assert_eq!(pays(hand_written.as_bytes()), spare);
        assert!(!pays(cam.as_bytes()));
        assert!(!pays(&hand_written.as_bytes()[..AHEAD_FROM - 1]));
        // Lines that end in a carriage return alone are sampled as well.
        assert_eq!(pays(hand_written.replace('\n', "\r").as_bytes()), spare);
    }
}
