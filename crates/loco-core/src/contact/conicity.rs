//! Equivalent conicity by the nonlinear kinematic method of EN 15302 (integration of the wheelset's
//! kinematic equation of motion with the nonlinear Δr(y)).
//!
//! # Method
//!
//! A wheelset rolling without slip on straight track obeys Klingel's kinematic equations
//! (EN 15302:2008+A1:2010, Annex B): dy/dx = ψ and dψ/dx = −Δr(y) / (2·e·r0), with x the distance
//! run (m), ψ the yaw angle (rad), e half the lateral distance between the contact points (m) and
//! r0 the nominal rolling radius (m). With S(y) = ∫ Δr dy this is a conservative oscillator:
//!
//! ψ² = (C − S(y)) / (e·r0),
//!
//! with C = S(y_min) = S(y_max) the level of the two turning points. The wheelset amplitude is
//! ŷ = (y_max − y_min)/2; for an asymmetric Δr (different wheel radii or profiles, cases E5–E9)
//! the oscillation is not centred on y = 0. Half a wavelength is the distance run from one turning
//! point to the other,
//!
//! λ/2 = ∫_{y_min}^{y_max} dy / ψ = √(e·r0) · I,   I = ∫ dy / √(C − S(y)),
//!
//! and Klingel's formula for a conical wheelset, λ = 2π·√(r0·e / tan γe), turns it into the
//! equivalent conicity tan γe = (π / I)². The product e·r0 cancels: tan γe depends only on
//! Δr(y) and ŷ; e and r0 only scale the wavelength ([`KinematicOscillation::wavelength`]).
//!
//! # Numerics
//!
//! Δr is linear between its samples ([`DeltaR`]), so S is exactly piecewise quadratic. The level C
//! is solved (Illinois regula falsi) so that the turning points, found from the centred running
//! position outward, are 2ŷ apart. The integral, singular like 1/√ at both turning points, is
//! regularised by y = m + h·sin θ (m, h the centre and half-width of the swing), which makes the
//! integrand smooth; it is integrated with Gauss–Legendre rules between the grid points mapped to
//! θ, with C − S(y) integrated from the nearer turning point so that it keeps its precision
//! there. No time stepping is involved, so there is no step-size error.
//!
//! If Δr is zero on an interval around the running position (a neutral zone, EN 15302 case E4) and
//! ŷ is not larger than its half-width, nothing steers the wheelset back: tan γe = 0.

use super::delta_r::DeltaR;
use super::quadrature::integrate_pieces;
use crate::error::{check_positive, LocoError, Result};
use std::f64::consts::{FRAC_PI_2, PI};

/// The kinematic oscillation of a wheelset at one amplitude.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinematicOscillation {
    /// Wheelset amplitude ŷ = (y_max − y_min)/2 (m).
    pub amplitude: f64,
    /// Equivalent conicity tan γe (-).
    pub tan_gamma_e: f64,
    /// Turning point on the right, the smallest lateral displacement of the swing (m).
    pub y_min: f64,
    /// Turning point on the left, the largest lateral displacement of the swing (m).
    pub y_max: f64,
}

impl KinematicOscillation {
    /// Kinematic wavelength λ = 2π·√(r0·e / tan γe) (m) for `half_contact_distance` e (m, half
    /// the lateral distance between the nominal contact points) and `nominal_radius` r0 (m);
    /// infinite when tan γe = 0.
    pub fn wavelength(&self, half_contact_distance: f64, nominal_radius: f64) -> Result<f64> {
        let e = check_positive("half_contact_distance", half_contact_distance)?;
        let r0 = check_positive("nominal_radius", nominal_radius)?;
        Ok(2.0 * PI * (r0 * e / self.tan_gamma_e).sqrt())
    }
}

/// Equivalent conicity tan γe (-) at wheelset amplitude `amplitude` (m) by the nonlinear kinematic
/// method of EN 15302; see [`kinematic_oscillation`].
pub fn equivalent_conicity(delta_r: &DeltaR, amplitude: f64) -> Result<f64> {
    Ok(kinematic_oscillation(delta_r, amplitude)?.tan_gamma_e)
}

