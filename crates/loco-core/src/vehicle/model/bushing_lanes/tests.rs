//! The lanes against [`Bushing::apply`] one element at a time, bit for bit.

use super::*;
use crate::vehicle::model::elements::{BodyStates, Wrenches};
use crate::vehicle::model::layout::N_BODIES;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::params::parameters::ParameterSet;

/// A state with every body moving (values of the runs' order, both signs) and zeros of both
/// signs, and wrenches that already hold forces.
fn state(seed: f64) -> (BodyStates, Wrenches) {
    let mut states = BodyStates::default();
    let mut wrenches = [[0.0; 6]; N_BODIES];
    for (i, wrench) in wrenches.iter_mut().enumerate() {
        for (k, w) in wrench.iter_mut().enumerate() {
            let x = (seed + 0.37 * (6 * i + k) as f64).sin();
            states.position[i][k] = 1e-3 * x;
            states.velocity[i][k] = if (i + k) % 7 == 0 {
                -0.0
            } else {
                0.05 * x.cos()
            };
            *w = if (i + k) % 5 == 0 {
                0.0
            } else {
                1e3 * (2.0 * x).sin()
            };
        }
    }
    (states, wrenches)
}

fn bits(w: &Wrenches) -> Vec<u64> {
    w.iter().flatten().map(|x| x.to_bits()).collect()
}

/// The lanes' forces in the plain-array lane set (the baseline copy's, on any processor).
fn apply_plain(lanes: &BushingLanes, states: &BodyStates, wrenches: &mut Wrenches) {
    let mut forces = Vec::new();
    compute_in(crate::simd::Plain, lanes, states, &mut forces);
    for slot in &lanes.slots {
        add_in_order(slot, &forces[slot.quad], wrenches);
    }
}

#[test]
fn the_lanes_add_the_bits_of_one_element_at_a_time() {
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let bushings = &structure.suspension.bushings;
    assert!(bushings.iter().any(|b| b.on_load_path) && bushings.iter().any(|b| !b.on_load_path));
    let lanes = BushingLanes::new(bushings);
    for seed in [0.0, 1.3, -2.1] {
        let (states, start) = state(seed);
        let mut expected = start;
        for b in bushings {
            b.apply(&states, &mut expected);
        }
        let mut got = start;
        lanes.apply(bushings, &states, &mut got);
        assert_eq!(bits(&got), bits(&expected), "seed {seed}");
        let mut plain = start;
        apply_plain(&lanes, &states, &mut plain);
        assert_eq!(bits(&plain), bits(&expected), "plain lanes, seed {seed}");
    }
}

#[test]
fn a_subset_of_elements_fills_part_of_a_quad() {
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let bushings: Vec<_> = structure.suspension.bushings[3..9].to_vec();
    let lanes = BushingLanes::new(&bushings);
    let (states, start) = state(0.7);
    let mut expected = start;
    for b in &bushings {
        b.apply(&states, &mut expected);
    }
    let mut got = start;
    lanes.apply(&bushings, &states, &mut got);
    assert_eq!(bits(&got), bits(&expected));
    let mut plain = start;
    apply_plain(&lanes, &states, &mut plain);
    assert_eq!(bits(&plain), bits(&expected));
}
