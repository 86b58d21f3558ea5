//! FaStrip: strip theory for steady rolling with spin (M. Sh. Sichani, R. Enblom, M. Berg, "An
//! alternative to FASTSIM for tangential solution of the wheel–rail contact", Vehicle System
//! Dynamics 54(6), 2016), in the modified form of CONTACT (E. Vollebregt, CONTACT user
//! guide, "Modified FaStrip", solver M = 5, 2024–2025).
//!
//! Each strip y = y_j of the Hertz ellipse (half-length a_j = a √(1 − y_j²/b²), peak pressure
//! p0·a_j/a) carries the two-dimensional Carter / Haines–Ollerton solution: traction on the bound
//! μ p_n in a slip zone at the trailing edge, and in the adhesion zone [x_i, a_j] at the leading
//! edge, x_i = 2d − a_j, the bound minus a smaller semi-ellipse of radius a_j − d centred at d.
//! In units of μ p0 (p0 = 3N/(2πab), S_c = √(a_j² − x²)/a, S_a = √((a_j − d)² − (x − d)²)/a):
//!
//! ```text
//! p_x = κ (S_c − S_a),   p_y = λ S_c − (λ − φ') S_a                         (adhesion)
//! ξ' = −2(1−ν) G C11 ξ / (π² μ p0),  η' = −2(1−ν) G C22 η / (π² μ p0),  φ' = −3 G c C23 φ / (2π μ p0)
//! d  = (√(η'² + (1 − φ'²)(ξ' − φ' y/a)²) + η' φ') / (1 − φ'²) · a / (1 − ν)
//! κ, λ = (ξ' − φ' y/a, η' + φ' d/a) / |(ξ' − φ' y/a, η' + φ' d/a)|
//! ```
//!
//! with c = √(ab) and Kalker's coefficients C_ij(a/b) (Sichani's scaling, chosen so that the
//! strip theory reproduces Kalker's linear Fx and Fy at vanishing creepage). A strip has no
//! adhesion (full slip) when the discriminant is negative, d < 0, d ≥ a_j or |φ'| = 1. In the slip
//! zone the traction has the magnitude μ p_n of Hertz's elliptic pressure and the direction of
//! FASTSIM's traction with three flexibilities (as in [`super::fastsim`], elliptic bound), which
//! is integrated along every strip from the leading edge. Where |φ'| > 1 the strip solution can
//! exceed the traction bound; as in CONTACT, a strip whose adhesion tractions exceed μ p0 at an
//! element centre keeps the FASTSIM solution instead.
//!
//! Quadrature: the adhesion zone is integrated in closed form per strip (∫S_c over [x_i, a_j]
//! by the circular-segment formula, ∫S_a = π(a_j − d)²/(2a)); the slip zone has the closed-form
//! magnitude ∫ μ p_n over [−a_j, x_i], spread over FASTSIM's elements in proportion to each
//! element's slip fraction times its bound, along each element's FASTSIM direction (sampling
//! the bound at element centres instead would overstate the thin slip zones of small creepage).
//! At vanishing creepage the only error left is the strip (y) quadrature; p0 is taken from the
//! same strip sum (→ 3N/(2πab)), so full slip gives |F| = μN on any grid. The Kalker coefficient
//! factor k multiplies G in the flexibilities and in the scaled creepages. Every per-strip step
//! (the strip theory, the march, the bound check, the zones' forces) runs in passes of [`LANES`]
//! strips in SIMD registers (`fastrip_lanes`; with AVX 4 + 4 + 2, as FASTSIM's strips), and each
//! register's slip-zone sums start at its own first slipping element. [`Fastrip::new`] precomputes the grid; [`Fastrip::creep_forces`] allocates nothing.

use super::fastrip_lanes::{pass, Element, LANES};
use super::fastsim::FastsimParams;
use super::kalker::{CreepForces, Creepages, KalkerTable};
use crate::error::Result;
use crate::simd::{multiversion, target_cfg_f};
use std::f64::consts::PI;

/// Tolerance on φ' = 1, where the slip-length formula is singular (CONTACT's value).
const UNIT_SPIN_TOLERANCE: f64 = 1e-6;

/// Parameters of FaStrip. The defaults are FASTSIM's ([`FastsimParams::default`]): the two
/// solvers compared on the same grid and material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastripParams {
    /// Elements per strip along the rolling direction (≥ 1), for the slip zone.
    pub nx: usize,
    /// Strips across the ellipse (≥ 1).
    pub ny: usize,
    /// Kalker coefficient factor k (> 0): scales the creepage coefficients (1: Kalker's values).
    pub kalker_factor: f64,
    /// Poisson's ratio ν (–), for the creepage coefficients and the strip theory.
    pub poisson_ratio: f64,
    /// Combined shear modulus G (Pa).
    pub shear_modulus: f64,
}

