//! The programmable frame that a list of frame statements makes, composed as
//! the control composes it (`reference/sinumerik.md` section 3): `TRANS`,
//! `ROT` and `ROTS` replace the whole programmable frame, `ATRANS`, `AROT`
//! and `AROTS` are chained to its end (`old : new`, so a later one moves
//! along and turns about the axes the earlier ones made), `ROT X.. Y.. Z..`
//! in one block turns in the RPY order Z, Y', X'' (MD10600 = 1), `RPL`
//! turns in the active plane (G17 about Z, G18 about Y, G19 about X).
//!
//! It reads blocks of frame statements and plane selections only, with
//! constant values (`X=2*15` is read, `X=R1` is not), and refuses the rest:
//! scaling and mirroring (no rigid motion), `CROTS` (it reads the frame
//! held in the control's data). A control set to Euler angles (MD10600 = 2,
//! Z, X', Z'') reads `ROT X.. Y.. Z..` otherwise; RPY is taken here, as the
//! rest of sinuprep takes it.

use nalgebra::{Rotation3, Vector3};

use crate::rotation::forms::{pose, Pose};
use crate::rotation::{matrix, Axis, Kind, Sequence};
use crate::semantic::eval::{evaluate, Lookup};
use crate::semantic::value::{Unknown, Value};
use crate::syntax::tree::{Block, FrameKind, StatementKind, WordValue};

/// A statement the evaluation cannot take: its 1-based line and why.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("line {line}: {why}")]
pub struct FrameStatementError {
    pub line: usize,
    pub why: String,
}

/// No variable has a value here: only constants are read.
struct Constants;

impl Lookup for Constants {
    fn variable(&self, key: &str) -> Result<Value, Unknown> {
        Err(Unknown::Invalid(format!(
            "`{key}` has no value here: give the frame's numbers"
        )))
    }
}

/// The active plane, for `RPL`.
#[derive(Clone, Copy)]
enum Plane {
    G17,
    G18,
    G19,
}

/// The programmable frame of `source`'s frame statements, from an empty one
/// in G17.
pub fn evaluate_frame_statements(source: &[u8]) -> Result<Pose, FrameStatementError> {
    let program = crate::syntax::parse(source);
    if let Some(diagnostic) = program.diagnostics.first() {
        let line = source[..diagnostic.span.start.min(source.len())]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        return Err(FrameStatementError {
            line: line + 1,
            why: diagnostic.message.clone(),
        });
    }
    let mut frame = Pose::identity();
    let mut plane = Plane::G17;
    for (index, line) in program.lines.iter().enumerate() {
        let crate::syntax::tree::LineKind::Block(block) = &line.kind else {
            continue;
        };
        let fail = |why: String| FrameStatementError {
            line: index + 1,
            why,
        };
        block_effect(source, block, &mut frame, &mut plane).map_err(fail)?;
    }
    Ok(frame)
}

