//! `sinuprep probe`: points probed on an inclined face to its two angles as
//! CYCLE600 takes them (extrinsic X, then Y), the CYCLE600 call that swivels
//! to it and the CYCLE800 `sinuprep rewrite` makes of that call.
//!
//! Three things a probing calculator must not get wrong, each handled here:
//! points probed while a rotation is active are in its coordinates, so the
//! face's rotation composes with it (R = R_active · R_face, centre mapped
//! through the active frame); lengths are in the unit given (the angles do
//! not depend on it, the centre and the tolerance do, and the calls must run
//! in that unit); the centre of the rotation is a point that stays where it
//! is (the first point unless one is given), CYCLE800's `_X0 _Y0 _Z0`.

use nalgebra::{Point3, Rotation3, Vector3};

use crate::cli::args::{ProbeArgs, Units};
use crate::cli::error::CliError;
use crate::cli::{write_stdout, ExitStatus};
use crate::emit::cycle600::{cycle600, cycle800};
use crate::measure::face::{self, Face, FaceError, Measured};
use crate::number::format;
use crate::rotation::{decompose, matrix, Sequence};
use crate::semantic::cycle600::{evaluate_parameters, Evaluation, Parameters};
use crate::semantic::env::Active;
use crate::span::Span;

/// The face and what swivels to it.
struct Probed {
    face: Face,
    /// The face's two angles in the frame it was probed in.
    measured: [f64; 2],
    /// The normal in machine axes.
    normal: Vector3<f64>,
    /// The centre in machine coordinates.
    centre: Point3<f64>,
    /// How far the centre lies above the face (0 on it).
    height: f64,
    evaluation: Evaluation,
    tolerance: f64,
    in_frame: Option<Rotation3<f64>>,
}

/// The two calls that swivel to the face, CYCLE600 and CYCLE800.
struct Calls {
    cycle600: String,
    cycle800: String,
}

pub fn run(args: &ProbeArgs) -> Result<ExitStatus, CliError> {
    let probed = probe(args)?;
    let cycle800 =
        cycle800(&probed.evaluation, args.precision).ok_or_else(|| CliError::Measure {
            argument: "--to",
            why: format!(
                "{} is a proper Euler sequence, which CYCLE800 has no `_MODE` for",
                args.to
            ),
            help: "give a sequence of three different axes, as i:ZYX (`_MODE` 27) or i:ZXY (39)"
                .into(),
        })?;
    // Only with the head they name: an empty name is no record the
    // control (or a HEAD_DEF) knows.
    let calls = args.head.is_some().then(|| Calls {
        cycle600: cycle600(&probed.evaluation.parameters, args.precision),
        cycle800,
    });
    let text = if args.json {
        json(args, &probed, calls.as_ref())
    } else {
        table(args, &probed, calls.as_ref())
    };
    write_stdout(text.as_bytes())?;
    Ok(ExitStatus::Success)
}

fn probe(args: &ProbeArgs) -> Result<Probed, CliError> {
    let tolerance = args.tolerance.unwrap_or(match args.units {
        Units::Mm => 0.01,
        Units::Inch => 0.0005,
    });
    let at = |p: &[f64; 3]| Point3::from(*p);
    let form = if args.points.is_some() {
        "--points"
    } else {
        "--along-x"
    };
    let (face, first) = match (&args.along_x, &args.along_y, &args.points, args.normal) {
        (Some(x), Some(y), _, _) => (
            face::along([at(&x[0]), at(&x[1])], [at(&y[0]), at(&y[1])], tolerance),
            Some(at(&x[0])),
        ),
        (_, _, Some(p), _) => (
            face::through([at(&p[0]), at(&p[1]), at(&p[2])], tolerance),
            Some(at(&p[0])),
        ),
        (_, _, _, Some(n)) => (face::with_normal(Vector3::from(n)), None),
        // clap's group asks for one of the three.
        _ => (Err(FaceError::NoNormal), None),
    };
    let face = face.map_err(|error| refused(error, form, tolerance, args.units))?;
    let measured = face::angles(&face.normal);
    // A zero point alone is a frame too: a shift without a turn.
    let in_frame = (args.in_frame.is_some() || args.in_frame_origin.is_some())
        .then(|| matrix(args.in_frame_sequence, args.in_frame.unwrap_or_default()));
    let active = in_frame.unwrap_or_else(Rotation3::identity);
    let origin = Vector3::from(args.in_frame_origin.unwrap_or_default());
    let given = args.center.map(Point3::from);
    let local = given.or(first).unwrap_or_else(Point3::origin);
    let height = first.map_or(0.0, |p| face.normal.dot(&(local - p)));
    // The active frame maps its own coordinates into the machine's.
    let centre = Point3::from(origin + active * local.coords);
    let rotation = active * face::rotation(measured);
    let input = face::sequence();
    let parameters = Parameters {
        head: args.head.clone().unwrap_or_default(),
        recalculate_only: false,
        input,
        before: centre.coords,
        // Without an active rotation the face's own angles, exactly.
        angles: match in_frame {
            Some(_) => decompose(input, &rotation).angles,
            None => [measured[0], measured[1], 0.0],
        },
        after: Vector3::zeros(),
        output: args.to,
        additive: false,
        inverse: false,
        retract: false,
    };
    // A new rotation (not additive) is never refused.
    let (evaluation, _) =
        evaluate_parameters(parameters, &Active::None, Span::new(0, 0)).map_err(|d| {
            CliError::Measure {
                argument: "--to",
                why: d.message.clone(),
                help: String::new(),
            }
        })?;
    Ok(Probed {
        face,
        measured,
        normal: active * face.normal,
        centre,
        height,
        evaluation,
        tolerance,
        in_frame,
    })
}

