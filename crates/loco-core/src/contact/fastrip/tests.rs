//! FaStrip against Kalker's linear theory, the strip theory's own small-spin limit, saturation,
//! symmetry and Kalker's signs.

use super::super::fastsim::{Fastsim, FastsimParams, TractionBound};
use super::super::kalker::{kalker_coefficients, linear_creep_forces};
use super::*;

const A: f64 = 8e-3;
const B: f64 = 4e-3;
const N: f64 = 82e3;
const G: f64 = 82e9;
const MU: f64 = 0.3;

fn creep(xi: f64, eta: f64, phi: f64) -> Creepages {
    Creepages {
        longitudinal: xi,
        lateral: eta,
        spin: phi,
    }
}

fn solver(nx: usize, ny: usize) -> Fastrip {
    Fastrip::new(FastripParams {
        nx,
        ny,
        shear_modulus: G,
        ..FastripParams::default()
    })
    .unwrap()
}

/// Semi-axes with a/b = `aob` and the area of the 8 × 4 mm ellipse.
fn axes(aob: f64) -> (f64, f64) {
    let c = (A * B).sqrt();
    (c * aob.sqrt(), c / aob.sqrt())
}

#[test]
fn small_creepage_tends_to_linear_theory() {
    // Sichani's scaling reproduces Kalker's C11 ξ, C22 η and C23 φ in the forces. The adhesion
    // zone is integrated in closed form, so the only error left is the midpoint rule across the
    // strips (and the slip sliver, O(√creepage)).
    let s = solver(10, 200);
    for aob in [0.3_f64, 1.0, 2.0, 5.0] {
        let (a, b) = axes(aob);
        let coef = kalker_coefficients(a / b, 0.28).unwrap();
        for c in [
            creep(1e-9, 0.0, 0.0),
            creep(0.0, 1e-9, 0.0),
            creep(0.0, 0.0, 1e-7),
        ] {
            let f = s.creep_forces(a, b, N, MU, &c);
            let lin = linear_creep_forces(a, b, G, &coef, &c);
            let (got, want) = (f.fx + f.fy, lin.fx + lin.fy);
            assert!(
                (got / want - 1.0).abs() < 2e-3,
                "a/b={aob}: {got} vs {want} for {c:?}"
            );
        }
    }
}

#[test]
fn small_spin_moment_is_the_strip_theorys() {
    // Hand calculation: at small spin each strip slips over d = |φ' y|/(1 − ν) and carries
    // p_x = −sign(φ' y) μ p0/a (S_c − S_a), so Fx_j = −φ' y μ p0 π a_j/((1 − ν) a) and
    // Mz = −∫ y Fx_j dy = φ' μ p0 π² b³/(8(1 − ν)) = −3π G c C23 b³ φ / (16 (1 − ν)).
    // Strip theory has no C33: its Mz differs from Kalker's −G c⁴ C33 φ.
    let s = solver(10, 400);
    let phi = 1e-7;
    for aob in [0.5_f64, 1.0, 2.0] {
        let (a, b) = axes(aob);
        let coef = kalker_coefficients(a / b, 0.28).unwrap();
        let c = (a * b).sqrt();
        let want = -3.0 * PI * G * c * coef.c23 * b.powi(3) * phi / (16.0 * 0.72);
        let got = s.creep_forces(a, b, N, MU, &creep(0.0, 0.0, phi)).mz;
        assert!(
            (got / want - 1.0).abs() < 5e-3,
            "a/b={aob}: {got} vs {want}"
        );
    }
}

