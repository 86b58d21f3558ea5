//! Eigenvalues (nalgebra's Schur decomposition, unbalanced) of matrices whose spectrum is known
//! by construction, including one scaled like the vehicle's state matrix.

use super::*;

/// Every expected eigenvalue has a computed one within `tol·max(1, |λ|)`, and the counts match.
fn assert_spectrum(a: &[f64], n: usize, expected: &[(f64, f64)], tol: f64) {
    let got = eigenvalues(a, n).unwrap();
    assert_eq!(got.len(), expected.len());
    let mut used = vec![false; got.len()];
    for &(re, im) in expected {
        let (k, d) = got
            .iter()
            .enumerate()
            .filter(|(k, _)| !used[*k])
            .map(|(k, e)| (k, ((e.re - re).powi(2) + (e.im - im).powi(2)).sqrt()))
            .fold(
                (usize::MAX, f64::INFINITY),
                |m, x| if x.1 < m.1 { x } else { m },
            );
        let scale = (re * re + im * im).sqrt().max(1.0);
        assert!(
            d <= tol * scale,
            "{re} + {im}i: nearest off by {d:e} in {got:?}"
        );
        used[k] = true;
    }
}

#[test]
fn companion_matrix_gives_the_polynomial_roots() {
    // (λ + 1)(λ + 2)(λ − 3)(λ² − 2λ + 5), multiplied out below.
    let roots = [
        (-1.0, 0.0),
        (-2.0, 0.0),
        (3.0, 0.0),
        (1.0, 2.0),
        (1.0, -2.0),
    ];
    // Coefficients of the monic polynomial by multiplying out (real arithmetic on pairs).
    let mut c = vec![1.0]; // highest degree first
    let mut mul = |f: &[f64]| {
        let mut out = vec![0.0; c.len() + f.len() - 1];
        for (i, a) in c.iter().enumerate() {
            for (j, b) in f.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        c = out;
    };
    mul(&[1.0, 1.0]);
    mul(&[1.0, 2.0]);
    mul(&[1.0, -3.0]);
    mul(&[1.0, -2.0, 5.0]);
    let n = 5;
    let mut a = vec![0.0; n * n];
    for j in 0..n {
        a[j] = -c[j + 1];
    }
    for i in 1..n {
        a[i * n + i - 1] = 1.0;
    }
    assert_spectrum(&a, n, &roots, 1e-10);
}

#[test]
fn similar_matrix_with_widely_spread_modes() {
    // Block-diagonal D with the kinds of modes a vehicle has (slow drift, lightly damped and
    // unstable oscillations, stiff real poles), hidden by a dense similarity P·D·P⁻¹ and a
    // diagonal scaling that spreads the entries over ten orders of magnitude.
    let pairs = [(-0.05, 25.0), (0.02, 8.0), (-3.0, 2000.0), (-1e-3, 0.4)];
    let reals = [-1e4, -5e3, -0.2, 0.0, -80.0, -1.0];
    let n = 2 * pairs.len() + reals.len();
    let mut d = vec![0.0; n * n];
    let mut expected = Vec::new();
    for (k, &(s, w)) in pairs.iter().enumerate() {
        let i = 2 * k;
        d[i * n + i] = s;
        d[i * n + i + 1] = w;
        d[(i + 1) * n + i] = -w;
        d[(i + 1) * n + i + 1] = s;
        expected.extend([(s, w), (s, -w)]);
    }
    for (k, &r) in reals.iter().enumerate() {
        let i = 2 * pairs.len() + k;
        d[i * n + i] = r;
        expected.push((r, 0.0));
    }
    // Deterministic pseudo-random P = I + 0.4·R, R in [−1, 1].
    let mut seed = 12345_u64;
    let mut next = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let p: Vec<f64> = (0..n * n)
        .map(|k| if k / n == k % n { 1.0 } else { 0.0 } + 0.4 * next())
        .collect();
    let p_inv: Vec<f64> = DMatrix::from_row_slice(n, n, &p)
        .try_inverse()
        .unwrap()
        .transpose()
        .as_slice()
        .to_vec();
    let product = |x: &[f64], y: &[f64]| {
        let mut out = vec![0.0; n * n];
        for i in 0..n {
            for k in 0..n {
                for j in 0..n {
                    out[i * n + j] += x[i * n + k] * y[k * n + j];
                }
            }
        }
        out
    };
    let mut a = product(&product(&p, &d), &p_inv);
    for i in 0..n {
        let s = 10f64.powi(i as i32 % 6 - 2);
        for j in 0..n {
            a[i * n + j] *= s;
            a[j * n + i] /= s;
        }
    }
    assert_spectrum(&a, n, &expected, 1e-8);
}

#[test]
fn damped_oscillator_state_matrix() {
    let (omega, zeta) = (2.0 * std::f64::consts::PI * 4.0, 0.03);
    let a = [0.0, 1.0, -omega * omega, -2.0 * zeta * omega];
    let wd = omega * (1.0 - zeta * zeta).sqrt();
    assert_spectrum(&a, 2, &[(-zeta * omega, wd), (-zeta * omega, -wd)], 1e-12);
}

#[test]
fn bad_input_is_refused() {
    assert!(eigenvalues(&[1.0, 2.0, 3.0], 2).is_err());
    assert!(eigenvalues(&[1.0, f64::NAN, 0.0, 1.0], 2).is_err());
}
