//! Kalker's linear theory of rolling contact: the creepage coefficients C11, C22, C23, C33 and the
//! creep forces at vanishing creepage.
//!
//! Source of the table: J. J. Kalker, *Three-Dimensional Elastic Bodies in Rolling Contact*,
//! Kluwer 1990, Table E.3 (first published in Kalker's thesis, *On the rolling contact of two
//! elastic bodies in the presence of dry friction*, Delft 1967; reproduced e.g. in Garg &
//! Dukkipati, *Dynamics of Railway Vehicle Systems*, 1984, and Iwnicki (ed.), *Handbook of Railway
//! Vehicle Dynamics*, 2006). The C11, C22 and C23 columns were checked entry by entry against the
//! copy of Table E.3 in the open-source CONTACT library (eve70a/CONTACT, `m_hertz.f90`).
//!
//! Sign conventions (Kalker): with creepages ξ (longitudinal), η (lateral), φ (spin, 1/m), shear
//! modulus G, semi-axes a (rolling direction) and b, c = √(ab), the forces that the rail exerts on
//! the wheel in the contact plane are
//!
//! ```text
//! Fx = −G c² C11 ξ
//! Fy = −G c² (C22 η + c C23 φ)
//! Mz = −G c³ (−C23 η + c C33 φ)
//! ```
//!
//! Interpolation: linear in the axis ratio g within each branch of the table (g = a/b ≤ 1 and
//! g = b/a ≤ 1, rows 0.1 … 1.0); in ν, quadratic Lagrange interpolation of 1/C through ν = 0,
//! 0.25, 0.5 — chosen because 1/C is linear in ν in Kalker's asymptotes (e.g. 1/C11 = 4(1 − ν)/π²
//! for a/b → 0), so the interpolant is nearly exact. Below g = 0.1 the table is continued by
//! Kalker's asymptotic expressions for C11, C22, C23 (Kalker 1990, appendix E), scaled to meet the
//! table at g = 0.1; C33, which only enters the linear spin moment, is held at its g = 0.1 value.

use crate::error::{check_finite, check_non_negative, check_positive, LocoError, Result};
use std::f64::consts::PI;

/// Creepage coefficients of Kalker's linear theory (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KalkerCoefficients {
    /// Longitudinal force per longitudinal creepage, C11.
    pub c11: f64,
    /// Lateral force per lateral creepage, C22.
    pub c22: f64,
    /// Lateral force per spin and spin moment per lateral creepage, C23.
    pub c23: f64,
    /// Spin moment per spin, C33.
    pub c33: f64,
}

impl KalkerCoefficients {
    /// The inverse flexibilities 1/L₁, 1/L₂, 1/L₃ (Pa/m) of the simplified theory on an ellipse
    /// of semi-axes `a` (rolling direction) and `b` (m), for the shear modulus `g` (Pa, already
    /// multiplied by any coefficient factor): L₁ = 8a/(3C₁₁G), L₂ = 8a/(3C₂₂G) and
    /// L₃ = πa√(a/b)/(4C₂₃G), chosen so that the simplified theory reproduces Kalker's linear
    /// creep coefficients (Kalker 1982). FASTSIM and FaStrip's slip direction both use them.
    pub fn inverse_flexibilities(&self, g: f64, a: f64, b: f64) -> [f64; 3] {
        [
            3.0 * self.c11 * g / (8.0 * a),
            3.0 * self.c22 * g / (8.0 * a),
            4.0 * self.c23 * g / (PI * a * (a / b).sqrt()),
        ]
    }
}

/// Creepages at a contact: longitudinal ξ (–), lateral η (–), spin φ (1/m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creepages {
    /// Longitudinal creepage ξ (–).
    pub longitudinal: f64,
    /// Lateral creepage η (–).
    pub lateral: f64,
    /// Spin creepage φ (1/m).
    pub spin: f64,
}

/// Tangential contact forces on the wheel in the contact plane.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CreepForces {
    /// Longitudinal force Fx (N), along the rolling direction.
    pub fx: f64,
    /// Lateral force Fy (N), in the contact plane.
    pub fy: f64,
    /// Spin moment Mz (N·m), about the contact normal.
    pub mz: f64,
}

/// Poisson's ratios of the table columns.
const NU_COLUMNS: [f64; 3] = [0.0, 0.25, 0.5];

/// One table row: `[C11; C22; C23; C33]`, each for ν = 0, 0.25, 0.5.
type Row = [[f64; 3]; 4];

