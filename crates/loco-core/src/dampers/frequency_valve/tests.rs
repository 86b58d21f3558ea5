//! Tests of the hydraulic frequency valve against hand calculations and the bench.

use super::*;
use crate::dampers::bench::{run, BenchMotion, BenchOptions};
use crate::dampers::ValveDesign;
use crate::dampers::{Damper, FsdDamper, FsdParams};

fn spec_closed() -> ClosedModule {
    FsdParams::default().closed_module()
}

fn spec_valve() -> HydraulicValve {
    *FsdDamper::spec_hydraulic().hydraulic_valve().unwrap()
}

#[test]
fn chamber_filling_matches_the_turbulent_closed_form() {
    // A nearly free piston (spring 1e-6 of the design's) under p = P·sin ωt from the centre:
    // the half-cycle passes V_½ = C_d·A_o·√(2P/ρ)·I/ω (hand integral of Q = C_d·A_o·√(2p/ρ)),
    // less the laminar drop, which at this pressure (Re ≈ 10³) is a small correction.
    let base = spec_valve().params;
    let valve = HydraulicValve::new(HydraulicValveParams {
        spring_stiffness_npm: base.spring_stiffness_npm * 1e-6,
        ..base
    })
    .unwrap();
    let (pressure, omega) = (4e6, TAU * 1.5);
    let n = 20_000;
    let dt = PI / omega / n as f64;
    let mut v = 0.0;
    for i in 1..=n {
        let p = pressure * (omega * i as f64 * dt).sin();
        v = valve.step(v, p * base.piston_area_m2, dt);
    }
    let closed_form = base.flow_coefficient
        * base.orifice_area_m2
        * (2.0 * pressure / base.oil_density_kgpm3).sqrt()
        * SQRT_SINE_INTEGRAL
        / omega;
    let ratio = v / closed_form;
    // Laminar share at the peak: r·Q/p with Q the turbulent flow; it lowers the flow by less.
    let q_peak = closed_form * omega / SQRT_SINE_INTEGRAL;
    let laminar_share = valve.laminar * q_peak / pressure;
    assert!(
        ratio < 1.0 && ratio > 1.0 - 2.0 * laminar_share - 2e-3,
        "{ratio} (laminar share {laminar_share})"
    );
    // The orbit solver (RK4 shooting, independent of the implicit step): the centred piston
    // swings ±V_½/2.
    let peak = valve.orbit_peak_volume(pressure, omega) / (0.5 * closed_form);
    assert!(
        peak < 1.0 && peak > 1.0 - 2.0 * laminar_share - 2e-3,
        "orbit peak over V_½/2: {peak}"
    );
}

#[test]
fn derived_cutoff_at_the_reference_amplitude_is_f_p() {
    let valve = spec_valve();
    let (lower, upper) = valve
        .opening_band_hz(&spec_closed(), REFERENCE_STROKE_AMPLITUDE_M)
        .unwrap();
    assert!((upper - 2.0).abs() < 0.01, "cut-off {upper} Hz");
    // From closed, the spring's quasi-static limit is where the c2 pressure equals the c1
    // pressure at f_l = 0.5 Hz: about f_l·c1/c2 = 0.125 Hz, a little above it (the orbit at a
    // finite frequency needs more than the quasi-static balance).
    assert!(lower > 0.12 && lower < 0.2, "lower limit {lower} Hz");
    // Amplitude dependence: about proportional below the series spring's corner (3 Hz).
    let (_, half) = valve
        .opening_band_hz(&spec_closed(), 0.5 * REFERENCE_STROKE_AMPLITUDE_M)
        .unwrap();
    assert!(
        half > 0.8 && half < 1.2,
        "cut-off at half the amplitude {half} Hz"
    );
    let (_, double) = valve
        .opening_band_hz(&spec_closed(), 2.0 * REFERENCE_STROKE_AMPLITUDE_M)
        .unwrap();
    assert!(
        double > upper && double < 4.0,
        "cut-off at twice the amplitude {double} Hz"
    );
}

#[test]
fn the_bands_of_several_amplitudes_are_each_amplitudes_band_in_order() {
    let (valve, closed) = (spec_valve(), spec_closed());
    // From 0.02 mm, where the valve opens nowhere, to 8 mm.
    let amplitudes: Vec<f64> = (0..9).map(|i| 2e-5 * 2f64.powi(i)).collect();
    let bands = valve.opening_bands_hz(&closed, &amplitudes).unwrap();
    assert_eq!(bands.len(), amplitudes.len());
    for (x, band) in amplitudes.iter().zip(&bands) {
        assert_eq!(*band, valve.opening_band_hz(&closed, *x), "{x} m");
    }
    assert!(bands.iter().any(Option::is_some) && bands.iter().any(Option::is_none));
    let err = valve.opening_bands_hz(&closed, &[1e-3, -1e-3]).unwrap_err();
    assert!(err.to_string().contains("amplitudes"), "{err}");
}

