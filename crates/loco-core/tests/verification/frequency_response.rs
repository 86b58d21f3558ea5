//! The frequency response of the linearised vehicle against the time integration of the full
//! model: a sinusoidal irregularity of one channel (0.2 mm), the steady-state
//! amplitude and phase of a sinusoid fitted after the transient, against `H·U`.
//!
//! CI runs a representative subset; `sinusoidal_full_matrix` (ignored, run by
//! `scripts/verify/frf_verification.sh`) runs every scenario, damper, channel and wavelength and prints
//! the table docs/model/frequency_response.md reports.

use crate::record::Record;
use loco_core::dampers::Damper;
use loco_core::track::{Channel, TrackIrregularity};
use loco_core::vehicle::analysis::frequency_response::ResponseSolver;
use loco_core::vehicle::analysis::linearise::{least_damped, LinearisationSettings};
use loco_core::vehicle::analysis::track_input::{
    scenario_track_model, scenario_track_model_with, TrackInputModel,
};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::simulate;
use loco_core::vehicle::scenarios::scenario::{start_distance, Scenario, TrackSpec};
use loco_core::Result;
use nalgebra::Complex;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::Arc;

/// Irregularity amplitude, m (0.2 mm).
const AMPLITUDE: f64 = 2e-4;
/// Speed, m/s (200 km/h).
const SPEED: f64 = 200.0 / 3.6;
/// Outputs compared: wheelset lateral displacement, frame and carbody floor lateral acceleration.
const OUTPUTS: [&str; 3] = [
    "wheelset1_y",
    "frame1_ay_wheelset1",
    "carbody_floor_ay_front",
];
/// Time run before the fit, s: the least damped body mode at 200 km/h decays by e^-4 or more.
const SETTLE: f64 = 16.0;
/// Amplitude and phase tolerances of the comparison.
const AMPLITUDE_TOLERANCE: f64 = 0.05;
const PHASE_TOLERANCE_DEG: f64 = 5.0;

fn damper(name: &str) -> Damper {
    match name {
        "YD1" => Damper::yd1(),
        "YD2" => Damper::yd2(),
        _ => Damper::fsd(),
    }
}

fn scenario(name: &str, yaw: &str) -> Scenario {
    let mut s = Scenario::study(name, SPEED, 100.0, 0).unwrap();
    s.yaw_damper = Some(damper(yaw));
    s
}

/// A track whose `channel` is `AMPLITUDE · sin(k s)` after a 60 m cosine run-in, others zero.
fn sine_track(channel: Channel, wavelength: f64, length: f64) -> TrackIrregularity {
    let step = 0.1;
    let n = (length / step).ceil() as usize + 1;
    let k = 2.0 * PI / wavelength;
    let zero = vec![0.0; n];
    let mut values = [zero.clone(), zero.clone(), zero.clone(), zero.clone()];
    let mut slopes = [zero.clone(), zero.clone(), zero.clone(), zero];
    for i in 0..n {
        let s = i as f64 * step;
        values[channel.index()][i] = AMPLITUDE * (k * s).sin();
        slopes[channel.index()][i] = AMPLITUDE * k * (k * s).cos();
    }
    TrackIrregularity::from_channels(step, &values, &slopes, 60.0, None).unwrap()
}

/// Complex amplitude `a − i b` of the least-squares fit `a cos ωt + b sin ωt + c` to `y(t)`.
fn fit_sinusoid(t: &[f64], y: &[f64], omega: f64) -> Complex<f64> {
    let mut m = nalgebra::Matrix3::<f64>::zeros();
    let mut r = nalgebra::Vector3::<f64>::zeros();
    for (&ti, &yi) in t.iter().zip(y) {
        let basis = nalgebra::Vector3::new((omega * ti).cos(), (omega * ti).sin(), 1.0);
        m += basis * basis.transpose();
        r += basis * yi;
    }
    let x = m.lu().solve(&r).unwrap();
    Complex::new(x[0], -x[1])
}

/// One case's measured and linear complex amplitudes of [`OUTPUTS`].
struct Case {
    time_domain: Vec<Complex<f64>>,
    linear: Vec<Complex<f64>>,
}

