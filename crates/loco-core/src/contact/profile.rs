//! Wheel and rail profiles: points (y, z) in m and a C2 interpolant for height, slope, curvature.
//!
//! # Profile frame (both wheels and rails)
//!
//! Every profile is stored as the profile of the **left** wheel or rail seen in the direction of
//! travel, in the plane of the wheelset axle (cross-section of the track):
//!
//! - `y` lateral in m, **increasing toward the field side** (away from the track centre, i.e. the
//!   track's +y for the left side). The wheel's flange and the rail's gauge corner are therefore
//!   on the **low-y** side. The right wheel and rail use the same profile mirrored (`y → −y` in
//!   track axes); the contact search does this, users never mirror by hand.
//! - `z` vertical in m, **up**.
//! - Wheel origin: the taping line (nominal rolling circle), `y = 0`, `z = 0` on the rolling
//!   circle; `z(y) = r0 − r(y)` is the height of the wheel's lowest point at lateral position `y`
//!   above that of the taping line, so the flange has `z < 0` (radius larger than `r0`). The flange
//!   back (inner face) lies at `y ≈ −0.070` m for UIC/EN and Chinese treads; its distance to the
//!   origin is the wheelset set-up's `flange_back_offset`.
//! - Rail origin: free (usually the top of the rail head or its centre line). The rail is placed
//!   on the track by its gauge point (the gauge-side point `gauge_height` below the highest point
//!   after inclination) and its highest point, so the origin does not matter. Rail profiles are
//!   stored **upright** (not inclined) unless a file says it is already canted, in which case the
//!   set-up's inclination must be 0.
//!
//! This is the frame of the EN 15302 reference files (`RUIC519A.dat`, `SUIC519A.dat`, mm) and of
//! processed SIMPACK profiles with the z axis flipped (SIMPACK uses z down); the loaders convert.
//!
//! EN 15302 reference files (criogenox data, checked against the points): wheels `RUIC519*` have
//! the flange back at y = −70 mm and the taping line at the origin (`flange_back_offset` 0.070).
//! The rail `SUIC519A` is **already inclined** and given in the frame of the centred wheel: its
//! first point (−32.5, −14) mm is the gauge point, 14 mm below z = 0, while the head's highest
//! point is at z = +0.49 mm. To reproduce that set-up use `rail_inclination = 0` and
//! `gauge_height = 0.014 + max(z)` (the gauge point then lands on the file's first point) with
//! gauge 1.435 m and back-to-back 1.360 m: the file's origin is then on the taping line, 750 mm
//! from the track centre, as the standard's Δr functions confirm
//! (`tests/verification/conicity_en15302_profiles.rs`).
//!
//! # Interpolant
//!
//! A natural cubic spline in `y` through the points ([`CubicSpline`]): C2, so the contact angle
//! (slope) and the transverse curvature (second derivative) are continuous. It interpolates;
//! measured or rounded profiles (the EN 15302 files are rounded to 1e-5 mm every 0.135 mm, which
//! alone makes the interpolated curvature wrong by several 1/m) should be smoothed with
//! [`Profile::smoothed`], a cubic smoothing spline with a smoothing length of a few mm (below
//! contact-patch sizes, so the curvature seen by Hertz is kept).

use super::spline::{CubicSpline, SplineValue};
use crate::error::{LocoError, Result};

/// Whether a profile is a wheel or a rail.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ProfileKind {
    /// A wheel profile (flange on the low-y side, origin at the taping line).
    Wheel,
    /// A rail profile (gauge corner on the low-y side).
    Rail,
}

impl ProfileKind {
    /// `"wheel"` or `"rail"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Wheel => "wheel",
            Self::Rail => "rail",
        }
    }

    /// Parses `"wheel"` or `"rail"` (case-insensitive); the error names `field`.
    pub fn parse(field: &str, text: &str) -> Result<Self> {
        match text.to_ascii_lowercase().as_str() {
            "wheel" => Ok(Self::Wheel),
            "rail" => Ok(Self::Rail),
            other => Err(LocoError::param(
                field,
                format!("must be 'wheel' or 'rail', got '{other}'"),
            )),
        }
    }
}

/// Smallest number of points a profile needs.
pub const MIN_PROFILE_POINTS: usize = 5;

/// A wheel or rail profile in the profile frame of the module documentation.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    name: String,
    kind: ProfileKind,
    spline: CubicSpline,
}

impl Profile {
    /// Builds a profile from points `y`, `z` in m, `y` strictly increasing (toward the field
    /// side), at least [`MIN_PROFILE_POINTS`] finite points.
    pub fn new(name: impl Into<String>, kind: ProfileKind, y: &[f64], z: &[f64]) -> Result<Self> {
        let name = name.into();
        if y.len() < MIN_PROFILE_POINTS {
            return Err(LocoError::input(
                format!("profile '{name}'"),
                format!(
                    "needs at least {MIN_PROFILE_POINTS} points, got {}",
                    y.len()
                ),
            ));
        }
        let spline = CubicSpline::new(&format!("profile '{name}'"), y, z)?;
        Ok(Self { name, kind, spline })
    }