/// The error of points that give no face, naming the argument.
fn refused(error: FaceError, form: &'static str, tolerance: f64, units: Units) -> CliError {
    let unit = unit(units);
    let flag = |which: Measured| match which {
        Measured::AlongX => "--along-x",
        Measured::AlongY => "--along-y",
        Measured::Points => "--points",
        Measured::Normal => "--normal",
    };
    let l = |v: f64| format(v, 6);
    let (argument, why, help) = match error {
        FaceError::Coincident { which, distance } => (
            flag(which),
            format!(
                "two points are {} {unit} apart, within the tolerance {} {unit}: they coincide",
                l(distance),
                l(tolerance)
            ),
            "probe points far apart (the farther, the more exact the angles)".to_string(),
        ),
        FaceError::Parallel => (
            "--along-y",
            "the points along Y lie on a line parallel to the points along X: together they span no face".to_string(),
            "probe the second pair across the first".to_string(),
        ),
        FaceError::Collinear { height } => (
            "--points",
            format!(
                "the three points lie on one line (the third {} {unit} off it, within the tolerance {} {unit})",
                l(height),
                l(tolerance)
            ),
            "probe three points spread over the face".to_string(),
        ),
        FaceError::Vertical { normal } => (
            form,
            format!(
                "the face is vertical (its normal {} {} {} is horizontal): the points cannot tell which side of it the tool is on",
                l(normal.x),
                l(normal.y),
                l(normal.z)
            ),
            "give the normal on the tool's side with --normal NX,NY,NZ".to_string(),
        ),
        FaceError::NotFlat { distance } => (
            "--along-y",
            format!(
                "the points along Y lie {} {unit} off the face through the points along X, more than the tolerance {} {unit}",
                l(distance),
                l(tolerance)
            ),
            "probe again, or allow more with --tolerance; points off one plane measure no face".to_string(),
        ),
        FaceError::NoNormal => (
            flag(Measured::Normal),
            "the normal is zero: it has no direction".to_string(),
            "give the face's normal, as 0.02,-0.015,1".to_string(),
        ),
    };
    CliError::Measure {
        argument,
        why,
        help,
    }
}

fn unit(units: Units) -> &'static str {
    match units {
        Units::Mm => "mm",
        Units::Inch => "inch",
    }
}

/// The G function the calls' lengths need.
fn g_function(units: Units) -> &'static str {
    match units {
        Units::Mm => "G71 (metric)",
        Units::Inch => "G70 (inch)",
    }
}

