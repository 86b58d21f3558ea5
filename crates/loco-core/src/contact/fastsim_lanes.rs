//! FASTSIM's strip integration, two strips per SIMD register.
//!
//! Strips are independent, so the elements of several strips are integrated in lockstep. Written
//! as arrays of strips, the compiler packed each strip's (p_x, p_y) pair into one register and
//! took the square root and the division of every strip one at a time (`sqrtsd`, `divsd`): the
//! serial chain that bounds FASTSIM's cost. Here a value of two strips is one [`F64x2`], whose
//! lane-wise operations the compiler turns into packed ones (`sqrtpd`, `divpd` with SSE2, the
//! x86_64 baseline). Every lane does the scalar code's IEEE operations in the scalar code's order
//! (no fused multiply-add, no reordering), so the forces are bit for bit those of one strip at a
//! time, on any machine.

use std::ops::{Add, Mul, Sub};

/// The same quantity of two strips.
#[derive(Debug, Clone, Copy, PartialEq)]
struct F64x2([f64; 2]);

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl $trait for F64x2 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                Self([self.0[0] $op rhs.0[0], self.0[1] $op rhs.0[1]])
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);

impl F64x2 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        Self([v, v])
    }
    #[inline(always)]
    fn div(self, rhs: Self) -> Self {
        Self([self.0[0] / rhs.0[0], self.0[1] / rhs.0[1]])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Self([self.0[0].sqrt(), self.0[1].sqrt()])
    }
    #[inline(always)]
    fn max(self, floor: Self) -> Self {
        Self([self.0[0].max(floor.0[0]), self.0[1].max(floor.0[1])])
    }
    #[inline(always)]
    fn min(self, cap: Self) -> Self {
        Self([self.0[0].min(cap.0[0]), self.0[1].min(cap.0[1])])
    }
}

/// Pairs of lanes integrated together: every element step of all of them is independent, which
/// hides the latency of the square root and the division.
pub(super) const PAIRS: usize = 5;

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
/// (1/m) and `inv_l3 = 1/L3` (Pa/m).
#[inline(always)]
pub(super) fn integrate_strips(
    inputs: &StripInputs,
    elements: &[(f64, f64)],
    eta_l2: f64,
    phi: f64,
    inv_l3: f64,
) -> StripSums {
    let lanes = |a: &[f64; 2 * PAIRS]| -> [F64x2; PAIRS] {
        std::array::from_fn(|p| F64x2([a[2 * p], a[2 * p + 1]]))
    };
    let a_j = lanes(&inputs.a_j);
    let slope_x = lanes(&inputs.slope_x);
    let bound_j = lanes(&inputs.bound);
    let (eta_l2, half) = (F64x2::splat(eta_l2), F64x2::splat(0.5));
    let (phi, inv_l3) = (F64x2::splat(phi), F64x2::splat(inv_l3));
    let (one, floor) = (F64x2::splat(1.0), F64x2::splat(f64::MIN_POSITIVE));
    let zero = F64x2::splat(0.0);
    let mut px = [zero; PAIRS];
    let mut py = [zero; PAIRS];
    let mut sx = [zero; PAIRS];
    let mut sy = [zero; PAIRS];
    let mut sxpy = [zero; PAIRS];
    let mut x_prev = a_j;
    for &(u_k, shape_k) in elements {
        let (u_k, shape_k) = (F64x2::splat(u_k), F64x2::splat(shape_k));
        for p in 0..PAIRS {
            let x = u_k * a_j[p];
            let h = x_prev[p] - x;
            let x_mid = half * (x_prev[p] + x);
            px[p] = px[p] - h * slope_x[p];
            py[p] = py[p] - h * (eta_l2 + phi * x_mid * inv_l3);
            let bound = bound_j[p] * shape_k;
            // Projection onto the bound: scale = min(1, bound/|p|) (|p| = 0 gives 1 through the
            // tiny floor).
            let norm = (px[p] * px[p] + py[p] * py[p]).sqrt().max(floor);
            let scale = bound.div(norm).min(one);
            px[p] = px[p] * scale;
            py[p] = py[p] * scale;
            sx[p] = sx[p] + px[p];
            sy[p] = sy[p] + py[p];
            sxpy[p] = sxpy[p] + x * py[p];
            x_prev[p] = x;
        }
    }
    let unpack =
        |v: [F64x2; PAIRS]| -> [f64; 2 * PAIRS] { std::array::from_fn(|l| v[l / 2].0[l % 2]) };
    StripSums {
        sx: unpack(sx),
        sy: unpack(sy),
        sxpy: unpack(sxpy),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One strip at a time, the plain scalar loop (FASTSIM's integration before the lanes).
    fn one_strip(
        a_j: f64,
        slope_x: f64,
        bound_j: f64,
        e: &[(f64, f64)],
        c: (f64, f64, f64),
    ) -> [f64; 3] {
        let (eta_l2, phi, inv_l3) = c;
        let (mut px, mut py, mut sx, mut sy, mut sxpy) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut x_prev = a_j;
        for &(u_k, shape_k) in e {
            let x = u_k * a_j;
            let h = x_prev - x;
            let x_mid = 0.5 * (x_prev + x);
            px -= h * slope_x;
            py -= h * (eta_l2 + phi * x_mid * inv_l3);
            let norm = (px * px + py * py).sqrt().max(f64::MIN_POSITIVE);
            let scale = (bound_j * shape_k / norm).min(1.0);
            px *= scale;
            py *= scale;
            sx += px;
            sy += py;
            sxpy += x * py;
            x_prev = x;
        }
        [sx, sy, sxpy]
    }

    #[test]
    fn lanes_give_the_bits_of_one_strip_at_a_time() {
        // A small deterministic generator: strips from adhesion to full slip, with spin, and
        // empty padding strips (a_j = 0, bound 0).
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let elements: Vec<(f64, f64)> = (0..10)
            .map(|k| {
                let u = 1.0 - (2 * k + 1) as f64 / 10.0;
                (u, 1.0 - u * u)
            })
            .collect();
        for case in 0..200 {
            let c = (
                (next() - 0.5) * 1e9,
                (next() - 0.5) * 1e12 * f64::from(case % 3 != 0),
                1e10 * (1.0 + next()),
            );
            let inputs = StripInputs {
                a_j: std::array::from_fn(|l| if l == 5 { 0.0 } else { 1e-2 * next() }),
                slope_x: std::array::from_fn(|_| (next() - 0.5) * 1e9),
                bound: std::array::from_fn(|l| if l == 5 { 0.0 } else { 1e9 * next().powi(4) }),
            };
            let sums = integrate_strips(&inputs, &elements, c.0, c.1, c.2);
            for l in 0..2 * PAIRS {
                let want = one_strip(
                    inputs.a_j[l],
                    inputs.slope_x[l],
                    inputs.bound[l],
                    &elements,
                    c,
                );
                let got = [sums.sx[l], sums.sy[l], sums.sxpy[l]];
                assert_eq!(
                    got.map(f64::to_bits),
                    want.map(f64::to_bits),
                    "case {case} lane {l}"
                );
            }
        }
    }
}
