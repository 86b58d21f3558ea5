//! Eigenvalues of a real square matrix, for the linear stability of the vehicle: the least damped
//! mode and the linear critical speed ([`super::linearise`], `loco.critical_speed`). Only
//! `loco.eigen`, which also needs the mode shapes, uses LAPACK through numpy.
//!
//! The classical dense algorithm (Wilkinson and Reinsch, Handbook for Automatic Computation II,
//! 1971: `balanc`, `elmhes`, `hqr`): balancing by powers of two (the vehicle's state matrix mixes
//! entries of order 1 with contact stiffness over mass, ~10⁸ 1/s²), reduction to upper Hessenberg
//! form by stabilised elementary similarity transformations, then Francis' double-shift QR
//! iteration. Eigenvalues only, O(n³): about 10 ms for the vehicle's ~200 states.

use crate::error::{LocoError, Result};

/// A complex eigenvalue `re + i·im` (units of the matrix: 1/s for a state matrix).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Eigenvalue {
    pub re: f64,
    pub im: f64,
}

/// Most QR iterations spent on one eigenvalue before giving up (a handful is typical).
const MAX_ITERATIONS: usize = 60;

/// The n×n matrix with 1-based indices, as the algorithms are stated.
struct Matrix {
    n: usize,
    a: Vec<f64>,
}

impl Matrix {
    #[inline]
    fn at(&self, i: usize, j: usize) -> f64 {
        self.a[(i - 1) * self.n + (j - 1)]
    }
    #[inline]
    fn at_mut(&mut self, i: usize, j: usize) -> &mut f64 {
        &mut self.a[(i - 1) * self.n + (j - 1)]
    }
}

/// Eigenvalues of the row-major n×n matrix `a`, in no particular order; complex ones come in
/// conjugate pairs. Fails on a wrong size, a non-finite entry or a QR iteration that does not
/// converge.
pub fn eigenvalues(a: &[f64], n: usize) -> Result<Vec<Eigenvalue>> {
    if a.len() != n * n {
        return Err(LocoError::input(
            "matrix",
            format!("expected {n}×{n} entries, got {}", a.len()),
        ));
    }
    if a.iter().any(|v| !v.is_finite()) {
        return Err(LocoError::input("matrix", "has a non-finite entry"));
    }
    let mut m = Matrix { n, a: a.to_vec() };
    balance(&mut m);
    hessenberg(&mut m);
    qr_eigenvalues(&mut m)
}

/// Scales rows and columns by powers of two until their off-diagonal norms are comparable.
fn balance(m: &mut Matrix) {
    const RADIX: f64 = 2.0;
    let n = m.n;
    let mut done = false;
    while !done {
        done = true;
        for i in 1..=n {
            let (mut c, mut r) = (0.0, 0.0);
            for j in (1..=n).filter(|&j| j != i) {
                c += m.at(j, i).abs();
                r += m.at(i, j).abs();
            }
            if c == 0.0 || r == 0.0 {
                continue;
            }
            let s = c + r;
            let mut f = 1.0;
            while c < r / RADIX {
                f *= RADIX;
                c *= RADIX * RADIX;
            }
            while c > r * RADIX {
                f /= RADIX;
                c /= RADIX * RADIX;
            }
            if (c + r) / f < 0.95 * s {
                done = false;
                for j in 1..=n {
                    *m.at_mut(i, j) /= f;
                    *m.at_mut(j, i) *= f;
                }
            }
        }
    }
}

/// Reduces to upper Hessenberg form by elimination with partial pivoting (a similarity).
fn hessenberg(m: &mut Matrix) {
    let n = m.n;
    for k in 2..n {
        let (mut x, mut pivot) = (0.0_f64, k);
        for j in k..=n {
            if m.at(j, k - 1).abs() > x.abs() {
                x = m.at(j, k - 1);
                pivot = j;
            }
        }
        if pivot != k {
            for j in k - 1..=n {
                let t = m.at(pivot, j);
                *m.at_mut(pivot, j) = m.at(k, j);
                *m.at_mut(k, j) = t;
            }
            for j in 1..=n {
                let t = m.at(j, pivot);
                *m.at_mut(j, pivot) = m.at(j, k);
                *m.at_mut(j, k) = t;
            }
        }
        if x == 0.0 {
            continue;
        }
        for i in k + 1..=n {
            let y = m.at(i, k - 1) / x;
            *m.at_mut(i, k - 1) = 0.0;
            if y != 0.0 {
                for j in k..=n {
                    *m.at_mut(i, j) -= y * m.at(k, j);
                }
                for j in 1..=n {
                    *m.at_mut(j, k) += y * m.at(j, i);
                }
            }
        }
    }
}

