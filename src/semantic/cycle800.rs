//! What a CYCLE800 call asks for, parameter by parameter, in words: the
//! retraction, the record, new or additive plane, what `_MODE` makes of the
//! three angles, the direction. Read from the call's constant arguments;
//! an argument that is not a constant is shown as written.
//!
//! The codings rest on `../shared/reference/sinumerik.md` §1 (the operating
//! manual's screen parameters, and the `_MODE` bits as CAM posts and the
//! cycle's parameter classes write them); where only the swivel mode's two
//! high bits are known (solid and projection angle), only the mode is said.

use crate::rotation::{Axis, Kind, Sequence};
use crate::semantic::eval::{evaluate, Lookup};
use crate::semantic::value::{Unknown, Value};
use crate::syntax::tree::Call;

/// The parameters in call order (the 16-parameter form of SINUMERIK Operate).
pub const PARAMETERS: [&str; 16] = [
    "_FR", "_TC", "_ST", "_MODE", "_X0", "_Y0", "_Z0", "_A", "_B", "_C", "_X1", "_Y1", "_Z1",
    "_DIR", "_FR_I", "_DMODE",
];

/// A CYCLE800 call's arguments, each a constant where it is one.
pub struct Arguments<'c> {
    source: &'c [u8],
    call: &'c Call,
}

impl<'c> Arguments<'c> {
    pub fn of(source: &'c [u8], call: &'c Call) -> Self {
        Self { source, call }
    }

    /// Argument `index` (from 0) as a constant: one left out is 0 (an
    /// empty string for `_TC`, which reads the same); `None` for one that
    /// is not a constant.
    pub fn value(&self, index: usize) -> Option<Value> {
        match self
            .call
            .arguments
            .items
            .get(index)
            .and_then(|a| a.value.as_ref())
        {
            None => Some(Value::Number(0.0)),
            Some(expr) => evaluate(self.source, expr, &Constants).ok(),
        }
    }

    pub fn number(&self, index: usize) -> Option<f64> {
        match self.value(index)? {
            Value::Number(n) => Some(n),
            Value::Text(_) => None,
        }
    }

    /// Argument `index` as written, trimmed; `None` past the last one.
    fn written(&self, index: usize) -> Option<String> {
        let argument = self.call.arguments.items.get(index)?;
        let text = String::from_utf8_lossy(argument.span.of(self.source));
        Some(text.trim().to_string())
    }

    fn count(&self) -> usize {
        self.call.arguments.items.len()
    }
}

/// Constants only: a variable's value is the walk's business.
struct Constants;

impl Lookup for Constants {
    fn variable(&self, key: &str) -> Result<Value, Unknown> {
        Err(Unknown::Invalid(format!("`{key}` is a variable")))
    }
}

/// How `_MODE` reads the three angles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mode {
    /// `_A`, `_B`, `_C` turn about the three axes in this order, each about
    /// the axis as the turns before it left it.
    AxisByAxis(Sequence),
    SolidAngle,
    ProjectionAngle,
    /// `_A` and `_B` are the positions of rotary axes 1 and 2.
    RotaryAxesDirect,
}

impl Mode {
    /// Bits 7-6 the swivel mode; for axis by axis, bits 1-0, 3-2 and 5-4
    /// the axes `_A`, `_B` and `_C` turn about (01 X, 10 Y, 11 Z).
    pub fn of(code: f64) -> Option<Mode> {
        if code.fract() != 0.0 || !(0.0..256.0).contains(&code) {
            return None;
        }
        let code = code as i64;
        match code >> 6 {
            0 => Sequence::from_code(code, Kind::Intrinsic)
                .ok()
                .map(Mode::AxisByAxis),
            1 => Some(Mode::SolidAngle),
            2 => Some(Mode::ProjectionAngle),
            _ => Some(Mode::RotaryAxesDirect),
        }
    }

