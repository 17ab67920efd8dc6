//! Facts about lines that do not need their tree: whether a line is nothing
//! but address words with numbers (the millions of motion blocks of a CAM
//! program), and every block number of a file.
//!
//! The CYCLE600 walk and the jump rules use them to skip the parser where the
//! tree could not tell them anything.

use crate::span::Span;
use crate::syntax::block::{parse_block_number, parse_skip};
use crate::syntax::lexer::{is_blank, parse_blank, Input};
use crate::syntax::lines::{line_at, line_from, RawLine};
use crate::syntax::tree::BlockNumber;

/// The line's content (before any `;` comment) is nothing but address words
/// with plain decimal numbers, `N10 G1 X-12.5 Y.5 F2000.`: it parses without
/// error into such words (property-tested), so it assigns, calls, jumps and
/// reads nothing. Strict and conservative: `false` means "parse it to know".
pub fn is_plain(content: &[u8]) -> bool {
    scan_plain(content, 0).is_some()
}

/// What the rules ask of every line, read from a line [`is_plain`] accepts
/// without building its tree (property-tested to agree with the tree).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlainFacts {
    /// The block number it starts with (`N10`).
    pub number: Option<BlockNumber>,
    /// It holds at least one word besides the block number.
    pub has_words: bool,
    /// The comment, from its `;`.
    pub comment: Option<Span>,
}

/// The [`PlainFacts`] of a line's content starting at `start` in the file, if
/// [`is_plain`] accepts it.
pub fn scan_plain(content: &[u8], start: usize) -> Option<PlainFacts> {
    let (stop, mut facts) = scan_words(content, start)?;
    if stop < content.len() {
        facts.comment = Some(Span::new(start + stop, start + content.len()));
    }
    Some(facts)
}

/// The plain line starting at `start` in `source`, with its facts; `None`
/// when the line is not plain. The pass that reads the words also finds the
/// line's end, so a plain line costs one look at each byte.
pub fn scan_plain_line(source: &[u8], start: usize) -> Option<(RawLine, PlainFacts)> {
    let rest = &source[start..];
    let (stop, mut facts) = scan_words(rest, start)?;
    let mut end = stop;
    if rest.get(stop) == Some(&b';') {
        end = memchr::memchr2(b'\n', b'\r', &rest[stop..]).map_or(rest.len(), |n| stop + n);
        facts.comment = Some(Span::new(start + stop, start + end));
    }
    Some((line_at(source, start, start + end), facts))
}

/// Reads the plain line at an offset, if it is one ([`scan_plain_line`]).
pub type PlainScanner = fn(&[u8], usize) -> Option<(RawLine, PlainFacts)>;

/// Every line of `source`, with its [`PlainFacts`] when it is plain: a plain
/// line's words and its end are found in one pass, other lines' ends by a
/// search.
pub fn scanned_lines(source: &[u8]) -> ScannedLines<'_> {
    scanned_lines_with(source, scan_plain_line)
}

/// [`scanned_lines`] with another scanner (`|_, _| None` takes no line for
/// plain: the reference the shortcut is tested against).
pub fn scanned_lines_with(source: &[u8], scan: PlainScanner) -> ScannedLines<'_> {
    ScannedLines {
        source,
        at: 0,
        scan,
    }
}

pub struct ScannedLines<'a> {
    source: &'a [u8],
    at: usize,
    scan: PlainScanner,
}

impl Iterator for ScannedLines<'_> {
    type Item = (RawLine, Option<PlainFacts>);

    fn next(&mut self) -> Option<Self::Item> {
        if self.at >= self.source.len() {
            return None;
        }
        let (raw, facts) = match (self.scan)(self.source, self.at) {
            Some((raw, facts)) => (raw, Some(facts)),
            None => (line_from(self.source, self.at), None),
        };
        self.at = raw.full().end;
        Some((raw, facts))
    }
}

