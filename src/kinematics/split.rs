//! Three rotary axes: a rotary table (a P record of one axis) under a
//! two-axis head (a T record), the heavy horizontal machines CYCLE600 was
//! built for, which CYCLE800 alone cannot drive.
//!
//! The table turns the workpiece by `R_t = R(u, γ)`, the head the tool by
//! `H`; the tool then points along `R_t⁻¹ · H · Z` in the workpiece. One
//! tool direction leaves one degree of freedom: the table's angle `γ`. It
//! is fixed (given), or chosen so that the head's axes lie nearest the
//! middles of their limits (the largest distance from a middle, as a share
//! of its half range, is the smallest; an axis whose limits hold a whole
//! turn has no middle to keep to; a tie goes to the position nearest the
//! table's current one); the head is then solved for what is left,
//! `R_t · R_req`, with its two solutions, `_DIR`, Hirth grid and the
//! residual about the tool axis. The zero-point shift is the table's.

use nalgebra::{Rotation3, Vector3};

use crate::kinematics::record::{Kinematics, Record, RecordError};
use crate::kinematics::swivel::{orientation, shift, solve, Request, Swivel};

/// How the table's angle was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TableAngle {
    /// As given.
    Fixed,
    /// Chosen for the head's limits.
    Chosen,
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
    /// The zero-point shift the table's offset vectors make.
    pub shift: Vector3<f64>,
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

/// Sampling step (degrees) of the search for the table's angle, then the
/// half width of the fine search around the best sample.
const COARSE_STEP: f64 = 1.0;
const FINE_STEPS: usize = 200;
/// Valleys of the coarse search closed in on, the lowest first, and as
/// many jumps of the head's positions.
const VALLEYS: usize = 6;
/// A change of a head position (degrees) between two coarse samples that
/// only a pole or a change of solution makes.
const POLE_JUMP: f64 = 30.0;

