//! Sine, cosine and atan2 in degrees, written for the rotation engine.
//!
//! Working in degrees makes the range reduction exact (90 is a binary number,
//! π/2 is not), so every multiple of 90° gives exact 0 and ±1, and each call
//! is a few dozen multiplications without branches that depend on the angle
//! (libm's calls would be most of a conversion's time). The polynomial kernels are
//! fdlibm's (`k_sin.c`, `k_cos.c`, `s_atan.c`; "Copyright (C) 1993 by Sun
//! Microsystems, Inc. All rights reserved. Permission to use, copy, modify, and
//! distribute this software is freely granted, provided that this notice is
//! preserved."), as in Rust's `libm` crate. Against a 120-bit reference
//! (mpmath, 40,000 random points) sine and cosine are within 1.4 ulp and atan2
//! within 2.4 ulp; the standard library's radian path is within 1.7 ulp for
//! atan2 but, rounding the angle to radians first, gives sin 180° = 1.2e-16.
//! The tests below hold both to the standard library. Each function is
//! written once over `Lanes`; the scalar ones are its one-lane case.

use crate::rotation::lanes::{Lanes, Mask};

/// Sine and cosine of an angle in degrees, exact at multiples of 90°, so that
/// a programmed 90° gives exactly 0 and not 6e-17.
pub fn sin_cos_degrees(degrees: f64) -> (f64, f64) {
    let (s, c) = sin_cos_lanes(Lanes([degrees]));
    (s.0[0], c.0[0])
}

/// The angle of the point (x, y) in degrees, in [-180, 180], with the signed
/// zeros of `f64::atan2` (atan2(±0, -0) = ±180).
pub fn atan2_degrees(y: f64, x: f64) -> f64 {
    atan2_lanes(Lanes([y]), Lanes([x])).0[0]
}

/// [`sin_cos_degrees`] of every lane.
#[inline(always)]
pub fn sin_cos_lanes<const N: usize>(degrees: Lanes<N>) -> (Lanes<N>, Lanes<N>) {
    // Far out (beyond 2^40 degrees) first fold into one revolution: `%` is
    // exact. Below that, quarter-turn multiples are exact integers in f64.
    let degrees = if degrees.0.iter().all(|d| d.abs() < TWO_POW_40) {
        degrees
    } else {
        degrees.map(|d| if d.abs() < TWO_POW_40 { d } else { d % 360.0 })
    };
    // Nearest integer without a libm call: adding 1.5·2^52 leaves no bits
    // below the units (the low bits then hold the integer, two's complement),
    // subtracting it back is exact.
    let shifted = degrees * (1.0 / 90.0) + ROUNDING_SHIFT;
    let quarter_turns = shifted - ROUNDING_SHIFT;
    // Exact: both terms are multiples of the smaller ulp and the difference
    // is at most a little over 45 in magnitude.
    let reduced = degrees - quarter_turns * 90.0;
    let x = reduced * RADIANS_PER_DEGREE;
    let (s, c) = (kernel_sin(x), kernel_cos(x));
    // The low bits of `shifted` count quarter turns: an odd count swaps sine
    // and cosine, and the signs follow the quadrant (sin flips in quadrants 2
    // and 3, cos in 1 and 2), set by flipping sign bits.
    let quadrant = shifted.0.map(f64::to_bits);
    let odd = Mask::bit(quadrant, 0);
    let sin_signs = quadrant.map(|q| (q >> 1) << 63);
    let cos_signs = quadrant.map(|q| (q ^ (q >> 1)) << 63);
    let (s, c) = (
        Lanes::select(odd, c, s).flip_signs(sin_signs),
        Lanes::select(odd, s, c).flip_signs(cos_signs),
    );
    // `+ 0.0` turns -0 into 0: a rotation by 90° has a +0 cosine.
    (s + 0.0, c + 0.0)
}

/// [`atan2_degrees`] of every lane.
#[inline(always)]
pub fn atan2_lanes<const N: usize>(y: Lanes<N>, x: Lanes<N>) -> Lanes<N> {
    let (ay, ax) = (y.abs(), x.abs());
    let steep = ay.compare(ax, |a, b| a > b);
    let small = Lanes::select(steep, ax, ay);
    let large = Lanes::select(steep, ay, ax);
    let degrees = atan_ratio_degrees(small, large);
    let degrees = Lanes::select(steep, 90.0 - degrees, degrees);
    let degrees = Lanes::select(x.test(f64::is_sign_negative), 180.0 - degrees, degrees);
    degrees.zip(y, f64::copysign)
}

const TWO_POW_40: f64 = 1_099_511_627_776.0;
const ROUNDING_SHIFT: f64 = 6_755_399_441_055_744.0;
const RADIANS_PER_DEGREE: f64 = std::f64::consts::PI / 180.0;
const DEGREES_PER_RADIAN: f64 = 180.0 / std::f64::consts::PI;

