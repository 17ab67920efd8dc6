//! Macros (`DEFINE NAME AS text`) expanded where the control expands them:
//! the control replaces a macro's name by its text before it reads the
//! block (Siemens, Programming Manual Job Planning, "Macro technique (DEFINE
//! ... AS)"), so a line that names a macro is read here as the control reads
//! it, and every span of what is read maps back to the source as written:
//! a part of an expansion maps to the macro's use. The source is never
//! replaced (printing a program copies its lines), and a line that names no
//! macro is parsed as it is, at no cost beyond a look at its names.
//!
//! What this deliberately does not do: expand inside a string or a comment,
//! or in a `DEFINE` (its name and text are the definition), which the
//! control does not either; decide what an expansion means (that is the
//! tree's and its readers').

use std::collections::HashMap;

use crate::diagnostic::Diagnostic;
use crate::span::Span;
use crate::syntax::lexer::is_name_char;
use crate::syntax::tree::{self, Line, LineKind, Statement, StatementKind};
use crate::syntax::MAX_PARSED_LINE;

/// Expansions within expansions followed at most this deep: past it a
/// name is left as it is, as for a macro that names itself.
const MAX_DEPTH: usize = 16;

/// The macros a program's lines are read with: its definition files' and
/// its own, by name in upper case (the control ignores case).
#[derive(Clone, Debug, Default)]
pub struct Macros {
    texts: HashMap<Vec<u8>, Box<[u8]>>,
    /// A macro's name may start with this byte (either case): most names of
    /// a line are passed over without a look-up.
    starts: [u64; 4],
    /// Some macro is named as an address word with a number (`M6`, `G81`,
    /// `L6`), which a plain line may hold.
    plain_shaped: bool,
}

/// One macro written in a line, and what it stood for there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Use {
    /// The name as written.
    pub span: Span,
    /// What the control reads there: the text with the macros it names
    /// expanded in turn; the name itself when it is `recursive`.
    pub text: String,
    /// The macro names itself through its text: it is not expanded.
    pub recursive: bool,
}

impl Macros {
    pub fn is_empty(&self) -> bool {
        self.texts.is_empty()
    }

    pub fn len(&self) -> usize {
        self.texts.len()
    }

    /// Defines `name` (any case) as `text`, replacing an earlier definition.
    pub fn define(&mut self, name: &[u8], text: &[u8]) {
        let name = name.to_ascii_uppercase();
        let Some(&first) = name.first() else {
            return;
        };
        for byte in [first, first.to_ascii_lowercase()] {
            self.starts[usize::from(byte / 64)] |= 1 << (byte % 64);
        }
        self.plain_shaped |= name.len() > 1
            && name[0].is_ascii_alphabetic()
            && name[1..].iter().all(u8::is_ascii_digit);
        self.texts.insert(name, text.trim_ascii().into());
    }

    /// The text of macro `name` (upper case).
    pub fn text(&self, name: &[u8]) -> Option<&[u8]> {
        self.texts.get(name).map(|text| &text[..])
    }

    /// Whether a plain line (address words with numbers alone) may name a
    /// macro: only when one is named like an address word (`M6`).
    pub fn reach_plain_lines(&self) -> bool {
        self.plain_shaped
    }

    /// The macro `name` (any case) names, if it is one.
    fn get(&self, name: &[u8], buffer: &mut Vec<u8>) -> Option<&[u8]> {
        let first = name[0];
        if self.starts[usize::from(first / 64)] & (1 << (first % 64)) == 0 {
            return None;
        }
        buffer.clear();
        buffer.extend(name.iter().map(u8::to_ascii_uppercase));
        self.text(buffer)
    }

    /// Whether `content` (a line without its ending) names a macro where
    /// the control expands it.
    pub fn named_in(&self, content: &[u8]) -> bool {
        if self.is_empty() {
            return false;
        }
        let mut buffer = Vec::new();
        let mut found = false;
        names(content, |name| {
            found = self.get(name.of(content), &mut buffer).is_some();
            !found
        });
        found
    }