impl From<FastsimParams> for FastripParams {
    /// FASTSIM's grid, Kalker factor and material (the traction bound of FaStrip is always
    /// Hertz's elliptic pressure).
    fn from(p: FastsimParams) -> Self {
        Self {
            nx: p.nx,
            ny: p.ny,
            kalker_factor: p.kalker_factor,
            poisson_ratio: p.poisson_ratio,
            shear_modulus: p.shear_modulus,
        }
    }
}

impl Default for FastripParams {
    /// FASTSIM's defaults: 10 × 10 grid, k = 1, steel (ν = 0.28, G = 8.2e10 Pa).
    fn default() -> Self {
        FastsimParams::default().into()
    }
}

/// Geometry of [`LANES`] strips in units of (a, b).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct StripLanes {
    /// Strip centre y_j / b.
    pub(super) eta: [f64; LANES],
    /// Strip half-length a_j / a (0 for padding).
    pub(super) half_length: [f64; LANES],
    /// a / a_j (0 for padding).
    pub(super) inv_half_length: [f64; LANES],
}

/// A ready-to-run FaStrip solver: parameters, Kalker table and the normalised grid.
#[derive(Debug, Clone)]
pub struct Fastrip {
    params: FastripParams,
    table: KalkerTable,
    strips: Vec<StripLanes>,
    elements: Vec<Element>,
    /// Elliptic pressure at shape factor 1 per N/(ab) (–), so that FASTSIM's discrete bound sums
    /// to μN.
    pressure_scale: f64,
    /// Σ_j (π/2)(a_j/a)² · 2/ny (–): the strips' semi-ellipses, so that p0 = N/(ab · this)
    /// (2π/3 in the limit, Hertz's p0 = 3N/(2πab)).
    strip_norm: f64,
}

/// Per-call constants of [`Fastrip::creep_forces`] (SI units; primed creepages in units of μ p0).
pub(super) struct Call {
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) inv_a: f64,
    pub(super) xi_s: f64,
    pub(super) eta_s: f64,
    pub(super) phi_s: f64,
    pub(super) d_factor: f64,
    pub(super) unit_spin: bool,
    /// FASTSIM's slope of p_x: (ξ/L1, φ/L3), Pa/m and Pa/m².
    pub(super) slope_x: (f64, f64),
    /// FASTSIM's slope of p_y: (η/L2, φ/L3), Pa/m and Pa/m².
    pub(super) slope_y: (f64, f64),
    pub(super) bound_peak: f64,
    pub(super) dy: f64,
    /// μ p0/a · dy (N/m²).
    pub(super) strip_scale: f64,
}