fn json(args: &ProbeArgs, probed: &Probed, calls: Option<&Calls>) -> String {
    let p = &probed.evaluation.parameters;
    let triple = |v: Vector3<f64>| [v.x + 0.0, v.y + 0.0, v.z + 0.0];
    let value = serde_json::json!({
        "sequence": p.input.to_string(),
        "code": p.input.code(),
        "angles": p.angles.map(|a| a + 0.0),
        "measured": probed.measured,
        "projection": face::projection_angles(&probed.face.normal),
        "normal": triple(probed.normal),
        "tilt": tilt(&probed.normal),
        "centre": triple(probed.centre.coords),
        "height": probed.height,
        "flatness": probed.face.flatness,
        "tolerance": probed.tolerance,
        "units": unit(args.units),
        "in_frame": probed.in_frame.map(|_| serde_json::json!({
            "sequence": args.in_frame_sequence.to_string(),
            "angles": args.in_frame.unwrap_or_default(),
            "origin": args.in_frame_origin.unwrap_or_default(),
        })),
        "output": {
            "sequence": p.output.to_string(),
            "code": p.output.code(),
            "angles": probed.evaluation.output.angles,
            "gimbal_lock": probed.evaluation.output.gimbal_lock,
        },
        "cycle600": calls.map(|c| &c.cycle600),
        "cycle800": calls.map(|c| &c.cycle800),
    });
    format!("{value}\n")
}

/// The angle between the tool axis Z and the normal, degrees.
fn tilt(normal: &Vector3<f64>) -> f64 {
    crate::rotation::trig::atan2_degrees(normal.x.hypot(normal.y), normal.z)
}

fn table(args: &ProbeArgs, probed: &Probed, calls: Option<&Calls>) -> String {
    let p = &probed.evaluation.parameters;
    let n = |v: f64| format(v, args.precision);
    let unit = unit(args.units);
    let vector = |v: Vector3<f64>| format!("{} {} {}", n(v.x), n(v.y), n(v.z));
    let sequence = |s: Sequence| format!("{s} (code {})", s.code());
    let [a, b] = probed.measured;
    let [pa, pb] = face::projection_angles(&probed.face.normal);
    let mut text = format!(
        "face        normal {}, tilt {}°\n",
        vector(probed.normal),
        n(tilt(&probed.normal))
    );
    if n(probed.face.flatness) != "0" {
        text.push_str(&format!(
            "            the points lie within {} {unit} of one plane (tolerance {} {unit})\n",
            n(probed.face.flatness),
            n(probed.tolerance)
        ));
    }
    text.push_str(&format!("angles      X {} Y {}\n", n(a), n(b)));
    if (pa - a).abs() > 0.5 * 10f64.powi(-(args.precision.min(15) as i32)) {
        text.push_str(&format!(
            "            not the projection angles X {} Y {} (the slopes of the face's traces), which are no rotation pair once both are non-zero\n",
            n(pa),
            n(pb)
        ));
    }
    if probed.in_frame.is_some() {
        let angles = args.in_frame.unwrap_or_default();
        text.push_str(&format!(
            "in frame    {} {} {} {}, zero point {}: the points are in its coordinates, the angles above are in its axes\n",
            sequence(args.in_frame_sequence),
            n(angles[0]),
            n(angles[1]),
            n(angles[2]),
            vector(Vector3::from(args.in_frame_origin.unwrap_or_default())),
        ));
        text.push_str(&format!(
            "composed    {} {}, in the machine's axes\n",
            sequence(p.input),
            p.angles.map(n).join(" ")
        ));
    } else {
        text.push_str(&format!(
            "            {} {}\n",
            sequence(p.input),
            p.angles.map(n).join(" ")
        ));
    }
    let which = match (args.center, args.normal) {
        (Some(_), _) => "the point given",
        (None, Some(_)) => "the origin",
        (None, None) => "the first point",
    };
    text.push_str(&format!(
        "centre      {} {unit}: {which} stays where it is (CYCLE800 _X0 _Y0 _Z0)\n",
        vector(probed.centre.coords)
    ));
    if probed.height != 0.0 {
        text.push_str(&format!(
            "            {} {unit} above the face: the face lies at Z={} in the new system\n",
            n(probed.height),
            n(-probed.height)
        ));
    }
    text.push_str(&format!(
        "units       {unit}: the angles do not depend on it; the calls' lengths do, run them under {}\n",
        g_function(args.units)
    ));
    text.push_str(&format!(
        "output      {} {}{}\n",
        sequence(p.output),
        probed.evaluation.output.angles.map(n).join(" "),
        if probed.evaluation.output.gimbal_lock {
            " (gimbal lock: the third angle is 0 and the first carries the whole rotation)"
        } else {
            ""
        }
    ));
    match calls {
        Some(calls) => text.push_str(&format!("\n{}\n{}\n", calls.cycle600, calls.cycle800)),
        None => text.push_str(
            "calls       give --head NAME, the machine's swivel data record ($TC_CARR34), for the CYCLE600 and CYCLE800 calls\n",
        ),
    }
    text
}
