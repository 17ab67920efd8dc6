//! A line laid out: the skip level and block number at its start, one
//! indent step per level of the control blocks around it, one blank where
//! the source had blanks between words (none added where it had none), no
//! trailing blanks; strings, the comment and the blanks before it copied
//! byte for byte. The case of the language's words ([`super::case`]) and
//! the renumbering's replacements ([`super::renumber`]) are applied on the
//! way, so a line is written once.
//!
//! Which level a line stands at is the block structure's: the model's
//! matching of IF/ELSE/ENDIF and the loops ([`Depths`]), the one the walk
//! and the unclosed-block rule read. Nothing here parses.

use crate::format::Case;
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::block::{parse_block_number, parse_skip};
use crate::syntax::lexer::Input;
use crate::syntax::tree::Block;

/// The level each line stands at, asked for in line order: one more
/// inside each closed IF, WHILE, FOR, LOOP and REPEAT than at its opener
/// and closer, an ELSE at its IF's level; a PROC's body one more (until a
/// `%` header starts another program). A block left unclosed indents
/// nothing: where it would end is not known.
pub struct Depths {
    /// (row, +1 or -1), sorted by row.
    changes: Vec<(usize, i32)>,
    next: usize,
    level: i32,
    /// ELSE rows, sorted.
    elses: Vec<usize>,
    next_else: usize,
    proc_body: bool,
}

impl Depths {
    pub fn new(model: &Model) -> Self {
        let closed = model.blocks.closed();
        let mut changes = Vec::with_capacity(closed.len() * 2);
        let mut elses = Vec::new();
        for block in closed {
            changes.push((block.row + 1, 1));
            changes.push((block.end, -1));
            elses.extend(block.else_row);
        }
        changes.sort_unstable();
        elses.sort_unstable();
        Self {
            changes,
            next: 0,
            level: 0,
            elses,
            next_else: 0,
            proc_body: false,
        }
    }

    /// The level of `row`; rows are asked for in increasing order.
    pub fn at(&mut self, row: usize) -> usize {
        while let Some(&(at, change)) = self.changes.get(self.next) {
            if at > row {
                break;
            }
            self.level += change;
            self.next += 1;
        }
        while self.elses.get(self.next_else).is_some_and(|&e| e < row) {
            self.next_else += 1;
        }
        let on_else = self.elses.get(self.next_else) == Some(&row);
        let level = self.level - i32::from(on_else) + i32::from(self.proc_body);
        usize::try_from(level).unwrap_or(0)
    }

    /// The lines after this one are a PROC's body (`true`), or another
    /// program's (a `%` header: `false`).
    pub fn set_proc_body(&mut self, inside: bool) {
        self.proc_body = inside;
    }
}

/// Which bytes of a line's code are the language's words, whose case the
/// settings decide.
#[derive(Clone, Copy, Debug)]
pub enum Words<'a> {
    /// Every letter: a plain line is address words with numbers only.
    Letters,
    /// These spans, sorted.
    Spans(&'a [Span]),
}

/// One line to lay out.
#[derive(Clone, Copy, Debug)]
pub struct LineParts<'a> {
    pub content: Span,
    /// Where the skip level and block number at the start end.
    pub prefix_end: Option<usize>,
    /// Where the comment starts, or the content's end.
    pub code_end: usize,
    pub words: Words<'a>,
    /// Replacements (span, text), sorted, within the code.
    pub replacements: &'a [(Span, Vec<u8>)],
}

/// The skip level and block number of a block, where they end.
pub fn prefix_end(block: &Block) -> Option<usize> {
    block
        .number
        .map(|n| n.span.end)
        .or(block.skip.as_ref().map(|s| s.span.end))
}

/// A plain line's prefix end and block number digits, read from its bytes
/// as the parser reads them.
pub fn plain_prefix(source: &[u8], content: Span) -> (Option<usize>, Option<Span>) {
    let mut at = content.start + blanks(source, content.start, content.end);
    let mut end = None;
    let input = |at: usize| Input::new(&source[at..content.end], at);
    if let Ok((_, skip)) = parse_skip(input(at)) {
        at = skip.span.end;
        end = Some(at);
        at += blanks(source, at, content.end);
    }
    if let Ok((_, number)) = parse_block_number(input(at)) {
        return (Some(number.span.end), Some(number.digits));
    }
    (end, None)
}

/// The blanks (space, tab) from `at`, before `end`.
fn blanks(source: &[u8], at: usize, end: usize) -> usize {
    source[at..end]
        .iter()
        .take_while(|&&b| b == b' ' || b == b'\t')
        .count()
}

fn is_blank(byte: u8) -> bool {
    byte == b' ' || byte == b'\t'
}

