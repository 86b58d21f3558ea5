//! Which state the vehicle's body states were last computed from, so that the first stage of a
//! step reuses the body states of the step before.
//!
//! RK4's first stage evaluates f(t_{n+1}, y_{n+1}) at exactly the state that `after_step` has
//! just turned into body states (for the FSD valves): the second computation of the same 25
//! body motions, 1.6 % of a run's instructions, gives the same bits. The key is the coordinates
//! and velocities themselves (compared bitwise, a few dozen instructions against the ≈4 000 of
//! the body states) and the structure they were mapped with, so no caller can be handed stale
//! states: any other state, and any write of the body states elsewhere (`invalidate`), misses.

use crate::vehicle::model::layout::N_DOF;
use crate::vehicle::model::structure::VehicleStructure;

/// The key of the body states in [`crate::vehicle::system::simulation::VehicleSystem`].
#[derive(Debug, Clone, Default)]
pub(crate) struct StatesCache {
    /// The structure (its address) and the coordinates and velocities (m, rad, m/s, rad/s) the
    /// body states hold; `None`: they hold nothing that may be reused.
    structure: Option<usize>,
    coordinates_velocities: Vec<f64>,
}

impl StatesCache {
    /// The body states were just computed from `y` (its first 2·N_DOF entries) with `structure`.
    pub(crate) fn store(&mut self, structure: &VehicleStructure, y: &[f64]) {
        self.coordinates_velocities.clear();
        self.coordinates_velocities
            .extend_from_slice(&y[..2 * N_DOF]);
        self.structure = Some(structure as *const VehicleStructure as usize);
    }

    /// Whether the body states are those of `y` with `structure`, bit for bit.
    pub(crate) fn holds(&self, structure: &VehicleStructure, y: &[f64]) -> bool {
        self.structure == Some(structure as *const VehicleStructure as usize)
            && self.coordinates_velocities.as_slice() == &y[..2 * N_DOF]
    }

    /// The body states were written from something else (a different state, the statics).
    pub(crate) fn invalidate(&mut self) {
        self.structure = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::params::parameters::ParameterSet;

    #[test]
    fn only_the_stored_state_and_structure_hit() {
        let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
        let other = structure.clone();
        let y = vec![0.25; 2 * N_DOF + 7];
        let mut cache = StatesCache::default();
        assert!(!cache.holds(&structure, &y));
        cache.store(&structure, &y);
        assert!(cache.holds(&structure, &y));
        // The damper states after 2·N_DOF do not enter the body states.
        let mut damper_changed = y.clone();
        damper_changed[2 * N_DOF] = 9.0;
        assert!(cache.holds(&structure, &damper_changed));
        let mut velocity_changed = y.clone();
        velocity_changed[2 * N_DOF - 1] = f64::from_bits(0.25f64.to_bits() + 1);
        assert!(!cache.holds(&structure, &velocity_changed));
        assert!(!cache.holds(&other, &y));
        cache.invalidate();
        assert!(!cache.holds(&structure, &y));
    }
}
