//! C615 `cycle800-fed-extrinsic`: Finds a CYCLE800 whose angles are `_CYC600_2` .. `_CYC600_4` from a CYCLE600 that computed

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{CallAt, Check, FileContext, Sees};
use crate::lint::rules::support::*;
use crate::syntax::tree::ExprKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "C615",
    name: "cycle800-fed-extrinsic",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a CYCLE800 whose angles are `_CYC600_2` .. `_CYC600_4` from a CYCLE600 that computed
extrinsic angles (`_INEXOUT` = 0).

## Why it matters
CYCLE800 turns axis by axis about the rotated axes: it takes intrinsic angles only. Extrinsic
angles in the same order describe another orientation, and the head turns wrong.

## Example
```
N120 CYCLE600(0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 0, 39, 0, 0, 0)
N125 STOPRE
N135 CYCLE800(0, _CYC600_1, 0, _CYC600_6, 0,0,0, _CYC600_2, _CYC600_3, _CYC600_4,0,0,0,-1)
```

## Fix
Ask CYCLE600 for intrinsic output (`_INEXOUT` = 1), or let `sinuprep rewrite` emit the CYCLE800."#,
};

#[derive(Default)]
pub struct Checker {
    extrinsic_from: Option<usize>,
}

/// `_INEXOUT` of a call written as a literal: 15th argument (16th in the 19-value form).
fn literal_inexout(call: &crate::syntax::tree::Call) -> Option<f64> {
    let index = match call.arguments.items.len() {
        18 => 13,
        19 => 14,
        _ => return None,
    };
    match call.arguments.items[index].value.as_ref().map(|v| &v.kind) {
        Some(ExprKind::Number(n)) => Some(n.value),
        None => Some(0.0),
        _ => None,
    }
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::CALLS
    }

    fn call(&mut self, file: &FileContext, at: &CallAt, out: &mut Vec<Diagnostic>) {
        let call = at.call;
        if call.name.is(file.source, "CYCLE600") {
            self.extrinsic_from = (literal_inexout(call) == Some(0.0)).then_some(at.row);
            return;
        }
        let Some(from) = self.extrinsic_from else {
            return;
        };
        if !call.name.is(file.source, "CYCLE800") {
            return;
        }
        for argument in call.arguments.items.iter().skip(7).take(3) {
            let Some(expr) = &argument.value else {
                continue;
            };
            let text = upper(file.source, expr.span);
            if matches!(text.as_str(), "_CYC600_2" | "_CYC600_3" | "_CYC600_4") {
                out.push(
                        RULE.at(expr.span)
                            .message(format!("CYCLE800 gets {text}, an extrinsic angle from the CYCLE600 on line {}", from + 1))
                            .label("extrinsic angle")
                            .help("CYCLE800 takes intrinsic angles only: set _INEXOUT=1 in the CYCLE600 call, or let sinuprep rewrite emit the CYCLE800"),
                    );
                break;
            }
        }
    }
}
