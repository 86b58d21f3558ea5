//! Natural cubic interpolating spline z(y) on strictly increasing abscissae.
//!
//! Profiles are interpolated by this spline so that slope and curvature exist everywhere and are
//! continuous (C2): contact angles come from the first derivative and the Hertz ellipse from the
//! second, so a piecewise-linear or C1 (monotone/PCHIP) interpolant would give curvatures that are
//! zero or jump at every data point. "Natural" end conditions (zero second derivative at both ends)
//! are used because the profile ends lie outside the contact zone.

use crate::error::{LocoError, Result};

/// Value, first and second derivative of the spline at one abscissa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SplineValue {
    /// z(y), in the unit of the ordinates (m for profiles).
    pub value: f64,
    /// dz/dy (dimensionless for profiles).
    pub slope: f64,
    /// d²z/dy² (1/m for profiles).
    pub second: f64,
}

/// Natural cubic spline through `(y[i], z[i])`.
#[derive(Debug, Clone, PartialEq)]
pub struct CubicSpline {
    y: Vec<f64>,
    z: Vec<f64>,
    /// Second derivatives at the knots.
    m: Vec<f64>,
}

/// Longest smoothing length, m: the smoothing removes features shorter than it, and a wheel's
/// flange throat radius and its contact patches (semi-axes of some 5–10 mm) are about 10 mm;
/// 2 mm suits measured profiles.
pub const MAX_SMOOTHING_LENGTH: f64 = 0.01;

impl CubicSpline {
    /// Builds the spline; `y` must be strictly increasing and finite, at least 3 points.
    /// `name` names the data in errors.
    pub fn new(name: &str, y: &[f64], z: &[f64]) -> Result<Self> {
        if y.len() != z.len() {
            return Err(LocoError::input(
                name,
                format!("y has {} values but z has {}", y.len(), z.len()),
            ));
        }
        let n = y.len();
        if n < 3 {
            return Err(LocoError::input(
                name,
                format!("needs at least 3 points, got {n}"),
            ));
        }
        for i in 0..n {
            if !y[i].is_finite() || !z[i].is_finite() {
                return Err(LocoError::input(name, format!("point {i} is not finite")));
            }
            if i > 0 && y[i] <= y[i - 1] {
                return Err(LocoError::input(
                    name,
                    format!("y is not strictly increasing at point {i}"),
                ));
            }
        }
        // Tridiagonal system for the interior second derivatives (Thomas algorithm).
        let mut m = vec![0.0; n];
        let mut c_prime = vec![0.0; n];
        let mut d_prime = vec![0.0; n];
        for i in 1..n - 1 {
            let h0 = y[i] - y[i - 1];
            let h1 = y[i + 1] - y[i];
            let a = h0 / 6.0;
            let b = (h0 + h1) / 3.0;
            let c = h1 / 6.0;
            let d = (z[i + 1] - z[i]) / h1 - (z[i] - z[i - 1]) / h0;
            let denom = b - a * c_prime[i - 1];
            c_prime[i] = c / denom;
            d_prime[i] = (d - a * d_prime[i - 1]) / denom;
        }
        for i in (1..n - 1).rev() {
            m[i] = d_prime[i] - c_prime[i] * m[i + 1];
        }
        Ok(Self {
            y: y.to_vec(),
            z: z.to_vec(),
            m,
        })
    }

