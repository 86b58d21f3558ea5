//! FASTSIM: Kalker's simplified theory of rolling contact (J. J. Kalker, "A fast algorithm for the
//! simplified theory of rolling contact", Vehicle System Dynamics 11, 1982, pp. 1–13).
//!
//! The simplified theory replaces the elastic half-space by independent springs: the surface
//! displacement is `u = L·p` with flexibilities (Kalker 1982, chosen so that the theory reproduces
//! the linear theory at vanishing creepage)
//!
//! ```text
//! L1 = 8a / (3 C11 G),   L2 = 8a / (3 C22 G),   L3 = π a √(a/b) / (4 C23 G)
//! ```
//!
//! divided here by the Kalker coefficient factor k (k < 1 models reduced adhesion; the study
//! uses k = 1). In steady rolling (material flows from the leading edge x = +a to the trailing edge
//! x = −a) and with the rigid slip `(ξ − φ y, η + φ x)`, the traction in the adhesion area obeys
//! `∂p/∂x = (ξ/L1 − φ y/L3, η/L2 + φ x/L3)`, starting from zero at the leading edge. FASTSIM
//! integrates this along strips y = const of the ellipse and, wherever |p| exceeds the traction
//! bound μ p_n(x, y), projects p back onto the bound (slip). The normal pressure p_n is either
//! Hertz's elliptic distribution or the parabolic one that Kalker recommends for FASTSIM (it gives
//! a better force–creepage curve with the simplified theory's uniform flexibility):
//!
//! ```text
//! elliptic:  p_n = 3N/(2πab) · √(1 − x²/a² − y²/b²)
//! parabolic: p_n = 2N/(πab)  · (1 − x²/a² − y²/b²)
//! ```
//!
//! Discretisation: `ny` strips of equal width; each strip is cut into `nx` elements of equal
//! length; tractions live at element centres, and each step integrates the slip with the midpoint
//! rule, which is exact for the linear variation in x, so at vanishing creepage the only error left
//! is the strip quadrature. The discrete pressure is scaled so that it sums to N exactly, so that
//! full slip gives |F| = μN on any grid. The element geometry in units of (a, b) is precomputed in
//! [`Fastsim::new`]; [`Fastsim::creep_forces`] allocates nothing.

use super::fastsim_lanes::{integrate_strips, Element, StripInputs, PAIRS};
use super::kalker::{CreepForces, Creepages, KalkerTable};
use crate::error::{check_finite, check_non_negative, check_positive, LocoError, Result};

/// Strips integrated together in the hot loop (`fastsim_lanes`).
const LANES: usize = 2 * PAIRS;

/// Geometry of [`LANES`] strips in units of (a, b).
#[derive(Debug, Clone, Copy, Default)]
struct StripLanes {
    /// Strip centre y_j / b.
    eta: [f64; LANES],
    /// Strip half-length a_j / a.
    half_length: [f64; LANES],
    /// Pressure shape factor of the strip.
    shape: [f64; LANES],
    /// The lane of each of the group's strips, in the strips' order (the order of the sums).
    lane_of_strip: [usize; LANES],
}

/// Normal pressure distribution that bounds the tangential traction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TractionBound {
    /// Hertz's elliptic pressure.
    Elliptic,
    /// Parabolic pressure of the same total force (Kalker's choice for FASTSIM).
    #[default]
    Parabolic,
}

/// Parameters of FASTSIM.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastsimParams {
    /// Elements per strip along the rolling direction (≥ 1).
    pub nx: usize,
    /// Strips across the ellipse (≥ 1).
    pub ny: usize,
    /// Kalker coefficient factor k (> 0): the flexibilities are divided by k (1: Kalker's values).
    pub kalker_factor: f64,
    /// Traction bound.
    pub bound: TractionBound,
    /// Poisson's ratio ν (–), for the creepage coefficients.
    pub poisson_ratio: f64,
    /// Combined shear modulus G (Pa).
    pub shear_modulus: f64,
}

impl Default for FastsimParams {
    /// 10 × 10 grid, k = 1, parabolic bound, steel (ν = 0.28, G = 8.2e10 Pa).
    fn default() -> Self {
        Self {
            nx: 10,
            ny: 10,
            kalker_factor: 1.0,
            bound: TractionBound::Parabolic,
            poisson_ratio: 0.28,
            shear_modulus: 8.2e10,
        }
    }
}

