//! Rotation mathematics for CYCLE600: sequences, trigonometry in degrees,
//! angles <-> matrices (one conversion at a time or many side by side),
//! frames, and the other forms a rotation is written in (quaternion, axis
//! and angle, Gibbs vector, a post-processor's matrix, a tool-to-piece chain).
//!
//! Pure functions on nalgebra. No spans, no syntax types, no printing: the
//! conventions are those of `spec/cycle600.md` sections 2-4 (right-handed
//! elemental rotations, angles in degrees, intrinsic R = R_a·R_b·R_c and
//! extrinsic R = R_c·R_b·R_a).

pub(crate) mod batch;
pub mod euler;
pub mod forms;
pub mod frame;
pub(crate) mod lanes;
pub mod sequence;
pub mod trig;

pub use batch::convert_all;
pub use euler::{decompose, matrix, Angles, Decomposition};
pub use sequence::{Axis, Kind, Sequence, SequenceError};

use nalgebra::Rotation3;

/// Angles of one sequence converted into another.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conversion {
    pub matrix: Rotation3<f64>,
    pub output: Decomposition,
}

/// Builds the rotation from `angles` in `from` and reads it back in `to`.
pub fn convert(from: Sequence, angles: Angles, to: Sequence) -> Conversion {
    let matrix = matrix(from, angles);
    Conversion {
        matrix,
        output: decompose(to, &matrix),
    }
}
