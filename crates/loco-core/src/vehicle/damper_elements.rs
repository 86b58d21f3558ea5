//! The vehicle's dampers: each placement of the suspension with a damper law from the damper
//! module, its internal states inside the integrator's state vector and its discrete state.
//!
//! # Stiff series springs: the rigid form
//! A Maxwell element (series spring `k`, N/m, and damper `c`, N·s/m) has an internal pole at
//! `−k/c` (1/s). When `k/c·dt` exceeds RK4's stability limit the explicit step cannot carry it
//! (SPEC §6 reaches `k/c = 5·10³ 1/s`: C_sy = 10 kN·s/m with K_ncsy = 50 kN/mm). Such a spring is
//! then far stiffer than the damper at every frequency the vehicle responds to, and the element is
//! integrated as the pure damper `F = c·ẋ` ([`SeriesForm::Rigid`], the singular-perturbation limit
//! `c/k → 0`, no internal state). Error bound, from the complex stiffness of the Maxwell element
//! `k·iωc/(k + iωc) = iωc/(1 + iε)` with `ε = ωc/k` (ω in rad/s):
//!
//! - dissipation: the equivalent damping is `c/(1 + ε²)`, so the rigid form dissipates a fraction
//!   `ε²` more energy per cycle;
//! - force: the Maxwell force lags the damper force by `atan ε`, the difference is at most `ε` times
//!   the force amplitude (the series spring's in-phase stiffness `k·ε²/(1 + ε²)` is left out).
//!
//! The rigid form is used only when even the slowest internal pole, `k/c_max` with `c_max` the
//! largest slope of the law, is beyond the limit (`k/c_max·dt > 2.5`), hence `ε < ω·dt/2.5`: at the
//! default 1 ms step ε < 0.005 at 2 Hz, 0.025 at 10 Hz and 0.05 at 20 Hz (dissipation 2.5·10⁻⁵,
//! 6·10⁻⁴, 2.5·10⁻³). At the C_sy/K_ncsy corner itself (`c/k = 2·10⁻⁴ s`) ε is half of that.
//! A law that is stiff only in part of its range (a blow-off slope much smaller than the slope
//! below the knee) or whose slope has no upper bound (the hydraulic orifice law) is refused with a
//! typed error asking for a shorter step. The damper module and its bench keep the full model.

use super::elements::{BodyStates, Wrenches};
use super::kinematics::dot;
use super::suspension::{DamperPlacement, DamperRole};
use crate::dampers::{Damper, DamperDiscreteState, FsdDamper, MaxwellDamper, MaxwellParams};
use crate::error::{LocoError, Result};

/// Largest `rate·dt` of an internal pole (rate in 1/s, dt in s) that the vehicle integrates
/// explicitly: inside RK4's real-axis stability limit (2.785) with a margin.
pub const MAX_RATE_STEP: f64 = 2.5;

/// How the vehicle integrates a damper law at its step (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesForm {
    /// The law as the damper module states it, its internal states integrated with the vehicle.
    Compliant,
    /// Series spring rigid: the damper law at the elongation rate, no internal state.
    Rigid,
}

/// One damper on the vehicle.
#[derive(Debug, Clone)]
pub struct DamperElement {
    pub placement: DamperPlacement,
    pub law: Damper,
    /// How the law is integrated at the vehicle's step.
    pub form: SeriesForm,
    /// Index of the first internal state in the integrator's state vector.
    pub state_offset: usize,
    /// Distance change between the attachment points in the static equilibrium, m; the damper
    /// sees elongation measured from there (no force at rest).
    pub static_elongation: f64,
}

impl DamperElement {
    /// Elongation (m, from the static value) and its rate (m/s).
    #[inline]
    pub fn stroke(&self, states: &BodyStates) -> (f64, f64) {
        let (d, v) = self.placement.at.relative_motion(states);
        (
            dot(d, self.placement.direction) - self.static_elongation,
            dot(v, self.placement.direction),
        )
    }

    /// Number of internal states in the integrator's state vector (0 in the rigid form).
    #[inline]
    pub fn n_states(&self) -> usize {
        match self.form {
            SeriesForm::Compliant => self.law.n_states(),
            SeriesForm::Rigid => 0,
        }
    }

    /// Force (N, positive in tension) for elongation `x` (m) and its rate `v` (m/s); writes the
    /// rates of the internal `states` into `rates` (both [`DamperElement::n_states`] long).
    #[inline]
    pub fn force(
        &self,
        x: f64,
        v: f64,
        states: &[f64],
        discrete: &DamperDiscreteState,
        rates: &mut [f64],
    ) -> f64 {
        match self.form {
            SeriesForm::Compliant => self.law.evaluate(x, v, states, discrete, rates),
            SeriesForm::Rigid => rigid_force(&self.law, v, discrete.scale_factor),
        }
    }

