//! The internal states of the linear Maxwell dampers, integrated exactly by
//! [`crate::vehicle::time::exponential_rk4`] as first-order states that decay at a constant rate.
//!
//! Why: a Maxwell element (series spring `k`, N/m, damper `c`, N·s/m) carries the damper's
//! deflection `x_d` with `ẋ_d = r·(x − x_d)`, `r = k/c` (1/s), `x` the elongation. SPEC §6
//! reaches `r = 5·10³ 1/s` (C_sy = 10 kN·s/m with K_ncsy = 50 kN/mm). RK4 carries such a pole
//! only while `r·h ≤ 2.5` ([`crate::dampers::MAX_RATE_STEP`]); beyond it the element is reduced
//! to the pure damper ([`crate::dampers::Damper::for_step`]). At the exponential scheme's 2 ms
//! the laws with `r` in (1250, 2500] 1/s would be reduced where the 1 ms reference keeps them,
//! so those vehicles ran at 1 ms throughout (a quarter of the SPEC §6 box).
//!
//! The state solved exactly is the series spring's deflection, not `x_d`: with `x ≈ J q + c0`
//! (`J` the elongation per coordinate, constant; `c0` minus the static elongation), the variable
//! `δ = J q + c0 − x_d` obeys `δ̇ = J q̇ − r δ + r·(δ − δ_true)`, `δ_true = x − x_d`, so that
//! `L = −r` and `N = J q̇ + r·(J q + c0 − x)`: the forcing is the elongation rate, as smooth as
//! the bodies, and the remainder vanishes where the elongation is linear in the coordinates
//! (straight track; on a curve the track frame makes it nearly so). Taking `x_d` itself
//! (`N = r·x`) instead puts `r` into the Lipschitz constant of `N`: the stages' errors in the
//! coordinates are multiplied by it, and at `r·h = 2` the 500 m metrics moved by up to 12 %.
//!
//! Over a time `τ` under the forcing `w0 + w1·t + w2·t²/2`, `δ` moves to
//! `e^{−rτ} δ0 + τ φ1(−rτ) w0 + τ² φ2(−rτ) w1 + τ³ φ3(−rτ) w2` (Hochbruck and Ostermann, Acta
//! Numerica 19, 2010, §2.1: `φ_{k+1}(z) = (φ_k(z) − 1/k!)/z`, `φ_0 = e^z`), and `x_d` is
//! `J q + c0 − δ` with the stage's coordinates.

use crate::vehicle::time::row_groups::LaneRows;
use crate::vehicle::time::row_groups::Sparse;
use nalgebra::Matrix4;

/// One decaying state.
#[derive(Debug, Clone)]
pub struct DecayingState {
    /// Index of `x_d` in the state vector.
    pub index: usize,
    /// Decay rate `r = k/c`, 1/s.
    pub rate: f64,
    /// Elongation per coordinate, `J` (m/m, m/rad).
    pub elongation: Sparse,
    /// Elongation at zero coordinates, `c0`, m.
    pub offset: f64,
}

// The reference definitions: the time loop takes the rows' sums in lanes (`LaneRows`), and the
// tests check it against these.
#[cfg(test)]
impl DecayingState {
    /// The linearised elongation `J q + c0` (m) of the state vector (or stage) `y`.
    #[inline]
    fn elongation_at(&self, y: &[f64]) -> f64 {
        self.elongation.iter().map(|&(j, c)| c * y[j]).sum::<f64>() + self.offset
    }

    /// `δ = J q + c0 − x_d` (m) of the state vector (or stage) `y`.
    #[inline]
    fn deflection(&self, y: &[f64]) -> f64 {
        self.elongation_at(y) - y[self.index]
    }
}

/// The decaying states of a system, with their exact propagation over a stage length.
#[derive(Debug, Clone, Default)]
pub struct DecayingStates {
    states: Vec<DecayingState>,
    /// Number of coordinates `q` (the state is `[q | q̇ | other states]`).
    n_dof: usize,
    /// The states' elongation rows `J` in lanes: each row's sum as the state's own.
    elongations: LaneRows,
    /// One more than the largest state index (0 without states): the length the state vectors
    /// must have, checked once per call instead of at each state's accesses.
    end: usize,
}

/// Per state, over a time `τ`: `[e^{−rτ}, τ φ1, τ² φ2, τ³ φ3]` at `z = −rτ`.
#[derive(Debug, Clone, Default)]
pub struct DecayPropagator {
    coefficients: Vec<[f64; 4]>,
}

