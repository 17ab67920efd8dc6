//! Many conversions at once: eight side by side (see `lanes`), compiled a
//! second time for AVX2 and chosen at run time.
//!
//! The lane code is plain array arithmetic; what the compiler makes of it
//! depends on the instruction set it may use. The x86-64 baseline (SSE2) has
//! two-lane vectors and two-operand instructions, so many of a conversion's
//! instructions are register copies; with AVX2 the same source runs four
//! lanes wide with three-operand instructions. Both
//! builds compute the same IEEE operations in the same order (no fused
//! multiply-add: Rust never contracts `a * b + c`), so the results are the
//! same bit for bit on every machine.

use crate::rotation::euler::{decompose_lanes, matrix_lanes, rotation_of_lane};
use crate::rotation::lanes::Lanes;
use crate::rotation::{Angles, Conversion, Sequence};

/// [`convert`](crate::rotation::convert) of many angle triples: the same
/// results, bit for bit, two to four times as fast.
pub fn convert_all(from: Sequence, angles: &[Angles], to: Sequence) -> Vec<Conversion> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        return convert_all_avx2(from, angles, to);
    }
    convert_all_lanes(from, angles, to)
}

/// [`convert_all_lanes`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
fn convert_all_avx2(from: Sequence, angles: &[Angles], to: Sequence) -> Vec<Conversion> {
    #[target_feature(enable = "avx2")]
    unsafe fn with_avx2(from: Sequence, angles: &[Angles], to: Sequence) -> Vec<Conversion> {
        convert_all_lanes(from, angles, to)
    }
    // SAFETY: the only caller has checked that this CPU has AVX2; the
    // function is otherwise safe code.
    unsafe { with_avx2(from, angles, to) }
}

#[inline(always)]
fn convert_all_lanes(from: Sequence, angles: &[Angles], to: Sequence) -> Vec<Conversion> {
    const LANES: usize = 8;
    // Written in place into the vector's spare room: an `extend` over mapped
    // iterators was not inlined into the AVX2 build and ran as baseline code,
    // and filling the vector first wrote every conversion's 128 bytes twice
    // (a fifth of the wall time: the batch ran 19-28 instead of 25-35
    // million conversions a second).
    let mut conversions = Vec::with_capacity(angles.len());
    let mut rows = [[Lanes::<LANES>::splat(0.0); 3]; 3];
    let spare = &mut conversions.spare_capacity_mut()[..angles.len()];
    for (chunk, written) in angles.chunks(LANES).zip(spare.chunks_mut(LANES)) {
        // A short last chunk is padded with zero angles, computed and dropped.
        let mut lane_angles = [Lanes::<LANES>::splat(0.0); 3];
        for (lane, triple) in chunk.iter().enumerate() {
            for (angle, &value) in lane_angles.iter_mut().zip(triple) {
                angle.0[lane] = value;
            }
        }
        matrix_lanes(from, lane_angles, &mut rows);
        let outputs = decompose_lanes(to, &rows);
        for (lane, conversion) in written.iter_mut().enumerate() {
            conversion.write(Conversion {
                matrix: rotation_of_lane(&rows, lane),
                output: outputs[lane],
            });
        }
    }
    // SAFETY: the loop wrote each of the first `angles.len()` elements.
    #[allow(unsafe_code)]
    unsafe {
        conversions.set_len(angles.len())
    };
    conversions
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::convert;
    use proptest::prelude::*;

    /// Every number of a conversion as bits, so that -0 and 0 differ.
    fn bits(conversion: &Conversion) -> Vec<u64> {
        let output = &conversion.output;
        conversion
            .matrix
            .matrix()
            .iter()
            .chain(&output.angles)
            .chain(&output.alternative)
            .map(|x| x.to_bits())
            .chain([u64::from(output.gimbal_lock)])
            .collect()
    }

    fn angle() -> impl Strategy<Value = f64> {
        prop_oneof![
            -720.0..720.0f64,
            Just(0.0),
            Just(-0.0),
            Just(90.0),
            Just(-90.0),
            Just(180.0),
            (-90.0f64..90.0).prop_map(|x| x * 1e-9 + 90.0),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        /// Both builds (the baseline one and, on a CPU that has it, AVX2)
        /// give one-by-one conversion's results bit for bit, whatever the
        /// batch length (a short last chunk is padded).
        #[test]
        fn both_builds_equal_one_by_one_bit_for_bit(
            from in 0usize..24, to in 0usize..24,
            angles in prop::collection::vec((angle(), angle(), angle()), 0..40),
        ) {
            let all: Vec<Sequence> = Sequence::all().collect();
            let (from, to) = (all[from], all[to]);
            let angles: Vec<Angles> = angles.into_iter().map(|(a, b, c)| [a, b, c]).collect();
            let one_by_one: Vec<Vec<u64>> =
                angles.iter().map(|&a| bits(&convert(from, a, to))).collect();
            let baseline: Vec<Vec<u64>> =
                convert_all_lanes(from, &angles, to).iter().map(bits).collect();
            let dispatched: Vec<Vec<u64>> =
                convert_all(from, &angles, to).iter().map(bits).collect();
            prop_assert_eq!(&baseline, &one_by_one);
            prop_assert_eq!(&dispatched, &one_by_one);
        }
    }
}