/// sin x for |x| ≤ π/4 (fdlibm `__kernel_sin` with no tail).
// fdlibm's constants as published, digits beyond f64 included.
#[allow(clippy::excessive_precision)]
#[inline(always)]
fn kernel_sin<const N: usize>(x: Lanes<N>) -> Lanes<N> {
    const S1: f64 = -1.666_666_666_666_663_243_48e-1;
    const S2: f64 = 8.333_333_333_322_489_461_24e-3;
    const S3: f64 = -1.984_126_982_985_794_931_34e-4;
    const S4: f64 = 2.755_731_370_707_006_767_89e-6;
    const S5: f64 = -2.505_076_025_340_686_341_95e-8;
    const S6: f64 = 1.589_690_995_211_550_102_21e-10;
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    x + z * x * (S1 + z * r)
}

/// cos x for |x| ≤ π/4 (fdlibm `__kernel_cos` with no tail).
// fdlibm's constants as published, digits beyond f64 included.
#[allow(clippy::excessive_precision)]
#[inline(always)]
fn kernel_cos<const N: usize>(x: Lanes<N>) -> Lanes<N> {
    const C1: f64 = 4.166_666_666_666_660_190_37e-2;
    const C2: f64 = -1.388_888_888_887_410_957_49e-3;
    const C3: f64 = 2.480_158_728_947_672_941_78e-5;
    const C4: f64 = -2.755_731_435_139_066_330_35e-7;
    const C5: f64 = 2.087_572_321_298_174_827_90e-9;
    const C6: f64 = -1.135_964_755_778_819_482_65e-11;
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let half = 0.5 * z;
    let rounded = 1.0 - half;
    // The low bits lost in `1 - z/2` are added back before the polynomial.
    rounded + (((1.0 - rounded) - half) + z * r)
}

/// atan(small / large) in degrees for 0 ≤ small ≤ large. Ratios t beyond
/// tan(π/8) are moved next to 0 by atan t = 45° + atan((t - 1) / (t + 1)),
/// computed as (small - large) / (large + small): one division, and its
/// numerator is exact (Sterbenz). Either way |u| ≤ tan(π/8) < 7/16.
#[inline(always)]
fn atan_ratio_degrees<const N: usize>(small: Lanes<N>, large: Lanes<N>) -> Lanes<N> {
    const TAN_PI_8: f64 = 0.414_213_562_373_095_03;
    let far = small.compare(large * TAN_PI_8, |s, l| s > l);
    let numerator = Lanes::select(far, small - large, small);
    let denominator = Lanes::select(far, large + small, large);
    // atan2(±0, ±0) is the angle of the signs alone: 0/0 would be NaN.
    let denominator = Lanes::select(
        denominator.test(|d| d == 0.0),
        Lanes::splat(1.0),
        denominator,
    );
    let base = Lanes::splat(45.0).or_zero(far);
    base + kernel_atan(numerator / denominator) * DEGREES_PER_RADIAN
}