/// Whether a plain line at level 0 with nothing to replace is laid out
/// already: nothing `write` would change. Most lines of a CAM program are;
/// asking costs a few instructions a byte (vectorised searches), writing
/// them out and comparing about forty.
pub fn is_tidy_plain(content: &[u8], code_len: usize, case: Case) -> bool {
    let code = &content[..code_len];
    let (Some(&first), Some(&last)) = (content.first(), code.last()) else {
        // A comment alone is tidy where it starts the line; an empty line
        // is left to `write`, which counts blank lines.
        return content.first() == Some(&b';');
    };
    if is_blank(first) || (code_len == content.len() && is_blank(last)) {
        return false;
    }
    // Folds over whole slices into a byte, without an early exit, so that
    // each vectorises: a search per line (memchr, memmem) cost more than
    // the line's bytes.
    let letters = |first: u8| {
        code.iter().fold(0u8, |any, &b| {
            any | u8::from(b.wrapping_sub(first) < 26) | u8::from(b == b'\t')
        })
    };
    let wrong = match case {
        Case::Upper => letters(b'a'),
        Case::Lower => letters(b'A'),
        Case::Keep => code.iter().fold(0u8, |any, &b| any | u8::from(b == b'\t')),
    };
    let doubled = code[..code.len() - 1]
        .iter()
        .zip(&code[1..])
        .fold(0u8, |any, (&a, &b)| {
            any | (u8::from(a == b' ') & u8::from(b == b' '))
        });
    wrong == 0 && doubled == 0
}

/// Writes `line` laid out at `depth` into `out` (cleared first).
pub fn write(
    source: &[u8],
    line: &LineParts,
    depth: usize,
    indent: &str,
    case: Case,
    out: &mut Vec<u8>,
) {
    out.clear();
    let content = line.content;
    let code_start = content.start + blanks(source, content.start, line.code_end);
    let mut code_end = line.code_end;
    while code_end > code_start && is_blank(source[code_end - 1]) {
        code_end -= 1;
    }
    let has_comment = line.code_end < content.end;
    let mut copier = Copier {
        source,
        words: line.words,
        word: 0,
        replacements: line.replacements,
        replacement: 0,
        case,
    };
    let mut rest = code_start;
    if let Some(prefix) = line.prefix_end.filter(|&p| p <= code_end) {
        copier.copy(code_start, prefix, out);
        rest = prefix + blanks(source, prefix, code_end);
        if rest < code_end {
            if depth > 0 {
                out.push(b' ');
                push_indent(out, indent, depth);
            } else if rest > prefix {
                out.push(b' ');
            }
        }
    } else if rest < code_end || has_comment {
        push_indent(out, indent, depth);
    }
    copier.copy(rest, code_end, out);
    if has_comment {
        // The blanks before a trailing comment stay as they were: comments
        // aligned in a column over several lines stay aligned where the
        // code before them keeps its length.
        if code_end > code_start {
            out.extend_from_slice(&source[code_end..line.code_end]);
        }
        out.extend_from_slice(&source[line.code_end..content.end]);
    }
}

fn push_indent(out: &mut Vec<u8>, indent: &str, depth: usize) {
    for _ in 0..depth {
        out.extend_from_slice(indent.as_bytes());
    }
}

/// Copies a plain line's `bytes`, blank runs made one blank, each byte
/// through `cased`.
#[inline(always)]
fn letters(bytes: &[u8], blank: &mut bool, out: &mut Vec<u8>, cased: impl Fn(&u8) -> u8) {
    for byte in bytes {
        if is_blank(*byte) {
            *blank = true;
            continue;
        }
        if *blank {
            out.push(b' ');
            *blank = false;
        }
        out.push(cased(byte));
    }
}

/// Copies code with blank runs made one blank, strings as they are, the
/// words' case set and the replacements made.
struct Copier<'a> {
    source: &'a [u8],
    words: Words<'a>,
    word: usize,
    replacements: &'a [(Span, Vec<u8>)],
    replacement: usize,
    case: Case,
}

