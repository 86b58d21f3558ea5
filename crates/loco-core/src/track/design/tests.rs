use super::*;

const B: f64 = 0.75;

fn curve(radius: f64, cant: f64, direction: CurveDirection) -> DesignSection {
    DesignSection::Curve {
        length: 200.0,
        radius,
        cant,
        direction,
    }
}

fn entry(direction: CurveDirection) -> TrackDesign {
    TrackDesign::new(
        &[
            DesignSection::Straight { length: 50.0 },
            DesignSection::Transition {
                length: 100.0,
                cant_run_off: None,
            },
            curve(600.0, 0.12, direction),
        ],
        B,
        100.0,
    )
    .unwrap()
}

#[test]
fn clothoid_offset_and_heading_are_the_textbook_ones() {
    // Clothoid of length L into radius R: heading L/(2R) and lateral offset L²/(6R) at its end
    // (small angles); in the curve the heading grows by σ/R.
    let d = entry(CurveDirection::Left);
    let end = d.at(150.0);
    assert!((end.heading - 100.0 / 1200.0).abs() < 1e-15);
    assert!((end.heading_integral - 100.0f64.powi(2) / 3600.0).abs() < 1e-12);
    assert!((end.curvature - 1.0 / 600.0).abs() < 1e-15);
    let mid = d.at(100.0);
    assert!((mid.curvature - 0.5 / 600.0).abs() < 1e-15);
    assert!((mid.curvature_rate - 1.0 / 60_000.0).abs() < 1e-18);
    // Linear run-off: half the cant in the middle; the right (outer) rail is the high one.
    assert!((mid.roll + (0.06f64 / (2.0 * B)).atan()).abs() < 1e-15);
    let inside = d.at(300.0);
    assert!((inside.heading - (100.0 / 1200.0 + 150.0 / 600.0)).abs() < 1e-14);
    assert!((inside.roll + (0.12f64 / (2.0 * B)).atan()).abs() < 1e-15);
    assert_eq!(inside.roll_rate, 0.0);
    assert_eq!(inside.curvature_rate, 0.0);
    // Beyond the end the steady curve continues; before the start the straight.
    let beyond = d.at(400.0);
    assert!((beyond.heading - (100.0 / 1200.0 + 250.0 / 600.0)).abs() < 1e-14);
    assert_eq!(beyond.curvature, 1.0 / 600.0);
    assert_eq!(d.at(-10.0), DesignPoint::default());
    assert!(!d.is_straight());
}

#[test]
fn a_right_curve_is_the_mirror_image() {
    let (l, r) = (entry(CurveDirection::Left), entry(CurveDirection::Right));
    for s in [-5.0, 20.0, 75.0, 120.0, 150.0, 260.0, 500.0] {
        let (a, b) = (l.at(s), r.at(s));
        assert_eq!(a.curvature, -b.curvature);
        assert_eq!(a.curvature_rate, -b.curvature_rate);
        assert_eq!(a.roll, -b.roll);
        assert_eq!(a.roll_rate, -b.roll_rate);
        assert_eq!(a.heading, -b.heading);
        assert_eq!(a.heading_integral, -b.heading_integral);
    }
}

#[test]
fn a_shorter_run_off_is_centred_in_its_transition() {
    let d = TrackDesign::new(
        &[
            DesignSection::Transition {
                length: 100.0,
                cant_run_off: Some(60.0),
            },
            curve(1000.0, 0.15, CurveDirection::Right),
        ],
        B,
        100.0,
    )
    .unwrap();
    // Level until 20 m, full cant from 80 m, linear between (left rail higher in a right curve).
    assert_eq!(d.at(19.0).roll, 0.0);
    assert!((d.at(50.0).roll - (0.075f64 / (2.0 * B)).atan()).abs() < 1e-15);
    assert!((d.at(90.0).roll - (0.15f64 / (2.0 * B)).atan()).abs() < 1e-15);
    assert_eq!(d.at(10.0).roll_rate, 0.0);
    assert!(d.at(50.0).roll_rate > 0.0);
}

#[test]
fn bad_sections_are_named() {
    let err = |sections: &[DesignSection]| {
        TrackDesign::new(sections, B, 150.0)
            .unwrap_err()
            .to_string()
    };
    let e = err(&[
        DesignSection::Straight { length: 10.0 },
        curve(120.0, 0.1, CurveDirection::Left),
    ]);
    assert!(
        e.contains("curve section 2 (radius_m)") && e.contains("150"),
        "{e}"
    );
    let e = err(&[curve(600.0, 0.21, CurveDirection::Left)]);
    assert!(
        e.contains("curve section 1 (cant_mm)") && e.contains("210.0 mm"),
        "{e}"
    );
    let e = err(&[
        DesignSection::Transition {
            length: 50.0,
            cant_run_off: Some(80.0),
        },
        curve(600.0, 0.1, CurveDirection::Left),
    ]);
    assert!(
        e.contains("curve section 1 (cant_run_off_m)") && e.contains("shorter"),
        "{e}"
    );
    let e = err(&[DesignSection::Straight { length: -1.0 }]);
    assert!(e.contains("curve section 1 (length_m)"), "{e}");
    assert!(err(&[]).contains("curve"));
}