    /// Natural cubic **smoothing** spline (Reinsch 1967; Green & Silverman 1994, ch. 2): minimises
    /// Σ (z_i − f(y_i))² + λ ∫ f''² dy over the points, with λ in m³ here chosen from a smoothing
    /// length L (m, at most [`MAX_SMOOTHING_LENGTH`]) as λ = L⁴ / h̄ (h̄ the mean point spacing), so that features shorter than about
    /// L are smoothed out and longer ones kept (the spline's equivalent kernel has a bandwidth of
    /// order (λ·h̄)^(1/4) = L). Straight lines are reproduced exactly and, away from the ends,
    /// so are parabolas (constant curvature). `length = 0` interpolates.
    pub fn smoothing(name: &str, y: &[f64], z: &[f64], length: f64) -> Result<Self> {
        let interpolating = Self::new(name, y, z)?;
        if !(length.is_finite() && (0.0..=MAX_SMOOTHING_LENGTH).contains(&length)) {
            return Err(LocoError::param(
                "smoothing_length",
                format!(
                    "must be finite and in [0, {MAX_SMOOTHING_LENGTH}] m, got {length}: \
                     features shorter than the length are removed, and beyond 10 mm that \
                     takes the flange's throat radius and the contact patch's curvatures"
                ),
            ));
        }
        if length == 0.0 {
            return Ok(interpolating);
        }
        let n = y.len();
        let m = n - 2;
        let h: Vec<f64> = (0..n - 1).map(|i| y[i + 1] - y[i]).collect();
        let lambda = length.powi(4) / ((y[n - 1] - y[0]) / (n - 1) as f64);
        // Column c of Q (rows c, c+1, c+2) and the symmetric pentadiagonal R + λ QᵀQ.
        let q = |c: usize| (1.0 / h[c], -(1.0 / h[c] + 1.0 / h[c + 1]), 1.0 / h[c + 1]);
        let mut d = vec![0.0; m];
        let mut e = vec![0.0; m];
        let mut f = vec![0.0; m];
        let mut rhs = vec![0.0; m];
        for c in 0..m {
            let (q0, q1, q2) = q(c);
            d[c] = (h[c] + h[c + 1]) / 3.0 + lambda * (q0 * q0 + q1 * q1 + q2 * q2);
            if c + 1 < m {
                let (p0, p1, _) = q(c + 1);
                e[c] = h[c + 1] / 6.0 + lambda * (q1 * p0 + q2 * p1);
            }
            if c + 2 < m {
                f[c] = lambda * q2 * q(c + 2).0;
            }
            rhs[c] = q0 * z[c] + q1 * z[c + 1] + q2 * z[c + 2];
        }
        let gamma = solve_pentadiagonal(&d, &e, &f, &rhs);
        // Smoothed values g = z − λ Q γ.
        let mut g = z.to_vec();
        for c in 0..m {
            let (q0, q1, q2) = q(c);
            g[c] -= lambda * q0 * gamma[c];
            g[c + 1] -= lambda * q1 * gamma[c];
            g[c + 2] -= lambda * q2 * gamma[c];
        }
        let mut second = vec![0.0; n];
        second[1..n - 1].copy_from_slice(&gamma);
        if g.iter().chain(&second).any(|v| !v.is_finite()) {
            return Err(LocoError::input(
                name,
                "smoothing produced non-finite values",
            ));
        }
        Ok(Self {
            y: interpolating.y,
            z: g,
            m: second,
        })
    }

    /// The knots' abscissae.
    pub fn knots_y(&self) -> &[f64] {
        &self.y
    }

    /// The knots' ordinates.
    pub fn knots_z(&self) -> &[f64] {
        &self.z
    }

    /// Smallest and largest abscissa.
    pub fn range(&self) -> (f64, f64) {
        (self.y[0], self.y[self.y.len() - 1])
    }

    /// Index `i` of the interval `[y[i], y[i+1]]` containing `x` (clamped to the end intervals).
    /// `hint` is tried first so that sweeps in increasing `x` cost O(1) per call.
    #[inline]
    pub fn interval(&self, x: f64, hint: usize) -> usize {
        let n = self.y.len();
        let h = hint.min(n - 2);
        if x >= self.y[h] && x <= self.y[h + 1] {
            return h;
        }
        if h + 2 < n && x >= self.y[h + 1] && x <= self.y[h + 2] {
            return h + 1;
        }
        // partition_point: first knot > x; the interval starts one before.
        let p = self.y.partition_point(|&v| v <= x);
        p.clamp(1, n - 1) - 1
    }

    /// Evaluates at `x` using interval `i` (from [`Self::interval`]). Outside the knots the end
    /// cubic is extrapolated; callers check [`Self::range`] first.
    #[inline]
    pub fn eval_in(&self, i: usize, x: f64) -> SplineValue {
        let (y0, y1) = (self.y[i], self.y[i + 1]);
        let (z0, z1) = (self.z[i], self.z[i + 1]);
        let (m0, m1) = (self.m[i], self.m[i + 1]);
        let h = y1 - y0;
        let a = (y1 - x) / h;
        let b = (x - y0) / h;
        let value = a * z0 + b * z1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
        let slope =
            (z1 - z0) / h - (3.0 * a * a - 1.0) * h / 6.0 * m0 + (3.0 * b * b - 1.0) * h / 6.0 * m1;
        let second = a * m0 + b * m1;
        SplineValue {
            value,
            slope,
            second,
        }
    }

    /// Evaluates at `x` (binary search).
    pub fn eval(&self, x: f64) -> SplineValue {
        self.eval_in(self.interval(x, 0), x)
    }
}

