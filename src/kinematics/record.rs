//! A swivel data record (toolholder with orientation capability, TCARR) as
//! the solver needs it: what the control holds in `$TC_CARR1..65[m]`
//! (Siemens, Function Manual Tools, "Orientable toolholders"; the fields in
//! `reference/kinematics.md` section 1), with the fine offsets already added
//! where they apply.

use nalgebra::Vector3;

/// `$TC_CARR23`: what the rotary axes move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kinematics {
    /// `T`: both axes turn the tool (a swivel head); axis 2 rides on axis 1.
    Head,
    /// `P`: both axes turn the part (a swivel table); axis 2 rides on axis 1.
    Table,
    /// `M`: axis 1 turns the tool, axis 2 the part.
    Mixed,
}

impl Kinematics {
    /// The letter of `$TC_CARR23` (either case).
    pub fn from_letter(letter: &str) -> Option<Self> {
        match letter.trim() {
            "T" | "t" => Some(Self::Head),
            "P" | "p" => Some(Self::Table),
            "M" | "m" => Some(Self::Mixed),
            _ => None,
        }
    }

    pub fn letter(self) -> char {
        match self {
            Self::Head => 'T',
            Self::Table => 'P',
            Self::Mixed => 'M',
        }
    }
}

/// A grid of allowed positions: `offset + n · increment` (`$TC_CARR26..29`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hirth {
    pub offset: f64,
    pub increment: f64,
}

impl Hirth {
    /// The grid positions either side of `position` (the same one twice on
    /// the grid).
    pub fn neighbours(self, position: f64) -> [f64; 2] {
        let steps = (position - self.offset) / self.increment;
        [steps.floor(), steps.ceil()].map(|n| self.offset + n * self.increment)
    }

    /// The nearest grid position (half away from zero).
    pub fn round(self, position: f64) -> f64 {
        self.offset + self.increment * ((position - self.offset) / self.increment).round()
    }
}

/// One rotary axis of a record.
#[derive(Clone, Debug, PartialEq)]
pub struct RotaryAxis {
    /// `$TC_CARR35/36`: the channel axis name (empty when not given).
    pub name: String,
    /// `$TC_CARR7..9` / `10..12` as entered (zero: the axis does not exist).
    pub vector: Vector3<f64>,
    /// `$TC_CARR24/25` (+ `64/65` with fine offsets): the axis position of
    /// the initial state. sinuprep takes machine position = model angle +
    /// offset (the manuals leave the sign open).
    pub offset: f64,
    pub hirth: Option<Hirth>,
    /// `$TC_CARR30/32`, `31/33`: minimum and maximum position; `None` when
    /// both are 0 (no limit, as the control reads it).
    pub limits: Option<(f64, f64)>,
    /// `$TC_CARR13/14`: the axis's specified angle, which the control takes
    /// where no channel axis is referenced (`$TC_CARR21/22`); offline, the
    /// axis's position before a swivel (0 unless given).
    pub angle: f64,
}

/// An axis for the tests: `name` turning about `vector`, with no offset,
/// Hirth grid, limits or specified angle.
#[cfg(test)]
impl RotaryAxis {
    pub(crate) fn along(name: &str, vector: [f64; 3]) -> Self {
        RotaryAxis {
            name: name.into(),
            vector: Vector3::from(vector),
            offset: 0.0,
            hirth: None,
            limits: None,
            angle: 0.0,
        }
    }
}

impl RotaryAxis {
    pub fn exists(&self) -> bool {
        self.vector.norm() > 0.0
    }

    /// The axis's name for reports: `$TC_CARR35/36`, or `axis 1`/`axis 2`.
    pub fn label(&self, index: usize) -> String {
        if self.name.is_empty() {
            format!("axis {}", index + 1)
        } else {
            self.name.clone()
        }
    }
}

/// A swivel data record.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The record's number `m` of `$TC_CARRn[m]`.
    pub number: u32,
    /// `$TC_CARR34`: the name CYCLE800's `_TC` gives.
    pub name: String,
    pub kinematics: Kinematics,
    /// l1..l4 (`$TC_CARR1..6`, `15..20`), fine offsets added when asked.
    pub offsets: [Vector3<f64>; 4],
    pub axes: [RotaryAxis; 2],
    /// `$TC_CARR37`: CYCLE800's options in decimal digits.
    pub options: u64,
    /// Which axis `_DIR` refers to (0 or 1); `None`: the one the solver
    /// picks ([`Record::direction_reference`]).
    pub direction_axis: Option<usize>,
}

