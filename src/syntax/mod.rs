//! The syntax layer: bytes in, a lossless tree of lines out.
//!
//! [`parse`] never fails: a line it cannot read keeps its bytes as an
//! `unparsed` span and yields one diagnostic, and the next line is read as
//! usual. Printing a [`Program`] copies the source lines, so
//! `print(parse(x)) == x` for every input. This layer knows spelling only:
//! no values, no rotations.

pub mod ahead;
pub(crate) mod block;
pub mod clean;
mod errors;
pub mod expr;
pub(crate) mod input;
pub mod kind;
pub mod lexer;
pub(crate) mod line_table;
pub mod lines;
pub mod macros;
pub mod plain;
pub mod tree;
pub(crate) mod visit;

pub use kind::{program_kind, ProgramKind};
pub use line_table::{Lines, LinesRecorder};

use crate::diagnostic::Diagnostic;
use crate::registry;
use crate::span::Span;
use errors::to_diagnostic;
use lexer::{Input, SyntaxError, SyntaxErrorKind};
use lines::{raw_lines, RawLine};
use tree::{Block, Line, LineKind};

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

/// The syntax diagnostics of a program, without keeping its tree: each line
/// is parsed and dropped, so memory holds one line's tree at a time. Plain
/// lines and the lines [`clean::reads_clean`] accepts have no error to find
/// and are not parsed.
pub fn diagnostics(source: &[u8]) -> Vec<Diagnostic> {
    let lines = plain::scanned_lines(source).map(|line| match line {
        plain::Scanned::Plain(_) => None,
        plain::Scanned::Other(raw) if clean::reads_clean(raw.content.of(source)) => None,
        plain::Scanned::Other(raw) => Some(raw),
    });
    diagnostics_of(source, lines)
}

/// The diagnostics of `lines`, `None` for one without an error to find.
fn diagnostics_of(source: &[u8], lines: impl Iterator<Item = Option<RawLine>>) -> Vec<Diagnostic> {
    let mut parser = LineParser::default();
    let mut found = Vec::new();
    // A loop, not `filter_map`: the adapter was not inlined and cost a third
    // as much as scanning the line.
    for line in lines {
        match line {
            // A line without an error changes nothing but the row.
            None => parser.pass_plain_line(),
            Some(raw) => found.extend(parser.line_diagnostic(source, raw)),
        }
    }
    found
}

/// The lines of `source` that name `word` (as the control writes it, in
/// capitals, or in lower case), parsed; every other line costs a byte
/// search. For readers that need a few lines among thousands: swivel data
/// in a setup file, axis names in machine data.
pub fn lines_naming<'s>(
    source: &'s [u8],
    word: &str,
) -> impl Iterator<Item = (tree::Line, Option<Diagnostic>)> + 's {
    let finder = WordFinder::new(word);
    let mut parser = LineParser::default();
    lines::raw_lines(source)
        .filter(move |raw| finder.in_line(raw.content.of(source)))
        .map(move |raw| parser.parse_line(source, raw))
}

/// A word as the control writes it, in capitals, or in lower case (mixed
/// case is not looked for), found by a byte search; built once, used on
/// many lines.
pub struct WordFinder {
    upper: memchr::memmem::Finder<'static>,
    lower: memchr::memmem::Finder<'static>,
}

impl WordFinder {
    pub fn new(word: &str) -> Self {
        let finder = |w: String| memchr::memmem::Finder::new(w.as_bytes()).into_owned();
        Self {
            upper: finder(word.to_ascii_uppercase()),
            lower: finder(word.to_ascii_lowercase()),
        }
    }

    pub fn in_line(&self, line: &[u8]) -> bool {
        self.upper.find(line).is_some() || self.lower.find(line).is_some()
    }
}

/// Parses line after line, remembering the one thing that crosses lines: a
/// call left open at the end of the previous line (as the paper prints
/// CYCLE600 over two lines), so the next line's error can say so.
#[derive(Default)]
pub struct LineParser {
    row: usize,
    open_call: Option<OpenCall>,
    /// Where a block's statements are gathered, kept from line to line.
    statements: Vec<tree::Statement>,
}

struct OpenCall {
    row: usize,
    name: String,
}

impl LineParser {
    /// Steps over a line without an error (one [`plain::is_plain`] or
    /// [`clean::reads_clean`] accepts), as parsing it would.
    pub fn pass_plain_line(&mut self) {
        self.pass_plain_lines(1);
    }

    /// Steps over `count` lines [`plain::is_plain`] accepts.
    pub fn pass_plain_lines(&mut self, count: usize) {
        self.row += count;
        if count > 0 {
            self.open_call = None;
        }
    }

    pub fn parse_line(&mut self, source: &[u8], raw: RawLine) -> (Line, Option<Diagnostic>) {
        let (kind, diagnostic) = self.read_line(source, raw);
        let mut line = Line { raw, kind };
        if let LineKind::Block(block) = &mut line.kind {
            block.statements = block::take_gathered(&mut self.statements);
        }
        (line, diagnostic)
    }

    /// [`LineParser::parse_line`]'s diagnostic alone, for the syntax pass,
    /// which keeps no tree: the block's statements are dropped where they
    /// were gathered instead of being moved into a vector of their own.
    fn line_diagnostic(&mut self, source: &[u8], raw: RawLine) -> Option<Diagnostic> {
        let (_, diagnostic) = self.read_line(source, raw);
        if self.statements.capacity() > block::MANY_STATEMENTS {
            // Not held on to for the next line (a long block of words).
            self.statements = Vec::new();
        }
        diagnostic
    }

