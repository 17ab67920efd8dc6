//! The programs a run executes: the main program and the subprograms its
//! calls reach, read before the run (each once, however often it is
//! called), so that every program's model lives as long as the run.

use std::collections::{BTreeSet, HashMap};
use std::sync::Arc;

use crate::semantic::calls::{call_kind, CallKind};
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::macros::Macros;
use crate::syntax::tree::{upper, LineKind, Statement, StatementKind, WordValue};
use crate::syntax::ProgramKind;

/// The programs of a run: the main program, and the subprograms it may
/// call (`L105`, `NAME`, `NAME(...)`, `CALL "NAME"`) by name in upper case.
pub struct Programs<'s> {
    pub main: &'s Model<'s>,
    pub subprograms: HashMap<String, Model<'s>>,
}

impl<'s> Programs<'s> {
    /// A program that calls none the run can follow.
    pub fn alone(main: &'s Model<'s>) -> Self {
        Programs {
            main,
            subprograms: HashMap::new(),
        }
    }

    /// `main` and the subprograms of `sources` (name, text), read with
    /// `macros`.
    pub fn with(
        main: &'s Model<'s>,
        sources: &'s [(String, Vec<u8>)],
        macros: &Arc<Macros>,
    ) -> Self {
        let subprograms = sources
            .iter()
            .map(|(name, source)| {
                let model = Model::build_with(source, ProgramKind::Subprogram, macros.clone());
                (name.clone(), model)
            })
            .collect();
        Programs { main, subprograms }
    }
}

/// The names of the subprograms `model` may call: `L105` (the digits as
/// written), a bare name the control does not know, `NAME(...)`, a cycle
/// and `CALL "NAME"`; predefined procedures are not among them.
fn called(model: &Model) -> BTreeSet<String> {
    let source = model.source;
    let mut names = BTreeSet::new();
    for (_, line) in model.lines.other_lines() {
        let LineKind::Block(block) = &line.kind else {
            continue;
        };
        for statement in &block.statements {
            let name = match &statement.kind {
                StatementKind::IndirectCall {
                    keyword,
                    target: Some(target),
                } => match indirect_call(source, &keyword.upper(source), *target) {
                    Some(name) => name,
                    None => continue,
                },
                kind => match called_name(source, kind) {
                    Some(name) => name,
                    None => continue,
                },
            };
            // A cycle is followed too where its file is given (the
            // control's cycle directories, --cycles).
            let subprogram = call_kind(&name) == CallKind::Subprogram || name.starts_with("CYCLE");
            if subprogram && !crate::semantic::calls::is_predefined(&name) {
                names.insert(name);
            }
        }
    }
    // `L105` on a plain line (letters and numbers only): found by its letter.
    for at in memchr::memchr2_iter(b'L', b'l', source) {
        let starts_word = at == 0 || matches!(source[at - 1], b' ' | b'\t' | b'\n' | b'\r');
        let digits = source[at + 1..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        let ends_word = source
            .get(at + 1 + digits)
            .is_none_or(|b| matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b';'));
        if starts_word && digits > 0 && ends_word {
            names.insert(format!(
                "L{}",
                String::from_utf8_lossy(&source[at + 1..at + 1 + digits])
            ));
        }
    }
    names
}

/// What `MCALL` names (`MCALL CYCLE81(10,0,2,-5)`, `MCALL L10`, `MCALL
/// BOHR`): the subprogram, upper case as the control looks it up, and the
/// statement that calls it, read from the text after the keyword with
/// spans into `source`; `None` for a target read only at run time (a path,
/// an expression).
pub(crate) fn modal_call(source: &[u8], target: Span) -> Option<(String, Statement)> {
    let (kind, error) =
        crate::syntax::parse_line_kind(target.of(source), target.start, &mut Vec::new());
    let LineKind::Block(block) = kind else {
        return None;
    };
    let [statement] = <[Statement; 1]>::try_from(block.statements).ok()?;
    if error.is_some() {
        return None;
    }
    Some((called_name(source, &statement.kind)?, statement))
}

/// The program a statement calls by its name: `NAME(...)`, `NAME`, `L105`
/// (the digits as written), upper case as the control looks it up.
fn called_name(source: &[u8], kind: &StatementKind) -> Option<String> {
    match kind {
        StatementKind::Call(call) => Some(call.name.upper(source)),
        StatementKind::Command(name) => Some(name.upper(source)),
        StatementKind::Word(word) if word.address.is(source, "L") => match &word.value {
            WordValue::Number(n) => Some(format!("L{}", upper(n.span.of(source)))),
            WordValue::Expr(_) => None,
        },
        _ => None,
    }
}

/// The program `keyword` (upper case) calls with the text at `target`
/// where its name is written out: `CALL "NAME"`, `EXTCALL "/.../_N_NAME_SPF"`,
/// `MCALL NAME(...)`; `None` for a name computed at run time.
pub(crate) fn indirect_call(source: &[u8], keyword: &str, target: Span) -> Option<String> {
    match keyword {
        "CALL" => {
            let text = String::from_utf8_lossy(target.of(source));
            let name = text.trim().strip_prefix('"')?.strip_suffix('"')?;
            Some(name.to_ascii_uppercase())
        }
        "EXTCALL" => external_call(source, target),
        "MCALL" => Some(modal_call(source, target)?.0),
        _ => None,
    }
}

/// The program `EXTCALL "..."` names, as the control reads the name (Job
/// Planning, "Execute external subprogram (EXTCALL)"): the last part of a
/// path, with or without `_N_` and `_SPF`/`_MPF` (or a file's `.SPF`,
/// `.MPF`), upper case; `None` for a name computed at run time.
fn external_call(source: &[u8], target: Span) -> Option<String> {
    let text = String::from_utf8_lossy(target.of(source));
    let mut text = text.trim();
    while let Some(inner) = text.strip_prefix('(').and_then(|t| t.strip_suffix(')')) {
        text = inner.trim();
    }
    let path = text.strip_prefix('"')?.strip_suffix('"')?;
    if path.contains('"') {
        return None;
    }
    let name = path.rsplit(['/', '\\']).next()?.to_ascii_uppercase();
    let name = name.strip_prefix("_N_").unwrap_or(&name);
    let name = ["_SPF", "_MPF", ".SPF", ".MPF"]
        .iter()
        .find_map(|end| name.strip_suffix(end))
        .unwrap_or(name);
    (!name.is_empty()).then(|| name.to_string())
}

/// The texts of the subprograms `main` calls, and those they call in turn,
/// each read once by `read` (the file of a name, `None` where there is
/// none: its call is named as not followed when the run meets it).
pub fn subprogram_sources(
    main: &Model,
    macros: &Arc<Macros>,
    mut read: impl FnMut(&str) -> Option<Vec<u8>>,
) -> Vec<(String, Vec<u8>)> {
    let mut sources: Vec<(String, Vec<u8>)> = Vec::new();
    let mut seen: BTreeSet<String> = BTreeSet::new();
    let mut queue: Vec<String> = called(main).into_iter().collect();
    while let Some(name) = queue.pop() {
        if !seen.insert(name.clone()) {
            continue;
        }
        let Some(source) = read(&name) else {
            continue;
        };
        let model = Model::build_with(&source, ProgramKind::Subprogram, macros.clone());
        queue.extend(called(&model));
        drop(model);
        sources.push((name, source));
    }
    sources
}
