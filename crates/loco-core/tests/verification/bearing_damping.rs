//! The damping of the light bodies' stiff modes (the gearbox bearings' first, whence the name),
//! each a time `β` times the stiffness of the spring that makes the mode (`c = β·k`): each mode
//! is then damped at `ζ = β·ω/2`, which the linearised vehicle shows without any time
//! integration; without it they are undamped.
//!
//! The gearbox bearings (`hollow_shaft.bearing_damping_time`, Friswell et al. 2010): only RK4's
//! numerical damping at 1 ms made their modes decay. The traction rods' rubber nodes
//! (`traction_rod.bushing_damping_time`, loss factor 0.1 at the rod modes): without it the rods'
//! 49 Hz modes kept 0.13 % of damping from the frames, and the ringing a curve transition starts
//! was still 3e-3 rad/s² in the frames' roll 200 m on (`tests/verification/curving.rs`).

use crate::record::Record;
use loco_core::vehicle::analysis::linearise::least_damped;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::runs::simulate::linearised;
use loco_core::vehicle::scenarios::scenario::{Scenario, TrackSpec};

/// The bearings' modes (axial 238 Hz, tilt 320-330 Hz) and nothing else of the vehicle.
const BEARING_BAND_HZ: (f64, f64) = (200.0, 400.0);
/// The traction rods' modes (yaw and pitch on their nodes, 49 Hz) and nothing else: the bogie
/// frames' are below 40 Hz, the rotary arms' above 80 Hz.
const ROD_BAND_HZ: (f64, f64) = (40.0, 60.0);

/// The least damped mode in `band` (frequency Hz, damping ratio) with `key` set to `beta`.
fn least_damped_mode(key: &str, beta: Option<f64>, band: (f64, f64)) -> (f64, f64) {
    let mut p = ParameterSet::default_vehicle();
    if let Some(beta) = beta {
        p.set(key, beta).unwrap();
    }
    let mut s = Scenario::study("S_norm", 160.0 / 3.6, 100.0, 0).unwrap();
    s.track = TrackSpec::Perfect;
    let (a, n) = linearised(p, &s).unwrap();
    let mode = least_damped(&a, n, band).unwrap().unwrap();
    (mode.frequency, mode.damping_ratio)
}

#[test]
fn the_bearing_modes_are_damped_in_proportion_to_their_frequency() {
    let beta = ParameterSet::default_vehicle()
        .get("hollow_shaft.bearing_damping_time")
        .unwrap();
    let key = "hollow_shaft.bearing_damping_time";
    let (f, zeta) = least_damped_mode(key, None, BEARING_BAND_HZ);
    let expected = beta * std::f64::consts::PI * f;
    println!("least damped bearing mode {f:.1} Hz: ζ = {zeta:.5}, β·ω/2 = {expected:.5}");
    // The couplings' rubber adds a little; the bearing's damping is the mode's.
    assert!(
        zeta >= 0.95 * expected && zeta <= 1.1 * expected,
        "ζ {zeta} against β·ω/2 = {expected} at {f} Hz"
    );
    let (f0, zeta0) = least_damped_mode(key, Some(0.0), BEARING_BAND_HZ);
    println!("without bearing damping {f0:.1} Hz: ζ = {zeta0:.5}");
    assert!(
        zeta0 < 0.1 * expected,
        "ζ {zeta0} at {f0} Hz without damping"
    );
    Record::new("bearing_damping_bearings", file!())
        .value("time_constant", beta, "s", 2)
        .value("frequency", f, "Hz", 3)
        .value("expected_damping_ratio", expected, "", 2)
        .within("damping_ratio", zeta, "", 3, "≤", 1.1 * expected)
        .within("damping_ratio_without", zeta0, "", 1, "<", 0.1 * expected)
        .check();
}

#[test]
fn the_traction_rod_modes_are_damped_by_their_rubber_nodes() {
    let key = "traction_rod.bushing_damping_time";
    let beta = ParameterSet::default_vehicle().get(key).unwrap();
    let (f, zeta) = least_damped_mode(key, None, ROD_BAND_HZ);
    let expected = beta * std::f64::consts::PI * f;
    println!("least damped rod mode {f:.1} Hz: ζ = {zeta:.5}, β·ω/2 = {expected:.5}");
    // The frames and carbody at the nodes' other ends add a little.
    assert!(
        zeta >= 0.95 * expected && zeta <= 1.1 * expected,
        "ζ {zeta} against β·ω/2 = {expected} at {f} Hz"
    );
    let (f0, zeta0) = least_damped_mode(key, Some(0.0), ROD_BAND_HZ);
    println!("without node damping {f0:.1} Hz: ζ = {zeta0:.5}");
    assert!(
        zeta0 < 0.1 * expected,
        "ζ {zeta0} at {f0} Hz without damping"
    );
    Record::new("bearing_damping_traction_rods", file!())
        .value("time_constant", beta, "s", 2)
        .value("frequency", f, "Hz", 3)
        .value("expected_damping_ratio", expected, "", 2)
        .within("damping_ratio", zeta, "", 3, "≤", 1.1 * expected)
        .within("damping_ratio_without", zeta0, "", 1, "<", 0.1 * expected)
        .check();
}
