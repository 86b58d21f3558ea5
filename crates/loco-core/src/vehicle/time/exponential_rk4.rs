//! Exponential fourth-order Runge–Kutta with the stiff linear springs integrated exactly.
//!
//! The vehicle's equations split into `ẏ = L y + N(t, y)`: `L` the springs of
//! [`StiffLinearPart`] (the gearbox bearings) and the decay of the linear Maxwell dampers' series
//! springs ([`DecayingStates`]), `N = f − L y` all the rest (contact, creep, the dampers' forcing,
//! the other suspension, the bearings' small nonlinear terms), so that the split changes nothing in
//! the equations. ETDRK4 (Cox and Matthews, J. Comput. Phys. 176, 2002, eq. 26–29; in the
//! φ-function form of Hochbruck and Ostermann, Acta Numerica 19, 2010, §2.5) evaluates `N` at
//! four stages, like RK4, and solves the linear part exactly between them; with `L = 0` it is the
//! classical RK4. The step is then bounded by the stiffest mode of the rest, not by the
//! bearings' 230–330 Hz: 2 ms instead of 1.4 ms, with the output rate of 500 Hz on whole steps;
//! and a damper pole `k/c` beyond RK4's reach at that step keeps its law (the reference's).
//!
//! Each stage is the exact solution of `ẏ = L y + w0 + w1·t + w2·t²/2` from a start state
//! ([`propagate`]): the deflections `z = J q` of the stiff springs follow their small linear system
//! through a precomputed [`Propagator`], and every coordinate follows the polynomial forcing plus
//! the springs' accelerations `−B ∫z` (velocities) and `−B ∫∫z` (positions).

use crate::vehicle::time::decaying_states::{DecayPropagator, DecayingStates};
use crate::vehicle::time::integrator::OdeSystem;
use crate::vehicle::time::stiff_linear_part::{Propagator, StiffLinearPart};
use std::sync::Arc;

/// Preallocated stages of ETDRK4 for one step length.
#[derive(Debug, Clone)]
pub struct ExponentialRk4 {
    part: Arc<StiffLinearPart>,
    decaying: Arc<DecayingStates>,
    /// Propagators over half and the whole step.
    half: Propagator,
    full: Propagator,
    half_decay: DecayPropagator,
    full_decay: DecayPropagator,
    /// Step the propagators are made for, s.
    dt: f64,
    k: [Vec<f64>; 4],
    /// The first stage's state, which the third stage starts from.
    a: Vec<f64>,
    stage: Vec<f64>,
    w: [Vec<f64>; 3],
    /// Deflection inputs and outputs of the propagators (5r and 2r).
    input: Vec<f64>,
    output: Vec<f64>,
    /// The springs' deflections `[J q | J q̇]` (2r) of the step's start state, of the first
    /// stage's and of the others: formed once for each state and read by every stage that
    /// takes it out of `f` or starts from it.
    springs: [Vec<f64>; 3],
    /// The decaying states' deflections at the step's start, the three stages and the end.
    deltas: [Vec<f64>; 5],
}

impl ExponentialRk4 {
    /// Workspace for a system of `n` states `[q | q̇ | others]` with the stiff part `part`, the
    /// decaying first-order states `decaying` (among the others) and the fixed step `dt` (s).
    pub fn new(
        part: Arc<StiffLinearPart>,
        decaying: Arc<DecayingStates>,
        n: usize,
        dt: f64,
    ) -> Self {
        let r = part.len();
        let m = decaying.len();
        Self {
            deltas: std::array::from_fn(|_| vec![0.0; m]),
            half: part.propagator(0.5 * dt),
            full: part.propagator(dt),
            half_decay: decaying.propagator(0.5 * dt),
            full_decay: decaying.propagator(dt),
            part,
            decaying,
            dt,
            k: std::array::from_fn(|_| vec![0.0; n]),
            a: vec![0.0; n],
            stage: vec![0.0; n],
            w: std::array::from_fn(|_| vec![0.0; n]),
            input: vec![0.0; 5 * r],
            output: vec![0.0; 2 * r],
            springs: std::array::from_fn(|_| vec![0.0; 2 * r]),
        }
    }

