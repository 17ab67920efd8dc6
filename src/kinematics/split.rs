//! Three rotary axes: a rotary table (a P record of one axis) under a
//! two-axis head (a T record), the heavy horizontal machines CYCLE600 was
//! built for, which CYCLE800 alone cannot drive.
//!
//! The table turns the workpiece by `R_t = R(u, γ)⁻¹`, the head the tool by
//! `H`; the head must then point the tool along `q(γ) = R(u, γ) · f` (`f`
//! the requested frame's Z axis). One tool direction leaves one degree of
//! freedom, the table's angle `γ`: fixed (given), or chosen under a
//! [`Preference`] (the head nearest the middles of its limits, or the three
//! axes nearest where they stand); the head is then solved for what is
//! left, `R_t⁻¹ · R_req`, with its two solutions, `_DIR`, Hirth grid and
//! the residual about the tool axis. The zero-point shift is the table's.
//!
//! The table's angle is found exactly, not searched for. For each `γ` the
//! head's angles are Paden-Kahan's (subproblem 2); every event that
//! changes how they behave is the root of a sinusoid in `γ` (`k · q(γ) =
//! y` for a fixed `k`): a head axis at a given position (its middle, a
//! limit, where it is placed a turn further), the head's reach ending, an
//! axis turning back (the first axis's: where the table's circle of
//! directions touches a circle of constant first angle). Between two events
//! each axis's distance from its target only grows or only shrinks, so the
//! best of the largest of them lies at an event or where two of them are
//! equal, found by a root finder on that interval. Nothing the table can
//! do is missed, however narrow.

use nalgebra::{Rotation3, Vector3};

use crate::kinematics::record::{Hirth, Kinematics, Record, RecordError};
use crate::kinematics::subproblem::UpToTwo;
use crate::kinematics::swivel::{
    choose, shift, solutions, solve_toward, Direction, Request, Solution, Swivel,
};
use crate::rotation::frame::from_axis_angle;
use crate::rotation::trig::{atan2_degrees, sin_cos_degrees};

/// Which table angle is taken when it is not fixed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Preference {
    /// The head's axes nearest the middles of their limits: the largest
    /// distance from a middle, as a share of its half range, the smallest
    /// (an axis whose limits hold a whole turn has no middle to keep to);
    /// of equally good angles, the one nearest the table's position. The
    /// default: the head keeps the most of its travel for the machining
    /// that follows, and the answer does not depend on where the axes stood
    /// (offline that is seldom known), so a program gets the same positions
    /// wherever it is run from.
    #[default]
    Middle,
    /// The three axes nearest their positions before the swivel, as CAM
    /// systems choose: the largest of the three travels (degrees) the
    /// smallest, the axes moving together.
    Nearest,
}

impl Preference {
    pub fn name(self) -> &'static str {
        match self {
            Self::Middle => "middle",
            Self::Nearest => "nearest",
        }
    }
}

/// What a split asks of the table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TableAsk {
    /// The table's position before the swivel (degrees).
    pub current: f64,
    /// The table's position, fixed instead of chosen.
    pub fixed: Option<f64>,
    pub prefer: Preference,
}

/// How the table's angle was found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TableAngle {
    /// As given.
    Fixed,
    /// Chosen under the preference, the head inside its limits.
    Chosen(Preference),
    /// No table position brings the head inside its limits: the position
    /// where it comes nearest them, its solution `solution` (an index of
    /// the head's solutions) at most `beyond_deg` degrees beyond a limit.
    Beyond { solution: usize, beyond_deg: f64 },
    /// No table position lets the head turn the tool onto the frame's Z
    /// axis: the table's position is kept.
    Unreachable,
}

/// A swivel split between a table and a head.
#[derive(Clone, Debug, PartialEq)]
pub struct Split {
    /// The table's position (degrees, its offset applied, on its Hirth grid
    /// if it has one).
    pub table: f64,
    pub table_within_limits: bool,
    pub found: TableAngle,
    /// The head's swivel for what the table leaves.
    pub head: Swivel,
    /// What the table leaves the head: the requested rotation with the
    /// table's taken out, `T⁻¹ · R_req` (the frame CYCLE800 on the head's
    /// record is asked for once the table has turned).
    pub head_frame: Rotation3<f64>,
    /// The table axis's turn `R(v1, α)` of the record's shift
    /// (`l2 + R(v1, α) (l3 + l4) − (l2 + l3 + l4)`, the vector as entered).
    pub table_turn: Rotation3<f64>,
    /// The zero-point shift the table's offset vectors make: how far the
    /// end of its chain moves.
    pub shift: Vector3<f64>,
}

impl Split {
    /// How far a work zero at `x` (machine coordinates, the initial state)
    /// moves as the table turns: `shift + (R − I) · x`, the chain's end
    /// moving by `shift` and the work zero turning with the table about it.
    pub fn work_zero_moves(&self, x: &Vector3<f64>) -> Vector3<f64> {
        self.shift + (self.table_turn * x - x)
    }

    /// The head's swivel with the table's zero-point shift in place of the
    /// head's (a head's offsets shift nothing): what the table and the head
    /// together do.
    pub fn together(&self) -> Swivel {
        let mut head = self.head.clone();
        head.shift = head.shift.map(|shift| shift + self.shift);
        head
    }
}

