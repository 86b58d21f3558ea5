//! The contact compiled for AVX against its baseline compilation, and both against the contact
//! one point at a time, bit for bit.

use super::*;
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::layout::{body_wheelset, N_BODIES, N_WHEELSETS};
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::rail_contact::creep_model::CreepModel;
use crate::vehicle::scenarios::scenario::Scenario;
use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;

/// A small deterministic generator of uniform numbers in [−1, 1).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        2.0 * ((self.0 >> 11) as f64 / (1u64 << 53) as f64) - 1.0
    }
}

/// Wheelset poses from the centre to flange contact and beyond the table (a derailment error),
/// sunk into the rails by up to 0.2 mm (loads up to a few hundred kN) or lifted off them.
fn states(r: &mut Uniform) -> BodyStates {
    let mut s = BodyStates::default();
    for w in 0..N_WHEELSETS {
        let body = body_wheelset(w);
        let lateral = if r.next() > 0.95 { 0.03 } else { 0.012 };
        s.position[body] = [
            1e-3 * r.next(),
            lateral * r.next(),
            -1e-4 + 1.2e-4 * r.next(),
            2e-3 * r.next(),
            10.0 * r.next(),
            3e-3 * r.next(),
        ];
        s.velocity[body] = [
            0.1 * r.next(),
            0.2 * r.next(),
            0.05 * r.next(),
            0.1 * r.next(),
            r.next(),
            0.1 * r.next(),
        ];
    }
    s
}

fn rails(r: &mut Uniform) -> RailIrregularity {
    RailIrregularity {
        y_left: 3e-3 * r.next(),
        z_left: 3e-3 * r.next(),
        y_right: 3e-3 * r.next(),
        z_right: 3e-3 * r.next(),
        dy_left_ds: 1e-3 * r.next(),
        dz_left_ds: 1e-3 * r.next(),
        dy_right_ds: 1e-3 * r.next(),
        dz_right_ds: 1e-3 * r.next(),
    }
}

/// The forces of one call: the result, the wrenches' bits and the wheel forces (their `Debug`
/// form tells every bit of a float apart, the sign of zero included).
fn forces(
    call: impl FnOnce(&mut Wrenches, &mut [WheelForces; 2]) -> Result<()>,
) -> (Result<()>, Vec<u64>, String) {
    let mut wrenches: Wrenches = [[0.0; 6]; N_BODIES];
    let mut out = [WheelForces::default(); 2];
    let result = call(&mut wrenches, &mut out);
    let bits = wrenches.iter().flatten().map(|v| v.to_bits()).collect();
    (result, bits, format!("{out:?}"))
}

/// The dispatched call (the AVX copy where the processor has it) gives the bits of the body
/// compiled for the baseline, from the centre to two-point contact and derailment.
#[test]
fn the_dispatched_call_gives_the_bits_of_the_baseline() {
    let p = ParameterSet::default_vehicle();
    let mut r = Uniform(0x2545_f491_4f6c_dd1d);
    let modes = [
        ContactMode::Rolling,
        ContactMode::Held {
            tangential_stiffness: 1e7,
        },
    ];
    for (name, creep) in [
        ("S_high", CreepModel::Fastsim),
        ("S_low", CreepModel::Fastsim),
        ("S_high", CreepModel::Fastrip),
    ] {
        let scenario = Scenario {
            creep,
            ..Scenario::study(name, 55.0, 300.0, 1).unwrap()
        };
        let contact = shared_wheel_rail(&p, &scenario).unwrap();
        let (mut loaded, mut derailed) = (0, 0);
        for case in 0..400 {
            let s = states(&mut r);
            let speed = 55.0 * (1.0 + 0.2 * r.next());
            let mode = modes[usize::from(case % 7 == 0)];
            for w in 0..N_WHEELSETS {
                let plane = contact.rail_plane(&rails(&mut r), speed);
                let base =
                    forces(|wr, out| contact.apply_on(w, 1.0, &s, &plane, speed, mode, wr, out));
                let dispatched =
                    forces(|wr, out| contact.apply(w, 1.0, &s, &plane, speed, mode, wr, out));
                assert_eq!(
                    dispatched, base,
                    "{name} {creep:?} case {case} wheelset {w}"
                );
                loaded += usize::from(base.2.contains("points_in_contact: 2"));
                derailed += usize::from(base.0.is_err());
            }
        }
        // The cases reach two-point contact and the derailment error.
        assert!(loaded > 10 && derailed > 5, "{name}: {loaded} {derailed}");
    }
}
