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