/// What one block does to the frame (or the plane).
fn block_effect(
    source: &[u8],
    block: &Block,
    frame: &mut Pose,
    plane: &mut Plane,
) -> Result<(), String> {
    let Some(first) = block.statements.first() else {
        return Ok(());
    };
    let StatementKind::Frame(statement) = &first.kind else {
        return plane_selection(source, block, plane);
    };
    let mut values: Vec<(String, f64)> = Vec::new();
    for item in &block.statements[1..] {
        let (name, value) = match &item.kind {
            StatementKind::Word(word) if word.extension.is_none() => {
                let value = match &word.value {
                    WordValue::Number(number) => number.value,
                    WordValue::Expr(expr) => number(source, expr)?,
                };
                (word.address.upper(source), value)
            }
            StatementKind::Assign(assign) if assign.target.indices.is_empty() => (
                assign.target.name.upper(source),
                number(source, &assign.value)?,
            ),
            _ => {
                return Err(format!(
                    "`{}` is no value of a frame statement: write one frame statement a block, \
                     as `AROT Z=30`",
                    String::from_utf8_lossy(item.span.of(source))
                ))
            }
        };
        if values.iter().any(|(seen, _)| *seen == name) {
            return Err(format!("{name} is given twice"));
        }
        values.push((name, value));
    }
    let keyword = statement.keyword.upper(source);
    let allowed: &[&str] = match statement.kind {
        FrameKind::Rot | FrameKind::ARot => &["X", "Y", "Z", "RPL"],
        FrameKind::Trans | FrameKind::ATrans | FrameKind::Rots | FrameKind::ARots => {
            &["X", "Y", "Z"]
        }
        FrameKind::CRots => {
            return Err(
                "CROTS turns the frame the control holds in its data, which is not known here"
                    .into(),
            )
        }
        FrameKind::Scale | FrameKind::AScale | FrameKind::Mirror | FrameKind::AMirror => {
            return Err(format!(
                "{keyword} scales or mirrors: a frame with it is no rotation and translation"
            ))
        }
    };
    if let Some((name, _)) = values.iter().find(|(n, _)| !allowed.contains(&n.as_str())) {
        return Err(format!(
            "{keyword} takes {}, not {name}",
            allowed.join(", ")
        ));
    }
    let get = |name: &str| values.iter().find(|(n, _)| n == name).map(|(_, v)| *v);
    let xyz = [get("X"), get("Y"), get("Z")];
    let vector = || Vector3::from(xyz.map(|v| v.unwrap_or(0.0)));
    let rotation = || -> Result<Rotation3<f64>, String> {
        match get("RPL") {
            Some(_) if xyz.iter().any(Option::is_some) => {
                Err(format!("{keyword} takes RPL or axes, not both"))
            }
            Some(angle) => {
                let axis = match plane {
                    Plane::G17 => Axis::Z,
                    Plane::G18 => Axis::Y,
                    Plane::G19 => Axis::X,
                };
                Ok(elemental(axis, angle))
            }
            // RPY: Z, Y', X'' whatever order the axes are written in.
            None => {
                let [x, y, z] = xyz.map(|v| v.unwrap_or(0.0));
                Ok(matrix(
                    Sequence {
                        axes: [Axis::Z, Axis::Y, Axis::X],
                        kind: Kind::Intrinsic,
                    },
                    [z, y, x],
                ))
            }
        }
    };
    let translation = |v: Vector3<f64>| pose(v, Rotation3::identity());
    let turn = |r: Rotation3<f64>| pose(Vector3::zeros(), r);
    match statement.kind {
        // Without values, TRANS and ROT clear the programmable frame.
        FrameKind::Trans => *frame = translation(vector()),
        FrameKind::ATrans => *frame *= translation(vector()),
        FrameKind::Rot => *frame = turn(rotation()?),
        FrameKind::ARot => *frame *= turn(rotation()?),
        FrameKind::Rots => *frame = turn(solid_angles(xyz)?),
        FrameKind::ARots => *frame *= turn(solid_angles(xyz)?),
        _ => unreachable!("refused above"),
    }
    Ok(())
}

/// A block of G17, G18 or G19 alone.
fn plane_selection(source: &[u8], block: &Block, plane: &mut Plane) -> Result<(), String> {
    for statement in &block.statements {
        let text = statement.span.of(source);
        *plane = match text.to_ascii_uppercase().as_slice() {
            b"G17" => Plane::G17,
            b"G18" => Plane::G18,
            b"G19" => Plane::G19,
            _ => {
                return Err(format!(
                    "`{}` is no frame statement: write TRANS, ATRANS, ROT, AROT, ROTS or AROTS \
                     (each in a block of its own), or G17/G18/G19 for RPL",
                    String::from_utf8_lossy(text)
                ))
            }
        };
    }
    Ok(())
}

fn number(source: &[u8], expr: &crate::syntax::tree::Expr) -> Result<f64, String> {
    match evaluate(source, expr, &Constants) {
        Ok(Value::Number(n)) if n.is_finite() => Ok(n),
        Ok(_) => Err(format!(
            "`{}` is no number",
            String::from_utf8_lossy(expr.span.of(source))
        )),
        Err(unknown) => Err(unknown.to_string()),
    }
}

/// The right-hand rotation about one axis.
fn elemental(axis: Axis, degrees: f64) -> Rotation3<f64> {
    let other = if axis == Axis::X { Axis::Y } else { Axis::X };
    matrix(
        Sequence {
            axes: [axis, other, axis],
            kind: Kind::Intrinsic,
        },
        [degrees, 0.0, 0.0],
    )
}

