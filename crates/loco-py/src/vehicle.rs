//! Bindings of `loco_core::vehicle`: the parameter file, names of bodies and coordinates.

use crate::contact::PyProfile;
use crate::dampers::PyDamper;
use crate::errors::run_detached;
use crate::track::PyTrack;
use loco_core::contact::fastsim::FastsimParams;
use loco_core::contact::setup::TrackSetup;
use loco_core::metrics::RunMetrics;
use loco_core::track::{SynthesisParams, TrackSpectrum};
use loco_core::vehicle::layout::{body_names as core_body_names, dof_names as core_dof_names};
use loco_core::vehicle::parameters::{ParameterSet, DEFAULT_VEHICLE_TOML, STUDY_PARAMETERS};
use loco_core::vehicle::run::RunSettings;
use loco_core::vehicle::scenario::{linearised, simulate as core_simulate, Scenario, TrackSpec};
use loco_core::vehicle::structure::VehicleStructure;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;
use std::collections::BTreeMap;
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

/// What `simulate` returns: time (s), channel names, channels (n_channels × n_samples, SI),
/// metric names and values.
type SimulationTuple<'py> = (
    Bound<'py, PyArray1<f64>>,
    Vec<String>,
    Bound<'py, PyArray2<f64>>,
    Vec<&'static str>,
    Bound<'py, PyArray1<f64>>,
);

/// Simulates one run of the locomotive (see `loco.simulate`). The track is `track` when given,
/// perfect when `track_kind == "perfect"`, else synthesised from `spectrum`, `seed` and `band`.
#[pyfunction]
#[pyo3(signature = (
    wheel, rail, speed, distance, *, toml_text=None, origin="<vehicle>".to_string(),
    overrides=BTreeMap::new(), track=None, track_kind="synthetic".to_string(),
    spectrum="cn-hsr".to_string(), seed=0, band=(2.0, 200.0), yaw_damper=None, step=1e-3,
    output_rate=500.0, fastsim_grid=(10, 10), initial_lateral_offset=0.0,
    gauge=1.435, gauge_height=0.016, rail_inclination=None
))]
#[allow(clippy::too_many_arguments)]
fn simulate<'py>(
    py: Python<'py>,
    wheel: PyRef<'py, PyProfile>,
    rail: PyRef<'py, PyProfile>,
    speed: f64,
    distance: f64,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
    track: Option<PyRef<'py, PyTrack>>,
    track_kind: String,
    spectrum: String,
    seed: u64,
    band: (f64, f64),
    yaw_damper: Option<PyRef<'py, PyDamper>>,
    step: f64,
    output_rate: f64,
    fastsim_grid: (usize, usize),
    initial_lateral_offset: f64,
    gauge: f64,
    gauge_height: f64,
    rail_inclination: Option<f64>,
) -> PyResult<SimulationTuple<'py>> {
    let wheel = wheel.inner.clone();
    let rail = rail.inner.clone();
    let given = track.map(|t| Arc::new(t.inner.clone()));
    let yaw_damper = yaw_damper.map(|d| d.inner);
    let result = run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        let track = match (given, track_kind.as_str()) {
            (Some(t), _) => TrackSpec::Given(t),
            (None, "perfect") => TrackSpec::Perfect,
            (None, "synthetic") => TrackSpec::Synthetic(SynthesisParams {
                spectrum: TrackSpectrum::from_name(&spectrum)?,
                seed,
                wavelength_min: band.0,
                wavelength_max: band.1,
                ..SynthesisParams::default()
            }),
            (None, other) => {
                return Err(loco_core::LocoError::param(
                    "track_kind",
                    format!("expected 'synthetic' or 'perfect', got '{other}'"),
                ))
            }
        };
        let scenario = Scenario {
            wheel,
            rail,
            track_setup: TrackSetup {
                gauge,
                gauge_height,
                rail_inclination: rail_inclination
                    .unwrap_or(TrackSetup::default().rail_inclination),
            },
            speed,
            distance,
            track,
            yaw_damper,
            run: RunSettings {
                step,
                output_rate,
                ..RunSettings::default()
            },
            fastsim: FastsimParams {
                nx: fastsim_grid.0,
                ny: fastsim_grid.1,
                ..FastsimParams::default()
            },
            initial_lateral_offset,
        };
        core_simulate(set, &scenario)
    })?;
    let output = result.output;
    let n = output.time.len();
    let names = output.names;
    let flat: Vec<f64> = output.channels.into_iter().flatten().collect();
    let channels = numpy::ndarray::Array2::from_shape_vec((names.len(), n), flat)
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok((
        output.time.into_pyarray(py),
        names,
        channels.into_pyarray(py),
        RunMetrics::names().to_vec(),
        result.metrics.values().into_pyarray(py),
    ))
}

/// The state matrix of the vehicle linearised about its static equilibrium at `speed` (m/s) on
/// perfect track (see `loco.eigen`): a square numpy array over (coordinates, velocities, damper
/// internal states).
#[pyfunction]
#[pyo3(signature = (
    wheel, rail, speed, *, toml_text=None, origin="<vehicle>".to_string(),
    overrides=BTreeMap::new(), yaw_damper=None, fastsim_grid=(10, 10)
))]
#[allow(clippy::too_many_arguments)]
fn linearise<'py>(
    py: Python<'py>,
    wheel: PyRef<'py, PyProfile>,
    rail: PyRef<'py, PyProfile>,
    speed: f64,
    toml_text: Option<String>,
    origin: String,
    overrides: BTreeMap<String, f64>,
    yaw_damper: Option<PyRef<'py, PyDamper>>,
    fastsim_grid: (usize, usize),
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let wheel = wheel.inner.clone();
    let rail = rail.inner.clone();
    let yaw_damper = yaw_damper.map(|d| d.inner);
    let (a, n) = run_detached(py, move || {
        let set = parameter_set(toml_text.as_deref(), &origin, &overrides)?;
        let scenario = Scenario {
            wheel,
            rail,
            track_setup: TrackSetup::default(),
            speed,
            distance: 1.0,
            track: TrackSpec::Perfect,
            yaw_damper,
            run: RunSettings::default(),
            fastsim: FastsimParams {
                nx: fastsim_grid.0,
                ny: fastsim_grid.1,
                ..FastsimParams::default()
            },
            initial_lateral_offset: 0.0,
        };
        linearised(set, &scenario)
    })?;
    let matrix = numpy::ndarray::Array2::from_shape_vec((n, n), a)
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok(matrix.into_pyarray(py))
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(default_vehicle_toml, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_total_mass, m)?)?;
    m.add_function(wrap_pyfunction!(study_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(dof_names, m)?)?;
    m.add_function(wrap_pyfunction!(body_names, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(linearise, m)?)?;
    Ok(())
}
