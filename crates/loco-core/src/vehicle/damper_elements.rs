//! The vehicle's dampers: each placement of the suspension with a damper law from the damper
//! module, its internal states inside the integrator's state vector and its discrete state.

use super::elements::{BodyStates, Wrenches};
use super::kinematics::dot;
use super::suspension::{DamperPlacement, DamperRole};
use crate::dampers::{Damper, DamperDiscreteState, FsdDamper, MaxwellDamper, MaxwellParams};
use crate::error::Result;

/// One damper on the vehicle.
#[derive(Debug, Clone)]
pub struct DamperElement {
    pub placement: DamperPlacement,
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

/// Discrete states of all dampers at start.
pub fn initial_discrete(dampers: &[DamperElement]) -> Vec<DamperDiscreteState> {
    dampers.iter().map(|d| d.law.initial_discrete()).collect()
}
