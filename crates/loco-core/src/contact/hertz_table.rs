//! Tabulated Hertz shape functions, for evaluating the Hertz contact in a time loop where the
//! curvatures change at every step (the contact point moves across the profiles).
//!
//! The ellipse shape depends on the curvature ratio ρ = A_min/A_max only: the axis ratio g(ρ)
//! and the elliptic integrals K, E of modulus √(1 − g²). They are tabulated once on uniform nodes
//! in ln ρ ∈ [ln 10⁻⁶, 0] (ln g is nearly linear there, g ≈ ρ^{2/3} for small ρ, and K, E are
//! smooth) and interpolated linearly; [`super::hertz::HertzCoefficients::from_shape`] then gives
//! the semi-axis and stiffness coefficients. Outside the table (ρ < 10⁻⁶, a contact 10⁴ times
//! longer than wide) the exact solution is used. The interpolation error is measured in the tests.

use super::elliptic::{axis_ratio, elliptic_ke};
use super::hertz::HertzCoefficients;
use crate::error::{check_positive, Result};

/// Number of nodes in ln ρ.
const NODES: usize = 1025;
/// Smallest tabulated curvature ratio ρ, as ln ρ.
const LN_RHO_MIN: f64 = -13.815_510_557_964_274; // ln 1e-6

/// Shape functions of the Hertz contact on nodes in ln ρ: `[ln g, K, E]`.
#[derive(Debug, Clone)]
pub struct HertzShapeTable {
    nodes: Box<[[f64; 3]; NODES]>,
}

impl Default for HertzShapeTable {
    fn default() -> Self {
        Self::new()
    }
}

impl HertzShapeTable {
    /// Builds the table (about a thousand exact solutions: build once, share freely).
    pub fn new() -> Self {
        let mut nodes = Box::new([[0.0; 3]; NODES]);
        for (i, node) in nodes.iter_mut().enumerate() {
            let ln_rho = LN_RHO_MIN * (1.0 - i as f64 / (NODES - 1) as f64);
            let g = axis_ratio(ln_rho.exp());
            let (k, e) = elliptic_ke(1.0 - g * g);
            *node = [g.ln(), k, e];
        }
        Self { nodes }
    }

    /// Hertz coefficients for relative curvatures `a_curv` (rolling) and `b_curv` (lateral) (1/m,
    /// > 0) and contact modulus E* (Pa); no allocation, no iteration inside the table's range.
    pub fn coefficients(
        &self,
        a_curv: f64,
        b_curv: f64,
        contact_modulus: f64,
    ) -> Result<HertzCoefficients> {
        // The three inputs tested at once in float operations (x·0 is 0 for a finite x, NaN
        // for an infinite one): the three checks compiled to some fifty integer instructions
        // per contact point, so they run only to name the input at fault.
        let finite = a_curv * 0.0 + b_curv * 0.0 + contact_modulus * 0.0 == 0.0;
        if !(a_curv > 0.0 && b_curv > 0.0 && contact_modulus > 0.0 && finite) {
            check_positive("curvature_long", a_curv)?;
            check_positive("curvature_lat", b_curv)?;
            check_positive("contact_modulus", contact_modulus)?;
        }
        // Both are positive and finite here: a comparison orders them as `min`/`max` did,
        // without their NaN handling.
        let (lo, hi) = if a_curv <= b_curv {
            (a_curv, b_curv)
        } else {
            (b_curv, a_curv)
        };
        let ln_rho = (lo / hi).ln();
        if ln_rho < LN_RHO_MIN {
            return HertzCoefficients::from_curvatures(a_curv, b_curv, contact_modulus);
        }
        let pos = (1.0 - ln_rho / LN_RHO_MIN) * (NODES - 1) as f64;
        let i = (pos as usize).min(NODES - 2);
        let t = pos - i as f64;
        let (below, above) = (&self.nodes[i], &self.nodes[i + 1]);
        let lerp = |j: usize| below[j] + t * (above[j] - below[j]);
        Ok(HertzCoefficients::from_shape(
            a_curv,
            b_curv,
            contact_modulus,
            lerp(0).exp(),
            lerp(1),
            lerp(2),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_matches_exact_solution() {
        let table = HertzShapeTable::new();
        let e_star = 1.15e11;
        let mut worst = 0.0_f64;
        for i in 0..=400 {
            // Curvature ratios from 1e-6 to 1, both orientations, off the nodes.
            let rho = 10f64.powf(-6.0 * (i as f64 + 0.37) / 400.5);
            for (a, b) in [(rho, 1.0), (1.0, rho)] {
                let exact = HertzCoefficients::from_curvatures(a, b, e_star).unwrap();
                let fast = table.coefficients(a, b, e_star).unwrap();
                let (ce, cf) = (exact.contact(1e5), fast.contact(1e5));
                for (x, y) in [
                    (cf.semi_axis_long, ce.semi_axis_long),
                    (cf.semi_axis_lat, ce.semi_axis_lat),
                    (fast.stiffness(), exact.stiffness()),
                ] {
                    worst = worst.max((x / y - 1.0).abs());
                }
            }
        }
        eprintln!("Hertz table: worst relative error {worst:.2e}");
        assert!(worst < 1e-5, "worst relative error {worst}");
        // Beyond the table: exact fallback.
        let far = table.coefficients(1e-8, 1.0, e_star).unwrap();
        let exact = HertzCoefficients::from_curvatures(1e-8, 1.0, e_star).unwrap();
        assert_eq!(far, exact);
    }

    #[test]
    fn the_input_at_fault_is_named_as_by_three_checks() {
        let table = HertzShapeTable::new();
        let good = [0.8, 2.5, 1.15e11];
        let names = ["curvature_long", "curvature_lat", "contact_modulus"];
        let bad = [0.0, -0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        for (k, name) in names.iter().enumerate() {
            for v in bad {
                let mut x = good;
                x[k] = v;
                // A second bad input after the first: the first is still the one named.
                if k < 2 {
                    x[2] = f64::NAN;
                }
                let err = table.coefficients(x[0], x[1], x[2]).unwrap_err();
                let first = check_positive(name, v).unwrap_err();
                assert_eq!(err, first, "{name} = {v}");
            }
        }
        for (a, b) in [
            (0.8, 2.5),
            (2.5, 0.8),
            (1.0, 1.0),
            (f64::MAX, 1.0),
            (5e-324, 1.0),
        ] {
            let c = table.coefficients(a, b, 1.15e11).unwrap();
            let swapped = table.coefficients(b, a, 1.15e11).unwrap();
            assert_eq!(
                c.stiffness().to_bits(),
                swapped.stiffness().to_bits(),
                "{a} {b}"
            );
        }
    }
}
