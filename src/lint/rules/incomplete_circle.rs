//! N025 `incomplete-circle`: Finds a circle (`G2`, `G3`) without its centre or radius, or with a radius and no end point.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, Sees};
use crate::lint::rules::support::moves_a_named_axis;
use crate::semantic::addresses;
use crate::semantic::addresses::Address;
use crate::semantic::modal::{g_group, is_axis_letter};
use crate::semantic::model::PlainLine;
use crate::span::Span;
use crate::syntax::plain::{Letters, Motions};
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N025",
    name: "incomplete-circle",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a block that programs a circle with `G2` or `G3` and
- moves to an end point (an axis address) with neither a centre (`I J K`) nor a radius or aperture
  (`CR`, `AR`; `R` in ISO dialect), or
- gives the radius `CR` and no end point.
The circle is followed from block to block: a block after a `G2`/`G3` block that moves with
neither centre nor radius is the same mistake (`G2 X10 Y0 CR=5` then `X20 Y0`, as if `CR` held
on). Where the order the blocks run in is not known (after a label a jump may reach, a call, a
command, a control structure or a skipped block that changes the motion), the circle in force is
not assumed, so nothing is reported there. A polar end point (`AP`, `RP`) is an end
point whose centre is the pole.

Nor where the block's axis words mean something else: with a G function of group 2 or 3 (`G4`,
`G74`, `G110`-`G112`, `G25`/`G26`).

## Why it matters
The centre's `I J K`, the radius `CR` and the aperture `AR` hold for their block only (Siemens,
Programming Manual, "Circular interpolation" and the table of addresses, where they are non-modal,
"s"), while `G2`/`G3` stays in force: a circle block needs one of them, and a radius cannot
describe a full circle, so `CR` needs an end point other than the start. Without them the centre
is the start point and the end point lies off the circle: the control stops with an alarm at the
block.

## Example
```
N10 G2 X50 Y20 F200
N20 G3 CR=15
N30 G2 X10 Y0 CR=5
N40 X20 Y0
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

/// The circle in force is followed from block to block in the order they
/// run: straight on from a `G2`/`G3`, and no longer known after a label (a
/// jump may arrive), a call, a command, a control structure or a skipped
/// block that changes the motion.
#[derive(Default)]
pub struct Checker {
    /// `G2` or `G3` in force.
    circle: Option<u32>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::HEADERS | Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn header(&mut self, _file: &FileContext, _row: usize, _name: Span) {
        self.circle = None;
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        let block = at.block;
        if block.label.is_some() {
            self.circle = None;
        }
        let addresses = at.line.addresses(file.source);
        let mut circle = Circle::of(file.source, addresses);
        circle.end |= moves_a_named_axis(file, block);
        let words_only = block
            .statements
            .iter()
            .all(|s| matches!(s.kind, StatementKind::Word(_) | StatementKind::Assign(_)));
        self.step(file.source, &circle, addresses, words_only, out);
        if !words_only || (block.skip.is_some() && motion_of(file.source, addresses).is_some()) {
            self.circle = None;
        }
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        let source = file.source;
        for line in lines {
            let facts = &line.facts;
            let m = facts.motions;
            // Without centre or radius, and moving: a finding if a circle
            // is programmed here or in force.
            let bare = || facts.letters.meets(AXES) && !facts.letters.meets(CENTRE_OR_RADIUS);
            match m.only() {
                // Most lines of a CAM program: no G function, so the motion
                // stays, and no finding unless a circle is in force.
                None if m == Motions::default() && (self.circle.is_none() || !bare()) => {
                    continue;
                }
                // One of G0 to G3, read from the scan's bits: a straight
                // motion cannot be a finding, a circle with its centre or
                // radius neither.
                Some(0 | 1) => {
                    self.circle = None;
                    continue;
                }
                Some(circle) if !bare() => {
                    self.circle = Some(circle);
                    continue;
                }
                _ => {}
            }
            let addresses = addresses::of_plain(source, line.raw.content);
            self.step(
                source,
                &Circle::of(source, &addresses),
                &addresses,
                true,
                out,
            );
        }
    }
}

impl Checker {
    /// The block's findings, and the circle in force after it.
    fn step(
        &mut self,
        source: &[u8],
        circle: &Circle,
        addresses: &[Address],
        words_only: bool,
        out: &mut Vec<Diagnostic>,
    ) {
        let motion = motion_of(source, addresses);
        if circle.circle.is_some() {
            report(circle, out);
        } else if let (Some(number), true, None) = (self.circle, words_only, motion) {
            // Under a G function of group 2 or 3 (G4, G74, G111, G25, ...)
            // the axis words are no end point: a dwell, a reference point, a
            // pole, a limit.
            let other_meaning = addresses.iter().any(|a| {
                a.is(source, "G")
                    && a.whole(source)
                        .is_some_and(|n| matches!(g_group(n), Some(2 | 3)))
            });
            if !other_meaning {
                report_in_force(number, circle, addresses, out);
            }
        }
        if let Some(motion) = motion {
            self.circle = matches!(motion, 2 | 3).then_some(motion);
        }
    }
}

/// The motion a block programs: its last group 1 G function.
fn motion_of(source: &[u8], addresses: &[Address]) -> Option<u32> {
    addresses
        .iter()
        .filter(|a| a.is(source, "G"))
        .filter_map(|a| a.whole(source))
        .rfind(|&n| g_group(n) == Some(1))
}

/// The finding of a block that moves under a circle programmed before it,
/// without the centre or radius that hold for one block only.
fn report_in_force(number: u32, circle: &Circle, addresses: &[Address], out: &mut Vec<Diagnostic>) {
    let (Some(first), Some(last)) = (addresses.first(), addresses.last()) else {
        return;
    };
    let words = Span::new(first.span.start, last.span.end);
    if circle.end && !circle.centre && circle.radius.is_none() {
        out.push(
            RULE.at(words)
                .message(format!(
                    "this block moves under G{number}, in force from an earlier block, with neither a centre (I, J, K) nor a radius (CR): they hold for one block only"
                ))
                .label(format!("a G{number} circle without centre or radius"))
                .help("give the centre or the radius in this block too, or G1 if a straight line is meant"),
        );
    } else if let Some(radius) = circle.radius.filter(|_| !circle.end) {
        out.push(
            RULE.at(radius.span)
                .message(format!("this block gives G{number}'s circle, in force from an earlier block, a radius but no end point: a radius cannot describe a full circle"))
                .label("radius without end point")
                .help("give the end point, or the centre with I, J, K for a full circle"),
        );
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
