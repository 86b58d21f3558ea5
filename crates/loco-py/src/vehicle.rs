//! Bindings of `loco_core::vehicle`: the parameter file, names of bodies and coordinates, runs,
//! modes' kinetic energy, the linearisation and the critical speeds, each of a built vehicle
//! (`vehicle_handle::PyVehicle`).

use crate::errors::{run_detached, run_detached_monitored};
use crate::scenario::PyRunScenario;
use crate::vehicle_handle::PyVehicle;
use loco_core::metrics::RunMetrics;
use loco_core::vehicle::analysis::linear_critical_speed::{
    linear_critical_speed_cancellable, LinearSearch,
};
use loco_core::vehicle::analysis::modes::{
    body_kind, mode_energies as core_mode_energies, MOTIONS,
};
use loco_core::vehicle::model::layout::{
    body_names as core_body_names, dof_names as core_dof_names,
};
use loco_core::vehicle::output::run::RunOutput;
use loco_core::vehicle::output::run::{BOGIE_LATERAL, CARBODY_LATERAL, CARBODY_VERTICAL};
use loco_core::vehicle::output::wheel_channels::{
    wheel_channel_table, wheelset_channel_table, FLANGE_CONTACT_ANGLE,
};
use loco_core::vehicle::params::parameters::{DEFAULT_VEHICLE_TOML, STUDY_PARAMETERS};
use loco_core::vehicle::runs::critical_speed::{
    nonlinear_critical_speed, RampOutcome, RampSettings,
};
use loco_core::vehicle::runs::simulate::{linearised, simulate_cancellable};
use loco_core::vehicle::system::run_statistics::RunStatistics;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyReadonlyArray2};
use pyo3::prelude::*;
use std::collections::BTreeMap;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// The embedded default vehicle file (TOML text).
#[pyfunction]
fn default_vehicle_toml() -> &'static str {
    DEFAULT_VEHICLE_TOML
}

/// The six study parameters (SPEC §6) as `(alias, file key)` pairs.
#[pyfunction]
fn study_parameters() -> Vec<(&'static str, &'static str)> {
    STUDY_PARAMETERS.to_vec()
}

/// Names of the 90 coordinates, in state order.
#[pyfunction]
fn dof_names() -> Vec<String> {
    core_dof_names()
}

/// The run channels the metrics are computed from, by metric family: `A_yc` (carbody floor
/// lateral, also W_y), `A_zc` (carbody floor vertical, W_z) and `A_yb` (bogie frame lateral).
#[pyfunction]
fn metric_channels() -> BTreeMap<&'static str, &'static str> {
    BTreeMap::from([
        ("A_yc", CARBODY_LATERAL),
        ("A_zc", CARBODY_VERTICAL),
        ("A_yb", BOGIE_LATERAL),
    ])
}

/// The per-wheel channels by quantity (`Q`, `Y`, `YQ`, `dQQ`, `Tgamma`, `contact_angle`,
/// `flange`), each a list of names wheelset by wheelset, left before right.
#[pyfunction]
fn wheel_channels() -> BTreeMap<&'static str, Vec<String>> {
    wheel_channel_table().into_iter().collect()
}

/// The per-wheelset channels by quantity (`y`, `yaw` — the angle of attack on a curve — and
/// `sumY`), each a list of names wheelset by wheelset.
#[pyfunction]
fn wheelset_channels() -> BTreeMap<&'static str, Vec<String>> {
    wheelset_channel_table().into_iter().collect()
}

/// Contact angle above which a loaded point counts as flange contact (channel `flange`), rad.
#[pyfunction]
fn flange_contact_angle() -> f64 {
    FLANGE_CONTACT_ANGLE
}

/// Names of the 25 bodies.
#[pyfunction]
fn body_names() -> Vec<String> {
    core_body_names()
}

/// The six motions of a body (`longitudinal`, `lateral`, `vertical`, `roll`, `pitch`, `yaw`), in
/// the order of `mode_energies`' last axis.
#[pyfunction]
fn body_motion_names() -> Vec<&'static str> {
    MOTIONS.to_vec()
}

/// What `mode_energies` returns: body names, body kinds, energy shares (n_modes × n_bodies) and
/// motion shares (n_modes × n_bodies × 6).
type ModeEnergiesTuple<'py> = (
    Vec<String>,
    Vec<String>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray3<f64>>,
);

