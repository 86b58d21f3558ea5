//! FASTSIM against a closed form of Kalker's simplified theory in the non-linear range.
//!
//! For pure longitudinal creepage ξ and the parabolic traction bound, each strip y of half-length
//! a_y = a√(1 − y²/b²) carries a traction that rises linearly from the leading edge with slope
//! k = ξ/L1 until it meets the bound κ(a_y² − x²), κ = 2μN/(πa³b). Integrating adhesion and slip
//! parts gives the strip force (4/3) κ a_y³ [1 − (1 − ε)³] with ε = k/(2κ a_y) (1 for ε ≥ 1) — the
//! strip analogue of Carter's cubic. The total, a 1-D integral over y evaluated here by a fine
//! midpoint rule, is an independent reference for the 2-D FASTSIM discretisation.

use crate::record::Record;
use loco_core::contact::fastsim::{Fastsim, FastsimParams};
use loco_core::contact::kalker::{kalker_coefficients, Creepages};
use std::f64::consts::PI;

fn closed_form_fx(a: f64, b: f64, normal_force: f64, mu: f64, g: f64, xi: f64) -> f64 {
    let c11 = kalker_coefficients(a / b, 0.28).unwrap().c11;
    let slope = 3.0 * c11 * g * xi.abs() / (8.0 * a);
    let kappa = 2.0 * mu * normal_force / (PI * a * a * a * b);
    let n = 200_000;
    let dy = 2.0 * b / n as f64;
    let total: f64 = (0..n)
        .map(|j| {
            let y = -b + (j as f64 + 0.5) * dy;
            let a_y = a * (1.0 - (y / b).powi(2)).sqrt();
            let eps = (slope / (2.0 * kappa * a_y)).min(1.0);
            4.0 / 3.0 * kappa * a_y.powi(3) * (1.0 - (1.0 - eps).powi(3)) * dy
        })
        .sum();
    -xi.signum() * total
}

#[test]
fn pure_creepage_matches_strip_closed_form() {
    let (a, b, n, mu, g) = (8e-3, 4e-3, 82e3, 0.3, 82e9);
    let solver = |grid: usize| {
        Fastsim::new(FastsimParams {
            nx: grid,
            ny: grid,
            shear_modulus: g,
            ..FastsimParams::default()
        })
        .unwrap()
    };
    let (fine, coarse) = (solver(200), solver(10));
    let (mut worst_fine, mut worst_coarse) = (0.0_f64, 0.0_f64);
    for xi in [2e-4, 6e-4, 1.2e-3, 2.5e-3, -8e-4] {
        let creep = Creepages {
            longitudinal: xi,
            lateral: 0.0,
            spin: 0.0,
        };
        let reference = closed_form_fx(a, b, n, mu, g, xi);
        let f_fine = fine.creep_forces(a, b, n, mu, &creep).fx;
        let f_coarse = coarse.creep_forces(a, b, n, mu, &creep).fx;

        assert!(
            (f_fine / reference - 1.0).abs() < 2e-3,
            "ξ = {xi}: 200x200 {f_fine} vs closed form {reference}"
        );
        // The coarse grid misses part of the thin slip zone at the trailing edge (4 % of the
        // force at ξ = 2e-4, 0.7 % on 20 x 20): measured against the saturation force it is small.
        assert!(
            (f_coarse - reference).abs() < 0.01 * mu * n,
            "ξ = {xi}: 10x10 {f_coarse} vs closed form {reference}"
        );
        worst_fine = worst_fine.max((f_fine / reference - 1.0).abs());
        worst_coarse = worst_coarse.max((f_coarse - reference).abs() / (mu * n));
    }
    Record::new("fastsim_strip_closed_form", file!())
        .within("fine_grid", worst_fine, "", 2, "<", 2e-3)
        .within("default_grid_of_mu_n", worst_coarse, "", 2, "<", 0.01)
        .check();
}
