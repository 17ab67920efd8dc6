//! Where each name of a program is defined, read, written, jumped to or
//! called, with its span: the table an editor's definition, references and
//! rename follow. It is built on demand from the model's line table (the
//! command line never asks), and where a jump lands is the block
//! structure's answer, the one the walk follows.

use crate::semantic::calls::{call_kind, CallKind};
use crate::semantic::Model;
use crate::span::Span;
use crate::syntax::tree::{upper, Block, GotoKind, GotoTarget, Statement, StatementKind};
use crate::syntax::visit::{gotos, reads};

/// What a name names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Namespace {
    /// A DEF variable, a PROC parameter, an R parameter or a system variable.
    Variable,
    /// A label (`START:`) or a block number (`N100`) a jump names.
    Label,
    /// A subprogram or cycle: a PROC, a call.
    Subprogram,
}

/// What a use does with its name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// DEF, a PROC parameter, a PROC's own name, a label, a block number.
    Defines,
    Reads,
    /// The target of an assignment or the variable of a FOR.
    Writes,
    /// A GOTO/GOTOF/GOTOB/GOTOC, a CASE branch or a REPEAT naming a label.
    JumpsTo,
    Calls,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Use {
    /// Upper case, as the control compares names.
    pub name: String,
    pub namespace: Namespace,
    pub role: Role,
    /// The name as written.
    pub span: Span,
    /// 0-based.
    pub row: usize,
}

/// Every use of a program, in source order.
#[derive(Debug, Default)]
pub struct Uses {
    uses: Vec<Use>,
}

impl Uses {
    pub fn of(model: &Model) -> Self {
        let source = model.source;
        let mut uses = Vec::new();
        for row in 0..model.lines.len() {
            // A plain line's words name nothing.
            if model.lines.is_plain(row) {
                continue;
            }
            if let Some(block) = model.lines.block(row) {
                block_uses(source, row, &block, &mut uses);
            }
        }
        uses.sort_by_key(|u| (u.span.start, u.span.end));
        Self { uses }
    }

    /// In source order.
    pub fn all(&self) -> &[Use] {
        &self.uses
    }

    /// The use whose name covers `offset` (its end included, where an
    /// editor's cursor stands after typing a name).
    pub fn at(&self, offset: usize) -> Option<&Use> {
        let after = self.uses.partition_point(|u| u.span.start <= offset);
        // Names do not overlap: the last one starting at or before the
        // cursor holds it, if any does.
        self.uses[..after].last().filter(|u| offset <= u.span.end)
    }

    /// Every use of the name `of` names, its definitions included.
    pub fn references<'u>(&'u self, of: &'u Use) -> impl Iterator<Item = &'u Use> + 'u {
        self.uses
            .iter()
            .filter(move |u| u.namespace == of.namespace && u.name == of.name)
    }

    /// The definition `of` refers to, in this program: for a jump, the
    /// label or block number it lands on, searching as the control does;
    /// for a variable, its DEF or PROC parameter; for a call, the PROC.
    /// `None` when it is defined elsewhere (a GUD, another file) or nowhere.
    pub fn definition<'u>(&'u self, model: &Model, of: &'u Use) -> Option<&'u Use> {
        if of.role == Role::Defines {
            return Some(of);
        }
        let mut definitions = self.references(of).filter(|u| u.role == Role::Defines);
        if of.namespace != Namespace::Label {
            return definitions.next();
        }
        let landing = self.landing(model, of)?;
        definitions.find(|u| u.row == landing)
    }

    /// The line the jump `of` lands on.
    fn landing(&self, model: &Model, of: &Use) -> Option<usize> {
        let block = model.lines.block(of.row)?;
        if let Some(goto) = gotos(&block)
            .into_iter()
            .find(|g| target_span(g.target.as_ref()) == Some(of.span))
        {
            let target = goto.target.as_ref()?;
            return model.landing(target, goto.kind, of.row);
        }
        // A REPEAT searches its label backward from the line before it.
        let before = of.row.checked_sub(1)?;
        model.labels.landing(&of.name, GotoKind::Backward, before)
    }
}

/// The span a jump's target names: a label or a block number.
fn target_span(target: Option<&GotoTarget>) -> Option<Span> {
    match target? {
        GotoTarget::Label(name) => Some(name.span),
        GotoTarget::Number(number) => Some(number.span),
        GotoTarget::Computed(_) => None,
    }
}

/// How a label or block number is named, so that `N0100`, `N100`, the main
/// block's `:100` and the bare `100` of `GOTOF 100` are one name.
fn label_name(source: &[u8], span: Span) -> String {
    let name = upper(span.of(source));
    let digits = name.strip_prefix(['N', ':']).unwrap_or(&name);
    match crate::syntax::plain::digits_value(digits.as_bytes()) {
        Some(number) if !digits.is_empty() => format!("N{number}"),
        _ => name,
    }
}

