//! Splitting a file into physical lines, each with its exact terminator.
//!
//! A block ends at LF; CRLF and a lone CR also end a line (files from PCs and
//! old controls). The last line may have no terminator. Concatenating every
//! line's content and terminator gives back the input byte for byte. The
//! bounds of a line around an offset are `crate::span`'s, by the same rule.

use crate::span::Span;

/// How a physical line ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineEnding {
    Lf,
    CrLf,
    Cr,
    /// The last line of a file without a final newline.
    None,
}

impl LineEnding {
    pub fn as_bytes(self) -> &'static [u8] {
        match self {
            LineEnding::Lf => b"\n",
            LineEnding::CrLf => b"\r\n",
            LineEnding::Cr => b"\r",
            LineEnding::None => b"",
        }
    }
}

/// One physical line: its content (without terminator) and how it ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RawLine {
    pub content: Span,
    pub ending: LineEnding,
}

impl RawLine {
    /// The content plus the terminator.
    pub fn full(self) -> Span {
        Span::new(
            self.content.start,
            self.content.end + self.ending.as_bytes().len(),
        )
    }
}

/// Iterates over the physical lines of `source`; allocation-free.
pub fn raw_lines(source: &[u8]) -> RawLines<'_> {
    RawLines { source, at: 0 }
}

pub struct RawLines<'a> {
    source: &'a [u8],
    at: usize,
}

impl Iterator for RawLines<'_> {
    type Item = RawLine;

    fn next(&mut self) -> Option<RawLine> {
        let start = self.at;
        if start >= self.source.len() {
            return None;
        }
        let line = line_from(self.source, start);
        self.at = line.full().end;
        Some(line)
    }
}

/// The line that starts at `start` (which must be below `source.len()`).
pub fn line_from(source: &[u8], start: usize) -> RawLine {
    line_at(source, start, short_line_end(source, start))
}

/// Where the line from `start` ends (at a CR, an LF or the end of `source`).
/// Most lines that are not plain are short (setup files, hand-written
/// cycles: 20-30 bytes), and starting a vector search costs more than such a
/// line: the first 64 bytes are looked at eight at a time. Not inlined, so
/// that the plain-line scan's loop, which calls it rarely, stays small.
#[inline(never)]
fn short_line_end(source: &[u8], start: usize) -> usize {
    const ONES: u64 = u64::from_ne_bytes([0x01; 8]);
    const HIGHS: u64 = u64::from_ne_bytes([0x80; 8]);
    let mut at = start;
    for _ in 0..8 {
        let Some(chunk) = source.get(at..).and_then(<[u8]>::first_chunk) else {
            break;
        };
        let word = u64::from_le_bytes(*chunk);
        // A byte of `word ^ n` is zero where an LF is; the lowest flagged
        // byte is the first such (a borrow flags only bytes above it).
        let zero = |v: u64| v.wrapping_sub(ONES) & !v & HIGHS;
        let found = zero(word ^ (ONES * u64::from(b'\n'))) | zero(word ^ (ONES * u64::from(b'\r')));
        if found != 0 {
            return at + (found.trailing_zeros() / 8) as usize;
        }
        at += 8;
    }
    crate::span::line_end(source, at)
}

/// The line from `start` whose content ends at `end`: at a CR, an LF or the
/// end of `source`.
pub fn line_at(source: &[u8], start: usize, end: usize) -> RawLine {
    let ending = match (source.get(end), source.get(end + 1)) {
        (None, _) => LineEnding::None,
        (Some(b'\n'), _) => LineEnding::Lf,
        (_, Some(b'\n')) => LineEnding::CrLf,
        _ => LineEnding::Cr,
    };
    RawLine {
        content: Span::new(start, end),
        ending,
    }
}

/// The line ending most lines of the file use (LF for a file without any).
pub fn dominant_ending(source: &[u8]) -> LineEnding {
    // Counted, not found one by one: a search per line end cost 80
    // instructions a line. CRs are rare outside CRLF files.
    let line_feeds = memchr::memchr_iter(b'\n', source).count();
    let (mut crlf, mut cr) = (0usize, 0usize);
    for at in memchr::memchr_iter(b'\r', source) {
        if source.get(at + 1) == Some(&b'\n') {
            crlf += 1;
        } else {
            cr += 1;
        }
    }
    let lf = line_feeds - crlf;
    if crlf > lf && crlf >= cr {
        LineEnding::CrLf
    } else if cr > lf && cr > crlf {
        LineEnding::Cr
    } else {
        LineEnding::Lf
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rebuild(source: &[u8]) -> Vec<u8> {
        raw_lines(source)
            .flat_map(|line| line.full().of(source).to_vec())
            .collect()
    }

    #[test]
    fn lines_keep_every_kind_of_terminator() {
        let source = b"N10\nN20\r\nN30\rN40";
        let endings: Vec<_> = raw_lines(source).map(|l| l.ending).collect();
        assert_eq!(
            endings,
            [
                LineEnding::Lf,
                LineEnding::CrLf,
                LineEnding::Cr,
                LineEnding::None
            ]
        );
        assert_eq!(rebuild(source), source);
    }

    #[test]
    fn empty_lines_and_cr_before_crlf_are_lines_too() {
        let source = b"\n\n\r\r\n";
        assert_eq!(raw_lines(source).count(), 4);
        assert_eq!(rebuild(source), source);
        assert_eq!(raw_lines(b"").count(), 0);
    }

    #[test]
    fn dominant_ending_follows_the_majority() {
        assert_eq!(dominant_ending(b"a\r\nb\r\nc\n"), LineEnding::CrLf);
        assert_eq!(dominant_ending(b"a"), LineEnding::Lf);
    }

    proptest::proptest! {
        /// The end found eight bytes at a time is the first CR or LF.
        #[test]
        fn short_line_ends_are_the_first_terminator(text in "[a\r\n]{0,3}[a-z .]{0,90}[\r\n]?[a\r\n]{0,9}", start in 0usize..100) {
            let source = text.as_bytes();
            let start = start.min(source.len());
            let expected = source[start..]
                .iter()
                .position(|&b| b == b'\n' || b == b'\r')
                .map_or(source.len(), |n| start + n);
            proptest::prop_assert_eq!(short_line_end(source, start), expected);
        }
    }

    proptest::proptest! {
        /// The counts are the lines' own endings, ties included.
        #[test]
        fn dominant_ending_is_the_most_common_line_ending(text in "[a\r\n]{0,60}") {
            let source = text.as_bytes();
            let count = |ending| raw_lines(source).filter(|line| line.ending == ending).count();
            let (lf, crlf, cr) = (count(LineEnding::Lf), count(LineEnding::CrLf), count(LineEnding::Cr));
            let expected = if crlf > lf && crlf >= cr {
                LineEnding::CrLf
            } else if cr > lf && cr > crlf {
                LineEnding::Cr
            } else {
                LineEnding::Lf
            };
            proptest::prop_assert_eq!(dominant_ending(source), expected);
        }
    }
}
