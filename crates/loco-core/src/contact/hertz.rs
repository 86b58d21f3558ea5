//! Hertz's solution of the elastic normal contact between wheel and rail.
//!
//! Near the contact point the gap between the undeformed surfaces is `h = A x² + B y² − δ`, with
//! `x` the rolling direction, `y` lateral, and the principal relative curvatures (1/m)
//!
//! ```text
//! A = ½ (1/R_wheel_rolling + 1/R_rail_longitudinal)     (straight rail: 1/R_rail_longitudinal = 0)
//! B = ½ (1/R_wheel_transverse + 1/R_rail_transverse)
//! ```
//!
//! Radii are signed: convex positive, concave negative (a hollow-worn wheel tread or the flange
//! root has a negative transverse radius); an infinite radius is a straight generator (cone, flat).
//! Both `A` and `B` must be positive for an elliptic contact.
//!
//! The solution (K. L. Johnson, *Contact Mechanics*, CUP 1985, §4.2, eqs. 4.39 and the following;
//! the same closed form is in Hertz 1882) is, for the semi-axis `c_major` along the direction of the
//! smaller relative curvature and `c_minor = g·c_major` (`g ≤ 1`, eccentricity `e² = 1 − g²`, `K` and
//! `E` the complete elliptic integrals of modulus `e`):
//!
//! ```text
//! A_min / A_max = (K − E) / (E/g² − K)                        (fixes g)
//! c_major³     = 3 N E / (2π g² (A + B) E*)
//! p0           = 3 N / (2π a b)                                (peak pressure)
//! δ            = 3 N K / (2π c_major E*)                       (mutual approach)
//! ```
//!
//! with the contact modulus `1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂`. Since `c ∝ N^{1/3}` and
//! `δ ∝ N^{2/3}`, the load–approach law is `N = K_H δ^{3/2}` with a stiffness `K_H` that depends on
//! the geometry only: [`HertzCoefficients`] solves the transcendental equation once per geometry,
//! and then the ellipse for any load and the load for any approach cost a cube root or a square
//! root (no iteration, no allocation) — the form the vehicle model's time loop needs.

use super::elliptic::{axis_ratio, elliptic_ke};
use crate::error::{check_finite, check_non_negative, check_positive, LocoError, Result};
use std::f64::consts::PI;

/// Elastic constants of wheel and rail, both of the same material (steel by default).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElasticMaterial {
    /// Young's modulus E (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν (–).
    pub poisson_ratio: f64,
}

impl Default for ElasticMaterial {
    /// Steel: E = 2.1e11 Pa, ν = 0.28.
    fn default() -> Self {
        Self {
            youngs_modulus: 2.1e11,
            poisson_ratio: 0.28,
        }
    }
}

impl ElasticMaterial {
    /// Checks that E > 0 and 0 ≤ ν < 0.5 (errors name `E` and `nu`, the symbols of the Python API).
    pub fn validate(&self) -> Result<()> {
        check_positive("E", self.youngs_modulus)?;
        check_non_negative("nu", self.poisson_ratio)?;
        if self.poisson_ratio >= 0.5 {
            return Err(LocoError::param(
                "nu",
                format!("must be < 0.5, got {}", self.poisson_ratio),
            ));
        }
        Ok(())
    }

    /// Shear modulus G = E / (2 (1 + ν)) (Pa).
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Contact modulus E* (Pa) of two bodies of this material: 1/E* = 2 (1 − ν²)/E.
    pub fn contact_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 - self.poisson_ratio * self.poisson_ratio))
    }
}

/// Principal radii of the wheel and rail surfaces at the contact point (m, signed: convex
/// positive, concave negative, `f64::INFINITY` for a straight generator). The rail is straight
/// in the rolling direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactRadii {
    /// Wheel rolling radius (m), > 0.
    pub wheel_rolling: f64,
    /// Wheel transverse (profile) radius (m), signed.
    pub wheel_transverse: f64,
    /// Rail transverse (head profile) radius (m), signed.
    pub rail_transverse: f64,
}

