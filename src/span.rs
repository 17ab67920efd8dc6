//! Byte ranges into a source file, and their conversion to line and column.
//!
//! Spans are byte offsets so that every node of the tree can point back at the
//! exact bytes it came from; nothing here knows about the NC language.

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
    line_starts: Vec<usize>,
    utf8: bool,
}

impl<'a> LineIndex<'a> {
    pub fn new(source: &'a [u8]) -> Self {
        // The same line ends as `syntax::lines` (LF, CRLF, lone CR), written
        // again because `span` sits below `syntax` and may not depend on it.
        let mut line_starts = vec![0];
        let mut at = 0;
        while let Some(found) = memchr::memchr2(b'\n', b'\r', &source[at..]) {
            let end = at + found;
            let next = if source[end] == b'\r' && source.get(end + 1) == Some(&b'\n') {
                end + 2
            } else {
                end + 1
            };
            line_starts.push(next);
            at = next;
        }
        Self {
            source,
            line_starts,
            utf8: std::str::from_utf8(source).is_ok(),
        }
    }

    pub fn is_utf8(&self) -> bool {
        self.utf8
    }

    pub fn position(&self, offset: usize) -> Position {
        let offset = offset.min(self.source.len());
        let row = self.line_starts.partition_point(|&start| start <= offset) - 1;
        let before = &self.source[self.line_starts[row]..offset];
        let column = if self.utf8 {
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

    #[test]
    fn columns_count_characters_in_utf8_and_bytes_in_latin1() {
        let utf8 = LineIndex::new("ä=1".as_bytes());
        assert_eq!(utf8.position(2).column, 2);
        let latin1 = LineIndex::new(b"\xe4\xe4=1");
        assert_eq!(latin1.position(2).column, 3);
    }
}
