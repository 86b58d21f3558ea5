//! Hertz's elliptical contact against its closed forms: a sphere on a plane (a circular
//! contact, every quantity in closed form) and Hertz's table of the coefficients m and n of the
//! semi-axes (Timoshenko & Goodier, *Theory of Elasticity*, 1951, §140; reproduced in Iwnicki,
//! *Handbook of Railway Vehicle Dynamics*, 2006, ch. 4). CONTACT's normal solution is
//! `fastsim_contact_reference.rs`.

use crate::record::Record;
use loco_core::contact::hertz::{hertz_contact, ContactRadii, ElasticMaterial, HertzCoefficients};
use std::f64::consts::PI;

fn rel(x: f64, y: f64) -> f64 {
    (x - y).abs() / y.abs()
}

#[test]
fn sphere_on_plane_is_circular_hertz() {
    // Wheel "sphere" of radius R on a flat rail: a = b = (3NR/(4E*))^{1/3}, δ = a²/R.
    let r = 0.5;
    let radii = ContactRadii {
        wheel_rolling: r,
        wheel_transverse: r,
        rail_transverse: f64::INFINITY,
    };
    let mat = ElasticMaterial::default();
    let n = 1.0e5;
    let c = hertz_contact(n, &radii, &mat).unwrap();
    let a = (3.0 * n * r / (4.0 * mat.contact_modulus())).cbrt();
    let errors = [
        rel(c.semi_axis_long, a),
        rel(c.semi_axis_lat, a),
        rel(c.approach, a * a / r),
    ];
    let pressure = rel(c.peak_pressure, 3.0 * n / (2.0 * PI * a * a));
    let coef = HertzCoefficients::new(&radii, &mat).unwrap();
    let load = rel(coef.load_from_approach(c.approach), n);
    for e in errors.into_iter().chain([load]) {
        assert!(e < 1e-9);
    }
    assert!(pressure < 1e-12);
    let geometry = errors.into_iter().chain([load]).fold(0.0, f64::max);
    Record::new("hertz_sphere_on_plane", file!())
        .below("semi_axes_approach_load", geometry, "", 1e-13, "<", 1e-9)
        .below("peak_pressure", pressure, "", 1e-13, "<", 1e-12)
        .check();
}

#[test]
fn hertz_m_n_match_timoshenko_goodier_table() {
    // a = m·(3N/(4E*(A+B)))^{1/3}, b = n·(same), cos θ = (B − A)/(A + B).
    let table = [
        (30.0, 2.731, 0.493),
        (45.0, 1.926, 0.604),
        (60.0, 1.486, 0.717),
        (75.0, 1.202, 0.846),
        (90.0, 1.0, 1.0),
    ];
    let e_star = 1.0e11;
    let mut worst = 0.0_f64;
    for (theta_deg, m_ref, n_ref) in table {
        let cos_t = f64::to_radians(theta_deg).cos();
        let (a_curv, b_curv) = (1.0 - cos_t, 1.0 + cos_t); // A + B = 2
        let coef = HertzCoefficients::from_curvatures(a_curv, b_curv, e_star).unwrap();
        let n_force = 1.0e4;
        let c = coef.contact(n_force);
        let unit = (3.0 * n_force / (4.0 * e_star * 2.0)).cbrt();
        let (m, n) = (
            rel(c.semi_axis_long / unit, m_ref),
            rel(c.semi_axis_lat / unit, n_ref),
        );
        assert!(m < 2e-3, "m at θ={theta_deg}");
        assert!(n < 2e-3, "n at θ={theta_deg}");
        worst = worst.max(m).max(n);
    }
    Record::new("hertz_m_n_table", file!())
        .count("angles", table.len())
        .within("largest_deviation", worst, "", 2, "<", 2e-3)
        .check();
}
