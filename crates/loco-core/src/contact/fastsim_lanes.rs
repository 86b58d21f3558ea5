//! FASTSIM's strip integration, two strips per SIMD register (four with AVX).
//!
//! Strips are independent, so the elements of several strips are integrated in lockstep. Written
//! as arrays of strips, the compiler packed each strip's (p_x, p_y) pair into one register and
//! took the square root and the division of every strip one at a time (`sqrtsd`, `divsd`): the
//! serial chain that bounds FASTSIM's cost. Here a value of two strips is one `Lanes<2>`, whose
//! lane-wise operations the compiler turns into packed ones (`sqrtpd`, `divpd` with SSE2, the
//! x86_64 baseline); where the processor has AVX (detected at run time) four strips are one
//! `Lanes<4>` (`vsqrtpd`, `vdivpd` on 256-bit registers), the ten strips of a pass two of them
//! and one `Lanes<2>`. Every lane does the scalar code's IEEE operations in the scalar code's
//! order (no fused multiply-add, no reordering), so the forces are bit for bit those of one strip
//! at a time, on any machine.
//!
//! The root and the division take most of the time where the traction is projected onto the
//! bound (a cycle profile: the instructions waiting on them held a third of the samples), so the
//! test that skips them costs one product per element and the chain between them carries no
//! floor's maximum when no traction is zero.

pub(super) use crate::simd::Lanes;
use crate::simd::{multiversion, target_cfg_f};

/// |p|² ≤ bound²·this is inside the bound whatever the rounding (of the square, the root and the
/// division, each within 2⁻⁵³ relative): |p|/bound ≤ 1 − 5e-13 + 3e-16 < 1, so bound/|p| rounds to
/// at least 1 and the projection's scale min(1, bound/|p|) is exactly 1.
pub(super) const INSIDE_BOUND: f64 = 1.0 - 1e-12;

/// Pairs of lanes integrated together: every element step of all of them is independent, which
/// hides the latency of the square root and the division.
pub(super) const PAIRS: usize = 5;
/// Strips of one pass.
const STRIPS: usize = 2 * PAIRS;

/// An element of the strips' march, from the leading edge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Element {
    /// x_k / a_j (–).
    pub u: f64,
    /// The p_n shape factor of the element (–).
    pub shape: f64,
    /// shape²·[`INSIDE_BOUND`]: with a strip's bound² it gives the test of the projection's skip
    /// in one product instead of three (see [`inside_test`]).
    pub inside: f64,
}

impl Element {
    pub(super) fn new(u: f64, shape: f64) -> Self {
        Self {
            u,
            shape,
            inside: shape * shape * INSIDE_BOUND,
        }
    }
}

/// A strip's part of the skip test, bound_j² (Pa²): |p|² ≤ bound_j²·`inside` of an element keeps
/// |p| within the bound bound_j·shape by more than rounding (the three roundings of the test's
/// products, 4.4e-16 relative, against INSIDE_BOUND's 1e-12), so the scale is exactly 1, as
/// with the test on (bound_j·shape)² that it replaces. Outside 1e-145 ≤ bound_j ≤ 1e150, where
/// the products could leave the normal range (or reach the root's floor), the test never passes
/// (NaN) and the projection always runs, except for an empty strip (bound_j = 0), whose zero
/// traction is inside a zero bound and its scale is not needed.
#[inline(always)]
pub(super) fn inside_test(bound_j: f64) -> f64 {
    if (1e-145..=1e150).contains(&bound_j) {
        bound_j * bound_j
    } else if bound_j == 0.0 {
        0.0
    } else {
        f64::NAN
    }
}

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

/// Integrates the strips of `inputs` over `elements` (from the leading edge); p_y's slope is
/// `eta_l2 + φ·x·inv_l3` with `eta_l2 = η/L2` (Pa/m), spin φ (1/m) and `inv_l3 = 1/L3` (Pa/m).
/// Two strips per register in the baseline copy (SSE2); in the AVX copy eight strips in two
/// 256-bit registers and the last two (the innermost, see `fastsim`) in a 128-bit one. Why not
/// three AVX registers with two empty lanes: the divider takes a 256-bit root or division in
/// twice the time of a 128-bit one, and the inner strips project too. The bits are the same
/// either way.
#[multiversion(targets("x86_64+avx"))]
pub(super) fn integrate_strips(
    inputs: &StripInputs,
    elements: &[Element],
    eta_l2: f64,
    phi: f64,
    inv_l3: f64,
) -> StripSums {
    let c = (eta_l2, phi, inv_l3);
    if target_cfg_f!(target_feature = "avx") {
        integrate::<4, 2, 2>(inputs, elements, c)
    } else {
        integrate::<2, PAIRS, 0>(inputs, elements, c)
    }
}

