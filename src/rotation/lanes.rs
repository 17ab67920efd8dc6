//! `N` numbers computed side by side, so that the rotation engine is written
//! once and runs one conversion at a time (`N = 1`) or many (`N = 8`).
//!
//! Every operation is a plain loop over a fixed-size array; the compiler turns
//! those into vector instructions (two or four lanes at a time, whatever the
//! target has) without `unsafe` or platform intrinsics. Lane-dependent
//! decisions are selects, not branches, so unpredictable angles cost nothing.

use std::array;
use std::ops::{Add, Div, Mul, Neg, Sub};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanes<const N: usize>(pub [f64; N]);

/// One yes/no per lane, as all bits set or clear: the form a vector compare
/// produces and a bitwise select consumes, so masks never leave the vector
/// registers (a `[bool; N]` cost a pack and an unpack per select).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mask<const N: usize>([u64; N]);

impl<const N: usize> Mask<N> {
    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> bool) -> Self {
        Mask(array::from_fn(|lane| if f(lane) { u64::MAX } else { 0 }))
    }

    /// Lanes whose `bit` (0 = lowest) is set in `bits`.
    #[inline(always)]
    pub fn bit(bits: [u64; N], bit: u32) -> Self {
        Mask(bits.map(|b| ((b >> bit) & 1).wrapping_neg()))
    }

    #[inline(always)]
    pub fn lane(self, lane: usize) -> bool {
        self.0[lane] != 0
    }
}

impl<const N: usize> Lanes<N> {
    #[inline(always)]
    pub fn splat(value: f64) -> Self {
        Lanes([value; N])
    }

    #[inline(always)]
    pub fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Lanes(self.0.map(f))
    }

    #[inline(always)]
    pub fn zip(self, other: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        Lanes(array::from_fn(|lane| f(self.0[lane], other.0[lane])))
    }

    #[inline(always)]
    pub fn test(self, f: impl Fn(f64) -> bool) -> Mask<N> {
        Mask::from_fn(|lane| f(self.0[lane]))
    }

    #[inline(always)]
    pub fn compare(self, other: Self, f: impl Fn(f64, f64) -> bool) -> Mask<N> {
        Mask::from_fn(|lane| f(self.0[lane], other.0[lane]))
    }

    /// `yes` where `mask` holds, `no` elsewhere.
    #[inline(always)]
    pub fn select(mask: Mask<N>, yes: Self, no: Self) -> Self {
        Lanes(array::from_fn(|lane| {
            let m = mask.0[lane];
            f64::from_bits((yes.0[lane].to_bits() & m) | (no.0[lane].to_bits() & !m))
        }))
    }

    /// `self` where `mask` holds, +0 elsewhere.
    #[inline(always)]
    pub fn or_zero(self, mask: Mask<N>) -> Self {
        Lanes(array::from_fn(|lane| {
            f64::from_bits(self.0[lane].to_bits() & mask.0[lane])
        }))
    }

    /// Each lane's bits XOR `signs`' (`1 << 63` negates the lane).
    #[inline(always)]
    pub fn flip_signs(self, signs: [u64; N]) -> Self {
        Lanes(array::from_fn(|lane| {
            f64::from_bits(self.0[lane].to_bits() ^ signs[lane])
        }))
    }

    #[inline(always)]
    pub fn sqrt(self) -> Self {
        self.map(f64::sqrt)
    }

    #[inline(always)]
    pub fn abs(self) -> Self {
        self.map(f64::abs)
    }
}

macro_rules! lane_operator {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const N: usize> $trait for Lanes<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                self.zip(other, |a, b| a $op b)
            }
        }

        impl<const N: usize> $trait<f64> for Lanes<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: f64) -> Self {
                self.map(|a| a $op other)
            }
        }

        impl<const N: usize> $trait<Lanes<N>> for f64 {
            type Output = Lanes<N>;
            #[inline(always)]
            fn $method(self, other: Lanes<N>) -> Lanes<N> {
                other.map(|b| self $op b)
            }
        }
    };
}

lane_operator!(Add, add, +);
lane_operator!(Sub, sub, -);
lane_operator!(Mul, mul, *);
lane_operator!(Div, div, /);

impl<const N: usize> Neg for Lanes<N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|a| -a)
    }
}
