//! The syntax layer: bytes in, a lossless tree of lines out.
//!
//! [`parse`] never fails: a line it cannot read keeps its bytes as an
//! `unparsed` span and yields one diagnostic, and the next line is read as
//! usual. Printing a [`Program`] copies the source lines, so
//! `print(parse(x)) == x` for every input. This layer knows spelling only:
//! no values, no rotations.

pub mod block;
pub mod expr;
pub mod input;
pub mod lexer;
pub mod lines;
pub mod plain;
pub mod tree;
pub mod visit;

use std::cell::Cell;

use crate::diagnostic::Diagnostic;
use crate::registry;
use crate::span::Span;
use lexer::{Input, SyntaxError, SyntaxErrorKind};
use lines::{raw_lines, RawLine};
use tree::{Block, Line, LineKind, StatementKind};

/// A parsed program: its lines, in order, covering every byte of the source.
#[derive(Debug)]
pub struct Program<'src> {
    pub source: &'src [u8],
    pub lines: Vec<Line>,
    pub diagnostics: Vec<Diagnostic>,
}

impl Program<'_> {
    /// The program's bytes, rebuilt from its lines.
    pub fn print(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.source.len());
        for line in &self.lines {
            out.extend_from_slice(line.raw.full().of(self.source));
        }
        out
    }

    pub fn blocks(&self) -> impl Iterator<Item = (&Line, &Block)> {
        self.lines.iter().filter_map(|line| match &line.kind {
            LineKind::Block(block) => Some((line, block)),
            _ => None,
        })
    }
}

/// Parses a whole program.
pub fn parse(source: &[u8]) -> Program<'_> {
    let mut parser = LineParser::default();
    let mut lines = Vec::new();
    let mut diagnostics = Vec::new();
    for raw in raw_lines(source) {
        let (line, diagnostic) = parser.parse_line(source, raw);
        lines.push(line);
        diagnostics.extend(diagnostic);
    }
    Program {
        source,
        lines,
        diagnostics,
    }
}

/// A program's lines, each parsed when asked for: memory holds where every
/// [`STRIDE`]th line starts and a bit a line for whether it is plain (a
/// quarter of a byte a line), never the whole tree nor every line's start,
/// however large the program.
pub struct Lines<'src> {
    pub source: &'src [u8],
    len: usize,
    /// Where lines 0, `STRIDE`, 2 `STRIDE`, ... start: another line is found
    /// by reading on from the one before it that is known.
    strided_starts: Vec<usize>,
    /// Bit `n % 64` of word `n / 64`: line `n` is plain ([`plain::is_plain`]),
    /// asked by every pass over the lines.
    plain: Vec<u64>,
    /// The line found last and where it starts: the passes over the lines go
    /// forward, so the next line asked for is mostly read on from there.
    last: Cell<(usize, usize)>,
}

/// One line in this many has its start kept.
const STRIDE: usize = 32;

impl<'src> Lines<'src> {
    pub fn new(source: &'src [u8]) -> Self {
        let mut recorder = LinesRecorder::default();
        plain::scanned_lines(source).for_each(|line| recorder.record(&line));
        recorder.finish(source)
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Line `index` holds only address words with numbers (see [`plain::is_plain`]).
    pub fn is_plain(&self, index: usize) -> bool {
        assert!(index < self.len, "line {index} of {}", self.len);
        self.plain[index / 64] & (1 << (index % 64)) != 0
    }

    /// Line `index` (0-based): its content and ending, read on from the
    /// nearest line before it whose start is known.
    pub fn raw(&self, index: usize) -> RawLine {
        assert!(index < self.len, "line {index} of {}", self.len);
        let strided = index / STRIDE * STRIDE;
        let (mut at, mut start) = match self.last.get() {
            (last, start) if (strided..=index).contains(&last) => (last, start),
            _ => (strided, self.strided_starts[index / STRIDE]),
        };
        while at < index {
            start = lines::line_from(self.source, start).full().end;
            at += 1;
        }
        self.last.set((index, start));
        lines::line_from(self.source, start)
    }

    /// The tree of line `index` (0-based).
    pub fn parse(&self, index: usize) -> Line {
        let raw = self.raw(index);
        let (kind, _) = parse_line_kind(raw.content.of(self.source), raw.content.start);
        Line { raw, kind }
    }
}

/// Builds a [`Lines`] table from a pass over the lines that another job
/// makes anyway (`check`'s rules), instead of scanning the file again.
#[derive(Default)]
pub struct LinesRecorder {
    len: usize,
    strided_starts: Vec<usize>,
    plain: Vec<u64>,
}

impl LinesRecorder {
    /// The next line, in order from the first.
    pub fn record(&mut self, line: &plain::Scanned) {
        let index = self.len;
        if index.is_multiple_of(STRIDE) {
            self.strided_starts.push(line.raw().content.start);
        }
        if index.is_multiple_of(64) {
            self.plain.push(0);
        }
        if let (plain::Scanned::Plain(_), Some(word)) = (line, self.plain.last_mut()) {
            *word |= 1 << (index % 64);
        }
        self.len += 1;
    }

