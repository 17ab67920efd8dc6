//! N001 `undefined-label`: Finds GOTOF, GOTOB, GOTO, GOTOC and CASE jumps to a label or block number that the program does not have, and REPEAT labels it does not have.

use crate::diagnostic::{Applicability, Diagnostic, Fix, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, JumpAt, Sees, StatementAt};
use crate::lint::rules::support::*;
use crate::semantic::jumps;
use crate::span::Span;
use crate::suggest::Nearest;
use crate::syntax::tree::{GotoKind, StatementKind};

pub static RULE: RuleInfo = RuleInfo {
    code: "N001",
    name: "undefined-label",
    severity: Severity::Error,
    docs: r#"## What it does
Finds GOTOF, GOTOB, GOTO, GOTOC and CASE jumps to a label or block number that the program does not
have, and the labels of a REPEAT (`REPEAT START END P=2`, `REPEATB LBL`) it does not have.

## Why it matters
The control stops with alarm 14080 ("jump destination not found") when the jump is taken or the
section to repeat is searched; GOTOC suppresses the alarm and simply goes on, which hides the
mistake (reported as a warning).

## Example
```
N10 GOTOF ENDE
N20 END: M30       ; the label is END
```

## Fix
Correct the label's spelling (the help suggests the nearest existing label the jump can reach:
below it for GOTOF, above it for GOTOB) or add the label. The nearest label is offered as an
unsafe fix (`check --fix --unsafe-fixes`): it is a guess."#,
};

/// The labels are the file's ([`FileContext::labels`]).
#[derive(Default)]
pub struct Checker {
    jumps: Vec<Jump>,
}

/// A jump (or a REPEAT) to a place the program must have.
struct Jump {
    target: Target,
    span: Span,
    /// GOTOC: goes on without an alarm when the target is missing.
    tolerant: bool,
    /// A label a REPEAT names, not a GOTO's.
    repeat: bool,
    /// Its line, and how it searches (a REPEAT's labels: both ways).
    row: usize,
    kind: GotoKind,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::JUMPS | Sees::STATEMENTS
    }

    fn jump(&mut self, _file: &FileContext, at: &JumpAt, _out: &mut Vec<Diagnostic>) {
        if let Some((target, span)) = &at.target {
            self.jumps.push(Jump {
                target: target.clone(),
                span: *span,
                tolerant: at.goto.kind == GotoKind::Conditional,
                repeat: false,
                row: at.row,
                kind: at.goto.kind,
            });
        }
    }

    /// The labels a REPEAT names.
    fn statement(&mut self, file: &FileContext, at: &StatementAt, _out: &mut Vec<Diagnostic>) {
        if let StatementKind::Repeat { targets, .. } = &at.statement.kind {
            self.jumps.extend(targets.iter().map(|name| Jump {
                target: Target::Label(upper(file.source, name.span)),
                span: name.span,
                tolerant: false,
                repeat: true,
                row: at.row,
                kind: GotoKind::Both,
            }));
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        // Collected at the first jump that needs a did-you-mean.
        let mut names: Option<Nearest> = None;
        for Jump {
            target,
            span,
            tolerant,
            repeat,
            row,
            kind,
        } in &self.jumps
        {
            if file.model().has_target(target) {
                continue;
            }
            let wanted = target.to_string();
            let names = names.get_or_insert_with(|| {
                let mut nearest = Nearest::default();
                file.labels().names().for_each(|name| nearest.push(&name));
                nearest
            });
            // Only a label the jump finds, searching as it searches.
            let reaches = |name: &str| {
                let mut rows = file.labels().rows(name);
                rows.any(|label| jumps::reaches(*kind, label, *row))
            };
            let meant = names.closest_where(&wanted, 2, reaches).map(str::to_string);
            let help = match &meant {
                Some(label) => format!("did you mean `{label}`? Otherwise add the label `{wanted}:` where the jump should land"),
                None => format!("add the label `{wanted}:` where the jump should land, or correct the jump"),
            };
            let mut diagnostic = RULE
                .at(*span)
                .message(if *repeat {
                    format!("REPEAT names `{wanted}`, which is not a label of this program")
                } else {
                    format!(
                        "jump to `{wanted}`, which is not a label or block number of this program"
                    )
                })
                .label("no such label")
                .help(help);
            if let Some(label) = &meant {
                diagnostic = diagnostic.fix(Fix::replace(
                    format!("jump to `{label}`"),
                    Applicability::Unsafe,
                    *span,
                    label.as_bytes(),
                ));
            }
            if *tolerant {
                diagnostic.severity = Severity::Warning;
                diagnostic
                    .message
                    .push_str(" (GOTOC goes on without an alarm)");
            }
            out.push(diagnostic);
        }
    }
}
