//! N023 `g-group-conflict`: Finds two G functions of one group in a block (`G0 G1`).

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockWords, FileContext, Words};
use crate::lint::rules::support::group_conflicts;
use crate::semantic::addresses::Address;
use crate::semantic::modal::{g_group, is_syntax_defining, keyword_g_group};
use crate::span::Span;
use crate::syntax::plain::PlainFacts;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N023",
    name: "g-group-conflict",
    severity: Severity::Error,
    docs: r#"## What it does
Finds two different G functions of one G group in a block (`G0 G1`, `G90 G91`, `G17 G18`), by the
groups of the Programming Manual's list of G functions: G functions written as numbers, and the
keywords of groups 1 (`CIP`, `ASPLINE`, `BSPLINE`, `CSPLINE`, `POLY`, `CT`, `INVCW`, `INVCCW`) and
19 to 25 (spline ends, `BRISK`/`SOFT`/`DRIVE`, `CUT2D`...`CUT3DCCD`, `CDON`/`CDOF`, `FFWON`/`FFWOF`,
`ORIWKS`/`ORIMKS`). The same function twice is not reported.

## Why it matters
The functions of a group exclude each other (Siemens, Programming Manual Fundamentals, "List of G
functions"). The control refuses such a block: with two motion commands, dwells or frame functions
(groups 1 to 3, which shape how the block is read) always; for the other groups unless machine data
makes it ignore all but the last (MD11410), when the first one is silently lost.

## Example
```
N10 G0 G1 X10 F500
N20 G90 G91 X5
N30 SOFT BRISK
```

## Fix
Keep the G function that was meant."#,
};

pub struct Checker;

/// A G function of the block: a G word (`G1`) or a keyword (`CIP`, `SOFT`).
struct Function {
    span: Span,
    group: u8,
    number: u32,
}

impl BlockWords for Checker {
    fn may_find(facts: &PlainFacts) -> bool {
        facts.repeats && facts.letters.contains(b'G')
    }

    /// One finding per group, from its first function to the first other one.
    fn check(file: &FileContext, words: &Words, out: &mut Vec<Diagnostic>) {
        let (block, addresses) = (words.block, words.addresses);
        let source = file.source;
        let mut functions: Vec<Function> = addresses
            .iter()
            .filter_map(|a| {
                let (group, number) = grouped(source, a)?;
                Some(Function {
                    span: a.span,
                    group,
                    number,
                })
            })
            .collect();
        // Keywords stand only in parsed blocks; a plain line has none.
        if let Some(block) = block {
            let before = functions.len();
            functions.extend(block.statements.iter().filter_map(|s| match &s.kind {
                StatementKind::Command(name) => {
                    let (group, number) = keyword_g_group(name.text(source))?;
                    Some(Function {
                        span: name.span,
                        group,
                        number,
                    })
                }
                _ => None,
            }));
            if functions.len() > before {
                functions.sort_by_key(|f| f.span.start);
            }
        }
        if functions.len() < 2 {
            return;
        }
        for (group, first, second) in group_conflicts(&functions, |f| Some((f.group, f.number))) {
            let text = |f: &Function| String::from_utf8_lossy(f.span.of(source)).into_owned();
            let (first_text, second_text) = (text(first), text(second));
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
