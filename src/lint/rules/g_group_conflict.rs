//! N023 `g-group-conflict`: Finds two G functions of one group in a block (`G0 G1`).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::lint::rules::support::{both, each_plain_line, group_conflicts};
use crate::semantic::addresses::Address;
use crate::semantic::modal::{g_group, is_syntax_defining};

pub static RULE: RuleInfo = RuleInfo {
    code: "N023",
    name: "g-group-conflict",
    severity: Severity::Error,
    docs: r#"## What it does
Finds two different G functions of one G group in a block (`G0 G1`, `G90 G91`, `G17 G18`), by the
groups of the Programming Manual's list of G functions. G functions written as numbers are
checked; the same function twice is not reported.

## Why it matters
The functions of a group exclude each other (Siemens, Programming Manual Fundamentals, "List of G
functions"). The control refuses such a block: with two motion commands, dwells or frame functions
(groups 1 to 3, which shape how the block is read) always; for the other groups unless machine data
makes it ignore all but the last (MD11410), when the first one is silently lost.

## Example
```
N10 G0 G1 X10 F500
N20 G90 G91 X5
```

## Fix
Keep the G function that was meant."#,
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
            |line| line.facts.repeats && line.facts.letters.contains(b'G'),
            |_, addresses| check(file, addresses, out),
        );
    }
}

/// The G function's number and group.
fn grouped(source: &[u8], address: &Address) -> Option<(u32, u8)> {
    if !address.is(source, "G") || address.extension.is_some() {
        return None;
    }
    let number = address.whole(source)?;
    Some((number, g_group(number)?))
}

/// One finding per group, from its first word to the first other function
/// One finding per group, from its first function to the first other one.
fn check(file: &FileContext, addresses: &[Address], out: &mut Vec<Diagnostic>) {
    let source = file.source;
    let grouped = |a: &Address| grouped(source, a).map(|(number, group)| (group, number));
    for (group, first, second) in group_conflicts(addresses, grouped) {
        let (first_text, second_text) = both(source, first, second);
        let consequence = if is_syntax_defining(group) {
            "the control refuses the block"
        } else {
            "the control refuses the block, or keeps the last one"
        };
        out.push(
            RULE.at(first.span.to(second.span))
                .message(format!(
                    "`{first_text}` and `{second_text}` are both of G group {group} and exclude each other: {consequence}"
                ))
                .label(format!("two functions of group {group}"))
                .help(format!("keep `{first_text}` or `{second_text}`, the one that was meant")),
        );
    }
}
