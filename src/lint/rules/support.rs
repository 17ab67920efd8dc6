//! Small helpers the rules share: what a block jumps to, which names an
//! expression reads, whether a name is a user variable.

use crate::semantic::walk::{collect_variables, for_each_expression};
use crate::span::Span;
use crate::syntax::tree::{
    Block, Goto, GotoTarget, Initializer, Statement, StatementKind, Variable,
};

/// The upper-case text of `span`.
pub fn upper(source: &[u8], span: Span) -> String {
    String::from_utf8_lossy(span.of(source)).to_ascii_uppercase()
}

/// Labels a block defines: its `NAME:` label and its block number (`N100`).
pub fn labels(source: &[u8], block: &Block) -> Vec<(String, Span)> {
    let mut out = Vec::new();
    if let Some(label) = block.label {
        out.push((upper(source, label.span), label.span));
    }
    if let Some(number) = &block.number {
        if !number.main {
            let digits = String::from_utf8_lossy(number.digits.of(source))
                .trim_start_matches('0')
                .to_string();
            out.push((format!("N{digits}"), number.span));
        }
    }
    out
}

/// Every jump of a block (GOTO statements and CASE branches).
pub fn gotos(block: &Block) -> Vec<&Goto> {
    let mut out = Vec::new();
    for statement in &block.statements {
        match &statement.kind {
            StatementKind::Goto(goto) => out.push(goto),
            StatementKind::Case(case) => {
                out.extend(case.branches.iter().map(|(_, g)| g).chain(&case.default))
            }
            _ => {}
        }
    }
    out
}

/// The label a jump names, as `labels` spells it; `None` for computed targets.
pub fn target(source: &[u8], goto: &Goto) -> Option<(String, Span)> {
    match goto.target.as_ref()? {
        GotoTarget::Label(name) => {
            let text = upper(source, name.span);
            let text = match text.strip_prefix('N') {
                Some(d) if !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()) => {
                    format!("N{}", d.trim_start_matches('0'))
                }
                _ => text,
            };
            Some((text, name.span))
        }
        GotoTarget::Number(number) => Some((format!("N{}", number.value as u64), number.span)),
        GotoTarget::Computed(_) => None,
    }
}

/// Variables a statement reads (DEF initialisers and indices included).
pub fn reads(statement: &Statement) -> Vec<&Variable> {
    let mut out = Vec::new();
    for_each_expression(&statement.kind, &mut |expr| {
        collect_variables(expr, &mut out)
    });
    if let StatementKind::Def(def) = &statement.kind {
        for declarator in &def.variables {
            if let Some(Initializer::Expr(expr)) = &declarator.init {
                collect_variables(expr, &mut out);
            }
            for dimension in declarator
                .dimensions
                .iter()
                .filter_map(|d| d.value.as_ref())
            {
                collect_variables(dimension, &mut out);
            }
        }
    }
    out
}

/// A name a user could have defined: two leading letters (or `_` after a
/// letter), not a system variable, not a cycle's reserved `_` name, and not a
/// frame component or constant.
pub fn is_user_name(name: &str) -> bool {
    let bytes = name.as_bytes();
    bytes.len() >= 2
        && bytes[0].is_ascii_alphabetic()
        && (bytes[1].is_ascii_alphabetic() || bytes[1] == b'_')
        && !matches!(name, "TRUE" | "FALSE" | "TR" | "RT" | "SC" | "MI" | "FI")
}