impl Copier<'_> {
    fn copy(&mut self, from: usize, to: usize, out: &mut Vec<u8>) {
        out.reserve(to.saturating_sub(from));
        let mut at = from;
        let mut blank = false;
        while at < to {
            let next = self
                .replacements
                .get(self.replacement)
                .filter(|(span, _)| span.start < to);
            match next {
                Some((span, _)) if span.start < at => self.replacement += 1,
                Some((span, text)) if span.start == at => {
                    if blank {
                        out.push(b' ');
                        blank = false;
                    }
                    out.extend_from_slice(text);
                    at = span.end.max(at + 1);
                    self.replacement += 1;
                }
                Some((span, _)) => at = self.run(at, span.start, &mut blank, out),
                None => at = self.run(at, to, &mut blank, out),
            }
        }
    }

    /// Copies `from..to`, which holds no replacement; where it ends.
    fn run(&mut self, from: usize, to: usize, blank: &mut bool, out: &mut Vec<u8>) -> usize {
        let bytes = &self.source[from..to];
        if let Words::Letters = self.words {
            // A plain line: words and numbers, no strings; its own loop
            // for each case, the millions of CAM blocks go through it.
            match self.case {
                Case::Upper => letters(bytes, blank, out, u8::to_ascii_uppercase),
                Case::Lower => letters(bytes, blank, out, u8::to_ascii_lowercase),
                Case::Keep => letters(bytes, blank, out, |&b| b),
            }
            return to;
        }
        let mut i = 0;
        while i < bytes.len() {
            let byte = bytes[i];
            if is_blank(byte) {
                *blank = true;
                i += 1;
                continue;
            }
            if *blank {
                out.push(b' ');
                *blank = false;
            }
            if byte == b'"' || byte == b'\'' {
                // A string, as it is (a quote in a comment never gets here).
                let end = memchr::memchr(byte, &bytes[i + 1..]).map_or(bytes.len(), |p| i + p + 2);
                out.extend_from_slice(&bytes[i..end]);
                i = end;
                continue;
            }
            let cased = match (self.case, self.words) {
                (Case::Keep, _) => byte,
                (Case::Upper, Words::Letters) => byte.to_ascii_uppercase(),
                (Case::Lower, Words::Letters) => byte.to_ascii_lowercase(),
                (case, Words::Spans(_)) if byte.is_ascii_alphabetic() && self.is_word(from + i) => {
                    if case == Case::Upper {
                        byte.to_ascii_uppercase()
                    } else {
                        byte.to_ascii_lowercase()
                    }
                }
                _ => byte,
            };
            out.push(cased);
            i += 1;
        }
        to
    }

    /// Whether the letter at `at` belongs to one of the language's words.
    fn is_word(&mut self, at: usize) -> bool {
        match self.words {
            Words::Letters => true,
            Words::Spans(spans) => {
                while self.word < spans.len() && spans[self.word].end <= at {
                    self.word += 1;
                }
                spans.get(self.word).is_some_and(|s| s.start <= at)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn laid_out_as(text: &str, prefix: Option<usize>, code_end: usize, case: Case) -> String {
        let source = text.as_bytes();
        let line = LineParts {
            content: Span::new(0, source.len()),
            prefix_end: prefix,
            code_end,
            words: Words::Letters,
            replacements: &[],
        };
        let mut out = Vec::new();
        write(source, &line, 0, "  ", case, &mut out);
        String::from_utf8(out).expect("ascii")
    }

    fn laid_out(text: &str, prefix: Option<usize>, code_end: usize, depth: usize) -> String {
        let source = text.as_bytes();
        let line = LineParts {
            content: Span::new(0, source.len()),
            prefix_end: prefix,
            code_end,
            words: Words::Letters,
            replacements: &[],
        };
        let mut out = Vec::new();
        write(source, &line, depth, "  ", Case::Upper, &mut out);
        String::from_utf8(out).expect("ascii")
    }

    #[test]
    fn the_number_stays_first_and_the_indent_follows_it() {
        assert_eq!(laid_out("n10 g1  x10\t ", Some(3), 13, 1), "N10   G1 X10");
        assert_eq!(laid_out("   g1 x10", None, 9, 2), "    G1 X10");
        assert_eq!(laid_out("N10G1", Some(3), 5, 0), "N10G1");
        assert_eq!(laid_out("N10G1", Some(3), 5, 1), "N10   G1");
    }

    #[test]
    fn comments_and_strings_are_copied_as_they_are() {
        let text = "  msg(\"a  b\")   ; x  y  ";
        let line = LineParts {
            content: Span::new(0, text.len()),
            prefix_end: None,
            code_end: 16,
            words: Words::Spans(&[Span::new(2, 5)]),
            replacements: &[],
        };
        let mut out = Vec::new();
        write(text.as_bytes(), &line, 0, "  ", Case::Upper, &mut out);
        assert_eq!(out, b"MSG(\"a  b\")   ; x  y  ");
        assert_eq!(laid_out("    ; only  ", None, 4, 1), "  ; only  ");
        assert_eq!(laid_out("   \t", None, 4, 3), "");
    }

    #[test]
    fn a_tidy_plain_line_is_one_write_would_not_change() {
        for (text, case) in [
            ("N10 G1 X10 ; c  ", Case::Upper),
            ("N10G1X10", Case::Upper),
            ("n10 g1", Case::Lower),
            ("N10 g1", Case::Keep),
            ("; only", Case::Upper),
            ("", Case::Upper),
            (" G1", Case::Upper),
            ("G1 ", Case::Upper),
            ("G1  X1", Case::Upper),
            ("G1\tX1", Case::Upper),
            ("g1", Case::Upper),
            ("G1 ;", Case::Lower),
        ] {
            let code = text.find(';').unwrap_or(text.len());
            let prefix = if text.starts_with(['N', 'n']) {
                Some(3)
            } else {
                None
            };
            let written = laid_out_as(text, prefix, code, case);
            let tidy = is_tidy_plain(text.as_bytes(), code, case);
            // Tidy says unchanged; the converse is not promised.
            assert!(!tidy || written == text, "{text:?}: {written:?}");
            assert_eq!(tidy, written == text && !text.is_empty(), "{text:?}");
        }
    }

    #[test]
    fn a_plain_line_prefix_is_read_as_the_parser_reads_it() {
        let source = b" /1 N0100 G1";
        let (end, digits) = plain_prefix(source, Span::new(0, source.len()));
        assert_eq!(end, Some(9));
        assert_eq!(digits, Some(Span::new(5, 9)));
        assert_eq!(plain_prefix(b"G1 X1", Span::new(0, 5)), (None, None));
    }
}