/// A ready-to-run FASTSIM solver: parameters, Kalker table and the normalised grid.
#[derive(Debug, Clone)]
pub struct Fastsim {
    params: FastsimParams,
    table: KalkerTable,
    /// Strips in groups of [`LANES`]: `y_j/b`, `a_j/a` and the strip's p_n shape factor; the
    /// last group is padded with empty strips (a_j = 0), which contribute nothing.
    strips: Vec<StripLanes>,
    /// Per element k of a strip: x_k/a_j and the p_n shape factor of the element.
    elements: Vec<Element>,
    /// Pressure at shape factor 1 per N/(ab) (–): 1 / Σ shape·dA/(ab), so that the discrete
    /// pressure sums to N exactly.
    pressure_scale: f64,
}

impl Fastsim {
    /// Checks the parameters and precomputes the grid.
    pub fn new(params: FastsimParams) -> Result<Self> {
        let table = checked_grid_and_material(
            (params.nx, params.ny),
            params.kalker_factor,
            params.shear_modulus,
            params.poisson_ratio,
        )?;
        let elliptic = params.bound == TractionBound::Elliptic;
        // 1 − x²/a² − y²/b² = s_j² (1 − u_k²) with s_j = a_j/a, u_k = x/a_j: the pressure shape
        // separates into a strip factor and an element factor.
        let (nx, ny) = (params.nx, params.ny);
        let strip = |j: usize| {
            let eta = -1.0 + (2 * j + 1) as f64 / ny as f64;
            let s = (1.0 - eta * eta).sqrt();
            (eta, s, if elliptic { s } else { s * s })
        };
        // A group's strips go to the lanes outermost first, so that strips of similar width share
        // a register: the outer ones saturate first, and a register whose lanes are all inside
        // the bound skips the projection's root and division (`fastsim_lanes`). The sums still
        // run in the strips' order.
        let strips: Vec<StripLanes> = (0..ny.div_ceil(LANES))
            .map(|group| {
                let mut lanes = StripLanes::default();
                let mut order: [usize; LANES] = std::array::from_fn(|i| i);
                let eta_of = |i: usize| {
                    let j = group * LANES + i;
                    if j < ny {
                        strip(j).0.abs()
                    } else {
                        -1.0
                    }
                };
                order.sort_by(|&p, &q| eta_of(q).total_cmp(&eta_of(p)));
                for (lane, &i) in order.iter().enumerate() {
                    let j = group * LANES + i;
                    lanes.lane_of_strip[i] = lane;
                    if j < ny {
                        (lanes.eta[lane], lanes.half_length[lane], lanes.shape[lane]) = strip(j);
                    }
                }
                lanes
            })
            .collect();
        let elements: Vec<Element> = (0..nx)
            .map(|k| {
                let u = 1.0 - (2 * k + 1) as f64 / nx as f64;
                let w = 1.0 - u * u;
                Element::new(u, if elliptic { w.sqrt() } else { w })
            })
            .collect();
        // Discrete ∫∫ shape dA in units of ab: Σ_j Σ_k shape · (2 s_j/nx)(2/ny).
        let element_sum: f64 = elements.iter().map(|e| e.shape).sum();
        let discrete: f64 =
            (0..ny).map(|j| strip(j).1 * strip(j).2).sum::<f64>() * element_sum * 4.0
                / (nx * ny) as f64;
        // (The exact integral is 2π/3 elliptic, π/2 parabolic; the discrete one converges to it.)
        let pressure_scale = 1.0 / discrete;
        Ok(Self {
            params,
            table,
            strips,
            elements,
            pressure_scale,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &FastsimParams {
        &self.params
    }

    /// Kalker's coefficients for this solver's Poisson's ratio.
    pub fn kalker_table(&self) -> &KalkerTable {
        &self.table
    }

    /// Creep forces for semi-axes `a` (rolling direction) and `b` (m), normal force
    /// `normal_force` (N), friction coefficient `mu` and `creepages`. Inputs are not checked
    /// (hot path; [`fastsim`] and [`check_contact_inputs`](super::fastsim::check_contact_inputs)
    /// check them); a non-positive a, b or N gives zero forces.
    pub fn creep_forces(
        &self,
        a: f64,
        b: f64,
        normal_force: f64,
        mu: f64,
        creepages: &Creepages,
    ) -> CreepForces {
        if !(a > 0.0 && b > 0.0 && normal_force > 0.0) {
            return CreepForces::default();
        }
        let coef = self.table.coefficients(a / b);
        let g = self.params.shear_modulus * self.params.kalker_factor;
        // Inverse flexibilities 1/L (Pa/m).
        let [inv_l1, inv_l2, inv_l3] = coef.inverse_flexibilities(g, a, b);
        let Creepages {
            longitudinal: xi,
            lateral: eta,
            spin: phi,
        } = *creepages;
        let bound_peak = mu * normal_force * self.pressure_scale / (a * b);
        let nx = self.params.nx as f64;
        let dy = 2.0 * b / self.params.ny as f64;
        let (mut fx, mut fy, mut mz) = (0.0, 0.0, 0.0);
        let eta_l2 = eta * inv_l2;
        for group in &self.strips {
            let y: [f64; LANES] = std::array::from_fn(|l| group.eta[l] * b);
            let a_j: [f64; LANES] = std::array::from_fn(|l| group.half_length[l] * a);
            let inputs = StripInputs {
                a_j,
                // The slope of p_x is constant along a strip; p_y's grows linearly with x.
                slope_x: std::array::from_fn(|l| xi * inv_l1 - phi * y[l] * inv_l3),
                bound: std::array::from_fn(|l| bound_peak * group.shape[l]),
            };
            let sums = integrate_strips(&inputs, &self.elements, eta_l2, phi, inv_l3);
            // Each strip's terms lane by lane (packed divisions and products), then summed in
            // the strips' order: the same operations per strip as one strip at a time.
            let area: [f64; LANES] = std::array::from_fn(|l| 2.0 * a_j[l] / nx * dy);
            let tx: [f64; LANES] = std::array::from_fn(|l| sums.sx[l] * area[l]);
            let ty: [f64; LANES] = std::array::from_fn(|l| sums.sy[l] * area[l]);
            let tm: [f64; LANES] =
                std::array::from_fn(|l| (sums.sxpy[l] - y[l] * sums.sx[l]) * area[l]);
            for &l in &group.lane_of_strip {
                fx += tx[l];
                fy += ty[l];
                mz += tm[l];
            }
        }
        CreepForces { fx, fy, mz }
    }
}

/// Checks a creep solver's grid `(nx, ny)` (1..=10000 each) and material (Kalker factor and
/// shear modulus G in Pa > 0) and returns the Kalker coefficients for Poisson's ratio ν.
pub(super) fn checked_grid_and_material(
    (nx, ny): (usize, usize),
    kalker_factor: f64,
    shear_modulus: f64,
    poisson_ratio: f64,
) -> Result<KalkerTable> {
    for (name, n) in [("grid.nx", nx), ("grid.ny", ny)] {
        if !(1..=10_000).contains(&n) {
            return Err(LocoError::param(
                name,
                format!("must be in 1..=10000, got {n}"),
            ));
        }
    }
    check_positive("kalker_factor", kalker_factor)?;
    check_positive("shear_modulus", shear_modulus)?;
    KalkerTable::new(poisson_ratio)
}

/// One checked FASTSIM evaluation (builds the solver; for repeated calls keep a [`Fastsim`]).
pub fn fastsim(
    a: f64,
    b: f64,
    normal_force: f64,
    mu: f64,
    creepages: &Creepages,
    params: FastsimParams,
) -> Result<CreepForces> {
    check_contact_inputs(a, b, normal_force, mu, creepages)?;
    Ok(Fastsim::new(params)?.creep_forces(a, b, normal_force, mu, creepages))
}

/// Checks the inputs of a one-shot creep evaluation: semi-axes a, b (m) > 0, normal force (N)
/// and μ ≥ 0 (zero is a lost contact, zero forces), finite creepages.
pub fn check_contact_inputs(
    a: f64,
    b: f64,
    normal_force: f64,
    mu: f64,
    creepages: &Creepages,
) -> Result<()> {
    check_positive("a", a)?;
    check_positive("b", b)?;
    check_non_negative("normal_force", normal_force)?;
    check_non_negative("mu", mu)?;
    check_finite("creepage_long", creepages.longitudinal)?;
    check_finite("creepage_lat", creepages.lateral)?;
    check_finite("spin", creepages.spin)?;
    Ok(())
}

#[cfg(test)]
mod tests;
