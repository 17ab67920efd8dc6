//! N002 `jump-direction`: Finds a GOTOF whose label exists only before the jump, and a GOTOB whose label exists only after it.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
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

/// The labels are the file's ([`FileContext::labels`]).
#[derive(Default)]
pub struct Checker {
    jumps: Vec<(Target, Span, usize, GotoKind)>,
}

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        row: usize,
        line: &LineView,
        _out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block else {
            return;
        };
        if line.plain {
            return;
        }
        for goto in gotos(block) {
            if let Some((target, span)) = target(file, goto) {
                self.jumps.push((target, span, row, goto.kind));
            }
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        for (target, span, row, kind) in &self.jumps {
            let rows: Vec<usize> = match target {
                Target::Label(name) => file.labels().rows(name).collect(),
                Target::Number(n) => {
                    // Read from the file on first use: most programs never jump to one.
                    let numbers = file.block_numbers();
                    let first = numbers.partition_point(|(m, _)| m < n);
                    numbers[first..]
                        .iter()
                        .take_while(|(m, _)| m == n)
                        .map(|(_, r)| *r)
                        .collect()
                }
            };
            let (wrong, right, keyword) = match kind {
                GotoKind::Forward => ("before", rows.iter().any(|r| r > row), "GOTOB"),
                GotoKind::Backward => ("after", rows.iter().any(|r| r <= row), "GOTOF"),
                _ => continue,
            };
            if rows.is_empty() || right {
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