    /// `content` (a line starting at `start` in the source) as the control
    /// reads it, when it names a macro.
    pub fn expand(&self, content: &[u8], start: usize) -> Option<Expansion> {
        // A header is no block; a line too long to read stays unread (S009).
        if self.is_empty() || content.first() == Some(&b'%') || content.len() > MAX_PARSED_LINE {
            return None;
        }
        let mut expansion = Expansion::default();
        let mut buffer = Vec::new();
        let mut copied = 0;
        names(content, |name| {
            let Some(text) = self.get(name.of(content), &mut buffer) else {
                return true;
            };
            let mut stack = vec![buffer.clone()];
            let mut expanded = Vec::with_capacity(text.len());
            let recursive = !self.expand_text(text, &mut stack, &mut expanded);
            expansion.verbatim(&content[copied..name.start], start + copied);
            let at = start + name.start;
            let used = Span::new(at, at + name.len());
            if recursive {
                expansion.verbatim(name.of(content), at);
            } else {
                expansion.expanded(&expanded, used);
            }
            expansion.uses.push(Use {
                span: used,
                text: String::from_utf8_lossy(if recursive {
                    name.of(content)
                } else {
                    &expanded
                })
                .into_owned(),
                recursive,
            });
            copied = name.end;
            // Past this the line is too long to read (S009) whatever follows.
            expansion.text.len() <= MAX_PARSED_LINE
        });
        if expansion.uses.is_empty() {
            return None;
        }
        expansion.verbatim(&content[copied..], start + copied);
        Some(expansion)
    }

    /// Appends `text` to `out` with the macros it names expanded; `false`
    /// when one of them is on `stack` (it names itself, through others or
    /// directly) or they nest past [`MAX_DEPTH`].
    fn expand_text(&self, text: &[u8], stack: &mut Vec<Vec<u8>>, out: &mut Vec<u8>) -> bool {
        let mut buffer = Vec::new();
        let mut copied = 0;
        let mut sound = true;
        names(text, |name| {
            let Some(inner) = self.get(name.of(text), &mut buffer) else {
                return true;
            };
            if stack.len() >= MAX_DEPTH || stack.contains(&buffer) {
                sound = false;
                return false;
            }
            if out.len() > MAX_PARSED_LINE {
                return false;
            }
            out.extend_from_slice(&text[copied..name.start]);
            stack.push(buffer.clone());
            sound = self.expand_text(inner, stack, out);
            stack.pop();
            copied = name.end;
            sound
        });
        out.extend_from_slice(&text[copied..]);
        sound
    }
}

/// A finding at a macro's use (`uses` in source order) says what the
/// control read there, since the line shows only the name; a fix that would
/// edit the use is dropped: what it would change is the macro's text, in
/// its definition.
pub fn annotate(diagnostic: &mut Diagnostic, uses: &[Use], source: &[u8]) {
    let span = diagnostic.span;
    let from = uses.partition_point(|u| u.span.end <= span.start);
    let touches = |s: Span, u: &Use| s.start < u.span.end && u.span.start < s.end.max(s.start + 1);
    let Some(used) = uses[from..]
        .iter()
        .take_while(|u| u.span.start <= span.end)
        .find(|u| touches(span, u))
    else {
        return;
    };
    // A macro that names itself is left as written, and its finding says so.
    if !used.recursive {
        let name = String::from_utf8_lossy(used.span.of(source));
        diagnostic.message = format!(
            "{} (in `{name}`, which expands to `{}`)",
            diagnostic.message, used.text
        );
    }
    let edits_a_use = diagnostic.fix.as_ref().is_some_and(|fix| {
        fix.edits
            .iter()
            .any(|edit| uses.iter().any(|u| touches(edit.span, u)))
    });
    if edits_a_use {
        diagnostic.fix = None;
    }
}

/// Whether `span` is exactly a macro's name as written, where the macro
/// expands: a rule reading a name from its span there reads the macro's
/// name, which the control never reads (it reads the macro's text).
pub fn is_a_macro_name(span: Span, uses: &[Use]) -> bool {
    uses.binary_search_by(|u| u.span.start.cmp(&span.start))
        .is_ok_and(|at| uses[at].span == span && !uses[at].recursive)
}