/// `ROTS` with one or two solid angles (Siemens PM, "ROTS, AROTS, CROTS";
/// `reference/sinumerik.md` 3.4): of the plane of two programmed axes, taken
/// in cyclic order (first, second) = (X, Y), (Y, Z) or (Z, X), the angle of
/// the second axis turns the first about it into the oblique plane, the
/// angle of the first turns the second about it; the new first axis stays in
/// the plane of the first and third axes. One angle is `ROT` about its axis.
pub(crate) fn solid_angles(xyz: [Option<f64>; 3]) -> Result<Rotation3<f64>, String> {
    let given: Vec<usize> = (0..3).filter(|&i| xyz[i].is_some()).collect();
    let (first, second) = match given.as_slice() {
        [] => return Ok(Rotation3::identity()),
        [only] => return Ok(elemental(Axis::ALL[*only], xyz[*only].unwrap_or(0.0))),
        [0, 1] => (0, 1),
        [1, 2] => (1, 2),
        [0, 2] => (2, 0),
        _ => return Err("ROTS takes one or two solid angles, not three".into()),
    };
    let third = 3 - first - second;
    let unit = |i: usize| Vector3::ith(i, 1.0);
    let angle = |i: usize| xyz[i].unwrap_or(0.0);
    let new_first = elemental(Axis::ALL[second], angle(second)) * unit(first);
    let toward_second = elemental(Axis::ALL[first], angle(first)) * unit(second);
    let normal = new_first.cross(&toward_second);
    if normal.norm() < 1e-12 {
        return Err("the solid angles turn both axes onto one line: no plane".into());
    }
    let new_third = normal.normalize();
    let new_second = new_third.cross(&new_first);
    let mut columns = [Vector3::zeros(); 3];
    columns[first] = new_first;
    columns[second] = new_second;
    columns[third] = new_third;
    Ok(Rotation3::from_matrix_unchecked(
        nalgebra::Matrix3::from_columns(&columns),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(text: &str) -> Pose {
        evaluate_frame_statements(text.as_bytes()).expect("frame statements")
    }

    fn rotation(text: &str, angles: [f64; 3]) -> Rotation3<f64> {
        matrix(text.parse().expect("sequence"), angles)
    }

    fn close(a: &Pose, b: &Pose) -> bool {
        (a.to_homogeneous() - b.to_homogeneous()).abs().max() < 1e-12
    }

    /// Three AROT blocks are CYCLE800's mode 57; ROT in one block is RPY.
    #[test]
    fn arot_blocks_chain_intrinsically_and_rot_is_rpy() {
        let chained = frame("AROT X=30\nAROT Y=45\nAROT Z=60\n");
        assert!(close(
            &chained,
            &pose(Vector3::zeros(), rotation("i:XYZ", [30.0, 45.0, 60.0]))
        ));
        let rpy = frame("ROT Z60 X30 Y=45");
        assert!(close(
            &rpy,
            &pose(Vector3::zeros(), rotation("i:ZYX", [60.0, 45.0, 30.0]))
        ));
    }

    /// TRANS and ROT replace the frame; ATRANS moves along the turned axes.
    #[test]
    fn absolute_statements_replace_additive_ones_chain() {
        let f = frame("N10 ROT Z=45\nN20 TRANS X10 Y20\nAROT Z=90 ; turn\nATRANS X=2*5\n");
        let expected = pose(
            Vector3::new(10.0, 30.0, 0.0),
            rotation("i:ZYX", [90.0, 0.0, 0.0]),
        );
        assert!(close(&f, &expected), "{f}");
        assert!(close(
            &frame("TRANS X1\nAROT Z5\nTRANS\n"),
            &Pose::identity()
        ));
        assert!(close(&frame("TRANS X1\nROT\n"), &Pose::identity()));
    }

    /// Siemens' own example: `TRANS X30 Y26`, `AROT RPL=45`.
    #[test]
    fn rpl_turns_in_the_active_plane() {
        let g17 = frame("TRANS X30 Y26\nAROT RPL=45\n");
        assert!(close(
            &g17,
            &pose(
                Vector3::new(30.0, 26.0, 0.0),
                rotation("i:ZYX", [45.0, 0.0, 0.0])
            )
        ));
        let g18 = frame("G18\nROT RPL=20\n");
        assert!(close(
            &g18,
            &pose(Vector3::zeros(), rotation("i:YXZ", [20.0, 0.0, 0.0]))
        ));
    }

    /// ROTS X Y: the new X axis lies in the old ZX plane, turned by the Y
    /// angle; the new Y lies in the plane through the X-turned Y axis.
    #[test]
    fn rots_keeps_the_new_x_axis_in_the_zx_plane() {
        let f = frame("ROTS X10 Y20");
        let r = f.rotation;
        let x = r * Vector3::x();
        assert!(x.y.abs() < 1e-15);
        assert!((x - rotation("i:YXZ", [20.0, 0.0, 0.0]) * Vector3::x()).norm() < 1e-15);
        let toward_y = rotation("i:XYZ", [10.0, 0.0, 0.0]) * Vector3::y();
        assert!((r * Vector3::z()).dot(&toward_y).abs() < 1e-15);
        assert!((r.matrix().determinant() - 1.0).abs() < 1e-15);
        assert!(close(&frame("ROTS Z30"), &frame("ROT Z30")));
    }

    #[test]
    fn what_is_no_rigid_frame_statement_is_refused_with_its_line() {
        for (text, line, words) in [
            ("TRANS X1\nSCALE X2", 2, "scales"),
            ("MIRROR X0", 1, "mirrors"),
            ("CROTS X10 Y10", 1, "CROTS"),
            ("AROT X=R1", 1, "R1"),
            ("AROT A30", 1, "not A"),
            ("TRANS X1 X2", 1, "twice"),
            ("AROT RPL=5 X3", 1, "not both"),
            ("G1 X10", 1, "no frame statement"),
            ("ROTS X1 Y2 Z3", 1, "not three"),
            ("AROT X=(1", 1, ""),
        ] {
            let error = evaluate_frame_statements(text.as_bytes()).expect_err(text);
            assert_eq!(error.line, line, "{text}");
            assert!(error.why.contains(words), "{text}: {}", error.why);
        }
    }
}