/// Kalker 1990, Table E.3, branch a/b ≤ 1: rows g = a/b = 0.1, 0.2, …, 1.0.
#[allow(clippy::approx_constant)] // 3.14 is Kalker's C22(0.5, ν = 0.5), not π
#[rustfmt::skip]
const TABLE_A_LE_B: [Row; 10] = [
    [[2.51, 3.31, 4.85], [2.51, 2.52, 2.53], [0.334, 0.473, 0.731], [6.42, 8.28, 11.7]],
    [[2.59, 3.37, 4.81], [2.59, 2.63, 2.66], [0.483, 0.603, 0.809], [3.46, 4.27, 5.66]],
    [[2.68, 3.44, 4.80], [2.68, 2.75, 2.81], [0.607, 0.715, 0.889], [2.49, 2.96, 3.72]],
    [[2.78, 3.53, 4.82], [2.78, 2.88, 2.98], [0.720, 0.823, 0.977], [2.02, 2.32, 2.77]],
    [[2.88, 3.62, 4.83], [2.88, 3.01, 3.14], [0.827, 0.929, 1.07], [1.74, 1.93, 2.22]],
    [[2.98, 3.72, 4.91], [2.98, 3.14, 3.31], [0.930, 1.03, 1.18], [1.56, 1.68, 1.86]],
    [[3.09, 3.81, 4.97], [3.09, 3.28, 3.48], [1.03, 1.14, 1.29], [1.43, 1.50, 1.60]],
    [[3.19, 3.91, 5.05], [3.19, 3.41, 3.65], [1.13, 1.25, 1.40], [1.34, 1.37, 1.42]],
    [[3.29, 4.01, 5.12], [3.29, 3.54, 3.82], [1.23, 1.36, 1.51], [1.27, 1.27, 1.27]],
    [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63], [1.21, 1.19, 1.16]],
];

/// Kalker 1990, Table E.3, branch b/a ≤ 1: rows g = b/a = 0.1, 0.2, …, 1.0.
#[rustfmt::skip]
const TABLE_B_LE_A: [Row; 10] = [
    [[10.7, 11.7, 12.9], [10.7, 12.8, 16.0], [12.2, 14.6, 18.0], [0.795, 0.526, 0.379]],
    [[6.96, 7.78, 8.82], [6.96, 8.14, 9.79], [5.72, 6.63, 7.89], [0.828, 0.601, 0.444]],
    [[5.57, 6.34, 7.34], [5.57, 6.40, 7.51], [3.79, 4.32, 5.01], [0.868, 0.674, 0.507]],
    [[4.84, 5.57, 6.57], [4.84, 5.48, 6.31], [2.88, 3.24, 3.70], [0.912, 0.747, 0.586]],
    [[4.37, 5.10, 6.11], [4.37, 4.90, 5.56], [2.35, 2.62, 2.96], [0.958, 0.819, 0.669]],
    [[4.06, 4.78, 5.80], [4.06, 4.50, 5.04], [2.01, 2.23, 2.50], [1.01, 0.892, 0.756]],
    [[3.82, 4.54, 5.58], [3.82, 4.21, 4.67], [1.76, 1.95, 2.18], [1.05, 0.965, 0.852]],
    [[3.65, 4.36, 5.42], [3.65, 3.99, 4.39], [1.58, 1.75, 1.94], [1.10, 1.04, 0.95]],
    [[3.51, 4.22, 5.30], [3.51, 3.81, 4.16], [1.44, 1.59, 1.77], [1.16, 1.11, 1.06]],
    [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63], [1.21, 1.19, 1.16]],
];

/// Kalker's table with the Poisson interpolation done once: two branches of ten rows of
/// `[C11, C22, C23, C33]`. `Copy`, no allocation; a lookup costs a few flops (plus a logarithm
/// for very elongated ellipses), so the vehicle model can call it for every contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KalkerTable {
    poisson_ratio: f64,
    a_le_b: [[f64; 4]; 10],
    b_le_a: [[f64; 4]; 10],
}

impl KalkerTable {
    /// The table for Poisson's ratio `poisson_ratio` ∈ [0, 0.5].
    pub fn new(poisson_ratio: f64) -> Result<Self> {
        check_non_negative("nu", poisson_ratio)?;
        if poisson_ratio > 0.5 {
            return Err(LocoError::param(
                "nu",
                format!("must be <= 0.5, got {poisson_ratio}"),
            ));
        }
        let fold = |table: &[Row; 10]| {
            let mut out = [[0.0; 4]; 10];
            for (row_out, row) in out.iter_mut().zip(table) {
                for (c_out, column) in row_out.iter_mut().zip(row) {
                    *c_out = interpolate_in_nu(column, poisson_ratio);
                }
            }
            out
        };
        Ok(Self {
            poisson_ratio,
            a_le_b: fold(&TABLE_A_LE_B),
            b_le_a: fold(&TABLE_B_LE_A),
        })
    }