/// The table's and the head's positions for `request` (the table's
/// current position `table_current`), the table's fixed at `fixed` if given.
pub fn split(
    table: &Record,
    head: &Record,
    request: &Request,
    table_current: f64,
    fixed: Option<f64>,
) -> Result<Split, SplitError> {
    table.check()?;
    head.check()?;
    if table.kinematics != Kinematics::Table || table.axis_count() != 1 {
        return Err(SplitError::NotATable);
    }
    if head.kinematics != Kinematics::Head || head.axis_count() != 2 {
        return Err(SplitError::NotAHead);
    }
    if let Some(gamma) = fixed {
        return split_at(table, head, request, gamma, TableAngle::Fixed);
    }
    let spread_at =
        |gamma: f64| head_at(table, head, request, gamma).map(|swivel| score(head, &swivel));
    let axis = &table.axes[0];
    let (low, high) = axis
        .limits
        .unwrap_or((table_current - 180.0, table_current + 180.0));
    // The head sees the table's angle modulo a turn: the turn of the limits
    // nearest the current position holds an angle as good as any other,
    // and, of equally good ones, the one nearest the current position. So
    // limits of many turns (up to ±1e8 degrees) are searched over one.
    let low = (table_current - 180.0).max(low).min(low.max(high - 360.0));
    let high = high.min(low + 360.0);
    // (score, γ) of the best of `gammas`.
    let best_of =
        |gammas: &mut dyn Iterator<Item = f64>| -> Result<Option<(f64, f64)>, SplitError> {
            let mut best: Option<(f64, f64)> = None;
            for gamma in gammas {
                let candidate = (spread_at(gamma)?, gamma);
                let better = best.is_none_or(|b| {
                    candidate.0 < b.0 - 1e-9
                        || (candidate.0 <= b.0 + 1e-9
                            && (candidate.1 - table_current).abs() < (b.1 - table_current).abs())
                });
                if better {
                    best = Some(candidate);
                }
            }
            Ok(best)
        };
    let best = match axis.hirth.filter(|h| h.increment > 0.0) {
        // Only the grid's positions can be taken.
        Some(hirth) => {
            let first =
                hirth.offset + ((low - hirth.offset) / hirth.increment).ceil() * hirth.increment;
            let count = ((high - first) / hirth.increment).floor().max(-1.0) as i64 + 1;
            best_of(&mut (0..count.min(1_000_000)).map(|k| first + k as f64 * hirth.increment))?
        }
        None => {
            let steps = ((high - low) / COARSE_STEP).ceil() as usize;
            // (spread, γ, the head's positions) a coarse step apart.
            let coarse: Vec<(f64, f64, Option<[f64; 2]>)> = (0..=steps.min(100_000))
                .map(|k| (low + k as f64 * COARSE_STEP).min(high))
                .map(|gamma| {
                    let swivel = head_at(table, head, request, gamma)?;
                    let positions = swivel.chosen.map(|c| swivel.solutions[c].positions);
                    Ok((score(head, &swivel), gamma, positions))
                })
                .collect::<Result<_, SplitError>>()?;
            // A valley of the spread narrower than a coarse step shows as a
            // sample no higher than its neighbours, not always the lowest
            // one; near a pole of the head (its first axis free) the
            // valley lies where the head's positions jump between two
            // samples. The lowest of the first and each of the second are
            // closed in on.
            let mut valleys: Vec<(f64, f64)> = (0..coarse.len())
                .filter(|&k| {
                    let here = coarse[k].0;
                    here.is_finite()
                        && (k == 0 || here <= coarse[k - 1].0)
                        && coarse.get(k + 1).is_none_or(|next| here <= next.0)
                })
                .map(|k| (coarse[k].0, coarse[k].1))
                .collect();
            valleys.sort_by(|a, b| a.0.total_cmp(&b.0));
            valleys.truncate(VALLEYS);
            let jumps = coarse.windows(2).filter_map(|pair| {
                let (Some(a), Some(b)) = (pair[0].2, pair[1].2) else {
                    return None;
                };
                let jump = (0..2).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max);
                (jump > POLE_JUMP).then_some((f64::NAN, (pair[0].1 + pair[1].1) / 2.0))
            });
            valleys.extend(jumps.take(VALLEYS));
            let mut candidates = vec![table_current.clamp(low, high)];
            for &(_, centre) in &valleys {
                candidates.push(centre);
                let fine = COARSE_STEP / FINE_STEPS as f64;
                let around = (0..=2 * FINE_STEPS)
                    .map(|k| centre - COARSE_STEP + k as f64 * fine)
                    .filter(|gamma| (low..=high).contains(gamma));
                if let Some((spread, gamma)) = best_of(&mut around.into_iter())? {
                    candidates.push(gamma);
                    // A minimum between the samples: closed in on.
                    if spread > 1e-9 && spread.is_finite() {
                        let (a, b) = ((gamma - fine).max(low), (gamma + fine).min(high));
                        candidates.push(golden(a, b, spread_at)?);
                    }
                }
            }
            best_of(&mut candidates.into_iter())?
        }
    };
    let gamma = best.map_or(table_current, |(_, gamma)| gamma);
    split_at(table, head, request, gamma, TableAngle::Chosen)
}

/// The minimum of `f` on `[a, b]` by golden-section search, to 1e-10° or
/// as near as the numbers there resolve: far from zero two neighbouring
/// doubles lie more than 1e-10 apart (from 2^19 degrees on), so the steps
/// are counted too (the bracket shrinks by 0.618 a step: 100 steps take any
/// bracket of this search below a double's resolution).
fn golden(
    mut a: f64,
    mut b: f64,
    f: impl Fn(f64) -> Result<f64, SplitError>,
) -> Result<f64, SplitError> {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let (mut c, mut d) = (b - ratio * (b - a), a + ratio * (b - a));
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    for _ in 0..100 {
        if b - a <= 1e-10 {
            break;
        }
        if fc < fd {
            (b, d, fd) = (d, c, fc);
            c = b - ratio * (b - a);
            fc = f(c)?;
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + ratio * (b - a);
            fd = f(d)?;
        }
    }
    Ok((a + b) / 2.0)
}

/// The head's swivel with the table at `gamma`: `R_kin = T · H`, with `T`
/// the table's orientation, so the head must make `T⁻¹ · R_req`.
fn head_at(
    table: &Record,
    head: &Record,
    request: &Request,
    gamma: f64,
) -> Result<Swivel, SplitError> {
    let model = [gamma - table.axes[0].offset, 0.0];
    let turned: Rotation3<f64> = orientation(table, model).inverse() * request.rotation;
    let head_request = Request {
        rotation: turned,
        ..*request
    };
    Ok(solve(head, &head_request)?)
}

