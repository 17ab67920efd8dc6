//! N002 `jump-direction`: Finds a GOTOF whose label exists only before the jump, and a GOTOB whose label exists only after it.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, JumpAt, Sees};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::syntax::tree::GotoKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N002",
    name: "jump-direction",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a GOTOF whose label exists only before the jump, and a GOTOB whose label exists only after it.

## Why it matters
GOTOF searches forward only and GOTOB backward only: the control does not find the label and
stops with alarm 14080, although the label is right there.

## Example
```
N10 START: R1=R1+1
N20 GOTOF START    ; START is behind
```

## Fix
Use GOTOB (or GOTO, which searches both ways), or move the label."#,
};

/// The lines jumps land on are the model's ([`crate::semantic::Model::target_landing`]).
#[derive(Default)]
pub struct Checker {
    jumps: Vec<(Target, Span, usize, GotoKind)>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::JUMPS
    }

    fn jump(&mut self, _file: &FileContext, at: &JumpAt, _out: &mut Vec<Diagnostic>) {
        if let Some((target, span)) = &at.target {
            self.jumps
                .push((target.clone(), *span, at.row, at.goto.kind));
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        let model = file.model();
        for (target, span, row, kind) in &self.jumps {
            let (wrong, keyword) = match kind {
                GotoKind::Forward => ("before", "GOTOB"),
                GotoKind::Backward => ("after", "GOTOF"),
                _ => continue,
            };
            // Where the jump lands is the model's answer, the walk's: a
            // target the program has that the search does not find.
            let lands = model.target_landing(target, *kind, *row).is_some();
            if lands || !model.has_target(target) {
                continue;
            }
            out.push(
                RULE.at(*span)
                    .message(format!("`{target}` stands only {wrong} this jump, so the search in its direction cannot find it"))
                    .label(format!("only {wrong} the jump"))
                    .help(format!("jump with {keyword} or GOTO (which searches both ways), or move the label")),
            );
        }
    }
}
