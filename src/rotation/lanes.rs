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

/// One yes/no per lane.
pub type Mask<const N: usize> = [bool; N];

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
        self.0.map(f)
    }

    #[inline(always)]
    pub fn compare(self, other: Self, f: impl Fn(f64, f64) -> bool) -> Mask<N> {
        array::from_fn(|lane| f(self.0[lane], other.0[lane]))
    }

    /// `yes` where `mask` holds, `no` elsewhere.
    #[inline(always)]
    pub fn select(mask: Mask<N>, yes: Self, no: Self) -> Self {
        Lanes(array::from_fn(|lane| {
            if mask[lane] {
                yes.0[lane]
            } else {
                no.0[lane]
            }
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
