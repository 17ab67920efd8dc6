//! N003 `duplicate-label`: Finds a GOTO or GOTOC whose label is written both after it and before it.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, JumpAt, Sees};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::syntax::tree::GotoKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N003",
    name: "duplicate-label",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a GOTO or GOTOC whose label is written both after it and before it.

## Why it matters
The control does not refuse a label written more than once. A jump searches its label from the
block it stands in and takes the first one it finds: GOTOF toward the end of the program, GOTOB
toward its start, GOTO and GOTOC toward the end first and then toward the start (Siemens,
Programming Manual Job Planning, "Program jumps to jump markers (GOTOB, GOTOF, GOTO, GOTOC)"). A
REPEAT searches the label it names toward the start of the program, so a section is repeated from
the label just above the REPEAT; REPEATB, and the start label of `REPEAT START END`, are searched
toward the start first as well, and `ENDLABEL` may end as many sections as there are ("Program
section repetition (REPEAT, REPEATB, ENDLABEL, P)"). Machine builders' cycles rely on it: a label
written again before each REPEAT naming it (`TEMP:` ... `REPEAT TEMP P=59`, a hundred times in one
program) runs as written.

Where a GOTO or GOTOC has its label after it and before it, it goes forward, although a reader
who sees the label above (a loop written `WEITER:` ... `GOTO WEITER`) takes it for a jump back:
which block runs depends on a label elsewhere in the program. That is reported, as a warning (the
control runs it). Not reported: a label written twice that no such jump names, GOTOF, GOTOB and
CASE jumps (one direction: the nearest label in it) and the REPEAT forms (the label above).

## Example
```
N10 WEITER: R1=R1+1
N20 IF R1<5 GOTO WEITER   ; goes on to N40, not back to N10
N30 M0
N40 WEITER: M30
```

## Fix
Give each label its own name, or say the direction with GOTOB or GOTOF."#,
};

/// A GOTO or GOTOC to a label: the labels are the file's
/// ([`FileContext::labels`]), complete once the line pass is over.
#[derive(Default)]
pub struct Checker {
    jumps: Vec<Jump>,
}

struct Jump {
    /// The label, upper case.
    name: String,
    /// The label as the jump writes it.
    span: Span,
    row: usize,
    keyword: &'static str,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::JUMPS
    }

    fn jump(&mut self, _file: &FileContext, at: &JumpAt, _out: &mut Vec<Diagnostic>) {
        let keyword = match at.goto.kind {
            GotoKind::Both => "GOTO",
            GotoKind::Conditional => "GOTOC",
            _ => return,
        };
        if let Some((Target::Label(name), span)) = &at.target {
            self.jumps.push(Jump {
                name: name.clone(),
                span: *span,
                row: at.row,
                keyword,
            });
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        for jump in &self.jumps {
            // The search as the control makes it: forward to the first
            // label after the jump's block; back to the nearest at or
            // before it.
            let labels = file.labels();
            let after = labels.landing(&jump.name, GotoKind::Forward, jump.row);
            let before = labels.landing(&jump.name, GotoKind::Backward, jump.row);
            let (Some(after), Some(before)) = (after, before) else {
                continue;
            };
            out.push(ambiguous(jump, after, before));
        }
    }
}

#[cold]
fn ambiguous(jump: &Jump, after: usize, before: usize) -> Diagnostic {
    let Jump { name, keyword, .. } = jump;
    let (after, before) = (after + 1, before + 1);
    RULE.at(jump.span)
        .message(format!(
            "`{keyword} {name}` goes forward to `{name}` on line {after}, though `{name}` is also written before it, on line {before}"
        ))
        .label("two labels of this name in the two directions")
        .help(format!(
            "give each label its own name, or jump with GOTOF (line {after}) or GOTOB (line {before}) to say which"
        ))
}