    /// The table of the lines recorded, which must be all of `source`'s.
    pub fn finish(self, source: &[u8]) -> Lines<'_> {
        Lines {
            source,
            len: self.len,
            strided_starts: self.strided_starts,
            plain: self.plain,
            last: Cell::new((0, 0)),
        }
    }
}

/// The syntax diagnostics of a program, without keeping its tree: each line
/// is parsed and dropped, so memory holds one line's tree at a time.
pub fn diagnostics(source: &[u8]) -> Vec<Diagnostic> {
    let lines = plain::scanned_lines(source).map(|line| match line {
        plain::Scanned::Plain(_) => None,
        plain::Scanned::Other(raw) => Some(raw),
    });
    diagnostics_of(source, lines)
}

impl Lines<'_> {
    /// [`diagnostics`] from the line table: no second scan of the file.
    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        let lines = (0..self.len()).map(|index| (!self.is_plain(index)).then(|| self.raw(index)));
        diagnostics_of(self.source, lines)
    }
}

/// The diagnostics of `lines`, `None` for a plain one.
fn diagnostics_of(source: &[u8], lines: impl Iterator<Item = Option<RawLine>>) -> Vec<Diagnostic> {
    let mut parser = LineParser::default();
    let mut found = Vec::new();
    // A loop, not `filter_map`: the adapter was not inlined and cost a third
    // as much as scanning the line.
    for line in lines {
        match line {
            // A plain line has no error to find.
            None => parser.pass_plain_line(),
            Some(raw) => found.extend(parser.parse_line(source, raw).1),
        }
    }
    found
}

/// Parses line after line, remembering the one thing that crosses lines: a
/// call left open at the end of the previous line (as the paper prints
/// CYCLE600 over two lines), so the next line's error can say so.
#[derive(Default)]
pub struct LineParser {
    row: usize,
    open_call: Option<OpenCall>,
}

struct OpenCall {
    row: usize,
    name: String,
}

impl LineParser {
    /// Steps over a line [`plain::is_plain`] accepts, as parsing it would.
    pub fn pass_plain_line(&mut self) {
        self.row += 1;
        self.open_call = None;
    }

    pub fn parse_line(&mut self, source: &[u8], raw: RawLine) -> (Line, Option<Diagnostic>) {
        self.row += 1;
        let content = raw.content.of(source);
        let continued = self.open_call.take();
        let (kind, error) = parse_line_kind(content, raw.content.start);
        let diagnostic = error.map(|error| {
            if let (Some(open), LineKind::Block(block)) = (&continued, &kind) {
                if block.statements.is_empty() {
                    return continuation(open, block.unparsed.unwrap_or(raw.content));
                }
            }
            if let (SyntaxErrorKind::UnclosedBracket(b'('), LineKind::Block(block)) =
                (&error.kind, &kind)
            {
                self.open_call = open_call_name(source, block, error.at).map(|name| OpenCall {
                    row: self.row,
                    name,
                });
            }
            to_diagnostic(source, raw, &error)
        });
        (Line { raw, kind }, diagnostic)
    }
}

/// Lines longer than this (in bytes) are not read into a tree, unless they
/// are plain (address words with numbers, which have no tree to build): a
/// tree costs about 50 bytes a byte of source, and the control takes 512
/// characters a block. The bytes stay as they are, with an error (S009).
pub const MAX_PARSED_LINE: usize = 64 * 1024;

