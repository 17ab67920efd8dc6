//! `sinuprep axis`: the axis of a rotary joint from measurements, as unit
//! vectors and as the `$TC_CARR` axis vector of a swivel data record: from a
//! point before and after a known turn (the Rodrigues inverse problem, both
//! solutions), or from two or three measured positions of one point (the
//! axis and a point on it).

use nalgebra::{Point3, Vector3};

use crate::cli::args::AxisArgs;
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::measure::circle::{self, CircleError, Found};
use crate::measure::turn::{self, Every, NoAxis};
use crate::number::format;

pub fn run(args: &AxisArgs) -> Result<ExitStatus, CliError> {
    let text = match (&args.positions, args.before, args.after, args.angle) {
        (Some(positions), ..) => positions_form(args, positions)?,
        (None, Some(before), Some(after), Some(angle)) => {
            let (before, after) = (Vector3::from(before), Vector3::from(after));
            let axes = turn::axes(before, after, angle, args.tolerance)
                .map_err(|error| no_axis(error, args.tolerance))?;
            if args.json {
                turn_json(args, angle, before, &axes)
            } else {
                turn_table(args, angle, before, after, &axes)
            }
        }
        // clap asks for --after and --angle with --before.
        _ => {
            return Err(usage(
                "--before",
                "give --before, --after and --angle, or --positions",
            ))
        }
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

fn usage(argument: &'static str, why: &str) -> CliError {
    CliError::Measure {
        argument,
        why: why.to_string(),
        help: "`sinuprep axis --angle 90 --before X,Y,Z --after X,Y,Z`, or `sinuprep axis --positions P1 P2 P3`".into(),
    }
}

/// The record's axis vector as the control holds it: `$TC_CARR7..9[m]` for
/// the first rotary axis, `10..12` for the second.
fn tc_carr(args: &AxisArgs, direction: &Vector3<f64>) -> String {
    let first = if args.rotary == 1 { 7 } else { 10 };
    (0..3)
        .map(|i| {
            format!(
                "$TC_CARR{}[{}]={}",
                first + i,
                args.record,
                format(direction[i], args.precision)
            )
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn no_axis(error: NoAxis, tolerance: f64) -> CliError {
    let l = |v: f64| format(v, 6);
    let (argument, why, help) = match error {
        NoAxis::TooFar { chord, reach } => (
            "--after",
            format!(
                "no axis turns the point there by this angle: it moved {}, and a turn by the angle moves a point at its distance from the axis point at most {} (2·|before|·|sin(angle/2)|)",
                l(chord),
                l(reach)
            ),
            "check the angle, and that both points are relative to one point on the axis".to_string(),
        ),
        NoAxis::Distance { before, after } => (
            "--after",
            format!(
                "a turn keeps the distance from a point on its axis, but it changed from {} to {} (tolerance {})",
                l(before),
                l(after),
                l(tolerance)
            ),
            "give both points relative to one point on the axis, or allow more with --tolerance".to_string(),
        ),
        NoAxis::NoTurn { chord } => (
            "--angle",
            format!(
                "a turn by a whole number of turns moves no point, but this one moved {}",
                l(chord)
            ),
            "give the angle the axis turned between the two measurements".to_string(),
        ),
        NoAxis::Every { why } => (
            match why {
                Every::NoTurn => "--angle",
                Every::AtOrigin => "--before",
                Every::HalfTurnThrough => "--after",
            },
            match why {
                Every::NoTurn => "no turn, and the point did not move: every axis fits",
                Every::AtOrigin => "the point is the axis point itself: every axis through it fits",
                Every::HalfTurnThrough => "a half turn took the point to its opposite: every axis normal to it fits",
            }
            .to_string(),
            "measure a point away from the axis, turned by an angle other than 0° and 180°".to_string(),
        ),
    };
    CliError::Measure {
        argument,
        why,
        help,
    }
}

fn vector(v: &Vector3<f64>, precision: usize) -> String {
    format!(
        "{} {} {}",
        format(v.x, precision),
        format(v.y, precision),
        format(v.z, precision)
    )
}

fn triple(v: &Vector3<f64>) -> [f64; 3] {
    [v.x + 0.0, v.y + 0.0, v.z + 0.0]
}

/// Two roots the measurements cannot tell apart within the tolerance.
fn inseparable(args: &AxisArgs, before: Vector3<f64>, axes: &[turn::Axis]) -> bool {
    matches!(axes, [a, b] if a.direction.dot(&b.direction) > 0.0
        && turn::near_normal_plane(before, a.direction, args.tolerance))
}

fn turn_json(args: &AxisArgs, angle: f64, before: Vector3<f64>, axes: &[turn::Axis]) -> String {
    let value = serde_json::json!({
        "angle": angle,
        "separable": !inseparable(args, before, axes),
        "axes": axes.iter().map(|a| triple(&a.direction)).collect::<Vec<_>>(),
        "residuals": axes.iter().map(|a| a.residual).collect::<Vec<_>>(),
        "tc_carr": axes.iter().map(|a| tc_carr(args, &a.direction)).collect::<Vec<_>>(),
    });
    format!("{value}\n")
}

fn turn_table(
    args: &AxisArgs,
    angle: f64,
    before: Vector3<f64>,
    after: Vector3<f64>,
    axes: &[turn::Axis],
) -> String {
    let n = |v: f64| format(v, args.precision);
    let mut text = format!(
        "turn        {}° from {} to {} (relative to a point on the axis)\n",
        n(angle),
        vector(&before, args.precision),
        vector(&after, args.precision)
    );
    text.push_str(match axes {
        [_] => "axes        one: the point lies in the plane normal to the axis through the axis point\n",
        [a, b] if a.direction.dot(&b.direction) < -0.999_999_999 => {
            "axes        one, either way round: the point lies on it, or the turn is a half turn\n"
        }
        _ if inseparable(args, before, axes) => {
            "axes        two, which the measurements cannot tell apart within --tolerance: the point lies \
             that near the plane normal to the axis through the axis point; measure one farther from it\n"
        }
        _ => "axes        two: the axis at an acute or an obtuse angle to the point (the seed's two roots)\n",
    });
    for (i, axis) in axes.iter().enumerate() {
        text.push_str(&format!(
            "  {}  {}   residual {}\n     {}\n",
            i + 1,
            vector(&axis.direction, args.precision),
            n(axis.residual),
            tc_carr(args, &axis.direction)
        ));
    }
    text
}

fn positions_form(args: &AxisArgs, positions: &[[f64; 3]]) -> Result<String, CliError> {
    let at = |i: usize| Point3::from(positions[i]);
    let found = match (positions.len(), args.angle, args.direction) {
        (3, Some(_), _) => {
            return Err(usage(
                "--angle",
                "three positions give the turns between them: --angle is for two",
            ))
        }
        (3, None, nominal) => {
            let mut found = circle::three([at(0), at(1), at(2)], args.tolerance)
                .map_err(|e| refused(e, args.tolerance))?;
            // The way round the nominal axis points, if one is given.
            if let Some(nominal) = nominal {
                if found.direction.dot(&Vector3::from(nominal)) < 0.0 {
                    found.direction = -found.direction;
                    found.turns = found.turns.map(|t| (360.0 - t).rem_euclid(360.0));
                }
            }
            found
        }
        (_, Some(angle), Some(nominal)) => {
            circle::two([at(0), at(1)], angle, Vector3::from(nominal), args.tolerance)
                .map_err(|e| refused(e, args.tolerance))?
        }
        _ => {
            return Err(usage(
                "--positions",
                "two positions fix the axis only with the angle turned between them (--angle) and its nominal direction (--direction)",
            ))
        }
    };
    Ok(if args.json {
        positions_json(args, &found)
    } else {
        positions_table(args, positions.len(), &found)
    })
}

fn refused(error: CircleError, tolerance: f64) -> CliError {
    let l = |v: f64| format(v, 6);
    let (argument, why) = match error {
        CircleError::Coincident { distance } => (
            "--positions",
            format!(
                "two positions are {} apart, within the tolerance {}: they coincide",
                l(distance),
                l(tolerance)
            ),
        ),
        CircleError::Collinear { height } => (
            "--positions",
            format!(
                "the three positions lie on one line (the third {} off it): they fix no circle",
                l(height)
            ),
        ),
        CircleError::AlongChord => (
            "--direction",
            "the nominal direction runs along the chord between the positions: the axis is normal to it".to_string(),
        ),
        CircleError::NoDirection => (
            "--direction",
            "the nominal direction is zero: it has no direction".to_string(),
        ),
        CircleError::NoTurn => (
            "--angle",
            "a whole number of turns moves no point, but the positions differ".to_string(),
        ),
    };
    CliError::Measure {
        argument,
        why,
        help: "measure the point at positions turned well apart (say 0°, 45°, 90°)".into(),
    }
}

fn positions_json(args: &AxisArgs, found: &Found) -> String {
    let value = serde_json::json!({
        "axes": [triple(&found.direction)],
        "point": triple(&found.point.coords),
        "radius": found.radius,
        "turns": found.turns,
        "correction": found.correction,
        "tc_carr": [tc_carr(args, &found.direction)],
    });
    format!("{value}\n")
}

fn positions_table(args: &AxisArgs, count: usize, found: &Found) -> String {
    let n = |v: f64| format(v, args.precision);
    let mut text = format!(
        "axis        {}\n            {}\npoint       {} (the centre of the circle, on the axis)\nradius      {}\n",
        vector(&found.direction, args.precision),
        tc_carr(args, &found.direction),
        vector(&found.point.coords, args.precision),
        n(found.radius)
    );
    if count == 3 {
        text.push_str(&format!(
            "turns       {}° and {}° about the axis, from each position to the next\n",
            n(found.turns[0]),
            n(found.turns[1])
        ));
    } else {
        text.push_str(&format!(
            "nominal     turned {}° to be normal to the chord: two positions fix the axis's tilt in one plane only\n",
            n(found.correction)
        ));
    }
    text
}
