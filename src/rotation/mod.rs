//! Rotation mathematics for CYCLE600: sequences, trigonometry in degrees,
//! angles <-> matrices (one conversion at a time or many side by side),
//! frames.
//!
//! Pure functions on nalgebra. No spans, no syntax types, no printing: the
//! conventions are those of `spec/cycle600.md` sections 2-4 (right-handed
//! elemental rotations, angles in degrees, intrinsic R = R_a·R_b·R_c and
//! extrinsic R = R_c·R_b·R_a).

pub mod euler;
pub mod frame;
pub mod lanes;
pub mod sequence;
pub mod trig;

pub use euler::{decompose, matrix, Angles, Decomposition};
pub use frame::Frame;
pub use sequence::{Axis, Kind, Sequence, SequenceError};

use euler::{decompose_lanes, matrix_lanes, rotation_of_lane};
use lanes::Lanes;
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

/// [`convert`] of many angle triples, computed eight side by side (see
/// `lanes`): the same results, bit for bit, about twice as fast.
pub fn convert_all(from: Sequence, angles: &[Angles], to: Sequence) -> Vec<Conversion> {
    const LANES: usize = 8;
    let mut conversions = Vec::with_capacity(angles.len());
    for chunk in angles.chunks(LANES) {
        // A short last chunk is padded with zero angles, computed and dropped.
        let lane_angles = [0, 1, 2].map(|n| {
            Lanes(std::array::from_fn::<f64, LANES, _>(|lane| {
                chunk.get(lane).map_or(0.0, |angles| angles[n])
            }))
        });
        let rows = matrix_lanes(from, lane_angles);
        let outputs = decompose_lanes(to, &rows);
        conversions.extend(
            outputs
                .iter()
                .take(chunk.len())
                .enumerate()
                .map(|(lane, &output)| Conversion {
                    matrix: rotation_of_lane(&rows, lane),
                    output,
                }),
        );
    }
    conversions
}
