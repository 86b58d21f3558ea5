//! The linear contact parameters of a wheelset on its rails: besides the conicity, the
//! contact-angle parameter ε and the roll parameter σ that set its gravitational stiffness and
//! roll (Wickens' notation).
//!
//! # Definitions
//!
//! Wickens (A. H. Wickens, *Fundamentals of Rail Vehicle Dynamics*, Swets & Zeitlinger 2003,
//! ch. 2; the linearisation of Wickens, "The dynamic stability of railway vehicle wheelsets and
//! bogies having profiled wheels", Int. J. Solids Struct. 1, 1965) writes the rigid contact of a
//! wheelset displaced laterally by `y` (m, + left), for small `y`, as
//!
//! - rolling radii `r_L − r_R = 2 λ y` (λ, –, the conicity of the rolled wheelset);
//! - contact angles `θ_L − θ_R = 2 ε y / l0` (ε, –), θ measured from the wheelset's axle (the
//!   angle of the contact normal relative to the rolled wheelset; in track axes the angle is
//!   θ ± φ);
//! - roll `φ = σ y / l0` (σ, –), positive lifting the left wheel;
//!
//! with `l0` (m) half the lateral distance between the two contact points and `r0` (m) the
//! rolling radius, both at the centred pose, and `δ0` (rad) the contact angle there.
//!
//! The gravitational stiffness is the lateral stiffness that the axle load `W` (N) gives through
//! the contact constraint: the wheelset rises by `h(y)` as it moves across, so its potential is
//! `W·h(y)` and `K_g = W·d²h/dy²` (N/m). In Wickens' parameters, for the two circles of radius
//! `R_w` (wheel, concave, centre below the contact) and `R_r` (rail head) at the contact, the
//! moment balance of the wheelset about its centre gives the lateral force of the two normal
//! forces, to first order in `y` and exactly in `δ0` (derived in this module's tests):
//!
//! ```text
//! K_g / W = (ε + σ)/l0 + tan δ0 · (l0 sin δ0 + r0 cos δ0 + R_w) · ε
//!                               / (l0 · (l0 cos δ0 − r0 sin δ0))
//! ```
//!
//! The first term is Wickens' `W ε / l0` with the angles taken in track axes (`W (ε + σ)/l0`);
//! the second comes from the load transferred between the wheels by the roll moment. For a cone
//! on a knife edge ε = 0 and `R_w ε` stays finite (`→ l0 (l0 + R_r δ0)/(l0 − r0 δ0)`): the
//! stiffness is about `2 W δ0 / l0`, all of it from the rolled axle and the load transfer. This
//! module does not use the circle formula: it reads the parameters of any pair from its rigid
//! contact by central differences at `±amplitude` about the centred pose, and `K_g/W` from the
//! rise, exactly as the model sees it (the formula is its test).
//!
//! Units: lengths m, angles rad, ε, σ and λ dimensionless, `K_g/W` 1/m.

use super::geometry::{ContactGeometry, ContactWorkspace, WheelsetContact};
use super::setup::{LEFT, RIGHT};
use crate::error::{check_positive, LocoError, Result};

/// Default half step of the central differences, m: 0.5 mm, small against the tread's radii
/// (the parameters' second-order error is about (amplitude / radius)²) and large against the
/// contact search's tolerance (1e-11 m on the rise, whose change over the step is ≥ 1e-9 m on
/// the study's pairs).
pub const DEFAULT_AMPLITUDE: f64 = 5e-4;