    /// What `_A`, `_B` and `_C` are under this mode.
    fn angles(self) -> [String; 3] {
        match self {
            Mode::AxisByAxis(sequence) => {
                let [a, b, c] = sequence.axes;
                [
                    format!("first turn, about {}", letter(a)),
                    format!("second turn, about {}'", letter(b)),
                    format!("third turn, about {}''", letter(c)),
                ]
            }
            Mode::RotaryAxesDirect => [
                "position of rotary axis 1".to_string(),
                "position of rotary axis 2".to_string(),
                "not read".to_string(),
            ],
            Mode::SolidAngle | Mode::ProjectionAngle => [
                "angle".to_string(),
                "angle".to_string(),
                "angle".to_string(),
            ],
        }
    }
}

fn letter(axis: Axis) -> char {
    match axis {
        Axis::X => 'X',
        Axis::Y => 'Y',
        Axis::Z => 'Z',
    }
}

impl std::fmt::Display for Mode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Mode::AxisByAxis(sequence) => {
                let [a, b, c] = sequence.axes;
                write!(
                    f,
                    "axis by axis: {}, then {}', then {}''",
                    letter(a),
                    letter(b),
                    letter(c)
                )
            }
            Mode::SolidAngle => f.write_str("solid angle"),
            Mode::ProjectionAngle => f.write_str("projection angle"),
            Mode::RotaryAxesDirect => f.write_str("rotary axes direct"),
        }
    }
}

/// One parameter of a call: its name, its argument as written (empty where
/// left out), and what it means there.
pub struct Parameter {
    pub name: &'static str,
    pub written: String,
    pub meaning: String,
}

/// Each parameter the call gives, or leaves out up to `_DIR`, with its
/// meaning; arguments past the 16th are named by their place.
pub fn describe(source: &[u8], call: &Call) -> Vec<Parameter> {
    let arguments = Arguments::of(source, call);
    let mode = arguments.number(3).and_then(Mode::of);
    let angles = mode.map(Mode::angles);
    let shown = arguments.count().max(14);
    (0..shown)
        .map(|index| {
            let name = PARAMETERS.get(index).copied().unwrap_or("");
            let number = arguments.number(index);
            let meaning = match (index, number) {
                (_, None) if index != 1 => {
                    "not a constant: known when the program runs".to_string()
                }
                (0, Some(fr)) => retraction(fr),
                (1, _) => match arguments.value(1) {
                    Some(Value::Text(name)) if name.trim().is_empty() => {
                        "swivel data record: none named (the channel's only one)".to_string()
                    }
                    Some(Value::Text(name)) => format!("swivel data record `{name}`"),
                    Some(Value::Number(_)) => "swivel data record: none named".to_string(),
                    None => "swivel data record: not a constant".to_string(),
                },
                (2, Some(st)) if st.rem_euclid(10.0) == 0.0 => "new swivel plane".to_string(),
                (2, Some(st)) if st.rem_euclid(10.0) == 1.0 => {
                    "additive swivel plane (turns on from the plane in force)".to_string()
                }
                (2, Some(st)) => format!(
                    "ones digit {} is no swivel plane CYCLE800 knows (0 new, 1 additive)",
                    number_text(st.rem_euclid(10.0))
                ),
                (3, Some(code)) => match mode {
                    Some(mode) => mode.to_string(),
                    None => format!("{} is no swivel mode CYCLE800 knows", number_text(code)),
                },
                (4..=6, _) => "centre of rotation, in the plane before the swivel".to_string(),
                (7..=9, _) => match &angles {
                    Some(angles) => format!("{} (degrees)", angles[index - 7]),
                    None => "angle, read as `_MODE` says".to_string(),
                },
                (10..=12, _) => "zero point of the swivelled plane, after the turn".to_string(),
                (13, Some(dir)) => direction(dir),
                (14, _) => "retraction path in tool direction, for `_FR` 5 (mm)".to_string(),
                (15, _) => "how the screen form shows the plane (for the operator)".to_string(),
                _ => "not a CYCLE800 parameter".to_string(),
            };
            Parameter {
                name,
                written: arguments.written(index).unwrap_or_default(),
                meaning,
            }
        })
        .collect()
}