/// Solves the symmetric positive definite pentadiagonal system with diagonal `d`, first
/// super-diagonal `e` and second super-diagonal `f` (LDLᵀ factorisation, no pivoting needed).
fn solve_pentadiagonal(d: &[f64], e: &[f64], f: &[f64], b: &[f64]) -> Vec<f64> {
    let m = d.len();
    let mut dd = vec![0.0; m];
    let mut l1 = vec![0.0; m];
    let mut l2 = vec![0.0; m];
    for i in 0..m {
        if i >= 2 {
            l2[i] = f[i - 2] / dd[i - 2];
        }
        if i >= 1 {
            let carry = if i >= 2 {
                l2[i] * l1[i - 1] * dd[i - 2]
            } else {
                0.0
            };
            l1[i] = (e[i - 1] - carry) / dd[i - 1];
        }
        dd[i] =
            d[i] - if i >= 1 {
                l1[i] * l1[i] * dd[i - 1]
            } else {
                0.0
            } - if i >= 2 {
                l2[i] * l2[i] * dd[i - 2]
            } else {
                0.0
            };
    }
    let mut x = vec![0.0; m];
    for i in 0..m {
        x[i] = b[i]
            - if i >= 1 { l1[i] * x[i - 1] } else { 0.0 }
            - if i >= 2 { l2[i] * x[i - 2] } else { 0.0 };
    }
    for xi in x.iter_mut().zip(&dd) {
        *xi.0 /= xi.1;
    }
    for i in (0..m).rev() {
        let mut v = x[i];
        if i + 1 < m {
            v -= l1[i + 1] * x[i + 1];
        }
        if i + 2 < m {
            v -= l2[i + 2] * x[i + 2];
        }
        x[i] = v;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_a_cubic_inside_and_knots_exactly() {
        // A natural spline reproduces straight lines exactly.
        let y: Vec<f64> = (0..11).map(|i| i as f64 * 0.1).collect();
        let z: Vec<f64> = y.iter().map(|v| 2.0 * v - 1.0).collect();
        let s = CubicSpline::new("line", &y, &z).unwrap();
        let v = s.eval(0.537);
        assert!((v.value - 0.074).abs() < 1e-12);
        assert!((v.slope - 2.0).abs() < 1e-10);
        assert!(v.second.abs() < 1e-9);
    }

    #[test]
    fn circle_curvature_is_recovered() {
        // Points on a circle of radius 0.3 m around its top: z'' at the top ~ -1/R.
        let r = 0.3;
        let y: Vec<f64> = (-200..=200).map(|i| i as f64 * 1e-4).collect();
        let z: Vec<f64> = y.iter().map(|v| (r * r - v * v).sqrt() - r).collect();
        let s = CubicSpline::new("circle", &y, &z).unwrap();
        let v = s.eval(0.0013);
        let k = -v.second / (1.0 + v.slope * v.slope).powf(1.5);
        assert!((k - 1.0 / r).abs() < 1e-3 / r, "curvature {k}");
    }

    #[test]
    fn smoothing_recovers_the_curvature_of_rounded_data() {
        // A R = 0.3 m crown sampled every 0.135 mm and rounded to 1e-5 mm, as the EN 15302 files
        // are: the interpolating spline's curvature is dominated by the rounding, the smoothing
        // spline (L = 2 mm, well below contact patch sizes) recovers 1/R.
        let r = 0.3;
        let y: Vec<f64> = (-222..=222).map(|i| i as f64 * 1.35e-4).collect();
        let z: Vec<f64> = y
            .iter()
            .map(|v| (((r * r - v * v).sqrt() - r) * 1e8).round() * 1e-8)
            .collect();
        let interp = CubicSpline::new("crown", &y, &z).unwrap();
        let smooth = CubicSpline::smoothing("crown", &y, &z, 2e-3).unwrap();
        let curvature = |s: &CubicSpline, x: f64| {
            let v = s.eval(x);
            -v.second / (1.0 + v.slope * v.slope).powf(1.5)
        };
        let xs: Vec<f64> = (-100..=100).map(|i| i as f64 * 1e-4).collect();
        let worst = |s: &CubicSpline| {
            xs.iter()
                .map(|&x| (curvature(s, x) - 1.0 / r).abs())
                .fold(0.0, f64::max)
        };
        eprintln!(
            "curvature error: interpolating {} 1/m, smoothed {} 1/m",
            worst(&interp),
            worst(&smooth)
        );
        assert!(worst(&interp) > 0.5, "rounding noise {}", worst(&interp));
        assert!(worst(&smooth) < 0.1, "smoothed error {}", worst(&smooth));
        // Heights stay on the data within a micrometre.
        for x in &xs {
            assert!((smooth.eval(*x).value - interp.eval(*x).value).abs() < 1e-6);
        }
        // A straight line is reproduced exactly.
        let line: Vec<f64> = y.iter().map(|v| 0.05 * v).collect();
        let s = CubicSpline::smoothing("line", &y, &line, 5e-3).unwrap();
        assert!((s.eval(0.0123).value - 0.05 * 0.0123).abs() < 1e-12);
        assert!(CubicSpline::smoothing("line", &y, &line, -1.0).is_err());
    }

    #[test]
    fn rejects_bad_input() {
        assert!(CubicSpline::new("p", &[0.0, 1.0], &[0.0, 1.0]).is_err());
        assert!(CubicSpline::new("p", &[0.0, 1.0, 1.0], &[0.0, 1.0, 2.0]).is_err());
        assert!(CubicSpline::new("p", &[0.0, 1.0, f64::NAN], &[0.0, 1.0, 2.0]).is_err());
        assert!(CubicSpline::new("p", &[0.0, 1.0, 2.0], &[0.0, 1.0]).is_err());
    }
}
