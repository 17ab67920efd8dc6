//! What the text of a line before the cursor says about what is being
//! typed: the word under way, the word before it, and the calls whose
//! argument lists are open. Read from the bytes themselves, not from the
//! parse: a line being typed is seldom a valid block yet. What it reads is
//! the line alone (an NC block is one line): strings in `"` or `'` (a
//! `'H..'` constant reads as one), `;` comments, brackets; the rest of the
//! language is the parser's.

use lsp_types as lsp;

use super::answers::Snapshot;
use crate::span::{ColumnUnit, Span};

/// The line before the cursor, read.
#[derive(Debug, PartialEq, Eq)]
pub struct Before<'l> {
    /// The cursor is in a comment or a string: nothing is completed there.
    pub in_comment_or_string: bool,
    /// Where the word being typed starts, from the line's start.
    pub word_start: usize,
    /// The word being typed (empty right after a space or a bracket).
    pub word: &'l [u8],
    /// The word before it, with only blanks between.
    pub previous: Option<&'l [u8]>,
    /// The calls whose argument lists are open, the innermost first (in a
    /// string too: an argument may be one).
    pub calls: Vec<OpenCall<'l>>,
}

/// Where the cursor is and what the line before it says.
pub struct Cursor<'l> {
    /// The line's 0-based row.
    pub row: usize,
    /// The word being typed, to its end (after the cursor too).
    pub word: Span,
    pub before: Before<'l>,
}

impl<'a, 't> Snapshot<'a, 't> {
    /// The cursor at `position`, read.
    pub(super) fn cursor(&self, position: lsp::Position) -> Cursor<'t> {
        let at = self.offset(position);
        let row = self.text.position(at, ColumnUnit::Bytes).row - 1;
        // The editor counts an empty line after the last line end (and an
        // empty document as one line), the program's lines do not: there
        // the cursor's line is empty.
        let lines = &self.model.lines;
        let line = if row < lines.len() {
            lines.raw(row).content
        } else {
            Span::new(at, at)
        };
        let source: &'t [u8] = self.text.bytes();
        let at = at.clamp(line.start, line.end);
        let before = read(&source[line.start..at]);
        let rest = source[at..line.end]
            .iter()
            .take_while(|&&b| is_word_byte(b));
        let word = Span::new(line.start + before.word_start, at + rest.count());
        Cursor { row, word, before }
    }
}

/// A call whose argument list the cursor is in.
#[derive(Debug, PartialEq, Eq)]
pub struct OpenCall<'l> {
    /// The name before its `(`.
    pub name: &'l [u8],
    /// The argument the cursor is in, from 0.
    pub argument: usize,
}

/// A byte of a name (`$` starts a system variable's).
fn is_word_byte(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || byte == b'_' || byte == b'$'
}

/// Reads `line`, the bytes of a line from its start to the cursor.
pub fn read(line: &[u8]) -> Before<'_> {
    // An open bracket: the name before a `(` (empty for a bracket of an
    // expression or an index), and the commas met since.
    let mut open: Vec<(&[u8], usize)> = Vec::new();
    let mut quote = None;
    for (at, &byte) in line.iter().enumerate() {
        match (quote, byte) {
            (Some(q), _) if byte == q => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(byte),
            (None, b';') => return in_comment(line),
            (None, b'(' | b'[') => {
                let name = match byte {
                    b'(' => word_ending(line, trim_end(line, at)).1,
                    _ => &[][..],
                };
                open.push((name, 0));
            }
            (None, b')' | b']') => {
                open.pop();
            }
            (None, b',') => {
                if let Some((_, commas)) = open.last_mut() {
                    *commas += 1;
                }
            }
            _ => {}
        }
    }
    let (word_start, word) = word_ending(line, line.len());
    let before_word = trim_end(line, word_start);
    let previous = Some(word_ending(line, before_word).1)
        .filter(|previous| !previous.is_empty() && before_word < word_start);
    let calls = open
        .into_iter()
        .rev()
        .filter(|(name, _)| !name.is_empty())
        .map(|(name, argument)| OpenCall { name, argument })
        .collect();
    Before {
        in_comment_or_string: quote.is_some(),
        word_start,
        word,
        previous,
        calls,
    }
}

fn in_comment(line: &[u8]) -> Before<'_> {
    Before {
        in_comment_or_string: true,
        word_start: line.len(),
        word: &[],
        previous: None,
        calls: Vec::new(),
    }
}

/// Where the blanks before `end` begin.
fn trim_end(line: &[u8], end: usize) -> usize {
    line[..end]
        .iter()
        .rposition(|b| !matches!(b, b' ' | b'\t'))
        .map_or(0, |last| last + 1)
}

/// The word that ends at `end`, and where it starts.
fn word_ending(line: &[u8], end: usize) -> (usize, &[u8]) {
    let start = line[..end]
        .iter()
        .rposition(|&b| !is_word_byte(b))
        .map_or(0, |last| last + 1);
    (start, &line[start..end])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_word_under_way_and_the_one_before() {
        let before = read(b"N10 GOTOF  LA");
        assert!(!before.in_comment_or_string);
        assert_eq!((before.word_start, before.word), (11, &b"LA"[..]));
        assert_eq!(before.previous, Some(&b"GOTOF"[..]));
        let before = read(b"R1=$P_U");
        assert_eq!(before.word, b"$P_U");
        assert_eq!(before.previous, None, "`=` is between");
        let before = read(b"GOTOB ");
        assert_eq!(
            (before.word, before.previous),
            (&b""[..], Some(&b"GOTOB"[..]))
        );
    }

    #[test]
    fn the_open_calls_innermost_first_with_their_argument() {
        let before = read(b"CYCLE800(0,\"TC1\",200000,57,SIN(A[1,2]),");
        let calls: Vec<(&[u8], usize)> =
            before.calls.iter().map(|c| (c.name, c.argument)).collect();
        assert_eq!(calls, [(&b"CYCLE800"[..], 5)]);
        let before = read(b"MY_PROC (1, SIN(3");
        let calls: Vec<(&[u8], usize)> =
            before.calls.iter().map(|c| (c.name, c.argument)).collect();
        assert_eq!(calls, [(&b"SIN"[..], 0), (&b"MY_PROC"[..], 1)]);
        // A comma in a string, a closed call: neither counts.
        let before = read(b"CYCLE800(0,\"A,B\",F(1,2),");
        assert_eq!(before.calls[0].argument, 3);
    }

    #[test]
    fn comments_and_strings_are_text() {
        assert!(read(b"G1 X1 ; GOTOF LA").in_comment_or_string);
        assert!(read(b"G1 X1 ; CYCLE800(").calls.is_empty());
        assert!(!read(b"MSG(\"a;b\") GOTOF ").in_comment_or_string);
        // In a string argument, its call is still open.
        let before = read(b"CYCLE800(1,\"TC");
        assert!(before.in_comment_or_string);
        assert_eq!(before.calls[0].argument, 1);
    }
}