impl ContactRadii {
    /// Relative curvatures `(A, B)` (1/m) in the rolling and lateral directions; errors name the
    /// radius at fault when the contact is not elliptic (A ≤ 0 or B ≤ 0).
    pub fn relative_curvatures(&self) -> Result<(f64, f64)> {
        check_positive("r_wheel_rolling", self.wheel_rolling)?;
        let curvature = |name: &str, r: f64| -> Result<f64> {
            if r.is_nan() || r == 0.0 {
                return Err(LocoError::param(
                    name,
                    format!("must be non-zero (±inf for straight), got {r}"),
                ));
            }
            Ok(1.0 / r)
        };
        let a = 0.5 / self.wheel_rolling;
        let b = 0.5
            * (curvature("r_wheel_transverse", self.wheel_transverse)?
                + curvature("r_rail_transverse", self.rail_transverse)?);
        if b.is_finite() && b > 0.0 {
            Ok((a, b))
        } else {
            Err(LocoError::param(
                "r_wheel_transverse",
                format!(
                    "with r_rail_transverse = {} the lateral relative curvature is {b} 1/m; \
                     it must be > 0 (a concave wheel must be less curved than the rail head)",
                    self.rail_transverse
                ),
            ))
        }
    }
}

/// The Hertz contact for one load.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HertzContact {
    /// Semi-axis in the rolling direction a (m).
    pub semi_axis_long: f64,
    /// Semi-axis in the lateral direction b (m).
    pub semi_axis_lat: f64,
    /// Peak (centre) pressure p0 (Pa).
    pub peak_pressure: f64,
    /// Mutual approach of the two bodies δ (m).
    pub approach: f64,
}

/// Load-independent Hertz coefficients of one geometry: solve once, evaluate cheaply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzCoefficients {
    /// a³ = `long_cubed` · N (m³/N): the semi-axes grow as N^{1/3}, kept cubed so a contact
    /// takes one cube root (the hot path evaluates the coefficients at every contact).
    long_cubed: f64,
    /// b / a (–).
    lat_over_long: f64,
    /// Normal stiffness K_H of N = K_H δ^{3/2} (N·m^{-3/2}).
    stiffness: f64,
}

impl HertzCoefficients {
    /// Solves the Hertz problem for relative curvatures `a_curv` (rolling) and `b_curv` (lateral),
    /// both > 0 (1/m), and contact modulus `contact_modulus` E* (Pa).
    pub fn from_curvatures(a_curv: f64, b_curv: f64, contact_modulus: f64) -> Result<Self> {
        check_positive("curvature_long", a_curv)?;
        check_positive("curvature_lat", b_curv)?;
        check_positive("contact_modulus", contact_modulus)?;
        let (c_min, c_max) = (a_curv.min(b_curv), a_curv.max(b_curv));
        let g = axis_ratio(c_min / c_max);
        let (k, e) = elliptic_ke(1.0 - g * g);
        Ok(Self::from_shape(a_curv, b_curv, contact_modulus, g, k, e))
    }

    /// Coefficients from the ellipse shape: axis ratio `g` ≤ 1 and the elliptic integrals `k`,
    /// `e` of modulus √(1 − g²) (inputs valid; shared with [`super::hertz_table`]).
    pub(super) fn from_shape(
        a_curv: f64,
        b_curv: f64,
        contact_modulus: f64,
        g: f64,
        k: f64,
        e: f64,
    ) -> Self {
        let sum = a_curv + b_curv;
        // Semi-axes at N = 1 N, cubed: a³ = 3E/(2π g² (A+B) E*).
        let major_cubed = 3.0 * e / (2.0 * PI * g * g * sum * contact_modulus);
        // δ(N = 1) = 3K/(2π a E*), so K_H = δ^{-3/2} = (2π E*/(3K))^{3/2} · a^{3/2}.
        let c = 2.0 * PI * contact_modulus / (3.0 * k);
        let stiffness = c * c.sqrt() * major_cubed.sqrt();
        // The major axis lies along the direction of the smaller relative curvature.
        let (long_cubed, lat_over_long) = if a_curv <= b_curv {
            (major_cubed, g)
        } else {
            (g * g * g * major_cubed, 1.0 / g)
        };
        Self {
            long_cubed,
            lat_over_long,
            stiffness,
        }
    }

    /// As [`Self::from_curvatures`] from the radii and the material.
    pub fn new(radii: &ContactRadii, material: &ElasticMaterial) -> Result<Self> {
        material.validate()?;
        let (a, b) = radii.relative_curvatures()?;
        Self::from_curvatures(a, b, material.contact_modulus())
    }

