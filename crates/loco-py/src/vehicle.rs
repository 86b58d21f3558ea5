//! Bindings of `loco_core::vehicle`: the parameter file, names of bodies and coordinates, runs,
//! the bodies' motion maps and masses, the linearisation and the nonlinear critical speed.

use crate::errors::{run_detached, run_detached_monitored};
use crate::scenario::PyRunScenario;
use loco_core::metrics::RunMetrics;
use loco_core::vehicle::critical_speed::{nonlinear_critical_speed, RampOutcome, RampSettings};
use loco_core::vehicle::layout::N_DOF;
use loco_core::vehicle::layout::{body_names as core_body_names, dof_names as core_dof_names};
use loco_core::vehicle::parameters::{ParameterSet, DEFAULT_VEHICLE_TOML, STUDY_PARAMETERS};
use loco_core::vehicle::run::RunOutput;
use loco_core::vehicle::scenario::{linearised, simulate as core_simulate};
use loco_core::vehicle::structure::VehicleStructure;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3};
use pyo3::prelude::*;
use std::collections::BTreeMap;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// Parameters of a vehicle file (or the embedded default when `toml_text` is None) with the
/// overrides applied, each checked by building the vehicle.
pub fn parameter_set(
    toml_text: Option<&str>,
    origin: &str,
    overrides: &BTreeMap<String, f64>,
) -> loco_core::Result<ParameterSet> {
    let mut set = match toml_text {
        Some(text) => ParameterSet::from_toml_str(text, origin)?,
        None => ParameterSet::default_vehicle(),
    };
    for (name, value) in overrides {
        set.set(name, *value)?;
    }
    Ok(set)
}

/// The embedded default vehicle file (TOML text).
#[pyfunction]
fn default_vehicle_toml() -> &'static str {
    DEFAULT_VEHICLE_TOML
}

/// Parameters as `(key, value, unit, source)` rows after applying `overrides`; the vehicle is
/// built to check that the set is physical (errors name the parameter).
#[pyfunction]
#[pyo3(signature = (toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new()))]
fn vehicle_parameters(
    py: Python<'_>,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
) -> PyResult<Vec<(String, f64, String, String)>> {
    run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        VehicleStructure::new(set.clone())?;
        Ok(set
            .iter()
            .map(|(k, p)| (k.to_string(), p.value, p.unit.clone(), p.source.clone()))
            .collect())
    })
}

/// Total mass of the 25 bodies, kg.
#[pyfunction]
#[pyo3(signature = (toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new()))]
fn vehicle_total_mass(
    py: Python<'_>,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
) -> PyResult<f64> {
    run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        Ok(VehicleStructure::new(set)?.total_mass())
    })
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

/// Names of the 25 bodies.
#[pyfunction]
fn body_names() -> Vec<String> {
    core_body_names()
}

/// What `body_mass_maps` returns: body names, motion maps (n_bodies × 6 × 90) and mass
/// diagonals (n_bodies × 6).
type BodyMapsTuple<'py> = (
    Vec<String>,
    Bound<'py, PyArray3<f64>>,
    Bound<'py, PyArray2<f64>>,
);

/// Each body's absolute motion as a map of the 90 coordinates, `u = T q` with u = (x, y, z in m,
/// roll, pitch, yaw in rad) of its centre of gravity, and its mass diagonal (m, m, m in kg,
/// Ixx, Iyy, Izz in kg·m², principal axes along the vehicle's). The model's mass matrix is
/// `Σ Tᵀ diag(mass) T`; `loco.eigen` weighs modes with it (kinetic energy of each body).
#[pyfunction]
#[pyo3(signature = (toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new()))]
fn body_mass_maps<'py>(
    py: Python<'py>,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
) -> PyResult<BodyMapsTuple<'py>> {
    let structure = run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        VehicleStructure::new(set)
    })?;
    let n = structure.bodies.len();
    let mut maps = Array3::<f64>::zeros((n, 6, N_DOF));
    let mut masses = Array2::<f64>::zeros((n, 6));
    let mut names = Vec::with_capacity(n);
    for (b, body) in structure.bodies.iter().enumerate() {
        names.push(body.name.clone());
        for (k, row) in body.map.rows.iter().enumerate() {
            for &(j, c) in row {
                maps[[b, k, j]] = c;
            }
        }
        let [ixx, iyy, izz] = body.inertia;
        for (k, m) in [body.mass, body.mass, body.mass, ixx, iyy, izz]
            .into_iter()
            .enumerate()
        {
            masses[[b, k]] = m;
        }
    }
    Ok((names, maps.into_pyarray(py), masses.into_pyarray(py)))
}