/// The linear contact parameters of one wheelset on its rails (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearContactParameters {
    /// Half step of the central differences, m.
    pub amplitude: f64,
    /// l0: half the lateral distance between the two wheels' contact points at y = 0, m.
    pub half_contact_spacing: f64,
    /// r0: mean rolling radius at y = 0, m.
    pub rolling_radius: f64,
    /// δ0: mean contact angle at y = 0 (track axes), rad.
    pub contact_angle: f64,
    /// λ: half the slope of the rigid wheelset's rolling radius difference, –.
    pub conicity: f64,
    /// ε: contact-angle parameter, `θ_L − θ_R = 2 ε y / l0` with θ relative to the axle, –.
    pub contact_angle_parameter: f64,
    /// σ: roll parameter, `φ = σ y / l0`, –.
    pub roll_parameter: f64,
    /// `K_g / W = d²h/dy²`: gravitational stiffness per unit axle load, 1/m.
    pub gravitational_stiffness_per_load: f64,
}

impl LinearContactParameters {
    /// The lateral gravitational stiffness (N/m) under axle load `axle_load` (N, the wheelset's
    /// share of the vehicle's weight, its own included).
    pub fn gravitational_stiffness(&self, axle_load: f64) -> Result<f64> {
        check_positive("axle_load", axle_load)?;
        Ok(axle_load * self.gravitational_stiffness_per_load)
    }
}

/// The touching point of the wheel on `side`, or an error naming the displacement.
fn touching(c: &WheelsetContact, side: usize) -> Result<(f64, f64, f64)> {
    c.wheels[side]
        .touching()
        .map(|p| (p.lateral, p.rolling_radius, p.contact_angle))
        .ok_or_else(|| {
            LocoError::Contact(format!(
                "no contact point at lateral displacement {} m",
                c.lateral_displacement
            ))
        })
}

/// The linear contact parameters of `geometry` by central differences of its rigid contact at
/// `±amplitude` (m, > 0; [`DEFAULT_AMPLITUDE`] unless a pair needs another).
pub fn linear_parameters(
    geometry: &ContactGeometry,
    amplitude: f64,
) -> Result<LinearContactParameters> {
    check_positive("amplitude", amplitude)?;
    if amplitude > 0.01 {
        return Err(LocoError::param(
            "amplitude",
            format!("{amplitude} m is not a small displacement (at most 0.01 m)"),
        ));
    }
    let mut ws = ContactWorkspace::default();
    let centre = geometry.solve_with(0.0, geometry.roll_at_centre(), &mut ws)?;
    let plus = geometry.solve_with(amplitude, centre.roll, &mut ws)?;
    let minus = geometry.solve_with(-amplitude, centre.roll, &mut ws)?;
    let (lat_l, r_l, d_l) = touching(&centre, LEFT)?;
    let (lat_r, r_r, d_r) = touching(&centre, RIGHT)?;
    let l0 = 0.5 * (lat_l - lat_r);
    // Rolling radius difference and track-axes contact angle difference at a pose.
    let differences = |c: &WheelsetContact| -> Result<(f64, f64)> {
        let (_, rl, dl) = touching(c, LEFT)?;
        let (_, rr, dr) = touching(c, RIGHT)?;
        Ok((rl - rr, dl - dr))
    };
    let (dr_plus, dd_plus) = differences(&plus)?;
    let (dr_minus, dd_minus) = differences(&minus)?;
    let span = 2.0 * amplitude;
    let roll_slope = (plus.roll - minus.roll) / span;
    let sigma = l0 * roll_slope;
    // θ = δ ∓ φ on the left and right wheel: θ_L − θ_R = (δ_L − δ_R) − 2φ.
    let epsilon = 0.5 * l0 * ((dd_plus - dd_minus) / span - 2.0 * roll_slope);
    Ok(LinearContactParameters {
        amplitude,
        half_contact_spacing: l0,
        rolling_radius: 0.5 * (r_l + r_r),
        contact_angle: 0.5 * (d_l + d_r),
        conicity: 0.5 * (dr_plus - dr_minus) / span,
        contact_angle_parameter: epsilon,
        roll_parameter: sigma,
        gravitational_stiffness_per_load: (plus.rise + minus.rise - 2.0 * centre.rise)
            / (amplitude * amplitude),
    })
}

#[cfg(test)]
mod tests;
