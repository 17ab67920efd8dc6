//! The tool centre's path under tool radius compensation (G41/G42) in the
//! working plane: each contour element moved by the radius to the tool's
//! side, and the corners between them (Siemens, Programming Manual
//! Fundamentals, "Tool radius compensation" and "Corner behavior"): at an
//! outside corner a circle about the corner (G450) or the moved elements
//! extended until they meet (G451); at an inside corner, always where the
//! moved elements meet. Pure math on the plane's two coordinates (its
//! horizontal and vertical axis, a counter-clockwise turn from the first to
//! the second).

use std::f64::consts::{PI, TAU};

use nalgebra::Vector2;

pub type Point = Vector2<f64>;

/// Below this a cross product of two directions is a tangent transition,
/// and a length is none.
const FLAT: f64 = 1e-9;

/// A contour element in the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Element {
    Line {
        from: Point,
        to: Point,
    },
    /// About `centre`, from the angle `start` by `sweep` radians
    /// (positive counter-clockwise; a full turn or more where it says so).
    Arc {
        centre: Point,
        radius: f64,
        start: f64,
        sweep: f64,
    },
}

/// How the centre's path passes from one element to the next.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Join {
    /// Where the moved element before ends.
    pub end_before: Point,
    /// The circle about the corner between them (G450 at an outside corner).
    pub circle: Option<Element>,
    /// Where the moved element after starts.
    pub start_after: Point,
    /// Whether the corner is an outside one (the tool on the side the
    /// contour turns away from).
    pub outside: bool,
}

/// Why two moved elements have no join.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoJoin {
    /// At an inside corner the moved elements do not meet on both: one
    /// is shorter than the radius allows (a bottleneck).
    Bottleneck,
}

impl Element {
    pub fn from(&self) -> Point {
        match *self {
            Element::Line { from, .. } => from,
            Element::Arc {
                centre,
                radius,
                start,
                ..
            } => centre + radius * direction(start),
        }
    }

    pub fn to(&self) -> Point {
        match *self {
            Element::Line { to, .. } => to,
            Element::Arc {
                centre,
                radius,
                start,
                sweep,
            } => centre + radius * direction(start + sweep),
        }
    }

    /// The unit direction of travel at the start.
    pub fn start_direction(&self) -> Point {
        match *self {
            Element::Line { from, to } => (to - from).normalize(),
            Element::Arc { start, sweep, .. } => tangent(start, sweep),
        }
    }

    /// The unit direction of travel at the end.
    pub fn end_direction(&self) -> Point {
        match *self {
            Element::Line { .. } => self.start_direction(),
            Element::Arc { start, sweep, .. } => tangent(start + sweep, sweep),
        }
    }

    pub fn length(&self) -> f64 {
        match *self {
            Element::Line { from, to } => (to - from).norm(),
            Element::Arc { radius, sweep, .. } => radius * sweep.abs(),
        }
    }

    /// The element moved by `offset` to the left of its direction of travel
    /// (to the right where negative): a line beside it, an arc about the
    /// same centre. `None` where an arc's radius would not stay positive
    /// (the tool does not fit inside it).
    pub fn offset(&self, offset: f64) -> Option<Element> {
        match *self {
            Element::Line { from, to } => {
                let left = left_of(self.start_direction()) * offset;
                Some(Element::Line {
                    from: from + left,
                    to: to + left,
                })
            }
            Element::Arc {
                centre,
                radius,
                start,
                sweep,
            } => {
                // Left of a counter-clockwise arc is its centre.
                let radius = radius - offset * sweep.signum();
                (radius > FLAT).then_some(Element::Arc {
                    centre,
                    radius,
                    start,
                    sweep,
                })
            }
        }
    }

    /// The element from `from` to `to`, both on it or on its extension (a
    /// line's, or the arc's circle): its start and end moved along it by
    /// less than a half turn.
    pub fn between(&self, from: Point, to: Point) -> Element {
        match *self {
            Element::Line { .. } => Element::Line { from, to },
            Element::Arc {
                centre,
                radius,
                start,
                sweep,
            } => {
                let angle = |p: Point| (p.y - centre.y).atan2(p.x - centre.x);
                let new_start = angle(from);
                let new_end = angle(to);
                let moved_start = wrap(new_start - start);
                let moved_end = wrap(new_end - (start + sweep));
                Element::Arc {
                    centre,
                    radius,
                    start: start + moved_start,
                    sweep: sweep - moved_start + moved_end,
                }
            }
        }
    }