fn parse_line_kind(content: &[u8], start: usize) -> (LineKind, Option<SyntaxError>) {
    if content.len() > MAX_PARSED_LINE && !plain::is_plain(content) {
        let block = Block {
            unparsed: Some(Span::new(start, start + content.len())),
            ..Block::default()
        };
        let error = SyntaxError::new(start, SyntaxErrorKind::TooLong);
        return (LineKind::Block(block), Some(error));
    }
    if content.first() == Some(&b'%') {
        return (
            LineKind::Header {
                name: Span::new(start + 1, start + content.len()),
            },
            None,
        );
    }
    const PATH: &[u8] = b";$PATH=";
    if content.len() >= PATH.len() && content[..PATH.len()].eq_ignore_ascii_case(PATH) {
        return (
            LineKind::Path {
                directory: Span::new(start + PATH.len(), start + content.len()),
            },
            None,
        );
    }
    let (block, error) = block::parse_block(Input::new(content, start));
    (LineKind::Block(block), error)
}

/// The name of the call whose `(` at `open` was left unclosed, if it is one.
fn open_call_name(source: &[u8], block: &Block, open: usize) -> Option<String> {
    let unparsed = block.unparsed?;
    let text = source.get(unparsed.start..open)?;
    let name = text.trim_ascii_end();
    let start = name
        .iter()
        .rposition(|&b| !lexer::is_name_char(b))
        .map_or(0, |p| p + 1);
    let name = &name[start..];
    (!name.is_empty()).then(|| String::from_utf8_lossy(name).into_owned())
}

fn continuation(open: &OpenCall, unparsed: Span) -> Diagnostic {
    registry::syntax::CONTINUED_BLOCK
        .at(unparsed)
        .message(format!(
            "this line continues `{}(` from line {}, but a block ends at the end of its line",
            open.name, open.row
        ))
        .label("continuation of the previous line")
        .help(format!(
            "join this line to line {}: on the control a block is one line",
            open.row
        ))
}

/// Turns the parser's stop into a diagnostic at the offending bytes.
fn to_diagnostic(source: &[u8], raw: RawLine, error: &SyntaxError) -> Diagnostic {
    let diagnostic = describe(source, raw, error);
    match error.meant {
        Some(keyword) => diagnostic.help(format!(
            "did you mean `{keyword}`? The block's first word is no keyword, so it reads as a subprogram call"
        )),
        None => diagnostic,
    }
}