    /// Advances `y` from `t` over the step `dt` (s; the workspace's, for which its propagators
    /// are made) to `t_end` (`t + dt` as the caller counts time, see
    /// [`crate::vehicle::time::integrator::Rk4Workspace::step_observed`], whose signature this is), calling
    /// `observe(system, y, ẏ)` with the full derivatives at the step's start.
    pub fn step_observed<S: OdeSystem>(
        &mut self,
        system: &mut S,
        t: f64,
        dt: f64,
        t_end: f64,
        y: &mut [f64],
        observe: impl FnOnce(&S, &[f64], &[f64]),
    ) {
        debug_assert_eq!(dt, self.dt, "the propagators are made for another step");
        let h = self.dt;
        let Self {
            part,
            decaying,
            half,
            full,
            half_decay,
            full_decay,
            k: [k1, k2, k3, k4],
            a,
            stage,
            w: [w0, w1, w2],
            input,
            output,
            springs: [sy, sa, ss],
            deltas: [d0, da, db, dc, d_end],
            ..
        } = self;
        let linear = Linear {
            part,
            decaying,
            half: (half, half_decay),
            full: (full, full_decay),
        };
        let mut scratch = Scratch { input, output };
        // The decaying states' deflections go from stage to stage (each stage's from its
        // propagation), computed from the state only at the step's start.
        linear.decaying.deflections(y, d0);
        system.derivatives(t, y, k1);
        observe(system, y, k1);
        linear.remove(y, (d0, sy), k1);
        linear.propagate(linear.half, (y, d0, sy), &[k1], &mut scratch, (a, da));
        system.derivatives(t + 0.5 * h, a, k2);
        linear.remove(a, (da, sa), k2);
        linear.propagate(linear.half, (y, d0, sy), &[k2], &mut scratch, (stage, db));
        system.derivatives(t + 0.5 * h, stage, k3);
        linear.remove(stage, (db, ss), k3);
        dispatched::extrapolate(w0, k3, k1);
        linear.propagate(linear.half, (a, da, sa), &[w0], &mut scratch, (stage, dc));
        system.derivatives(t_end, stage, k4);
        linear.remove(stage, (dc, ss), k4);
        dispatched::quadratic(w1, w2, [&k1[..], &k2[..], &k3[..], &k4[..]], h);
        let end = (&mut stage[..], &mut d_end[..]);
        linear.propagate(linear.full, (y, d0, sy), &[k1, w1, w2], &mut scratch, end);
        y.copy_from_slice(stage);
        system.after_step(t_end, h, y);
    }
}

/// The linear part `L`: the stiff springs and the decaying states, with their propagators over
/// half and the whole step.
struct Linear<'a> {
    part: &'a StiffLinearPart,
    decaying: &'a DecayingStates,
    half: (&'a Propagator, &'a DecayPropagator),
    full: (&'a Propagator, &'a DecayPropagator),
}

impl Linear<'_> {
    /// `k = f(y)` into `N(y) = f(y) − L y`; `deflections` are the decaying states' at `y`, and
    /// `springs` receives the springs' deflections of `y` for the stages that start from it.
    fn remove(&self, y: &[f64], (deflections, springs): (&[f64], &mut [f64]), k: &mut [f64]) {
        // The decaying states read the coordinate rows (q̇) before the springs change them.
        self.decaying.remove_linear(deflections, k);
        remove_linear(self.part, y, springs, k);
    }

    /// The exact solution at the propagators' time of `ẏ = L y + Σ w_k t^k/k!` from the state
    /// `y0` with its decaying states' deflections `start` and its springs' deflections
    /// `deflected` (from [`Self::remove`]), into `out` with its deflections.
    fn propagate(
        &self,
        (springs, decay): (&Propagator, &DecayPropagator),
        (y0, start, deflected): (&[f64], &[f64], &[f64]),
        w: &[&[f64]],
        scratch: &mut Scratch,
        (out, deflections): (&mut [f64], &mut [f64]),
    ) {
        propagate(self.part, springs, y0, deflected, w, scratch, out);
        self.decaying.propagate(decay, start, w, out, deflections);
    }
}

/// The propagators' deflection buffers.
struct Scratch<'a> {
    input: &'a mut [f64],
    output: &'a mut [f64],
}

/// Turns `k = f(y)` into `N(y) = f(y) − L y` with `L y = [P q̇; −B J q]`: the springs' part
/// of the velocities `P q̇ = G J q̇` out of the coordinate rows, `+B J q` into the velocity rows.
/// `springs` receives `[J q | J q̇]` (2r).
fn remove_linear(part: &StiffLinearPart, y: &[f64], springs: &mut [f64], k: &mut [f64]) {
    let (n, r) = (part.n_dof(), part.len());
    let (z, u) = springs.split_at_mut(r);
    part.deflections(&y[..n], z);
    part.deflections(&y[n..2 * n], u);
    part.add_projection(u, -1.0, &mut k[..n]);
    part.add_response(z, 1.0, &mut k[n..2 * n]);
}