/// Operators written as names: a name after an operand is one of these
/// or something the control replaces (Siemens, Job Planning, "Arithmetic
/// operators", "Relational operators and logic operators").
const OPERATOR_NAMES: [&str; 10] = [
    "MOD", "DIV", "AND", "OR", "XOR", "NOT", "B_AND", "B_OR", "B_XOR", "B_NOT",
];

/// The first name `content` writes where an operator belongs, inside
/// parentheses (`($TC_CARR37[_TC1] _DEC2)`), as a range of `content`: read
/// without the macros of the machine, such a name is a syntax error, and it
/// may well be a macro. (Outside parentheses a name after an operand is the
/// block's next word.)
pub fn name_in_operator_position(content: &[u8]) -> Option<std::ops::Range<usize>> {
    let mut depth = 0usize;
    let mut after_operand = false;
    let mut at = 0;
    while at < content.len() {
        let byte = content[at];
        match byte {
            b';' => return None,
            b'"' => {
                at = memchr::memchr(b'"', &content[at + 1..]).map_or(content.len(), |n| at + n + 2);
                after_operand = true;
                continue;
            }
            b'(' | b'[' => {
                depth += 1;
                after_operand = false;
            }
            b')' | b']' => {
                depth = depth.saturating_sub(1);
                after_operand = true;
            }
            b' ' | b'\t' => {}
            _ if is_name_char(byte) || byte == b'$' || byte == b'.' => {
                let start = at;
                while at < content.len()
                    && (is_name_char(content[at]) || matches!(content[at], b'$' | b'.'))
                {
                    at += 1;
                }
                let word = &content[start..at];
                let operator = OPERATOR_NAMES
                    .iter()
                    .any(|o| word.eq_ignore_ascii_case(o.as_bytes()));
                if depth > 0 && after_operand && !operator && !byte.is_ascii_digit() {
                    return Some(start..at);
                }
                after_operand = !operator;
                continue;
            }
            _ => after_operand = false,
        }
        at += 1;
    }
    None
}

/// Calls `each` with the span (in `text`) of every name the control may
/// expand, in order, until it returns `false`: names outside strings and the
/// comment, not in a `DEFINE` (nor after it in its block), and not a system
/// variable's (`$TC_CARR37`) or a number's (`1E5`).
fn names(text: &[u8], mut each: impl FnMut(Span) -> bool) {
    let mut at = 0;
    while at < text.len() {
        let byte = text[at];
        match byte {
            b';' => return,
            b'"' => {
                at = memchr::memchr(b'"', &text[at + 1..]).map_or(text.len(), |n| at + n + 2);
            }
            b'$' | b'0'..=b'9' | b'.' => {
                at += 1;
                while at < text.len() && (is_name_char(text[at]) || text[at] == b'.') {
                    at += 1;
                }
            }
            _ if is_name_char(byte) => {
                let start = at;
                while at < text.len() && is_name_char(text[at]) {
                    at += 1;
                }
                let name = Span::new(start, at);
                if name.of(text).eq_ignore_ascii_case(b"DEFINE") || !each(name) {
                    return;
                }
            }
            _ => at += 1,
        }
    }
}

/// A line as the control reads it, and where each of its bytes comes from.
#[derive(Clone, Debug, Default)]
pub struct Expansion {
    /// The line with its macros replaced by their texts.
    pub text: Vec<u8>,
    /// The macros it names, in order.
    pub uses: Vec<Use>,
    /// Pieces of `text`, in order: (where it starts in `text`, where it
    /// comes from). Copied bytes come from their own place in the source,
    /// an expansion's from its use as a whole.
    pieces: Vec<(usize, Origin)>,
}

#[derive(Clone, Copy, Debug)]
enum Origin {
    /// Copied from the source, starting here.
    Source(usize),
    /// A macro's text, used here.
    Macro(Span),
}

impl Expansion {
    fn verbatim(&mut self, bytes: &[u8], from: usize) {
        if !bytes.is_empty() {
            self.pieces.push((self.text.len(), Origin::Source(from)));
            self.text.extend_from_slice(bytes);
        }
    }

    fn expanded(&mut self, bytes: &[u8], used: Span) {
        self.pieces.push((self.text.len(), Origin::Macro(used)));
        self.text.extend_from_slice(bytes);
    }

