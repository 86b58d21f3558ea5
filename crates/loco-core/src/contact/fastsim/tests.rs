//! FASTSIM against Kalker's linear theory, saturation, Kalker's signs and the Kalker factor, and
//! its SIMD lanes against one strip at a time.

use super::super::kalker::{kalker_coefficients, linear_creep_forces};
use super::*;
use std::f64::consts::PI;

const A: f64 = 8e-3;
const B: f64 = 4e-3;
const N: f64 = 82e3;
const G: f64 = 82e9;

fn creep(xi: f64, eta: f64, phi: f64) -> Creepages {
    Creepages {
        longitudinal: xi,
        lateral: eta,
        spin: phi,
    }
}

fn solver(n: usize, bound: TractionBound) -> Fastsim {
    Fastsim::new(FastsimParams {
        nx: n,
        ny: n,
        bound,
        shear_modulus: G,
        ..FastsimParams::default()
    })
    .unwrap()
}

/// FASTSIM strip by strip in the strips' order, the scalar loop of the lanes' operations.
fn strip_by_strip(f: &Fastsim, a: f64, b: f64, mu: f64, c: &Creepages) -> [f64; 3] {
    let coef = f.table.coefficients(a / b);
    let g = f.params.shear_modulus * f.params.kalker_factor;
    let inv_l1 = 3.0 * coef.c11 * g / (8.0 * a);
    let inv_l2 = 3.0 * coef.c22 * g / (8.0 * a);
    let inv_l3 = 4.0 * coef.c23 * g / (PI * a * (a / b).sqrt());
    let bound_peak = mu * N * f.pressure_scale / (a * b);
    let (nx, ny) = (f.params.nx, f.params.ny);
    let dy = 2.0 * b / ny as f64;
    let mut out = [0.0; 3];
    for j in 0..ny {
        let eta = -1.0 + (2 * j + 1) as f64 / ny as f64;
        let s = (1.0 - eta * eta).sqrt();
        let shape = if f.params.bound == TractionBound::Elliptic {
            s
        } else {
            s * s
        };
        let (y, a_j) = (eta * b, s * a);
        let slope_x = c.longitudinal * inv_l1 - c.spin * y * inv_l3;
        let (mut px, mut py, mut sx, mut sy, mut sxpy) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut x_prev = a_j;
        for &Element {
            u: u_k,
            shape: shape_k,
            ..
        } in &f.elements
        {
            let x = u_k * a_j;
            let h = x_prev - x;
            px -= h * slope_x;
            py -= h * (c.lateral * inv_l2 + c.spin * (0.5 * (x_prev + x)) * inv_l3);
            let norm = (px * px + py * py).sqrt().max(f64::MIN_POSITIVE);
            let scale = (bound_peak * shape * shape_k / norm).min(1.0);
            (px, py) = (px * scale, py * scale);
            (sx, sy, sxpy) = (sx + px, sy + py, sxpy + x * py);
            x_prev = x;
        }
        let area = 2.0 * a_j / nx as f64 * dy;
        out[0] += sx * area;
        out[1] += sy * area;
        out[2] += (sxpy - y * sx) * area;
    }
    out
}

#[test]
fn lanes_and_their_order_give_the_bits_of_one_strip_at_a_time() {
    // The strips sit in the lanes outermost first; the sums must still run in strip order.
    for (nx, ny) in [(10, 10), (7, 13), (20, 20), (3, 1)] {
        for bound in [TractionBound::Parabolic, TractionBound::Elliptic] {
            let f = Fastsim::new(FastsimParams {
                nx,
                ny,
                bound,
                shear_modulus: G,
                ..FastsimParams::default()
            })
            .unwrap();
            for c in [
                creep(1e-4, -6.25e-4, 0.625),
                creep(-2e-5, 3e-5, 0.05),
                creep(2e-3, -1e-3, -0.4),
                creep(0.0, 0.0, 3.0),
            ] {
                let got = f.creep_forces(A, B, N, 0.3, &c);
                let want = strip_by_strip(&f, A, B, 0.3, &c);
                assert_eq!(
                    [got.fx, got.fy, got.mz].map(f64::to_bits),
                    want.map(f64::to_bits),
                    "{nx}x{ny} {bound:?} {c:?}"
                );
            }
        }
    }
}