/// Equivalent conicity (-) at each of `amplitudes` (m) by the nonlinear kinematic method.
pub fn conicity_curve(delta_r: &DeltaR, amplitudes: &[f64]) -> Result<Vec<f64>> {
    amplitudes
        .iter()
        .map(|&a| equivalent_conicity(delta_r, a))
        .collect()
}

/// The kinematic oscillation of amplitude `amplitude` (m, > 0) under `delta_r`.
///
/// Errors: [`LocoError::InvalidParameter`] naming `amplitude` when it is not positive or when
/// the swing would leave the lateral range sampled by `delta_r`; [`LocoError::InvalidInput`]
/// naming `dr` when Δr has no upward zero crossing (no centred running position).
pub fn kinematic_oscillation(delta_r: &DeltaR, amplitude: f64) -> Result<KinematicOscillation> {
    let target = check_positive("amplitude", amplitude)?;
    let (y_eq, right_node) = delta_r.equilibrium()?;
    let swing = Swing {
        f: delta_r,
        y_eq,
        right_node,
    };

    let c_low = delta_r.potential(y_eq);
    let (neutral_min, neutral_max) = swing.turning_points(c_low, false)?;
    if 0.5 * (neutral_max - neutral_min) >= target {
        return Ok(KinematicOscillation {
            amplitude: target,
            tan_gamma_e: 0.0,
            y_min: neutral_min,
            y_max: neutral_max,
        });
    }
    let c_high = swing.highest_level();
    let (top_min, top_max) = swing.turning_points(c_high, true)?;
    let largest = 0.5 * (top_max - top_min);
    if largest < target {
        let (a, b) = delta_r.range();
        return Err(LocoError::param(
            "amplitude",
            format!(
                "{target} m needs a swing beyond the Δr samples [{a}, {b}] m \
                 (largest amplitude they support: {largest} m)"
            ),
        ));
    }

    let level = solve_level(&swing, target, (c_low, c_high))?;
    let (y_min, y_max) = swing.turning_points(level, true)?;
    let centre = 0.5 * (y_max + y_min);
    let half = 0.5 * (y_max - y_min);
    let mut breaks = vec![-FRAC_PI_2];
    // Grid points (kinks of the integrand) as breaks, except those so close to a turning point
    // that their piece would be narrower than the mapping can resolve.
    let margin = 1e-9 * half;
    for &node in delta_r.y() {
        if node > y_min + margin && node < y_max - margin {
            breaks.push(((node - centre) / half).clamp(-1.0, 1.0).asin());
        }
    }
    breaks.push(FRAC_PI_2);
    let integral = integrate_pieces(&breaks, |theta| {
        // Distance from the nearer turning point, 2h·sin²(φ/2) with φ = π/2 − |θ|, without the
        // round-off of 1 − |sin θ|; and the gap C − S(y) = ∫_y^{y_t} Δr, integrated locally.
        let from_turn = 2.0 * half * (0.5 * (FRAC_PI_2 - theta.abs())).sin().powi(2);
        let (y, turn) = if theta < 0.0 {
            (y_min + from_turn, y_min)
        } else {
            (y_max - from_turn, y_max)
        };
        // Closer to the turning point than y can resolve: its first-order gap |Δr(y_t)|·distance.
        let gap = match delta_r.integral(y, turn) {
            g if g > 0.0 => g,
            _ => (from_turn * delta_r.value(turn).abs()).max(f64::MIN_POSITIVE),
        };
        half * theta.cos() / gap.sqrt()
    });
    Ok(KinematicOscillation {
        amplitude: target,
        tan_gamma_e: (PI / integral).powi(2),
        y_min,
        y_max,
    })
}

