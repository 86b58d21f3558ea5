//! The reduced laws of [`Damper::for_step`]: the rigid series spring against the full Maxwell
//! element at a vehicle's frequencies, and the choice of the law for a step.

use super::*;
use crate::error::LocoError;

/// The SPEC §6 corner that the 1 ms step cannot integrate explicitly: C_sy = 10 kN·s/m with
/// K_ncsy = 50 kN/mm (k/c = 5·10³ 1/s).
const C: f64 = 10e3;
const K: f64 = 50e6;

fn corner() -> Damper {
    Damper::Maxwell(
        MaxwellDamper::new(MaxwellParams {
            damping_nspm: C,
            series_stiffness_npm: K,
            blow_off: None,
        })
        .unwrap(),
    )
}

/// Forces of both forms over the second of two cycles of `x = a·sin ωt` (N), and the energy each
/// dissipates in that cycle (J). The compliant form's internal state is integrated by RK4 with a
/// step 50 times shorter than its time constant c/k, so it is the exact Maxwell response.
fn second_cycle(frequency_hz: f64) -> (Vec<f64>, Vec<f64>, f64, f64) {
    let full = corner();
    let rigid = corner().for_step(1e-3).unwrap();
    assert!(rigid.has_rigid_series());
    let discrete = full.initial_discrete();
    let (a, omega) = (5e-3, 2.0 * PI * frequency_hz);
    let period = 1.0 / frequency_hz;
    let steps_per_cycle = ((period * K / C) * 50.0).ceil() as usize;
    let h = period / steps_per_cycle as f64;
    let stroke = |t: f64| (a * (omega * t).sin(), a * omega * (omega * t).cos());
    let rate = |t: f64, xd: f64| {
        let (x, v) = stroke(t);
        let mut r = [0.0];
        full.evaluate(x, v, &[xd], &discrete, &mut r);
        r[0]
    };
    let mut xd = 0.0;
    let (mut f_full, mut f_rigid) = (Vec::new(), Vec::new());
    let (mut e_full, mut e_rigid) = (0.0, 0.0);
    for i in 0..2 * steps_per_cycle {
        let t = i as f64 * h;
        if i >= steps_per_cycle {
            let (x, v) = stroke(t);
            let ff = full.evaluate(x, v, &[xd], &discrete, &mut [0.0]);
            let fr = rigid.evaluate(x, v, &[], &discrete, &mut []);
            // Same quadrature for both: its error cancels in the comparison.
            e_full += ff * v * h;
            e_rigid += fr * v * h;
            f_full.push(ff);
            f_rigid.push(fr);
        }
        let k1 = rate(t, xd);
        let k2 = rate(t + 0.5 * h, xd + 0.5 * h * k1);
        let k3 = rate(t + 0.5 * h, xd + 0.5 * h * k2);
        let k4 = rate(t + h, xd + h * k3);
        xd += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    (f_full, f_rigid, e_full, e_rigid)
}

#[test]
fn rigid_form_matches_the_maxwell_element_within_the_bound() {
    let dt = 1e-3;
    assert!(corner().for_step(dt).unwrap().has_rigid_series());
    for f in [0.5, 1.3, 2.0, 5.0, 10.0, 20.0] {
        let eps = 2.0 * PI * f * C / K;
        // The switch criterion k/c·dt > 2.5 guarantees ε < ω·dt/2.5.
        assert!(eps < 2.0 * PI * f * dt / MAX_RATE_STEP);
        let (full, rigid, e_full, e_rigid) = second_cycle(f);
        let amplitude = full.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let worst = full
            .iter()
            .zip(&rigid)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        // Force: the rigid form leads by atan ε, a difference of ε·amplitude.
        assert!(
            worst <= 1.02 * eps * amplitude && worst >= 0.9 * eps * amplitude,
            "{f} Hz: force difference {:.3e} of the amplitude, ε = {eps:.3e}",
            worst / amplitude
        );
        // Dissipation: c against c/(1 + ε²).
        let excess = e_rigid / e_full - 1.0;
        assert!(
            (excess - eps * eps).abs() <= 0.05 * eps * eps + 1e-7,
            "{f} Hz: dissipation excess {excess:.3e}, ε² = {:.3e}",
            eps * eps
        );
    }
}

#[test]
fn form_follows_the_step_and_the_law() {
    let law = corner();
    // k/c·dt = 2 at 0.4 ms: the full element fits the step.
    assert_eq!(law.for_step(4e-4).unwrap(), law);
    assert_eq!(Damper::yd2().for_step(1e-3).unwrap(), Damper::yd2());
    // Stiff only above the knee: no rigid form, a typed error naming the step (the vehicle adds
    // the damper's name: `vehicle::system::damper_elements`).
    let blow_off = stiff_above_the_knee();
    let err = blow_off.for_step(1e-3).unwrap_err();
    let text = err.to_string();
    assert!(
        matches!(err, LocoError::InvalidParameter { ref name, .. } if name == "step"),
        "{text}"
    );
    // A massless FSD stiff in both valve positions becomes c(s)·v.
    let fsd = Damper::Fsd(
        FsdDamper::new(FsdParams {
            low_damping_nspm: 5e3,
            high_damping_nspm: 8e3,
            equivalent_mass_kg: 0.0,
            equivalent_stiffness_npm: 50e6,
            ..FsdParams::default()
        })
        .unwrap(),
    );
    let rigid = fsd.for_step(1e-3).unwrap();
    assert!(rigid.has_rigid_series());
    let mut discrete = fsd.initial_discrete();
    discrete.scale_factor = 0.5;
    let force = rigid.evaluate(0.0, 0.1, &[], &discrete, &mut []);
    assert!((force - 6.5e3 * 0.1).abs() < 1e-9, "{force}");
    assert_eq!(rigid.n_states(), 0);
    // The spec's FSD at 1 ms: its mass pole does not fit, the massless law does.
    match Damper::fsd().for_step(1e-3).unwrap() {
        Damper::Fsd(d) => {
            assert_eq!(d.params().equivalent_mass_kg, 0.0);
            assert_eq!(d.n_states(), 1);
            assert!(!d.has_rigid_series());
        }
        other => panic!("{other:?}"),
    }
}