    /// Whether `p` lies on the element (within `FLAT` times its size).
    fn holds(&self, p: Point) -> bool {
        let tolerance = FLAT * (1.0 + self.from().norm() + self.length());
        match *self {
            Element::Line { from, to } => {
                let d = to - from;
                let t = (p - from).dot(&d) / d.norm_squared();
                (-tolerance..=1.0 + tolerance).contains(&t)
            }
            Element::Arc { start, sweep, .. } => {
                let centre = self.centre();
                let angle = (p.y - centre.y).atan2(p.x - centre.x);
                let along = if sweep > 0.0 {
                    (angle - start).rem_euclid(TAU)
                } else {
                    (start - angle).rem_euclid(TAU)
                };
                along <= sweep.abs() + tolerance || along >= TAU - tolerance
            }
        }
    }

    fn centre(&self) -> Point {
        match *self {
            Element::Line { from, .. } => from,
            Element::Arc { centre, .. } => centre,
        }
    }
}

/// The join at `corner` (the programmed point between the elements) of the
/// moved elements `before` and `after`, moved by `offset` (positive to the
/// left). `circle_outside` says, from how far the contour turns there
/// (degrees), whether an outside corner gets a circle about it (G450) or
/// the moved elements extended to where they meet (G451).
pub fn join(
    before: &Element,
    after: &Element,
    corner: Point,
    offset: f64,
    circle_outside: impl Fn(f64) -> bool,
) -> Result<Join, NoJoin> {
    let (end, start) = (before.to(), after.from());
    let (t_before, t_after) = (before.end_direction(), after.start_direction());
    let turn = cross(t_before, t_after);
    if turn.abs() <= FLAT && t_before.dot(&t_after) > 0.0 {
        return Ok(Join {
            end_before: end,
            circle: None,
            start_after: start,
            outside: false,
        });
    }
    // Outside: the tool on the side the contour turns away from.
    let reverses = turn.abs() <= FLAT;
    let outside = reverses || offset * turn < 0.0;
    let turned = turn.abs().atan2(t_before.dot(&t_after)).to_degrees();
    // The circle about the corner, from the one moved element to the other.
    let circle = || {
        let (u, w) = (end - corner, start - corner);
        let sweep = if reverses {
            -PI * offset.signum()
        } else {
            cross(u, w).atan2(u.dot(&w))
        };
        Ok(Join {
            end_before: end,
            circle: Some(Element::Arc {
                centre: corner,
                radius: offset.abs(),
                start: u.y.atan2(u.x),
                sweep,
            }),
            start_after: start,
            outside,
        })
    };
    if outside && (reverses || circle_outside(turned)) {
        return circle();
    }
    let meeting = meetings(before, after)
        .into_iter()
        .min_by(|a, b| (a - start).norm().total_cmp(&(b - start).norm()));
    match meeting {
        Some(p) if outside || (before.holds(p) && after.holds(p)) => Ok(Join {
            end_before: p,
            circle: None,
            start_after: p,
            outside,
        }),
        // G451 where the extended elements never meet (a line past a
        // small arc): the circle, as at a corner too pointed for G451.
        None if outside => circle(),
        _ => Err(NoJoin::Bottleneck),
    }
}

/// Whether the part of `element` from `from` to `to` runs the element's
/// way: where two inside corners come closer than the tool allows, the
/// part between them would run backwards (a bottleneck).
pub fn runs_forward(element: &Element, from: Point, to: Point) -> bool {
    match element.between(from, to) {
        Element::Line { from, to } => (to - from).dot(&element.start_direction()) >= -FLAT,
        Element::Arc { sweep, .. } => match *element {
            Element::Arc { sweep: whole, .. } => sweep * whole.signum() >= -FLAT,
            Element::Line { .. } => true,
        },
    }
}