fn retraction(fr: f64) -> String {
    match fr {
        0.0 => "no retraction".to_string(),
        1.0 => "retract machine Z".to_string(),
        2.0 => "retract machine Z, then X and Y".to_string(),
        4.0 => "retract as far as possible in tool direction".to_string(),
        5.0 => "retract in tool direction by `_FR_I`".to_string(),
        other => format!("{} is no retraction CYCLE800 knows", number_text(other)),
    }
}

fn direction(dir: f64) -> String {
    match dir {
        -1.0 => "minus: of the two solutions, the lower position of the reference axis".to_string(),
        1.0 => "plus: of the two solutions, the higher position of the reference axis".to_string(),
        0.0 => "rotary axes not moved: the frame only".to_string(),
        other => format!("{} is no direction CYCLE800 knows", number_text(other)),
    }
}

fn number_text(value: f64) -> String {
    crate::number::format(value, 6)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::semantic::Model;
    use crate::syntax::tree::{LineKind, StatementKind};

    fn described(line: &str) -> Vec<(String, String)> {
        let source = line.as_bytes();
        let model = Model::of(source);
        let lines: Vec<_> = model.lines.other_lines().collect();
        let (_, line) = &lines[0];
        let LineKind::Block(block) = &line.kind else {
            panic!("not a block");
        };
        let StatementKind::Call(call) = &block.statements[0].kind else {
            panic!("not a call");
        };
        describe(source, call)
            .into_iter()
            .map(|p| (p.name.to_string(), p.meaning))
            .collect()
    }

    #[test]
    fn an_axis_by_axis_call_reads_as_the_manual_says() {
        let found = described("CYCLE800(1,\"HERMLE\",100000,39,0,0,0,180,-90,0,0,0,0,-1,100,1)\n");
        let meaning = |name: &str| &found.iter().find(|(n, _)| n == name).expect("described").1;
        assert_eq!(meaning("_FR"), "retract machine Z");
        assert_eq!(meaning("_TC"), "swivel data record `HERMLE`");
        assert_eq!(meaning("_ST"), "new swivel plane");
        assert_eq!(meaning("_MODE"), "axis by axis: Z, then X', then Y''");
        assert_eq!(meaning("_A"), "first turn, about Z (degrees)");
        assert_eq!(meaning("_B"), "second turn, about X' (degrees)");
        assert_eq!(meaning("_C"), "third turn, about Y'' (degrees)");
        assert!(meaning("_DIR").starts_with("minus"));
        assert_eq!(found.len(), 16);
    }

    #[test]
    fn modes_and_codes_it_does_not_know_are_said_so() {
        let found = described("CYCLE800(3,\"TC1\",1,58,0,0,0,R1,0,0,0,0,0,2)\n");
        let meanings: Vec<&str> = found.iter().map(|(_, m)| m.as_str()).collect();
        assert_eq!(meanings[0], "3 is no retraction CYCLE800 knows");
        assert!(meanings[2].starts_with("additive"));
        assert_eq!(meanings[3], "58 is no swivel mode CYCLE800 knows");
        assert_eq!(meanings[7], "not a constant: known when the program runs");
        assert_eq!(meanings[13], "2 is no direction CYCLE800 knows");
        assert_eq!(found.len(), 14, "left-out parameters up to _DIR are shown");
        assert_eq!(Mode::of(192.0), Some(Mode::RotaryAxesDirect));
        assert_eq!(Mode::of(64.0), Some(Mode::SolidAngle));
        assert_eq!(Mode::of(128.0), Some(Mode::ProjectionAngle));
        assert_eq!(Mode::of(256.0), None);
        assert_eq!(Mode::of(57.5), None);
    }
}