impl DecayingStates {
    /// The states `states` (each rate finite and ≥ 0) of a system with `n_dof` coordinates.
    pub fn new(n_dof: usize, states: Vec<DecayingState>) -> Self {
        debug_assert!(states.iter().all(|s| s.rate.is_finite() && s.rate >= 0.0));
        // The unchecked accesses below rest on every index being past the coordinates.
        assert!(states.iter().all(|s| s.index >= 2 * n_dof));
        let rows: Vec<Sparse> = states.iter().map(|s| s.elongation.clone()).collect();
        Self {
            end: states.iter().map(|s| s.index + 1).max().unwrap_or(0),
            elongations: LaneRows::new(&rows),
            states,
            n_dof,
        }
    }

    /// Number of states.
    pub fn len(&self) -> usize {
        self.states.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.states.is_empty()
    }

    /// The states.
    pub fn states(&self) -> &[DecayingState] {
        &self.states
    }

    /// Writes the deflections `δ` of the state vector (or stage) `y` into `out` (one per state).
    #[inline]
    pub fn deflections(&self, y: &[f64], out: &mut [f64]) {
        // `DecayingState::deflection`, the rows' sums taken in lanes.
        self.elongations.for_each(y, |i, sum| {
            let s = &self.states[i];
            out[i] = sum + s.offset - y[s.index];
        });
    }

    /// Writes `N_δ = J q̇ − ẋ_d + r·δ` into each state's row of `k = f(y)`, with `deflections`
    /// those of `y` ([`Self::deflections`], or what [`Self::propagate`] gave for the stage); to
    /// be called before anything else changes the coordinate rows of `k` (`q̇` there).
    #[inline]
    pub fn remove_linear(&self, deflections: &[f64], k: &mut [f64]) {
        let n = self.states.len();
        assert!(deflections.len() >= n && k.len() >= self.end);
        let (rates, others) = k.split_at_mut(2 * self.n_dof);
        self.elongations.for_each(rates, |i, elongation_rate| {
            let s = &self.states[i];
            let r = &mut others[s.index - 2 * self.n_dof];
            *r = elongation_rate - *r + s.rate * deflections[i];
        });
    }

    /// The exact propagation over `tau` (s).
    pub fn propagator(&self, tau: f64) -> DecayPropagator {
        DecayPropagator {
            coefficients: self
                .states
                .iter()
                .map(|s| {
                    let [e, p1, p2, p3] = phi(-s.rate * tau);
                    [e, tau * p1, tau * tau * p2, tau.powi(3) * p3]
                })
                .collect(),
        }
    }

    /// Writes each `x_d` into `out`, whose coordinates already hold the stage's, and its `δ`
    /// into `deflections`: `δ` solves `δ̇ = −r δ + Σ w_k t^k/k!` exactly from `start` (the
    /// deflections at the start state) over the propagator's time (one to three forcing
    /// vectors, combinations of [`Self::remove_linear`]'s rows).
    #[inline]
    pub fn propagate(
        &self,
        p: &DecayPropagator,
        start: &[f64],
        w: &[&[f64]],
        out: &mut [f64],
        deflections: &mut [f64],
    ) {
        let n = self.states.len();
        assert!(p.coefficients.len() >= n && start.len() >= n && deflections.len() >= n);
        assert!(out.len() >= self.end && w.iter().all(|wk| wk.len() >= self.end));
        // The coordinates the elongations read, and the states written (after them).
        let (coordinates, others) = out.split_at_mut(2 * self.n_dof);
        self.elongations.for_each(coordinates, |i, sum| {
            let s = &self.states[i];
            let c = &p.coefficients[i];
            let mut d = c[0] * start[i];
            for (k, wk) in w.iter().enumerate() {
                d += c[k + 1] * wk[s.index];
            }
            deflections[i] = d;
            // `DecayingState::elongation_at` of the stage, less `δ`.
            others[s.index - 2 * self.n_dof] = sum + s.offset - d;
        });
    }
}