    /// Poisson's ratio of this table.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// The coefficients for the semi-axis ratio `a_over_b` (> 0, finite; not checked here —
    /// use [`kalker_coefficients`] for checked input).
    #[inline]
    pub fn coefficients(&self, a_over_b: f64) -> KalkerCoefficients {
        let (rows, g, a_shorter) = if a_over_b <= 1.0 {
            (&self.a_le_b, a_over_b, true)
        } else {
            (&self.b_le_a, 1.0 / a_over_b, false)
        };
        if g >= 0.1 {
            // Rows at g = 0.1 (i + 1); interpolate linearly between the bracketing rows.
            let pos = (g * 10.0 - 1.0).clamp(0.0, 9.0);
            let i = (pos as usize).min(8);
            let t = pos - i as f64;
            let lerp = |k: usize| rows[i][k] + t * (rows[i + 1][k] - rows[i][k]);
            return KalkerCoefficients {
                c11: lerp(0),
                c22: lerp(1),
                c23: lerp(2),
                c33: lerp(3),
            };
        }
        self.elongated(rows, g, a_shorter)
    }

    /// The coefficients below g = 0.1 (an elongated ellipse): Kalker's asymptotic shape,
    /// anchored to the table at g = 0.1. Out of line: rare, and its logarithms and powers would
    /// weigh on the inlined table look-up.
    #[inline(never)]
    fn elongated(&self, rows: &[[f64; 4]; 10], g: f64, a_shorter: bool) -> KalkerCoefficients {
        let nu = self.poisson_ratio;
        let at = asymptotes(g, nu, a_shorter);
        let edge = asymptotes(0.1, nu, a_shorter);
        KalkerCoefficients {
            c11: rows[0][0] * at[0] / edge[0],
            c22: rows[0][1] * at[1] / edge[1],
            c23: rows[0][2] * at[2] / edge[2],
            c33: rows[0][3],
        }
    }
}

/// Kalker's asymptotes `[C11, C22, C23]` for g → 0 (Kalker 1990, appendix E).
fn asymptotes(g: f64, nu: f64, a_shorter: bool) -> [f64; 3] {
    if a_shorter {
        // g = a/b → 0: the ellipse is narrow in the rolling direction.
        [
            PI * PI / (4.0 * (1.0 - nu)),
            PI * PI / 4.0,
            PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0)),
        ]
    } else {
        // g = b/a → 0: the ellipse is long in the rolling direction.
        let lambda = (16.0 / (g * g)).ln();
        let k = 3.0 - 4.0_f64.ln();
        let d = (1.0 - nu) * lambda + 2.0 * nu;
        [
            2.0 * PI / ((lambda - 2.0 * nu) * g) * (1.0 + k / (lambda - 2.0 * nu)),
            2.0 * PI / g * (1.0 + (1.0 - nu) * k / d) / d,
            2.0 * PI / (3.0 * g.powf(1.5) * ((1.0 - nu) * lambda - 2.0 + 4.0 * nu)),
        ]
    }
}

/// Quadratic Lagrange interpolation of 1/C through the columns ν = 0, 0.25, 0.5.
fn interpolate_in_nu(column: &[f64; 3], nu: f64) -> f64 {
    let [n0, n1, n2] = NU_COLUMNS;
    let l0 = (nu - n1) * (nu - n2) / ((n0 - n1) * (n0 - n2));
    let l1 = (nu - n0) * (nu - n2) / ((n1 - n0) * (n1 - n2));
    let l2 = (nu - n0) * (nu - n1) / ((n2 - n0) * (n2 - n1));
    1.0 / (l0 / column[0] + l1 / column[1] + l2 / column[2])
}

/// Kalker's coefficients for the semi-axis ratio `a_over_b` (a along the rolling direction) and
/// Poisson's ratio `nu`, with the inputs checked.
pub fn kalker_coefficients(a_over_b: f64, nu: f64) -> Result<KalkerCoefficients> {
    check_positive("a_over_b", a_over_b)?;
    Ok(KalkerTable::new(nu)?.coefficients(a_over_b))
}

/// Creep forces of Kalker's linear theory for semi-axes `a` (rolling direction) and `b` (m), shear
/// modulus `shear_modulus` G (Pa) and coefficients `coef`.
#[inline]
pub fn linear_creep_forces(
    a: f64,
    b: f64,
    shear_modulus: f64,
    coef: &KalkerCoefficients,
    creepages: &Creepages,
) -> CreepForces {
    let c = (a * b).sqrt();
    let gc2 = shear_modulus * c * c;
    let Creepages {
        longitudinal: xi,
        lateral: eta,
        spin: phi,
    } = *creepages;
    CreepForces {
        fx: -gc2 * coef.c11 * xi,
        fy: -gc2 * (coef.c22 * eta + c * coef.c23 * phi),
        mz: -gc2 * c * (-coef.c23 * eta + c * coef.c33 * phi),
    }
}

