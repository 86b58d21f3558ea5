//! The vehicle's stiffest mode about its static equilibrium and the RK4 step it allows.
//!
//! `ω = √|λ|max(M⁻¹ ∂Q/∂q)` with the Jacobian the equilibrium search keeps
//! ([`crate::vehicle::system::statics::Equilibrium::jacobian`], patches held, no damping): the fixed RK4 step of a
//! run must keep `ω·h` inside RK4's stability limit on the imaginary axis, 2√2 ([`check_step`]),
//! or the run blows up within steps. Only the callers that step in time (a run, the critical-speed
//! ramp) ask for it, so the linearisation, the frequency response and the contact checks do not
//! pay for it.
//!
//! Only the largest modulus is needed, not the spectrum: a few dozen Arnoldi steps on `M⁻¹J`
//! (Krylov subspaces find the extreme eigenvalues first; Saad, Numerical Methods for Large
//! Eigenvalue Problems, 2011, §6.2 and §6.7) give it to round-off for the 90 coordinates, at
//! about a tenth of the cost of the full QR solve of the 90×90 matrix that was used before. Where
//! the mode lies (its coordinate, for the error message) comes from a few steps of inverse
//! iteration shifted to that eigenvalue.

use crate::dampers::{Damper, MAX_RATE_STEP};
use crate::error::{LocoError, Result};
use crate::vehicle::analysis::creep_decay::{creep_decay_rate, CREEP_RESOLVED};
use crate::vehicle::model::layout::{dof_names, N_DOF};
use crate::vehicle::params::suspects::with_suspects;
use crate::vehicle::system::simulation::VehicleSystem;
use crate::vehicle::system::statics::{static_equilibrium, Equilibrium, StaticsSettings};
use crate::vehicle::time::integrator::Integrator;
use crate::vehicle::time::integrator::REFERENCE_STEP;
use crate::vehicle::time::stiff_linear_part::gearbox_bearings;
use nalgebra::{DMatrix, DVector};

/// RK4's stability limit on the imaginary axis, `|λ h| ≤ 2√2` (Hairer and Wanner, Solving ODEs
/// II, §IV.2: the stability region of the classical 4-stage method).
pub const RK4_IMAGINARY_LIMIT: f64 = 2.0 * std::f64::consts::SQRT_2;

/// The highest undamped natural frequency of the vehicle about its equilibrium and the
/// coordinate that moves most in it (by kinetic energy).
#[derive(Debug, Clone, PartialEq)]
pub struct StiffestMode {
    /// Angular frequency `√|λ|max(M⁻¹ ∂Q/∂q)`, rad/s.
    pub omega: f64,
    /// The coordinate (`body.coordinate`) with the largest share of the mode.
    pub coordinate: String,
}

/// Checks that a fixed RK4 step `step` (s) is stable for the stiffest mode of `system` about
/// `equilibrium`: an error naming `step`, with the mode's frequency, coordinate and the longest
/// stable step.
pub fn check_step(system: &VehicleSystem, equilibrium: &Equilibrium, step: f64) -> Result<()> {
    check_step_for(&stiffest_mode(system, equilibrium), step)
}

/// [`check_step`] for a mode already found.
fn check_step_for(mode: &StiffestMode, step: f64) -> Result<()> {
    if mode.omega * step <= RK4_IMAGINARY_LIMIT {
        return Ok(());
    }
    Err(LocoError::param(
        "step",
        format!(
            "{step} s is too long for the vehicle's stiffest mode ({:.0} rad/s, {:.0} Hz, mostly \
             `{}`): RK4 is stable for steps up to 2√2/ω = {:.2e} s; shorten the step or check the \
             stiffness and inertia parameters of that body",
            mode.omega,
            mode.omega / (2.0 * std::f64::consts::PI),
            mode.coordinate,
            RK4_IMAGINARY_LIMIT / mode.omega
        ),
    ))
}

/// Most RK4 substeps [`stable_step`] divides a step into. The physical ends of the schema's ranges
/// need at most 4 at the default 1 ms step (the hollow shaft's lightest roll and yaw inertias; its
/// stiffest bearings and the lightest motor inertias 2-3; `tests/api/test_fuzz_vehicle.py`); a
/// vehicle needing more than twice that has a mode far beyond any physical one (a research value
/// out of range, which the error then names), and its run would cost that many times more.
pub const MAX_SUBSTEPS: f64 = 8.0;