#[test]
fn pure_creepage_is_carters_solution_on_every_strip() {
    // Independent reference: with ξ alone every strip is Carter's two-dimensional solution, with
    // the slip half-length d = |ξ'| a/(1 − ν) and the traction along −x, so
    // Fx = −sign ξ · μ p0/a · ∫ (π/2)(a_y² − (a_y − d)²₊) dy, p0 = 3N/(2πab), evaluated here by
    // a fine midpoint rule in y.
    let coef = kalker_coefficients(A / B, 0.28).unwrap();
    let p0 = 1.5 * N / (PI * A * B);
    let s = solver(10, 100);
    for xi in [2e-4, 1e-3, 3e-3, 1e-2] {
        let d = 2.0 * G * coef.c11 * xi / (PI * PI * MU * p0) * A;
        let n = 100_000;
        let dy = 2.0 * B / n as f64;
        let want: f64 = -(0..n)
            .map(|j| {
                let y = -B + (j as f64 + 0.5) * dy;
                let a_y = A * (1.0 - (y / B).powi(2)).sqrt();
                0.5 * PI * (a_y * a_y - (a_y - d).max(0.0).powi(2)) * dy
            })
            .sum::<f64>()
            * MU
            * p0
            / A;
        let got = s.creep_forces(A, B, N, MU, &creep(xi, 0.0, 0.0)).fx;
        assert!((got / want - 1.0).abs() < 2e-3, "ξ={xi}: {got} vs {want}");
    }
}

#[test]
fn saturates_at_mu_n_on_any_grid() {
    for (nx, ny) in [(1, 1), (3, 5), (10, 10), (40, 40)] {
        let s = solver(nx, ny);
        let f = s.creep_forces(A, B, N, MU, &creep(0.3, -0.4, 0.0));
        let total = f.fx.hypot(f.fy);
        assert!((total / (MU * N) - 1.0).abs() < 1e-9, "{nx}x{ny}: {total}");
        // Full slip: the traction points along FASTSIM's (C11 ξ, C22 η) direction.
        let coef = kalker_coefficients(A / B, 0.28).unwrap();
        let want = (coef.c22 * -0.4) / (coef.c11 * 0.3);
        assert!((f.fy / f.fx - want).abs() < 1e-9);
    }
}

#[test]
fn force_never_exceeds_mu_n_and_grows_with_creepage() {
    // Over partial and full slip, with spin up to the flange's (φ' beyond 1).
    let s = solver(10, 10);
    for phi in [0.0, 0.6, 3.0, 10.0] {
        let mut last = 0.0;
        for i in 1..=40 {
            let eta = 1e-4 * f64::from(i) * f64::from(i);
            let f = s.creep_forces(A, B, N, MU, &creep(0.2 * eta, eta, phi));
            let total = f.fx.hypot(f.fy);
            assert!(total <= MU * N * (1.0 + 1e-9), "φ={phi}, η={eta}: {total}");
            if phi == 0.0 {
                assert!(total >= last * (1.0 - 1e-12), "η={eta}: {total} < {last}");
            }
            last = total;
        }
    }
}

#[test]
fn symmetries_and_signs_follow_kalker() {
    let s = solver(10, 10);
    let f = s.creep_forces(A, B, N, MU, &creep(1e-4, 0.0, 0.0));
    assert!(f.fx < 0.0 && f.fy.abs() < 1e-9 * f.fx.abs() && f.mz.abs() < 1e-9 * f.fx.abs() * A);
    let f = s.creep_forces(A, B, N, MU, &creep(0.0, 1e-4, 0.0));
    assert!(f.fy < 0.0 && f.fx.abs() < 1e-9 * f.fy.abs());
    // Spin: lateral force and moment of Kalker's signs; no longitudinal force (y ↦ −y).
    let f = s.creep_forces(A, B, N, MU, &creep(0.0, 0.0, 0.1));
    assert!(f.fy < 0.0 && f.mz < 0.0 && f.fx.abs() < 1e-9 * f.fy.abs());
    // Reversing every creepage reverses every force.
    let c = creep(2e-4, -6.25e-4, 0.625);
    let f = s.creep_forces(A, B, N, MU, &c);
    let r = s.creep_forces(A, B, N, MU, &creep(-2e-4, 6.25e-4, -0.625));
    for (x, y) in [(f.fx, r.fx), (f.fy, r.fy), (f.mz, r.mz)] {
        assert!((x + y).abs() <= 1e-12 * x.abs().max(1.0), "{x} vs {y}");
    }
    // Reversing ξ alone mirrors the contact in y: Fx reverses, Fy and Mz stay.
    let m = s.creep_forces(A, B, N, MU, &creep(-2e-4, -6.25e-4, 0.625));
    assert!((f.fx + m.fx).abs() < 1e-9 * f.fx.abs());
    assert!((f.fy - m.fy).abs() < 1e-9 * f.fy.abs());
    assert!((f.mz - m.mz).abs() < 1e-9 * f.mz.abs());
    // No creepage, no force.
    assert_eq!(
        s.creep_forces(A, B, N, MU, &creep(0.0, 0.0, 0.0)),
        CreepForces::default()
    );
}

