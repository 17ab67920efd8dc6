//! The forms `convert` and `frame` read and write a rotation or a whole
//! frame in: angles of any of the 24 sequences, the matrix, quaternion,
//! axis and angle, Gibbs vector, Sinumerik frame statements, a
//! post-processor's `ROT_MAT` / `TRANS_MAT` assignments, and the seed's
//! tool-to-piece chain order. Each form's text is what its input takes, so
//! an output reads back in; numbers to the decimals asked for (by default
//! as many as the conversions hold exactly), in JSON in full.

use std::fmt;
use std::str::FromStr;

use nalgebra::{Matrix3, Rotation3, Vector3};
use serde_json::{json, Value};

use crate::number::format as fixed;
use crate::rotation::forms::{
    axis_angle, chain_angles, chain_sequence, from_axis_angle, from_chain, from_gibbs,
    from_quaternion, gibbs, matrix_of_pose, pose, pose_of_matrix, quaternion, rotation_of_matrix,
    Pose, PostMatrix,
};
use crate::rotation::{decompose, matrix, Axis, Decomposition, Kind, Sequence, SequenceError};
use crate::semantic::frame_statements::evaluate_frame_statements;

/// A form a rotation or frame is written in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Notation {
    /// Three angles in a sequence (`e:XYZ`).
    Angles(Sequence),
    /// The 3x3 rotation matrix, or the 4x4 of a frame, row by row.
    Matrix,
    /// `w x y z`.
    Quaternion,
    /// `x y z angle`: the axis and the angle in degrees.
    AxisAngle,
    /// The Gibbs / Rodrigues vector `2 tan(χ/2) e`.
    Gibbs,
    /// Sinumerik frame statements (`TRANS`, `AROT`, ...).
    Sinumerik,
    /// A post-processor's `ROT_MAT1..9` and `TRANS_MATX..Z` assignments.
    Gpp,
    /// Position and angles in the order of the tool-to-piece chain (seed
    /// 004): x y z, then α about Z, β about X', γ about Y''.
    Chain,
}

/// The forms' names, for messages.
pub const FORMS: &str = "a sequence (`e:XYZ`, `i:39`), `matrix`, `quaternion`, `axis-angle`, \
                         `gibbs`, `sinumerik`, `gpp` or `chain`";

impl FromStr for Notation {
    type Err = String;

    fn from_str(text: &str) -> Result<Notation, String> {
        Ok(match text.trim().to_ascii_lowercase().as_str() {
            "matrix" => Notation::Matrix,
            "quaternion" => Notation::Quaternion,
            "axis-angle" => Notation::AxisAngle,
            "gibbs" | "rodrigues" => Notation::Gibbs,
            "sinumerik" => Notation::Sinumerik,
            "gpp" => Notation::Gpp,
            "chain" => Notation::Chain,
            _ if text.contains(':') => {
                Notation::Angles(text.parse().map_err(|e: SequenceError| e.to_string())?)
            }
            _ => return Err(format!("`{text}` is no form: give {FORMS}")),
        })
    }
}

impl fmt::Display for Notation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Notation::Angles(sequence) => write!(f, "{sequence}"),
            Notation::Matrix => f.write_str("matrix"),
            Notation::Quaternion => f.write_str("quaternion"),
            Notation::AxisAngle => f.write_str("axis-angle"),
            Notation::Gibbs => f.write_str("gibbs"),
            Notation::Sinumerik => f.write_str("sinumerik"),
            Notation::Gpp => f.write_str("gpp"),
            Notation::Chain => f.write_str("chain"),
        }
    }
}

impl Notation {
    /// Statements, not numbers.
    pub fn is_text(self) -> bool {
        matches!(self, Notation::Sinumerik | Notation::Gpp)
    }

    /// How many numbers the form takes for a rotation (`frame` false) or a
    /// frame (X Y Z first, except the 4x4 matrix).
    pub fn counts(self, frame: bool) -> &'static [usize] {
        match (self, frame) {
            (Notation::Angles(_) | Notation::Gibbs | Notation::Chain, false) => &[3],
            (Notation::Angles(_) | Notation::Gibbs | Notation::Chain, true) => &[6],
            // A 4x4 matrix of a pure rotation too.
            (Notation::Matrix, false) => &[9, 16],
            (Notation::Matrix, true) => &[16, 12],
            (Notation::Quaternion | Notation::AxisAngle, false) => &[4],
            (Notation::Quaternion | Notation::AxisAngle, true) => &[7],
            (Notation::Sinumerik | Notation::Gpp, _) => &[],
        }
    }
}