/// The largest axis limit (`$TC_CARR30..33`, degrees) a record may give.
/// Siemens documents no range for them (REAL); the control's own software
/// limit switches (MD36100/36110) default to ±1e8, its way of saying "no
/// limit", so a limit past that is a typo or garbage, and no real axis's.
/// Bounding it also keeps the placement and the table's search exact: at
/// 1e8 two neighbouring doubles lie 1.5e-8 degrees apart.
pub const LIMIT_BOUND_DEG: f64 = 1e8;

/// A record that cannot describe a machine: the solver refuses it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RecordError {
    #[error("rotary axis 1 has no direction vector ($TC_CARR7..9 are 0)")]
    NoFirstAxis,
    #[error("mixed kinematics (\"M\") needs two rotary axes; axis 2 has no direction vector ($TC_CARR10..12)")]
    MixedWithOneAxis,
    #[error("the two rotary axes are parallel: together they turn about one direction only")]
    ParallelAxes,
    #[error("{axis}: its {which} position {value:e} is no rotary axis's (beyond ±{LIMIT_BOUND_DEG:e} degrees)")]
    LimitBeyondBound {
        axis: String,
        /// 0 or 1.
        index: usize,
        /// "minimum" (`$TC_CARR30/31`) or "maximum" (`32/33`).
        which: &'static str,
        value: f64,
    },
    #[error("{axis}: its minimum position {min} is above its maximum {max}")]
    LimitsReversed {
        axis: String,
        /// 0 or 1.
        index: usize,
        min: f64,
        max: f64,
    },
    #[error("{axis}: its Hirth increment {increment} is negative")]
    NegativeHirth {
        axis: String,
        /// 0 or 1.
        index: usize,
        increment: f64,
    },
}

impl Record {
    /// How many rotary axes the record has (1 or 2 once [`Self::check`] passes).
    pub fn axis_count(&self) -> usize {
        self.axes.iter().filter(|a| a.exists()).count()
    }

    /// What makes the record unusable, or `Ok`.
    pub fn check(&self) -> Result<(), RecordError> {
        let [first, second] = &self.axes;
        if !first.exists() {
            return Err(RecordError::NoFirstAxis);
        }
        if self.kinematics == Kinematics::Mixed && !second.exists() {
            return Err(RecordError::MixedWithOneAxis);
        }
        if second.exists() {
            let cosine = first.vector.normalize().dot(&second.vector.normalize());
            if 1.0 - cosine.abs() < 1e-12 {
                return Err(RecordError::ParallelAxes);
            }
        }
        for (index, axis) in self.axes.iter().enumerate() {
            if let Some((min, max)) = axis.limits {
                for (which, value) in [("minimum", min), ("maximum", max)] {
                    if value.is_nan() || value.abs() > LIMIT_BOUND_DEG {
                        return Err(RecordError::LimitBeyondBound {
                            axis: axis.label(index),
                            index,
                            which,
                            value,
                        });
                    }
                }
                if min > max {
                    return Err(RecordError::LimitsReversed {
                        axis: axis.label(index),
                        index,
                        min,
                        max,
                    });
                }
            }
            if let Some(hirth) = axis.hirth {
                if hirth.increment < 0.0 {
                    return Err(RecordError::NegativeHirth {
                        axis: axis.label(index),
                        index,
                        increment: hirth.increment,
                    });
                }
            }
        }
        Ok(())
    }

    /// The axes' positions before a swivel, as offline they are known: their
    /// specified angles (`$TC_CARR13/14`).
    pub fn specified(&self) -> [f64; 2] {
        [self.axes[0].angle, self.axes[1].angle]
    }

    /// The axis whose lower or higher position `_DIR` selects: as given, or
    /// else the axis that tilts the tool, i.e. the one less parallel to the
    /// tool's base direction +Z (a C-A head: A; an A-C table: A; a B head
    /// over a C table: B, as the Operating Manual's example of `_DIR` has
    /// it; a nutating head: its inclined axis). `$TC_CARR37`'s digit for it
    /// is not documented publicly, so it is not read from there.
    pub fn direction_reference(&self) -> usize {
        if let Some(axis) = self.direction_axis {
            return axis.min(1);
        }
        if self.axis_count() < 2 {
            return 0;
        }
        let along_z = |axis: &RotaryAxis| axis.vector.normalize().z.abs();
        if along_z(&self.axes[1]) < along_z(&self.axes[0]) {
            1
        } else {
            0
        }
    }
}
