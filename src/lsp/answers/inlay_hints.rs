//! `textDocument/inlayHint`: the angles a CYCLE600 computes, what a CYCLE800's
//! `_MODE` makes of its angles.

use lsp_types as lsp;

use crate::semantic::cycle800;
use crate::span::{ColumnUnit, Span};
use crate::syntax::tree::StatementKind;

use super::Snapshot;
use crate::lsp::convert;

impl Snapshot<'_, '_> {
    /// After each CYCLE600 evaluated offline, the angles it computes; after
    /// each CYCLE800's constant `_MODE`, what it makes of the angles.
    pub fn inlay_hints(&self, range: lsp::Range) -> Vec<lsp::InlayHint> {
        let wanted = convert::span(self.text, range, self.unit);
        let precision = self.settings.emit.precision.min(4);
        let n = |v: f64| crate::number::format(v, precision);
        let mut hints: Vec<lsp::InlayHint> = self
            .calls()
            .filter(|site| wanted.start <= site.statement.end && site.statement.start <= wanted.end)
            .filter_map(|site| {
                let evaluation = site.evaluation.as_ref()?;
                let [a, b, c] = evaluation.output.angles;
                let sequence = &evaluation.parameters.output;
                let label = format!("→ {sequence} {} {} {}", n(a), n(b), n(c));
                Some(self.hint(site.statement.end, label))
            })
            .collect();
        hints.extend(self.cycle800_modes(wanted));
        hints.sort_by_key(|hint| (hint.position.line, hint.position.character));
        hints
    }

    fn cycle800_modes(&self, wanted: Span) -> Vec<lsp::InlayHint> {
        if !crate::semantic::mentions_cycle(self.text.bytes(), b"800") {
            return Vec::new();
        }
        let source = self.text.bytes();
        let first = self.text.position(wanted.start, ColumnUnit::Bytes).row - 1;
        let last = self.text.position(wanted.end, ColumnUnit::Bytes).row - 1;
        let mut hints = Vec::new();
        for row in first..=last.min(self.model.lines.len().saturating_sub(1)) {
            let Some(block) = self.model.lines.block(row) else {
                continue;
            };
            for statement in &block.statements {
                let StatementKind::Call(call) = &statement.kind else {
                    continue;
                };
                let Some(argument) = call.arguments.items.get(3) else {
                    continue;
                };
                if !call.name.is(source, "CYCLE800") || argument.value.is_none() {
                    continue;
                }
                let arguments = cycle800::Arguments::of(source, call);
                if let Some(mode) = arguments.number(3).and_then(cycle800::Mode::of) {
                    hints.push(self.hint(argument.span.end, mode.to_string()));
                }
            }
        }
        hints
    }

    fn hint(&self, at: usize, label: String) -> lsp::InlayHint {
        lsp::InlayHint {
            position: convert::position(self.text, at, self.unit),
            label: lsp::InlayHintLabel::String(label),
            kind: None,
            text_edits: None,
            tooltip: None,
            padding_left: Some(true),
            padding_right: None,
            data: None,
        }
    }
}
