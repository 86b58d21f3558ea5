//! Contact geometry on synthetic profiles with analytical answers (no reference data needed).

use loco_core::contact::*;

/// A "knife-edge" rail: an apex rounded with radius `rho` between two steep flanks at ±`alpha`,
/// apex at (0, 0). Returns the profile and the lateral distance apex → gauge point at `depth`.
fn knife_rail(rho: f64, alpha: f64, depth: f64) -> (Profile, f64) {
    let flank = 0.02;
    let start_y = -(rho * alpha.sin() + flank * alpha.cos());
    let start_z = -(rho * (1.0 - alpha.cos()) + flank * alpha.sin());
    let rail = ProfileBuilder::new(start_y, start_z, alpha)
        .line(flank)
        .arc(rho, -2.0 * alpha)
        .line(flank)
        .build("knife", ProfileKind::Rail, 2e-5)
        .unwrap();
    let to_gauge = rho * alpha.sin() + (depth - rho * (1.0 - alpha.cos())) / alpha.tan();
    (rail, to_gauge)
}

/// A purely conical wheel z = λ·t (radius r0 − λ·t) from −40 to +40 mm.
fn cone(lambda: f64) -> Profile {
    let t: Vec<f64> = (-400..=400).map(|i| i as f64 * 1e-4).collect();
    let z: Vec<f64> = t.iter().map(|t| lambda * t).collect();
    Profile::new("cone", ProfileKind::Wheel, &t, &z).unwrap()
}

#[test]
fn cone_on_knife_edge_gives_the_analytical_rolling_radius_difference() {
    let (lambda, r0) = (0.05, 0.46);
    let wheelset = WheelsetSetup {
        back_to_back: 1.36,
        flange_back_offset: 0.07,
        nominal_radius: [r0, r0],
    };
    let b = wheelset.taping_line_half_spacing();
    let depth = 0.014;
    let (rail, to_gauge) = knife_rail(5e-4, 1.2, depth);
    // Apex under the taping line of the centred wheelset.
    let track = TrackSetup {
        gauge: 2.0 * (b - to_gauge),
        gauge_height: depth,
        rail_inclination: 0.0,
    };
    let g =
        ContactGeometry::symmetric(&cone(lambda), &rail, &track, &wheelset, &Default::default())
            .unwrap();
    for y_mm in [-4.0, -1.0, 0.5, 2.0, 5.0] {
        let y = y_mm * 1e-3;
        let c = g.solve(y).unwrap();
        // Knife edges at fixed points: t_L = −y − r0·φ, t_R = y + r0·φ and φ = Δr/(2b) to first
        // order, so Δr = 2λ(y + r0·φ) = 2λy / (1 − λ·r0/b); the classical 2λy neglects the roll.
        let expected = 2.0 * lambda * y / (1.0 - lambda * r0 / b);
        let dr = c.rolling_radius_difference();
        assert!(
            (dr - expected).abs() < 2e-3 * expected.abs(),
            "y = {y_mm} mm: Δr = {dr}, expected {expected}"
        );
        assert!((c.roll - dr / (2.0 * b)).abs() < 2e-3 * c.roll.abs());
        // The contact angle is the cone's slope rotated by the roll (left: +φ, right: −φ).
        let left = c.wheels[LEFT].touching().unwrap();
        assert!((left.contact_angle - (lambda.atan() + c.roll)).abs() < 1e-6);
        assert!(left.gap == 0.0);
    }
}

/// A flanged wheel: flange face at 70°, flange root R15 mm, 1:20 tread, taping line at the origin.
fn flanged_wheel() -> Profile {
    let lambda = 0.05_f64;
    let face = 70_f64.to_radians();
    let (y, z) = ProfileBuilder::new(-0.048, -0.040, face)
        .line(0.025)
        .arc(0.015, -(face - lambda.atan()))
        .line(0.09)
        .points(2e-4)
        .unwrap();
    // Shift z so that the taping line (y = 0) is at z = 0.
    let tmp = Profile::new("tmp", ProfileKind::Wheel, &y, &z).unwrap();
    let z0 = tmp.height(0.0).unwrap();
    let z: Vec<f64> = z.iter().map(|v| v - z0).collect();
    Profile::new("flanged", ProfileKind::Wheel, &y, &z).unwrap()
}

/// A rail head: gauge face, R13 gauge corner, R300 crown, R13 field corner.
fn rail_head() -> Profile {
    ProfileBuilder::new(-0.0375, -0.045, 1.5)
        .line(0.030)
        .arc(0.013, -1.42)
        .arc(0.3, -0.16)
        .arc(0.013, -1.42)
        .line(0.015)
        .build("head", ProfileKind::Rail, 2e-4)
        .unwrap()
}

fn flanged_geometry() -> ContactGeometry {
    let wheelset = WheelsetSetup {
        back_to_back: 1.36,
        flange_back_offset: 0.07,
        nominal_radius: [0.46, 0.46],
    };
    let track = TrackSetup {
        gauge: 1.435,
        gauge_height: 0.014,
        rail_inclination: (1.0_f64 / 40.0).atan(),
    };
    ContactGeometry::symmetric(
        &flanged_wheel(),
        &rail_head(),
        &track,
        &wheelset,
        &Default::default(),
    )
    .unwrap()
}

