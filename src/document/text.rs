//! A document an editor holds open: the text is the document's own, its
//! line starts are known up front, and positions convert both ways in the
//! unit the client counts (UTF-16 by the Language Server Protocol's
//! default, UTF-8 bytes or characters when the client says so). Edits
//! replace a range and renumber only the lines after it. Nothing inside
//! changes on a read, so one text serves requests on several threads.

use std::ops::Range;

use crate::span::{char_len, is_utf8, line_end, next_line_start, width, ColumnUnit, Position};

#[derive(Clone)]
pub struct Text {
    bytes: Vec<u8>,
    /// Where each line starts; the first is 0. A line ends at LF, CRLF or a
    /// lone CR, as everywhere in sinuprep.
    line_starts: Vec<usize>,
    /// A file that is not UTF-8 is in a single-byte code page: a byte is a
    /// character (see [`crate::span::LineIndex`]).
    utf8: bool,
}

impl Text {
    pub fn new(bytes: Vec<u8>) -> Self {
        let line_starts = line_starts(&bytes, 0);
        let utf8 = is_utf8(&bytes);
        Self {
            bytes,
            line_starts,
            utf8,
        }
    }

    pub fn bytes(&self) -> &[u8] {
        &self.bytes
    }

    /// The number of lines; an empty text, or one ending in a line end,
    /// has an empty last line, as editors count.
    pub fn lines(&self) -> usize {
        self.line_starts.len()
    }

    /// The 1-based position of `offset` (clamped to the text), its column
    /// counted in `unit`. An offset inside a character counts the
    /// character's start.
    pub fn position(&self, offset: usize, unit: ColumnUnit) -> Position {
        let offset = self.char_start(offset.min(self.bytes.len()));
        let row = self.line_starts.partition_point(|&start| start <= offset) - 1;
        let before = &self.bytes[self.line_starts[row]..offset];
        Position {
            row: row + 1,
            column: width(before, unit, self.utf8) + 1,
        }
    }

    /// The byte offset of the 1-based `position`, its column in `unit`: a
    /// column past its line's end is that end (before the terminator), a
    /// row past the last is the end of the text, a column inside a
    /// character (half a UTF-16 pair) is the character's start.
    pub fn offset(&self, position: Position, unit: ColumnUnit) -> usize {
        let Some(&start) = self.line_starts.get(position.row.saturating_sub(1)) else {
            return self.bytes.len();
        };
        let end = line_end(&self.bytes, start);
        let wanted = position.column.saturating_sub(1);
        let (mut at, mut column) = (start, 0);
        while at < end {
            let len = char_len(self.bytes[at], self.utf8).min(end - at);
            let next = column + width(&self.bytes[at..at + len], unit, self.utf8);
            if next > wanted {
                break;
            }
            (at, column) = (at + len, next);
        }
        at
    }

    /// Replaces the bytes of `range` (clamped to the text, moved to
    /// character starts) by `with`, as an editor's incremental change does.
    pub fn replace(&mut self, range: Range<usize>, with: &[u8]) {
        let end = self.char_start(range.end.min(self.bytes.len()));
        let start = self.char_start(range.start.min(end));
        self.bytes.splice(start..end, with.iter().copied());
        // The lines from the one holding `start` (from the one before, if
        // `start` splits a CRLF) are found again; those after the change
        // move by its length.
        let first = self
            .line_starts
            .partition_point(|&line| line < start)
            .saturating_sub(1);
        let from = self.line_starts[first];
        let after = self.line_starts.partition_point(|&line| line <= end + 1);
        let moved: Vec<usize> = self.line_starts[after..]
            .iter()
            .map(|&line| line - end + start + with.len())
            .collect();
        let resume = moved.first().copied();
        self.line_starts.truncate(first);
        let until = resume.unwrap_or(self.bytes.len());
        self.line_starts.extend(
            line_starts(&self.bytes[..until], from)
                .into_iter()
                .filter(|&line| resume.is_none() || line < until),
        );
        self.line_starts.extend(moved);
        self.utf8 = if self.utf8 {
            is_utf8(with) && self.boundary(start) && self.boundary(start + with.len())
        } else {
            is_utf8(&self.bytes)
        };
    }

    /// Whether `at` is the start of a character (or the end).
    fn boundary(&self, at: usize) -> bool {
        !self.utf8 || self.bytes.get(at).is_none_or(|&b| (b & 0xC0) != 0x80)
    }