    /// The piece `at` (an offset in `text`) lies in, `at` the end of `text`
    /// belonging to the last one.
    fn piece(&self, at: usize) -> (usize, Origin) {
        let index = self.pieces.partition_point(|(start, _)| *start <= at);
        self.pieces[index.saturating_sub(1)]
    }

    /// Where offset `at` of `text` is in the source: a copied byte where it
    /// was copied from, a byte of an expansion at its use's start (`end`:
    /// its end, for the end of a span).
    fn source_offset(&self, at: usize, end: bool) -> usize {
        // The end of a span is the end of its last byte's piece.
        let looked = if end { at.saturating_sub(1) } else { at };
        match self.piece(looked) {
            (start, Origin::Source(from)) => from + (at - start),
            (_, Origin::Macro(used)) if end => used.end,
            (_, Origin::Macro(used)) => used.start,
        }
    }

    /// The source span `span` (in `text`) stands for: within an expansion,
    /// the macro's use.
    pub fn source_span(&self, span: Span) -> Span {
        if self.pieces.is_empty() {
            return span;
        }
        let start = self.source_offset(span.start, false);
        if span.is_empty() {
            return Span::new(start, start);
        }
        Span::new(start, self.source_offset(span.end, true).max(start))
    }

    /// The use `span` (in the source) lies in, if it lies in one.
    pub fn use_at(&self, span: Span) -> Option<&Use> {
        self.uses
            .iter()
            .find(|u| span.start < u.span.end && u.span.start < span.end.max(span.start + 1))
    }

    /// A diagnostic of `text` (a syntax error) moved to the source: its span
    /// and its fix's edits mapped back (see [`annotate`] for the rest).
    pub fn diagnostic_in_source(&self, mut diagnostic: Diagnostic) -> Diagnostic {
        diagnostic.span = self.source_span(diagnostic.span);
        if let Some(fix) = &mut diagnostic.fix {
            for edit in &mut fix.edits {
                edit.span = self.source_span(edit.span);
            }
        }
        diagnostic
    }

    /// Maps every span of `line` (parsed from `text`) back to the source.
    pub fn map_line(&self, line: &mut Line) {
        map_kind(&mut line.kind, &|span| self.source_span(span));
    }
}

/// Every span of a line's tree, through `f`. The structs are taken apart
/// field by field, so that a field added to the tree is a compile error
/// here until it is mapped too.
fn map_kind(kind: &mut LineKind, f: &dyn Fn(Span) -> Span) {
    match kind {
        LineKind::Header { name } => *name = f(*name),
        LineKind::Path { directory } => *directory = f(*directory),
        LineKind::Block(block) => {
            let tree::Block {
                skip,
                number,
                label,
                statements,
                comment,
                unparsed,
            } = block;
            if let Some(tree::Skip { span, level: _ }) = skip {
                *span = f(*span);
            }
            if let Some(tree::BlockNumber {
                span,
                main: _,
                digits,
            }) = number
            {
                *span = f(*span);
                *digits = f(*digits);
            }
            if let Some(label) = label {
                map_name(label, f);
            }
            statements.iter_mut().for_each(|s| map_statement(s, f));
            map_option(comment, f);
            map_option(unparsed, f);
        }
    }
}

fn map_option(span: &mut Option<Span>, f: &dyn Fn(Span) -> Span) {
    if let Some(span) = span {
        *span = f(*span);
    }
}

fn map_name(name: &mut tree::Name, f: &dyn Fn(Span) -> Span) {
    name.span = f(name.span);
}

