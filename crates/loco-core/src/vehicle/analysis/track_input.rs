//! The locomotive linearised about its static equilibrium at a running speed with the track as an
//! input: `ẏ = A y + B u`, `z = C y + D u` (deviations from equilibrium, SI units).
//!
//! - `u` holds, per wheelset, the eight rail inputs that [`VehicleSystem`] reads at the wheelset's
//!   own distance ([`RailIrregularity`]: y_left, z_left, y_right, z_right in m, then their slopes
//!   d/ds in m/m), wheelset 1 first: `4 × 8 = 32` inputs.
//! - `z` is every channel a run records ([`crate::vehicle::output::run::channel_names`], their units), through the
//!   same recording function ([`crate::vehicle::output::run::sample`]), so any recorded channel is an output.
//!
//! All four matrices are central finite differences of the full nonlinear right-hand side and of
//! the recording function about the equilibrium, as [`crate::vehicle::analysis::linearise`] forms `A` for the
//! eigenvalue analysis, with the same [`LinearisationSettings`]: the rails' lateral positions by
//! `contact_step` (they move the contact across the wheel as the wheelset's lateral position
//! does), their heights and slopes by `step` (m, m/m; heights act through the Hertz approach). Discrete damper states (a frequency valve) stay
//! at their start state, as in the eigenvalue analysis: an FSD is linearised with its valve in the
//! `start_closed` position.

use crate::error::{LocoError, Result};
use crate::track::RailIrregularity;
use crate::vehicle::analysis::linearise::LinearisationSettings;
use crate::vehicle::model::layout::N_WHEELSETS;
use crate::vehicle::output::channel_set::ChannelSet;
use crate::vehicle::system::simulation::VehicleSystem;
use crate::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use crate::vehicle::time::integrator::OdeSystem;

/// Rail inputs per wheelset (positions then slopes).
pub const RAIL_INPUTS: usize = 8;

/// The linearised vehicle with the rails as inputs; matrices row-major.
#[derive(Debug, Clone)]
pub struct TrackInputModel {
    /// Number of states n.
    pub n: usize,
    /// Number of inputs, `4 · 8`.
    pub n_inputs: usize,
    /// Output channel names, in the order of the rows of C and D.
    pub outputs: Vec<String>,
    /// n×n state matrix, 1/s.
    pub a: Vec<f64>,
    /// n×32 input matrix.
    pub b: Vec<f64>,
    /// m×n output matrix.
    pub c: Vec<f64>,
    /// m×32 feed-through matrix.
    pub d: Vec<f64>,
    /// Longitudinal position of each wheelset ahead of the vehicle origin, m.
    pub wheelset_x: [f64; N_WHEELSETS],
    /// Running speed, m/s.
    pub speed: f64,
    /// Equilibrium state.
    pub y0: Vec<f64>,
}

/// The field of a rail irregularity with index `j` (0..8, [`RailIrregularity`] field order).
fn rail_field(r: &mut RailIrregularity, j: usize) -> &mut f64 {
    match j {
        0 => &mut r.y_left,
        1 => &mut r.z_left,
        2 => &mut r.y_right,
        3 => &mut r.z_right,
        4 => &mut r.dy_left_ds,
        5 => &mut r.dz_left_ds,
        6 => &mut r.dy_right_ds,
        _ => &mut r.dz_right_ds,
    }
}

/// Right-hand side and outputs of `system` at `y` with the current rail inputs.
fn evaluate(
    system: &mut VehicleSystem,
    channel_set: &ChannelSet,
    y: &[f64],
    dy: &mut [f64],
    z: &mut Vec<f64>,
) {
    system.derivatives(0.0, y, dy);
    z.clear();
    channel_set.sample(system, y, dy, |v| z.push(v));
}

/// Linearises `system` about its static equilibrium at its (constant) speed with the rails as
/// inputs, with the default [`LinearisationSettings`]. The system's own track is not read.
pub fn track_input_model(system: &mut VehicleSystem) -> Result<TrackInputModel> {
    track_input_model_with(system, &LinearisationSettings::default())
}