/// `[φ0, φ1, φ2, φ3](z)`: the first row of the exponential of the 4×4 matrix with `z` in its
/// corner and ones on the superdiagonal (Sidje, ACM TOMS 24, 1998, Theorem 1: the φ-functions
/// as one matrix exponential), by nalgebra's scaled Padé exponential, which stays accurate for
/// small `|z|`, where the closed forms `(e^z − 1)/z, …` lose digits to cancellation.
pub fn phi(z: f64) -> [f64; 4] {
    let mut a = Matrix4::zeros();
    a[(0, 0)] = z;
    for i in 0..3 {
        a[(i, i + 1)] = 1.0;
    }
    let e = a.exp();
    [e[(0, 0)], e[(0, 1)], e[(0, 2)], e[(0, 3)]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phi_matches_the_closed_forms_from_small_to_large_arguments() {
        for z in [-1e-8f64, -0.3, -0.999, -1.0, -2.5, -12.0, -400.0] {
            let [p0, p1, p2, p3] = phi(z);
            assert!((p0 - z.exp()).abs() <= 1e-15, "{z}");
            // φ1 = (e^z − 1)/z by expm1, accurate for every z.
            let exact1 = z.exp_m1() / z;
            assert!((p1 - exact1).abs() <= 1e-15 * exact1, "{z}: {p1} {exact1}");
            // Limits: φ_k(0) = 1/k!; φ_k(z) ~ −1/((k−1)!·z) as z → −∞.
            if z.abs() < 1e-6 {
                assert!((p2 - 0.5).abs() < 1e-8 && (p3 - 1.0 / 6.0).abs() < 1e-8);
            }
            if z < -100.0 {
                assert!((p2 + 1.0 / z).abs() < 1e-4 && (p3 + 0.5 / z).abs() < 1e-4);
            }
        }
        // Continuous across |z| = 1 (where an earlier series/recurrence split switched).
        let (a, b) = (phi(-1.0 + 1e-12), phi(-1.0 - 1e-12));
        for k in 0..4 {
            assert!((a[k] - b[k]).abs() < 1e-11, "φ{k}");
        }
    }

    #[test]
    fn the_lanes_give_the_bits_of_one_state_at_a_time() {
        // Seven states (a group of four and one of three) of two row lengths over 6
        // coordinates; the state vector holds zeros of both signs.
        let states: Vec<DecayingState> = (0..7)
            .map(|i| DecayingState {
                index: 12 + i,
                rate: 100.0 * (i + 1) as f64,
                elongation: (0..2 + i % 2)
                    .map(|k| ((i + 2 * k) % 6, (i as f64 + 0.3 * k as f64).sin()))
                    .collect(),
                offset: 0.01 * i as f64,
            })
            .collect();
        let part = DecayingStates::new(6, states.clone());
        let y: Vec<f64> = (0..19)
            .map(|j| match j % 5 {
                0 => -0.0,
                1 => 0.0,
                _ => (j as f64 * 0.7).cos(),
            })
            .collect();
        let mut out = vec![f64::NAN; 7];
        part.deflections(&y, &mut out);
        for (s, o) in states.iter().zip(&out) {
            assert_eq!(o.to_bits(), s.deflection(&y).to_bits());
        }
        // `remove_linear` on `k = y`: each state's row against its indexed formula.
        let mut k = y.clone();
        part.remove_linear(&out, &mut k);
        for (s, d) in states.iter().zip(&out) {
            let rate: f64 = s.elongation.iter().map(|&(j, c)| c * y[j]).sum();
            let expected = rate - y[s.index] + s.rate * d;
            assert_eq!(k[s.index].to_bits(), expected.to_bits());
        }
        let p = part.propagator(1e-3);
        let (w0, w1) = (y.iter().map(|v| 2.0 * v).collect::<Vec<_>>(), y.clone());
        let (mut stage, mut delta) = (y.clone(), vec![0.0; 7]);
        part.propagate(&p, &out, &[&w0, &w1], &mut stage, &mut delta);
        for (s, d) in states.iter().zip(&delta) {
            assert_eq!(
                stage[s.index].to_bits(),
                (s.elongation_at(&stage) - d).to_bits()
            );
        }
    }

    #[test]
    fn propagation_is_the_exact_solution_under_a_quadratic_forcing() {
        // ẏ = −r y + w0 + w1 t + w2 t²/2, y(0) = y0: the particular solution is a quadratic,
        // y_p = a + b t + c t², with c = w2/(2r), b = (w1 − 2c)/r, a = (w0 − b)/r.
        let (r, y0, tau) = (2000.0f64, 0.3, 2e-3);
        let (w0, w1, w2) = (5.0, -700.0, 4e5);
        let c = w2 / (2.0 * r);
        let b = (w1 - 2.0 * c) / r;
        let a = (w0 - b) / r;
        let exact = a + b * tau + c * tau * tau + (y0 - a) * (-r * tau).exp();
        // One coordinate q (rows 0, 1 = q, q̇) and x_d at 2, with J = 0 and c0 = 0: δ = −x_d.
        let part = DecayingStates::new(
            1,
            vec![DecayingState {
                index: 2,
                rate: r,
                elongation: vec![],
                offset: 0.0,
            }],
        );
        let p = part.propagator(tau);
        let mut out = [9.0, 9.0, 9.0];
        let w = |v: f64| [0.0, 0.0, v];
        let mut start = [0.0];
        part.deflections(&[0.0, 0.0, -y0], &mut start);
        assert_eq!(start, [y0]);
        let mut delta = [0.0];
        part.propagate(&p, &start, &[&w(w0), &w(w1), &w(w2)], &mut out, &mut delta);
        assert_eq!(out[..2], [9.0, 9.0], "only the decaying states are written");
        assert_eq!(delta, [-out[2]]);
        let out = [-out[2]];
        assert!((out[0] - exact).abs() < 1e-14, "{} {exact}", out[0]);
    }
}