/// Francis double-shift QR on an upper Hessenberg matrix (destroyed).
fn qr_eigenvalues(m: &mut Matrix) -> Result<Vec<Eigenvalue>> {
    let n = m.n;
    let mut out = vec![Eigenvalue { re: 0.0, im: 0.0 }; n + 1];
    let mut norm = 0.0;
    for i in 1..=n {
        for j in i.saturating_sub(1).max(1)..=n {
            norm += m.at(i, j).abs();
        }
    }
    let mut nn = n;
    let mut shift = 0.0;
    while nn >= 1 {
        let mut its = 0;
        loop {
            // Look for a negligible subdiagonal element that splits the matrix.
            let mut l = nn;
            while l >= 2 {
                let mut s = m.at(l - 1, l - 1).abs() + m.at(l, l).abs();
                if s == 0.0 {
                    s = norm;
                }
                if m.at(l, l - 1).abs() <= f64::EPSILON * s {
                    *m.at_mut(l, l - 1) = 0.0;
                    break;
                }
                l -= 1;
            }
            let mut x = m.at(nn, nn);
            if l == nn {
                out[nn] = Eigenvalue {
                    re: x + shift,
                    im: 0.0,
                };
                nn -= 1;
                break;
            }
            let mut y = m.at(nn - 1, nn - 1);
            let mut w = m.at(nn, nn - 1) * m.at(nn - 1, nn);
            if l == nn - 1 {
                // A 2×2 block: a real pair or a complex conjugate pair.
                let p = 0.5 * (y - x);
                let q = p * p + w;
                let z = q.abs().sqrt();
                x += shift;
                if q >= 0.0 {
                    let z = p + z.copysign(p);
                    let second = if z != 0.0 { x - w / z } else { x + z };
                    out[nn - 1] = Eigenvalue { re: x + z, im: 0.0 };
                    out[nn] = Eigenvalue {
                        re: second,
                        im: 0.0,
                    };
                } else {
                    out[nn - 1] = Eigenvalue { re: x + p, im: -z };
                    out[nn] = Eigenvalue { re: x + p, im: z };
                }
                nn -= 2;
                break;
            }
            if its == MAX_ITERATIONS {
                return Err(LocoError::input(
                    "matrix",
                    format!("QR iteration did not converge for eigenvalue {nn} of {n}"),
                ));
            }
            if its > 0 && its % 10 == 0 {
                // Exceptional shift against cycling.
                shift += x;
                for i in 1..=nn {
                    *m.at_mut(i, i) -= x;
                }
                let s = m.at(nn, nn - 1).abs() + m.at(nn - 1, nn - 2).abs();
                x = 0.75 * s;
                y = x;
                w = -0.4375 * s * s;
            }
            its += 1;
            double_shift_sweep(m, l, nn, x, y, w);
        }
    }
    Ok(out.into_iter().skip(1).collect())
}

/// One implicit double-shift QR sweep on rows and columns `l..=nn`, shifts from `x`, `y`, `w`.
fn double_shift_sweep(m: &mut Matrix, l: usize, nn: usize, x: f64, y: f64, w: f64) {
    // Find two consecutive small subdiagonal elements to start the bulge at row `k0`.
    let mut k0 = nn - 2;
    let (mut p, mut q, mut r) = loop {
        let z = m.at(k0, k0);
        let (rr, ss) = (x - z, y - z);
        let p = (rr * ss - w) / m.at(k0 + 1, k0) + m.at(k0, k0 + 1);
        let q = m.at(k0 + 1, k0 + 1) - z - rr - ss;
        let r = m.at(k0 + 2, k0 + 1);
        let s = p.abs() + q.abs() + r.abs();
        let (p, q, r) = (p / s, q / s, r / s);
        if k0 == l {
            break (p, q, r);
        }
        let u = m.at(k0, k0 - 1).abs() * (q.abs() + r.abs());
        let v = p.abs() * (m.at(k0 - 1, k0 - 1).abs() + z.abs() + m.at(k0 + 1, k0 + 1).abs());
        if u <= f64::EPSILON * v {
            break (p, q, r);
        }
        k0 -= 1;
    };
    for i in k0 + 2..=nn {
        *m.at_mut(i, i - 2) = 0.0;
        if i != k0 + 2 {
            *m.at_mut(i, i - 3) = 0.0;
        }
    }
    let mut scale = 0.0;
    for k in k0..nn {
        if k != k0 {
            p = m.at(k, k - 1);
            q = m.at(k + 1, k - 1);
            r = if k != nn - 1 { m.at(k + 2, k - 1) } else { 0.0 };
            scale = p.abs() + q.abs() + r.abs();
            if scale != 0.0 {
                p /= scale;
                q /= scale;
                r /= scale;
            }
        }
        let s = (p * p + q * q + r * r).sqrt().copysign(p);
        if s == 0.0 {
            continue;
        }
        if k == k0 {
            if l != k0 {
                *m.at_mut(k, k - 1) = -m.at(k, k - 1);
            }
        } else {
            *m.at_mut(k, k - 1) = -s * scale;
        }
        p += s;
        let (hx, hy, hz) = (p / s, q / s, r / s);
        let (q, r) = (q / p, r / p);
        // Row transformation.
        for j in k..=nn {
            let mut t = m.at(k, j) + q * m.at(k + 1, j);
            if k != nn - 1 {
                t += r * m.at(k + 2, j);
                *m.at_mut(k + 2, j) -= t * hz;
            }
            *m.at_mut(k + 1, j) -= t * hy;
            *m.at_mut(k, j) -= t * hx;
        }
        // Column transformation.
        for i in l..=nn.min(k + 3) {
            let mut t = hx * m.at(i, k) + hy * m.at(i, k + 1);
            if k != nn - 1 {
                t += hz * m.at(i, k + 2);
                *m.at_mut(i, k + 2) -= t * r;
            }
            *m.at_mut(i, k + 1) -= t * q;
            *m.at_mut(i, k) -= t;
        }
    }
}

#[cfg(test)]
#[path = "eigenvalues_tests.rs"]
mod tests;