/// A frame read from the command line's values: statements joined as
/// lines, or numbers separated by blanks or commas.
pub fn read(notation: Notation, values: &[String], frame: bool) -> Result<Pose, String> {
    let pose = if notation.is_text() {
        read_text(notation, &values.join("\n"))?
    } else {
        read_numbers(notation, &numbers(&values.join(" "))?, frame)?
    };
    if !frame && pose.translation.vector != Vector3::zeros() {
        let t = pose.translation.vector;
        return Err(format!(
            "this is a frame, with the translation X{} Y{} Z{}: `sinuprep frame` converts frames, `convert` rotations",
            n(t.x),
            n(t.y),
            n(t.z)
        ));
    }
    Ok(pose)
}

/// The largest angle taken, in degrees (either sign): past it a double
/// holds an angle no closer than a few millionths of a degree, so its turn
/// is not known to the digits printed. As coordinates past ±1e9 are refused.
pub const LARGEST_ANGLE: f64 = 1e9;

/// `value` as an angle, refused past [`LARGEST_ANGLE`] with the reason.
pub fn angle(value: f64) -> Result<f64, String> {
    if value.abs() > LARGEST_ANGLE {
        return Err(format!(
            "{value:e} degrees is beyond ±1e9, where a double holds an angle only to about {:.0e}°: its turn is not known to the digits printed; give the angle within one turn",
            f64::EPSILON * value.abs()
        ));
    }
    Ok(value)
}

/// The numbers of a text, blanks or commas between them.
pub fn numbers(text: &str) -> Result<Vec<f64>, String> {
    text.split(|c: char| c.is_whitespace() || c == ',')
        .filter(|field| !field.is_empty())
        .map(|field| match field.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            _ => Err(format!("`{field}` is not a finite number")),
        })
        .collect()
}

/// A frame of `numbers` in a numeric form.
pub fn read_numbers(notation: Notation, numbers: &[f64], frame: bool) -> Result<Pose, String> {
    let counts = notation.counts(frame);
    if !counts.contains(&numbers.len()) {
        let what = match notation {
            Notation::Angles(_) if !frame => "three angles".to_string(),
            _ => format!(
                "{} numbers for {}{notation}",
                counts
                    .iter()
                    .map(usize::to_string)
                    .collect::<Vec<_>>()
                    .join(" or "),
                if frame { "a frame in " } else { "" },
            ),
        };
        return Err(format!(
            "{} numbers where {what} are expected",
            numbers.len()
        ));
    }
    let (translation, rest) = match notation {
        Notation::Matrix => (Vector3::zeros(), numbers),
        _ if frame => (
            Vector3::new(numbers[0], numbers[1], numbers[2]),
            &numbers[3..],
        ),
        _ => (Vector3::zeros(), numbers),
    };
    let three = |at: usize| [rest[at], rest[at + 1], rest[at + 2]];
    match notation {
        Notation::Angles(_) | Notation::Chain => {
            for &value in rest {
                angle(value)?;
            }
        }
        Notation::AxisAngle => {
            angle(rest[3])?;
        }
        _ => {}
    }
    let rotation = match notation {
        Notation::Angles(sequence) => matrix(sequence, three(0)),
        Notation::Chain => return Ok(from_chain(translation, three(0))),
        Notation::Matrix if rest.len() == 9 => {
            rotation_of_matrix(&Matrix3::from_row_slice(rest)).map_err(|e| e.to_string())?
        }
        Notation::Matrix => {
            let mut rows = [[0.0, 0.0, 0.0, 1.0]; 4];
            for (i, value) in rest.iter().enumerate() {
                rows[i / 4][i % 4] = *value;
            }
            return pose_of_matrix(&rows).map_err(|e| e.to_string());
        }
        Notation::Quaternion => {
            from_quaternion([rest[0], rest[1], rest[2], rest[3]]).map_err(|e| e.to_string())?
        }
        Notation::AxisAngle => {
            from_axis_angle(Vector3::from(three(0)), rest[3]).map_err(|e| e.to_string())?
        }
        Notation::Gibbs => from_gibbs(&Vector3::from(three(0))).map_err(|e| e.to_string())?,
        Notation::Sinumerik | Notation::Gpp => {
            return Err(format!("{notation} is written in statements, not numbers"))
        }
    };
    Ok(pose(translation, rotation))
}

/// A frame of statements.
pub fn read_text(notation: Notation, text: &str) -> Result<Pose, String> {
    match notation {
        Notation::Sinumerik => {
            evaluate_frame_statements(text.as_bytes()).map_err(|e| e.to_string())
        }
        Notation::Gpp => read_gpp(text),
        _ => Err(format!("{notation} is written in numbers, not statements")),
    }
}