/// Records that do not make a table under a head.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SplitError {
    #[error("the table record must be kinematics \"P\" with one rotary axis")]
    NotATable,
    #[error("the head record must be kinematics \"T\" with two rotary axes")]
    NotAHead,
    #[error(transparent)]
    Record(#[from] RecordError),
}

/// The table's and the head's positions for `request`, the table's as
/// `ask` says.
pub fn split(
    table: &Record,
    head: &Record,
    request: &Request,
    ask: &TableAsk,
) -> Result<Split, SplitError> {
    table.check()?;
    head.check()?;
    if table.kinematics != Kinematics::Table || table.axis_count() != 1 {
        return Err(SplitError::NotATable);
    }
    if head.kinematics != Kinematics::Head || head.axis_count() != 2 {
        return Err(SplitError::NotAHead);
    }
    if let Some(gamma) = ask.fixed {
        let problem = Problem::at(table, head, request, gamma);
        return Ok(problem.split(0.0, TableAngle::Fixed));
    }
    let problem = Problem::new(table, head, request, ask.current);
    let hirth = table.axes[0].hirth.filter(|h| h.increment > 0.0);
    let goal = match ask.prefer {
        Preference::Middle => Goal::Middle,
        Preference::Nearest => Goal::Nearest,
    };
    if let Some(best) = problem.minimise(&problem.events(goal), goal, Select::Chosen, hirth) {
        return Ok(problem.split(best.t, TableAngle::Chosen(ask.prefer)));
    }
    // Nowhere inside the limits: each of the head's two solutions as near
    // them as it comes, the nearer taken.
    let events = problem.events(Goal::Beyond);
    let nearest = [0, 1]
        .into_iter()
        .filter_map(|branch| problem.minimise(&events, Goal::Beyond, Select::Branch(branch), hirth))
        .reduce(|a, b| if problem.better(&b, &a) { b } else { a });
    Ok(match nearest {
        Some(best) => problem.split(
            best.t,
            TableAngle::Beyond {
                solution: best.branch,
                beyond_deg: best.cost,
            },
        ),
        None => problem.split(
            problem.current.clamp(0.0, problem.width),
            TableAngle::Unreachable,
        ),
    })
}

/// [`split`] `--prefer nearest` with `_DIR` left open: the split under each
/// `_DIR`, and of the two the one whose axes travel least (the largest
/// travel of the table's and the head's axes, the head's taken solution
/// inside its limits; a tie to `_DIR` -1). The other head solution may be
/// nearer than the one `_DIR` -1 takes: CAM systems choose over both. The
/// `_DIR` taken comes with it, for the CYCLE800 that is to select it.
pub fn split_nearest_either_way(
    table: &Record,
    head: &Record,
    request: &Request,
    current_table: f64,
) -> Result<(Split, Direction), SplitError> {
    let ask = TableAsk {
        current: current_table,
        fixed: None,
        prefer: Preference::Nearest,
    };
    let travel = |split: &Split| {
        let chosen = split
            .head
            .chosen
            .map(|i| split.head.solutions[i].positions)?;
        let head = (0..head.axis_count())
            .map(|i| (chosen[i] - request.current[i]).abs())
            .fold(0.0, f64::max);
        Some(head.max((split.table - current_table).abs()))
    };
    let under = |direction| {
        split(
            table,
            head,
            &Request {
                direction,
                ..*request
            },
            &ask,
        )
    };
    let (minus, plus) = (under(Direction::Minus)?, under(Direction::Plus)?);
    let plus_is_nearer = match (travel(&minus), travel(&plus)) {
        (Some(minus), Some(plus)) => plus < minus - 1e-9,
        (None, Some(_)) => true,
        _ => false,
    };
    Ok(match plus_is_nearer {
        true => (plus, Direction::Plus),
        false => (minus, Direction::Minus),
    })
}

/// What is made as small as it can be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Goal {
    /// [`Preference::Middle`].
    Middle,
    /// [`Preference::Nearest`].
    Nearest,
    /// How far the head lies beyond its limits (degrees, the largest of
    /// its axes').
    Beyond,
}

/// Which of the head's solutions is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Select {
    /// The one the control takes (`_DIR`, inside the limits).
    Chosen,
    /// The first or second, wherever it lies.
    Branch(usize),
}

/// One table position measured.
#[derive(Clone, Copy, Debug)]
struct Point {
    /// Degrees from the start of the turn searched.
    t: f64,
    /// The largest of `parts`.
    cost: f64,
    /// Each axis's share of the cost (the table's, the head's first and
    /// second), NaN for an axis the goal leaves out.
    parts: [f64; 3],
    /// The head's solution measured (its index).
    branch: usize,
}

/// A table position and what was measured there (`None`: no solution the
/// selection takes).
type Measured = (f64, Option<Point>);

/// Events closer than this (degrees) are one.
const MERGE: f64 = 1e-10;
/// How far inside an interval its ends are measured (degrees): a value at
/// an event may belong to either side of it.
const NUDGE: f64 = 1e-11;

