//! FASTSIM's strip integration, two strips per SIMD register (four with AVX).
//!
//! Strips are independent, so the elements of several strips are integrated in lockstep. Written
//! as arrays of strips, the compiler packed each strip's (p_x, p_y) pair into one register and
//! took the square root and the division of every strip one at a time (`sqrtsd`, `divsd`): the
//! serial chain that bounds FASTSIM's cost. Here a value of two strips is one `Lanes<2>`, whose
//! lane-wise operations the compiler turns into packed ones (`sqrtpd`, `divpd` with SSE2, the
//! x86_64 baseline); where the processor has AVX (detected at run time) four strips are one
//! `Lanes<4>` (`vsqrtpd`, `vdivpd` on 256-bit registers). Every lane does the scalar code's IEEE operations in the scalar code's order
//! (no fused multiply-add, no reordering), so the forces are bit for bit those of one strip at a
//! time, on any machine.

use std::ops::{Add, Mul, Sub};

/// The same quantity of `W` strips: two fill an SSE2 register, four an AVX one (also FaStrip's
/// march, `fastrip_lanes`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Lanes<const W: usize>(pub(super) [f64; W]);

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

impl<const W: usize> Lanes<W> {
    #[inline(always)]
    pub(super) fn splat(v: f64) -> Self {
        Self([v; W])
    }
    /// Lane by lane `f(self, rhs)`.
    #[inline(always)]
    pub(super) fn map2(self, rhs: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        let mut out = self.0;
        for (o, r) in out.iter_mut().zip(rhs.0) {
            *o = f(*o, r);
        }
        Self(out)
    }
    #[inline(always)]
    pub(super) fn div(self, rhs: Self) -> Self {
        self.map2(rhs, |a, b| a / b)
    }
    #[inline(always)]
    pub(super) fn sqrt(self) -> Self {
        let mut out = self.0;
        for o in &mut out {
            *o = o.sqrt();
        }
        Self(out)
    }
    #[inline(always)]
    pub(super) fn max(self, floor: Self) -> Self {
        self.map2(floor, f64::max)
    }
    #[inline(always)]
    pub(super) fn min(self, cap: Self) -> Self {
        self.map2(cap, f64::min)
    }
    /// Whether every lane is at most `cap`'s.
    #[inline(always)]
    pub(super) fn all_le(self, cap: Self) -> bool {
        self.0.iter().zip(cap.0).all(|(&a, b)| a <= b)
    }
    #[inline(always)]
    pub(super) fn clamp(self, lo: f64, hi: f64) -> Self {
        let mut out = self.0;
        for o in &mut out {
            *o = o.clamp(lo, hi);
        }
        Self(out)
    }
}

/// |p|² ≤ bound²·this is inside the bound whatever the rounding (of the square, the root and the
/// division, each within 2⁻⁵³ relative): |p|/bound ≤ 1 − 5e-13 + 3e-16 < 1, so bound/|p| rounds to
/// at least 1 and the projection's scale min(1, bound/|p|) is exactly 1.
pub(super) const INSIDE_BOUND: f64 = 1.0 - 1e-12;

/// Pairs of lanes integrated together: every element step of all of them is independent, which
/// hides the latency of the square root and the division.
pub(super) const PAIRS: usize = 5;
/// Strips of one pass.
const STRIPS: usize = 2 * PAIRS;
/// Groups of four lanes of the AVX pass: the ten strips padded to twelve with empty strips.
const QUADS: usize = STRIPS.div_ceil(4);

/// The per-strip inputs of one lockstep pass, `2·PAIRS` strips (SI units as in `fastsim`).
#[derive(Debug, Clone, Copy)]
pub(super) struct StripInputs {
    /// Strip half-length a_j, m.
    pub a_j: [f64; 2 * PAIRS],
    /// Slope of p_x along the strip, ξ/L1 − φ·y_j/L3, Pa/m.
    pub slope_x: [f64; 2 * PAIRS],
    /// Traction bound at the strip's centre line, μ·p_n / shape_k, Pa.
    pub bound: [f64; 2 * PAIRS],
}

/// Per-strip sums: Σ p_x, Σ p_y and Σ x·p_y over the elements (Pa, Pa, Pa·m).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct StripSums {
    pub sx: [f64; 2 * PAIRS],
    pub sy: [f64; 2 * PAIRS],
    pub sxpy: [f64; 2 * PAIRS],
}

/// Integrates the strips of `inputs` over `elements` (`(x_k/a_j, p_n shape factor)` from the
/// leading edge); p_y's slope is `eta_l2 + φ·x·inv_l3` with `eta_l2 = η/L2` (Pa/m), spin φ
/// (1/m) and `inv_l3 = 1/L3` (Pa/m). On a processor with AVX four strips share a register
/// (checked once at run time, then a cached flag); the bits are the same either way.
#[inline(always)]
pub(super) fn integrate_strips(
    inputs: &StripInputs,
    elements: &[(f64, f64)],
    eta_l2: f64,
    phi: f64,
    inv_l3: f64,
) -> StripSums {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the processor has just been found to support AVX, the only feature the
        // function enables.
        return unsafe { integrate_strips_avx(inputs, elements, eta_l2, phi, inv_l3) };
    }
    integrate_strips_sse2(inputs, elements, eta_l2, phi, inv_l3)
}