/// The RK4 step a run with the requested (longest) `step` (s) takes: `step` itself when the
/// vehicle's stiffest mode about `equilibrium` is stable with it (every run of a vehicle the
/// step suits is unchanged), else the longest whole fraction `step / k` that is, so that the
/// output samples stay on whole steps; and the reference step where a longer one would not
/// resolve the creep forces' decay ([`CREEP_RESOLVED`]). Beyond [`MAX_SUBSTEPS`] the error of
/// [`check_step`].
pub fn stable_step(system: &VehicleSystem, equilibrium: &Equilibrium, step: f64) -> Result<f64> {
    let mode = stiffest_mode(system, equilibrium);
    let stable = if mode.omega * step <= RK4_IMAGINARY_LIMIT {
        step
    } else {
        let k = (mode.omega * step / RK4_IMAGINARY_LIMIT).ceil();
        if k > MAX_SUBSTEPS {
            return check_step_for(&mode, step).map(|()| step);
        }
        step / k
    };
    // Nor is a step beyond the reference taken where it does not resolve the creep forces'
    // decay (slow runs, [`creep_decay_rate`]).
    if stable > REFERENCE_STEP
        && creep_decay_rate(system, 0.0, &equilibrium.state) * stable > CREEP_RESOLVED
    {
        return Ok(step / (step / REFERENCE_STEP).ceil());
    }
    Ok(stable)
}

/// The system `build` makes for an RK4 step (s), in static equilibrium, at the step a time
/// integration takes: built for the requested (longest) `step`, and, when its stiffest mode needs
/// a shorter one ([`stable_step`]), built again for that step, whose dampers are made for it;
/// beyond the reference step, with the reference step's damper laws where the scheme carries
/// them (`carries_laws`), else at the reference step.
/// Returns the system, its equilibrium and the step. A step error names the suspects among
/// the parameters allowed outside their range.
pub fn in_equilibrium_at_stable_step(
    step: f64,
    statics: &StaticsSettings,
    build: impl Fn(f64) -> Result<VehicleSystem>,
) -> Result<(VehicleSystem, Equilibrium, f64)> {
    let mut system = build(step)?;
    let equilibrium = static_equilibrium(&mut system, statics)?;
    let mut stable = stable_step(&system, &equilibrium, step)
        .map_err(|e| with_suspects(e, &system.structure.parameters))?;
    // A step beyond the reference takes the damper laws of the reference step (the reduced
    // laws, a Maxwell damper's series spring made rigid or an FSD's mass left out, are checked
    // there, and a compliance slower than it matters) where the scheme carries them at that
    // step: every pole fits RK4's stages, or the exponential scheme solves it exactly. Otherwise
    // the vehicle runs at the reference step.
    let mut reference = None;
    if stable > REFERENCE_STEP {
        let at_reference = build(REFERENCE_STEP)?;
        if carries_laws(&at_reference, stable) {
            reference = Some(at_reference);
        } else {
            stable = step / (step / REFERENCE_STEP).ceil();
        }
    }
    let same_laws = |other: &VehicleSystem| damper_laws(other) == damper_laws(&system);
    if stable == step && reference.as_ref().is_none_or(same_laws) {
        return Ok((system, equilibrium, step));
    }
    let mut system = match reference {
        Some(at_reference) => at_reference,
        None => build(stable)?,
    };
    let equilibrium = static_equilibrium(&mut system, statics)?;
    Ok((system, equilibrium, stable))
}

/// Whether the scheme of `system` carries all its damper laws at `step` (s): each internal pole
/// fits the explicit stages (`rate·step ≤` [`MAX_RATE_STEP`]) or, with the exponential scheme,
/// is a decaying state it solves exactly
/// ([`crate::dampers::Damper::linear_state_rate_per_s`]).
fn carries_laws(system: &VehicleSystem, step: f64) -> bool {
    system.dampers.iter().all(|d| {
        d.law.fastest_rate_per_s() * step <= MAX_RATE_STEP
            || (system.integrator == Integrator::ExponentialRk4
                && d.law.linear_state_rate_per_s().is_some())
    })
}

/// Each damper's law.
fn damper_laws(system: &VehicleSystem) -> Vec<Damper> {
    system.dampers.iter().map(|d| d.law).collect()
}

/// A start vector with no symmetry: the vehicle is symmetric left-right and nearly front-back,
/// and a uniform vector would have no part in the antisymmetric modes (the golden-ratio sequence
/// is equidistributed, Weyl 1916).
fn start_vector(n: usize) -> DVector<f64> {
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    DVector::from_fn(n, |i, _| ((i + 1) as f64 * golden).fract() - 0.5)
}

