//! N023 `g-group-conflict`: Finds two G functions of one group in a block (`G0 G1`).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockWords, FileContext};
use crate::lint::rules::support::{both, group_conflicts};
use crate::semantic::addresses::Address;
use crate::semantic::modal::{g_group, is_syntax_defining};
use crate::syntax::plain::PlainFacts;
use crate::syntax::tree::Block;

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

pub struct Checker;

impl BlockWords for Checker {
    fn may_find(facts: &PlainFacts) -> bool {
        facts.repeats && facts.letters.contains(b'G')
    }

    /// One finding per group, from its first function to the first other one.
    fn check(
        file: &FileContext,
        _block: Option<&Block>,
        addresses: &[Address],
        out: &mut Vec<Diagnostic>,
    ) {
        let source = file.source;
        for (group, first, second) in group_conflicts(addresses, |a| grouped(source, a)) {
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
}

/// The G function's group and number.
fn grouped(source: &[u8], address: &Address) -> Option<(u8, u32)> {
    if !address.is(source, "G") || address.extension.is_some() {
        return None;
    }
    let number = address.whole(source)?;
    Some((g_group(number)?, number))
}