/// Where the two elements, extended (a line to both sides, an arc to its
/// circle), cross.
fn meetings(a: &Element, b: &Element) -> Vec<Point> {
    match (*a, *b) {
        (Element::Line { from, to }, Element::Line { from: c, to: d }) => {
            let (r, s) = (to - from, d - c);
            let denominator = cross(r, s);
            if denominator.abs() <= FLAT * r.norm() * s.norm() {
                return Vec::new();
            }
            vec![from + r * (cross(c - from, s) / denominator)]
        }
        (Element::Line { from, to }, Element::Arc { centre, radius, .. })
        | (Element::Arc { centre, radius, .. }, Element::Line { from, to }) => {
            line_circle(from, to, centre, radius)
        }
        (
            Element::Arc {
                centre: c1,
                radius: r1,
                ..
            },
            Element::Arc {
                centre: c2,
                radius: r2,
                ..
            },
        ) => circle_circle(c1, r1, c2, r2),
    }
}

fn line_circle(from: Point, to: Point, centre: Point, radius: f64) -> Vec<Point> {
    let d = (to - from).normalize();
    let foot = from + d * (centre - from).dot(&d);
    let distance = (foot - centre).norm();
    if distance > radius * (1.0 + FLAT) {
        return Vec::new();
    }
    let half = (radius * radius - distance * distance).max(0.0).sqrt();
    vec![foot - d * half, foot + d * half]
}

fn circle_circle(c1: Point, r1: f64, c2: Point, r2: f64) -> Vec<Point> {
    let between = c2 - c1;
    let distance = between.norm();
    if distance <= FLAT || distance > (r1 + r2) * (1.0 + FLAT) || distance < (r1 - r2).abs() {
        return Vec::new();
    }
    let along = (distance * distance + r1 * r1 - r2 * r2) / (2.0 * distance);
    let half = (r1 * r1 - along * along).max(0.0).sqrt();
    let unit = between / distance;
    let middle = c1 + unit * along;
    vec![middle + left_of(unit) * half, middle - left_of(unit) * half]
}

fn direction(angle: f64) -> Point {
    Point::new(angle.cos(), angle.sin())
}

/// The direction of travel at `angle` on an arc turning by `sweep`'s sign.
fn tangent(angle: f64, sweep: f64) -> Point {
    left_of(direction(angle)) * sweep.signum()
}

fn left_of(d: Point) -> Point {
    Point::new(-d.y, d.x)
}