fn map_statement(statement: &mut Statement, f: &dyn Fn(Span) -> Span) {
    let Statement { span, kind } = statement;
    *span = f(*span);
    match kind {
        StatementKind::Word(word) => map_word(word, f),
        StatementKind::Assign(tree::Assign { target, value }) => {
            map_variable(target, f);
            map_expr(value, f);
        }
        StatementKind::Call(call) => map_call(call, f),
        StatementKind::Command(name) => map_name(name, f),
        StatementKind::Frame(tree::FrameStatement { keyword, kind: _ }) => map_name(keyword, f),
        StatementKind::Def(def) => {
            let tree::Def {
                scope,
                attributes,
                data_type,
                variables,
            } = &mut **def;
            if let Some(scope) = scope {
                map_name(scope, f);
            }
            attributes.iter_mut().for_each(|a| map_attribute(a, f));
            map_data_type(data_type, f);
            variables.iter_mut().for_each(|d| map_declarator(d, f));
        }
        StatementKind::Redef { name, attributes } => {
            map_name(name, f);
            attributes.iter_mut().for_each(|a| map_attribute(a, f));
        }
        StatementKind::AccessLevels(attributes) => {
            attributes.iter_mut().for_each(|a| map_attribute(a, f));
        }
        StatementKind::Proc(tree::Proc {
            name,
            parameters,
            attributes,
        }) => {
            map_name(name, f);
            for tree::Parameter {
                span,
                by_reference: _,
                data_type,
                declarator,
            } in parameters
            {
                *span = f(*span);
                map_data_type(data_type, f);
                map_declarator(declarator, f);
            }
            attributes.iter_mut().for_each(|a| map_name(a, f));
        }
        StatementKind::Extern { name, parameters } => {
            map_name(name, f);
            map_option(parameters, f);
        }
        StatementKind::Define { name, body } => {
            map_name(name, f);
            *body = f(*body);
        }
        StatementKind::If { condition }
        | StatementKind::While { condition }
        | StatementKind::Until { condition } => map_expr(condition, f),
        StatementKind::For {
            variable,
            start,
            end,
        } => {
            map_name(variable, f);
            map_expr(start, f);
            map_expr(end, f);
        }
        StatementKind::Repeat { targets, count } => {
            targets.iter_mut().for_each(|t| map_name(t, f));
            if let Some(count) = count {
                map_expr(count, f);
            }
        }
        StatementKind::Case(case) => {
            let tree::Case {
                selector,
                branches,
                default,
            } = &mut **case;
            map_expr(selector, f);
            for (value, goto) in branches {
                map_expr(value, f);
                map_goto(goto, f);
            }
            if let Some(goto) = default {
                map_goto(goto, f);
            }
        }
        StatementKind::Goto(goto) => map_goto(goto, f),
        StatementKind::IndirectCall { keyword, target } => {
            map_name(keyword, f);
            map_option(target, f);
        }
        StatementKind::SyncAction(action) => {
            let tree::SyncAction {
                id,
                condition,
                do_keyword,
                actions,
                otherwise,
            } = &mut **action;
            if let Some((name, value)) = id {
                map_name(name, f);
                map_expr(value, f);
            }
            if let Some(tree::SyncCondition {
                frequency,
                g_functions,
                expr,
            }) = condition
            {
                map_name(frequency, f);
                g_functions.iter_mut().for_each(|s| map_statement(s, f));
                map_expr(expr, f);
            }
            map_name(do_keyword, f);
            actions.iter_mut().for_each(|s| map_statement(s, f));
            if let Some((name, statements)) = otherwise {
                map_name(name, f);
                statements.iter_mut().for_each(|s| map_statement(s, f));
            }
        }
        StatementKind::Else
        | StatementKind::EndIf
        | StatementKind::EndWhile
        | StatementKind::EndFor
        | StatementKind::Loop
        | StatementKind::EndLoop => {}
    }
}

fn map_word(word: &mut tree::Word, f: &dyn Fn(Span) -> Span) {
    let tree::Word {
        address,
        extension,
        value,
    } = word;
    map_name(address, f);
    map_option(extension, f);
    match value {
        tree::WordValue::Number(number) => map_number(number, f),
        tree::WordValue::Expr(expr) => map_expr(expr, f),
    }
}

fn map_number(number: &mut tree::Number, f: &dyn Fn(Span) -> Span) {
    number.span = f(number.span);
}

fn map_variable(variable: &mut tree::Variable, f: &dyn Fn(Span) -> Span) {
    let tree::Variable {
        span,
        name,
        indices,
    } = variable;
    *span = f(*span);
    map_name(name, f);
    indices.iter_mut().for_each(|e| map_expr(e, f));
}

