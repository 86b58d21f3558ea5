//! Small dense linear algebra for the static equilibrium and the linearisation: LU with partial
//! pivoting on row-major square matrices.

use crate::error::{LocoError, Result};

/// LU factorisation with partial pivoting of an n×n row-major matrix.
#[derive(Debug, Clone)]
pub struct Lu {
    n: usize,
    lu: Vec<f64>,
    pivot: Vec<usize>,
}

impl Lu {
    /// Factorises `a` (n×n, row-major); fails on a (numerically) singular matrix, naming `what`.
    pub fn new(mut a: Vec<f64>, n: usize, what: &str) -> Result<Self> {
        if a.len() != n * n {
            return Err(LocoError::input(
                what,
                format!("expected {n}×{n} entries, got {}", a.len()),
            ));
        }
        let scale = a.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let mut pivot: Vec<usize> = (0..n).collect();
        for k in 0..n {
            let (p, max) = (k..n)
                .map(|i| (i, a[i * n + k].abs()))
                .fold((k, -1.0), |acc, x| if x.1 > acc.1 { x } else { acc });
            if max.is_nan() || max <= 1e-14 * scale {
                return Err(LocoError::input(
                    what,
                    format!(
                        "matrix is singular (column {k}): a body or coordinate is unrestrained"
                    ),
                ));
            }
            if p != k {
                for j in 0..n {
                    a.swap(k * n + j, p * n + j);
                }
                pivot.swap(k, p);
            }
            let d = a[k * n + k];
            for i in k + 1..n {
                let f = a[i * n + k] / d;
                a[i * n + k] = f;
                if f != 0.0 {
                    for j in k + 1..n {
                        a[i * n + j] -= f * a[k * n + j];
                    }
                }
            }
        }
        Ok(Self { n, lu: a, pivot })
    }

    /// Solves `A x = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let n = self.n;
        let mut x: Vec<f64> = self.pivot.iter().map(|&p| b[p]).collect();
        for i in 0..n {
            let s: f64 = (0..i).map(|j| self.lu[i * n + j] * x[j]).sum();
            x[i] -= s;
        }
        for i in (0..n).rev() {
            let s: f64 = (i + 1..n).map(|j| self.lu[i * n + j] * x[j]).sum();
            x[i] = (x[i] - s) / self.lu[i * n + i];
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_pivoting_system() {
        let a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let lu = Lu::new(a.clone(), 3, "a").unwrap();
        let x = lu.solve(&[3.0, 2.0, 4.0]);
        for i in 0..3 {
            let r: f64 = (0..3).map(|j| a[i * 3 + j] * x[j]).sum();
            assert!((r - [3.0, 2.0, 4.0][i]).abs() < 1e-12);
        }
        assert!(Lu::new(vec![1.0, 2.0, 2.0, 4.0], 2, "s").is_err());
    }
}