#[test]
fn centred_symmetric_wheelset_has_no_roll_and_equal_radii() {
    let g = flanged_geometry();
    let c = g.solve(0.0).unwrap();
    assert!(c.roll.abs() < 1e-12 && c.rise.abs() < 1e-12);
    assert!(c.rolling_radius_difference().abs() < 1e-12);
    let (l, r) = (
        c.wheels[LEFT].touching().unwrap(),
        c.wheels[RIGHT].touching().unwrap(),
    );
    assert!((l.contact_angle - r.contact_angle).abs() < 1e-12);
    assert!((l.lateral + r.lateral).abs() < 1e-12);
    // Tread contact on a convex rail crown and a straight (cone) tread.
    assert!(l.rail_curvature > 0.0 && l.wheel_curvature.abs() < 1e-6);
}

#[test]
fn rolling_radius_difference_is_odd_and_flange_contact_appears() {
    let g = flanged_geometry();
    let ys: Vec<f64> = (-75..=75).map(|i| i as f64 * 1e-4).collect();
    let dr = rolling_radius_difference(&g, &ys).unwrap();
    for (i, d) in dr.iter().enumerate() {
        let mirror = dr[dr.len() - 1 - i];
        assert!((d + mirror).abs() < 1e-9, "Δr not odd at y = {}", ys[i]);
    }
    // Far out the left wheel runs on its flange (this straight 70° flange without a tip radius
    // is climbed within about 1 mm once touched, because the roll swings the flange outward by
    // r·φ: the rigid solution derails at y ≈ 7.8 mm): steep contact angle, second (tread) point kept.
    let c = g.solve(0.0075).unwrap();
    let left = c.wheels[LEFT];
    let touching = left.touching().unwrap();
    assert!(
        touching.contact_angle > 1.0,
        "angle {}",
        touching.contact_angle
    );
    let n_points = left.points.iter().flatten().count();
    assert_eq!(n_points, 2, "flange and tread points expected: {left:?}");
    let tread = left.points[0].unwrap();
    assert!(tread.gap > 0.0 && tread.wheel_y > touching.wheel_y);
    // The rise grows when the flange climbs.
    assert!(c.rise > 1e-3);
}

#[test]
fn table_lookup_matches_direct_solutions_between_grid_points() {
    let g = flanged_geometry();
    let grid = ContactTableParams {
        y_min: -0.0075,
        y_max: 0.0075,
        step: 1e-4,
    };
    let table = ContactTable::build(&g, &grid).unwrap();
    assert_eq!(table.rows().len(), 151);
    for y in [-0.00533, -0.00105, 0.00021, 0.00377] {
        let direct = g.solve(y).unwrap();
        let looked = table.lookup(y);
        assert!(
            (direct.rolling_radius_difference() - looked.rolling_radius_difference()).abs() < 2e-6
        );
        assert!((direct.roll - looked.roll).abs() < 1e-6);
    }
    // Outside the grid the end values are held.
    assert_eq!(table.lookup(1.0).roll, table.rows().last().unwrap().roll);
}

#[test]
fn bad_setups_are_rejected() {
    let w = flanged_wheel();
    let r = rail_head();
    let bad_track = TrackSetup {
        gauge: -1.0,
        ..Default::default()
    };
    let e =
        ContactGeometry::symmetric(&w, &r, &bad_track, &Default::default(), &Default::default());
    assert!(e.unwrap_err().to_string().contains("gauge"));
    // Wheel and rail swapped.
    let e = ContactGeometry::symmetric(
        &r,
        &w,
        &Default::default(),
        &Default::default(),
        &Default::default(),
    );
    assert!(e.is_err());
    let g = flanged_geometry();
    assert!(g.solve(f64::NAN).is_err());
    // Far beyond flange contact the wheel leaves its rail: an error, not a panic.
    assert!(g.solve(0.2).is_err());
    assert!(g.solve(0.009).is_err());
}

#[test]
fn different_wheel_radii_offset_the_rolling_radius_difference() {
    // Cones with r0 = 0.460 (left) and 0.459 m (right) on knife edges under the taping lines:
    // the centred wheelset rolls by φ = (r_L − r_R)/(2b) and the contacts move by r0·φ along
    // the cones, so Δr(0) = Δr0 / (1 − λ·r0/b) to first order, with Δr0 = 1 mm.
    let (lambda, r0) = (0.05, 0.46);
    let wheelset = WheelsetSetup {
        back_to_back: 1.36,
        flange_back_offset: 0.07,
        nominal_radius: [r0, r0 - 1e-3],
    };
    let b = wheelset.taping_line_half_spacing();
    let depth = 0.014;
    let (rail, to_gauge) = knife_rail(5e-4, 1.2, depth);
    let track = TrackSetup {
        gauge: 2.0 * (b - to_gauge),
        gauge_height: depth,
        rail_inclination: 0.0,
    };
    let wheel = cone(lambda);
    let g = ContactGeometry::new(
        [&wheel, &wheel],
        [&rail, &rail],
        &track,
        &wheelset,
        &Default::default(),
    )
    .unwrap();
    let c = g.solve(0.0).unwrap();
    let expected = 1e-3 / (1.0 - lambda * r0 / b);
    assert!((c.rolling_radius_difference() - expected).abs() < 5e-3 * expected);
    assert!(g.roll_at_centre() > 0.0 && c.rise.abs() < 1e-12);
}
