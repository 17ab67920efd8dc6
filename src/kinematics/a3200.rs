//! A swivel table in Aerotech A3200 words: the `ROTATION n InputAxes ...
//! OutputAxes ...`, `ANGLE` and `Displacement` setup of the same machine
//! (seed 003, "Using the A3200 ROTATION command for five-axis systems"), and
//! back where that setup determines the record.
//!
//! The seed's rules: one ROTATION per rotary axis that carries the part,
//! from the part outward; its input axes name a right-handed frame whose
//! third axis is the one it turns about (positive by the right-hand rule,
//! `ANGLE name -1` inverts it); the displacement runs from the reference
//! point (the part origin, then the previous rotation's point) to a point
//! on the axis, written in the order of the input axes. A ROTATION maps the
//! part's coordinates onto the machine's (turning the x/y plane turns the
//! part), as the record's `R(v, α)` does for a table, so an axis vector
//! `±e` is the ROTATION about e with sign ±1.
//!
//! So a table record (P) maps exactly: ROTATION 1 is axis 2 (it rides on
//! axis 1, nearest the part) with the displacement `-l4` (part origin to its
//! pivot), ROTATION 2 is axis 1 with `-l3` (pivot 2 to pivot 1); a record
//! with one axis has one ROTATION with `-(l3 + l4)`. `l2` (machine reference
//! to pivot 1) has no A3200 word: the setup leaves where the part sits on the
//! machine to the linear axes, and reading it back closes the chain,
//! `l2 = -(l3 + l4)`, as the commissioning manual requires. A head turns the
//! tool, not the part's coordinates, and has no ROTATION setup; nor has an
//! axis that is not along X, Y or Z. The ANGLE offset is not mapped: the seed
//! does not say how it enters the angle, so a record with `$TC_CARR24/25`
//! and a setup with an offset are refused rather than guessed.

use nalgebra::Vector3;

use crate::kinematics::record::{Kinematics, Record, RotaryAxis};

/// One `ROTATION n` of the setup.
#[derive(Clone, Debug, PartialEq)]
pub struct Rotation {
    /// The indices (0 = x, 1 = y, 2 = z) of the input axes in order; the
    /// rotation turns about the third.
    pub input: [usize; 3],
    /// The rotary axis's name (`ANGLE A 1, 0`).
    pub axis: String,
    /// `1`, or `-1` to turn the other way.
    pub sign: f64,
    /// In the machine's x, y, z (written in input-axis order).
    pub displacement: Vector3<f64>,
}

/// A whole setup: the rotations from the part outward.
#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    pub rotations: Vec<Rotation>,
}