/// The split's one-angle problem: the head's tool direction as the table
/// turns, and what is measured there.
struct Problem<'a> {
    table: &'a Record,
    head: &'a Record,
    request: &'a Request,
    direction: Direction,
    /// The head's axes before the swivel.
    head_current: [f64; 2],
    /// The table's axis (unit) and the requested tool direction.
    u: Vector3<f64>,
    f: Vector3<f64>,
    u_cross_f: Vector3<f64>,
    u_dot_f: f64,
    /// The turn searched: the table's position `low + t` for `t` in
    /// `[0, width]`, its model angle `x0 + t` (`x0` in `[0, 360)`, so that
    /// the turn's size does not cost precision).
    low: f64,
    width: f64,
    x0: f64,
    /// The table's position before the swivel, as a `t`.
    current: f64,
}

impl<'a> Problem<'a> {
    /// The table's turn nearest `current` (where its limits allow).
    fn new(table: &'a Record, head: &'a Record, request: &'a Request, current: f64) -> Self {
        let (low, high) = table.axes[0]
            .limits
            .unwrap_or((current - 180.0, current + 180.0));
        // The head sees the table's angle modulo a turn: the turn of the
        // limits nearest the current position holds an angle as good as any
        // other, and, of equally good ones, the one nearest the current
        // position. So limits of many turns (up to ±1e8 degrees) are searched
        // over one.
        let low = (current - 180.0).max(low).min(low.max(high - 360.0));
        let high = high.min(low + 360.0);
        Self::over(table, head, request, low, high, current)
    }

    /// The table at `gamma` alone.
    fn at(table: &'a Record, head: &'a Record, request: &'a Request, gamma: f64) -> Self {
        Self::over(table, head, request, gamma, gamma, gamma)
    }

    fn over(
        table: &'a Record,
        head: &'a Record,
        request: &'a Request,
        low: f64,
        high: f64,
        current: f64,
    ) -> Self {
        let u = table.axes[0].vector.normalize();
        let f = request.rotation * Vector3::z();
        Problem {
            table,
            head,
            request,
            direction: request.direction,
            head_current: request.current,
            u,
            f,
            u_cross_f: u.cross(&f),
            u_dot_f: u.dot(&f),
            low,
            width: (high - low).max(0.0),
            x0: (low - table.axes[0].offset).rem_euclid(360.0),
            current: current - low,
        }
    }

    /// The split with the table at `t`: the head solved for the direction
    /// [`Self::measure`] measures there, so that it takes the solution
    /// measured, however near a limit.
    fn split(&self, t: f64, found: TableAngle) -> Split {
        let axis = &self.table.axes[0];
        let mut gamma = self.position(t);
        let table_within_limits = axis
            .limits
            .is_none_or(|(min, max)| (min - 1e-9..=max + 1e-9).contains(&gamma));
        // Within the tolerance of a limit counts as at it, and is put there
        // (as the head's positions are): a position printed never lies
        // beyond a limit it is said to keep. Elsewhere `t` stays as
        // measured: `(low + t) - low` may differ from it in the last bit,
        // and a best point beside a jump (the head's axis taking another
        // turn) would then be solved on the jump's other side.
        let mut t = t;
        if let Some((min, max)) = axis.limits.filter(|_| table_within_limits) {
            if !(min..=max).contains(&gamma) {
                gamma = gamma.clamp(min, max);
                t = gamma - self.low;
            }
        }
        // The table turns the workpiece by R(u, x)⁻¹: the head makes R(u, x) · R_req.
        let turned = from_axis_angle(self.u, self.x0 + t) * self.request.rotation;
        let head = solve_toward(
            self.head,
            &Request {
                rotation: turned,
                ..*self.request
            },
            &self.direction_at(t),
        );
        let found = match found {
            // The index among the solutions found at that position.
            TableAngle::Beyond {
                solution,
                beyond_deg,
            } => TableAngle::Beyond {
                solution: solution.min(head.solutions.len().saturating_sub(1)),
                beyond_deg,
            },
            found => found,
        };
        Split {
            table: gamma,
            table_within_limits,
            found,
            head,
            head_frame: turned,
            table_turn: from_axis_angle(axis.vector, self.x0 + t),
            shift: shift(self.table, [gamma - axis.offset, 0.0]),
        }
    }

    /// The table's position of `t`.
    fn position(&self, t: f64) -> f64 {
        self.low + t
    }

    /// The head's tool direction with the table at `t`.
    fn direction_at(&self, t: f64) -> Vector3<f64> {
        let (s, c) = sin_cos_degrees(self.x0 + t);
        self.f * c + self.u_cross_f * s + self.u * (self.u_dot_f * (1.0 - c))
    }

    /// The table at `t` measured for `goal`; `None` where `select` finds no
    /// solution.
    fn measure(&self, t: f64, goal: Goal, select: Select) -> Option<Point> {
        let found = solutions(self.head, &self.direction_at(t), self.head_current);
        let branch = match select {
            Select::Chosen => choose(self.head, &found, self.direction, |s| s.within_limits)?,
            Select::Branch(branch) => branch.min(found.len().checked_sub(1)?),
        };
        let parts = self.parts(t, goal, &found[branch]);
        Some(Point {
            t,
            cost: parts
                .iter()
                .filter(|p| !p.is_nan())
                .fold(0.0, |a, &b| a.max(b)),
            parts,
            branch,
        })
    }