fn map_call(call: &mut tree::Call, f: &dyn Fn(Span) -> Span) {
    let tree::Call { name, arguments } = call;
    map_name(name, f);
    map_arguments(arguments, f);
}

fn map_arguments(arguments: &mut tree::Arguments, f: &dyn Fn(Span) -> Span) {
    let tree::Arguments { span, items } = arguments;
    *span = f(*span);
    for tree::Argument { span, value } in items {
        *span = f(*span);
        if let Some(value) = value {
            map_expr(value, f);
        }
    }
}

fn map_attribute(attribute: &mut tree::Attribute, f: &dyn Fn(Span) -> Span) {
    let tree::Attribute { keyword, value } = attribute;
    map_name(keyword, f);
    if let Some(value) = value {
        map_expr(value, f);
    }
}

fn map_data_type(data_type: &mut tree::DataType, f: &dyn Fn(Span) -> Span) {
    let tree::DataType {
        span,
        kind: _,
        length,
    } = data_type;
    *span = f(*span);
    if let Some(length) = length {
        map_expr(length, f);
    }
}

fn map_declarator(declarator: &mut tree::Declarator, f: &dyn Fn(Span) -> Span) {
    let tree::Declarator {
        name,
        dimensions,
        init,
    } = declarator;
    map_name(name, f);
    for tree::Argument { span, value } in dimensions {
        *span = f(*span);
        if let Some(value) = value {
            map_expr(value, f);
        }
    }
    match init {
        Some(tree::Initializer::Expr(expr)) => map_expr(expr, f),
        Some(tree::Initializer::List(arguments)) => map_arguments(arguments, f),
        None => {}
    }
}

fn map_goto(goto: &mut tree::Goto, f: &dyn Fn(Span) -> Span) {
    let tree::Goto {
        keyword,
        kind: _,
        target,
    } = goto;
    map_name(keyword, f);
    match target {
        Some(tree::GotoTarget::Label(name)) => map_name(name, f),
        Some(tree::GotoTarget::Number(number)) => map_number(number, f),
        Some(tree::GotoTarget::Computed(expr)) => map_expr(expr, f),
        None => {}
    }
}

/// An expression's spans, without recursion: an expression may nest 256
/// levels deep (S008), each level a frame here otherwise.
fn map_expr(expr: &mut tree::Expr, f: &dyn Fn(Span) -> Span) {
    let mut pending = vec![expr];
    while let Some(expr) = pending.pop() {
        let tree::Expr { span, kind } = expr;
        *span = f(*span);
        match kind {
            tree::ExprKind::Number(number) => map_number(number, f),
            tree::ExprKind::String => {}
            tree::ExprKind::Variable(variable) => {
                let tree::Variable {
                    span,
                    name,
                    indices,
                } = variable;
                *span = f(*span);
                map_name(name, f);
                pending.extend(indices.iter_mut());
            }
            tree::ExprKind::Call(tree::Call { name, arguments }) => {
                map_name(name, f);
                arguments_of(arguments, f, &mut pending);
            }
            tree::ExprKind::Tuple(arguments) => arguments_of(arguments, f, &mut pending),
            tree::ExprKind::Unary { op: _, operand } => pending.push(operand),
            tree::ExprKind::Binary { op: _, lhs, rhs } => {
                pending.push(lhs);
                pending.push(rhs);
            }
            tree::ExprKind::Paren(inner) => pending.push(inner),
        }
    }
}

