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
    fn rejects_bad_input() {
        assert!(CubicSpline::new("p", &[0.0, 1.0], &[0.0, 1.0]).is_err());
        assert!(CubicSpline::new("p", &[0.0, 1.0, 1.0], &[0.0, 1.0, 2.0]).is_err());
        assert!(CubicSpline::new("p", &[0.0, 1.0, f64::NAN], &[0.0, 1.0, 2.0]).is_err());
        assert!(CubicSpline::new("p", &[0.0, 1.0, 2.0], &[0.0, 1.0]).is_err());
    }
}