#[test]
fn kalker_factor_scales_small_creepage_forces() {
    let base = solver(10, 10);
    let half = Fastrip::new(FastripParams {
        kalker_factor: 0.5,
        ..*base.params()
    })
    .unwrap();
    let c = creep(1e-9, 1e-9, 0.0);
    let (f1, f2) = (
        base.creep_forces(A, B, N, MU, &c),
        half.creep_forces(A, B, N, MU, &c),
    );
    assert!((f2.fx / f1.fx - 0.5).abs() < 1e-3);
}

#[test]
fn agrees_with_fastsim_where_both_are_exact() {
    // Full slip with spin: both put the traction on the elliptic bound along FASTSIM's
    // direction, so they agree to the quadrature of the slip zone.
    let fs = Fastsim::new(FastsimParams {
        nx: 40,
        ny: 40,
        bound: TractionBound::Elliptic,
        shear_modulus: G,
        ..FastsimParams::default()
    })
    .unwrap();
    let c = creep(0.05, 0.05, 20.0);
    let (f, g) = (
        solver(40, 40).creep_forces(A, B, N, MU, &c),
        fs.creep_forces(A, B, N, MU, &c),
    );
    for (x, y) in [(f.fx, g.fx), (f.fy, g.fy)] {
        assert!((x - y).abs() < 5e-3 * MU * N, "{x} vs {y}");
    }
}

#[test]
fn bad_input_names_the_argument() {
    let p = FastripParams::default();
    let c = creep(0.0, 0.0, 0.0);
    let err = fastrip(0.0, B, N, MU, &c, p).unwrap_err();
    assert!(err.to_string().contains("`a`"));
    assert_eq!(
        fastrip(A, B, 0.0, MU, &creep(1e-3, 0.0, 0.0), p).unwrap(),
        CreepForces::default()
    );
    assert_eq!(
        fastrip(A, B, N, 0.0, &creep(1e-3, 0.0, 0.0), p).unwrap(),
        CreepForces::default()
    );
    let err = fastrip(A, B, N, -0.1, &c, p).unwrap_err();
    assert!(err.to_string().contains("mu"));
    let err = fastrip(A, B, N, MU, &c, FastripParams { ny: 0, ..p }).unwrap_err();
    assert!(err.to_string().contains("grid.ny"));
    let err = fastrip(A, B, N, MU, &creep(0.0, f64::NAN, 0.0), p).unwrap_err();
    assert!(err.to_string().contains("creepage_lat"));
    let err = Fastrip::new(FastripParams {
        poisson_ratio: 0.7,
        ..p
    })
    .unwrap_err();
    assert!(err.to_string().contains("nu"));
}

/// The AVX copy's lane layout and the dispatched call give the bits of the baseline layout,
/// with and without the fallback (|φ'| > 1), in partial and full slip, on the default and an
/// odd grid.
#[test]
fn avx_and_baseline_paths_give_the_same_bits() {
    {
        let (a, b) = axes(1.7);
        let mut fallbacks = [0, 0];
        for f in [solver(10, 10), solver(7, 13)] {
            for c in [
                creep(1e-4, -6.25e-4, 0.625),
                creep(-2e-3, 1e-3, 0.0),
                creep(0.0, 0.0, 4.0),
                creep(5e-3, -8e-3, -1.5),
                creep(0.05, 0.02, 0.3),
            ] {
                let call = f.prepare(a, b, 80e3, 0.35, &c).unwrap();
                fallbacks[usize::from(call.phi_s.abs() > 1.0)] += 1;
                let same = |x: CreepForces, y: CreepForces| {
                    [x.fx, x.fy, x.mz].map(f64::to_bits) == [y.fx, y.fy, y.mz].map(f64::to_bits)
                };
                let (plain, four, dispatched) = if call.phi_s.abs() > 1.0 {
                    (
                        f.integrate_lanes::<true, 2, { LANES / 2 }, 0>(&call),
                        f.integrate_lanes::<true, 4, 2, 2>(&call),
                        f.integrate::<true>(&call),
                    )
                } else {
                    (
                        f.integrate_lanes::<false, 2, { LANES / 2 }, 0>(&call),
                        f.integrate_lanes::<false, 4, 2, 2>(&call),
                        f.integrate::<false>(&call),
                    )
                };
                assert!(same(plain, four), "{c:?}: {plain:?} against {four:?}");
                assert!(
                    same(plain, dispatched),
                    "{c:?}: {plain:?} against {dispatched:?}"
                );
            }
        }
        assert!(fallbacks[0] > 0 && fallbacks[1] > 0, "{fallbacks:?}");
    }
}

