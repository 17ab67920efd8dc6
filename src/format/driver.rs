//! One program formatted: the model built once, then each line in order
//! laid out at its level, with its words' case and the renumbering's
//! replacements, unless it is one to leave; blank lines in a row limited.
//! The result is a list of edits, one per changed line, so that an
//! archive's member is formatted like any file and a diff names lines.

use std::collections::HashSet;
use std::ops::Range;

use crate::diagnostic::Diagnostic;
use crate::edit::Edit;
use crate::format::case::language_words;
use crate::format::layout::{
    is_tidy_plain, plain_prefix, prefix_end, write, Depths, LineParts, Words,
};
use crate::format::protect::{hmi_rows, is_data_file, mentions_hmi};
use crate::format::renumber::{self, Plan};
use crate::format::{Case, Settings};
use crate::semantic::addresses::{self, is_end_word};
use crate::semantic::uses::Uses;
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::lexer::find_ignoring_case;
use crate::syntax::lines::raw_lines;
use crate::syntax::tree::{Block, LineKind, StatementKind};
use crate::syntax::ProgramKind;

/// What the formatter says about a file besides its edits.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    /// Where it applies (an empty span at 0 for the whole file).
    pub span: Span,
    pub message: String,
    /// Something asked for was not done (`--renumber` refused).
    pub refused: bool,
}

/// A program formatted.
#[derive(Debug, Default)]
pub struct Formatted {
    /// One edit a changed line (or a blank line removed), in order.
    pub edits: Vec<Edit>,
    /// Syntax errors: when there are any, the program is left as it is.
    pub syntax: Vec<Diagnostic>,
    pub notes: Vec<Note>,
    /// Blocks numbered again.
    pub renumbered: usize,
}

/// Formats `source`, the program `name` (a path or an archive's member
/// name, whose suffix tells a definition file).
pub fn format(name: &str, source: &[u8], kind: ProgramKind, settings: &Settings) -> Formatted {
    format_with(name, source, kind, settings, false, None)
}

/// [`format`], laying out only the lines `rows` (0-based): an editor's
/// range. The lines before them are read for what carries over (the
/// levels, the program's end, blank lines in a row), not laid out.
pub fn format_rows(
    name: &str,
    source: &[u8],
    kind: ProgramKind,
    settings: &Settings,
    rows: Range<usize>,
) -> Formatted {
    format_with(name, source, kind, settings, false, Some(rows))
}

/// [`format`], the edits of neighbouring lines merged into one (with the
/// line endings between them): the same bytes once applied, in a few large
/// edits instead of one a line, for a file written whole (a program whose
/// every line changes took four times its size in per-line edits). A diff
/// or an editor's range wants [`format`]'s.
pub fn format_merged(
    name: &str,
    source: &[u8],
    kind: ProgramKind,
    settings: &Settings,
) -> Formatted {
    format_with(name, source, kind, settings, true, None)
}