    /// Adds the damper's forces for tension `force` (N) to the two bodies.
    #[inline]
    pub fn apply(&self, states: &BodyStates, force: f64, wrenches: &mut Wrenches) {
        let n = self.placement.direction;
        // Tension pulls the second end (B) back toward the first.
        self.placement.at.apply_pair(
            states,
            [-force * n[0], -force * n[1], -force * n[2]],
            wrenches,
        );
    }
}

/// Force (N) of the damper part of `law` at elongation rate `v` (m/s) and valve scale factor `s`:
/// the whole element when its series spring is rigid.
#[inline]
fn rigid_force(law: &Damper, v: f64, scale_factor: f64) -> f64 {
    match law {
        Damper::Maxwell(d) => d.damper_force(v),
        Damper::Fsd(d) => d.damping_at(scale_factor) * v,
        Damper::Hydraulic(d) => d.damper_force(v, scale_factor),
    }
}

/// Slowest internal pole of a law (1/s), `k/c_max`, when the slope of its force-velocity law is
/// bounded by `c_max` and it has no mass; `None` otherwise (no rigid form).
fn slowest_rate_per_s(law: &Damper) -> Option<f64> {
    match law {
        // Validation keeps the blow-off slope at or below the damping under the knee.
        Damper::Maxwell(d) => Some(d.params().series_stiffness_npm / d.params().damping_nspm),
        Damper::Fsd(d) if d.params().equivalent_mass_kg == 0.0 => {
            Some(d.params().equivalent_stiffness_npm / d.params().high_damping_nspm)
        }
        Damper::Fsd(_) | Damper::Hydraulic(_) => None,
    }
}

/// The form in which the vehicle integrates damper `name` with `law` at step `dt` (s): compliant
/// when its fastest pole fits the step, rigid when even its slowest one does not (error bound in
/// the module documentation), a typed `step` error otherwise.
pub fn series_form(name: &str, law: &Damper, dt: f64) -> Result<SeriesForm> {
    let fastest = law.fastest_rate_per_s();
    if fastest * dt <= MAX_RATE_STEP {
        return Ok(SeriesForm::Compliant);
    }
    match slowest_rate_per_s(law) {
        Some(slowest) if slowest * dt > MAX_RATE_STEP => Ok(SeriesForm::Rigid),
        _ => Err(LocoError::param(
            "step",
            format!(
                "{dt} s is too long for damper `{name}` (internal rate {fastest:.3e} 1/s, not stiff \
                 over its whole law); use < {:.2e} s",
                MAX_RATE_STEP / fastest
            ),
        )),
    }
}

/// The law of a damper placement: the yaw dampers take `yaw_damper` when given, every other
/// damper (and the yaw dampers otherwise) the linear Maxwell law of the parameter file.
pub fn damper_law(placement: &DamperPlacement, yaw_damper: Option<&Damper>) -> Result<Damper> {
    if placement.role == DamperRole::Yaw {
        if let Some(law) = yaw_damper {
            return Ok(*law);
        }
    }
    Ok(Damper::Maxwell(MaxwellDamper::new(MaxwellParams {
        damping_nspm: placement.damping,
        series_stiffness_npm: placement.series_stiffness,
        blow_off: None,
    })?))
}

/// The form of a damper law used in the vehicle's time integration with step `dt` (s).
///
/// The FSD's equivalent mass (15 kg against 15 kN/mm and up to 800 kN·s/m) adds a pole at
/// −c2/m ≈ −5·10⁴ 1/s, a 19 µs lag that no explicit integrator at the vehicle's step can carry.
/// Its effect on the force at frequency f is of relative order m·(2πf)²/k: 0.4 % at 10 Hz,
/// 10⁻⁴ at 2 Hz, so when `dt` is too long for that pole the vehicle uses the same FSD without the
/// mass (singular perturbation); the damper bench keeps the mass.
pub fn law_for_step(law: Damper, dt: f64) -> Result<Damper> {
    match law {
        Damper::Fsd(fsd) if fsd.fastest_rate_per_s() * dt > 2.0 => {
            let mut params = *fsd.params();
            params.equivalent_mass_kg = 0.0;
            Ok(Damper::Fsd(FsdDamper::new(params)?))
        }
        other => Ok(other),
    }
}

#[cfg(test)]
#[path = "damper_elements_tests.rs"]
mod tests;
