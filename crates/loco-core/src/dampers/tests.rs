//! Verification of the dampers on the bench against closed forms and the FSD requirements of the
//! issue (regimes, switching delay, sweep through f_p, two-tone and multi-tone excitation).

use super::bench::{run, BenchMotion, BenchOptions, BenchRecord, Equivalent};
use super::*;
use std::f64::consts::{PI, TAU};

fn sine(damper: &Damper, frequency_hz: f64, amplitude_m: f64, cycles: usize) -> Equivalent {
    let motion = BenchMotion::Sine {
        frequency_hz,
        amplitude_m,
        cycles,
    };
    run(damper, &motion, &BenchOptions::default())
        .unwrap()
        .equivalent
        .unwrap()
}

/// Closed form of a spring k in series with a damper c with mass m at the node:
/// complex stiffness `k·(iωc - mω²)/(k - mω² + iωc)`; returns (c_eq, k_eq).
fn closed_form(c: f64, k: f64, m: f64, frequency_hz: f64) -> (f64, f64) {
    let w = TAU * frequency_hz;
    let (num_re, num_im) = (-m * w * w, w * c);
    let (den_re, den_im) = (k - m * w * w, w * c);
    let den = den_re * den_re + den_im * den_im;
    let re = k * (num_re * den_re + num_im * den_im) / den;
    let im = k * (num_im * den_re - num_re * den_im) / den;
    (im / w, re)
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn maxwell_matches_closed_form_within_one_percent() {
    for (damper, c) in [(Damper::yd1(), 200e3), (Damper::yd2(), 800e3)] {
        let k = 22.5e6;
        for f in [0.5, 1.0, 2.0, 4.0, 8.0] {
            let eq = sine(&damper, f, 3e-3, 6);
            let wck = TAU * f * c / k;
            let c_closed = c / (1.0 + wck * wck);
            let k_closed = k * wck * wck / (1.0 + wck * wck);
            assert!(
                rel(eq.damping_nspm, c_closed) < 0.01,
                "c at {f} Hz: {eq:?} vs {c_closed}"
            );
            assert!(
                rel(eq.stiffness_npm, k_closed) < 0.01,
                "k at {f} Hz: {eq:?} vs {k_closed}"
            );
            let energy = PI * c_closed * TAU * f * 9e-6;
            assert!(
                rel(eq.energy_per_cycle_j, energy) < 0.01,
                "energy at {f} Hz"
            );
        }
    }
}

#[test]
fn force_is_positive_in_tension() {
    let damper = Damper::yd2();
    let mut states = [0.0; MAX_STATES];
    let mut dstates = [0.0; MAX_STATES];
    let discrete = damper.initial_discrete();
    let force = damper.evaluate(1e-3, 0.0, &states[..1], &discrete, &mut dstates[..1]);
    assert!((force - 22.5e3).abs() < 1e-9);
    // The damper element then yields toward the elongation, relaxing the force.
    assert!(dstates[0] > 0.0);
    states[0] = 2e-3;
    assert!(damper.evaluate(1e-3, 0.0, &states[..1], &discrete, &mut dstates[..1]) < 0.0);
}

#[test]
fn fsd_low_below_and_high_above_the_cutoff() {
    let damper = Damper::fsd();
    let (m, k) = (15.0, 15e6);
    for (f, c) in [(0.5, 200e3), (1.0, 200e3), (4.0, 800e3), (8.0, 800e3)] {
        let eq = sine(&damper, f, 3e-3, 10);
        let (c_closed, k_closed) = closed_form(c, k, m, f);
        assert!(
            rel(eq.damping_nspm, c_closed) < 0.01,
            "c at {f} Hz: {eq:?} vs {c_closed}"
        );
        assert!(
            rel(eq.stiffness_npm, k_closed) < 0.01,
            "k at {f} Hz: {eq:?} vs {k_closed}"
        );
    }
}

/// Steps the discrete state of the damper API at `dt` as the vehicle does, with the motion
/// `x(t)`; returns per step (t, scale factor, trigger decision).
fn drive(
    damper: &Damper,
    dt: f64,
    duration: f64,
    x: impl Fn(f64) -> (f64, f64),
) -> Vec<(f64, f64, bool)> {
    // The valve judges the stroke only, so the continuous states do not matter here.
    let mut discrete = damper.initial_discrete();
    let (x0, v0) = x(0.0);
    damper.advance(&mut discrete, 0.0, 0.0, x0, v0, &[0.0; MAX_STATES]);
    let mut out = Vec::new();
    for i in 1..=(duration / dt) as usize {
        let t = i as f64 * dt;
        let (xi, vi) = x(t);
        damper.advance(&mut discrete, t, dt, xi, vi, &[0.0; MAX_STATES]);
        out.push((t, discrete.scale_factor, discrete.trigger.high_frequency));
    }
    out
}

#[test]
fn fsd_switches_completely_after_the_delay() {
    let dt = 1e-4;
    // 0.5 Hz from a closed start: the trigger decides "low" after its warm-up, then the valve
    // opens linearly and is fully open exactly one switching delay later.
    let steps = drive(&Damper::fsd(), dt, 4.0, |t| {
        (
            3e-3 * (TAU * 0.5 * t).sin(),
            3e-3 * TAU * 0.5 * (TAU * 0.5 * t).cos(),
        )
    });
    let decided = steps.iter().find(|s| !s.2).expect("never decided low").0;
    let open = steps.iter().find(|s| s.1 == 0.0).expect("never opened").0;
    assert!(
        (open - decided - 0.05).abs() <= 1.5 * dt,
        "decided {decided}, open {open}"
    );
    assert!(decided >= FsdTriggerParams::default().warmup_time_s);
    let halfway = steps.iter().find(|s| s.0 >= decided + 0.025).unwrap().1;
    assert!(
        (halfway - 0.5).abs() < 0.01,
        "scale factor half-way {halfway}"
    );
}

#[test]
fn fsd_sweep_switches_at_the_cutoff_with_its_hysteresis() {
    let (f0, f1, duration) = (0.5, 4.0, 40.0);
    let damper = Damper::fsd();
    let params = FsdTriggerParams::default();
    for (start, end) in [(f0, f1), (f1, f0)] {
        let rate = (end - start) / duration;
        let record = run(
            &damper,
            &BenchMotion::Sweep {
                start_frequency_hz: start,
                end_frequency_hz: end,
                amplitude_m: 2e-3,
                duration_s: duration,
            },
            &BenchOptions::default(),
        )
        .unwrap();
        let after_warmup = |r: &BenchRecord, i: usize| r.time_s[i] > 2.0;
        // Frequency at which the valve starts to move after the warm-up, away from its state.
        let target = if end > start { 1.0 } else { 0.0 };
        let first_move = (1..record.time_s.len())
            .filter(|&i| after_warmup(&record, i))
            .find(|&i| {
                (record.scale_factor[i] - target).abs()
                    < (record.scale_factor[i - 1] - target).abs()
            })
            .expect("the valve never switched");
        let f_switch = start + rate * record.time_s[first_move];
        // Threshold f_p(1 ± h), reached through the trigger's averaging lag (about two time
        // constants, 0.5 s at the sweep rate of 0.0875 Hz/s: 0.044 Hz).
        let threshold = if end > start {
            2.0 * (1.0 + params.hysteresis_ratio)
        } else {
            2.0 * (1.0 - params.hysteresis_ratio)
        };
        let lag = 2.0 * params.averaging_time_s * rate;
        println!("sweep {start} -> {end} Hz: valve moves at {f_switch:.3} Hz");
        assert!(
            (f_switch - threshold - lag).abs() < 0.06,
            "{start} -> {end} Hz: switched at {f_switch} Hz, expected {threshold} + {lag}"
        );
        assert_eq!(*record.scale_factor.last().unwrap(), target);
    }
}

/// Valve scale factors after the warm-up for the motion `x(t)`, and the number of reversals.
fn valve_after_warmup(x: impl Fn(f64) -> (f64, f64), start_closed: bool) -> (Vec<f64>, usize) {
    let damper = Damper::Fsd(
        FsdDamper::new(FsdParams {
            start_closed,
            ..FsdParams::default()
        })
        .unwrap(),
    );
    let steps = drive(&damper, 1e-3, 30.0, x);
    let decisions: Vec<bool> = steps.iter().filter(|s| s.0 > 2.0).map(|s| s.2).collect();
    let reversals = decisions.windows(2).filter(|w| w[0] != w[1]).count();
    (
        steps.iter().filter(|s| s.0 > 2.0).map(|s| s.1).collect(),
        reversals,
    )
}

#[test]
fn stroke_with_small_fast_ripple_keeps_the_valve_open() {
    // 1 Hz stroke of 3 mm with a 5 Hz ripple of 0.3 mm (a tenth): from both start states.
    let x = |t: f64| {
        let (a, b) = (3e-3, 0.3e-3);
        (
            a * (TAU * t).sin() + b * (TAU * 5.0 * t).sin(),
            a * TAU * (TAU * t).cos() + b * TAU * 5.0 * (TAU * 5.0 * t).cos(),
        )
    };
    for start_closed in [true, false] {
        let (s, reversals) = valve_after_warmup(x, start_closed);
        assert!(s.iter().all(|&s| s == 0.0), "valve not open throughout");
        assert_eq!(reversals, 0);
    }
}

#[test]
fn fast_motion_with_slow_drift_keeps_the_valve_closed() {
    // 5 Hz motion of 1 mm on a 0.3 Hz drift of 3 mm (three times larger).
    let x = |t: f64| {
        let (a, d) = (1e-3, 3e-3);
        (
            a * (TAU * 5.0 * t).sin() + d * (TAU * 0.3 * t).sin(),
            a * TAU * 5.0 * (TAU * 5.0 * t).cos() + d * TAU * 0.3 * (TAU * 0.3 * t).cos(),
        )
    };
    for start_closed in [true, false] {
        let (s, reversals) = valve_after_warmup(x, start_closed);
        let open_samples = s.iter().filter(|&&s| s != 1.0).count();
        assert_eq!(
            open_samples, 0,
            "start closed {start_closed}: valve not closed throughout"
        );
        assert_eq!(reversals, 0);
    }
}

#[test]
fn two_tone_limits_of_the_trigger_documentation() {
    // The limits stated in `fsd_trigger`: ripple up to a quarter of the stroke, drift up to six
    // times the fast motion.
    let two_tone = |slow_hz: f64, slow_m: f64, fast_m: f64| {
        move |t: f64| {
            (
                slow_m * (TAU * slow_hz * t).sin() + fast_m * (TAU * 5.0 * t).sin(),
                slow_m * TAU * slow_hz * (TAU * slow_hz * t).cos()
                    + fast_m * TAU * 5.0 * (TAU * 5.0 * t).cos(),
            )
        }
    };
    let (s, _) = valve_after_warmup(two_tone(1.0, 3e-3, 0.25 * 3e-3), true);
    assert!(
        s.iter().all(|&s| s == 0.0),
        "ripple of a quarter closed the valve"
    );
    let (s, _) = valve_after_warmup(two_tone(0.3, 6e-3, 1e-3), false);
    assert!(
        s.iter().all(|&s| s == 1.0),
        "drift of six times opened the valve"
    );
}

#[test]
fn multi_tone_noise_on_a_stroke_does_not_chatter() {
    // 1.2 Hz stroke of 4 mm plus twelve tones from 4 to 20 Hz of 0.05 mm each with spread phases
    // (a broadband ripple whose velocity is 80 % of the stroke's): the valve stays open.
    let x = |t: f64| {
        let mut x = 4e-3 * (TAU * 1.2 * t).sin();
        let mut v = 4e-3 * TAU * 1.2 * (TAU * 1.2 * t).cos();
        for i in 0..12 {
            let f = 4.0 + 16.0 * i as f64 / 11.0;
            let phase = TAU * ((i as f64 * 0.618_033_988_7) % 1.0);
            x += 0.05e-3 * (TAU * f * t + phase).sin();
            v += 0.05e-3 * TAU * f * (TAU * f * t + phase).cos();
        }
        (x, v)
    };
    let (s, reversals) = valve_after_warmup(x, true);
    assert!(s.iter().all(|&s| s == 0.0));
    assert_eq!(reversals, 0);
}

#[test]
fn hydraulic_equivalent_damping_matches_the_quadratic_closed_form() {
    // A stiff joint (1e9 N/m) isolates the orifice law: F = c_lin·v + b·v|v| per direction
    // has the equivalent damping c_lin + 8·b·ω·A/(3π) (energy balance over a cycle), averaged
    // over rebound and compression.
    for valve in [None, Some(0.0), Some(1.0)] {
        let mut params = HydraulicParams {
            series_stiffness_npm: 1e9,
            ..HydraulicParams::default()
        };
        if valve.is_some() {
            params.frequency_valve = HydraulicDamper::fsd_default().params().frequency_valve;
        }
        let damper = HydraulicDamper::new(params).unwrap();
        // Valve open at 0.5 Hz, closed at 4 Hz (after the warm-up).
        let f = if valve == Some(0.0) { 0.5 } else { 4.0 };
        let s = valve.unwrap_or(1.0);
        let (rebound, compression) = damper.laws(s);
        let a = 4e-3;
        let w = TAU * f;
        let c_closed = 0.5 * (rebound.linear_nspm + compression.linear_nspm)
            + 8.0 * w * a * 0.5 * (rebound.quadratic_ns2pm2 + compression.quadratic_ns2pm2)
                / (3.0 * PI);
        let eq = sine(&Damper::Hydraulic(damper), f, a, 8);
        assert!(
            rel(eq.damping_nspm, c_closed) < 0.01,
            "{valve:?}: {eq:?} vs {c_closed}"
        );
    }
}

#[test]
fn hydraulic_default_gives_yaw_damper_level_damping() {
    // Documented in `hydraulic`: about 670 kN·s/m at 1 Hz, 5 mm, and the open frequency valve
    // divides the turbulent part by the square of the area ratio (4).
    let damper = HydraulicDamper::new(HydraulicParams::default()).unwrap();
    let eq = sine(&Damper::Hydraulic(damper), 1.0, 5e-3, 6);
    assert!(eq.damping_nspm > 5.0e5 && eq.damping_nspm < 7.5e5, "{eq:?}");
    let fsd = HydraulicDamper::fsd_default();
    let ratio = fsd.laws(1.0).0.quadratic_ns2pm2 / fsd.laws(0.0).0.quadratic_ns2pm2;
    assert!((ratio - 4.0).abs() < 1e-9);
}

#[test]
fn bench_rejects_bad_input() {
    let damper = Damper::yd1();
    let bad = BenchMotion::Sine {
        frequency_hz: -1.0,
        amplitude_m: 1e-3,
        cycles: 3,
    };
    let err = run(&damper, &bad, &BenchOptions::default()).unwrap_err();
    assert!(err.to_string().contains("frequency_hz"));
    let bad = BenchMotion::Recorded {
        time_s: vec![0.0, 1.0, 1.0],
        displacement_m: vec![0.0; 3],
    };
    let err = run(&damper, &bad, &BenchOptions::default()).unwrap_err();
    assert!(err.to_string().contains("time_s"));
    // A microgram equivalent mass makes a pole far too fast for a 100 s run: refused, no hang.
    let stiff = Damper::Fsd(
        FsdDamper::new(FsdParams {
            equivalent_mass_kg: 1e-9,
            ..FsdParams::default()
        })
        .unwrap(),
    );
    let long = BenchMotion::Sine {
        frequency_hz: 0.1,
        amplitude_m: 1e-3,
        cycles: 10,
    };
    let err = run(&stiff, &long, &BenchOptions::default()).unwrap_err();
    assert!(err.to_string().contains("motion"), "{err}");
}

/// The reduced laws of [`Damper::for_step`] (its own file).
mod for_step;

/// The step's end forms strokes only for the dampers with a valve: the others' `advance` must
/// leave their discrete state as it was, whatever the stroke.
#[test]
fn only_dampers_with_a_valve_advance() {
    let hydraulic =
        |params: HydraulicParams| Damper::Hydraulic(HydraulicDamper::new(params).unwrap());
    let dampers = [
        Damper::yd1(),
        Damper::yd2(),
        Damper::fsd(),
        hydraulic(HydraulicParams::default()),
        Damper::Hydraulic(HydraulicDamper::fsd_default()),
    ];
    for damper in dampers {
        let mut discrete = damper.initial_discrete();
        let start = discrete;
        let states = vec![1e-3; damper.n_states()];
        for i in 0..2000 {
            let t = i as f64 * 1e-3;
            let (x, v) = (0.01 * (40.0 * t).sin(), 0.4 * (40.0 * t).cos());
            damper.advance(&mut discrete, t, 1e-3, x, v, &states);
        }
        assert_eq!(damper.valve_state(&discrete).is_some(), damper.has_valve());
        if !damper.has_valve() {
            // As text: the unset frequency estimate is NaN, which `==` never equals.
            assert_eq!(format!("{discrete:?}"), format!("{start:?}"));
        }
    }
}