fn format_with(
    name: &str,
    source: &[u8],
    kind: ProgramKind,
    settings: &Settings,
    merge: bool,
    rows: Option<Range<usize>>,
) -> Formatted {
    let mut formatted = Formatted::default();
    if is_data_file(name) {
        formatted.notes.push(Note {
            span: Span::new(0, 0),
            message: "a definition file: its data are left as they are".to_string(),
            refused: false,
        });
        return formatted;
    }
    let model = Model::build(source, kind);
    let plan = match settings.renumber {
        Some((start, step)) => match renumber::plan(&model, start, step) {
            Ok(plan) => Some(plan),
            Err(refusal) => {
                formatted.notes.push(Note {
                    span: refusal.span,
                    message: format!("not renumbered: {}", refusal.message),
                    refused: true,
                });
                None
            }
        },
        None => None,
    };
    let rows = rows.unwrap_or(0..usize::MAX);
    let laid = match lay_out(&model, settings, plan.as_ref(), merge, &rows) {
        Ok(laid) => {
            if let Some(plan) = plan.filter(|p| p.blocks > 0) {
                formatted.renumbered = plan.blocks;
                formatted.notes.push(Note {
                    span: Span::new(0, 0),
                    message: format!(
                        "{} block numbers changed: a block search, an ASUB or another program's `CALL ... BLOCK ... TO` naming them is not seen here",
                        plan.blocks
                    ),
                    refused: false,
                });
            }
            laid
        }
        Err(span) => {
            formatted.notes.push(Note {
                span,
                message: "not renumbered: this block number or reference stands in a line left as it is (HMI region, emitted code, a macro, after the program's end)".to_string(),
                refused: true,
            });
            lay_out(&model, settings, None, merge, &rows).unwrap_or_default()
        }
    };
    // An error in what the control never reads (after the end) stops
    // nothing; any other leaves the program as it is.
    let unread = |at: usize| {
        let after = laid.unread.partition_point(|span| span.end <= at);
        laid.unread.get(after).is_some_and(|span| span.start <= at)
    };
    if model.syntax.iter().any(|d| !unread(d.span.start)) {
        formatted.notes.clear();
        formatted.renumbered = 0;
        formatted.syntax = model.syntax;
        return formatted;
    }
    formatted.edits = laid.edits;
    formatted
}

/// The lines' edits, and the lines after the program's end (left as they
/// are: the control does not read them), as spans in order.
#[derive(Default)]
struct Laid {
    edits: Vec<Edit>,
    unread: Vec<Span>,
}