#[test]
fn small_creepage_tends_to_linear_theory() {
    for aob in [0.3_f64, 1.0, 2.0, 5.0] {
        let (a, b) = (
            A * aob.sqrt() / 2.0_f64.sqrt(),
            B * 2.0_f64.sqrt() / aob.sqrt(),
        );
        let coef = kalker_coefficients(a / b, 0.28).unwrap();
        let s = solver(100, TractionBound::Parabolic);
        for c in [
            creep(1e-7, 0.0, 0.0),
            creep(0.0, 1e-7, 0.0),
            creep(0.0, 0.0, 1e-5),
        ] {
            let f = s.creep_forces(a, b, N, 0.3, &c);
            let lin = linear_creep_forces(a, b, G, &coef, &c);
            let (got, want) = (f.fx + f.fy, lin.fx + lin.fy);
            assert!(
                (got / want - 1.0).abs() < 0.01,
                "a/b={aob}: {got} vs {want} for {c:?}"
            );
        }
    }
}

#[test]
fn saturates_at_mu_n_on_any_grid() {
    for n in [1, 3, 10, 40] {
        for bound in [TractionBound::Parabolic, TractionBound::Elliptic] {
            let s = solver(n, bound);
            let f = s.creep_forces(A, B, N, 0.3, &creep(0.3, -0.4, 0.0));
            let total = f.fx.hypot(f.fy);
            assert!((total / (0.3 * N) - 1.0).abs() < 1e-9, "n={n}: {total}");
            // Full slip: FASTSIM's traction points along (ξ/L1, η/L2) = (C11 ξ, C22 η)·const.
            let coef = kalker_coefficients(A / B, 0.28).unwrap();
            let want = (coef.c22 * -0.4) / (coef.c11 * 0.3);
            assert!((f.fy / f.fx - want).abs() < 1e-9);
        }
    }
}

#[test]
fn signs_follow_kalker() {
    let s = solver(20, TractionBound::Parabolic);
    let f = s.creep_forces(A, B, N, 0.3, &creep(1e-4, 0.0, 0.0));
    assert!(f.fx < 0.0 && f.fy.abs() < 1e-9 * f.fx.abs());
    let f = s.creep_forces(A, B, N, 0.3, &creep(0.0, 1e-4, 0.0));
    assert!(f.fy < 0.0 && f.mz > 0.0);
    let f = s.creep_forces(A, B, N, 0.3, &creep(0.0, 0.0, 0.1));
    assert!(f.fy < 0.0 && f.mz < 0.0);
}

#[test]
fn kalker_factor_scales_small_creepage_forces() {
    let base = solver(20, TractionBound::Parabolic);
    let half = Fastsim::new(FastsimParams {
        kalker_factor: 0.5,
        ..*base.params()
    })
    .unwrap();
    let c = creep(1e-7, 1e-7, 0.0);
    let f1 = base.creep_forces(A, B, N, 0.3, &c);
    let f2 = half.creep_forces(A, B, N, 0.3, &c);
    assert!((f2.fx / f1.fx - 0.5).abs() < 1e-9);
}

#[test]
fn bad_input_names_the_argument() {
    let p = FastsimParams::default();
    let c = creep(0.0, 0.0, 0.0);
    let err = fastsim(0.0, B, N, 0.3, &c, p).unwrap_err();
    assert!(err.to_string().contains("`a`"));
    assert_eq!(
        fastsim(A, B, 0.0, 0.3, &creep(1e-3, 0.0, 0.0), p).unwrap(),
        CreepForces::default()
    );
    let err = fastsim(A, B, N, -0.1, &c, p).unwrap_err();
    assert!(err.to_string().contains("mu"));
    let err = fastsim(A, B, N, 0.3, &c, FastsimParams { nx: 0, ..p }).unwrap_err();
    assert!(err.to_string().contains("grid.nx"));
    let err = fastsim(A, B, N, 0.3, &creep(f64::NAN, 0.0, 0.0), p).unwrap_err();
    assert!(err.to_string().contains("creepage_long"));
}