/// [`track_input_model`] with the given settings.
pub fn track_input_model_with(
    system: &mut VehicleSystem,
    settings: &LinearisationSettings,
) -> Result<TrackInputModel> {
    let settings = settings.checked()?;
    let y0 = static_equilibrium(system, &StaticsSettings::default())?.state;
    let channel_set = ChannelSet::new(&system.structure)?;
    let outputs = channel_set.names();
    let (n, m, p) = (system.dimension(), outputs.len(), N_WHEELSETS * RAIL_INPUTS);
    let (mut a, mut c) = (vec![0.0; n * n], vec![0.0; m * n]);
    let (mut b, mut d) = (vec![0.0; n * p], vec![0.0; m * p]);
    let (mut plus, mut minus) = (vec![0.0; n], vec![0.0; n]);
    let (mut z_plus, mut z_minus) = (Vec::with_capacity(m), Vec::with_capacity(m));
    let perfect = [RailIrregularity::default(); N_WHEELSETS];
    system.rail_inputs = Some(perfect);
    let mut y = y0.clone();
    for j in 0..n {
        let h = settings.state_step(j, y0[j]);
        y[j] = y0[j] + h;
        evaluate(system, &channel_set, &y, &mut plus, &mut z_plus);
        y[j] = y0[j] - h;
        evaluate(system, &channel_set, &y, &mut minus, &mut z_minus);
        y[j] = y0[j];
        for i in 0..n {
            a[i * n + j] = (plus[i] - minus[i]) / (2.0 * h);
        }
        for i in 0..m {
            c[i * n + j] = (z_plus[i] - z_minus[i]) / (2.0 * h);
        }
    }
    for w in 0..N_WHEELSETS {
        for k in 0..RAIL_INPUTS {
            let col = w * RAIL_INPUTS + k;
            // The rails' lateral positions move the contact across the wheel, as the wheelset's
            // lateral position does; heights and slopes act through the Hertz approach.
            let h = if k == 0 || k == 2 {
                settings.contact_step
            } else {
                settings.step
            };
            let mut rails = perfect;
            *rail_field(&mut rails[w], k) = h;
            system.rail_inputs = Some(rails);
            evaluate(system, &channel_set, &y0, &mut plus, &mut z_plus);
            *rail_field(&mut rails[w], k) = -h;
            system.rail_inputs = Some(rails);
            evaluate(system, &channel_set, &y0, &mut minus, &mut z_minus);
            for i in 0..n {
                b[i * p + col] = (plus[i] - minus[i]) / (2.0 * h);
            }
            for i in 0..m {
                d[i * p + col] = (z_plus[i] - z_minus[i]) / (2.0 * h);
            }
        }
    }
    system.rail_inputs = None;
    if let Some(e) = system.error.take() {
        return Err(e);
    }
    Ok(TrackInputModel {
        n,
        n_inputs: p,
        outputs,
        a,
        b,
        c,
        d,
        wheelset_x: system.structure.layout.wheelset_x,
        speed: system.speed_at(0.0),
        y0,
    })
}

/// The track-input model of a vehicle (parameter set or built structure) in a scenario (wheel, rail, speed, yaw
/// damper; the scenario's track is not used) about its equilibrium at the scenario's speed.
pub fn scenario_track_model(
    vehicle: impl crate::vehicle::model::structure::IntoVehicle,
    scenario: &crate::vehicle::scenarios::scenario::Scenario,
) -> Result<TrackInputModel> {
    scenario_track_model_with(vehicle, scenario, &LinearisationSettings::default())
}

/// [`scenario_track_model`] with the given settings.
pub fn scenario_track_model_with(
    vehicle: impl crate::vehicle::model::structure::IntoVehicle,
    scenario: &crate::vehicle::scenarios::scenario::Scenario,
    settings: &LinearisationSettings,
) -> Result<TrackInputModel> {
    if !scenario.curve.is_empty() {
        return Err(LocoError::param(
            "curve",
            "the frequency response is taken about the straight-track equilibrium; about a \
             steady curve it is not implemented: leave `curve` out (straight track), or run \
             `simulate` in the curve",
        ));
    }
    let vehicle =
        crate::vehicle::scenarios::perfect_track::PerfectTrackVehicle::new(vehicle, scenario)?;
    let mut system = vehicle.system(scenario.speed)?;
    track_input_model_with(&mut system, settings)
}
