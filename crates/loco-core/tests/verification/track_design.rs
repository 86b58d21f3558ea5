//! The designed alignment (`track::design`) against the textbook clothoid and its mirror image:
//! a transition of length L into radius R ends with heading L/(2R) and lateral offset L²/(6R)
//! (small angles), the cant runs off linearly, and a right curve is the exact mirror of a left.

use crate::record::Record;
use loco_core::track::{CurveDirection, DesignPoint, DesignSection, TrackDesign};

/// Half the distance between the rails' nominal contact points, m.
const B: f64 = 0.75;

fn entry(direction: CurveDirection) -> TrackDesign {
    TrackDesign::new(
        &[
            DesignSection::Straight { length: 50.0 },
            DesignSection::Transition {
                length: 100.0,
                cant_run_off: None,
            },
            DesignSection::Curve {
                length: 200.0,
                radius: 600.0,
                cant: 0.12,
                direction,
            },
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
    let mid = d.at(100.0);
    let inside = d.at(300.0);
    let beyond = d.at(400.0);
    // (error, tolerance) of each closed form.
    let checks = [
        ((end.heading - 100.0 / 1200.0).abs(), 1e-15),
        (
            (end.heading_integral - 100.0f64.powi(2) / 3600.0).abs(),
            1e-12,
        ),
        ((end.curvature - 1.0 / 600.0).abs(), 1e-15),
        ((mid.curvature - 0.5 / 600.0).abs(), 1e-15),
        ((mid.curvature_rate - 1.0 / 60_000.0).abs(), 1e-18),
        // Linear run-off: half the cant in the middle; the right (outer) rail is the high one.
        ((mid.roll + (0.06f64 / (2.0 * B)).atan()).abs(), 1e-15),
        (
            (inside.heading - (100.0 / 1200.0 + 150.0 / 600.0)).abs(),
            1e-14,
        ),
        ((inside.roll + (0.12f64 / (2.0 * B)).atan()).abs(), 1e-15),
        (
            (beyond.heading - (100.0 / 1200.0 + 250.0 / 600.0)).abs(),
            1e-14,
        ),
    ];
    for (i, (error, tolerance)) in checks.iter().enumerate() {
        assert!(error < tolerance, "check {i}: {error} ≥ {tolerance}");
    }
    assert_eq!(inside.roll_rate, 0.0);
    assert_eq!(inside.curvature_rate, 0.0);
    // Beyond the end the steady curve continues; before the start the straight.
    assert_eq!(beyond.curvature, 1.0 / 600.0);
    assert_eq!(d.at(-10.0), DesignPoint::default());
    assert!(!d.is_straight());
    let offset = checks[1].0;
    let heading = [0, 6, 8].iter().map(|&i| checks[i].0).fold(0.0, f64::max);
    Record::new("clothoid", file!())
        .below("heading", heading, "rad", 1e-14, "<", 1e-14)
        .below("offset_integral", offset, "m", 1e-12, "<", 1e-12)
        .check();
}

#[test]
fn a_right_curve_is_the_mirror_image() {
    let (l, r) = (entry(CurveDirection::Left), entry(CurveDirection::Right));
    let mut differing = 0;
    let points = [-5.0, 20.0, 75.0, 120.0, 150.0, 260.0, 500.0];
    for s in points {
        let (a, b) = (l.at(s), r.at(s));
        assert_eq!(a.curvature, -b.curvature);
        assert_eq!(a.curvature_rate, -b.curvature_rate);
        assert_eq!(a.roll, -b.roll);
        assert_eq!(a.roll_rate, -b.roll_rate);
        assert_eq!(a.heading, -b.heading);
        assert_eq!(a.heading_integral, -b.heading_integral);
        let pairs = [
            (a.curvature, b.curvature),
            (a.curvature_rate, b.curvature_rate),
            (a.roll, b.roll),
            (a.roll_rate, b.roll_rate),
            (a.heading, b.heading),
            (a.heading_integral, b.heading_integral),
        ];
        differing += pairs.iter().filter(|(x, y)| *x != -*y).count();
    }
    Record::new("clothoid_mirror", file!())
        .count("points", points.len())
        .within("values_not_mirrored", differing as f64, "", 1, "=", 0.0)
        .check();
}