/// `out` = the exact solution at `tau` of `ẏ = L y + Σ w_k t^k/k!` from `y0` (its springs'
/// deflections `[J q | J q̇]` in `deflected`), with one to three
/// forcing vectors `w` (combinations of `N`, whose coordinate rows `(I − P) q̇` deflect no
/// spring). Outside the springs' part this is the polynomial RK4 takes; inside it the
/// propagator adds the springs' motion.
fn propagate(
    part: &StiffLinearPart,
    propagator: &Propagator,
    y0: &[f64],
    deflected: &[f64],
    w: &[&[f64]],
    scratch: &mut Scratch,
    out: &mut [f64],
) {
    let (n, r, tau) = (part.n_dof(), part.len(), propagator.tau);
    let input = &mut *scratch.input;
    input[..2 * r].copy_from_slice(deflected);
    input[(2 + w.len()) * r..].fill(0.0);
    for (i, wi) in w.iter().enumerate() {
        part.deflections(&wi[n..2 * n], &mut input[(2 + i) * r..(3 + i) * r]);
    }
    propagator.apply(input, scratch.output);
    // τ^(k+1)/(k+1)! for k = 0..2.
    let c = [tau, tau * tau / 2.0, tau * tau * tau / 6.0];
    dispatched::polynomial(out, y0, w, c);
    let output = &*scratch.output;
    part.add_response(&output[..r], -1.0, &mut out[n..2 * n]);
    part.add_response(&output[r..2 * r], 1.0, &mut out[..n]);
}

/// The loops over all states in the baseline and the AVX copy (the module `simd`'s dispatch).
///
/// Why: the loops over all states were a third of the propagation's instructions in SSE2's
/// two lanes; AVX's four take the same IEEE operations per state (separate multiplies, adds and
/// divisions, no fused multiply-add), so the results are the same bits.
mod dispatched {
    use crate::simd::multiversion;

    #[multiversion(targets("x86_64+avx"))]
    pub(super) fn polynomial(out: &mut [f64], y0: &[f64], w: &[&[f64]], c: [f64; 3]) {
        super::polynomial(out, y0, w, c);
    }

    #[multiversion(targets("x86_64+avx"))]
    pub(super) fn extrapolate(w0: &mut [f64], k3: &[f64], k1: &[f64]) {
        super::extrapolate(w0, k3, k1);
    }

    #[multiversion(targets("x86_64+avx"))]
    pub(super) fn quadratic(w1: &mut [f64], w2: &mut [f64], k: [&[f64]; 4], h: f64) {
        super::quadratic(w1, w2, k, h);
    }
}

/// `w0 = 2 N3 − N1`, the third stage's forcing.
#[inline(always)]
fn extrapolate(w0: &mut [f64], k3: &[f64], k1: &[f64]) {
    for ((w, x3), x1) in w0.iter_mut().zip(k3).zip(k1) {
        *w = 2.0 * x3 - x1;
    }
}

/// N along the step as the quadratic `w0 + w1·t + w2·t²/2` (the φ1, φ2, φ3 weights) from the
/// four stages' `N` over the step `h` (s). As zipped slices (no bounds checks, so in SIMD lanes:
/// the same IEEE operations per state; indexed, the loop was 8 % of the scheme's own work).
#[inline(always)]
fn quadratic(w1: &mut [f64], w2: &mut [f64], [k1, k2, k3, k4]: [&[f64]; 4], h: f64) {
    let (w12, k23) = (w1.iter_mut().zip(w2.iter_mut()), k2.iter().zip(k3));
    for (((w1, w2), &n1), ((&n2, &n3), &n4)) in w12.zip(k1).zip(k23.zip(k4)) {
        let n23 = n2 + n3;
        *w1 = (-3.0 * n1 + 2.0 * n23 - n4) / h;
        *w2 = 4.0 * (n1 - n23 + n4) / (h * h);
    }
}

/// `out = y0 + Σ c_k w_k`: the stages' one forcing and the step's three as straight loops over
/// the states (the same sums in the same order as the general case).
#[inline(always)]
fn polynomial(out: &mut [f64], y0: &[f64], w: &[&[f64]], c: [f64; 3]) {
    match *w {
        [w0] => {
            for ((o, &y), &a) in out.iter_mut().zip(y0).zip(w0) {
                *o = y + c[0] * a;
            }
        }
        [w0, w1, w2] => {
            for ((((o, &y), &a), &b), &d) in out.iter_mut().zip(y0).zip(w0).zip(w1).zip(w2) {
                *o = y + c[0] * a + c[1] * b + c[2] * d;
            }
        }
        _ => {
            for (i, o) in out.iter_mut().enumerate() {
                let mut s = y0[i];
                for (k, wk) in w.iter().enumerate() {
                    s += c[k] * wk[i];
                }
                *o = s;
            }
        }
    }
}

#[cfg(test)]
mod tests;
