//! N009 `cycle800-arguments`: Checks CYCLE800 calls: at most 16 arguments, and a literal `_MODE`

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{CallAt, Check, FileContext, Sees};
use crate::rotation::{Kind, Sequence};
use crate::syntax::tree::ExprKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N009",
    name: "cycle800-arguments",
    severity: Severity::Error,
    docs: r#"## What it does
Checks CYCLE800 calls: at most 16 arguments, and a literal `_MODE` whose axis-by-axis coding
names a valid axis order. Fewer arguments are fine: trailing parameters may be left out and are
passed as 0 (Programming Manual, "incomplete parameter lists"), as in `CYCLE800()` or
`CYCLE800(,"0")`, which deselect.

## Why it matters
A wrong argument list shifts every later parameter (angles land in the translation, the head turns
wrong); an invalid `_MODE` raises a cycle alarm.

## Example
```
CYCLE800(0,"TC1",0,58,0,0,0,30,0,45,0,0,0,-1)   ; 58 = Y, Y, Z
```

## Fix
Write the 14 classic (or 16 extended) parameters; for axis by axis use 57, 45, 54, 30, 39 or 27."#,
};

#[derive(Default)]
pub struct Checker;

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::CALLS
    }

    fn call(&mut self, file: &FileContext, at: &CallAt, out: &mut Vec<Diagnostic>) {
        let call = at.call;
        if !call.name.is(file.source, "CYCLE800") {
            return;
        }
        let count = call.arguments.items.len();
        if count > 16 {
            out.push(
                    RULE.at(call.arguments.span)
                        .message(format!("CYCLE800 takes at most 16 arguments (14 classic, 2 more extended), this call has {count}"))
                        .label(format!("{count} arguments"))
                        .help("write _FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR (then _FR_I, _DMODE)"),
                );
            return;
        }
        let Some(mode) = call.arguments.items.get(3) else {
            return;
        };
        let Some(ExprKind::Number(number)) = mode.value.as_ref().map(|v| &v.kind) else {
            return;
        };
        let code = number.value as i64;
        let axis_by_axis = (code >> 6) & 0b11 == 0;
        if axis_by_axis
            && code & 0b111111 != 0
            && Sequence::from_code(code & 0b111111, Kind::Intrinsic)
                .map_or(true, |s| s.is_proper_euler())
        {
            out.push(
                RULE.at(mode.span)
                    .message(format!(
                        "_MODE {code} is not an axis-by-axis order CYCLE800 knows"
                    ))
                    .label("invalid _MODE")
                    .help(
                        "axis by axis: 57 (XYZ), 45 (XZY), 54 (YXZ), 30 (YZX), 39 (ZXY), 27 (ZYX)",
                    ),
            );
        }
    }
}
