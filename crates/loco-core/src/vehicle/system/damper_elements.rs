//! The vehicle's dampers: each placement of the suspension with a damper law from the damper
//! module, its internal states inside the integrator's state vector and its discrete state.
//!
//! A law too stiff for the vehicle's step is used in its reduced form, [`Damper::for_step`] (FSD
//! without its mass, a series spring rigid; thresholds and error bounds in [`crate::dampers`]).

use crate::dampers::{Damper, DamperDiscreteState, MaxwellDamper, MaxwellParams};
use crate::error::{LocoError, Result};
use crate::vehicle::model::elements::{BodyStates, Wrenches};
use crate::vehicle::model::kinematics::dot;
use crate::vehicle::model::layout::N_DOF;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::model::suspension::{DamperPlacement, DamperRole};
use crate::vehicle::time::decaying_states::{DecayingState, DecayingStates};

/// One damper on the vehicle.
#[derive(Debug, Clone)]
pub struct DamperElement {
    pub placement: DamperPlacement,
    /// The law at the vehicle's step ([`Damper::for_step`]).
    pub law: Damper,
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

    /// Number of internal states in the integrator's state vector (0 with a rigid series
    /// spring).
    #[inline]
    pub fn n_states(&self) -> usize {
        self.law.n_states()
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
        self.law.evaluate(x, v, states, discrete, rates)
    }

    /// Adds the forces of the placement's `count` dampers, each in tension `force` (N), to the
    /// two bodies at the placement's lever arms on A and B, already turned with the bodies (m,
    /// `DamperMotions::arms`).
    #[inline]
    pub fn apply_at(&self, arms: &[[f64; 3]; 2], force: f64, wrenches: &mut Wrenches) {
        let force = force * self.placement.count;
        let n = self.placement.direction;
        // Tension pulls the second end (B) back toward the first.
        self.placement.at.apply_pair_at(
            arms,
            [-force * n[0], -force * n[1], -force * n[2]],
            wrenches,
        );
    }
}

/// The internal states of `dampers` that decay at a constant rate (the linear Maxwell laws,
/// [`Damper::linear_state_rate_per_s`]), which the exponential scheme solves exactly, with their
/// elongation per coordinate of `structure` (the bodies' small-motion kinematics, as
/// [`DamperElement::stroke`] forms it) and their static elongation.
pub fn decaying_states(structure: &VehicleStructure, dampers: &[DamperElement]) -> DecayingStates {
    let states = dampers
        .iter()
        .filter_map(|d| {
            let rate = d.law.linear_state_rate_per_s()?;
            let elongation = structure
                .relative_motion_per_coordinate(&d.placement.at)
                .into_iter()
                .map(|(j, m)| (j, dot([m[0], m[1], m[2]], d.placement.direction)))
                .filter(|(_, value)| *value != 0.0)
                .collect();
            Some(DecayingState {
                index: d.state_offset,
                rate,
                elongation,
                offset: -d.static_elongation,
            })
        })
        .collect();
    DecayingStates::new(N_DOF, states)
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

/// The law of a damper placement at the vehicle's step `dt` (s): [`damper_law`] reduced by
/// [`Damper::for_step`]; a step too long for it is an error on `step` naming the damper.
pub fn law_for_step(
    placement: &DamperPlacement,
    yaw_damper: Option<&Damper>,
    dt: f64,
) -> Result<Damper> {
    damper_law(placement, yaw_damper)?
        .for_step(dt)
        .map_err(|e| match e {
            LocoError::InvalidParameter { name, reason } => {
                LocoError::param(name, format!("damper `{}`: {reason}", placement.name))
            }
            other => other,
        })
}

#[cfg(test)]
mod tests;
