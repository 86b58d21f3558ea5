//! The lanes against `DamperElement::stroke` and `Attachment::apply_pair`, bit for bit.

use super::*;
use crate::vehicle::model::elements::{BodyStates, Wrenches};
use crate::vehicle::model::layout::N_BODIES;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::params::parameters::ParameterSet;

#[test]
fn the_lanes_give_the_strokes_and_forces_of_one_damper_at_a_time() {
    let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
    let placements = &structure.suspension.dampers;
    assert!(placements.len() > W, "dampers in more than one quad");
    let lanes = DamperLanes::new(placements);
    let mut states = BodyStates::default();
    for i in 0..N_BODIES {
        for k in 0..6 {
            let x = (0.37 * (6 * i + k) as f64).sin();
            states.position[i][k] = if (i + k) % 7 == 0 { -0.0 } else { 1e-3 * x };
            states.velocity[i][k] = 0.05 * x.cos();
        }
    }
    let start: Wrenches = std::array::from_fn(|i| std::array::from_fn(|k| (i * 6 + k) as f64));
    let bits = |w: &Wrenches| w.iter().flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
    let (mut expected, mut got) = (start, start);
    let force = |i: usize| 1e3 * (i as f64 * 0.9).cos();
    lanes.with_motions(placements, &states, false, |motions| {
        for (i, p) in placements.iter().enumerate() {
            let (d, v) = p.at.relative_motion(&states);
            let stroke = (dot(d, p.direction) - 0.01, dot(v, p.direction));
            let (x, rate) = motions.stroke(i, 0.01);
            assert_eq!(
                (x.to_bits(), rate.to_bits()),
                (stroke.0.to_bits(), stroke.1.to_bits())
            );
            let f = [
                -force(i) * p.direction[0],
                -force(i) * p.direction[1],
                -force(i) * p.direction[2],
            ];
            p.at.apply_pair(&states, f, &mut expected);
            p.at.apply_pair_at(&motions.arms(i), f, &mut got);
        }
    });
    assert_eq!(bits(&got), bits(&expected));
    // The plain-array lane set (the baseline copy's) gives the same motions.
    let mut plain = vec![QuadMotion::default(); lanes.quads.len()];
    quad_motions_in(crate::simd::Plain, &lanes.quads, &states, &mut plain);
    lanes.with_motions(placements, &states, false, |motions| {
        for (q, p) in motions.0.iter().zip(&plain) {
            let b = |m: &QuadMotion| {
                let arms = m.arm_a.iter().chain(&m.arm_b).flatten();
                let v = m.along.iter().chain(&m.rate).chain(arms);
                v.map(|x| x.to_bits()).collect::<Vec<_>>()
            };
            assert_eq!(b(q), b(p));
        }
    });
}
