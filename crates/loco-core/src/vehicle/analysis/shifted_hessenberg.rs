//! Solves `(iω I − A) x = b` for many frequencies ω with one O(n³) reduction of A.
//!
//! `A = Q H Qᵀ` with H upper Hessenberg (nalgebra's Householder reduction, once). Then
//! `(iω I − H) z = Qᵀ b`, `x = Q z`: the shifted matrix is still upper Hessenberg, and Gaussian
//! elimination with partial pivoting only ever compares a row with the one below it, so each
//! frequency costs O(n²) for the factorisation and O(n²) per right-hand side instead of the
//! O(n³) of a dense complex solve. Callers keep the right-hand sides and outputs in the reduced
//! basis (`Qᵀ B`, `C Q` formed once), so Q is never applied per frequency.

use crate::error::{LocoError, Result};
use nalgebra::{Complex, DMatrix, Hessenberg};

/// Complex double.
pub type C64 = Complex<f64>;

/// A real square matrix in Hessenberg form with its orthogonal basis.
#[derive(Debug, Clone)]
pub struct ShiftedHessenberg {
    n: usize,
    /// H, row-major n×n.
    h: Vec<f64>,
    /// Q (A = Q H Qᵀ).
    q: DMatrix<f64>,
    /// Workspace: the shifted matrix with the right-hand sides appended, row-major.
    work: Vec<C64>,
}

impl ShiftedHessenberg {
    /// Reduces the row-major n×n matrix `a`.
    pub fn new(a: &[f64], n: usize) -> Self {
        let matrix = DMatrix::from_row_slice(n, n, a);
        let (q, h) = Hessenberg::new(matrix).unpack();
        let mut rows = vec![0.0; n * n];
        for i in 0..n {
            // Below the first subdiagonal the reduction leaves exact zeros by construction.
            for j in i.saturating_sub(1)..n {
                rows[i * n + j] = h[(i, j)];
            }
        }
        Self {
            n,
            h: rows,
            q,
            work: Vec::new(),
        }
    }

    /// Order n.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Always false for a reduced matrix.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The orthogonal basis Q (n×n).
    pub fn basis(&self) -> &DMatrix<f64> {
        &self.q
    }

    /// Solves `(s I − H) z_r = rhs_r` for every right-hand side `rhs[r]` (length n, in the
    /// reduced basis), overwriting them with the solutions. `s` is the complex shift (iω, 1/s).
    pub fn solve_shifted(&mut self, s: C64, rhs: &mut [Vec<C64>]) -> Result<()> {
        let n = self.n;
        let r = rhs.len();
        let width = n + r;
        self.work.clear();
        self.work.resize(n * width, C64::new(0.0, 0.0));
        let m = &mut self.work;
        for i in 0..n {
            for j in i.saturating_sub(1)..n {
                m[i * width + j] = C64::new(-self.h[i * n + j], 0.0);
            }
            m[i * width + i] += s;
            for (k, b) in rhs.iter().enumerate() {
                m[i * width + n + k] = b[i];
            }
        }
        // Elimination: row k+1 is the only one with an entry below the pivot of column k.
        for k in 0..n.saturating_sub(1) {
            let (upper, lower) = (k * width, (k + 1) * width);
            if m[lower + k].norm_sqr() > m[upper + k].norm_sqr() {
                for j in k..width {
                    m.swap(upper + j, lower + j);
                }
            }
            let pivot = m[upper + k];
            if pivot.norm_sqr() == 0.0 {
                return Err(singular(s));
            }
            let factor = m[lower + k] / pivot;
            if factor.norm_sqr() != 0.0 {
                for j in k..width {
                    let u = m[upper + j];
                    m[lower + j] -= factor * u;
                }
            }
        }
        // Back substitution on the upper triangle, all right-hand sides at once.
        for i in (0..n).rev() {
            let pivot = m[i * width + i];
            if pivot.norm_sqr() == 0.0 || !pivot.is_finite() {
                return Err(singular(s));
            }
            for k in 0..r {
                let mut acc = m[i * width + n + k];
                for j in i + 1..n {
                    acc -= m[i * width + j] * rhs[k][j];
                }
                rhs[k][i] = acc / pivot;
            }
        }
        Ok(())
    }
}

fn singular(s: C64) -> LocoError {
    LocoError::param(
        "frequencies",
        format!(
            "{} Hz is an eigenfrequency of the undamped linear model (iω I − A is singular)",
            s.im / (2.0 * std::f64::consts::PI)
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_a_dense_complex_solve() {
        // A deterministic non-symmetric 7×7 matrix; the dense reference is nalgebra's LU.
        let n = 7;
        let a: Vec<f64> = (0..n * n)
            .map(|k| ((k * 37 % 11) as f64 - 5.0) * 0.3 + if k % (n + 1) == 0 { -2.0 } else { 0.0 })
            .collect();
        let mut solver = ShiftedHessenberg::new(&a, n);
        let b: Vec<C64> = (0..n)
            .map(|i| C64::new(i as f64 - 2.0, 0.5 * i as f64))
            .collect();
        let q = solver.basis().clone();
        for omega in [0.3, 2.0, 17.0] {
            let s = C64::new(0.0, omega);
            // Reduced right-hand side Qᵀ b, solve, back to x = Q z.
            let qtb: Vec<C64> = (0..n)
                .map(|i| (0..n).map(|j| b[j] * q[(j, i)]).sum())
                .collect();
            let mut rhs = vec![qtb];
            solver.solve_shifted(s, &mut rhs).unwrap();
            let x: Vec<C64> = (0..n)
                .map(|i| (0..n).map(|j| rhs[0][j] * q[(i, j)]).sum())
                .collect();
            let dense = DMatrix::from_fn(n, n, |i, j| {
                let d = if i == j { s } else { C64::new(0.0, 0.0) };
                d - C64::new(a[i * n + j], 0.0)
            });
            let reference = dense
                .lu()
                .solve(&nalgebra::DVector::from_vec(b.clone()))
                .unwrap();
            for i in 0..n {
                assert!((x[i] - reference[i]).norm() < 1e-12 * (1.0 + reference[i].norm()));
            }
        }
    }
}