/// The strips in passes of ten (two AVX registers and a 128-bit one, each register's slip-zone
/// sums from its own first slipping element) give the bits of the twelve-strip passes they
/// replaced, on grids whose strips fill a pass, leave padding or fill several, from adhesion to
/// full slip and beyond |φ'| = 1, on both builds.
#[test]
fn passes_of_ten_give_the_bits_of_the_old_passes_of_twelve() {
    use rand::{RngExt, SeedableRng};
    let mut rng = rand_chacha::ChaCha20Rng::seed_from_u64(34);
    let mut uniform = move || rng.random::<f64>();
    let same = |x: CreepForces, y: CreepForces| {
        [x.fx, x.fy, x.mz].map(f64::to_bits) == [y.fx, y.fy, y.mz].map(f64::to_bits)
    };
    let mut seen = [0_usize; 2];
    for (nx, ny) in [
        (10, 10),
        (20, 20),
        (7, 13),
        (13, 5),
        (3, 25),
        (1, 1),
        (10, 12),
    ] {
        let f = solver(nx, ny);
        for _ in 0..300 {
            let (a, b) = axes(0.2 + 4.0 * uniform());
            let size = 10f64.powf(-6.0 + 4.5 * uniform());
            // Each of the three with either sign: uniform on (−size, size).
            let mut signed = |scale: f64| size * scale * (2.0 * uniform() - 1.0);
            let c = creep(signed(1.0), signed(1.0), signed(2e3));
            let call = f
                .prepare(a, b, 2e4 + 1e5 * uniform(), 0.1 + 0.4 * uniform(), &c)
                .unwrap();
            let fallback = call.phi_s.abs() > 1.0;
            seen[usize::from(fallback)] += 1;
            let (old, plain) = if fallback {
                (
                    reference::creep_forces::<true>(&f, &call),
                    f.integrate_lanes::<true, 2, { LANES / 2 }, 0>(&call),
                )
            } else {
                (
                    reference::creep_forces::<false>(&f, &call),
                    f.integrate_lanes::<false, 2, { LANES / 2 }, 0>(&call),
                )
            };
            assert!(
                same(old, plain),
                "{nx}x{ny} {c:?}: {old:?} against {plain:?}"
            );
            let dispatched = if fallback {
                f.integrate::<true>(&call)
            } else {
                f.integrate::<false>(&call)
            };
            assert!(
                same(old, dispatched),
                "{nx}x{ny} {c:?}: {old:?} against {dispatched:?}"
            );
        }
    }
    assert!(seen[0] > 100 && seen[1] > 100, "{seen:?}");
}

/// The strips' vectorised arc cosine is within 2 ulp of libm's over [−1, 1] (2·10⁵ points and
/// the ends), exact at −1, 0 and 1, and the same alone, in pairs and in fours.
#[test]
fn vectorised_arc_cosine_is_within_two_ulp_of_libm() {
    use super::super::fastrip_lanes::acos;
    use crate::simd::Lanes;
    let n = 200_001;
    let mut worst = 0;
    for i in 0..n {
        let x = -1.0 + 2.0 * i as f64 / (n - 1) as f64;
        let got = acos(Lanes([x])).0[0];
        worst = worst.max((got.to_bits() as i64 - x.acos().to_bits() as i64).unsigned_abs());
        let four = acos(Lanes([x, -x, 0.5 * x, x])).0;
        assert_eq!(four.map(f64::to_bits)[3], got.to_bits(), "{x}");
    }
    assert!(worst <= 2, "{worst} ulp");
    for x in [-1.0, -0.0, 0.0, 1.0] {
        assert_eq!(acos(Lanes([x, x])).0[0], f64::acos(x), "{x}");
    }
}
