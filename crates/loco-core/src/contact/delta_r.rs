//! The rolling radius difference function Δr(y) of a wheelset on a track, as sampled data.
//!
//! Δr(y) = r_left(y) − r_right(y) (m) for the wheelset's lateral displacement y (m, + to the left,
//! `docs/CONVENTIONS.md`). A wheelset displaced to the left rolls on a larger left radius, so Δr
//! grows with y; the equivalent conicity methods ([`super::conicity`],
//! [`super::conicity_harmonic`]) only read this function. Between samples Δr is taken as linear,
//! so that its integral, the kinematic "potential" S(y) = ∫ Δr dy, is exact and piecewise quadratic.

use crate::error::{check_all_finite, LocoError, Result};

/// Δr(y) sampled on a strictly increasing lateral grid, linear between samples.
#[derive(Debug, Clone, PartialEq)]
pub struct DeltaR {
    /// Lateral wheelset displacements (m), strictly increasing.
    y: Vec<f64>,
    /// Rolling radius difference r_left − r_right at each `y` (m).
    dr: Vec<f64>,
    /// S(y_i) = ∫_{y_0}^{y_i} Δr dy (m²), exact for the piecewise-linear Δr.
    potential: Vec<f64>,
}

impl DeltaR {
    /// Checks and stores a sampled Δr(y): `y` (m) strictly increasing, `dr` (m) of the same
    /// length, both finite, at least two samples.
    pub fn new(y: Vec<f64>, dr: Vec<f64>) -> Result<Self> {
        if y.len() != dr.len() {
            return Err(LocoError::input(
                "dr",
                format!("has {} values but y has {}", dr.len(), y.len()),
            ));
        }
        if y.len() < 2 {
            return Err(LocoError::input("y", "needs at least two samples"));
        }
        check_all_finite("y", &y)?;
        check_all_finite("dr", &dr)?;
        if let Some(i) = y.windows(2).position(|w| w[1] <= w[0]) {
            return Err(LocoError::input(
                "y",
                format!("must be strictly increasing (element {} <= {i})", i + 1),
            ));
        }
        let mut potential = Vec::with_capacity(y.len());
        potential.push(0.0);
        for i in 1..y.len() {
            let step = 0.5 * (dr[i] + dr[i - 1]) * (y[i] - y[i - 1]);
            potential.push(potential[i - 1] + step);
        }
        Ok(Self { y, dr, potential })
    }

    /// The lateral grid (m).
    pub fn y(&self) -> &[f64] {
        &self.y
    }

    /// Δr at the grid points (m).
    pub fn values(&self) -> &[f64] {
        &self.dr
    }

    /// First and last grid point (m).
    pub fn range(&self) -> (f64, f64) {
        (self.y[0], self.y[self.y.len() - 1])
    }

    /// S(y_i) at the grid points (m²).
    pub(crate) fn potential_at_nodes(&self) -> &[f64] {
        &self.potential
    }

    /// Index i of the segment [y_i, y_{i+1}] holding `y` (clamped to the first or last segment).
    pub(crate) fn segment(&self, y: f64) -> usize {
        let upper = self.y.partition_point(|&node| node <= y);
        upper.clamp(1, self.y.len() - 1) - 1
    }

    /// Δr(y) (m), linear between samples; `y` must lie in [`Self::range`].
    pub fn value(&self, y: f64) -> f64 {
        let i = self.segment(y);
        let t = y - self.y[i];
        self.dr[i] + self.slope(i) * t
    }

    /// S(y) = ∫ Δr dy from the first grid point (m²); `y` must lie in [`Self::range`].
    pub(crate) fn potential(&self, y: f64) -> f64 {
        let i = self.segment(y);
        // At the grid points, the stored sums exactly (the turning-point search compares them).
        if y == self.y[i + 1] {
            return self.potential[i + 1];
        }
        let t = y - self.y[i];
        self.potential[i] + self.dr[i] * t + 0.5 * self.slope(i) * t * t
    }