fn cross(a: Point, b: Point) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `angle` into (-π, π].
fn wrap(angle: f64) -> f64 {
    let wrapped = angle.rem_euclid(TAU);
    if wrapped > PI {
        wrapped - TAU
    } else {
        wrapped
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: Point, b: Point) -> bool {
        (a - b).norm() < 1e-9
    }

    fn line(a: (f64, f64), b: (f64, f64)) -> Element {
        Element::Line {
            from: Point::new(a.0, a.1),
            to: Point::new(b.0, b.1),
        }
    }

    /// Along +X, then up +Y: a left turn at (10, 0).
    fn left_turn() -> (Element, Element, Point) {
        (
            line((0.0, 0.0), (10.0, 0.0)),
            line((10.0, 0.0), (10.0, 10.0)),
            Point::new(10.0, 0.0),
        )
    }

    #[test]
    fn a_line_moves_to_the_left_or_right_of_its_travel() {
        let along_x = line((0.0, 0.0), (10.0, 0.0));
        assert_eq!(along_x.offset(2.0), Some(line((0.0, 2.0), (10.0, 2.0))));
        assert_eq!(along_x.offset(-2.0), Some(line((0.0, -2.0), (10.0, -2.0))));
    }

    #[test]
    fn left_of_a_counter_clockwise_arc_is_its_centre() {
        let ccw = Element::Arc {
            centre: Point::zeros(),
            radius: 10.0,
            start: 0.0,
            sweep: PI / 2.0,
        };
        let moved = ccw.offset(2.0);
        assert!(matches!(moved, Some(Element::Arc { radius, .. }) if (radius - 8.0).abs() < 1e-12));
        assert!(near(ccw.start_direction(), Point::new(0.0, 1.0)));
        assert!(near(ccw.end_direction(), Point::new(-1.0, 0.0)));
        let cw = Element::Arc {
            centre: Point::zeros(),
            radius: 10.0,
            start: 0.0,
            sweep: -PI / 2.0,
        };
        assert!(
            matches!(cw.offset(2.0), Some(Element::Arc { radius, .. }) if (radius - 12.0).abs() < 1e-12)
        );
        // A tool larger than the arc inside it does not fit.
        assert_eq!(ccw.offset(10.0), None);
    }

    #[test]
    fn an_outside_corner_gets_a_circle_or_the_meeting_point() {
        // The tool on the right of a left turn is outside.
        let (a, b, corner) = left_turn();
        let (ma, mb) = (a.offset(-2.0).unwrap_or(a), b.offset(-2.0).unwrap_or(b));
        let circle = join(&ma, &mb, corner, -2.0, |_| true);
        let Ok(Join {
            end_before,
            circle: Some(arc),
            start_after,
            outside: true,
        }) = circle
        else {
            panic!("no circle: {circle:?}");
        };
        assert!(near(end_before, Point::new(10.0, -2.0)));
        assert!(near(start_after, Point::new(12.0, 0.0)));
        assert!(near(arc.from(), end_before) && near(arc.to(), start_after));
        // About the corner, turning left a quarter with the contour.
        assert!(matches!(arc, Element::Arc { centre, radius, sweep, .. }
            if near(centre, corner) && (radius - 2.0).abs() < 1e-12 && (sweep - PI / 2.0).abs() < 1e-12));
        let meeting = join(&ma, &mb, corner, -2.0, |_| false);
        assert_eq!(
            meeting.map(|j| (j.end_before, j.circle)),
            Ok((Point::new(12.0, -2.0), None))
        );
    }

    #[test]
    fn an_inside_corner_is_where_the_moved_elements_meet() {
        let (a, b, corner) = left_turn();
        let (ma, mb) = (a.offset(2.0).unwrap_or(a), b.offset(2.0).unwrap_or(b));
        let joined = join(&ma, &mb, corner, 2.0, |_| true);
        assert_eq!(
            joined.map(|j| (j.end_before, j.start_after)),
            Ok((Point::new(8.0, 2.0), Point::new(8.0, 2.0)))
        );
        // A step shorter than the radius: the moved elements miss each other.
        let short = line((10.0, 0.0), (10.0, 1.0));
        let c = line((10.0, 1.0), (0.0, 1.0));
        let (ms, mc) = (
            short.offset(2.0).unwrap_or(short),
            c.offset(2.0).unwrap_or(c),
        );
        assert_eq!(
            join(&ms, &mc, Point::new(10.0, 1.0), 2.0, |_| true),
            Err(NoJoin::Bottleneck)
        );
    }

    #[test]
    fn a_line_into_a_tangent_arc_joins_without_a_corner() {
        let a = line((-10.0, -10.0), (0.0, -10.0));
        let arc = Element::Arc {
            centre: Point::zeros(),
            radius: 10.0,
            start: -PI / 2.0,
            sweep: PI,
        };
        let (ma, mb) = (a.offset(3.0).unwrap_or(a), arc.offset(3.0).unwrap_or(arc));
        let joined = join(&ma, &mb, Point::new(0.0, -10.0), 3.0, |_| true);
        assert!(
            joined.is_ok_and(|j| j.circle.is_none() && near(j.end_before, Point::new(0.0, -7.0)))
        );
    }

    #[test]
    fn an_arc_cut_short_keeps_its_centre_and_direction() {
        let arc = Element::Arc {
            centre: Point::new(1.0, 1.0),
            radius: 5.0,
            start: 0.0,
            sweep: -PI,
        };
        let from = Point::new(1.0, 1.0) + 5.0 * direction(-0.1);
        let to = Point::new(1.0, 1.0) + 5.0 * direction(-PI + 0.2);
        let cut = arc.between(from, to);
        assert!(near(cut.from(), from) && near(cut.to(), to));
        assert!(matches!(cut, Element::Arc { sweep, .. } if (sweep + PI - 0.3).abs() < 1e-12));
    }
}