/// Finds the level C in `bracket` whose turning points are 2·`target` apart (Illinois method).
fn solve_level(swing: &Swing<'_>, target: f64, bracket: (f64, f64)) -> Result<f64> {
    let excess = |c: f64| -> Result<f64> {
        let (lo, hi) = swing.turning_points(c, true)?;
        Ok(0.5 * (hi - lo) - target)
    };
    let (mut a, mut b) = bracket;
    let (mut fa, mut fb) = (excess(a)?, excess(b)?);
    let tolerance = 1e-13 * target;
    let mut side = 0i8;
    for _ in 0..200 {
        let c = if fb != fa {
            (a * fb - b * fa) / (fb - fa)
        } else {
            0.5 * (a + b)
        };
        let c = if c > a.min(b) && c < a.max(b) {
            c
        } else {
            0.5 * (a + b)
        };
        let fc = excess(c)?;
        if fc.abs() <= tolerance || (b - a).abs() <= 1e-15 * a.abs().max(b.abs()) {
            return Ok(c);
        }
        if (fc > 0.0) == (fb > 0.0) {
            b = c;
            fb = fc;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            a = c;
            fa = fc;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    Ok(0.5 * (a + b))
}

/// The centred running position of a Δr function and the search for turning points from it.
struct Swing<'a> {
    f: &'a DeltaR,
    /// Upward zero crossing of Δr (m).
    y_eq: f64,
    /// Index of the first grid point right of `y_eq`.
    right_node: usize,
}

impl Swing<'_> {
    /// The highest level C at which both turning points still lie within the samples: the lower
    /// of the maxima of S on the left and on the right of the running position (m²).
    fn highest_level(&self) -> f64 {
        let s = self.f.potential_at_nodes();
        let left = s[..self.right_node]
            .iter()
            .copied()
            .fold(f64::MIN, f64::max);
        let right = s[self.right_node..]
            .iter()
            .copied()
            .fold(f64::MIN, f64::max);
        left.min(right)
    }

    /// Turning points (y_min, y_max) (m) at level `c`: walking outward from the running position,
    /// the first points where S reaches `c` (S ≥ c when `inclusive`, S > c otherwise; the strict
    /// form at the bottom level crosses a neutral zone where S stays equal to `c`).
    fn turning_points(&self, c: f64, inclusive: bool) -> Result<(f64, f64)> {
        let y = self.f.y();
        let reached = |s: f64| if inclusive { s >= c } else { s > c };
        // Left: segments [y_{i-1}, y_i] walked from the running position toward smaller y.
        let mut start = self.y_eq;
        let mut y_min = None;
        for i in (0..self.right_node).rev() {
            let end = y[i];
            if let Some(hit) = self.crossing(start, end, &reached) {
                y_min = Some(hit);
                break;
            }
            start = end;
        }
        let mut start = self.y_eq;
        let mut y_max = None;
        for &end in &y[self.right_node..] {
            if let Some(hit) = self.crossing(start, end, &reached) {
                y_max = Some(hit);
                break;
            }
            start = end;
        }
        match (y_min, y_max) {
            (Some(lo), Some(hi)) => Ok((lo, hi)),
            _ => Err(LocoError::param(
                "amplitude",
                "the swing leaves the lateral range sampled by Δr",
            )),
        }
    }

    /// The first point from `start` toward `end` (within one Δr segment) where `reached(S)`;
    /// `None` if there is none. S is quadratic there: its extremum inside is checked too.
    fn crossing(&self, start: f64, end: f64, reached: &impl Fn(f64) -> bool) -> Option<f64> {
        if start == end {
            return reached(self.f.potential(end)).then_some(end);
        }
        let segment = self.f.segment(0.5 * (start + end));
        let node = self.f.y()[segment];
        let slope = self.f.slope(segment);
        // The extremum of S inside the segment, where Δr = 0.
        let mut far = end;
        if slope != 0.0 {
            let y_zero = node - self.f.values()[segment] / slope;
            let inside = (y_zero - start) * (y_zero - end) < 0.0;
            if inside && reached(self.f.potential(y_zero)) {
                far = y_zero;
            }
        }
        if !reached(self.f.potential(far)) {
            return None;
        }
        // S is monotone on [start, far] and reaches the level at `far`: bisect to round-off.
        let (mut below, mut above) = (start, far);
        for _ in 0..200 {
            let mid = 0.5 * (below + above);
            if mid == below || mid == above {
                break;
            }
            if reached(self.f.potential(mid)) {
                above = mid;
            } else {
                below = mid;
            }
        }
        Some(above)
    }
}

#[cfg(test)]
mod tests;