/// One register of `W` strips through the march: their inputs, tractions and sums.
#[derive(Clone, Copy)]
struct Group<const W: usize> {
    a_j: Lanes<W>,
    slope_x: Lanes<W>,
    bound_j: Lanes<W>,
    /// [`inside_test`] of each strip.
    inside_j: Lanes<W>,
    x_prev: Lanes<W>,
    px: Lanes<W>,
    py: Lanes<W>,
    sx: Lanes<W>,
    sy: Lanes<W>,
    sxpy: Lanes<W>,
}

impl<const W: usize> Group<W> {
    /// The strips `first..first + W` of `inputs`.
    #[inline(always)]
    fn new(inputs: &StripInputs, first: usize) -> Self {
        let take = |a: &[f64; STRIPS]| {
            let mut lanes = [0.0; W];
            lanes.copy_from_slice(&a[first..first + W]);
            Lanes(lanes)
        };
        let bound_j = take(&inputs.bound);
        // Loops, not `array::map` or `from_fn`: in the AVX compilation their closures were called
        // per lane.
        let mut inside_j = bound_j;
        for v in &mut inside_j.0 {
            *v = inside_test(*v);
        }
        let zero = Lanes::splat(0.0);
        Self {
            a_j: take(&inputs.a_j),
            slope_x: take(&inputs.slope_x),
            bound_j,
            inside_j,
            x_prev: take(&inputs.a_j),
            px: zero,
            py: zero,
            sx: zero,
            sy: zero,
            sxpy: zero,
        }
    }

    /// One element step; `c` is `(eta_l2, phi, inv_l3)`. Every lane does the scalar code's IEEE
    /// operations in its order.
    #[inline(always)]
    fn step(&mut self, e: &Element, c: (f64, f64, f64)) {
        let (eta_l2, phi, inv_l3) = (Lanes::splat(c.0), Lanes::splat(c.1), Lanes::splat(c.2));
        let x = Lanes::splat(e.u) * self.a_j;
        let h = self.x_prev - x;
        let x_mid = Lanes::splat(0.5) * (self.x_prev + x);
        self.px = self.px - h * self.slope_x;
        self.py = self.py - h * (eta_l2 + phi * x_mid * inv_l3);
        // Projection onto the bound: scale = min(1, bound/max(|p|, tiny floor)). Where every
        // lane is inside the bound by more than rounding can move |p|, the scale is exactly 1
        // and the root and division are skipped: the same bits for a fraction of the cost in
        // the adhesion zone, most of a tread contact.
        let norm2 = self.px * self.px + self.py * self.py;
        if !norm2.all_le(self.inside_j * Lanes::splat(e.inside)) {
            let bound = self.bound_j * Lanes::splat(e.shape);
            let root = norm2.sqrt();
            // A positive |p|² has a root of at least 1e-162, above the floor: the floor's
            // maximum, on the chain of the root and the division, is then skipped.
            let q = if norm2.all_gt(Lanes::splat(0.0)) {
                bound.div(root)
            } else {
                bound.div(root.max(Lanes::splat(f64::MIN_POSITIVE)))
            };
            let scale = q.min(Lanes::splat(1.0));
            self.px = self.px * scale;
            self.py = self.py * scale;
        }
        self.sx = self.sx + self.px;
        self.sy = self.sy + self.py;
        self.sxpy = self.sxpy + x * self.py;
        self.x_prev = x;
    }

    /// Writes the sums into lanes `first..first + W` of `out`.
    #[inline(always)]
    fn store(&self, out: &mut StripSums, first: usize) {
        out.sx[first..first + W].copy_from_slice(&self.sx.0);
        out.sy[first..first + W].copy_from_slice(&self.sy.0);
        out.sxpy[first..first + W].copy_from_slice(&self.sxpy.0);
    }
}

/// The lockstep integration of the strips in `G` groups of `W` lanes and the last `T` in one
/// group of `T` (`W·G + T` = the pass's strips); `c` is `(eta_l2, phi, inv_l3)`.
#[inline(always)]
fn integrate<const W: usize, const G: usize, const T: usize>(
    inputs: &StripInputs,
    elements: &[Element],
    c: (f64, f64, f64),
) -> StripSums {
    const { assert!(W * G + T == STRIPS) };
    // A loop, not `from_fn`, whose closure the AVX compilation called per group.
    let mut groups = [Group::<W>::new(inputs, 0); G];
    for (g, group) in groups.iter_mut().enumerate().skip(1) {
        *group = Group::new(inputs, W * g);
    }
    let mut tail: Group<T> = Group::new(inputs, W * G);
    for e in elements {
        for group in &mut groups {
            group.step(e, c);
        }
        tail.step(e, c);
    }
    let mut out = StripSums::default();
    for (g, group) in groups.iter().enumerate() {
        group.store(&mut out, W * g);
    }
    tail.store(&mut out, W * G);
    out
}

#[cfg(test)]
mod tests;