/// Why a record or a setup does not translate.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum A3200Error {
    #[error("a swivel head (T) turns the tool: A3200's ROTATION turns the part's coordinates, so only a table (P) has a ROTATION setup")]
    Head,
    #[error("mixed kinematics (M): axis 1 turns the tool, which A3200's ROTATION cannot describe; only a table (P) has a ROTATION setup")]
    Mixed,
    #[error("{axis} turns about ({x}, {y}, {z}): a ROTATION turns about one of the input axes, so the axis must lie along X, Y or Z")]
    Oblique {
        axis: String,
        x: f64,
        y: f64,
        z: f64,
    },
    #[error("{axis} has the offset {offset}° ($TC_CARR24/25): how the ANGLE offset enters the A3200's angle is not documented, so it is not written")]
    Offset { axis: String, offset: f64 },
    #[error("line {line}: {why}")]
    Text { line: usize, why: String },
    #[error("ROTATION {0} is {1}")]
    Incomplete(u32, &'static str),
    #[error("{0} ROTATION commands: a swivel data record has at most two rotary axes")]
    TooMany(usize),
    #[error("no ROTATION command")]
    Empty,
    #[error(transparent)]
    Record(#[from] crate::kinematics::record::RecordError),
    #[error("{axis}: a number of the record is not finite")]
    NotFinite { axis: String },
    #[error("{axis} is named {name:?}: an ANGLE names its axis with letters, digits and `_`, starting with a letter")]
    Name { axis: String, name: String },
}

/// Whether `name` can name an axis in an ANGLE, and so in `$TC_CARR35/36`:
/// letters, digits and `_`, starting with a letter.
fn axis_name(name: &str) -> bool {
    name.starts_with(|c: char| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The setup of a table record.
pub fn setup_of(record: &Record) -> Result<Setup, A3200Error> {
    match record.kinematics {
        Kinematics::Head => return Err(A3200Error::Head),
        Kinematics::Mixed => return Err(A3200Error::Mixed),
        Kinematics::Table => {}
    }
    record.check()?;
    let [_, _, l3, l4] = record.offsets;
    let rotation = |index: usize, displacement: Vector3<f64>| {
        let axis = &record.axes[index];
        let label = axis.label(index);
        let finite = |v: &Vector3<f64>| v.iter().all(|c| c.is_finite());
        if !(finite(&axis.vector) && finite(&displacement) && axis.offset.is_finite()) {
            return Err(A3200Error::NotFinite { axis: label });
        }
        if !axis.name.is_empty() && !axis_name(&axis.name) {
            return Err(A3200Error::Name {
                axis: format!("rotary axis {}", index + 1),
                name: axis.name.clone(),
            });
        }
        if axis.offset != 0.0 {
            return Err(A3200Error::Offset {
                axis: label,
                offset: axis.offset,
            });
        }
        let v = axis.vector;
        let along = (0..3).find(|&i| v[i] != 0.0 && (0..3).all(|j| j == i || v[j] == 0.0));
        let Some(about) = along else {
            return Err(A3200Error::Oblique {
                axis: label,
                x: v.x,
                y: v.y,
                z: v.z,
            });
        };
        Ok(Rotation {
            // The right-handed order that ends with the axis turned about:
            // x y z, y z x, z x y.
            input: [(about + 1) % 3, (about + 2) % 3, about],
            axis: if axis.name.is_empty() {
                ["A", "B", "C"][about].to_string()
            } else {
                axis.name.clone()
            },
            sign: v[about].signum(),
            displacement: displacement.map(|c| c + 0.0),
        })
    };
    let rotations = if record.axis_count() == 2 {
        vec![rotation(1, -l4)?, rotation(0, -l3)?]
    } else {
        vec![rotation(0, -(l3 + l4))?]
    };
    Ok(Setup { rotations })
}

/// The table record a setup describes (record number 1, unnamed).
pub fn record_of(setup: &Setup) -> Result<Record, A3200Error> {
    let axis = |rotation: &Rotation| RotaryAxis {
        name: rotation.axis.clone(),
        vector: Vector3::ith(rotation.input[2], rotation.sign),
        offset: 0.0,
        hirth: None,
        limits: None,
        angle: 0.0,
    };
    let none = RotaryAxis {
        name: String::new(),
        vector: Vector3::zeros(),
        offset: 0.0,
        hirth: None,
        limits: None,
        angle: 0.0,
    };
    let (axes, l3, l4) = match setup.rotations.as_slice() {
        [] => return Err(A3200Error::Empty),
        [only] => ([axis(only), none], Vector3::zeros(), -only.displacement),
        [near, far] => (
            [axis(far), axis(near)],
            -far.displacement,
            -near.displacement,
        ),
        more => return Err(A3200Error::TooMany(more.len())),
    };
    Ok(Record {
        number: 1,
        name: String::new(),
        kinematics: Kinematics::Table,
        offsets: [Vector3::zeros(), -(l3 + l4), l3, l4].map(|v| v.map(|c| c + 0.0)),
        axes,
        options: 0,
        direction_axis: None,
    })
}

const LOWER: [&str; 3] = ["x", "y", "z"];
const UPPER: [&str; 3] = ["X", "Y", "Z"];

impl Setup {
    /// The setup as the seed's example program writes it, numbers in full.
    pub fn text(&self) -> String {
        let mut text = String::new();
        for (index, rotation) in self.rotations.iter().enumerate() {
            let n = index + 1;
            let names = |names: [&str; 3]| rotation.input.map(|i| names[i]).join(" ");
            let displacement = rotation
                .input
                .map(|i| format!("{}", rotation.displacement[i] + 0.0))
                .join(", ");
            text.push_str(&format!(
                "ROTATION {n} InputAxes {} OutputAxes {}\nROTATION {n} ANGLE {} {}, 0\nROTATION {n} Displacement {displacement}\n",
                names(LOWER),
                names(UPPER),
                rotation.axis,
                rotation.sign,
            ));
        }
        text
    }

    /// Reads the ROTATION lines of a setup (any case; other lines and `;`
    /// comments skipped). The input axes are x, y, z and the output axes X,
    /// Y, Z, each in a right-handed order, the output in the input's.
    pub fn read(text: &str) -> Result<Setup, A3200Error> {
        #[derive(Default)]
        struct Partial {
            input: Option<[usize; 3]>,
            angle: Option<(String, f64)>,
            displacement: Option<[f64; 3]>,
        }
        let mut found: std::collections::BTreeMap<u32, Partial> = Default::default();
        for (index, line) in text.lines().enumerate() {
            let fail = |why: String| A3200Error::Text {
                line: index + 1,
                why,
            };
            let line = line.split(';').next().unwrap_or_default().trim();
            let mut words = line.split_whitespace();
            if !words
                .next()
                .is_some_and(|w| w.eq_ignore_ascii_case("ROTATION"))
            {
                continue;
            }
            let number: u32 = words
                .next()
                .and_then(|w| w.parse().ok())
                .ok_or_else(|| fail("ROTATION is followed by its number".into()))?;
            let entry = found.entry(number).or_default();
            let Some(what) = words.next() else {
                return Err(fail(
                    "ROTATION n is followed by InputAxes, ANGLE, Displacement, ON or OFF".into(),
                ));
            };
            let rest: Vec<&str> = words.collect();
            match what.to_ascii_lowercase().as_str() {
                "inputaxes" => {
                    let (input, output) = match rest
                        .iter()
                        .position(|w| w.eq_ignore_ascii_case("OutputAxes"))
                    {
                        Some(at) => (&rest[..at], &rest[at + 1..]),
                        None => return Err(fail("InputAxes are followed by OutputAxes".into())),
                    };
                    let order = |names: &[&str], expected: [&str; 3]| -> Option<[usize; 3]> {
                        let indices: Vec<usize> = names
                            .iter()
                            .map(|n| expected.iter().position(|e| e == n))
                            .collect::<Option<_>>()?;
                        match indices[..] {
                            [a, b, c] if (a + 1) % 3 == b && (b + 1) % 3 == c => Some([a, b, c]),
                            _ => None,
                        }
                    };
                    let input = order(input, LOWER).ok_or_else(|| {
                        fail("the input axes are x, y, z in a right-handed order: x y z, y z x or z x y".into())
                    })?;
                    if order(output, UPPER) != Some(input) {
                        return Err(fail(
                            "the output axes are X, Y, Z in the order of the input axes".into(),
                        ));
                    }
                    entry.input = Some(input);
                }
                "angle" => {
                    let joined = rest.join(" ");
                    let fields: Vec<&str> = joined
                        .split(|c: char| c == ',' || c.is_whitespace())
                        .filter(|f| !f.is_empty())
                        .collect();
                    let (name, sign, offset) = match fields[..] {
                        [name, sign, offset] => (name, sign, offset),
                        [name, sign] => (name, sign, "0"),
                        _ => {
                            return Err(fail("ANGLE takes the axis, 1 or -1, and an offset".into()))
                        }
                    };
                    let sign = match sign.parse::<f64>() {
                        Ok(s) if s == 1.0 || s == -1.0 => s,
                        _ => return Err(fail(format!("`{sign}` is no direction: give 1 or -1"))),
                    };
                    if offset.parse::<f64>() != Ok(0.0) {
                        return Err(fail(format!(
                            "the ANGLE offset `{offset}`: how it enters the angle is not documented, so only 0 is read"
                        )));
                    }
                    if !axis_name(name) {
                        return Err(fail(format!(
                            "the ANGLE's axis `{name}`: an axis is named with letters, digits and `_`, starting with a letter"
                        )));
                    }
                    entry.angle = Some((name.to_string(), sign));
                }
                "displacement" => {
                    let joined = rest.join(" ");
                    let values: Vec<f64> = joined
                        .split(|c: char| c == ',' || c.is_whitespace())
                        .filter(|f| !f.is_empty())
                        .map(|f| f.parse::<f64>().ok().filter(|v| v.is_finite()))
                        .collect::<Option<_>>()
                        .ok_or_else(|| fail("a displacement is three numbers".into()))?;
                    let [a, b, c] = values[..] else {
                        return Err(fail("a displacement is three numbers".into()));
                    };
                    // As a point on the command line: past ±1e9 (1000 km
                    // in mm) a coordinate is a typo.
                    if [a, b, c].iter().any(|v| v.abs() > 1e9) {
                        return Err(fail(format!(
                            "the displacement {a}, {b}, {c} has a number beyond ±1e9, which no machine's coordinate is"
                        )));
                    }
                    entry.displacement = Some([a, b, c]);
                }
                "on" | "off" => {}
                other => return Err(fail(format!("`{other}` is no ROTATION setting"))),
            }
        }
        if found.len() > 2 {
            return Err(A3200Error::TooMany(found.len()));
        }
        let mut rotations = Vec::new();
        for (expected, (number, partial)) in (1..).zip(found) {
            if number != expected {
                return Err(A3200Error::Incomplete(expected, "missing"));
            }
            let input = partial
                .input
                .ok_or(A3200Error::Incomplete(number, "without InputAxes"))?;
            let (axis, sign) = partial
                .angle
                .ok_or(A3200Error::Incomplete(number, "without ANGLE"))?;
            let written = partial.displacement.unwrap_or([0.0; 3]);
            let mut displacement = Vector3::zeros();
            for (k, &i) in input.iter().enumerate() {
                displacement[i] = written[k];
            }
            rotations.push(Rotation {
                input,
                axis,
                sign,
                displacement,
            });
        }
        if rotations.is_empty() {
            return Err(A3200Error::Empty);
        }
        Ok(Setup { rotations })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The seed's machine: the part on the A table (about z), 15 mm above
    /// its top and 10 mm off its centre in X; A on the B trunnion (about y),
    /// whose axis lies 12 mm above A's point. As a record: B is axis 1, A
    /// axis 2; l4 from A's point to the part origin, l3 from B's to A's.
    pub(crate) fn seed_machine() -> Record {
        Record {
            number: 1,
            name: "A3200_SEED".into(),
            kinematics: Kinematics::Table,
            offsets: [
                Vector3::zeros(),
                Vector3::new(10.0, 0.0, -3.0),
                Vector3::new(0.0, 0.0, -12.0),
                Vector3::new(-10.0, 0.0, 15.0),
            ],
            axes: [
                RotaryAxis::along("B", [0.0, 1.0, 0.0]),
                RotaryAxis::along("A", [0.0, 0.0, 1.0]),
            ],
            options: 0,
            direction_axis: None,
        }
    }

    const SEED: &str = "ROTATION 1 InputAxes x y z OutputAxes X Y Z\n\
                        ROTATION 1 ANGLE A 1, 0\n\
                        ROTATION 1 Displacement 10, 0, -15\n\
                        ROTATION 2 InputAxes z x y OutputAxes Z X Y\n\
                        ROTATION 2 ANGLE B 1, 0\n\
                        ROTATION 2 Displacement 12, 0, 0\n";

    #[test]
    fn the_seeds_machine_gives_the_seeds_setup() {
        let setup = setup_of(&seed_machine()).expect("a table");
        assert_eq!(setup.text(), SEED);
    }

    #[test]
    fn the_seeds_setup_gives_the_seeds_machine_back() {
        let setup = Setup::read(SEED).expect("a setup");
        let mut record = record_of(&setup).expect("a record");
        record.name = "A3200_SEED".into();
        assert_eq!(record, seed_machine());
        assert_eq!(setup_of(&record), Ok(setup));
    }

    /// The seed's example program, as it stands (with `Rotation 1 OFF`,
    /// comments, and G-code between).
    #[test]
    fn the_seeds_example_program_is_read() {
        let program = format!(
            "enable X Y Z A B x y z\nRotation 1 OFF\nRotation 2 OFF\n{SEED}\
             DependentCoordinatedAccelLimit = 4000\n;move physical X/Y/Z\nG0 X 5 Y60 Z23\nROTATION 1 ON\n"
        );
        assert_eq!(Setup::read(&program), Setup::read(SEED));
    }

    /// The setup moves the part as the record does: the part origin, turned
    /// by the ROTATIONs about their points, shifts as the swivel's zero
    /// point shifts (`swivel::shift`).
    #[test]
    fn the_setup_moves_the_part_origin_as_the_record_shifts_it() {
        let record = seed_machine();
        let setup = setup_of(&record).expect("a table");
        for (a, b) in [(30.0, 0.0), (0.0, 45.0), (-70.0, 20.0)] {
            let turn = |r: &Rotation, degrees: f64| {
                crate::rotation::frame::from_axis_angle(Vector3::ith(r.input[2], r.sign), degrees)
            };
            let [first, second] = &setup.rotations[..] else {
                panic!("two rotations")
            };
            // Part point → about A's point → about B's point.
            let place = |a: f64, b: f64, p: Vector3<f64>| {
                turn(second, b) * (turn(first, a) * (p - first.displacement) - second.displacement)
            };
            let moved = place(a, b, Vector3::zeros()) - place(0.0, 0.0, Vector3::zeros());
            let shift = crate::kinematics::swivel::shift(&record, [b, a]);
            assert!((moved - shift).abs().max() < 1e-12, "{a} {b}");
        }
    }

    #[test]
    fn a_reversed_axis_turns_with_sign_minus_one() {
        let mut record = seed_machine();
        record.axes[1].vector = Vector3::new(0.0, 0.0, -2.0);
        let setup = setup_of(&record).expect("a table");
        assert_eq!(setup.rotations[0].sign, -1.0);
        let back = record_of(&setup).expect("a record");
        assert_eq!(back.axes[1].vector, Vector3::new(0.0, 0.0, -1.0));
    }

    #[test]
    fn one_axis_tables_take_the_whole_way_to_their_pivot() {
        let mut record = seed_machine();
        record.axes[1] = RotaryAxis::along("", [0.0; 3]);
        record.axes[0] = RotaryAxis::along("", [1.0, 0.0, 0.0]);
        let setup = setup_of(&record).expect("a table");
        assert_eq!(
            setup.text(),
            "ROTATION 1 InputAxes y z x OutputAxes Y Z X\nROTATION 1 ANGLE A 1, 0\nROTATION 1 Displacement 0, -3, 10\n"
        );
    }

    #[test]
    fn what_has_no_rotation_setup_is_refused() {
        let mut head = seed_machine();
        head.kinematics = Kinematics::Head;
        assert_eq!(setup_of(&head), Err(A3200Error::Head));
        let mut oblique = seed_machine();
        oblique.axes[0].vector = Vector3::new(0.0, 1.0, 1.0);
        assert!(matches!(
            setup_of(&oblique),
            Err(A3200Error::Oblique { .. })
        ));
        let mut offset = seed_machine();
        offset.axes[0].offset = 5.0;
        assert!(matches!(setup_of(&offset), Err(A3200Error::Offset { .. })));
        for (text, words) in [
            (
                "ROTATION 1 InputAxes x z y OutputAxes X Z Y",
                "right-handed",
            ),
            (
                "ROTATION 1 InputAxes x y z OutputAxes Y Z X",
                "order of the input",
            ),
            ("ROTATION 1 ANGLE A 2, 0", "no direction"),
            ("ROTATION 1 ANGLE A 1, 5", "offset"),
            ("ROTATION 1 Displacement 1, 2", "three numbers"),
            (
                "ROTATION 1 InputAxes x y z OutputAxes X Y Z",
                "without ANGLE",
            ),
            (
                "ROTATION 2 InputAxes x y z OutputAxes X Y Z\nROTATION 2 ANGLE A 1, 0",
                "missing",
            ),
            ("G1 X1", "no ROTATION"),
        ] {
            let error = Setup::read(text)
                .and_then(|s| record_of(&s))
                .expect_err(text);
            assert!(error.to_string().contains(words), "{text}: {error}");
        }
    }
}
