//! Contact geometry against independent references in the shared data directory: the Manchester
//! contact benchmark A-2.2 (CONTACT's input and reference output, S1002 on UIC60) and the EN 15302
//! reference profiles. Each test skips, saying so, when the data are absent.

use crate::manchester;
use crate::record::Record;
use crate::support;

use loco_core::contact::*;

#[test]
fn manchester_benchmark_a22_contact_positions() {
    let Some(manchester::Benchmark {
        poses,
        flanging,
        other,
        geometry: g,
    }) = manchester::load()
    else {
        return;
    };
    // CONTACT's y points to the right: its Y_WS > 0 pushes its right wheel into flange contact,
    // which is loco's left wheel for y > 0 (the problem is symmetric, so loco's y = Y_WS with
    // the wheels swapped).
    // Tolerances. The benchmark poses carry a yaw angle (up to 24 mrad) that the 2-D geometry
    // ignores, and CONTACT reports the reference location of the elastic contact patch (10 kN),
    // not the rigid minimum-gap point, so:
    // - lateral positions on wheel and rail within 1 mm (about a tenth of the patch width), or,
    //   where the rigid gap is nearly flat (conformal contact close to a contact jump), the
    //   reference point must lie inside the rigid interpenetration zone for CONTACT's own approach
    //   (our gap there smaller than that approach);
    // - contact angle within 0.025 rad (yaw turns the flange contact plane; worst seen 0.018);
    // - rolling radius within 0.25 mm;
    // - roll within 3 % + 1e-5 rad (the benchmark's rigid roll includes the yaw).
    println!("case  y    wheel  side  Δwheel_y  Δrail_y  Δangle   Δradius (mm, mm, rad, mm)");
    let mut worst = [0.0_f64; 4];
    for (case, pose) in poses.iter().enumerate() {
        let (y_mm, roll_ref, yaw) = (pose.y_mm, pose.roll, pose.yaw);
        let y = y_mm * 1e-3;
        let c = g.solve(y).unwrap();
        // CONTACT's roll is about its x axis with y right, z down: the opposite sign.
        println!(
            "{:>3} {:>5.1}  roll {:.4e} ref {:.4e}  yaw {:.4}",
            case + 1,
            y_mm,
            c.roll,
            -roll_ref,
            yaw
        );
        assert!(
            (c.roll + roll_ref).abs() <= 1e-5 + 0.03 * roll_ref.abs(),
            "case {}: roll {} vs {}",
            case + 1,
            c.roll,
            -roll_ref
        );
        for (side, name, reference) in [
            (LEFT, "flanging", &flanging[case]),
            (RIGHT, "other", &other[case]),
        ] {
            let (patches, r) = *reference;
            assert_eq!(patches, 1);
            let p = c.wheels[side].touching().unwrap();
            let d = [
                p.wheel_y * 1e3 - r.wheel_y,
                p.rail_y * 1e3 - r.rail_y,
                p.contact_angle - r.angle,
                p.rolling_radius * 1e3 - r.radius,
            ];
            println!(
                "          {name:>8}  {:+8.3} {:+8.3} {:+8.4} {:+8.3}   (ref {:.3} {:.3} {:.4} {:.3})",
                d[0], d[1], d[2], d[3], r.wheel_y, r.rail_y, r.angle, r.radius
            );
            let where_ = format!("case {} {name} wheel", case + 1);
            if d[0].abs() > 1.0 || d[1].abs() > 1.0 {
                let gap_mm = g.gap_at(y, side, r.wheel_y * 1e-3).unwrap() * 1e3;
                println!(
                    "          rigid gap at the reference point {gap_mm:.4} mm, approach {:.4} mm",
                    r.approach
                );
                assert!(gap_mm < r.approach, "{where_}: position {d:?}");
            } else {
                for k in 0..2 {
                    worst[k] = worst[k].max(d[k].abs());
                }
            }
            assert!(d[2].abs() < 0.025, "{where_}: contact angle {}", d[2]);
            assert!(d[3].abs() < 0.25, "{where_}: rolling radius {}", d[3]);
            worst[2] = worst[2].max(d[2].abs());
            worst[3] = worst[3].max(d[3].abs());
        }
    }
    println!("worst (outside the flat-gap cases): {worst:?}");
    Record::new("manchester_a22_positions", file!())
        .count("poses", poses.len())
        .value("wheel_position", worst[0], "mm", 2)
        .value("rail_position", worst[1], "mm", 2)
        .within("contact_angle", worst[2], "rad", 2, "<", 0.025)
        .within("rolling_radius", worst[3], "mm", 2, "<", 0.25)
        .check();
}