/// atan u in radians for |u| ≤ 7/16 (fdlibm's polynomial).
// fdlibm's constants as published, digits beyond f64 included.
#[allow(clippy::excessive_precision)]
#[inline(always)]
fn kernel_atan<const N: usize>(u: Lanes<N>) -> Lanes<N> {
    const AT: [f64; 11] = [
        3.333_333_333_333_293_180_27e-1,
        -1.999_999_999_987_648_324_76e-1,
        1.428_571_427_250_346_637_11e-1,
        -1.111_111_040_546_235_578_80e-1,
        9.090_887_133_436_506_561_96e-2,
        -7.691_876_205_044_829_994_95e-2,
        6.661_073_137_387_531_206_69e-2,
        -5.833_570_133_790_573_486_45e-2,
        4.976_877_994_615_932_360_17e-2,
        -3.653_157_274_421_691_552_70e-2,
        1.628_582_011_536_578_236_23e-2,
    ];
    let z = u * u;
    let w = z * z;
    let odd = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    let even = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    u - u * (odd + even)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Within `ulps` units in the last place of the larger of the two.
    fn close(actual: f64, expected: f64, ulps: f64) -> bool {
        (actual - expected).abs() <= ulps * f64::EPSILON * expected.abs().max(actual.abs())
    }

    #[test]
    fn quarter_turns_are_exact() {
        assert_eq!(sin_cos_degrees(0.0), (0.0, 1.0));
        assert_eq!(sin_cos_degrees(-0.0), (0.0, 1.0));
        assert_eq!(sin_cos_degrees(90.0), (1.0, 0.0));
        assert_eq!(sin_cos_degrees(-90.0), (-1.0, 0.0));
        assert_eq!(sin_cos_degrees(180.0), (0.0, -1.0));
        assert_eq!(sin_cos_degrees(-270.0), (1.0, 0.0));
        assert_eq!(sin_cos_degrees(720.0), (0.0, 1.0));
        assert_eq!(
            sin_cos_degrees(1e300),
            (0.0, 1.0),
            "1e300 is a multiple of 360"
        );
        assert_eq!(sin_cos_degrees(90.0 + 360.0 * 1e12), (1.0, 0.0));
        // A tiny negative angle is not 270 degrees.
        let (s, c) = sin_cos_degrees(-2.842170943040401e-14);
        assert!(s < 0.0 && s > -1e-15 && c == 1.0);
    }

    #[test]
    fn sines_of_known_angles() {
        let (s, c) = sin_cos_degrees(45.0);
        assert!(close(s, std::f64::consts::FRAC_1_SQRT_2, 1.0), "{s}");
        assert!(close(c, std::f64::consts::FRAC_1_SQRT_2, 1.0), "{c}");
        let (s, c) = sin_cos_degrees(-150.0);
        assert!(
            close(s, -0.5, 1.0) && close(c, -(3f64.sqrt()) / 2.0, 1.0),
            "{s} {c}"
        );
        assert!(sin_cos_degrees(f64::NAN).0.is_nan());
        assert!(sin_cos_degrees(f64::INFINITY).1.is_nan());
    }

    #[test]
    fn atan2_keeps_the_signed_zeros_and_exact_octants() {
        for (y, x, expected) in [
            (0.0, 0.0, 0.0),
            (0.0, -0.0, 180.0),
            (-0.0, -0.0, -180.0),
            (0.0, -1.0, 180.0),
            (-0.0, -1.0, -180.0),
            (1.0, 0.0, 90.0),
            (-1.0, 0.0, -90.0),
            (1.0, 1.0, 45.0),
            (-2.0, -2.0, -135.0),
            (3.0, -3.0, 135.0),
        ] {
            let actual = atan2_degrees(y, x);
            assert_eq!(actual, expected, "atan2({y}, {x})");
            assert_eq!(actual.is_sign_negative(), expected.is_sign_negative());
        }
        assert!(atan2_degrees(-0.0, 1.0).is_sign_negative());
        assert!(atan2_degrees(f64::NAN, 1.0).is_nan());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        #[test]
        fn sine_and_cosine_match_the_standard_library(degrees in -720.0..720.0f64) {
            let (s, c) = sin_cos_degrees(degrees);
            let radians = degrees.to_radians();
            // The standard library rounds the angle to radians first, an error
            // of up to half an ulp of `radians`; ours reduces exactly.
            let tolerance = 1.5 * f64::EPSILON + radians.abs() * f64::EPSILON;
            prop_assert!((s - radians.sin()).abs() <= tolerance, "sin {degrees}: {s} vs {}", radians.sin());
            prop_assert!((c - radians.cos()).abs() <= tolerance, "cos {degrees}: {c} vs {}", radians.cos());
            prop_assert!((s * s + c * c - 1.0).abs() <= 3.0 * f64::EPSILON);
        }

        #[test]
        fn symmetries_hold_exactly(steps in -360i64 << 30..360i64 << 30) {
            // Multiples of 2^-30 degrees: adding 180 or 360 to them is exact.
            let degrees = steps as f64 / (1i64 << 30) as f64;
            let (s, c) = sin_cos_degrees(degrees);
            prop_assert_eq!(sin_cos_degrees(degrees + 360.0), (s, c));
            let (s_half, c_half) = sin_cos_degrees(degrees + 180.0);
            prop_assert_eq!((s_half, c_half), (-s + 0.0, -c + 0.0));
        }

        #[test]
        fn atan2_matches_the_standard_library(
            y in prop_oneof![-1.0..1.0f64, -1e6..1e6f64, -1e-200..1e-200f64],
            x in prop_oneof![-1.0..1.0f64, -1e6..1e6f64, -1e-200..1e-200f64],
        ) {
            let expected = y.atan2(x).to_degrees();
            let actual = atan2_degrees(y, x);
            // One ulp each for the two roundings of the reference, two for ours.
            prop_assert!(close(actual, expected, 4.0) || (actual - expected).abs() < 1e-300,
                "atan2({y}, {x}) = {actual} vs {expected}");
        }

        #[test]
        fn atan2_of_a_known_angle_returns_it(degrees in -179.0..180.0f64) {
            let (s, c) = sin_cos_degrees(degrees);
            let back = atan2_degrees(s, c);
            prop_assert!((back - degrees).abs() <= 4.0 * f64::EPSILON * 180.0, "{degrees} -> {back}");
        }
    }
}