/// As [`linear_creep_forces`] with every input checked (the Python entry point).
pub fn linear_creep_forces_checked(
    a: f64,
    b: f64,
    shear_modulus: f64,
    nu: f64,
    creepages: &Creepages,
) -> Result<CreepForces> {
    check_positive("a", a)?;
    check_positive("b", b)?;
    check_positive("shear_modulus", shear_modulus)?;
    check_finite("creepage_long", creepages.longitudinal)?;
    check_finite("creepage_lat", creepages.lateral)?;
    check_finite("spin", creepages.spin)?;
    let coef = kalker_coefficients(a / b, nu)?;
    Ok(linear_creep_forces(a, b, shear_modulus, &coef, creepages))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_table_nodes() {
        for (i, row) in TABLE_B_LE_A.iter().enumerate() {
            let g = 0.1 * (i + 1) as f64;
            for (j, &nu) in NU_COLUMNS.iter().enumerate() {
                let c = kalker_coefficients(1.0 / g, nu).unwrap();
                assert!((c.c11 - row[0][j]).abs() < 1e-9 * row[0][j]);
                assert!((c.c23 - row[2][j]).abs() < 1e-9 * row[2][j]);
            }
        }
        let c = kalker_coefficients(0.3, 0.25).unwrap();
        assert!((c.c22 - 2.75).abs() < 1e-12 && (c.c33 - 2.96).abs() < 1e-12);
    }

    #[test]
    fn branches_meet_at_circle_and_are_continuous() {
        let t = KalkerTable::new(0.28).unwrap();
        let below = t.coefficients(1.0 - 1e-9);
        let above = t.coefficients(1.0 + 1e-9);
        assert!((below.c11 - above.c11).abs() < 1e-6);
        assert!((below.c23 - above.c23).abs() < 1e-6);
        for aob in [0.1, 10.0] {
            let inside = t.coefficients(aob * (1.0 + 1e-9));
            let outside = t.coefficients(aob * (1.0 - 1e-9));
            assert!((inside.c11 - outside.c11).abs() < 1e-4 * inside.c11);
            assert!((inside.c22 - outside.c22).abs() < 1e-4 * inside.c22);
        }
    }

    #[test]
    fn asymptotes_agree_with_table_edge() {
        // Kalker's g → 0 expressions should be close to the tabulated g = 0.1 row already.
        for (j, &nu) in NU_COLUMNS.iter().enumerate() {
            let narrow = asymptotes(0.1, nu, true);
            assert!((narrow[0] / TABLE_A_LE_B[0][0][j] - 1.0).abs() < 0.02);
            assert!((narrow[2] / TABLE_A_LE_B[0][2][j] - 1.0).abs() < 0.07);
            let long = asymptotes(0.1, nu, false);
            assert!((long[2] / TABLE_B_LE_A[0][2][j] - 1.0).abs() < 0.05);
            assert!((long[1] / TABLE_B_LE_A[0][1][j] - 1.0).abs() < 0.05);
        }
    }

    #[test]
    fn nu_interpolation_recovers_the_exact_small_g_law() {
        // For a/b → 0, C11 = π²/(4(1 − ν)): 1/C11 is linear in ν, which the 1/C Lagrange
        // interpolation reproduces exactly.
        let col = [0.0, 0.25, 0.5].map(|nu: f64| PI * PI / (4.0 * (1.0 - nu)));
        let c = interpolate_in_nu(&col, 0.28);
        assert!((c - PI * PI / (4.0 * 0.72)).abs() < 1e-12);
    }

    #[test]
    fn linear_forces_signs() {
        let coef = kalker_coefficients(2.0, 0.28).unwrap();
        let pos = |xi, eta, phi| {
            linear_creep_forces(
                8e-3,
                4e-3,
                8.2e10,
                &coef,
                &Creepages {
                    longitudinal: xi,
                    lateral: eta,
                    spin: phi,
                },
            )
        };
        let f = pos(1e-4, 0.0, 0.0);
        assert!(f.fx < 0.0 && f.fy == 0.0 && f.mz == 0.0);
        let f = pos(0.0, 1e-4, 0.0);
        assert!(f.fy < 0.0 && f.mz > 0.0);
        let f = pos(0.0, 0.0, 0.1);
        assert!(f.fy < 0.0 && f.mz < 0.0);
        assert!(kalker_coefficients(f64::NAN, 0.28).is_err());
        assert!(kalker_coefficients(1.0, 0.6).is_err());
    }
}