    /// The profile's name (file stem or built-in name).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Wheel or rail.
    pub fn kind(&self) -> ProfileKind {
        self.kind
    }

    /// Lateral coordinates of the points, m, strictly increasing.
    pub fn y(&self) -> &[f64] {
        self.spline.knots_y()
    }

    /// Vertical coordinates of the points, m, up.
    pub fn z(&self) -> &[f64] {
        self.spline.knots_z()
    }

    /// Lateral extent `(y_min, y_max)` in m.
    pub fn y_range(&self) -> (f64, f64) {
        self.spline.range()
    }

    /// The interpolant (for the contact search, which evaluates it with interval hints).
    pub(crate) fn spline(&self) -> &CubicSpline {
        &self.spline
    }

    /// Height z (m), slope dz/dy (–) and second derivative d²z/dy² (1/m) at `y` (m); `None` outside
    /// the profile's lateral extent or for a non-finite `y`.
    pub fn evaluate(&self, y: f64) -> Option<SplineValue> {
        let (lo, hi) = self.y_range();
        if y.is_finite() && y >= lo && y <= hi {
            Some(self.spline.eval(y))
        } else {
            None
        }
    }

    fn evaluate_checked(&self, y: f64) -> Result<SplineValue> {
        self.evaluate(y).ok_or_else(|| {
            let (lo, hi) = self.y_range();
            LocoError::input(
                "y",
                format!("{y} m is outside profile '{}' ({lo} .. {hi} m)", self.name),
            )
        })
    }

    /// Height z (m, up) at lateral position `y` (m).
    pub fn height(&self, y: f64) -> Result<f64> {
        Ok(self.evaluate_checked(y)?.value)
    }

    /// Slope dz/dy (dimensionless) at `y` (m).
    pub fn slope(&self, y: f64) -> Result<f64> {
        Ok(self.evaluate_checked(y)?.slope)
    }

    /// Signed curvature of the curve z(y) at `y`, in 1/m: `z'' / (1 + z'^2)^(3/2)`, positive where
    /// the profile bends upward (a cup), negative for a cap such as a rail crown (−1/0.3 m for a
    /// 300 mm crown radius).
    pub fn curvature(&self, y: f64) -> Result<f64> {
        let v = self.evaluate_checked(y)?;
        Ok(v.second / (1.0 + v.slope * v.slope).powf(1.5))
    }

    /// The profile smoothed by a natural cubic smoothing spline with smoothing `length` (m):
    /// features shorter than about `length` are removed, longer ones kept; straight parts and
    /// constant-curvature arcs (away from the ends) are unchanged. 2e-3 m suits measured wheel
    /// and rail profiles; 0 returns the interpolating profile. The points' z become the smoothed
    /// heights.
    pub fn smoothed(&self, length: f64) -> Result<Self> {
        let spline = CubicSpline::smoothing(
            &format!("profile '{}'", self.name),
            self.y(),
            self.z(),
            length,
        )?;
        Ok(Self {
            name: self.name.clone(),
            kind: self.kind,
            spline,
        })
    }

    /// The same profile with another name.
    pub fn renamed(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle_rail() -> Profile {
        let r = 0.3;
        let y: Vec<f64> = (-300..=300).map(|i| i as f64 * 1e-4).collect();
        let z: Vec<f64> = y.iter().map(|v| (r * r - v * v).sqrt() - r).collect();
        Profile::new("crown", ProfileKind::Rail, &y, &z).unwrap()
    }

    #[test]
    fn height_slope_curvature_of_a_crown() {
        let p = circle_rail();
        assert!(p.height(0.0).unwrap().abs() < 1e-12);
        let y = 0.01_f64;
        let exact_slope = -y / (0.09 - y * y).sqrt();
        assert!((p.slope(y).unwrap() - exact_slope).abs() < 1e-7);
        assert!((p.curvature(y).unwrap() + 1.0 / 0.3).abs() < 1e-3);
        assert!(p.height(0.5).is_err());
        assert!(p.height(f64::NAN).is_err());
    }

    #[test]
    fn too_few_or_unsorted_points_are_rejected() {
        let e = Profile::new("p", ProfileKind::Wheel, &[0.0, 1.0, 2.0], &[0.0; 3]).unwrap_err();
        assert!(e.to_string().contains("at least"));
        let y = [0.0, 1.0, 3.0, 2.0, 4.0];
        let e = Profile::new("p", ProfileKind::Wheel, &y, &[0.0; 5]).unwrap_err();
        assert!(e.to_string().contains("point 3"));
        assert_eq!(
            ProfileKind::parse("kind", "Rail").unwrap(),
            ProfileKind::Rail
        );
        assert!(ProfileKind::parse("kind", "axle").is_err());
    }
}