fn describe(source: &[u8], raw: RawLine, error: &SyntaxError) -> Diagnostic {
    let at = error.at.min(raw.content.end);
    let line_end = raw.content.end;
    let one = Span::new(at, (at + 1).min(line_end).max(at));
    let rest = Span::new(at, line_end);
    let show = |span: Span| String::from_utf8_lossy(span.of(source)).into_owned();
    match &error.kind {
        SyntaxErrorKind::UnclosedString => {
            registry::syntax::UNCLOSED_STRING.at(rest)
                .message("string is not closed on this line")
                .label("this string has no closing `\"`")
                .help("add the closing `\"`; strings cannot span lines")
        }
        SyntaxErrorKind::UnclosedBracket(open) => {
            let (open, close) = (*open as char, if *open == b'(' { ')' } else { ']' });
            let help = if is_call_paren(source, raw.content.start, at) {
                format!("add the missing `{close}`; a call broken over several lines (as the paper prints CYCLE600) must be joined into one line")
            } else {
                format!("add the missing `{close}`")
            };
            registry::syntax::UNBALANCED_BRACKET.at(one)
                .message(format!("`{open}` is not closed on this line"))
                .label(format!("this `{open}` has no matching `{close}`"))
                .help(help)
        }
        SyntaxErrorKind::UnmatchedClose(close) => {
            let close = *close as char;
            registry::syntax::UNBALANCED_BRACKET.at(one)
                .message(format!("`{close}` without a matching opening bracket"))
                .label("nothing to close here")
                .help(format!(
                    "remove this `{close}` or add the opening bracket it closes"
                ))
        }
        SyntaxErrorKind::InvalidNumber(why) => registry::syntax::INVALID_NUMBER.at(number_span(source, at, line_end),
        )
        .message(format!(
            "invalid number `{}`",
            show(number_span(source, at, line_end))
        ))
        .label("not a number")
        .help(why.to_string()),
        SyntaxErrorKind::UnknownCharacter => {
            let help = match source.get(at) {
                Some(b'^') => {
                    "Sinumerik has no power operator: write POT(x) for x², or EXP(y*LN(x))"
                }
                Some(b'!') => "write `<>` for not equal and NOT for negation",
                _ => "remove it, or put it in a comment after `;` or inside a string",
            };
            registry::syntax::UNKNOWN_CHARACTER.at(char_span(source, at, line_end),
            )
            .message(format!(
                "character {} has no meaning here",
                describe_char(source, at, line_end)
            ))
            .label("unknown character")
            .help(help)
        }
        SyntaxErrorKind::MissingValue => registry::syntax::MISSING_VALUE.at(one,
        )
        .message(format!("address `{}` has no value", show(one)))
        .label("value missing")
        .help("write the value directly after the address (`X0`, not `X`) or as `X=expression`"),
        SyntaxErrorKind::ChainTooLong => {
            registry::syntax::NESTING_TOO_DEEP.at(one)
                .message(format!(
                    "more than {} operators in a row in one expression",
                    expr::MAX_DEPTH
                ))
                .label("too many operators")
                .help("split the expression over several assignments (a block takes 512 characters on the control)")
        }
        SyntaxErrorKind::TooDeep => {
            registry::syntax::NESTING_TOO_DEEP.at(one)
                .message(format!(
                    "expression nested deeper than {} levels",
                    expr::MAX_DEPTH
                ))
                .label("too deep")
                .help("split the expression over several assignments")
        }
        SyntaxErrorKind::TooLong => {
            registry::syntax::TOO_LONG_TO_READ.at(one)
                .message(format!(
                    "block of {} bytes: too long to read (the control takes at most 512 characters a block)",
                    raw.content.len()
                ))
                .label("too long")
                .help("split it into blocks of at most 512 characters")
        }
        SyntaxErrorKind::Trailing { after, help } => {
            registry::syntax::UNEXPECTED_TOKEN.at(word_span(source, at, line_end))
                .message(format!(
                    "unexpected `{}` after {after}",
                    show_token(source, at, line_end)
                ))
                .label(format!("nothing may follow {after} in its block"))
                .help(*help)
        }
        SyntaxErrorKind::NotAlone(what) => {
            registry::syntax::UNEXPECTED_TOKEN.at(word_span(source, at, line_end))
                .message(format!("{what} must stand alone in its block"))
                .label("after other statements")
                .help("move the statements before it into a block of their own")
        }
        SyntaxErrorKind::Expected(what) => {
            let found = if at >= line_end {
                "the end of the line".to_string()
            } else {
                format!("`{}`", show_token(source, at, line_end))
            };
            registry::syntax::UNEXPECTED_TOKEN.at(if at >= line_end {
                    Span::new(at, at)
                } else {
                    one
                },
            )
            .message(format!("expected {what}, found {found}"))
            .label(format!("expected {what}"))
            .help("check the statement's spelling against the Sinumerik programming manual")
        }
    }
}

/// Whether the `(` at `at` follows a name, as in `CYCLE600 (`.
fn is_call_paren(source: &[u8], line_start: usize, at: usize) -> bool {
    source[line_start..at]
        .iter()
        .rev()
        .find(|&&b| !lexer::is_blank(b))
        .is_some_and(|&b| lexer::is_name_char(b))
}

/// The bytes of a malformed number, up to the next blank or separator.
fn number_span(source: &[u8], at: usize, end: usize) -> Span {
    let len = source[at..end]
        .iter()
        .take_while(|&&b| b.is_ascii_alphanumeric() || b == b'.' || b == b'\'')
        .count();
    Span::new(at, at + len.max(1).min(end - at))
}

/// One character: a whole UTF-8 sequence when it is one, else one byte.
fn char_span(source: &[u8], at: usize, end: usize) -> Span {
    let len = (1..=4)
        .filter(|&n| at + n <= end)
        .find(|&n| std::str::from_utf8(&source[at..at + n]).is_ok())
        .unwrap_or(1);
    Span::new(at, (at + len).min(end))
}