/// [`integrate_strips`] two strips per register (the x86_64 baseline, SSE2).
#[inline(always)]
fn integrate_strips_sse2(
    inputs: &StripInputs,
    elements: &[(f64, f64)],
    eta_l2: f64,
    phi: f64,
    inv_l3: f64,
) -> StripSums {
    let (sx, sy, sxpy) = integrate::<2, PAIRS, STRIPS>(
        &inputs.a_j,
        &inputs.slope_x,
        &inputs.bound,
        elements,
        (eta_l2, phi, inv_l3),
    );
    StripSums { sx, sy, sxpy }
}

/// [`integrate_strips`] four strips per register; the two padding strips are empty (a_j = 0,
/// bound 0: their tractions stay 0) and dropped.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn integrate_strips_avx(
    inputs: &StripInputs,
    elements: &[(f64, f64)],
    eta_l2: f64,
    phi: f64,
    inv_l3: f64,
) -> StripSums {
    let pad = |a: &[f64; STRIPS]| -> [f64; 4 * QUADS] {
        std::array::from_fn(|l| if l < STRIPS { a[l] } else { 0.0 })
    };
    let sums = integrate::<4, QUADS, { 4 * QUADS }>(
        &pad(&inputs.a_j),
        &pad(&inputs.slope_x),
        &pad(&inputs.bound),
        elements,
        (eta_l2, phi, inv_l3),
    );
    let cut = |a: [f64; 4 * QUADS]| -> [f64; STRIPS] { std::array::from_fn(|l| a[l]) };
    StripSums {
        sx: cut(sums.0),
        sy: cut(sums.1),
        sxpy: cut(sums.2),
    }
}

/// Per-strip sums (Σ p_x, Σ p_y, Σ x·p_y) of `N = W·G` strips.
type Sums<const N: usize> = ([f64; N], [f64; N], [f64; N]);

/// The lockstep integration of `N = W·G` strips in `G` groups of `W` lanes; `c` is
/// `(eta_l2, phi, inv_l3)`. Every lane does the scalar code's IEEE operations in its order.
#[inline(always)]
fn integrate<const W: usize, const G: usize, const N: usize>(
    a_j: &[f64; N],
    slope_x: &[f64; N],
    bound_j: &[f64; N],
    elements: &[(f64, f64)],
    c: (f64, f64, f64),
) -> Sums<N> {
    let lanes = |a: &[f64; N]| -> [Lanes<W>; G] {
        std::array::from_fn(|p| Lanes(std::array::from_fn(|l| a[W * p + l])))
    };
    let a_j = lanes(a_j);
    let slope_x = lanes(slope_x);
    let bound_j = lanes(bound_j);
    let (eta_l2, half) = (Lanes::splat(c.0), Lanes::splat(0.5));
    let (phi, inv_l3) = (Lanes::splat(c.1), Lanes::splat(c.2));
    let (one, floor) = (Lanes::splat(1.0), Lanes::splat(f64::MIN_POSITIVE));
    let inside = Lanes::splat(INSIDE_BOUND);
    let zero = Lanes::splat(0.0);
    let mut px = [zero; G];
    let mut py = [zero; G];
    let mut sx = [zero; G];
    let mut sy = [zero; G];
    let mut sxpy = [zero; G];
    let mut x_prev = a_j;
    for &(u_k, shape_k) in elements {
        let (u_k, shape_k) = (Lanes::splat(u_k), Lanes::splat(shape_k));
        for p in 0..G {
            let x = u_k * a_j[p];
            let h = x_prev[p] - x;
            let x_mid = half * (x_prev[p] + x);
            px[p] = px[p] - h * slope_x[p];
            py[p] = py[p] - h * (eta_l2 + phi * x_mid * inv_l3);
            let bound = bound_j[p] * shape_k;
            // Projection onto the bound: scale = min(1, bound/|p|) (|p| = 0 gives 1 through the
            // tiny floor). Where every lane is inside the bound by more than rounding can move
            // |p|, the scale is exactly 1 and the root and division are skipped: the same bits
            // for a fraction of the cost in the adhesion zone, most of a tread contact.
            let norm2 = px[p] * px[p] + py[p] * py[p];
            if !norm2.all_le(bound * bound * inside) {
                let scale = bound.div(norm2.sqrt().max(floor)).min(one);
                px[p] = px[p] * scale;
                py[p] = py[p] * scale;
            }
            sx[p] = sx[p] + px[p];
            sy[p] = sy[p] + py[p];
            sxpy[p] = sxpy[p] + x * py[p];
            x_prev[p] = x;
        }
    }
    let unpack = |v: [Lanes<W>; G]| -> [f64; N] { std::array::from_fn(|l| v[l / W].0[l % W]) };
    (unpack(sx), unpack(sy), unpack(sxpy))
}

#[cfg(test)]
#[path = "fastsim_lanes_tests.rs"]
mod tests;
