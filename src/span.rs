//! Byte ranges into a source file, and their conversion to line and column.
//!
//! Spans are byte offsets so that every node of the tree can point back at the
//! exact bytes it came from; nothing here knows about the NC language.

use std::cell::{OnceCell, RefCell};
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

/// A 1-based position: `row` is the line, `column` counts characters (or the
/// unit [`LineIndex::position_in`] is asked for).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Position {
    pub row: usize,
    pub column: usize,
}

/// What a column counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColumnUnit {
    /// Characters (Unicode scalar values): what messages about settings
    /// files count.
    CodePoints,
    /// UTF-16 code units: what the Language Server Protocol counts by
    /// default (a character beyond the Basic Multilingual Plane is two),
    /// and every report format (`cli::render::COLUMNS`).
    Utf16,
    Bytes,
}

/// Maps byte offsets to rows and columns, and back.
///
/// Columns count characters: UTF-8 scalar values when the whole file is valid
/// UTF-8, otherwise bytes. A file that is not UTF-8 is in a single-byte code
/// page (Latin-1, Windows-1252, Windows-1251 on Russian controls), where
/// every byte is one character of the Basic Multilingual Plane: one code
/// point and one UTF-16 unit, whichever the page. Tabs count as one column.
pub struct LineIndex<'a> {
    source: &'a [u8],
    /// The line ends before each `BLOCK`-byte block: a row is found by
    /// counting the line ends of at most one block. Counted up to the block
    /// asked about, when asked (a file without findings never asks, and a
    /// large file is read in step with its report) with `memchr`'s vectorised
    /// count, not a search per line end.
    rows_before_block: RefCell<Vec<usize>>,
    utf8: OnceCell<bool>,
}

const BLOCK: usize = 4096;

impl<'a> LineIndex<'a> {
    pub fn new(source: &'a [u8]) -> Self {
        Self {
            source,
            rows_before_block: RefCell::new(vec![0]),
            utf8: OnceCell::new(),
        }
    }

    pub fn is_utf8(&self) -> bool {
        *self.utf8.get_or_init(|| is_utf8(self.source))
    }

    /// The line ends before `block`.
    fn rows_before(&self, block: usize) -> usize {
        let mut rows = self.rows_before_block.borrow_mut();
        while rows.len() <= block {
            let start = (rows.len() - 1) * BLOCK;
            let end = (start + BLOCK).min(self.source.len());
            let row = rows[rows.len() - 1] + line_ends(self.source, start..end);
            rows.push(row);
        }
        rows[block]
    }

    /// The position of `offset`, its column in characters.
    pub fn position(&self, offset: usize) -> Position {
        self.position_in(offset, ColumnUnit::CodePoints)
    }

    /// The position of `offset`, its column in `unit`.
    pub fn position_in(&self, offset: usize, unit: ColumnUnit) -> Position {
        let offset = offset.min(self.source.len());
        let block = offset / BLOCK;
        let row = self.rows_before(block) + line_ends(self.source, block * BLOCK..offset);
        let before = &self.source[line_start(self.source, offset)..offset];
        Position {
            row: row + 1,
            column: self.width(before, unit) + 1,
        }
    }

    /// The columns `bytes` (a part of one line) take in `unit`.
    fn width(&self, bytes: &[u8], unit: ColumnUnit) -> usize {
        // Only a line with other bytes than ASCII asks how the file is
        // encoded: the question reads the whole file.
        if unit == ColumnUnit::Bytes || bytes.is_ascii() {
            return bytes.len();
        }
        width(bytes, unit, self.is_utf8())
    }
}

/// Whether `bytes` are UTF-8.
pub(crate) fn is_utf8(bytes: &[u8]) -> bool {
    std::str::from_utf8(bytes).is_ok()
}

/// The columns `bytes` (a part of one line of a file that is UTF-8 or not)
/// take in `unit`. In a file that is not UTF-8 every byte is a character of
/// the Basic Multilingual Plane (see [`LineIndex`]).
pub(crate) fn width(bytes: &[u8], unit: ColumnUnit, utf8: bool) -> usize {
    if unit == ColumnUnit::Bytes || !utf8 {
        return bytes.len();
    }
    let starts = bytes.iter().filter(|&&b| (b & 0xC0) != 0x80).count();
    match unit {
        ColumnUnit::Utf16 => starts + bytes.iter().filter(|&&b| b >= 0xF0).count(),
        _ => starts,
    }
}

/// The length in bytes of the character whose first byte is `lead`.
pub(crate) fn char_len(lead: u8, utf8: bool) -> usize {
    if lead < 0x80 || !utf8 {
        return 1;
    }
    match lead {
        0xF0.. => 4,
        0xE0.. => 3,
        _ => 2,
    }
}

// What ends a line, for every part of the program: LF, CRLF and a lone CR
// (files from PCs and old controls). `syntax::lines` splits files by the
// same rule; the functions below find a line's bounds around an offset.