#[test]
fn en15302_reference_profiles_load_in_the_profile_frame() {
    let (Some(w), Some(r)) = (
        support::shared_file("en15302/RUIC519A.dat"),
        support::shared_file("en15302/SUIC519A.dat"),
    ) else {
        return;
    };
    let wheel = load_profile(&w, Some(ProfileKind::Wheel), false).unwrap();
    let rail = load_profile(&r, Some(ProfileKind::Rail), false).unwrap();
    // Wheel A: flange back at y = -70 mm, taping line at the origin, flange tip 28 mm below it.
    assert!((wheel.y_range().0 + 0.070).abs() < 1e-9);
    assert!(wheel.height(0.0).unwrap().abs() < 2e-4);
    let tip = wheel.z().iter().cloned().fold(f64::INFINITY, f64::min);
    assert!((tip + 0.028).abs() < 5e-4, "flange height {tip}");
    let track = TrackSetup {
        gauge: 1.435,
        gauge_height: 0.014,
        rail_inclination: 0.0,
    };
    let wheelset = WheelsetSetup {
        back_to_back: 1.360,
        flange_back_offset: 0.070,
        nominal_radius: [0.46, 0.46],
    };
    let g =
        ContactGeometry::symmetric(&wheel, &rail, &track, &wheelset, &Default::default()).unwrap();
    let c = g.solve(0.0).unwrap();
    assert!(c.roll.abs() < 1e-12);
}

#[test]
fn manchester_benchmark_a22_hertz_from_our_curvatures() {
    // Checks the contact angle, rolling radius and transverse curvatures together: the Hertz
    // ellipse they give for CONTACT's own normal force must have CONTACT's peak pressure and
    // approach. Hertz assumes one isolated contact with constant curvatures over the patch, so
    // the check applies where (a) no second contact point lies within twice CONTACT's approach
    // and (b) the rigid point is within 1 mm of CONTACT's (not a flat, conformal gap); there
    // 5 % on both (the curvatures vary across patches up to 15 mm wide; worst seen 4.3 %).
    use loco_core::contact::hertz::{hertz_contact, ContactRadii, ElasticMaterial};
    let Some(manchester::Benchmark {
        poses,
        flanging,
        other,
        geometry: g,
    }) = manchester::load()
    else {
        return;
    };
    // The benchmark's material: G = 82 GPa, ν = 0.28, so E = 2G(1 + ν).
    let material = ElasticMaterial {
        youngs_modulus: 2.0 * 82e9 * 1.28,
        poisson_ratio: 0.28,
    };
    let (mut checked, mut worst) = (0, [0.0_f64; 2]);
    for (case, pose) in poses.iter().enumerate() {
        let c = g.solve(pose.y_mm * 1e-3).unwrap();
        for (side, reference) in [(LEFT, &flanging[case]), (RIGHT, &other[case])] {
            let r = reference.1;
            let p = c.wheels[side].touching().unwrap();
            let isolated = c.wheels[side]
                .points
                .iter()
                .flatten()
                .all(|q| q.gap == 0.0 || q.gap * 1e3 > 2.0 * r.approach);
            let located = (p.wheel_y * 1e3 - r.wheel_y).abs() <= 1.0;
            // The wheel's curvature in the rolling direction, seen in the contact plane tilted
            // by the contact angle, is cos δ / r.
            let radii = ContactRadii {
                wheel_rolling: p.rolling_radius / p.contact_angle.cos(),
                wheel_transverse: 1.0 / p.wheel_curvature,
                rail_transverse: 1.0 / p.rail_curvature,
            };
            let h = hertz_contact(r.normal_force, &radii, &material).unwrap();
            let d = [
                h.peak_pressure * 1e-6 / r.peak_pressure - 1.0,
                h.approach * 1e3 / r.approach - 1.0,
            ];
            println!(
                "case {:>2} side {side}: pmax {:7.1} ref {:7.1} MPa, approach {:.4} ref {:.4} mm{}",
                case + 1,
                h.peak_pressure * 1e-6,
                r.peak_pressure,
                h.approach * 1e3,
                r.approach,
                if isolated && located {
                    ""
                } else {
                    "  (not compared)"
                }
            );
            if isolated && located {
                checked += 1;
                assert!(
                    d[0].abs() < 0.05 && d[1].abs() < 0.05,
                    "case {}: {d:?}",
                    case + 1
                );
                worst = [worst[0].max(d[0].abs()), worst[1].max(d[1].abs())];
            }
        }
    }
    println!("compared {checked} of 42 contacts; worst relative error pmax, approach: {worst:?}");
    // Guard against a vacuous test: most contacts of the benchmark are isolated tread contacts.
    assert!(checked > 21, "only {checked} contacts compared");
    Record::new("manchester_a22_hertz", file!())
        .count("contacts_compared", checked)
        .within("peak_pressure", worst[0], "", 2, "<", 0.05)
        .within("approach", worst[1], "", 2, "<", 0.05)
        .check();
}