    /// The start of the character holding `at`.
    fn char_start(&self, mut at: usize) -> usize {
        while at > 0 && !self.boundary(at) {
            at -= 1;
        }
        at
    }
}

/// The starts of the lines of `bytes` from offset `from` (a line's start).
fn line_starts(bytes: &[u8], from: usize) -> Vec<usize> {
    let mut starts = vec![from];
    let mut at = from;
    while at < bytes.len() {
        let end = line_end(bytes, at);
        if end == bytes.len() {
            break;
        }
        at = next_line_start(bytes, end);
        starts.push(at);
    }
    starts
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::span::LineIndex;
    use proptest::prelude::*;

    #[test]
    fn columns_count_in_the_unit_asked() {
        let text = Text::new("X1 ; ü😀 Z\n".as_bytes().to_vec());
        let z = "X1 ; ü😀 ".len();
        let at = |column| Position { row: 1, column };
        assert_eq!(text.position(z, ColumnUnit::Bytes), at(z + 1));
        assert_eq!(text.position(z, ColumnUnit::CodePoints), at(9));
        assert_eq!(text.position(z, ColumnUnit::Utf16), at(10));
        assert_eq!(text.offset(at(10), ColumnUnit::Utf16), z);
        // Half a surrogate pair is the character's start.
        assert_eq!(text.offset(at(8), ColumnUnit::Utf16), z - 5);
        assert_eq!(
            text.offset(at(99), ColumnUnit::Utf16),
            z + 1,
            "the line's end"
        );
        assert_eq!(
            text.offset(Position { row: 9, column: 1 }, ColumnUnit::Utf16),
            z + 2
        );
    }

    /// Text of ASCII, two-, three- and four-byte characters and every line end.
    fn texts() -> impl Strategy<Value = String> {
        proptest::collection::vec(
            prop_oneof![
                Just("G1"),
                Just(" "),
                Just("ü"),
                Just("€"),
                Just("😀"),
                Just("\n"),
                Just("\r\n"),
                Just("\r"),
            ],
            0..40,
        )
        .prop_map(|parts| parts.concat())
    }

    proptest! {
        /// Positions agree with the command line's line index, and each
        /// converts back to its offset, in every unit.
        #[test]
        fn positions_agree_and_convert_back(text in texts()) {
            let document = Text::new(text.clone().into_bytes());
            let index = LineIndex::new(text.as_bytes());
            for (offset, _) in text.char_indices().chain([(text.len(), ' ')]) {
                for unit in [ColumnUnit::Bytes, ColumnUnit::CodePoints, ColumnUnit::Utf16] {
                    let position = document.position(offset, unit);
                    prop_assert_eq!(position, index.position_in(offset, unit));
                    let back = document.offset(position, unit);
                    // An offset on the LF of a CRLF is its line's end.
                    let expected = if text[..offset].ends_with('\r') && text[offset..].starts_with('\n') {
                        offset - 1
                    } else {
                        offset
                    };
                    prop_assert_eq!(back, expected);
                }
            }
        }

        /// Positions agree with the command line's line index over texts
        /// several of its 4,096-byte blocks long, in every unit.
        #[test]
        fn positions_agree_across_blocks(
            text in "([aä𝛼 ]{0,30}(\r\n|\n|\r)){0,400}",
            picks in proptest::collection::vec(0usize..20_000, 1..20),
        ) {
            let document = Text::new(text.clone().into_bytes());
            let index = LineIndex::new(text.as_bytes());
            for pick in picks {
                let mut offset = pick.min(text.len());
                while !text.is_char_boundary(offset) {
                    offset += 1;
                }
                for unit in [ColumnUnit::Bytes, ColumnUnit::CodePoints, ColumnUnit::Utf16] {
                    prop_assert_eq!(document.position(offset, unit), index.position_in(offset, unit));
                }
            }
        }

        /// An edit leaves the text as if it had been read anew.
        #[test]
        fn an_edit_is_a_text_read_anew(text in texts(), with in texts(), a in 0usize..200, b in 0usize..200) {
            let mut document = Text::new(text.clone().into_bytes());
            let (start, end) = (a.min(b).min(text.len()), a.max(b).min(text.len()));
            document.replace(start..end, with.as_bytes());
            let fresh = Text::new(document.bytes().to_vec());
            prop_assert_eq!(&document.line_starts, &fresh.line_starts);
            prop_assert_eq!(document.utf8, fresh.utf8);
        }
    }
}