/// `ROT_MAT1=...;` ... `TRANS_MATZ=...;`, in any order and case, one or
/// more a line; all nine `ROT_MAT` are needed, a `TRANS_MAT` not given is 0.
fn read_gpp(text: &str) -> Result<Pose, String> {
    let mut rot: [Option<f64>; 9] = [None; 9];
    let mut trans = [0.0; 3];
    for (index, line) in text.lines().enumerate() {
        let fail = |why: String| format!("line {}: {why}", index + 1);
        for statement in line.split(';').map(str::trim).filter(|s| !s.is_empty()) {
            let (name, value) = statement.split_once('=').ok_or_else(|| {
                fail(format!(
                    "`{statement}` is no assignment such as `ROT_MAT1=1;`"
                ))
            })?;
            let name = name.trim().to_ascii_uppercase();
            let value = match value.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => v,
                _ => return Err(fail(format!("`{}` is not a finite number", value.trim()))),
            };
            let rot_index = name
                .strip_prefix("ROT_MAT")
                .and_then(|digit| digit.parse::<usize>().ok())
                .filter(|k| (1..=9).contains(k));
            let trans_index = name
                .strip_prefix("TRANS_MAT")
                .and_then(|axis| ["X", "Y", "Z"].iter().position(|a| *a == axis));
            match (rot_index, trans_index) {
                (Some(k), _) => rot[k - 1] = Some(value),
                (_, Some(i)) => trans[i] = value,
                _ => {
                    return Err(fail(format!(
                        "`{name}` is none of ROT_MAT1..ROT_MAT9, TRANS_MATX..TRANS_MATZ"
                    )))
                }
            }
        }
    }
    let mut rot_mat = [0.0; 9];
    for (k, value) in rot.iter().enumerate() {
        rot_mat[k] = value.ok_or_else(|| format!("ROT_MAT{} is not given", k + 1))?;
    }
    PostMatrix {
        rot_mat,
        trans_mat: trans,
    }
    .pose()
    .map_err(|e| e.to_string())
}

/// A frame written in a form: its text (what the form's input takes), its
/// JSON object, and a warning for stderr.
pub struct Written {
    pub text: String,
    pub json: Value,
    pub warning: Option<String>,
}

/// The shortest text that reads back as the same double; no `-0`.
pub fn n(value: f64) -> String {
    format!("{}", value + 0.0)
}

/// `values` to `precision` decimals, blanks between them.
fn line(values: &[f64], precision: usize) -> String {
    values
        .iter()
        .map(|v| fixed(*v, precision))
        .collect::<Vec<_>>()
        .join(" ")
}

fn rows3(rotation: &Rotation3<f64>) -> [[f64; 3]; 3] {
    let m = rotation.matrix();
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[(r, c)] + 0.0))
}

/// The warning of a decomposition at gimbal lock.
pub fn gimbal_warning(sequence: Sequence, decomposition: &Decomposition) -> Option<String> {
    decomposition.gimbal_lock.then(|| {
        let [a, _, c] = sequence.axes.map(|a| a.letter());
        format!(
            "warning: gimbal lock: the middle rotation aligns the first and third axes ({a} and {c}), so only \
             their combination is defined; the third angle is set to 0 and the first carries the whole rotation"
        )
    })
}