    fn parts(&self, t: f64, goal: Goal, solution: &Solution) -> [f64; 3] {
        let mut parts = [f64::NAN; 3];
        // The positions before a Hirth grid: what the table's angle moves
        // smoothly.
        let positions = solution.exact;
        if goal == Goal::Nearest {
            parts[0] = (t - self.current).abs();
        }
        for (i, axis) in self.head.axes.iter().enumerate() {
            let narrow = axis.limits.filter(|(min, max)| max - min < 360.0);
            parts[i + 1] = match (goal, narrow) {
                (Goal::Nearest, _) => (positions[i] - self.head_current[i]).abs(),
                (Goal::Middle, Some((min, max))) => {
                    let half = (max - min) / 2.0;
                    if half > 0.0 {
                        (positions[i] - (min + half)).abs() / half
                    } else {
                        0.0
                    }
                }
                (Goal::Beyond, Some((min, max))) => {
                    let past = (positions[i] - min).rem_euclid(360.0);
                    if past <= max - min {
                        0.0
                    } else {
                        (past - (max - min)).min(360.0 - past)
                    }
                }
                _ => f64::NAN,
            };
        }
        parts
    }

    /// `a` is better than `b`: lower, or as low and nearer the table's
    /// current position.
    fn better(&self, a: &Point, b: &Point) -> bool {
        let tie = 1e-12 * b.cost.abs().max(1.0);
        a.cost < b.cost - tie
            || (a.cost <= b.cost + tie && (a.t - self.current).abs() < (b.t - self.current).abs())
    }

    /// The best table position for `goal` (its [`Self::events`] given), on
    /// the table's Hirth grid if given; `None` where no position gives a
    /// solution `select` takes.
    fn minimise(
        &self,
        events: &[Event],
        goal: Goal,
        select: Select,
        hirth: Option<Hirth>,
    ) -> Option<Point> {
        // Each event measured on either side, or once where nothing jumps.
        let sides: Vec<[Measured; 2]> = events
            .iter()
            .map(|event| {
                if event.jump && event.t > 0.0 && event.t < self.width {
                    [-NUDGE, NUDGE].map(|nudge| self.measured(event.t + nudge, goal, select))
                } else {
                    [self.measured(event.t, goal, select); 2]
                }
            })
            .collect();
        let mut best: Option<Point> = None;
        let consider = |point: Option<Point>, best: &mut Option<Point>| {
            if let Some(point) = point {
                if best.is_none_or(|b| self.better(&point, &b)) {
                    *best = Some(point);
                }
            }
        };
        for k in 1..events.len() {
            let local = self.interval(sides[k - 1][1], sides[k][0], goal, select, true);
            match hirth {
                None => consider(local, &mut best),
                Some(grid) => {
                    // Between two events the cost falls, then rises: the
                    // best grid position of the interval is one of the two
                    // around its lowest point.
                    let Some(local) = local else { continue };
                    let (left, right) = (events[k - 1].t, events[k].t);
                    for position in grid.neighbours(self.position(local.t)) {
                        let t = position - self.low;
                        if (left - MERGE..=right + MERGE).contains(&t)
                            && (0.0..=self.width).contains(&t)
                        {
                            consider(self.measure(t, goal, select), &mut best);
                        }
                    }
                }
            }
        }
        best
    }

    /// [`Self::measure`] at `t`, with `t` kept where nothing is found.
    fn measured(&self, t: f64, goal: Goal, select: Select) -> Measured {
        (t, self.measure(t, goal, select))
    }