    /// ∫_a^b Δr dy = S(b) − S(a) (m²), `a`, `b` in [`Self::range`], computed piecewise so that
    /// it has no cancellation error when `a` and `b` are close (near a turning point, where
    /// S(a) and S(b) are large and nearly equal).
    pub(crate) fn integral(&self, a: f64, b: f64) -> f64 {
        if a > b {
            return -self.integral(b, a);
        }
        let (i, j) = (self.segment(a), self.segment(b));
        if i == j {
            return (b - a) * self.value(0.5 * (a + b));
        }
        // Partial first and last segments exactly (Δr linear: midpoint rule), full ones between.
        let first_end = self.y[i + 1];
        let last_start = self.y[j];
        (first_end - a) * self.value(0.5 * (a + first_end))
            + (self.potential[j] - self.potential[i + 1])
            + (b - last_start) * self.value(0.5 * (last_start + b))
    }

    /// dΔr/dy on segment i (-).
    pub(crate) fn slope(&self, i: usize) -> f64 {
        (self.dr[i + 1] - self.dr[i]) / (self.y[i + 1] - self.y[i])
    }

    /// The centred running position: the upward zero crossing of Δr (Δr ≤ 0 on its left, > 0 on
    /// its right, a minimum of S) nearest to y = 0, as `(y_eq, node index right of it)`.
    ///
    /// A wheelset with different wheel radii or profiles (EN 15302 cases E5–E9) runs off centre;
    /// the kinematic oscillation is about this point. When Δr is zero on a whole interval, the
    /// crossing is that interval's right end, and the interval is a neutral zone.
    pub(crate) fn equilibrium(&self) -> Result<(f64, usize)> {
        let mut best: Option<(f64, usize)> = None;
        for i in 0..self.y.len() - 1 {
            let (a, b) = (self.dr[i], self.dr[i + 1]);
            if a <= 0.0 && b > 0.0 {
                let y_eq = self.y[i] - a * (self.y[i + 1] - self.y[i]) / (b - a);
                if best.is_none_or(|(y_best, _)| y_eq.abs() < y_best.abs()) {
                    best = Some((y_eq, i + 1));
                }
            }
        }
        best.ok_or_else(|| {
            LocoError::input(
                "dr",
                "never changes sign from <= 0 to > 0: the wheelset has no centred running position",
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_interpolation_and_exact_potential() {
        let y = vec![-2.0, -1.0, 0.0, 1.0, 3.0];
        let dr: Vec<f64> = y.iter().map(|v| 0.2 * v).collect();
        let f = DeltaR::new(y, dr).unwrap();
        assert!((f.value(0.5) - 0.1).abs() < 1e-15);
        // S(y) = 0.1 (y² − 4) for Δr = 0.2 y from y = −2.
        for q in [-1.7, -0.2, 0.0, 1.4, 2.9] {
            assert!((f.potential(q) - 0.1 * (q * q - 4.0)).abs() < 1e-14, "{q}");
        }
        assert!((f.integral(1.4, -1.7) - 0.1 * (1.7f64.powi(2) - 1.4f64.powi(2))).abs() < 1e-15);
        assert!((f.integral(0.2, 0.3) - 0.1 * (0.09 - 0.04)).abs() < 1e-16);
        let (y_eq, i) = f.equilibrium().unwrap();
        assert!(y_eq.abs() < 1e-15 && i == 3);
    }

    #[test]
    fn rejects_bad_grids() {
        assert!(DeltaR::new(vec![0.0, 1.0], vec![0.0]).is_err());
        assert!(DeltaR::new(vec![0.0], vec![0.0]).is_err());
        let err = DeltaR::new(vec![0.0, 0.0], vec![0.0, 1.0]).unwrap_err();
        assert!(err.to_string().contains("`y`"));
        assert!(DeltaR::new(vec![0.0, 1.0], vec![f64::NAN, 1.0]).is_err());
        let no_crossing = DeltaR::new(vec![0.0, 1.0], vec![1.0, 2.0]).unwrap();
        assert!(no_crossing.equilibrium().is_err());
    }
}