/// Runs the full model on the sine track and evaluates the linear model's response to it.
fn run_case(
    model: &TrackInputModel,
    base: &Scenario,
    channel: Channel,
    wavelength: f64,
) -> Result<Case> {
    let f = SPEED / wavelength;
    let omega = 2.0 * PI * f;
    // At least 4 periods and 4 s, a whole number of periods.
    let periods = (4.0f64).max((4.0 * f).ceil());
    let fit = periods / f;
    let lead_in = SETTLE * SPEED;
    let mut s = base.clone();
    s.lead_in = lead_in;
    s.distance = fit * SPEED;
    s.track = TrackSpec::Given(Arc::new(sine_track(
        channel,
        wavelength,
        lead_in + s.distance + 40.0,
    )));
    let result = simulate(ParameterSet::default_vehicle(), &s)?;
    let out = &result.output;
    let dt = s.run.step;
    let t0 = (SETTLE / dt).round() * dt;
    let t: Vec<f64> = out.time.iter().map(|t| t + t0).collect();
    let time_domain = OUTPUTS
        .iter()
        .map(|name| fit_sinusoid(&t, out.channel(name).unwrap(), omega))
        .collect();
    // The channel at the vehicle origin: Im(A e^{ik s_o}), s_o = start + V t.
    let structure = VehicleStructure::new(ParameterSet::default_vehicle())?;
    let k = 2.0 * PI / wavelength;
    let u0 =
        Complex::new(0.0, -AMPLITUDE) * Complex::from_polar(1.0, k * start_distance(&structure));
    let names: Vec<String> = OUTPUTS.iter().map(|s| s.to_string()).collect();
    let h = ResponseSolver::new(model, &names)?.response(&[channel], &[f])?;
    let linear = (0..OUTPUTS.len()).map(|o| h.at(o, 0, 0) * u0).collect();
    Ok(Case {
        time_domain,
        linear,
    })
}

/// Amplitude ratio error and phase difference (deg) of a measured vs a linear amplitude.
fn compare(measured: Complex<f64>, linear: Complex<f64>) -> (f64, f64) {
    let ratio = measured / linear;
    (ratio.norm() - 1.0, ratio.arg().to_degrees())
}

/// Checks the lateral outputs of a channel that moves the vehicle laterally; returns the worst
/// (amplitude error, phase error).
fn check_case(label: &str, case: &Case) -> (f64, f64) {
    let mut worst = (0.0f64, 0.0f64);
    for (o, name) in OUTPUTS.iter().enumerate() {
        let (da, dp) = compare(case.time_domain[o], case.linear[o]);
        println!(
            "{label} {name}: |z| time {:.4e} linear {:.4e} ({:+.2} %), phase {:+.2} deg",
            case.time_domain[o].norm(),
            case.linear[o].norm(),
            100.0 * da,
            dp
        );
        worst = (worst.0.max(da.abs()), worst.1.max(dp.abs()));
    }
    worst
}

/// Whether the linear model is stable (least damped mode in 0.3–20 Hz has positive damping).
fn linearly_stable(model: &TrackInputModel) -> bool {
    least_damped(&model.a, model.n, (0.3, 20.0))
        .unwrap()
        .is_none_or(|m| m.damping_ratio > 0.0)
}

const WAVELENGTHS: [f64; 4] = [20.0, 40.0, 70.0, 150.0];

/// Checks every wavelength of one scenario, damper and channel with the default linearisation,
/// and records the worst amplitude and phase errors.
fn lateral_channel_cases(name: &str, yaw: &str, channel: Channel) {
    let (amplitude, phase) =
        lateral_channel_cases_with(name, yaw, channel, &LinearisationSettings::default());
    let case = format!("frf_{}_{}_{}", name, yaw, channel.name()).to_lowercase();
    Record::new(&case.replace(['-', ' '], "_"), file!())
        .count("wavelengths", WAVELENGTHS.len())
        .within("amplitude", amplitude, "", 2, "<", AMPLITUDE_TOLERANCE)
        .within("phase", phase, "deg", 2, "<", PHASE_TOLERANCE_DEG)
        .check();
}

fn lateral_channel_cases_with(
    name: &str,
    yaw: &str,
    channel: Channel,
    settings: &LinearisationSettings,
) -> (f64, f64) {
    let base = scenario(name, yaw);
    let model =
        scenario_track_model_with(ParameterSet::default_vehicle(), &base, settings).unwrap();
    assert!(linearly_stable(&model), "{name} {yaw} is linearly unstable");
    let results: Vec<(f64, Case)> = WAVELENGTHS
        .par_iter()
        .map(|&w| (w, run_case(&model, &base, channel, w).unwrap()))
        .collect();
    let mut worst = (0.0_f64, 0.0_f64);
    for (w, case) in &results {
        let label = format!("{name} {yaw} {} {w} m", channel.name());
        let (da, dp) = check_case(&label, case);
        assert!(da < AMPLITUDE_TOLERANCE, "{label}: amplitude off by {da}");
        assert!(dp < PHASE_TOLERANCE_DEG, "{label}: phase off by {dp} deg");
        worst = (worst.0.max(da), worst.1.max(dp));
    }
    worst
}

