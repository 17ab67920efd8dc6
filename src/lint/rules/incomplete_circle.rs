//! N025 `incomplete-circle`: Finds a circle (`G2`, `G3`) without its centre or radius, or with a radius and no end point.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockWords, FileContext};
use crate::lint::rules::support::moves_a_named_axis;
use crate::semantic::addresses::Address;
use crate::semantic::modal::is_axis_letter;
use crate::span::Span;
use crate::syntax::plain::{Letters, PlainFacts};
use crate::syntax::tree::Block;

pub static RULE: RuleInfo = RuleInfo {
    code: "N025",
    name: "incomplete-circle",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a block that programs a circle with `G2` or `G3` and
- moves to an end point (an axis address) with neither a centre (`I J K`) nor a radius or aperture
  (`CR`, `AR`; `R` in ISO dialect), or
- gives the radius `CR` and no end point.
Only blocks that write `G2`/`G3` themselves are checked. A polar end point (`AP`, `RP`) is an end
point whose centre is the pole.

## Why it matters
The centre's `I J K` and the radius `CR` hold for their block only (Siemens, Programming Manual
Fundamentals, "Circular interpolation"): a circle block needs one of them, and a radius cannot
describe a full circle, so `CR` needs an end point other than the start. The control stops with an
alarm at the block.

## Example
```
N10 G2 X50 Y20 F200
N20 G3 CR=15
```

## Fix
Give the centre (`I J K`, incremental from the start by default) or the radius `CR=`, and the end
point."#,
};

/// What a circle block has.
#[derive(Default)]
struct Circle {
    /// The words of the block, from its `G2`/`G3` on.
    circle: Option<Span>,
    end: bool,
    centre: bool,
    radius: Option<Address>,
}

impl Circle {
    fn of(source: &[u8], addresses: &[Address]) -> Self {
        let mut circle = Self::default();
        for address in addresses {
            let single = address.name.len() == 1;
            let letter = address.letter(source);
            if let Some(words) = &mut circle.circle {
                *words = words.to(address.span);
            }
            if single && letter == b'G' && matches!(address.whole(source), Some(2 | 3)) {
                circle.circle.get_or_insert(address.span);
            } else if single && is_axis_letter(letter) {
                circle.end = true;
            } else if address.is(source, "AP") || address.is(source, "RP") {
                // A polar end point: the circle's centre is the pole.
                circle.end = true;
                circle.centre = true;
            } else if single && matches!(letter, b'I' | b'J' | b'K' | b'R')
                || address.is(source, "AR")
            {
                circle.centre = true;
            } else if address.is(source, "CR") {
                circle.radius = Some(*address);
            }
        }
        circle
    }
}

/// The default axis names, and what gives a plain line's circle its centre
/// or (ISO) radius.
const AXES: Letters = Letters::of(b"XYZABCUVW");
const CENTRE_OR_RADIUS: Letters = Letters::of(b"IJKR");

pub struct Checker;

impl BlockWords for Checker {
    /// A plain line cannot hold CR: with a centre or an ISO radius it is
    /// complete, without an axis it has no end point.
    fn may_find(facts: &PlainFacts) -> bool {
        (facts.motions.contains(2) || facts.motions.contains(3))
            && facts.letters.meets(AXES)
            && !facts.letters.meets(CENTRE_OR_RADIUS)
    }

    fn check(
        file: &FileContext,
        block: Option<&Block>,
        addresses: &[Address],
        out: &mut Vec<Diagnostic>,
    ) {
        let mut circle = Circle::of(file.source, addresses);
        circle.end |= block.is_some_and(|block| moves_a_named_axis(file, block));
        report(&circle, out);
    }
}

/// The finding of a circle block that lacks what it needs.
fn report(circle: &Circle, out: &mut Vec<Diagnostic>) {
    let Some(words) = circle.circle else {
        return;
    };
    if circle.end && !circle.centre && circle.radius.is_none() {
        out.push(
            RULE.at(words)
                .message(
                    "the circle has an end point but neither a centre (I, J, K) nor a radius (CR)",
                )
                .label("circle without centre or radius")
                .help("give the centre with I, J, K (from the start point) or the radius with CR="),
        );
    } else if let Some(radius) = circle.radius.filter(|_| !circle.end) {
        out.push(
            RULE.at(radius.span)
                .message("the circle has a radius but no end point: a radius cannot describe a full circle")
                .label("radius without end point")
                .help("give the end point, or the centre with I, J, K for a full circle"),
        );
    }
}