/// The line ends (LF, CRLF, lone CR; a CRLF counted at its LF) within `range`.
pub(crate) fn line_ends(source: &[u8], range: Range<usize>) -> usize {
    let bytes = &source[range.clone()];
    let line_feeds = memchr::memchr_iter(b'\n', bytes).count();
    let lone_returns = memchr::memchr_iter(b'\r', bytes)
        .filter(|&at| source.get(range.start + at + 1) != Some(&b'\n'))
        .count();
    line_feeds + lone_returns
}

/// Where the line containing `offset` starts (an offset on the LF of a CRLF
/// belongs to the line that CRLF ends).
pub fn line_start(source: &[u8], offset: usize) -> usize {
    let mut before = offset;
    while let Some(end) = memchr::memrchr2(b'\n', b'\r', &source[..before]) {
        if source[end] == b'\r' && source.get(end + 1) == Some(&b'\n') {
            // `offset` is the LF of this CRLF: the line started before it.
            before = end;
            continue;
        }
        return end + 1;
    }
    0
}

/// Where the line holding `at` ends, before its terminator.
pub fn line_end(source: &[u8], at: usize) -> usize {
    memchr::memchr2(b'\n', b'\r', &source[at..]).map_or(source.len(), |end| at + end)
}

/// Where the line before the one starting at `start` ends, before its
/// terminator (`start` itself on the first line).
pub fn previous_line_end(source: &[u8], start: usize) -> usize {
    match &source[..start] {
        [.., b'\r', b'\n'] => start - 2,
        [.., _] => start - 1,
        [] => start,
    }
}

/// Where the next line starts after the terminator at `at` (`at` itself at
/// the end of the file).
pub fn next_line_start(source: &[u8], at: usize) -> usize {
    match &source[at..] {
        [b'\r', b'\n', ..] => at + 2,
        [_, ..] => at + 1,
        [] => at,
    }
}

/// The terminator that ends the text before `at`, if `at` starts a line:
/// `\r\n`, `\n` or `\r`.
pub fn ending_before(source: &[u8], at: usize) -> Option<&'static [u8]> {
    match &source[..at] {
        [.., b'\r', b'\n'] => Some(b"\r\n"),
        [.., b'\n'] => Some(b"\n"),
        [.., b'\r'] => Some(b"\r"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_bounds_follow_every_line_ending() {
        let source = b"a\nbc\r\nd\re";
        assert_eq!(line_start(source, 4), 2, "on the CR of a CRLF");
        assert_eq!(line_start(source, 5), 2, "on the LF of a CRLF");
        assert_eq!(line_end(source, 2), 4);
        assert_eq!(line_end(source, 8), 9, "the last line has no terminator");
        assert_eq!(next_line_start(source, 4), 6);
        assert_eq!(next_line_start(source, 1), 2);
        assert_eq!(next_line_start(source, 9), 9);
        assert_eq!(previous_line_end(source, 6), 4);
        assert_eq!(previous_line_end(source, 8), 7);
        assert_eq!(previous_line_end(source, 0), 0);
        assert_eq!(ending_before(source, 6), Some(b"\r\n".as_slice()));
        assert_eq!(ending_before(source, 8), Some(b"\r".as_slice()));
        assert_eq!(ending_before(source, 2), Some(b"\n".as_slice()));
        assert_eq!(ending_before(source, 3), None);
    }

    #[test]
    fn positions_follow_every_line_ending() {
        let index = LineIndex::new(b"a\nbc\r\nd\re");
        assert_eq!(index.position(0), Position { row: 1, column: 1 });
        assert_eq!(index.position(3), Position { row: 2, column: 2 });
        assert_eq!(index.position(6), Position { row: 3, column: 1 });
        assert_eq!(index.position(8), Position { row: 4, column: 1 });
    }

    proptest::proptest! {
        /// Found from the block counts (texts over two blocks long too), a
        /// position is the one counting every line from the start gives.
        #[test]
        fn positions_agree_with_counting_every_line(
            text in "[a\r\n]{0,400}|[ab\r\n]{8000,9000}",
            at in 0usize..9000,
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
    fn columns_in_every_unit() {
        // `ä` is 2 bytes, one UTF-16 unit; `𝛼` 4 bytes, two units.
        let source = "X=1\näY=\"𝛼\" Z\r\nW".as_bytes();
        let index = LineIndex::new(source);
        let z = source.iter().position(|&b| b == b'Z').expect("Z");
        let at = |unit| index.position_in(z, unit);
        assert_eq!(at(ColumnUnit::CodePoints), Position { row: 2, column: 8 });
        assert_eq!(at(ColumnUnit::Utf16), Position { row: 2, column: 9 });
        assert_eq!(at(ColumnUnit::Bytes), Position { row: 2, column: 12 });
        let latin1 = LineIndex::new(b"\xe4\xe4=1");
        assert_eq!(latin1.position_in(2, ColumnUnit::Utf16).column, 3);
    }

    #[test]
    fn columns_count_characters_in_utf8_and_bytes_in_latin1() {
        let utf8 = LineIndex::new("ä=1".as_bytes());
        assert_eq!(utf8.position(2).column, 2);
        let latin1 = LineIndex::new(b"\xe4\xe4=1");
        assert_eq!(latin1.position(2).column, 3);
    }
}