/// Kinetic-energy shares of complex mode shapes `real + i·imag` (n_modes × n, the first 90
/// columns the coordinates): each body's share of each mode's energy and, per body, the share
/// of its energy in each motion (see `loco.modes`), of the built `vehicle`.
#[pyfunction]
fn mode_energies<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    real: PyReadonlyArray2<'py, f64>,
    imag: PyReadonlyArray2<'py, f64>,
) -> PyResult<ModeEnergiesTuple<'py>> {
    let (real, imag) = (real.as_array(), imag.as_array());
    if real.dim() != imag.dim() {
        return Err(pyo3::exceptions::PyValueError::new_err(format!(
            "real and imag must have the same shape, got {:?} and {:?}",
            real.dim(),
            imag.dim()
        )));
    }
    let rows = |a: numpy::ndarray::ArrayView2<'_, f64>| -> Vec<Vec<f64>> {
        a.rows().into_iter().map(|r| r.to_vec()).collect()
    };
    let (real, imag) = (rows(real), rows(imag));
    let structure = Arc::clone(&vehicle.structure);
    let (structure, energies) = run_detached(py, move || {
        let shapes: Vec<(&[f64], &[f64])> = real
            .iter()
            .zip(&imag)
            .map(|(r, i)| (r.as_slice(), i.as_slice()))
            .collect();
        let energies = core_mode_energies(&structure, &shapes)?;
        Ok((structure, energies))
    })?;
    let n_bodies = structure.bodies.len();
    let mut shares = Array2::<f64>::zeros((energies.len(), n_bodies));
    let mut motions = Array3::<f64>::zeros((energies.len(), n_bodies, MOTIONS.len()));
    for (m, e) in energies.iter().enumerate() {
        for b in 0..n_bodies {
            shares[[m, b]] = e.bodies[b];
            for k in 0..MOTIONS.len() {
                motions[[m, b, k]] = e.motions[b][k];
            }
        }
    }
    let names: Vec<String> = structure.bodies.iter().map(|b| b.name.clone()).collect();
    let kinds = names.iter().map(|n| body_kind(n)).collect();
    Ok((
        names,
        kinds,
        shares.into_pyarray(py),
        motions.into_pyarray(py),
    ))
}

/// What `simulate` returns: time (s), channel names, channels (n_channels × n_samples, SI),
/// metric names and values.
type SimulationTuple<'py> = (
    Bound<'py, PyArray1<f64>>,
    Vec<String>,
    Bound<'py, PyArray2<f64>>,
    Vec<&'static str>,
    Bound<'py, PyArray1<f64>>,
    Vec<(&'static str, f64)>,
);

/// Time (s), channel names and channels (n_channels × n_samples) of a run.
pub type ChannelsTuple<'py> = (
    Bound<'py, PyArray1<f64>>,
    Vec<String>,
    Bound<'py, PyArray2<f64>>,
);

/// Channels of a run as a (n_channels × n_samples) array, moved without copying the samples
/// twice.
pub fn channels_array<'py>(py: Python<'py>, output: RunOutput) -> PyResult<ChannelsTuple<'py>> {
    let n = output.time.len();
    let names = output.names;
    let flat: Vec<f64> = output.channels.into_iter().flatten().collect();
    let channels = numpy::ndarray::Array2::from_shape_vec((names.len(), n), flat)
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok((
        output.time.into_pyarray(py),
        names,
        channels.into_pyarray(py),
    ))
}

/// Simulates one run of the locomotive (see `loco.simulate`) through `scenario`.
#[pyfunction]
fn simulate<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    scenario: PyRef<'py, PyRunScenario>,
) -> PyResult<SimulationTuple<'py>> {
    let scenario = scenario.inner.clone();
    let structure = Arc::clone(&vehicle.structure);
    // On a worker thread, so that Ctrl-C (checked every 100 ms) stops the run.
    let cancel = Arc::new(AtomicBool::new(false));
    let worker_cancel = Arc::clone(&cancel);
    let work = move || simulate_cancellable(structure, &scenario, Some(&worker_cancel));
    let result = run_detached_monitored(py, work, &cancel, |_| Ok(()))?;
    let (time, names, channels) = channels_array(py, result.output)?;
    Ok((
        time,
        names,
        channels,
        RunMetrics::names().to_vec(),
        result.metrics.values().into_pyarray(py),
        RunStatistics::NAMES
            .into_iter()
            .zip(result.statistics.values())
            .collect(),
    ))
}

/// The state matrix of the vehicle linearised about its static equilibrium at the scenario's
/// speed (m/s) on perfect track (see `loco.eigen`): a square numpy array over (coordinates,
/// velocities, damper internal states).
#[pyfunction]
fn linearise<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    scenario: PyRef<'py, PyRunScenario>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let scenario = scenario.inner.clone();
    let structure = Arc::clone(&vehicle.structure);
    let (a, n) = run_detached(py, move || linearised(structure, &scenario))?;
    let matrix = numpy::ndarray::Array2::from_shape_vec((n, n), a)
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok(matrix.into_pyarray(py))
}

