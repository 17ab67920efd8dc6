//! N024 `m-group-conflict`: Finds two M functions of one group in a block (`M3 M4`).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockWords, FileContext, Words};
use crate::lint::rules::support::{both, group_conflicts};
use crate::semantic::addresses::Address;
use crate::semantic::modal::m_group;
use crate::syntax::plain::PlainFacts;

pub static RULE: RuleInfo = RuleInfo {
    code: "N024",
    name: "m-group-conflict",
    severity: Severity::Error,
    docs: r#"## What it does
Finds two different M functions of one predefined group for the same spindle or channel in a
block: the program's stops and ends (`M0 M1 M2 M17 M30`), or a spindle's direction, stop and
positioning (`M3 M4 M5 M19 M70`; `M1=3` and `M2=4` are two spindles, and `M3` is compared only
with other M functions without an extension, since the master spindle is set by machine data).

## Why it matters
The functions of an auxiliary function group exclude each other; the control refuses the block
(alarm 14760, "auxiliary function of a group programmed repeatedly"; Siemens, Function Manual
Basic Functions, "Auxiliary function outputs": the predefined groups 1 and 2). `M3 M5` asks the
spindle to turn and to stop at once; `M6` typed for `M5` is not caught here, since M6 is in no
group. Groups that machine data defines beyond these are not known here.

## Example
```
N10 S2000 M3 M4
```

## Fix
Keep the M function that was meant."#,
};

pub struct Checker;

impl BlockWords for Checker {
    fn may_find(facts: &PlainFacts) -> bool {
        facts.repeats && facts.letters.contains(b'M')
    }

    /// One finding per group and extension, from its first function to the
    /// first other one.
    fn check(file: &FileContext, words: &Words, out: &mut Vec<Diagnostic>) {
        let addresses = words.addresses;
        let source = file.source;
        for ((group, _), first, second) in group_conflicts(addresses, |a| grouped(source, a)) {
            let (first_text, second_text) = both(source, first, second);
            let what = match group {
                1 => "stop or end the program",
                _ => "set what the spindle does",
            };
            out.push(
                RULE.at(first.span.to(second.span))
                    .message(format!(
                        "`{first_text}` and `{second_text}` both {what} (M function group {group}): the control refuses the block"
                    ))
                    .label(format!("two functions of group {group}"))
                    .help(format!("keep `{first_text}` or `{second_text}`, the one that was meant")),
            );
        }
    }
}

/// The M function's group with its extension (the spindle), and its number.
fn grouped(source: &[u8], address: &Address) -> Option<((u8, Option<u32>), u32)> {
    if !address.is(source, "M") {
        return None;
    }
    let number = address.whole(source)?;
    let extension = match address.extension {
        Some(_) => Some(address.extension_value(source)?),
        None => None,
    };
    Some(((m_group(number)?, extension), number))
}