/// The stiffest mode of the vehicle of `system` about `equilibrium` (its Jacobian ∂Q/∂q, N/m
/// and N·m/rad, with the system's mass matrix).
pub fn stiffest_mode(system: &VehicleSystem, equilibrium: &Equilibrium) -> StiffestMode {
    let mass = &system.structure.mass;
    // The exponential scheme solves the gearbox bearings' springs exactly: the step is bounded
    // by the rest of the Jacobian (∂Q/∂q holds −Jᵀ K J of the bearings; adding it back removes
    // them).
    let without_bearings;
    let jacobian = match system.integrator {
        Integrator::Rk4 => &equilibrium.jacobian,
        Integrator::ExponentialRk4 => {
            without_bearings =
                &equilibrium.jacobian + gearbox_bearings(&system.structure).stiffness_matrix(mass);
            &without_bearings
        }
    };
    // M⁻¹J column by column with the block Cholesky factor (a few hundred flops per column).
    // (Both matrices are column-major: column j is the slice [j·N, (j+1)·N).)
    let mut a = DMatrix::zeros(N_DOF, N_DOF);
    let columns = a.as_mut_slice().chunks_exact_mut(N_DOF);
    for (out, rhs) in columns.zip(jacobian.as_slice().chunks_exact(N_DOF)) {
        mass.solve(rhs, out);
    }
    let largest = largest_modulus(&a);
    // Where the mode is: a few steps of inverse iteration with the shift -|λ| (the stiffest mode
    // of a restoring Jacobian is real and negative), weighted by the kinetic energy.
    let shifted = &a - DMatrix::identity(N_DOF, N_DOF) * (-largest * (1.0 + 1e-9));
    let shifted = shifted.lu();
    let mut x = start_vector(N_DOF);
    for _ in 0..4 {
        match shifted.solve(&x) {
            Some(next) if next.amax().is_finite() && next.amax() > 0.0 => {
                x = &next / next.amax();
            }
            _ => break,
        }
    }
    let share = |i: usize| x[i].abs() * mass.get(i, i).sqrt();
    let k = (0..N_DOF)
        .max_by(|&i, &j| share(i).total_cmp(&share(j)))
        .unwrap_or(0);
    StiffestMode {
        omega: largest.sqrt(),
        coordinate: dof_names()[k].clone(),
    }
}

/// Krylov dimensions at which the Ritz values are checked.
const CHECK_EVERY: usize = 8;
/// Relative change of the largest Ritz modulus between two checks below which it has converged.
const RITZ_TOLERANCE: f64 = 1e-11;

/// The largest eigenvalue modulus of the square matrix `a` (Arnoldi with modified Gram–Schmidt,
/// orthogonalised twice; the largest Ritz modulus, checked every [`CHECK_EVERY`] steps until it
/// no longer changes, or exact when the Krylov space becomes invariant or reaches the full
/// dimension).
pub fn largest_modulus(a: &DMatrix<f64>) -> f64 {
    let n = a.nrows();
    let mut basis: Vec<DVector<f64>> = Vec::with_capacity(n + 1);
    let v0 = start_vector(n);
    basis.push(&v0 / v0.norm());
    let mut h = DMatrix::<f64>::zeros(n + 1, n);
    let scale = a.amax();
    let mut last = f64::NAN;
    for j in 0..n {
        let mut w = a * &basis[j];
        for _ in 0..2 {
            for (i, v) in basis.iter().enumerate() {
                let c = v.dot(&w);
                h[(i, j)] += c;
                w.axpy(-c, v, 1.0);
            }
        }
        let beta = w.norm();
        h[(j + 1, j)] = beta;
        let m = j + 1;
        let invariant = beta.is_nan() || beta <= 1e-14 * scale;
        if invariant || m == n || m % CHECK_EVERY == 0 {
            let ritz = ritz_largest(&h, m);
            let converged = (ritz - last).abs() <= RITZ_TOLERANCE * ritz;
            if invariant || m == n || converged || !ritz.is_finite() {
                return match ritz.is_finite() {
                    true => ritz,
                    // A QR of the small matrix that does not converge: the full spectrum.
                    false => full_largest(a),
                };
            }
            last = ritz;
        }
        basis.push(w / beta);
    }
    full_largest(a)
}

/// The largest eigenvalue modulus of the leading m×m block of the Hessenberg matrix `h` (NaN if
/// its QR does not converge).
fn ritz_largest(h: &DMatrix<f64>, m: usize) -> f64 {
    let block = h.view((0, 0), (m, m)).transpose();
    match crate::vehicle::analysis::linearise::eigenvalues(block.as_slice(), m) {
        Ok(values) => values.iter().map(|l| l.norm()).fold(0.0, f64::max),
        Err(_) => f64::NAN,
    }
}

/// The largest eigenvalue modulus from the whole spectrum of `a` (QR), or by power iteration
/// when that QR does not converge (nearly equal stiff modes of the four quills).
fn full_largest(a: &DMatrix<f64>) -> f64 {
    let row_major: Vec<f64> = a.transpose().as_slice().to_vec();
    match crate::vehicle::analysis::linearise::eigenvalues(&row_major, a.nrows()) {
        Ok(lambdas) => lambdas.into_iter().map(|l| l.norm()).fold(0.0, f64::max),
        Err(_) => power_iteration(a),
    }
}

/// The largest eigenvalue modulus of `a` by power iteration (200 steps from a uniform vector).
fn power_iteration(a: &DMatrix<f64>) -> f64 {
    let mut x = DVector::from_element(a.nrows(), 1.0);
    let mut growth = 0.0;
    for _ in 0..200 {
        let next = a * &x;
        growth = next.norm() / x.norm();
        if !(growth.is_finite() && growth > 0.0) {
            break;
        }
        x = &next / next.norm();
    }
    growth
}

#[cfg(test)]
mod tests;