/// Linear critical speed (m/s) by bisection of the linearisation on perfect track, or from a
/// `guess` (m/s) by a bracket around it and interpolation (see
/// `loco.critical_speed(..., method="linear")`) and how the search ended: `"found"`,
/// `"stable_at_high"` (speed `inf`: none below the search limit `high`) or `"unstable_at_low"`
/// (speed `low`: at or below it); and the bracket (low, high) searched, m/s. Each setting left as
/// None takes the core's default.
#[pyfunction]
#[pyo3(signature = (
    vehicle, scenario, *, low=None, high=None, tolerance=None, band=None, guess=None
))]
#[allow(clippy::too_many_arguments)]
fn linear_critical_speed(
    py: Python<'_>,
    vehicle: PyRef<'_, PyVehicle>,
    scenario: PyRef<'_, PyRunScenario>,
    low: Option<f64>,
    high: Option<f64>,
    tolerance: Option<f64>,
    band: Option<(f64, f64)>,
    guess: Option<f64>,
) -> PyResult<(f64, &'static str, f64, f64)> {
    let scenario = scenario.inner.clone();
    let structure = Arc::clone(&vehicle.structure);
    let default = LinearSearch::default();
    let search = LinearSearch {
        low: low.unwrap_or(default.low),
        high: high.unwrap_or(default.high),
        tolerance: tolerance.unwrap_or(default.tolerance),
        band: band.unwrap_or(default.band),
        guess,
        ..default
    };
    let (searched_low, searched_high) = (search.low, search.high);
    // On a worker thread, so that Ctrl-C (checked every 100 ms) stops it between linearisations.
    let cancel = Arc::new(AtomicBool::new(false));
    let worker_cancel = Arc::clone(&cancel);
    let work = move || {
        linear_critical_speed_cancellable(structure, &scenario, &search, Some(&worker_cancel))
    };
    let speed = run_detached_monitored(py, work, &cancel, |_| Ok(()))?;
    // The core returns exactly `inf` and `low` for the two ends of the bracket; a found
    // critical speed lies strictly inside it.
    let outcome = if speed.is_infinite() {
        "stable_at_high"
    } else if speed == searched_low {
        "unstable_at_low"
    } else {
        "found"
    };
    Ok((speed, outcome, searched_low, searched_high))
}

/// What `ramp_down` returns: critical speed (m/s), outcome (`"died_out"`, `"stable_at_start"`,
/// `"hunts_at_end"`), and the speed (m/s) at the centre and the hunting amplitude (m) of each
/// window.
type RampTuple<'py> = (
    f64,
    &'static str,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
);

/// Nonlinear critical speed by a speed ramp-down from the scenario's speed on perfect track (see
/// `loco.critical_speed(..., method="nonlinear")`); Ctrl-C stops it. Each setting left as None
/// takes the core's default (`RampSettings::default`).
#[pyfunction]
#[pyo3(signature = (
    vehicle, scenario, *, end_speed=None, deceleration=None, hold=None, max_hold=None, disturbance=None, window=None,
    threshold=None
))]
#[allow(clippy::too_many_arguments)]
fn ramp_down<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    scenario: PyRef<'py, PyRunScenario>,
    end_speed: Option<f64>,
    deceleration: Option<f64>,
    hold: Option<f64>,
    max_hold: Option<f64>,
    disturbance: Option<f64>,
    window: Option<f64>,
    threshold: Option<f64>,
) -> PyResult<RampTuple<'py>> {
    let scenario = scenario.inner.clone();
    let structure = Arc::clone(&vehicle.structure);
    let default = RampSettings::default();
    let settings = RampSettings {
        end_speed: end_speed.unwrap_or(default.end_speed),
        deceleration: deceleration.unwrap_or(default.deceleration),
        hold: hold.unwrap_or(default.hold),
        max_hold: max_hold.unwrap_or(default.max_hold),
        disturbance: disturbance.unwrap_or(default.disturbance),
        window: window.unwrap_or(default.window),
        threshold: threshold.unwrap_or(default.threshold),
    };
    let cancel = Arc::new(AtomicBool::new(false));
    let worker_cancel = Arc::clone(&cancel);
    let work =
        move || nonlinear_critical_speed(structure, &scenario, &settings, Some(&worker_cancel));
    let result = run_detached_monitored(py, work, &cancel, |_| Ok(()))?;
    let outcome = match result.outcome {
        RampOutcome::DiedOut => "died_out",
        RampOutcome::StableAtStart => "stable_at_start",
        RampOutcome::HuntsAtEnd => "hunts_at_end",
    };
    Ok((
        result.critical_speed,
        outcome,
        result.window_speed.into_pyarray(py),
        result.window_amplitude.into_pyarray(py),
    ))
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(default_vehicle_toml, m)?)?;
    m.add_function(wrap_pyfunction!(study_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(dof_names, m)?)?;
    m.add_function(wrap_pyfunction!(body_names, m)?)?;
    m.add_function(wrap_pyfunction!(metric_channels, m)?)?;
    m.add_function(wrap_pyfunction!(wheel_channels, m)?)?;
    m.add_function(wrap_pyfunction!(wheelset_channels, m)?)?;
    m.add_function(wrap_pyfunction!(flange_contact_angle, m)?)?;
    m.add_function(wrap_pyfunction!(body_motion_names, m)?)?;
    m.add_function(wrap_pyfunction!(mode_energies, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(linearise, m)?)?;
    m.add_function(wrap_pyfunction!(linear_critical_speed, m)?)?;
    m.add_function(wrap_pyfunction!(ramp_down, m)?)?;
    Ok(())
}