    /// Normal stiffness K_H (N·m^{-3/2}) of the law N = K_H δ^{3/2}.
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// Ratio a/b of the semi-axes (rolling over lateral), independent of the load.
    pub fn axis_ratio(&self) -> f64 {
        1.0 / self.lat_over_long
    }

    /// Semi-axes (a along the rolling direction, b lateral; m) for normal force `normal_force`
    /// (N, > 0): one cube root, for the vehicle's time loop.
    #[inline]
    pub fn semi_axes(&self, normal_force: f64) -> (f64, f64) {
        let a = (self.long_cubed * normal_force).cbrt();
        (a, a * self.lat_over_long)
    }

    /// Normal force (N) for an elastic approach `approach` (m); zero for δ ≤ 0 (no contact).
    #[inline]
    pub fn load_from_approach(&self, approach: f64) -> f64 {
        if approach > 0.0 {
            self.stiffness * approach * approach.sqrt()
        } else {
            0.0
        }
    }

    /// The contact for normal force `normal_force` (N, ≥ 0; zero gives an empty contact).
    #[inline]
    pub fn contact(&self, normal_force: f64) -> HertzContact {
        if normal_force <= 0.0 || !normal_force.is_finite() {
            return HertzContact::default();
        }
        let (a, b) = self.semi_axes(normal_force);
        HertzContact {
            semi_axis_long: a,
            semi_axis_lat: b,
            peak_pressure: 3.0 * normal_force / (2.0 * PI * a * b),
            approach: (normal_force / self.stiffness).powf(2.0 / 3.0),
        }
    }
}

/// Hertz contact for `normal_force` (N, ≥ 0) between wheel and rail of radii `radii`.
pub fn hertz_contact(
    normal_force: f64,
    radii: &ContactRadii,
    material: &ElasticMaterial,
) -> Result<HertzContact> {
    check_non_negative("normal_force", normal_force)?;
    check_finite("normal_force", normal_force)?;
    Ok(HertzCoefficients::new(radii, material)?.contact(normal_force))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(x: f64, y: f64) -> f64 {
        (x - y).abs() / y.abs()
    }

    #[test]
    fn major_axis_follows_smaller_curvature() {
        let coef = HertzCoefficients::from_curvatures(2.0, 1.0, 1e11).unwrap();
        assert!(coef.axis_ratio() < 1.0);
        let swapped = HertzCoefficients::from_curvatures(1.0, 2.0, 1e11).unwrap();
        assert!(rel(coef.axis_ratio(), 1.0 / swapped.axis_ratio()) < 1e-9);
        assert!(rel(coef.stiffness(), swapped.stiffness()) < 1e-12);
    }

    #[test]
    fn load_approach_round_trip_and_scaling() {
        let radii = ContactRadii {
            wheel_rolling: 0.625,
            wheel_transverse: -0.5,
            rail_transverse: 0.3,
        };
        let coef = HertzCoefficients::new(&radii, &ElasticMaterial::default()).unwrap();
        for n in [1e3, 5e4, 1.1e5] {
            let c = coef.contact(n);
            assert!(rel(coef.load_from_approach(c.approach), n) < 1e-12);
            // a ∝ N^{1/3}
            let c8 = coef.contact(8.0 * n);
            assert!(rel(c8.semi_axis_long, 2.0 * c.semi_axis_long) < 1e-12);
        }
        assert_eq!(coef.load_from_approach(-1e-6), 0.0);
    }

    #[test]
    fn bad_geometry_names_the_radius() {
        let mat = ElasticMaterial::default();
        let concave_too_much = ContactRadii {
            wheel_rolling: 0.625,
            wheel_transverse: -0.2,
            rail_transverse: 0.3,
        };
        let err = hertz_contact(1e5, &concave_too_much, &mat).unwrap_err();
        assert!(err.to_string().contains("r_wheel_transverse"));
        let nan = ContactRadii {
            wheel_rolling: f64::NAN,
            ..concave_too_much
        };
        let err = hertz_contact(1e5, &nan, &mat).unwrap_err();
        assert!(err.to_string().contains("r_wheel_rolling"));
        let err = hertz_contact(-1.0, &nan, &mat).unwrap_err();
        assert!(err.to_string().contains("normal_force"));
    }
}
