//! [`Lanes`], the lane type of the SIMD kernels: `W` numbers with lane-wise operations.

use std::ops::{Add, Mul, Neg, Sub};

/// The same quantity of `W` independent elements (strips, bushings, bodies): two fill an SSE2
/// register, four an AVX one. Every operation is lane by lane, one IEEE operation per lane, as
/// loops over the array: the compiler turns them into packed instructions of the width the
/// copy it compiles has (see the module `simd`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Lanes<const W: usize>(pub(crate) [f64; W]);

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const W: usize> $trait for Lanes<W> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                self.map2(rhs, |a, b| a $op b)
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);

impl<const W: usize> Neg for Lanes<W> {
    type Output = Self;
    /// −x lane by lane (exact: the sign bit flipped, as the scalar `-x`).
    #[inline(always)]
    fn neg(self) -> Self {
        let mut out = self.0;
        for o in &mut out {
            *o = -*o;
        }
        Self(out)
    }
}

impl<const W: usize> Lanes<W> {
    #[inline(always)]
    pub(crate) fn splat(v: f64) -> Self {
        Self([v; W])
    }
    /// Lane by lane `f(self, rhs)`.
    #[inline(always)]
    pub(crate) fn map2(self, rhs: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        let mut out = self.0;
        for (o, r) in out.iter_mut().zip(rhs.0) {
            *o = f(*o, r);
        }
        Self(out)
    }
    #[inline(always)]
    pub(crate) fn div(self, rhs: Self) -> Self {
        self.map2(rhs, |a, b| a / b)
    }
    #[inline(always)]
    pub(crate) fn sqrt(self) -> Self {
        let mut out = self.0;
        for o in &mut out {
            *o = o.sqrt();
        }
        Self(out)
    }
    #[inline(always)]
    pub(crate) fn max(self, floor: Self) -> Self {
        self.map2(floor, f64::max)
    }
    #[inline(always)]
    pub(crate) fn min(self, cap: Self) -> Self {
        self.map2(cap, f64::min)
    }
    /// Whether every lane is at most `cap`'s.
    #[inline(always)]
    pub(crate) fn all_le(self, cap: Self) -> bool {
        self.0.iter().zip(cap.0).all(|(&a, b)| a <= b)
    }
    /// Whether every lane is above `floor`'s.
    #[inline(always)]
    pub(crate) fn all_gt(self, floor: Self) -> bool {
        self.0.iter().zip(floor.0).all(|(&a, b)| a > b)
    }
    #[inline(always)]
    pub(crate) fn clamp(self, lo: f64, hi: f64) -> Self {
        let mut out = self.0;
        for o in &mut out {
            *o = o.clamp(lo, hi);
        }
        Self(out)
    }
}

/// A number or a set of lanes of numbers: what the 3-vector algebra of `kinematics` is written
/// over, so that one source serves one element (`f64`) and `W` elements in lockstep
/// ([`Lanes`]), each lane doing the scalar operations in the scalar order.
pub(crate) trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
}

impl Real for f64 {}

impl<const W: usize> Real for Lanes<W> {}
