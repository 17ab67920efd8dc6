//! N024 `m-group-conflict`: Finds two M functions of one group in a block (`M3 M4`).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::lint::rules::support::{both, each_plain_line, group_conflicts};
use crate::semantic::addresses::Address;
use crate::semantic::modal::m_group;

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

#[derive(Default)]
pub struct Checker;

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        check(file, line.addresses(file.source), out);
    }

    fn sees_plain_lines(&self) -> bool {
        true
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        each_plain_line(
            file,
            lines,
            |line| line.facts.repeats && line.facts.letters.contains(b'M'),
            |_, addresses| check(file, addresses, out),
        );
    }
}

/// The M function's number, extension and group.
fn grouped(source: &[u8], address: &Address) -> Option<(u32, Option<u32>, u8)> {
    if !address.is(source, "M") {
        return None;
    }
    let number = address.whole(source)?;
    let extension = match address.extension {
        Some(_) => Some(address.extension_value(source)?),
        None => None,
    };
    Some((number, extension, m_group(number)?))
}

/// One finding per group and extension, from its first word to the first
/// One finding per group and extension, from its first function to the
/// first other one.
fn check(file: &FileContext, addresses: &[Address], out: &mut Vec<Diagnostic>) {
    let source = file.source;
    let grouped = |a: &Address| {
        grouped(source, a).map(|(number, extension, group)| ((group, extension), number))
    };
    for ((group, _), first, second) in group_conflicts(addresses, grouped) {
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