impl Fastrip {
    /// Checks the parameters and precomputes the grid.
    pub fn new(params: FastripParams) -> Result<Self> {
        let table = super::fastsim::checked_grid_and_material(
            (params.nx, params.ny),
            params.kalker_factor,
            params.shear_modulus,
            params.poisson_ratio,
        )?;
        let (nx, ny) = (params.nx, params.ny);
        let strip = |j: usize| {
            let eta = -1.0 + (2 * j + 1) as f64 / ny as f64;
            (eta, (1.0 - eta * eta).sqrt())
        };
        let strips = (0..ny.div_ceil(LANES))
            .map(|group| {
                let mut lanes = StripLanes::default();
                for lane in 0..LANES {
                    let j = group * LANES + lane;
                    if j < ny {
                        (lanes.eta[lane], lanes.half_length[lane]) = strip(j);
                        lanes.inv_half_length[lane] = 1.0 / lanes.half_length[lane];
                    }
                }
                lanes
            })
            .collect();
        let centre = |k: usize| 1.0 - (2 * k + 1) as f64 / nx as f64;
        let elements: Vec<Element> = (0..nx)
            .map(|k| Element::new(centre(k), if k == 0 { 1.0 } else { centre(k - 1) }, nx))
            .collect();
        // p_n = scale · N/(ab) · s_j · √(1 − u²): Σ_j Σ_k s_j² √(1 − u_k²) · 4/(nx ny) = 1/scale.
        let element_sum: f64 = elements.iter().map(|e| e.shape).sum();
        let strip_sum: f64 = (0..ny).map(|j| strip(j).1.powi(2)).sum();
        let pressure_scale = (nx * ny) as f64 / (4.0 * strip_sum * element_sum);
        let strip_norm = PI * strip_sum / ny as f64;
        Ok(Self {
            params,
            table,
            strips,
            elements,
            pressure_scale,
            strip_norm,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &FastripParams {
        &self.params
    }

    /// Creep forces for semi-axes `a` (rolling direction) and `b` (m), normal force
    /// `normal_force` (N), friction coefficient `mu` and `creepages`. Inputs are not checked
    /// (hot path; [`fastrip`] and [`check_contact_inputs`](super::fastsim::check_contact_inputs)
    /// check them); a non-positive a, b, N or μ gives zero forces.
    pub fn creep_forces(
        &self,
        a: f64,
        b: f64,
        normal_force: f64,
        mu: f64,
        creepages: &Creepages,
    ) -> CreepForces {
        let Some(call) = self.prepare(a, b, normal_force, mu, creepages) else {
            return CreepForces::default();
        };
        // Beyond |φ'| = 1 the strip solution may exceed the bound: FASTSIM's own sums are kept
        // for the fallback.
        if call.phi_s.abs() > 1.0 {
            self.integrate::<true>(&call)
        } else {
            self.integrate::<false>(&call)
        }
    }

    /// The per-call constants of [`Self::creep_forces`] (`None`: zero forces).
    fn prepare(
        &self,
        a: f64,
        b: f64,
        normal_force: f64,
        mu: f64,
        creepages: &Creepages,
    ) -> Option<Call> {
        if !(a > 0.0 && b > 0.0 && normal_force > 0.0 && mu > 0.0) {
            return None;
        }
        let coef = self.table.coefficients(a / b);
        let nu = self.table.poisson_ratio();
        let g = self.params.shear_modulus * self.params.kalker_factor;
        // FASTSIM's inverse flexibilities 1/L (Pa/m), for the slip direction.
        let [inv_l1, inv_l2, inv_l3] = coef.inverse_flexibilities(g, a, b);
        let Creepages {
            longitudinal: xi,
            lateral: eta,
            spin: phi,
        } = *creepages;
        // Strip theory in units of μ p0, p0 from the discrete strip sum (→ 3N/(2πab)) so that
        // full slip gives μN on any grid.
        let mu_p0 = mu * normal_force / (a * b * self.strip_norm);
        let xi_s = -2.0 * (1.0 - nu) * g * coef.c11 * xi / (PI * PI * mu_p0);
        let eta_s = -2.0 * (1.0 - nu) * g * coef.c22 * eta / (PI * PI * mu_p0);
        let phi_s = -3.0 * g * (a * b).sqrt() * coef.c23 * phi / (2.0 * PI * mu_p0);
        let call = Call {
            a,
            b,
            inv_a: 1.0 / a,
            xi_s,
            eta_s,
            phi_s,
            // d = (√disc + η'φ') · a/((1 − ν)(1 − φ'²)); |φ'| = 1 is full slip.
            d_factor: a / ((1.0 - nu) * (1.0 - phi_s * phi_s)),
            unit_spin: (phi_s.abs() - 1.0).abs() <= UNIT_SPIN_TOLERANCE,
            slope_x: (xi * inv_l1, phi * inv_l3),
            slope_y: (eta * inv_l2, phi * inv_l3),
            bound_peak: mu * normal_force * self.pressure_scale / (a * b),
            dy: 2.0 * b / self.params.ny as f64,
            strip_scale: mu_p0 / a * 2.0 * b / self.params.ny as f64,
        };
        Some(call)
    }

    /// [`Self::integrate_lanes`] in the layout of the copy [`integrate_copy`] runs.
    #[inline(always)]
    fn integrate<const FALLBACK: bool>(&self, k: &Call) -> CreepForces {
        integrate_copy::<FALLBACK>(self, k)
    }

    /// Every pass of [`LANES`] strips, `G` registers of `W` lanes and a tail of `T`.
    #[inline(always)]
    fn integrate_lanes<const FALLBACK: bool, const W: usize, const G: usize, const T: usize>(
        &self,
        k: &Call,
    ) -> CreepForces {
        let mut f = [0.0; 3];
        for strips in &self.strips {
            pass::<FALLBACK, W, G, T>(strips, &self.elements, k, &mut f);
        }
        let [fx, fy, mz] = f;
        CreepForces { fx, fy, mz }
    }
}

/// [`Fastrip::integrate_lanes`] two strips per register in the baseline copy (SSE2); in the AVX
/// copy eight strips in two 256-bit registers and the last two in a 128-bit one. The same IEEE
/// operations either way (no fused multiply-add), so the same bits.
#[multiversion(targets("x86_64+avx"))]
fn integrate_copy<const FALLBACK: bool>(solver: &Fastrip, k: &Call) -> CreepForces {
    if target_cfg_f!(target_feature = "avx") {
        solver.integrate_lanes::<FALLBACK, 4, 2, 2>(k)
    } else {
        solver.integrate_lanes::<FALLBACK, 2, { LANES / 2 }, 0>(k)
    }
}

/// One checked FaStrip evaluation (builds the solver; for repeated calls keep a [`Fastrip`]).
pub fn fastrip(
    a: f64,
    b: f64,
    normal_force: f64,
    mu: f64,
    creepages: &Creepages,
    params: FastripParams,
) -> Result<CreepForces> {
    super::fastsim::check_contact_inputs(a, b, normal_force, mu, creepages)?;
    Ok(Fastrip::new(params)?.creep_forces(a, b, normal_force, mu, creepages))
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod reference;