fn arguments_of<'e>(
    arguments: &'e mut tree::Arguments,
    f: &dyn Fn(Span) -> Span,
    pending: &mut Vec<&'e mut tree::Expr>,
) {
    let tree::Arguments { span, items } = arguments;
    *span = f(*span);
    for tree::Argument { span, value } in items {
        *span = f(*span);
        pending.extend(value.as_mut());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn macros(definitions: &[(&str, &str)]) -> Macros {
        let mut macros = Macros::default();
        for (name, text) in definitions {
            macros.define(name.as_bytes(), text.as_bytes());
        }
        macros
    }

    #[test]
    fn a_name_is_replaced_by_its_text_outside_strings_comments_and_definitions() {
        let m = macros(&[("_DEC2", "MOD 100 DIV 10"), ("M6", "DM_WWMAG")]);
        let line = b"IF (($TC_CARR37[_TC1] _dec2)==1) ; _DEC2";
        let expansion = m.expand(line, 100).expect("names a macro");
        assert_eq!(
            expansion.text,
            b"IF (($TC_CARR37[_TC1] MOD 100 DIV 10)==1) ; _DEC2"
        );
        assert_eq!(expansion.uses.len(), 1);
        assert_eq!(expansion.uses[0].span, Span::new(122, 127));
        assert!(m.expand(b"MSG(\"_DEC2\") ; M6", 0).is_none());
        assert!(m.expand(b"DEFINE M6 AS L6", 0).is_none());
        assert!(m.expand(b"N10 G0 X=1E5 $M6", 0).is_none());
        assert!(!m.named_in(b"T1 D1 ; M6") && m.named_in(b"T1 m6"));
        assert!(m.reach_plain_lines());
        assert!(!macros(&[("ENDE", "M30")]).reach_plain_lines());
    }

    #[test]
    fn a_name_after_an_operand_in_parentheses_may_be_a_macro() {
        assert_eq!(
            name_in_operator_position(b"IF (($TC_CARR37[_TC1] _DEC2)==1)"),
            Some(22..27)
        );
        for plain in [
            &b"IF (($TC_CARR37[_TC1] MOD 100)==1)"[..],
            b"G1 X10 Y20 F=R1 ; (A B)",
            b"IF (R1 == 1) AND NOT (R2 > 0) GOTOF END",
            b"MSG(\"A B\" << R1)",
        ] {
            assert_eq!(name_in_operator_position(plain), None);
        }
    }

    /// Macros that multiply their text at every level stop growing once
    /// the line is too long to read (S009): the expansion takes time and
    /// memory of the order of that limit, not of the 8^15 bytes asked for.
    #[test]
    fn an_expansion_stops_growing_past_the_longest_line_read() {
        let mut m = macros(&[("_M0", "R1")]);
        for level in 1..15 {
            let inner = format!("_M{} ", level - 1).repeat(8);
            m.define(format!("_M{level}").as_bytes(), inner.as_bytes());
        }
        let expansion = m.expand(b"R2=_M14", 0).expect("names a macro");
        assert!(expansion.text.len() > MAX_PARSED_LINE);
        assert!(expansion.text.len() < 2 * MAX_PARSED_LINE);
    }

    #[test]
    fn spans_in_an_expansion_map_to_the_use_and_others_to_themselves() {
        let m = macros(&[("LINE", "G1 G94 F300")]);
        let expansion = m.expand(b"N70 LINE X10", 10).expect("names a macro");
        assert_eq!(expansion.text, b"N70 G1 G94 F300 X10");
        let used = Span::new(14, 18);
        assert_eq!(expansion.source_span(Span::new(0, 3)), Span::new(10, 13));
        assert_eq!(expansion.source_span(Span::new(4, 6)), used);
        assert_eq!(expansion.source_span(Span::new(7, 15)), used);
        assert_eq!(expansion.source_span(Span::new(16, 19)), Span::new(19, 22));
        assert_eq!(expansion.source_span(Span::new(4, 19)), Span::new(14, 22));
        assert_eq!(expansion.source_span(Span::new(19, 19)), Span::new(22, 22));
        assert_eq!(
            expansion.use_at(Span::new(14, 18)).map(|u| u.span),
            Some(used)
        );
        assert!(expansion.use_at(Span::new(19, 22)).is_none());
    }

    #[test]
    fn nested_macros_expand_and_a_recursive_one_is_left_as_written() {
        let m = macros(&[("A", "B + 1"), ("B", "C * 2"), ("C", "R1")]);
        let expansion = m.expand(b"R2=A", 0).expect("names a macro");
        assert_eq!(expansion.text, b"R2=R1 * 2 + 1");
        assert_eq!(expansion.uses[0].text, "R1 * 2 + 1");
        let m = macros(&[("P", "Q"), ("Q", "P")]);
        let expansion = m.expand(b"R2=P", 0).expect("names a macro");
        assert_eq!(expansion.text, b"R2=P");
        assert!(expansion.uses[0].recursive);
    }
}