#[test]
fn alignment_s_low_yd2_matches_the_linear_response() {
    lateral_channel_cases("S_low", "YD2", Channel::Alignment);
}

/// The case that tells the linearisation steps apart (S_norm + YD1 alignment at 20 m, near a
/// resonance): with the default one step of 1e-7 the carbody is −11.4 % / −5.4°; with the two
/// groups of steps (`LinearisationSettings::two_groups`, the candidate default) it is inside the
/// band (+1.2 % / +2.5°, −4.5 % / −0.1°).
#[test]
#[ignore = "the candidate steps; run with --ignored (a few minutes on 2 cores)"]
fn alignment_s_norm_yd1_with_the_two_groups_of_steps() {
    let settings = LinearisationSettings::two_groups();
    let _ = lateral_channel_cases_with("S_norm", "YD1", Channel::Alignment, &settings);
}

/// A difference step that is not a positive number is refused, naming the field.
#[test]
fn a_non_positive_linearisation_step_is_refused() {
    let base = scenario("S_norm", "YD2");
    for step in [0.0, -1e-5, f64::NAN] {
        let defaults = LinearisationSettings::default();
        for (field, settings) in [
            ("step", LinearisationSettings { step, ..defaults }),
            (
                "contact_step",
                LinearisationSettings {
                    contact_step: step,
                    ..defaults
                },
            ),
        ] {
            let err = scenario_track_model_with(ParameterSet::default_vehicle(), &base, &settings)
                .unwrap_err();
            assert!(err.to_string().contains(field), "{step}: {err}");
        }
    }
}

#[test]
fn alignment_s_high_yd2_matches_the_linear_response() {
    lateral_channel_cases("S_high", "YD2", Channel::Alignment);
}

#[test]
fn cross_level_s_high_yd2_matches_the_linear_response() {
    lateral_channel_cases("S_high", "YD2", Channel::CrossLevel);
}

/// Before the contact was read in the rails' plane, 0.2 mm of cross level at 40 m moved the
/// S_low wheelsets by 3.5 mm (YD2) to 7.8 mm (YD1), far beyond the linear range (time domain 19–24 % below the
/// linear response); rolled with the rails they move by about h0·θ.
#[test]
fn cross_level_s_low_yd2_matches_the_linear_response() {
    lateral_channel_cases("S_low", "YD2", Channel::CrossLevel);
}

/// Vertical profile and gauge move the rails symmetrically: neither the model nor its
/// linearisation moves the vehicle laterally (below 1e-8 of the alignment response).
#[test]
fn symmetric_channels_leave_the_lateral_motion_alone() {
    let base = scenario("S_norm", "YD2");
    let model = scenario_track_model(ParameterSet::default_vehicle(), &base).unwrap();
    let cases: Vec<Case> = [Channel::Alignment, Channel::Vertical, Channel::Gauge]
        .par_iter()
        .map(|&c| run_case(&model, &base, c, 40.0).unwrap())
        .collect();
    let mut worst = 0.0_f64;
    for case in &cases[1..] {
        for (o, name) in OUTPUTS.iter().enumerate() {
            let reference = cases[0].time_domain[o].norm();
            assert!(case.time_domain[o].norm() < 1e-8 * reference, "{name}");
            assert!(case.linear[o].norm() < 1e-8 * reference, "{name}");
            worst = worst
                .max(case.time_domain[o].norm() / reference)
                .max(case.linear[o].norm() / reference);
        }
    }
    Record::new("frf_symmetric_channels", file!())
        .below("lateral_of_alignment_response", worst, "", 1e-9, "<", 1e-8)
        .check();
}