    /// The lowest point between `left` and `right` (measured just inside
    /// two neighbouring events): an end, or where two axes' parts are equal.
    /// Where the solution measured changes between the ends, or is found at
    /// one end only (an event the closed forms placed a rounding away, near
    /// a pole), the change is found and each side searched on its own, once.
    fn interval(
        &self,
        (left_t, left): Measured,
        (right_t, right): Measured,
        goal: Goal,
        select: Select,
        split_again: bool,
    ) -> Option<Point> {
        let mut best: Option<Point> = None;
        let mut consider = |point: Option<Point>| {
            if let Some(point) = point {
                if best.is_none_or(|b| self.better(&point, &b)) {
                    best = Some(point);
                }
            }
        };
        consider(left);
        consider(right);
        match (left, right) {
            (Some(l), Some(r)) if l.branch == r.branch => {
                for (i, j) in [(0, 1), (0, 2), (1, 2)] {
                    consider(self.crossing(l, r, i, j, goal, select));
                }
            }
            (Some(_), _) | (_, Some(_)) if split_again => {
                let key = |p: &Option<Point>| p.map(|p| p.branch);
                let (mut lo, mut hi) = (left_t, right_t);
                let left_key = key(&left);
                for _ in 0..60 {
                    let mid = (lo + hi) / 2.0;
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if key(&self.measure(mid, goal, select)) == left_key {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let (lo, hi) = (
                    self.measured(lo, goal, select),
                    self.measured(hi, goal, select),
                );
                consider(self.interval((left_t, left), lo, goal, select, false));
                consider(self.interval(hi, (right_t, right), goal, select, false));
            }
            _ => {}
        }
        best
    }

    /// Where parts `i` and `j` are equal between `l` and `r` (the same
    /// solution measured at both), if they change order there: the Illinois
    /// variant of regula falsi, to a bracket of 1e-12 degrees.
    fn crossing(
        &self,
        l: Point,
        r: Point,
        i: usize,
        j: usize,
        goal: Goal,
        select: Select,
    ) -> Option<Point> {
        let h = |p: &Point| p.parts[i] - p.parts[j];
        let (mut a, mut fa, mut b, mut fb) = (l.t, h(&l), r.t, h(&r));
        if fa.is_nan() || fb.is_nan() || fa * fb >= 0.0 {
            return None;
        }
        let mut found = None;
        for step in 0..100 {
            let secant = (a * fb - b * fa) / (fb - fa);
            let (lo, hi) = (a.min(b), a.max(b));
            // Bisection where the secant stalls or leaves the bracket.
            let t = if step % 8 == 7 || !(lo < secant && secant < hi) {
                (lo + hi) / 2.0
            } else {
                secant
            };
            let point = self
                .measure(t, goal, select)
                .filter(|p| p.branch == l.branch)?;
            let ft = h(&point);
            found = Some(point);
            if ft.abs() <= 1e-15 || hi - lo <= 1e-12 {
                break;
            }
            if ft * fb < 0.0 {
                (a, fa) = (b, fb);
            } else {
                fa /= 2.0;
            }
            (b, fb) = (t, ft);
        }
        found
    }

    /// The table positions (sorted, the turn's ends included) at which
    /// something changes for `goal`.
    fn events(&self, goal: Goal) -> Vec<Event> {
        let (u, f) = (&self.u, &self.f);
        let z = Vector3::z();
        let c = self.head.axes[0].vector.normalize();
        let a = self.head.axes[1].vector.normalize();
        // Model angles of the table (degrees), and whether a measure jumps
        // there.
        let mut angles: Vec<(f64, bool)> = Vec::with_capacity(48);
        let smooth = |angle: &f64| (*angle, false);
        let jump = |angle: &f64| (*angle, true);
        // c · q(x): what the head's second axis follows. Its extremes: the
        // second axis turns back, and the tool passes nearest the first
        // axis (a pole, where the first axis turns fastest).
        let along_c = Wave::new(&c, u, f);
        angles.extend(along_c.extremes().iter().map(smooth));
        // The head's reach ends where c · q leaves the range of
        // c · R(a, θ2) Z.
        let reach = Wave::new(&c, &a, &z);
        for y in [
            reach.mean + reach.amplitude(),
            reach.mean - reach.amplitude(),
        ] {
            angles.extend(along_c.solve(y).iter().map(jump));
        }
        // The first axis turns back where the table's circle of directions
        // (axis u, radius φu) touches a circle of constant first angle v
        // (axis R(c, v) a, radius φa): u · R(c, v) a = cos(φu ± φa), then
        // at the extreme of (R(c, v) a) · q(x).
        let phi_u = u.dot(f).clamp(-1.0, 1.0).acos();
        let phi_a = a.dot(&z).clamp(-1.0, 1.0).acos();
        let tilt = Wave::new(u, &c, &a);
        for y in [(phi_u + phi_a).cos(), (phi_u - phi_a).cos()] {
            for v in tilt.solve(y).iter() {
                let k = from_axis_angle(c, *v) * a;
                // Of its maximum and minimum, the one that touches a · Z.
                let wave = Wave::new(&k, u, f);
                let [top, bottom] = wave.extremes();
                let high = wave.mean + wave.amplitude() - a.dot(&z);
                let low = wave.mean - wave.amplitude() - a.dot(&z);
                angles.push((if high.abs() <= low.abs() { top } else { bottom }, false));
            }
        }
        // Each head axis at the positions where its part, its placement or
        // its being inside the limits changes.
        for (i, axis) in self.head.axes.iter().enumerate() {
            let current = self.head_current[i];
            // (position, jump): where the head's part turns (smooth), where
            // its being inside the limits or its placement changes (a jump).
            let mut at: [(f64, bool); 4] = [(f64::NAN, false); 4];
            match axis.limits {
                // Inside from 1e-9 beyond a limit on (placed inside where
                // it can be, else left where it is).
                Some((min, max)) if max - min < 360.0 => {
                    let middle = (min + max) / 2.0;
                    let target = match goal {
                        Goal::Middle => middle,
                        Goal::Nearest => current,
                        Goal::Beyond => middle + 180.0,
                    };
                    at[..3].copy_from_slice(&[
                        (min - 1e-9, true),
                        (max + 1e-9, true),
                        (target, false),
                    ]);
                }
                // Placed nearest the current position, of its turns
                // within 1e-9 of the limits: a turn becomes one to take
                // where it reaches `min - 1e-9` and stops being one past
                // `max + 1e-9`.
                Some((min, max)) => at[..3].copy_from_slice(&[
                    (min - 1e-9, true),
                    (max + 1e-9, true),
                    (current + 180.0, true),
                ]),
                // Placed within half a turn of the current position.
                None => at[0] = (current + 180.0, true),
            }
            if goal == Goal::Nearest && axis.limits.is_none_or(|(min, max)| max - min >= 360.0) {
                at[3] = (current, false);
            }
            for (k, &(position, jumps)) in at.iter().enumerate() {
                // The same position a turn apart is one event.
                let again = at[..k].iter().any(|&(other, _)| {
                    let apart = (other - position).rem_euclid(360.0);
                    !(1e-12..=360.0 - 1e-12).contains(&apart)
                });
                if position.is_nan() || again {
                    continue;
                }
                let model = position - axis.offset;
                let found = match i {
                    0 => {
                        let k = from_axis_angle(c, model) * a;
                        Wave::new(&k, u, f).solve(a.dot(&z))
                    }
                    _ => along_c.solve(c.dot(&(from_axis_angle(a, model) * z))),
                };
                angles.extend(found.iter().map(|&angle| (angle, jumps)));
            }
        }
        let mut events: Vec<Event> = Vec::with_capacity(angles.len() + 4);
        for (angle, jump) in angles {
            let t = (angle - self.x0).rem_euclid(360.0);
            for t in [t, t + 360.0] {
                if t > 0.0 && t < self.width {
                    events.push(Event { t, jump });
                }
            }
        }
        events.extend([0.0, self.width].map(|t| Event { t, jump: false }));
        if (0.0..=self.width).contains(&self.current) {
            events.push(Event {
                t: self.current,
                jump: false,
            });
        }
        events.sort_by(|a, b| a.t.total_cmp(&b.t));
        events.dedup_by(|later, earlier| {
            let same = later.t - earlier.t < MERGE;
            if same {
                earlier.jump |= later.jump;
            }
            same
        });
        // The turn's end stays where it is.
        if let Some(last) = events.last_mut() {
            last.t = self.width;
        }
        events
    }
}

/// A table position where something changes.
#[derive(Clone, Copy, Debug)]
struct Event {
    /// As a `t`.
    t: f64,
    /// A measure jumps there: it is measured on either side.
    jump: bool,
}

/// `k · R(n, x) p` as the angle `x` turns: `mean + cos · cos x + sin · sin x`.
#[derive(Clone, Copy, Debug)]
struct Wave {
    mean: f64,
    cos: f64,
    sin: f64,
}

impl Wave {
    fn new(k: &Vector3<f64>, n: &Vector3<f64>, p: &Vector3<f64>) -> Self {
        let along = k.dot(n) * n.dot(p);
        Wave {
            mean: along,
            cos: k.dot(p) - along,
            sin: k.dot(&n.cross(p)),
        }
    }

    fn amplitude(&self) -> f64 {
        self.cos.hypot(self.sin)
    }

    /// The angles (degrees) of its maximum and its minimum.
    fn extremes(&self) -> [f64; 2] {
        let top = atan2_degrees(self.sin, self.cos);
        [top, top + 180.0]
    }

    /// The angles (degrees) where it equals `y`: two, one at its maximum or
    /// minimum (within rounding), none beyond them or where it is constant.
    fn solve(&self, y: f64) -> UpToTwo<f64> {
        let mut found = UpToTwo::new();
        let amplitude = self.amplitude();
        if amplitude < 1e-12 {
            return found;
        }
        let ratio = (y - self.mean) / amplitude;
        if ratio.abs() > 1.0 + 1e-9 {
            return found;
        }
        let top = atan2_degrees(self.sin, self.cos);
        let apart = ratio.clamp(-1.0, 1.0).acos().to_degrees();
        found.push(top + apart);
        if apart > 0.0 {
            found.push(top - apart);
        }
        found
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::record::RotaryAxis;
    use crate::kinematics::swivel::{orientation, solve};
    use crate::kinematics::Direction;
    use crate::rotation::frame::from_axis_angle;
    use nalgebra::Rotation3;

    fn axis(name: &str, vector: [f64; 3], limits: Option<(f64, f64)>) -> RotaryAxis {
        RotaryAxis {
            limits,
            ..RotaryAxis::along(name, vector)
        }
    }

    fn record(kinematics: Kinematics, axes: [RotaryAxis; 2]) -> Record {
        Record {
            number: 1,
            name: "TEST".into(),
            kinematics,
            offsets: [Vector3::zeros(); 4],
            axes,
            options: 0,
            direction_axis: None,
        }
    }

    /// A B table about Y (entered reversed, as a table's vector is) under
    /// a C-A head whose A tilts at most 30°.
    fn machine() -> (Record, Record) {
        let table = record(
            Kinematics::Table,
            [axis("B", [0.0, -1.0, 0.0], None), axis("", [0.0; 3], None)],
        );
        let head = record(
            Kinematics::Head,
            [
                axis("C", [0.0, 0.0, 1.0], Some((-180.0, 180.0))),
                axis("A", [1.0, 0.0, 0.0], Some((-30.0, 30.0))),
            ],
        );
        (table, head)
    }

    fn request(rotation: Rotation3<f64>) -> Request {
        Request {
            rotation,
            direction: Direction::Minus,
            current: [0.0; 2],
        }
    }

    /// The tool direction the table and the head make, in the workpiece.
    fn reached(table: &Record, head: &Record, split: &Split) -> Vector3<f64> {
        let positions = split.head.solutions[split.head.chosen.expect("taken")].positions;
        let t = orientation(table, [split.table, 0.0]);
        t * orientation(head, positions) * Vector3::z()
    }

    fn middle(fixed: Option<f64>) -> TableAsk {
        TableAsk {
            current: 0.0,
            fixed,
            prefer: Preference::Middle,
        }
    }

    /// With `_DIR` left open, the nearest split travels no more than the
    /// nearer of the two `_DIR`s, reaches the orientation, and names the
    /// `_DIR` that selects its head solution.
    #[test]
    fn the_nearest_split_over_both_head_solutions_travels_least() {
        let (table, head) = machine();
        let nearest = TableAsk {
            current: 0.0,
            fixed: None,
            prefer: Preference::Nearest,
        };
        // No travel where the head has no solution inside its limits.
        let travel = |split: &Split, asked: &Request| {
            let p = split.head.solutions[split.head.chosen?].positions;
            Some(
                (0..2)
                    .map(|i| (p[i] - asked.current[i]).abs())
                    .fold(split.table.abs(), f64::max),
            )
        };
        let mut chose_plus = false;
        for k in 0..24 {
            let turn = from_axis_angle(Vector3::new(1.0, 0.5, 0.2), 7.5 * f64::from(k))
                * from_axis_angle(Vector3::z(), 40.0);
            let asked = Request {
                current: [30.0, -10.0],
                ..request(turn)
            };
            let (found, direction) =
                split_nearest_either_way(&table, &head, &asked, 0.0).expect("valid");
            let each = [Direction::Minus, Direction::Plus].map(|direction| {
                split(&table, &head, &Request { direction, ..asked }, &nearest).expect("valid")
            });
            let Some(travelled) = travel(&found, &asked) else {
                assert!(each.iter().all(|s| s.head.chosen.is_none()), "{k}");
                continue;
            };
            let f = asked.rotation * Vector3::z();
            assert!((reached(&table, &head, &found) - f).norm() < 1e-9, "{k}");
            let least = each
                .iter()
                .filter_map(|s| travel(s, &asked))
                .fold(f64::INFINITY, f64::min);
            assert!(travelled <= least + 1e-9, "{k}");
            let taken = &each[usize::from(direction == Direction::Plus)];
            assert_eq!(taken.head.chosen, found.head.chosen, "{k}");
            chose_plus |= direction == Direction::Plus;
        }
        assert!(
            chose_plus,
            "no case where the other head solution is nearer"
        );
    }

    #[test]
    fn a_tilt_beyond_the_head_s_reach_goes_to_the_table() {
        let (table, head) = machine();
        // The tool 60° about Y: the head alone (A at most 30°) cannot.
        let asked = request(from_axis_angle(Vector3::y(), 60.0));
        assert_eq!(solve(&head, &asked).expect("valid").chosen, None);
        let split = split(&table, &head, &asked, &middle(None)).expect("valid");
        assert_eq!(split.found, TableAngle::Chosen(Preference::Middle));
        let f = asked.rotation * Vector3::z();
        assert!((reached(&table, &head, &split) - f).norm() < 1e-9);
        // The head stays at its middles: the table takes the whole tilt.
        assert!((split.table - 60.0).abs() < 1e-9, "{}", split.table);
        let positions = split.head.solutions[split.head.chosen.expect("taken")].positions;
        assert!(positions[1].abs() < 1e-9, "{positions:?}");
    }

    #[test]
    fn limits_of_many_turns_choose_as_one_turn_does() {
        let (mut table, head) = machine();
        let asked = request(from_axis_angle(Vector3::y(), 60.0));
        let mut chosen = Vec::new();
        for limits in [(-360.0, 360.0), (-1e8, 1e8), (-1e8, 50.5), (-70.0, 1e8)] {
            table.axes[0].limits = Some(limits);
            let split = split(&table, &head, &asked, &middle(None)).expect("valid");
            chosen.push(split.table);
        }
        // The whole tilt on the table, at the turn nearest 0 the limits
        // allow (-300 is 60 a turn lower); once the coarse search of a range
        // of 2e8 degrees sampled its first 100,000 only, at the lower end.
        let round = |x: f64| (x * 1e6).round() / 1e6;
        assert_eq!(
            chosen.iter().map(|&x| round(x)).collect::<Vec<_>>(),
            [60.0, 60.0, -300.0, 60.0]
        );
    }

    #[test]
    fn a_fixed_table_leaves_the_rest_to_the_head() {
        let (table, head) = machine();
        let asked = request(from_axis_angle(Vector3::y(), 60.0));
        let split = split(&table, &head, &asked, &middle(Some(40.0))).expect("valid");
        assert_eq!((split.found, split.table), (TableAngle::Fixed, 40.0));
        let f = asked.rotation * Vector3::z();
        assert!((reached(&table, &head, &split) - f).norm() < 1e-9);
        let too_far = split_at(&table, &head, &asked, 0.0);
        assert_eq!(too_far.head.chosen, None);
    }

    /// A table position a rounding beyond a limit counts as at it, and is
    /// put there, as the head's are: never printed beyond a limit it is
    /// said to keep.
    #[test]
    fn a_table_position_at_a_limit_is_never_beyond_it() {
        let (mut table, head) = machine();
        table.axes[0].limits = Some((-90.0, 90.0));
        let asked = request(from_axis_angle(Vector3::y(), 60.0));
        for (gamma, at) in [(90.0 + 5e-10, 90.0), (-90.0 - 5e-10, -90.0)] {
            let split = split_at(&table, &head, &asked, gamma);
            assert!(split.table_within_limits, "{gamma}");
            assert_eq!(split.table, at, "{gamma}");
        }
        let beyond = split_at(&table, &head, &asked, 90.0 + 1e-6);
        assert!(!beyond.table_within_limits);
        assert_eq!(beyond.table, 90.0 + 1e-6);
    }

    fn split_at(table: &Record, head: &Record, asked: &Request, gamma: f64) -> Split {
        split(table, head, asked, &middle(Some(gamma))).expect("valid")
    }

    #[test]
    fn nowhere_inside_the_limits_the_nearest_split_is_given() {
        let (table, head) = machine();
        // The tool along Y: a table about Y does not move it, and A reaches
        // 30° only: 60° beyond, whatever the table does.
        let asked = request(from_axis_angle(Vector3::x(), -90.0));
        let nearest = split(&table, &head, &asked, &middle(None)).expect("valid");
        let TableAngle::Beyond {
            solution,
            beyond_deg,
        } = nearest.found
        else {
            panic!("{:?}", nearest.found)
        };
        assert!((beyond_deg - 60.0).abs() < 1e-9, "{beyond_deg}");
        assert_eq!(nearest.head.chosen, None);
        let positions = nearest.head.solutions[solution].positions;
        assert!((positions[1].abs() - 90.0).abs() < 1e-9, "{positions:?}");
        // A head whose 45° axis tilts the tool 90° at most, under a table
        // about Z: the tool straight up is out of its reach at every angle.
        let mut nutating = head.clone();
        nutating.axes[1].vector = Vector3::new(0.0, 1.0, 1.0);
        let mut about_z = table.clone();
        about_z.axes[0].vector = Vector3::z();
        let up = request(from_axis_angle(Vector3::x(), 180.0));
        let unreachable = split(&about_z, &nutating, &up, &middle(None)).expect("valid");
        assert_eq!(unreachable.found, TableAngle::Unreachable);
        assert!(unreachable.head.solutions.is_empty());
    }

    #[test]
    fn nearest_keeps_the_axes_where_they_stand_when_it_can() {
        let (table, head) = machine();
        // Tilted 20° about Y: the head alone can (the table stays at 0),
        // the table alone can (B 20 keeps the head at its middles).
        let asked = Request {
            current: [0.0, 0.0],
            ..request(from_axis_angle(Vector3::y(), 20.0))
        };
        let middle = split(&table, &head, &asked, &middle(None)).expect("valid");
        assert!((middle.table - 20.0).abs() < 1e-9, "{}", middle.table);
        let ask = TableAsk {
            current: 0.0,
            fixed: None,
            prefer: Preference::Nearest,
        };
        let nearest = split(&table, &head, &asked, &ask).expect("valid");
        assert_eq!(nearest.found, TableAngle::Chosen(Preference::Nearest));
        // The largest of the three travels: no more than the middle's
        // 20° of the table.
        let travel = |split: &Split| {
            let p = split.head.solutions[split.head.chosen.expect("taken")].positions;
            split.table.abs().max(p[0].abs()).max(p[1].abs())
        };
        assert!(travel(&nearest) <= travel(&middle) + 1e-9);
        assert!((reached(&table, &head, &nearest) - asked.rotation * Vector3::z()).norm() < 1e-9);
    }

    #[test]
    fn a_table_on_a_hirth_grid_takes_its_best_grid_position() {
        let (mut table, mut head) = machine();
        table.axes[0].hirth = Some(Hirth {
            offset: 0.25,
            increment: 2.5,
        });
        head.axes[0].limits = Some((-100.0, 100.0));
        let spread = |split: &Split| {
            let Some(chosen) = split.head.chosen else {
                return f64::INFINITY;
            };
            let p = split.head.solutions[chosen].positions;
            (p[0].abs() / 100.0).max(p[1].abs() / 30.0)
        };
        for (x, y) in [(10.0, 50.0), (-35.0, 20.0), (40.0, -70.0), (5.0, 5.0)] {
            let asked =
                request(from_axis_angle(Vector3::x(), x) * from_axis_angle(Vector3::y(), y));
            let found = split(&table, &head, &asked, &middle(None)).expect("valid");
            assert!((((found.table - 0.25) / 2.5).round() * 2.5 + 0.25 - found.table).abs() < 1e-9);
            // Every grid position of the turn, one by one.
            let best = (-72..72)
                .map(|k| 0.25 + 2.5 * f64::from(k))
                .map(|gamma| spread(&split_at(&table, &head, &asked, gamma)))
                .fold(f64::INFINITY, f64::min);
            assert!(
                spread(&found) <= best + 1e-12,
                "{x} {y}: {} > {best}",
                spread(&found)
            );
        }
    }

    #[test]
    fn records_of_other_kinds_are_refused() {
        let (table, head) = machine();
        let asked = request(Rotation3::identity());
        assert_eq!(
            split(&head, &head, &asked, &middle(None)),
            Err(SplitError::NotATable)
        );
        assert_eq!(
            split(&table, &table, &asked, &middle(None)),
            Err(SplitError::NotAHead)
        );
    }
}