/// What `simulate` returns: time (s), channel names, channels (n_channels × n_samples, SI),
/// metric names and values.
type SimulationTuple<'py> = (
    Bound<'py, PyArray1<f64>>,
    Vec<String>,
    Bound<'py, PyArray2<f64>>,
    Vec<&'static str>,
    Bound<'py, PyArray1<f64>>,
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
#[pyo3(signature = (
    scenario, *, toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new()
))]
fn simulate<'py>(
    py: Python<'py>,
    scenario: PyRef<'py, PyRunScenario>,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
) -> PyResult<SimulationTuple<'py>> {
    let scenario = scenario.inner.clone();
    let result = run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        core_simulate(set, &scenario)
    })?;
    let (time, names, channels) = channels_array(py, result.output)?;
    Ok((
        time,
        names,
        channels,
        RunMetrics::names().to_vec(),
        result.metrics.values().into_pyarray(py),
    ))
}

/// The state matrix of the vehicle linearised about its static equilibrium at the scenario's
/// speed (m/s) on perfect track (see `loco.eigen`): a square numpy array over (coordinates,
/// velocities, damper internal states).
#[pyfunction]
#[pyo3(signature = (
    scenario, *, toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new()
))]
fn linearise<'py>(
    py: Python<'py>,
    scenario: PyRef<'py, PyRunScenario>,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let scenario = scenario.inner.clone();
    let (a, n) = run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        linearised(set, &scenario)
    })?;
    let matrix = numpy::ndarray::Array2::from_shape_vec((n, n), a)
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok(matrix.into_pyarray(py))
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
/// `loco.critical_speed(..., method="nonlinear")`); Ctrl-C stops it.
#[pyfunction]
#[pyo3(signature = (
    scenario, *, toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new(),
    end_speed=20.0, deceleration=0.5, hold=3.0, max_hold=30.0, disturbance=8e-3, window=1.0,
    threshold=5e-4
))]
#[allow(clippy::too_many_arguments)]
fn ramp_down<'py>(
    py: Python<'py>,
    scenario: PyRef<'py, PyRunScenario>,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
    end_speed: f64,
    deceleration: f64,
    hold: f64,
    max_hold: f64,
    disturbance: f64,
    window: f64,
    threshold: f64,
) -> PyResult<RampTuple<'py>> {
    let scenario = scenario.inner.clone();
    let settings = RampSettings {
        end_speed,
        deceleration,
        hold,
        max_hold,
        disturbance,
        window,
        threshold,
    };
    let cancel = Arc::new(AtomicBool::new(false));
    let worker_cancel = Arc::clone(&cancel);
    let work = move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        nonlinear_critical_speed(set, &scenario, &settings, Some(&worker_cancel))
    };
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
    m.add_function(wrap_pyfunction!(vehicle_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_total_mass, m)?)?;
    m.add_function(wrap_pyfunction!(study_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(dof_names, m)?)?;
    m.add_function(wrap_pyfunction!(body_names, m)?)?;
    m.add_function(wrap_pyfunction!(body_mass_maps, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(linearise, m)?)?;
    m.add_function(wrap_pyfunction!(ramp_down, m)?)?;
    Ok(())
}