/// Fraction of the last `tail` seconds with the valve open (scale factor 0).
fn open_fraction(damper: &Damper, motion: &BenchMotion, tail: f64) -> f64 {
    let opts = BenchOptions {
        steps_per_cycle: 400,
        samples_per_cycle: 100,
        equivalent_cycles: 1,
    };
    let r = run(damper, motion, &opts).unwrap();
    let t_end = *r.time_s.last().unwrap();
    let tail: Vec<f64> = r
        .time_s
        .iter()
        .zip(&r.scale_factor)
        .filter(|(t, _)| **t >= t_end - tail)
        .map(|(_, s)| *s)
        .collect();
    tail.iter().filter(|s| **s < 1.0).count() as f64 / tail.len() as f64
}

#[test]
fn bench_opens_below_and_stays_closed_above_the_cutoff() {
    // The damper on the bench (real force, Maxwell phase, 10 s to leave the start transient):
    // 5 % either side of the derived cut-off at the reference amplitude.
    let damper = Damper::fsd_hydraulic();
    let sine = |f: f64| BenchMotion::Sine {
        frequency_hz: f,
        amplitude_m: REFERENCE_STROKE_AMPLITUDE_M,
        cycles: (12.0 * f) as usize,
    };
    assert!(open_fraction(&damper, &sine(1.9), 3.0) > 0.2);
    assert_eq!(open_fraction(&damper, &sine(2.1), 3.0), 0.0);
    // 1.2 Hz sway opens it in every half-cycle, 4 Hz never. A valve that times each
    // half-cycle opens late in it: with V_½ ∝ f^-1/2 the centred piston needs about 89 % of the
    // half-cycle's flow at 1.2 Hz before it opens, so it is open for part of each stroke only.
    assert!(open_fraction(&damper, &sine(1.2), 3.0) > 0.3);
    assert_eq!(open_fraction(&damper, &sine(4.0), 3.0), 0.0);
}

#[test]
fn switching_takes_the_delay_after_the_piston_passes_its_stroke() {
    let fsd = FsdDamper::spec_hydraulic();
    let valve = *fsd.hydraulic_valve().unwrap();
    let mut trigger = crate::dampers::TriggerMemory::new(true);
    let mut scale = 1.0;
    let dt = 1e-4;
    // A constant force well above the opening pressure fills the chamber; count the steps from
    // the first step with the piston past its stroke to the scale factor reaching 0.
    let force = 3.0 * valve.opening_pressure_pa() * valve.params().piston_area_m2;
    let mut passed = None;
    for i in 0..200_000 {
        fsd.advance_valve(&mut trigger, &mut scale, dt, 0.0, 0.0, force);
        if passed.is_none() && valve.is_open(trigger.valve_volume_m3) {
            passed = Some(i);
        }
        if scale == 0.0 {
            let steps = i - passed.unwrap();
            assert!((steps as f64 * dt - 0.05).abs() < 1.5 * dt, "{steps} steps");
            return;
        }
    }
    panic!("the valve never opened");
}

#[test]
fn dither_on_the_sway_closes_the_valve_only_when_it_dominates() {
    // 1.2 Hz stroke at the reference amplitude plus a 10 Hz dither: a dither of 5 % of the
    // stroke leaves the valve opening, one of the stroke's own amplitude (8x its velocity, the
    // flow reversing every dither cycle) keeps it closed.
    let damper = Damper::fsd_hydraulic();
    let x = REFERENCE_STROKE_AMPLITUDE_M;
    let two_tone = |ratio: f64| {
        let dt = 1e-3;
        let time_s: Vec<f64> = (0..12_000).map(|i| i as f64 * dt).collect();
        let displacement_m = time_s
            .iter()
            .map(|t| x * (TAU * 1.2 * t).sin() + ratio * x * (TAU * 10.0 * t).sin())
            .collect();
        BenchMotion::Recorded {
            time_s,
            displacement_m,
        }
    };
    assert!(open_fraction(&damper, &two_tone(0.05), 4.0) > 0.3);
    assert_eq!(open_fraction(&damper, &two_tone(1.0), 4.0), 0.0);
}

#[test]
fn non_physical_parameters_are_refused_naming_the_field() {
    let field = |e: crate::LocoError| e.to_string();
    let g = HydraulicValveParams::default_geometry();
    let zero_orifice = HydraulicValveParams {
        orifice_area_m2: 0.0,
        ..g
    };
    assert!(field(HydraulicValve::new(zero_orifice).unwrap_err()).contains("orifice_area_m2"));
    let negative_volume = HydraulicValveParams {
        opening_stroke_m: -1e-3,
        ..g
    };
    assert!(field(HydraulicValve::new(negative_volume).unwrap_err()).contains("opening_stroke_m"));
    let unreachable = ValveDesign {
        lowest_holding_frequency_hz: 2.5,
        ..ValveDesign::spec(REFERENCE_STROKE_AMPLITUDE_M)
    };
    let open = FsdParams::default().open_module();
    assert!(
        field(unreachable.derive(&spec_closed(), &open).unwrap_err())
            .contains("lowest_holding_frequency_hz")
    );
    let no_amplitude = ValveDesign::spec(f64::NAN);
    assert!(
        field(no_amplitude.derive(&spec_closed(), &open).unwrap_err())
            .contains("reference_stroke_amplitude_m")
    );
    assert!(
        field(FsdDamper::spec().with_hydraulic_valve(-1e-3).unwrap_err())
            .contains("reference_stroke_amplitude_m")
    );
}
