//! Rotation sequences: three axes, performed intrinsically (about the moving
//! workpiece axes) or extrinsically (about the fixed machine axes).
//!
//! The Siemens code is CYCLE800's `_MODE` axis coding (spec section 2): three
//! 2-bit groups, X = 01, Y = 10, Z = 11, bits 1-0 holding the axis of the
//! rotation performed first. So 57 = X, Y, Z and 39 = Z, X, Y, for intrinsic
//! and extrinsic sequences alike.

use std::fmt;
use std::str::FromStr;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    X = 0,
    Y = 1,
    Z = 2,
}

impl Axis {
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    pub fn index(self) -> usize {
        self as usize
    }

    pub fn letter(self) -> char {
        ['X', 'Y', 'Z'][self.index()]
    }

    fn from_letter(letter: char) -> Option<Axis> {
        match letter.to_ascii_uppercase() {
            'X' => Some(Axis::X),
            'Y' => Some(Axis::Y),
            'Z' => Some(Axis::Z),
            _ => None,
        }
    }

    /// The 2-bit group of the Siemens code.
    fn bits(self) -> u32 {
        self.index() as u32 + 1
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// About the axes of the rotating body (workpiece): R = R_a · R_b · R_c.
    Intrinsic,
    /// About the fixed axes (machine): R = R_c · R_b · R_a.
    Extrinsic,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Intrinsic => "intrinsic",
            Kind::Extrinsic => "extrinsic",
        }
    }

    /// CYCLE600's BOOL: 1 intrinsic, 0 extrinsic.
    pub fn from_flag(intrinsic: bool) -> Kind {
        if intrinsic {
            Kind::Intrinsic
        } else {
            Kind::Extrinsic
        }
    }
}

/// Three axes in the order they are performed, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sequence {
    pub axes: [Axis; 3],
    pub kind: Kind,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SequenceError {
    #[error("{0} is not a rotation sequence code: the valid codes are 57 (XYZ), 45 (XZY), 54 (YXZ), 30 (YZX), 39 (ZXY), 27 (ZYX), and for proper Euler sequences 25 (XYX), 29 (XZX), 38 (YXY), 46 (YZY), 55 (ZXZ), 59 (ZYZ)")]
    InvalidCode(i64),
    #[error("`{0}` is not a rotation sequence: write `intrinsic:ZXY`, `extrinsic:XYZ`, `i:ZXY` or `e:57` (kind, then three axes X/Y/Z with no axis twice in a row, or a code)")]
    InvalidText(String),
}

impl Sequence {
    pub fn new(axes: [Axis; 3], kind: Kind) -> Result<Sequence, SequenceError> {
        if axes[0] == axes[1] || axes[1] == axes[2] {
            let text: String = axes.iter().map(|a| a.letter()).collect();
            return Err(SequenceError::InvalidText(format!(
                "{}:{text}",
                kind.name()
            )));
        }
        Ok(Sequence { axes, kind })
    }

    /// All 24 sequences: 6 Tait-Bryan and 6 proper Euler orders, each of both kinds.
    pub fn all() -> impl Iterator<Item = Sequence> {
        [Kind::Intrinsic, Kind::Extrinsic]
            .into_iter()
            .flat_map(|kind| {
                Axis::ALL.into_iter().flat_map(move |a| {
                    Axis::ALL.into_iter().flat_map(move |b| {
                        Axis::ALL
                            .into_iter()
                            .filter_map(move |c| Sequence::new([a, b, c], kind).ok())
                    })
                })
            })
    }

    /// Proper Euler sequences (first axis = third axis) have their middle
    /// angle in [0, 180]; Tait-Bryan ones in [-90, 90].
    pub fn is_proper_euler(self) -> bool {
        self.axes[0] == self.axes[2]
    }

    /// The Siemens code (CYCLE800 `_MODE` bits 5-0).
    pub fn code(self) -> u32 {
        self.axes[0].bits() | self.axes[1].bits() << 2 | self.axes[2].bits() << 4
    }