/// A whole name if one starts at `at`, else one character.
/// The name at `at` (`$` included), or its one character.
fn word_span(source: &[u8], at: usize, end: usize) -> Span {
    let len = source[at.min(end)..end]
        .iter()
        .take_while(|&&b| lexer::is_name_char(b) || b == b'$')
        .count();
    Span::new(at, (at + len.max(1)).min(end).max(at))
}

fn show_token(source: &[u8], at: usize, end: usize) -> String {
    let len = source[at..end]
        .iter()
        .take_while(|&&b| lexer::is_name_char(b))
        .count();
    if len > 1 {
        String::from_utf8_lossy(&source[at..at + len]).into_owned()
    } else {
        show_char(source, at, end)
    }
}

/// `` `#` ``, `` `ä` (Latin-1 byte 0xE4) `` or `byte 0x01`, for messages.
fn describe_char(source: &[u8], at: usize, end: usize) -> String {
    let span = char_span(source, at, end);
    let bytes = span.of(source);
    match (std::str::from_utf8(bytes), bytes) {
        (Ok(text), _) if !text.chars().any(char::is_control) => format!("`{text}`"),
        (Err(_), &[byte]) if byte >= 0xA0 => {
            format!("`{}` (Latin-1 byte 0x{byte:02X})", byte as char)
        }
        _ => bytes
            .iter()
            .map(|b| format!("byte 0x{b:02X}"))
            .collect::<Vec<_>>()
            .join(" "),
    }
}

fn show_char(source: &[u8], at: usize, end: usize) -> String {
    let span = char_span(source, at, end);
    match std::str::from_utf8(span.of(source)) {
        Ok(text) if !text.chars().any(char::is_control) => text.to_string(),
        _ => span
            .of(source)
            .iter()
            .map(|b| format!("\\x{b:02X}"))
            .collect(),
    }
}

/// What kind of program a file holds, by its name or its content.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProgramKind {
    Main,
    Subprogram,
}

/// What kind of program a file holds: by its extension (`.SPF`, `.MPF`), else
/// by a `%_N_..._SPF` header or a PROC line among its first blocks.
pub fn program_kind(file_name: Option<&str>, source: &[u8]) -> ProgramKind {
    if let Some(name) = file_name {
        let upper = name.to_ascii_uppercase();
        if upper.ends_with(".SPF") {
            return ProgramKind::Subprogram;
        }
        if upper.ends_with(".MPF") {
            return ProgramKind::Main;
        }
    }
    let mut parser = LineParser::default();
    for raw in raw_lines(source).take(200) {
        let (line, _) = parser.parse_line(source, raw);
        let is_sub = match &line.kind {
            LineKind::Header { name } => name.of(source).to_ascii_uppercase().ends_with(b"_SPF"),
            LineKind::Block(block) => block
                .statements
                .iter()
                .any(|s| matches!(s.kind, StatementKind::Proc(_))),
            LineKind::Path { .. } => false,
        };
        if is_sub {
            return ProgramKind::Subprogram;
        }
    }
    ProgramKind::Main
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The line table keeps every 32nd line's start; the lines it gives
        /// back, in any order, are the ones splitting the source gives,
        /// endings included, and so are their plain bits.
        #[test]
        fn the_line_table_gives_back_every_line(
            text in "[aN1 ;\r\n]{0,60}|([aN1 X;]{0,6}(\r\n|\n|\r)){0,200}[aN1 ]{0,3}",
            order in proptest::collection::vec(proptest::prelude::any::<usize>(), 0..300),
        ) {
            let source = text.as_bytes();
            let lines = Lines::new(source);
            let expected: Vec<plain::Scanned> = plain::scanned_lines(source).collect();
            proptest::prop_assert_eq!(lines.len(), expected.len());
            let forward = 0..expected.len();
            let shuffled = order.iter().map(|n| n % expected.len().max(1));
            for index in forward.chain(shuffled).filter(|&n| n < expected.len()) {
                proptest::prop_assert_eq!(lines.raw(index), expected[index].raw());
                let plain = matches!(expected[index], plain::Scanned::Plain(_));
                proptest::prop_assert_eq!(lines.is_plain(index), plain);
            }
        }
    }
}