fn block_uses(source: &[u8], row: usize, block: &Block, out: &mut Vec<Use>) {
    let mut put = |namespace, role, span: Span| {
        let name = match namespace {
            Namespace::Label => label_name(source, span),
            _ => upper(span.of(source)),
        };
        out.push(Use {
            name,
            namespace,
            role,
            span,
            row,
        })
    };
    if let Some(label) = block.label {
        put(Namespace::Label, Role::Defines, label.span);
    }
    if let Some(number) = &block.number {
        put(Namespace::Label, Role::Defines, number.span);
    }
    for goto in gotos(block) {
        if let Some(span) = target_span(goto.target.as_ref()) {
            put(Namespace::Label, Role::JumpsTo, span);
        }
    }
    for statement in &block.statements {
        statement_uses(source, statement, &mut put);
    }
}

fn statement_uses(
    source: &[u8],
    statement: &Statement,
    put: &mut impl FnMut(Namespace, Role, Span),
) {
    for variable in reads(statement) {
        put(Namespace::Variable, Role::Reads, variable.name.span);
    }
    match &statement.kind {
        StatementKind::Assign(assign) => {
            put(Namespace::Variable, Role::Writes, assign.target.name.span)
        }
        StatementKind::For { variable, .. } => {
            put(Namespace::Variable, Role::Writes, variable.span)
        }
        StatementKind::Def(def) => {
            for declarator in &def.variables {
                put(Namespace::Variable, Role::Defines, declarator.name.span);
            }
        }
        StatementKind::Proc(proc) => {
            put(Namespace::Subprogram, Role::Defines, proc.name.span);
            for parameter in &proc.parameters {
                put(
                    Namespace::Variable,
                    Role::Defines,
                    parameter.declarator.name.span,
                );
            }
        }
        StatementKind::Call(call) => put(Namespace::Subprogram, Role::Calls, call.name.span),
        // A bare name calls a subprogram unless the control knows it.
        StatementKind::Command(name)
            if call_kind(&upper(name.text(source))) == CallKind::Subprogram =>
        {
            put(Namespace::Subprogram, Role::Calls, name.span)
        }
        StatementKind::Repeat { targets, .. } => {
            for target in targets {
                put(Namespace::Label, Role::JumpsTo, target.span);
            }
        }
        StatementKind::SyncAction(sync) => {
            let otherwise = sync.otherwise.iter().flat_map(|(_, actions)| actions);
            for action in sync.actions.iter().chain(otherwise) {
                if let StatementKind::Assign(assign) = &action.kind {
                    put(Namespace::Variable, Role::Writes, assign.target.name.span);
                }
            }
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PROGRAM: &str = "\
PROC DRILL(REAL _DEPTH) SAVE
DEF INT _N=0
AGAIN:
N10 _N=_N+1
IF _N<3 GOTOB AGAIN
AGAIN:
G1 Z=-_DEPTH
REPEAT AGAIN P=2
GOTOF 0020
N20 HOLE_CHECK
FOR _N=1 TO 3
ENDFOR
M17
";

    fn at<'u>(uses: &'u Uses, text: &str, nth: usize) -> &'u Use {
        let offset = PROGRAM
            .match_indices(text)
            .nth(nth)
            .expect("in the program")
            .0;
        uses.at(offset).expect("a use")
    }

    #[test]
    fn every_name_is_found_where_it_stands() {
        let model = Model::of(PROGRAM.as_bytes());
        let uses = Uses::of(&model);
        let n = at(&uses, "_N", 1);
        assert_eq!(
            (n.role, n.namespace, n.row),
            (Role::Writes, Namespace::Variable, 3)
        );
        let all_n: Vec<Role> = uses.references(n).map(|u| u.role).collect();
        use Role::*;
        assert_eq!(all_n, [Defines, Writes, Reads, Reads, Writes]);
        assert_eq!(uses.definition(&model, n).map(|d| d.row), Some(1));
        let depth = at(&uses, "_DEPTH", 1);
        assert_eq!(depth.role, Reads);
        assert_eq!(
            uses.definition(&model, depth).map(|d| d.span.start),
            Some(16)
        );
        let proc = at(&uses, "DRILL", 0);
        assert_eq!(
            (proc.role, proc.namespace),
            (Defines, Namespace::Subprogram)
        );
        let call = at(&uses, "HOLE_CHECK", 0);
        assert_eq!((call.role, call.namespace), (Calls, Namespace::Subprogram));
        assert!(
            uses.definition(&model, call).is_none(),
            "defined in another file"
        );
        assert!(uses.all().iter().all(|u| u.name != "G1" && u.name != "M17"));
    }

    #[test]
    fn a_jump_leads_where_the_control_searches() {
        let model = Model::of(PROGRAM.as_bytes());
        let uses = Uses::of(&model);
        // GOTOB searches backward: the first AGAIN, not the nearer one below.
        let back = at(&uses, "AGAIN", 1);
        assert_eq!(back.role, Role::JumpsTo);
        assert_eq!(uses.definition(&model, back).map(|d| d.row), Some(2));
        // REPEAT searches backward from itself: the second AGAIN.
        let repeat = at(&uses, "AGAIN", 3);
        assert_eq!(uses.definition(&model, repeat).map(|d| d.row), Some(5));
        assert_eq!(uses.references(repeat).count(), 4);
        // `GOTOF 0020` lands on `N20`.
        let number = at(&uses, "0020", 0);
        assert_eq!(number.name, "N20");
        assert_eq!(uses.definition(&model, number).map(|d| d.row), Some(9));
    }
}
