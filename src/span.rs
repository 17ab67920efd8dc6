//! Byte ranges into a source file, and their conversion to line and column.
//!
//! Spans are byte offsets so that every node of the tree can point back at the
//! exact bytes it came from; nothing here knows about the NC language.

use std::cell::OnceCell;
use std::ops::Range;

/// A half-open byte range `start..end` into the source.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default, PartialOrd, Ord)]
pub struct Span {
    pub start: usize,
    pub end: usize,
}

impl Span {
    pub const fn new(start: usize, end: usize) -> Self {
        Self { start, end }
    }

    pub const fn len(self) -> usize {
        self.end - self.start
    }

    pub const fn is_empty(self) -> bool {
        self.start == self.end
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }

    pub fn range(self) -> Range<usize> {
        self.start..self.end
    }

    /// The bytes of this span in `source`.
    pub fn of(self, source: &[u8]) -> &[u8] {
        &source[self.range()]
    }
}

impl std::fmt::Debug for Span {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

/// A 1-based position: `row` is the line, `column` counts characters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Position {
    pub row: usize,
    pub column: usize,
}

/// Maps byte offsets to rows and columns.
///
/// Columns count characters: UTF-8 scalar values when the whole file is valid
/// UTF-8, otherwise bytes (the file is read as Latin-1 / Windows-1252, where one
/// byte is one character). Tabs count as one column.
pub struct LineIndex<'a> {
    source: &'a [u8],
    /// Where lines 0, STRIDE, 2 * STRIDE, ... start: a position is found from
    /// the nearest one by reading at most STRIDE lines. Every line start
    /// would cost 8 bytes a line, 22 MB for a 100 MB CAM program. Read on
    /// the first question: a file without findings never needs them.
    checkpoints: OnceCell<Vec<usize>>,
    utf8: OnceCell<bool>,
}

const STRIDE: usize = 32;

impl<'a> LineIndex<'a> {
    pub fn new(source: &'a [u8]) -> Self {
        Self {
            source,
            checkpoints: OnceCell::new(),
            utf8: OnceCell::new(),
        }
    }

    pub fn is_utf8(&self) -> bool {
        *self
            .utf8
            .get_or_init(|| std::str::from_utf8(self.source).is_ok())
    }

    fn checkpoints(&self) -> &[usize] {
        self.checkpoints.get_or_init(|| {
            let mut checkpoints = vec![0];
            let mut row = 0;
            // One search over the file: a search per line costs more to
            // start than to run on a 50-byte line.
            for end in memchr::memchr2_iter(b'\n', b'\r', self.source) {
                if self.source[end] == b'\r' && self.source.get(end + 1) == Some(&b'\n') {
                    continue; // the LF that follows ends this line
                }
                row += 1;
                if row % STRIDE == 0 {
                    checkpoints.push(end + 1);
                }
            }
            checkpoints
        })
    }

    pub fn position(&self, offset: usize) -> Position {
        let offset = offset.min(self.source.len());
        let checkpoints = self.checkpoints();
        let checkpoint = checkpoints.partition_point(|&start| start <= offset) - 1;
        let mut row = checkpoint * STRIDE;
        let mut line_start = checkpoints[checkpoint];
        while let Some(next) = next_line_start(self.source, line_start).filter(|&n| n <= offset) {
            row += 1;
            line_start = next;
        }
        let before = &self.source[line_start..offset];
        let column = if self.is_utf8() {
            before.iter().filter(|&&b| (b & 0xC0) != 0x80).count()
        } else {
            before.len()
        };
        Position {
            row: row + 1,
            column: column + 1,
        }
    }
}

/// Where the line after the one containing `at` starts. The same line ends
/// as `syntax::lines` (LF, CRLF, lone CR), written again because `span` sits
/// below `syntax` and may not depend on it.
fn next_line_start(source: &[u8], at: usize) -> Option<usize> {
    let end = at + memchr::memchr2(b'\n', b'\r', source.get(at..)?)?;
    Some(
        if source[end] == b'\r' && source.get(end + 1) == Some(&b'\n') {
            end + 2
        } else {
            end + 1
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_follow_every_line_ending() {
        let index = LineIndex::new(b"a\nbc\r\nd\re");
        assert_eq!(index.position(0), Position { row: 1, column: 1 });
        assert_eq!(index.position(3), Position { row: 2, column: 2 });
        assert_eq!(index.position(6), Position { row: 3, column: 1 });
        assert_eq!(index.position(8), Position { row: 4, column: 1 });
    }

    proptest::proptest! {
        /// Found from the checkpoints, a position is the one counting every
        /// line from the start gives.
        #[test]
        fn positions_agree_with_counting_every_line(
            text in "[a\r\n]{0,400}",
            at in 0usize..400,
        ) {
            let source = text.as_bytes();
            let offset = at.min(source.len());
            let mut starts = vec![0];
            let mut i = 0;
            while i < source.len() {
                if source[i] == b'\r' && source.get(i + 1) == Some(&b'\n') {
                    i += 1;
                }
                if matches!(source[i], b'\n' | b'\r') {
                    starts.push(i + 1);
                }
                i += 1;
            }
            let row = starts.iter().filter(|&&s| s <= offset).count();
            let column = offset - starts[row - 1] + 1;
            proptest::prop_assert_eq!(LineIndex::new(source).position(offset), Position { row, column });
        }
    }

    #[test]
    fn columns_count_characters_in_utf8_and_bytes_in_latin1() {
        let utf8 = LineIndex::new("ä=1".as_bytes());
        assert_eq!(utf8.position(2).column, 2);
        let latin1 = LineIndex::new(b"\xe4\xe4=1");
        assert_eq!(latin1.position(2).column, 3);
    }
}