/// The split with the table at `gamma`, found as `found` says.
fn split_at(
    table: &Record,
    head: &Record,
    request: &Request,
    gamma: f64,
    found: TableAngle,
) -> Result<Split, SplitError> {
    let axis = &table.axes[0];
    Ok(Split {
        table: gamma,
        table_within_limits: axis
            .limits
            .is_none_or(|(min, max)| (min - 1e-9..=max + 1e-9).contains(&gamma)),
        found,
        head: head_at(table, head, request, gamma)?,
        shift: shift(table, [gamma - axis.offset, 0.0]),
    })
}

/// How far the head's taken solution lies from the middles of its limits:
/// the largest distance as a share of the half range (0 at the middles, 1
/// at a limit); infinite when no solution lies inside the limits. An axis
/// whose limits hold a whole turn reaches every angle, so it has no middle
/// to keep to.
fn score(head: &Record, swivel: &Swivel) -> f64 {
    let Some(index) = swivel.chosen else {
        return f64::INFINITY;
    };
    let positions = swivel.solutions[index].positions;
    head.axes
        .iter()
        .zip(positions)
        .filter_map(|(axis, position)| {
            let (min, max) = axis.limits.filter(|(min, max)| max - min < 360.0)?;
            let half = (max - min) / 2.0;
            Some(if half > 0.0 {
                (position - (min + half)).abs() / half
            } else {
                0.0
            })
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::record::RotaryAxis;
    use crate::kinematics::Direction;
    use crate::rotation::frame::from_axis_angle;

    fn axis(name: &str, vector: [f64; 3], limits: Option<(f64, f64)>) -> RotaryAxis {
        RotaryAxis {
            name: name.into(),
            vector: Vector3::from(vector),
            offset: 0.0,
            hirth: None,
            limits,
            angle: 0.0,
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

    #[test]
    fn the_fine_search_ends_where_doubles_are_coarser_than_its_tolerance() {
        // About 1e8 two neighbouring doubles lie 1.5e-8 apart: a bracket
        // never gets narrower than 1e-10 there.
        let centre = 1e8 + 0.25;
        let found =
            golden(centre - 0.005, centre + 0.005, |g| Ok((g - centre).abs())).expect("no error");
        assert!((found - centre).abs() < 1e-7, "{found}");
    }

    #[test]
    fn a_tilt_beyond_the_head_s_reach_goes_to_the_table() {
        let (table, head) = machine();
        // The tool 60° about Y: the head alone (A at most 30°) cannot.
        let asked = request(from_axis_angle(Vector3::y(), 60.0));
        assert_eq!(solve(&head, &asked).expect("valid").chosen, None);
        let split = split(&table, &head, &asked, 0.0, None).expect("valid");
        assert_eq!(split.found, TableAngle::Chosen);
        let f = asked.rotation * Vector3::z();
        assert!((reached(&table, &head, &split) - f).norm() < 1e-9);
        // The head stays at its middles: the table takes the whole tilt.
        assert!((split.table - 60.0).abs() < 1e-6, "{}", split.table);
        let positions = split.head.solutions[split.head.chosen.expect("taken")].positions;
        assert!(positions[1].abs() < 1e-6, "{positions:?}");
    }

    #[test]
    fn limits_of_many_turns_choose_as_one_turn_does() {
        let (mut table, head) = machine();
        let asked = request(from_axis_angle(Vector3::y(), 60.0));
        let mut chosen = Vec::new();
        for limits in [(-360.0, 360.0), (-1e8, 1e8), (-1e8, 50.5), (-70.0, 1e8)] {
            table.axes[0].limits = Some(limits);
            let split = split(&table, &head, &asked, 0.0, None).expect("valid");
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
        let split = split(&table, &head, &asked, 0.0, Some(40.0)).expect("valid");
        assert_eq!((split.found, split.table), (TableAngle::Fixed, 40.0));
        let f = asked.rotation * Vector3::z();
        assert!((reached(&table, &head, &split) - f).norm() < 1e-9);
        let too_far = split_at(&table, &head, &asked, 0.0);
        assert_eq!(too_far.head.chosen, None);
    }

    fn split_at(table: &Record, head: &Record, asked: &Request, gamma: f64) -> Split {
        split(table, head, asked, 0.0, Some(gamma)).expect("valid")
    }

    #[test]
    fn records_of_other_kinds_are_refused() {
        let (table, head) = machine();
        let asked = request(Rotation3::identity());
        assert_eq!(
            split(&head, &head, &asked, 0.0, None),
            Err(SplitError::NotATable)
        );
        assert_eq!(
            split(&table, &table, &asked, 0.0, None),
            Err(SplitError::NotAHead)
        );
    }
}
