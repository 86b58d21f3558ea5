//! The gearbox bearings' damping, `c = β·k` on their axial and tilting stiffness
//! (`hollow_shaft.bearing_damping_time`, Friswell et al. 2010): each of their modes is then
//! damped at `ζ = β·ω/2` (stiffness-proportional damping on the spring that makes the mode),
//! which the linearised vehicle shows without any time integration; without it they are
//! undamped, and only RK4's numerical damping at 1 ms made them decay.

use loco_core::vehicle::linearise::least_damped;
use loco_core::vehicle::parameters::ParameterSet;
use loco_core::vehicle::scenario::{linearised, Scenario, TrackSpec};

/// The bearings' modes (axial 238 Hz, tilt 320-330 Hz) and nothing else of the vehicle.
const BEARING_BAND_HZ: (f64, f64) = (200.0, 400.0);

fn least_damped_bearing_mode(beta: Option<f64>) -> (f64, f64) {
    let mut p = ParameterSet::default_vehicle();
    if let Some(beta) = beta {
        p.set("hollow_shaft.bearing_damping_time", beta).unwrap();
    }
    let mut s = Scenario::study("S_norm", 160.0 / 3.6, 100.0, 0).unwrap();
    s.track = TrackSpec::Perfect;
    let (a, n) = linearised(p, &s).unwrap();
    let mode = least_damped(&a, n, BEARING_BAND_HZ).unwrap().unwrap();
    (mode.frequency, mode.damping_ratio)
}

#[test]
fn the_bearing_modes_are_damped_in_proportion_to_their_frequency() {
    let beta = ParameterSet::default_vehicle()
        .get("hollow_shaft.bearing_damping_time")
        .unwrap();
    let (f, zeta) = least_damped_bearing_mode(None);
    let expected = beta * std::f64::consts::PI * f;
    println!("least damped bearing mode {f:.1} Hz: ζ = {zeta:.5}, β·ω/2 = {expected:.5}");
    // The couplings' rubber adds a little; the bearing's damping is the mode's.
    assert!(
        zeta >= 0.95 * expected && zeta <= 1.1 * expected,
        "ζ {zeta} against β·ω/2 = {expected} at {f} Hz"
    );
    let (f0, zeta0) = least_damped_bearing_mode(Some(0.0));
    println!("without bearing damping {f0:.1} Hz: ζ = {zeta0:.5}");
    assert!(
        zeta0 < 0.1 * expected,
        "ζ {zeta0} at {f0} Hz without damping"
    );
}