/// `frame` in `notation`, the text's numbers to `precision` decimals;
/// `frame` false writes the rotation alone.
pub fn write(
    notation: Notation,
    frame_pose: &Pose,
    frame: bool,
    precision: usize,
) -> Result<Written, String> {
    let line = |values: &[f64]| line(values, precision);
    let n = |value: f64| fixed(value, precision);
    let rotation = frame_pose.rotation;
    let t = frame_pose.translation.vector;
    let prefix = |values: &[f64]| {
        if frame {
            [&[t.x, t.y, t.z][..], values].concat()
        } else {
            values.to_vec()
        }
    };
    let mut warning = None;
    let (text, mut object) = match notation {
        Notation::Angles(_) | Notation::Chain => {
            let sequence = match notation {
                Notation::Angles(sequence) => sequence,
                _ => chain_sequence(),
            };
            let d = match notation {
                Notation::Chain => chain_angles(&rotation),
                _ => decompose(sequence, &rotation),
            };
            warning = gimbal_warning(sequence, &d);
            let mut object = json!({
                "sequence": sequence.to_string(),
                "code": sequence.code(),
                "angles": d.angles,
                "alternative": d.alternative,
                "gimbal_lock": d.gimbal_lock,
            });
            if notation == Notation::Chain {
                // The seed's names: α about Z, β about X', γ about Y''.
                let [alpha, beta, gamma] = d.angles;
                object["alpha_z"] = json!(alpha);
                object["beta_x"] = json!(beta);
                object["gamma_y"] = json!(gamma);
            }
            (line(&prefix(&d.angles)), object)
        }
        Notation::Matrix => {
            let text = if frame {
                matrix_of_pose(frame_pose).map(|row| line(&row)).join("\n")
            } else {
                rows3(&rotation).map(|row| line(&row)).join("\n")
            };
            (text, json!({}))
        }
        Notation::Quaternion => {
            let q = quaternion(&rotation);
            (line(&prefix(&q)), json!({ "quaternion": q }))
        }
        Notation::AxisAngle => {
            let (axis, angle) = axis_angle(&rotation);
            let values = [axis.x, axis.y, axis.z, angle];
            (
                line(&prefix(&values)),
                json!({ "axis": [axis.x, axis.y, axis.z], "angle": angle }),
            )
        }
        Notation::Gibbs => {
            let g = gibbs(&rotation).map_err(|e| e.to_string())?;
            let values = [g.x, g.y, g.z];
            (line(&prefix(&values)), json!({ "gibbs": values }))
        }
        Notation::Sinumerik => {
            // One ROT block is RPY: Z, Y', X''.
            let rpy = Sequence {
                axes: [Axis::Z, Axis::Y, Axis::X],
                kind: Kind::Intrinsic,
            };
            let d = decompose(rpy, &rotation);
            let [z, y, x] = d.angles;
            let turn = format!("X={} Y={} Z={}", n(x), n(y), n(z));
            let statements = if frame {
                vec![
                    format!("TRANS X={} Y={} Z={}", n(t.x), n(t.y), n(t.z)),
                    format!("AROT {turn}"),
                ]
            } else {
                vec![format!("ROT {turn}")]
            };
            (statements.join("\n"), json!({ "statements": statements }))
        }
        Notation::Gpp => {
            let post = PostMatrix::of(frame_pose);
            let mut statements: Vec<String> = post
                .rot_mat
                .iter()
                .enumerate()
                .map(|(k, v)| format!("ROT_MAT{}={};", k + 1, n(*v)))
                .collect();
            for (axis, v) in ["X", "Y", "Z"].iter().zip(post.trans_mat) {
                statements.push(format!("TRANS_MAT{axis}={};", n(v)));
            }
            (
                statements.join("\n"),
                json!({
                    "statements": statements,
                    "rot_mat": post.rot_mat,
                    "trans_mat": post.trans_mat,
                }),
            )
        }
    };
    object["form"] = json!(notation.to_string());
    if frame {
        object["translation"] = json!([t.x + 0.0, t.y + 0.0, t.z + 0.0]);
        object["matrix"] = json!(matrix_of_pose(frame_pose));
    } else {
        object["matrix"] = json!(rows3(&rotation));
    }
    Ok(Written {
        text: format!("{text}\n"),
        json: object,
        warning,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn forms_are_named_and_sequences_keep_their_message() {
        assert_eq!("Matrix".parse(), Ok(Notation::Matrix));
        assert_eq!("axis-angle".parse(), Ok(Notation::AxisAngle));
        assert!(matches!("e:57".parse(), Ok(Notation::Angles(_))));
        let sequence_error = "x:ZYX".parse::<Notation>().expect_err("no sequence");
        assert!(sequence_error.contains("is not a rotation sequence"));
        let form_error = "euler".parse::<Notation>().expect_err("no form");
        assert!(form_error.contains("`gpp`"), "{form_error}");
    }

    /// The post-processor seed's example: `convert 30 0 0 --from e:XYZ --to gpp`.
    #[test]
    fn gpp_statements_in_the_posts_own_form() {
        let pose = read(
            Notation::Angles("e:XYZ".parse().expect("seq")),
            &["30 0 0".into()],
            false,
        )
        .expect("a rotation");
        let written = write(Notation::Gpp, &pose, false, 12).expect("written");
        let lines: Vec<&str> = written.text.lines().collect();
        assert_eq!(lines.len(), 12);
        assert_eq!(lines[0], "ROT_MAT1=1;");
        assert_eq!(lines[5], "ROT_MAT6=0.5;");
        assert_eq!(lines[11], "TRANS_MATZ=0;");
        let back = read(Notation::Gpp, &[written.text], false).expect("read back");
        let error = (back.rotation.matrix() - pose.rotation.matrix())
            .abs()
            .max();
        assert!(error < 1e-12, "{error}");
    }

    #[test]
    fn bad_statements_and_counts_are_refused() {
        for (notation, values, words) in [
            (Notation::Gpp, "ROT_MAT1=1;", "ROT_MAT2 is not given"),
            (Notation::Gpp, "ROT_MAT10=1;", "none of"),
            (Notation::Gpp, "ROT_MAT1=one;", "finite number"),
            (Notation::Gpp, "ROT_MAT1", "no assignment"),
            (Notation::Quaternion, "1 2 3", "3 numbers where 4"),
            (Notation::Matrix, "1 0 0 0 1 0 0 0 2", "not orthonormal"),
            (Notation::Sinumerik, "TRANS X5", "is a frame"),
            (Notation::Sinumerik, "MIRROR X0", "line 1"),
        ] {
            let error = read(notation, &[values.to_string()], false).expect_err(values);
            assert!(error.contains(words), "{values}: {error}");
        }
    }
}
