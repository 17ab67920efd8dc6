//! `textDocument/signatureHelp`: inside a call's argument list, the
//! parameters of what it calls, the one being written marked. A cycle's
//! parameters come with their meaning ([`crate::semantic::cycles`]); a
//! PROC's as its header declares them, in this program or in the file the
//! control calls. Of nested calls, the innermost one known is shown.

use lsp_types as lsp;

use crate::semantic::cycles;
use crate::semantic::uses::{Namespace, Role};
use crate::span::ColumnUnit;
use crate::syntax::tree::{upper, StatementKind};

use super::answers::Snapshot;

impl Snapshot<'_, '_> {
    /// The signature of the call the cursor at `position` is in; its
    /// parameters as offsets into the label where the client takes them
    /// (`offsets`), else as the label's text.
    pub fn signature_help(
        &self,
        position: lsp::Position,
        offsets: bool,
    ) -> Option<lsp::SignatureHelp> {
        let cursor = self.cursor(position);
        cursor.before.calls.iter().find_map(|call| {
            let name = upper(call.name);
            let (signature, argument) = match cycles::cycle(call.name) {
                Some(cycle) => (self.of_cycle(cycle, offsets), call.argument),
                None => (self.of_proc(&name, offsets)?, call.argument),
            };
            Some(lsp::SignatureHelp {
                signatures: vec![signature],
                active_signature: Some(0),
                active_parameter: u32::try_from(argument).ok(),
            })
        })
    }

    fn of_cycle(&self, cycle: &cycles::Cycle, offsets: bool) -> lsp::SignatureInformation {
        let parameters: Vec<(&str, Option<&str>)> = (cycle.parameters.iter())
            .map(|p| (p.name, Some(p.meaning)))
            .collect();
        let what = format!("{}\n\n*{}*", cycle.what, cycle.manual);
        self.signature(cycle.name, &parameters, what, offsets)
    }

    /// A PROC's header, in this program or the file the control calls.
    fn of_proc(&self, name: &str, offsets: bool) -> Option<lsp::SignatureInformation> {
        let source = self.text.bytes();
        let here = self.uses().all().iter().find(|u| {
            u.namespace == Namespace::Subprogram && u.role == Role::Defines && u.name == name
        });
        if let Some(defined) = here {
            let block = self.model.lines.block(defined.row)?;
            let proc = block.statements.iter().find_map(|s| match &s.kind {
                StatementKind::Proc(proc) => Some(proc),
                _ => None,
            })?;
            let written: Vec<String> = (proc.parameters.iter())
                .map(|p| String::from_utf8_lossy(p.span.of(source)).into_owned())
                .collect();
            let parameters: Vec<(&str, Option<&str>)> =
                written.iter().map(|p| (p.as_str(), None)).collect();
            let what = format!("PROC on line {}", defined.row + 1);
            return Some(self.signature(name, &parameters, what, offsets));
        }
        let procedure = self.settings.environment.procedures.get(name)?;
        let parameters: Vec<(&str, Option<&str>)> = (procedure.parameters.iter())
            .map(|p| (p.as_str(), None))
            .collect();
        let what = match &procedure.defined {
            Some((file, _)) => format!("PROC in `{}`", file.display()),
            None => "PROC of an archive".to_string(),
        };
        Some(self.signature(name, &parameters, what, offsets))
    }

    /// `NAME(first, second, ...)`, each parameter found in the label by
    /// its offsets (counted in the unit agreed with the client) or its text.
    fn signature(
        &self,
        name: &str,
        parameters: &[(&str, Option<&str>)],
        what: String,
        offsets: bool,
    ) -> lsp::SignatureInformation {
        let mut label = format!("{name}(");
        let mut shown = Vec::new();
        for (i, (parameter, meaning)) in parameters.iter().enumerate() {
            if i > 0 {
                label.push_str(", ");
            }
            let start = width(&label, self.unit);
            label.push_str(parameter);
            shown.push(lsp::ParameterInformation {
                label: match offsets {
                    true => lsp::ParameterLabel::LabelOffsets([start, width(&label, self.unit)]),
                    false => lsp::ParameterLabel::Simple(found_first(&label, parameter.len())),
                },
                documentation: meaning.map(|m| lsp::Documentation::String(m.to_string())),
            });
        }
        label.push(')');
        lsp::SignatureInformation {
            label,
            documentation: Some(lsp::Documentation::MarkupContent(lsp::MarkupContent {
                kind: lsp::MarkupKind::Markdown,
                value: what,
            })),
            parameters: Some(shown),
            active_parameter: None,
        }
    }
}

/// The text a client without offsets finds at the end of `label`, where
/// it looks for a parameter's text by its first occurrence: the last
/// `length` bytes, with as much of what stands before as makes them occur
/// nowhere earlier (CYCLE84's `PIT` stands inside `MPIT` before it; ` PIT`
/// does not).
fn found_first(label: &str, length: usize) -> String {
    let end = label.len();
    let mut start = end - length;
    while label.find(&label[start..]) != Some(start) && start > 0 {
        start -= 1;
        while !label.is_char_boundary(start) {
            start -= 1;
        }
    }
    label[start..].to_string()
}

/// The length of `text` in `unit`.
fn width(text: &str, unit: ColumnUnit) -> u32 {
    let width = match unit {
        ColumnUnit::Bytes => text.len(),
        ColumnUnit::Utf16 => text.encode_utf16().count(),
        ColumnUnit::CodePoints => text.chars().count(),
    };
    u32::try_from(width).unwrap_or(u32::MAX)
}
