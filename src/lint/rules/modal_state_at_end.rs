//! N031 `modal-state-at-end`: Finds a main program that ends with a programmable frame, `G91` or `G41`/`G42` still in force.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, ModalRule, ModalStep};
use crate::lint::rules::support::upper;
use crate::span::Span;
use crate::syntax::plain::PlainFacts;

pub static RULE: RuleInfo = RuleInfo {
    code: "N031",
    name: "modal-state-at-end",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a main program that reaches its end (`M30` or `M2`) with something it switched on still in
force:
- a programmable frame (`TRANS X10`, `ATRANS`, `AROT`, `ASCALE`, `AMIRROR`, ...) never cleared by
  `TRANS`, `ROT`, `SCALE` or `MIRROR` without values;
- incremental dimensions `G91` never set back to `G90`;
- the tool radius compensation `G41`/`G42` never deselected with `G40`.

One finding for each, at the statement that switched it on. The blocks are read in the order of the
lines, as long as that is the order the control runs them: a jump, a block structure (IF, ELSE,
loops, CASE), a subprogram or cycle call or a PROC ends what the rule knows (the subprogram may
reset it), and so does a skippable block (`/`) that changes it. A program ended with `M17` or `RET`
is not checked: it returns to a caller, and leaving a frame or `G91` to the caller can be its
purpose (a zero-point subprogram, a step-and-repeat pattern). TRAORI left on is N012's.

## Why it matters
As delivered, the control resets the G groups to their reset values at the program end and deletes
the programmable frame (Function Manual Basic Functions: MD20110 `$MC_RESET_MODE_MASK`, MD20152
`$MC_GCODE_RESET_MODE`, MD24010 `$MC_PFRAME_RESET_MODE`). A machine whose machine data keep them
starts the next program, or the operator's next MDI block, with the shifted coordinates, the
incremental dimensions or the compensation this program left; and the compensation's deselection
motion, which the program never made, is not made at the end either. The program relies on machine
data it cannot see.

## Example
```
N10 G54 G90
N20 ATRANS X100
N30 G0 X0 Y0
N40 M30
```

## Fix
Clear what the program switched on before the end:
```
N10 G54 G90
N20 ATRANS X100
N30 G0 X0 Y0
N35 TRANS
N40 M30
```"#,
};

#[derive(Default)]
pub struct Checker;

impl ModalRule for Checker {
    fn reads(file: &FileContext, main: bool) -> bool {
        main && !file.definition_file
    }

    /// A plain line can end the program (an M) or change G90/G91 or the
    /// compensation (a G function beyond G0-G3); it holds no frame.
    fn may_matter(facts: &PlainFacts) -> bool {
        facts.letters.contains(b'M') || facts.motions.others()
    }

    fn block(&mut self, file: &FileContext, step: &ModalStep, out: &mut Vec<Diagnostic>) {
        let source = file.source;
        let Some(end) = step.addresses.iter().find(|a| {
            a.is(source, "M") && a.extension.is_none() && matches!(a.whole(source), Some(2 | 30))
        }) else {
            return;
        };
        // What the end's own block switches off does not outlive it.
        let (before, at_end) = (&step.before, &step.after);
        let end_word = upper(source, end.span);
        let line = step.row + 1;
        let report = |span: Span, what: &str, help: &'static str| {
            RULE.at(span)
                .message(format!(
                    "{what} is still in force when the program ends (`{end_word}` on line {line})"
                ))
                .label("switched on here, never off")
                .help(help)
        };
        if let Some(frame) = at_end.programmable_frame {
            let text = String::from_utf8_lossy(frame.of(source)).into_owned();
            out.push(report(
                frame,
                &format!("the programmable frame `{text}`"),
                "clear it with TRANS (no values) before the end; as delivered the control deletes it at the end, a machine set to keep it does not",
            ));
        }
        if let Some(g91) = before.incremental.filter(|_| at_end.incremental.is_some()) {
            out.push(report(
                g91,
                "`G91` (incremental dimensions)",
                "program G90 before the end; as delivered the control resets it at the end, a machine set to keep it does not",
            ));
        }
        if let Some(g) = before
            .radius_compensation
            .filter(|_| at_end.radius_compensation.is_some())
        {
            let what = format!("the tool radius compensation `{}`", upper(source, g));
            out.push(report(
                g,
                &what,
                "deselect it with G40 in a block with a motion before the end",
            ));
        }
    }
}