    /// The line's kind, a block's statements left in `self.statements`, and
    /// its diagnostic. Inlined into both readers, so that its result (about
    /// 300 bytes) is built where it is used, not copied there.
    #[inline(always)]
    fn read_line(&mut self, source: &[u8], raw: RawLine) -> (LineKind, Option<Diagnostic>) {
        self.row += 1;
        let content = raw.content.of(source);
        let continued = self.open_call.take();
        let (kind, error) = read_line_kind(content, raw.content.start, &mut self.statements);
        let diagnostic = error.map(|error| {
            if let (Some(open), LineKind::Block(block)) = (&continued, &kind) {
                if self.statements.is_empty() {
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
        (kind, diagnostic)
    }
}

impl LineParser {
    /// [`Self::parse_line`], the line read as the control reads it when it
    /// names one of `macros` (see [`macros`]): the tree of its expansion,
    /// every span mapped back to the source, and the expansion.
    pub fn parse_line_expanding(
        &mut self,
        source: &[u8],
        raw: RawLine,
        macros: &macros::Macros,
    ) -> (Line, Option<Diagnostic>, Option<macros::Expansion>) {
        let Some(expansion) = macros.expand(raw.content.of(source), raw.content.start) else {
            let (line, diagnostic) = self.parse_line(source, raw);
            return (line, diagnostic, None);
        };
        self.row += 1;
        self.open_call = None;
        let text = &expansion.text;
        let (kind, error) = parse_line_kind(text, 0, &mut self.statements);
        let mut line = Line { raw, kind };
        expansion.map_line(&mut line);
        let diagnostic = error.map(|error| {
            let read = RawLine {
                content: Span::new(0, text.len()),
                ending: raw.ending,
            };
            expansion.diagnostic_in_source(to_diagnostic(text, read, &error))
        });
        (line, diagnostic, Some(expansion))
    }
}

/// The longest block the control takes, in characters, comment included:
/// the length commonly quoted (N008 says what it rests on).
pub const BLOCK_CHARACTERS: usize = 512;

/// A block's length in characters, as [`BLOCK_CHARACTERS`] counts them: a
/// UTF-8 sequence is one, and in a line that is no UTF-8 every byte is one
/// (Latin-1).
/// Never more than the line's bytes: a line of at most
/// [`BLOCK_CHARACTERS`] bytes needs no count.
pub fn block_characters(bytes: &[u8]) -> usize {
    match std::str::from_utf8(bytes) {
        Ok(text) => text.chars().count(),
        Err(_) => bytes.len(),
    }
}

/// Lines longer than this (in bytes) are not read into a tree, whatever they
/// hold: a tree costs about 50 bytes a byte of source (a line of address
/// words alone, 80 bytes a word), and the control takes 512 characters a
/// block. The bytes stay as they are, with an error (S009).
pub const MAX_PARSED_LINE: usize = 64 * 1024;

/// The line's kind and tree, its statements gathered in `scratch` (see
/// [`block::parse_block_with`]).
#[inline]
pub(crate) fn parse_line_kind(
    content: &[u8],
    start: usize,
    scratch: &mut Vec<tree::Statement>,
) -> (LineKind, Option<SyntaxError>) {
    let (mut kind, error) = read_line_kind(content, start, scratch);
    if let LineKind::Block(block) = &mut kind {
        block.statements = block::take_gathered(scratch);
    }
    (kind, error)
}

/// The line's kind and tree, a block's statements left in `scratch`
/// (cleared first; see [`block::parse_block_gathered`]); inlined into its
/// two callers, for the reason [`LineParser::read_line`] is.
#[inline(always)]
fn read_line_kind(
    content: &[u8],
    start: usize,
    scratch: &mut Vec<tree::Statement>,
) -> (LineKind, Option<SyntaxError>) {
    scratch.clear();
    if content.len() > MAX_PARSED_LINE {
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
            header_error(content, start),
        );
    }
    if is_archive_path(content) {
        return (
            LineKind::Path {
                directory: Span::new(start + ARCHIVE_PATH.len(), start + content.len()),
            },
            None,
        );
    }
    let (block, error) = block::parse_block_gathered(Input::new(content, start), scratch);
    (LineKind::Block(block), error)
}

/// How an archive's line naming its target directory begins
/// (`;$PATH=/_N_MPF_DIR`): a line of its own to the parser, not a comment.
const ARCHIVE_PATH: &[u8] = b";$PATH=";

/// Whether a line's content is an archive's `;$PATH=` line (any case).
pub(crate) fn is_archive_path(content: &[u8]) -> bool {
    content
        .get(..ARCHIVE_PATH.len())
        .is_some_and(|start| start.eq_ignore_ascii_case(ARCHIVE_PATH))
}

/// A character the control's name in a header `%_N_<name>_<type>` cannot
/// hold: a program's name is letters, digits and `_` (Siemens, Programming
/// Manual NC programming, "Subprogram names": "Permissible characters").
/// Other headers (`%Flange3_MPF`, a lone `%` of a CAM post) are not read.
fn header_error(content: &[u8], start: usize) -> Option<SyntaxError> {
    const PREFIX: &[u8] = b"%_N_";
    if content.len() < PREFIX.len() || !content[..PREFIX.len()].eq_ignore_ascii_case(PREFIX) {
        return None;
    }
    let name = &content[PREFIX.len()..];
    let end = name
        .iter()
        .position(|b| b.is_ascii_whitespace())
        .unwrap_or(name.len());
    let bad = name[..end]
        .iter()
        .position(|&b| !(b.is_ascii_alphanumeric() || b == b'_'))?;
    Some(SyntaxError::new(
        start + PREFIX.len() + bad,
        SyntaxErrorKind::NotInProgramName,
    ))
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