    pub fn from_code(code: i64, kind: Kind) -> Result<Sequence, SequenceError> {
        if !(0..64).contains(&code) {
            return Err(SequenceError::InvalidCode(code));
        }
        let group = |shift: i64| match (code >> shift) & 0b11 {
            1 => Some(Axis::X),
            2 => Some(Axis::Y),
            3 => Some(Axis::Z),
            _ => None,
        };
        match (group(0), group(2), group(4)) {
            (Some(a), Some(b), Some(c)) => {
                Sequence::new([a, b, c], kind).map_err(|_| SequenceError::InvalidCode(code))
            }
            _ => Err(SequenceError::InvalidCode(code)),
        }
    }

    /// The same rotation written the other way: an extrinsic a, b, c with
    /// angles θ1, θ2, θ3 is the intrinsic c, b, a with θ3, θ2, θ1.
    pub fn reversed(self) -> Sequence {
        let [a, b, c] = self.axes;
        let kind = match self.kind {
            Kind::Intrinsic => Kind::Extrinsic,
            Kind::Extrinsic => Kind::Intrinsic,
        };
        Sequence {
            axes: [c, b, a],
            kind,
        }
    }

    pub fn letters(self) -> String {
        self.axes.iter().map(|a| a.letter()).collect()
    }
}

impl fmt::Display for Sequence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.kind.name(), self.letters())
    }
}

impl FromStr for Sequence {
    type Err = SequenceError;

    /// `intrinsic:ZXY`, `extrinsic:XYZ`, `i:ZXY`, `e:57`, any case.
    fn from_str(text: &str) -> Result<Sequence, SequenceError> {
        let invalid = || SequenceError::InvalidText(text.to_string());
        let (kind, rest) = text.trim().split_once(':').ok_or_else(invalid)?;
        let kind = match kind.trim().to_ascii_lowercase().as_str() {
            "i" | "intrinsic" => Kind::Intrinsic,
            "e" | "extrinsic" => Kind::Extrinsic,
            _ => return Err(invalid()),
        };
        let rest = rest.trim();
        if let Ok(code) = rest.parse::<i64>() {
            return Sequence::from_code(code, kind);
        }
        let letters: Vec<Axis> = rest
            .chars()
            .filter(|c| !matches!(c, ',' | '-' | '\'' | ' '))
            .map(Axis::from_letter)
            .collect::<Option<_>>()
            .ok_or_else(invalid)?;
        match letters.as_slice() {
            &[a, b, c] => Sequence::new([a, b, c], kind).map_err(|_| invalid()),
            _ => Err(invalid()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_table_codes_map_both_ways() {
        let table = [
            (57, "XYZ"),
            (45, "XZY"),
            (54, "YXZ"),
            (30, "YZX"),
            (39, "ZXY"),
            (27, "ZYX"),
            (55, "ZXZ"),
        ];
        for (code, letters) in table {
            for kind in [Kind::Intrinsic, Kind::Extrinsic] {
                let sequence = Sequence::from_code(code, kind).expect("valid code");
                assert_eq!(sequence.letters(), letters);
                assert_eq!(sequence.code(), code as u32);
            }
        }
    }

    #[test]
    fn there_are_24_sequences_each_with_its_own_code() {
        let all: Vec<Sequence> = Sequence::all().collect();
        assert_eq!(all.len(), 24);
        for sequence in all {
            assert_eq!(
                Sequence::from_code(sequence.code() as i64, sequence.kind),
                Ok(sequence)
            );
            assert_eq!(sequence.to_string().parse(), Ok(sequence));
        }
    }

    #[test]
    fn invalid_codes_are_refused() {
        for code in [0, 5, 21, 63, 64, -1, 1000, 0b111111] {
            assert!(
                Sequence::from_code(code, Kind::Intrinsic).is_err(),
                "{code}"
            );
        }
    }

    #[test]
    fn text_forms() {
        let zxy = Sequence::from_code(39, Kind::Intrinsic).expect("valid");
        assert_eq!("intrinsic:ZXY".parse(), Ok(zxy));
        assert_eq!("I:zxy".parse(), Ok(zxy));
        assert_eq!("i:39".parse(), Ok(zxy));
        assert_eq!(
            "e:57".parse::<Sequence>().map(|s| s.kind),
            Ok(Kind::Extrinsic)
        );
        for bad in ["ZXY", "x:ZXY", "i:ZZY", "i:XY", "i:ABC", "e:0", ""] {
            assert!(bad.parse::<Sequence>().is_err(), "{bad}");
        }
    }
}