/// The edits of the lines `rows` (every line read); `Err` with the span of
/// a renumbering's replacement that falls in a line left as it is.
fn lay_out(
    model: &Model,
    settings: &Settings,
    plan: Option<&Plan>,
    merge: bool,
    rows: &Range<usize>,
) -> Result<Laid, Span> {
    let source = model.source;
    let structure = model.structure();
    let mut depths = Depths::new(model);
    let hmi = if mentions_hmi(source) {
        hmi_rows(source)
    } else {
        Vec::new()
    };
    let mut next_hmi = 0;
    let macro_lines: Vec<Span> = model.macro_uses.iter().map(|u| u.span).collect();
    let mut next_macro = 0;
    let replacements = plan.map_or(&[][..], |p| &p.replacements[..]);
    let mut next_replacement = 0;
    let mut end = ProgramEnd::new(model);
    let mut edits = Vec::new();
    let mut unread: Vec<Span> = Vec::new();
    let mut out = Vec::new();
    let mut words = Vec::new();
    // The user's names, where they take the case too.
    let names = (settings.case_names && settings.case != Case::Keep).then(|| Uses::of(model));
    let mut blank_run = 0;
    let mut emitted_run = false;
    for (row, raw) in raw_lines(source).enumerate() {
        let content = raw.content;
        let depth = depths.at(row).min(MAX_INDENT_LEVELS);
        let first = next_replacement;
        while replacements
            .get(next_replacement)
            .is_some_and(|(span, _)| span.start < content.end.max(content.start + 1))
        {
            next_replacement += 1;
        }
        let own = &replacements[first..next_replacement];
        while macro_lines
            .get(next_macro)
            .is_some_and(|s| s.end <= content.start)
        {
            next_macro += 1;
        }
        let uses_macro = macro_lines
            .get(next_macro)
            .is_some_and(|s| s.start < content.end);
        while hmi.get(next_hmi).is_some_and(|rows| rows.end <= row) {
            next_hmi += 1;
        }
        let hmi_owns = hmi.get(next_hmi).is_some_and(|rows| rows.start <= row);
        // The `; sinuprep:` line, the frames or CYCLE800 the block
        // structure knows sinuprep emitted under it, and the assignments of
        // its results (`_CYC600_1=...`) the GUD form writes there.
        let marked = structure.marked_call(row).is_some();
        emitted_run = marked
            || (emitted_run
                && (structure.is_emitted(row)
                    || find_ignoring_case(content.of(source), b"_CYC600_").is_some()));
        let emitted = emitted_run;
        let plain = model.lines.is_plain(row);
        let tree = (!plain).then(|| model.lines.line(row));
        let block = match tree.as_deref() {
            Some(crate::syntax::tree::Line {
                kind: LineKind::Block(block),
                ..
            }) => Some(block),
            Some(_) => None,
            None => None,
        };
        let after_end = end.line(row, plain, block);
        if !after_end {
            end.learn(source, content, plain, block, depth);
        }
        if let Some(line) = tree.as_deref() {
            if let LineKind::Header { .. } = line.kind {
                depths.set_proc_body(false);
            }
        }
        if after_end {
            match unread.last_mut() {
                Some(last) if last.end == raw.content.start => last.end = raw.full().end,
                _ => unread.push(raw.full()),
            }
        }
        let header = !plain && block.is_none();
        if hmi_owns || emitted || uses_macro || after_end || header {
            if let Some((span, _)) = own.first() {
                return Err(*span);
            }
            blank_run = 0;
            continue;
        }
        if !rows.contains(&row) {
            // Read for what carries over to the lines laid out, as laying
            // it out would leave it: blank (written as nothing) or not.
            let blank = content.of(source).iter().all(|&b| b == b' ' || b == b'\t');
            blank_run = if blank { blank_run + 1 } else { 0 };
            if block.is_some_and(opens_proc) {
                depths.set_proc_body(settings.indent_proc_body);
            }
            continue;
        }
        let parts = match block {
            None => {
                let bytes = content.of(source);
                let code_len = memchr::memchr(b';', bytes).unwrap_or(bytes.len());
                if depth == 0 && own.is_empty() && is_tidy_plain(bytes, code_len, settings.case) {
                    // Not blank: a plain line has words.
                    blank_run = 0;
                    continue;
                }
                let (prefix, _) = plain_prefix(source, content);
                let code_end = content.start + code_len;
                LineParts {
                    content,
                    prefix_end: prefix,
                    code_end,
                    words: Words::Letters,
                    replacements: own,
                }
            }
            Some(block) => {
                let code_end = block.comment.map_or(content.end, |c| c.start);
                words.clear();
                if settings.case != Case::Keep {
                    words = language_words(source, content, code_end, block);
                }
                if let Some(names) = &names {
                    // The uses are in source order: this line's, found by halving.
                    let all = names.all();
                    let first = all.partition_point(|u| u.span.start < content.start);
                    let user = all[first..].iter().map(|u| u.span);
                    words.extend(user.take_while(|s| s.end <= code_end));
                    words.sort_unstable_by_key(|w| (w.start, w.end));
                    words.dedup();
                }
                LineParts {
                    content,
                    prefix_end: prefix_end(block),
                    code_end,
                    words: Words::Spans(&words),
                    replacements: own,
                }
            }
        };
        write(
            source,
            &parts,
            depth,
            &settings.indent,
            settings.case,
            &mut out,
        );
        if too_long(&out, content.of(source)) {
            // Indented less, down to none, rather than past the limit.
            let fits = (0..depth).rev().find(|&less| {
                write(
                    source,
                    &parts,
                    less,
                    &settings.indent,
                    settings.case,
                    &mut out,
                );
                !too_long(&out, content.of(source))
            });
            if fits.is_none() {
                blank_run = 0;
                continue;
            }
        }
        if out.is_empty() {
            blank_run += 1;
            if blank_run > settings.max_blank_lines {
                push(&mut edits, source, raw.full(), &[], merge);
                continue;
            }
        } else {
            blank_run = 0;
        }
        if out != content.of(source) {
            push(&mut edits, source, content, &out, merge);
        }
        if block.is_some_and(opens_proc) {
            depths.set_proc_body(settings.indent_proc_body);
        }
    }
    Ok(Laid { edits, unread })
}