/// Hand check of the wheelset delays: on a long alignment wave (λ = 2 km, 0.028 Hz) every
/// wheelset follows the track centre line quasi-statically, so `H(wheelset w_y) → e^{ik x_w}`:
/// unit gain and the phase of the wheelset's own position, k·x_w (a trailing wheelset lags the
/// leading one by k·Δx).
#[test]
fn wheelsets_follow_a_long_alignment_wave_with_their_delays() {
    let base = scenario("S_norm", "YD2");
    let model = scenario_track_model(ParameterSet::default_vehicle(), &base).unwrap();
    let names: Vec<String> = (1..=4).map(|w| format!("wheelset{w}_y")).collect();
    let wavelength = 2000.0;
    let k = 2.0 * PI / wavelength;
    let h = ResponseSolver::new(&model, &names)
        .unwrap()
        .response(&[Channel::Alignment], &[SPEED / wavelength])
        .unwrap();
    for w in 0..4 {
        let expected = Complex::from_polar(1.0, k * model.wheelset_x[w]);
        let error = (h.at(w, 0, 0) - expected).norm();
        println!(
            "wheelset{} H = {:.5} expected {:.5}",
            w + 1,
            h.at(w, 0, 0),
            expected
        );
        // k·x_w reaches 0.019 rad; the quasi-static tracking error is O((k·L)²) ≈ 1e-3.
        assert!(error < 2e-3, "wheelset{}: |H − e^(ikx)| = {error}", w + 1);
    }
    let lag = (h.at(0, 0, 0) / h.at(3, 0, 0)).arg();
    let dx = model.wheelset_x[0] - model.wheelset_x[3];
    assert!(
        (lag - k * dx).abs() < 1e-4,
        "lag {lag} rad vs k·Δx {}",
        k * dx
    );
    let worst = (0..4)
        .map(|w| (h.at(w, 0, 0) - Complex::from_polar(1.0, k * model.wheelset_x[w])).norm())
        .fold(0.0, f64::max);
    Record::new("frf_wheelset_delays", file!())
        .within("tracking_error", worst, "", 2, "<", 2e-3)
        .within("lag_error", (lag - k * dx).abs(), "rad", 2, "<", 1e-4)
        .check();
}

/// Every scenario, damper, channel and wavelength; prints the table (run by
/// `scripts/verify/frf_verification.sh`). Vertical and gauge inputs move the vehicle symmetrically:
/// their lateral responses are reported, not compared.
#[test]
#[ignore = "about 7 minutes on 2 cores: the full matrix, run by scripts/verify/frf_verification.sh"]
fn sinusoidal_full_matrix() {
    // The linearisation steps: `FRF_STEP` and `FRF_CONTACT_STEP` if set, else the defaults.
    let defaults = LinearisationSettings::default();
    let from_env = |name: &str, default: f64| {
        std::env::var(name).map_or(default, |v| v.parse().expect("a number"))
    };
    let settings = LinearisationSettings {
        step: from_env("FRF_STEP", defaults.step),
        contact_step: from_env("FRF_CONTACT_STEP", defaults.contact_step),
    };
    println!(
        "linearisation steps {:e} (Hertz side), {:e} (across the contact)",
        settings.step, settings.contact_step
    );
    let mut lines = Vec::new();
    for name in ["S_low", "S_norm", "S_high"] {
        for yaw in ["YD1", "YD2", "FSD"] {
            let base = scenario(name, yaw);
            let model =
                scenario_track_model_with(ParameterSet::default_vehicle(), &base, &settings)
                    .unwrap();
            if !linearly_stable(&model) {
                lines.push(format!("{name} {yaw}: linearly unstable, skipped"));
                continue;
            }
            let cases: Vec<(Channel, f64)> = Channel::ALL
                .iter()
                .flat_map(|&c| WAVELENGTHS.iter().map(move |&w| (c, w)))
                .collect();
            let results: Vec<_> = cases
                .par_iter()
                .map(|&(c, w)| (c, w, run_case(&model, &base, c, w)))
                .collect();
            for (c, w, case) in results {
                let label = format!("{name} {yaw} {} {w} m", c.name());
                match case {
                    Err(e) => lines.push(format!("{label}: run failed: {e}")),
                    Ok(case) => {
                        let mut line = label.clone();
                        for (o, out) in OUTPUTS.iter().enumerate() {
                            let (da, dp) = compare(case.time_domain[o], case.linear[o]);
                            line += &format!(
                                " | {out} td {:.3e} lin {:.3e} {:+.1}% {:+.1}deg",
                                case.time_domain[o].norm(),
                                case.linear[o].norm(),
                                100.0 * da,
                                dp
                            );
                        }
                        lines.push(line);
                    }
                }
            }
        }
    }
    println!("{}", lines.join("\n"));
}
