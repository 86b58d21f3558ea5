use super::*;

/// A matrix with known eigenvalues: a similarity transform of a diagonal (and one rotation
/// block, a complex pair) by a fixed well-conditioned matrix.
fn known(values: &[f64], pair: (f64, f64)) -> DMatrix<f64> {
    let n = values.len() + 2;
    let mut d = DMatrix::zeros(n, n);
    for (i, v) in values.iter().enumerate() {
        d[(i, i)] = *v;
    }
    let (re, im) = pair;
    d[(n - 2, n - 2)] = re;
    d[(n - 1, n - 1)] = re;
    d[(n - 2, n - 1)] = im;
    d[(n - 1, n - 2)] = -im;
    let s = DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            2.0
        } else {
            0.3 * ((i * 7 + j * 3) as f64).sin() / (1.0 + (i as f64 - j as f64).abs())
        }
    });
    let inv = s.clone().try_inverse().unwrap();
    &s * d * inv
}

#[test]
fn arnoldi_finds_the_largest_modulus_among_clustered_and_complex_eigenvalues() {
    // A cluster of four nearly equal stiff modes (the quills), a spread below, and a complex
    // pair that is the largest in one case and not in the other.
    let mut values: Vec<f64> = (0..80).map(|i| -1e3 * (1.0 + i as f64).powi(2)).collect();
    values.extend([-4.0e7, -4.0e7 * (1.0 + 1e-7), -3.99e7, -3.9e7]);
    let cases = [
        ((-1e5, 2e5), 4.0e7 * (1.0 + 1e-7)),
        ((-3e7, 3e7), 3e7 * 2f64.sqrt()),
    ];
    for (pair, expected) in cases {
        let a = known(&values, pair);
        let found = largest_modulus(&a);
        // Within the cluster's width (1e-7), far finer than a step decision needs.
        assert!(
            (found / expected - 1.0).abs() < 2e-7,
            "{found} against {expected}"
        );
    }
}

/// The Jacobian and the M⁻¹J of the default vehicle (`bearing`: the quill bearings' radial
/// stiffness, N/m, allowed out of range) at its equilibrium on S_norm.
fn vehicle_matrix(bearing: Option<f64>) -> (VehicleSystem, Equilibrium, DMatrix<f64>) {
    use crate::vehicle::model::structure::VehicleStructure;
    use crate::vehicle::params::parameters::ParameterSet;
    use crate::vehicle::scenarios::scenario::{build_track, start_distance, Scenario, TrackSpec};
    use crate::vehicle::scenarios::scenario_contact::build_wheel_rail;
    use crate::vehicle::system::statics::{static_equilibrium, StaticsSettings};
    use std::sync::Arc;
    let mut set = ParameterSet::default_vehicle();
    if let Some(k) = bearing {
        let key = "hollow_shaft.bearing_radial_stiffness";
        set.allow_out_of_range(key).unwrap();
        set.set(key, k).unwrap();
    }
    let mut s = Scenario::study("S_norm", 200.0 / 3.6, 3.0, 0).unwrap();
    s.track = TrackSpec::Perfect;
    let structure = Arc::new(VehicleStructure::new(set).unwrap());
    let wr = Arc::new(build_wheel_rail(&structure.parameters, &s).unwrap());
    let track = Arc::new(build_track(&s, &structure).unwrap());
    let start = start_distance(&structure);
    let mut sys = VehicleSystem::new(structure, wr, track, s.speed, start, None, 1e-3).unwrap();
    // The full spectrum: the scheme that takes every mode in its stages.
    sys.integrator = Integrator::Rk4;
    let eq = static_equilibrium(&mut sys, &StaticsSettings::default()).unwrap();
    let m = DMatrix::from_fn(N_DOF, N_DOF, |i, j| sys.structure.mass.get(i, j));
    let a = m.lu().solve(&eq.jacobian).unwrap();
    (sys, eq, a)
}

#[test]
fn the_vehicles_stiffest_mode_is_the_full_spectrums_largest() {
    // Against the whole spectrum of M⁻¹J (dense LU of M, QR), the way it was computed before.
    for bearing in [None, Some(2e10)] {
        let (sys, eq, a) = vehicle_matrix(bearing);
        let exact = full_largest(&a).sqrt();
        let mode = stiffest_mode(&sys, &eq);
        assert!(
            (mode.omega / exact - 1.0).abs() < 1e-8,
            "{bearing:?}: {} against {exact}",
            mode.omega
        );
        eprintln!(
            "{bearing:?}: ω = {:.6e} rad/s, `{}`",
            mode.omega, mode.coordinate
        );
    }
}

#[test]
fn the_gearbox_bearings_are_the_stiffest_modes_and_the_rest_fits_a_2_ms_step() {
    // Independent of the exponential scheme: the full vehicle's stiffest mode (Arnoldi on the
    // equilibrium Jacobian) against the bearings' own system `J M⁻¹ Jᵀ K`, and what is left
    // when the bearings are taken out of the Jacobian.
    let (mut sys, eq, _) = vehicle_matrix(None);
    let full = stiffest_mode(&sys, &eq);
    let bearings = gearbox_bearings(&sys.structure).frequencies();
    let own = *bearings.last().unwrap();
    eprintln!(
        "full {:.1} rad/s `{}`; bearings {:.1}–{own:.1} rad/s",
        full.omega, full.coordinate, bearings[0]
    );
    assert!(
        (own / full.omega - 1.0).abs() < 0.01,
        "{own} against {}",
        full.omega
    );
    sys.integrator = Integrator::ExponentialRk4;
    let rest = stiffest_mode(&sys, &eq);
    eprintln!(
        "without the bearings {:.1} rad/s `{}`",
        rest.omega, rest.coordinate
    );
    assert!(
        rest.omega < bearings[0],
        "{} not below the bearings",
        rest.omega
    );
    assert!(rest.omega * 2e-3 <= RK4_IMAGINARY_LIMIT, "{}", rest.omega);
}