/// The deepest level a line is indented to: deeper lines stand at it, so
/// that indentation grows no program without bound (20,000 nested IFs
/// would be indented 40,000 blanks). No Siemens text found gives the
/// control's nesting limit for IF and the loops; sixteen is the number of
/// program levels it nests calls to, more than hand-written cycles nest.
const MAX_INDENT_LEVELS: usize = 16;

/// Whether the laid-out line `out` is a block the control would refuse for
/// its length where the `original` was not: such a line is indented less,
/// or left as it is.
fn too_long(out: &[u8], original: &[u8]) -> bool {
    use crate::syntax::{block_characters, BLOCK_CHARACTERS};
    out.len() > BLOCK_CHARACTERS
        && out.len() > original.len()
        && block_characters(out) > BLOCK_CHARACTERS
        && block_characters(original) <= BLOCK_CHARACTERS
}

/// Adds the edit `span` -> `text`; with `merge`, into the last edit when
/// only a line ending lies between them.
fn push(edits: &mut Vec<Edit>, source: &[u8], span: Span, text: &[u8], merge: bool) {
    if merge {
        if let Some(last) = edits.last_mut() {
            let between = &source[last.span.end..span.start];
            if between.len() <= 2 && between.iter().all(|&b| b == b'\r' || b == b'\n') {
                last.text.extend_from_slice(between);
                last.text.extend_from_slice(text);
                last.span.end = span.end;
                return;
            }
        }
    }
    edits.push(Edit::replace(span, text.to_vec()));
}

fn opens_proc(block: &Block) -> bool {
    block
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::Proc(_)))
}

/// Where a main program ends (M2, M30 outside every control block): the
/// lines after it, up to a line a jump may reach (a label, a block number
/// a jump names) or another program (a header, a PROC), are not read by
/// the control and stay as they are.
struct ProgramEnd {
    main: bool,
    ended: bool,
    /// Rows whose block number some jump names.
    jumped_to: HashSet<usize>,
    /// Where the next `M` or `m` at or after the line asked about is: a
    /// plain line without one ends nothing, and one search over the bytes
    /// finds them all, instead of one a line.
    next_m: Option<usize>,
    searched_to: usize,
}

impl ProgramEnd {
    fn new(model: &Model) -> Self {
        Self {
            main: model.kind == ProgramKind::Main,
            ended: false,
            jumped_to: model.block_numbers().iter().map(|&(_, row)| row).collect(),
            next_m: None,
            searched_to: 0,
        }
    }

    /// Whether line `row` stands after the end; fed every line in order.
    fn line(&mut self, row: usize, plain: bool, block: Option<&Block>) -> bool {
        if !self.main {
            return false;
        }
        if self.ended {
            let reachable = self.jumped_to.contains(&row)
                || (!plain && block.is_none_or(|b| b.label.is_some() || opens_proc(b)));
            if !reachable {
                return true;
            }
            self.ended = false;
        }
        false
    }

    /// Learns whether the line `content` (at `depth`) ends the program.
    fn learn(
        &mut self,
        source: &[u8],
        content: Span,
        plain: bool,
        block: Option<&Block>,
        depth: usize,
    ) {
        if !self.main || depth > 0 {
            return;
        }
        let ends = match (plain, block) {
            (true, _) => {
                if self.searched_to <= content.start
                    && self.next_m.is_none_or(|at| at < content.start)
                {
                    self.next_m = memchr::memchr2(b'M', b'm', &source[content.start..])
                        .map(|at| content.start + at);
                    self.searched_to = self.next_m.unwrap_or(source.len()) + 1;
                }
                self.next_m.is_some_and(|at| at < content.end)
                    && addresses::of_plain(source, content)
                        .iter()
                        .any(|a| is_end_word(source, a))
            }
            (false, Some(block)) => addresses::of_block(source, block)
                .iter()
                .any(|a| is_end_word(source, a)),
            (false, None) => false,
        };
        self.ended |= ends;
    }
}