/// Reads address words up to a `;`, a line end or the end of `bytes`: where
/// it stopped and what it found (no comment yet), or `None` at anything else.
fn scan_words(bytes: &[u8], start: usize) -> Option<(usize, PlainFacts)> {
    let class = |at: usize| bytes.get(at).map_or(Class::End, |&b| CLASS[usize::from(b)]);
    let mut facts = PlainFacts {
        number: None,
        has_words: false,
        comment: None,
    };
    let mut at = 0;
    let mut first_word = true;
    loop {
        while class(at) == Class::Blank {
            at += 1;
        }
        let letter = at;
        match class(at) {
            Class::End | Class::Comment => return Some((at, facts)),
            Class::Letter => at += 1,
            _ => return None,
        }
        let signed = class(at) == Class::Sign;
        if signed {
            at += 1;
        }
        let (digits_start, mut points) = (at, 0);
        loop {
            match class(at) {
                Class::Digit => {}
                Class::Point => points += 1,
                _ => break,
            }
            at += 1;
        }
        // A number needs a digit, has one point at most, and is no longer
        // than machine positions get (`1` with 400 zeros is too large for a
        // REAL: the parser says so).
        let length = at - digits_start;
        if length == points || points > 1 || length > 24 {
            return None;
        }
        // The parser's block number: a first word N with digits alone.
        if first_word && !signed && points == 0 && bytes[letter].eq_ignore_ascii_case(&b'N') {
            facts.number = Some(BlockNumber {
                span: Span::new(start + letter, start + at),
                main: false,
                digits: Span::new(start + digits_start, start + at),
            });
        } else {
            facts.has_words = true;
        }
        first_word = false;
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Class {
    /// A line end (CR, LF) or the end of the bytes.
    End,
    Letter,
    Digit,
    Point,
    Sign,
    Blank,
    Comment,
    Other,
}

/// Each byte's class, looked up rather than tested: this runs on every byte.
static CLASS: [Class; 256] = {
    let mut table = [Class::Other; 256];
    let mut byte = 0;
    while byte < 256 {
        let b = byte as u8;
        table[byte] = if b.is_ascii_alphabetic() {
            Class::Letter
        } else if b.is_ascii_digit() {
            Class::Digit
        } else if b == b'.' {
            Class::Point
        } else if b == b'-' || b == b'+' {
            Class::Sign
        } else if b == b';' {
            Class::Comment
        } else if b == b'\n' || b == b'\r' {
            Class::End
        } else if is_blank(b) {
            Class::Blank
        } else {
            Class::Other
        };
        byte += 1;
    }
    table
};

/// Every block number (`N100`; not the main block number `:100`) with its
/// 0-based line, sorted by number and then line. Numbers beyond `u64` are
/// left out.
pub fn block_numbers(source: &[u8]) -> Vec<(u64, usize)> {
    let mut numbers = Vec::new();
    let mut read = |row: usize, start: usize, end: usize| {
        let input = parse_blank(Input::new(&source[start..end], start));
        let input = parse_skip(input).map_or(input, |(rest, _)| parse_blank(rest));
        if let Ok((_, number)) = parse_block_number(input) {
            if let Some(value) = digits_value(number.digits.of(source)).filter(|_| !number.main) {
                numbers.push((value, row));
            }
        }
    };
    // One search over the file for the line ends (LF, CRLF, lone CR): a
    // search per line costs more to start than to run on a 50-byte line.
    let (mut row, mut start) = (0, 0);
    for end in memchr::memchr2_iter(b'\n', b'\r', source) {
        if end < start {
            continue; // the LF of a CRLF
        }
        read(row, start, end);
        let crlf = source[end] == b'\r' && source.get(end + 1) == Some(&b'\n');
        (row, start) = (row + 1, end + 1 + usize::from(crlf));
    }
    if start < source.len() {
        read(row, start, source.len());
    }
    // Stable, so rows stay in order; and fast on the ascending runs that
    // block numbers come in.
    numbers.sort_by_key(|&(number, _)| number);
    numbers
}

/// The value of ASCII digits, `None` beyond `u64` (or for anything else).
pub fn digits_value(digits: &[u8]) -> Option<u64> {
    digits.iter().try_fold(0u64, |value, &digit| {
        let digit = (digit as char).to_digit(10)?;
        value.checked_mul(10)?.checked_add(u64::from(digit))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::tree::{LineKind, StatementKind, WordValue};
    use crate::syntax::Lines;

    #[test]
    fn plain_lines_are_address_words_with_numbers() {
        for plain in [
            "N10 G1 X-12.5 Y.5",
            "X1 Y2 ; TRAORI",
            "",
            "  N20",
            "G01X498.375Y82.325",
        ] {
            assert!(is_plain(plain.as_bytes()), "{plain}");
        }
        for not in [
            "TRAORI", "R1=5", "X=R1", "GOTOF L1", "X 5", "X", "L1: X5", "/1 X5", "X1EX3", "T\"A\"",
        ] {
            assert!(!is_plain(not.as_bytes()), "{not}");
        }
    }

    proptest::proptest! {
        /// The block numbers found without trees are the trees' own, sorted
        /// by number and line, whatever the line endings.
        #[test]
        fn block_numbers_are_the_trees_numbers(
            lines in proptest::collection::vec("( ?/[0-9]? ?)?(N[0-9]{1,3}|:[0-9]{1,2}|N9{20}|N1\\.5)?( X1)?", 0..12),
            endings in proptest::collection::vec(proptest::prop_oneof!["\n", "\r\n", "\r"], 12),
            last in "(N[0-9])?",
        ) {
            let mut text: String = lines.iter().zip(&endings).map(|(l, e)| format!("{l}{e}")).collect();
            text.push_str(&last); // a last line without terminator
            let source = text.as_bytes();
            let lines = Lines::new(source);
            let mut expected: Vec<(u64, usize)> = (0..lines.len())
                .filter_map(|row| match lines.parse(row).kind {
                    LineKind::Block(block) => block
                        .number
                        .filter(|n| !n.main)
                        .and_then(|n| digits_value(n.digits.of(source)))
                        .map(|value| (value, row)),
                    _ => None,
                })
                .collect();
            expected.sort_unstable();
            proptest::prop_assert_eq!(block_numbers(source), expected);
        }
    }

    proptest::proptest! {
        // Plain lines are a small share of random ones: many cases.
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(4000))]

        /// What `is_plain` calls plain parses without a diagnostic into
        /// address words with numbers only.
        #[test]
        fn a_plain_line_parses_into_number_words(text in proptest::prop_oneof![
            "[NGXYZEx0-9 .;+=:(-]{0,40}",
            "([NGXYZEx][-+]?[0-9.]{0,5} ?){0,8}(;[A-Z=]{0,3})?",
        ]) {
            if is_plain(text.as_bytes()) {
                proptest::prop_assert!(crate::syntax::diagnostics(text.as_bytes()).is_empty());
                let lines = Lines::new(text.as_bytes());
                for index in 0..lines.len() {
                    let LineKind::Block(block) = lines.parse(index).kind else {
                        continue;
                    };
                    proptest::prop_assert!(block.label.is_none() && block.unparsed.is_none());
                    let raw = lines.raw[index];
                    let facts = scan_plain(raw.content.of(text.as_bytes()), raw.content.start)
                        .expect("plain");
                    proptest::prop_assert_eq!(facts.number, block.number);
                    proptest::prop_assert_eq!(facts.has_words, !block.statements.is_empty());
                    proptest::prop_assert_eq!(facts.comment, block.comment);
                    for statement in &block.statements {
                        let number_word = matches!(
                            &statement.kind,
                            StatementKind::Word(word) if matches!(word.value, WordValue::Number(_))
                        );
                        proptest::prop_assert!(number_word, "{:?}", statement);
                    }
                }
            }
        }
    }
}
