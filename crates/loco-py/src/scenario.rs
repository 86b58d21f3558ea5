//! The run scenario as a native object: wheel and rail, speed, distance, track, yaw damper and
//! integration settings, checked once and then shared by `simulate`, `linearise` and `run_batch`.

use crate::contact::PyProfile;
use crate::dampers::PyDamper;
use crate::errors::to_py_err;
use crate::track::PyTrack;
use loco_core::util::toml_fields::read_table;
use loco_core::vehicle::params::presets::SCENARIOS;
use loco_core::vehicle::rail_contact::creep_model::CreepModel;
use loco_core::vehicle::scenarios::scenario::Scenario;
use loco_core::vehicle::scenarios::scenario_settings::CurveSetting;
use loco_core::vehicle::scenarios::scenario_settings::{GivenObjects, ScenarioSettings};
use loco_core::vehicle::time::integrator::Integrator;
use loco_core::LocoError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use std::path::Path;
use std::sync::Arc;

/// A checked run scenario (SI units), from the settings of `loco_core`'s `ScenarioSettings`
/// (the study file's `[scenario]` keys, same names, types and checks: `name`, `wheel`, `rail`,
/// `speed`, `distance`, `lead_in`, `track`, `spectrum`, `seed`, `band`, `yaw_damper`,
/// `fsd_trigger`, `step`, `integrator`, `output_rate`, `fastsim_grid`, `creep`, `initial_lateral_offset`,
/// `gauge`, `gauge_height`, `rail_inclination`, `curve`), every one optional (`scenario_defaults()`), and
/// the objects a caller holds instead of names (wheel and rail profiles, a track, a damper).
#[pyclass(name = "RunScenario", module = "loco._loco", frozen)]
pub struct PyRunScenario {
    pub inner: Scenario,
}

/// A Python setting value as TOML (bool, int, float, str, a list/tuple of them, or a dict of
/// them as a table), so that the settings are read by the same deserialiser as the study file.
fn toml_value(key: &str, value: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    let bad = || {
        to_py_err(LocoError::param(
            key,
            format!(
                "expected a number, a string, a bool, a dict or a list of them, got {}",
                value
                    .get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_default()
            ),
        ))
    };
    if let Ok(b) = value.cast::<PyBool>() {
        return Ok(toml::Value::Boolean(b.is_true()));
    }
    if let Ok(text) = value.cast::<PyString>() {
        return Ok(toml::Value::String(text.to_str()?.to_string()));
    }
    if value.cast::<PyFloat>().is_ok() {
        return Ok(toml::Value::Float(value.extract::<f64>()?));
    }
    if let Ok(i) = value.extract::<i64>() {
        return Ok(toml::Value::Integer(i));
    }
    if value.cast::<PyInt>().is_ok() {
        // Not read as a float: that would be refused as the wrong type, or lose digits.
        return Err(to_py_err(LocoError::param(
            key,
            format!("{value} is outside the 64-bit signed integers of TOML (the study file's)"),
        )));
    }
    if let Ok(x) = value.extract::<f64>() {
        return Ok(toml::Value::Float(x));
    }
    if value.cast::<PyList>().is_ok() || value.cast::<PyTuple>().is_ok() {
        // A list of dicts is a list of sections (`curve`), whose fields the core names as
        // `curve section 2 (radius_m)`; other items are named by the setting.
        let items: PyResult<Vec<toml::Value>> = value
            .try_iter()?
            .enumerate()
            .map(|(i, v)| {
                let v = v?;
                if v.cast::<PyDict>().is_ok() {
                    toml_value(&format!("{key} section {}", i + 1), &v)
                } else {
                    toml_value(key, &v)
                }
            })
            .collect();
        return Ok(toml::Value::Array(items?));
    }
    if let Ok(dict) = value.cast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, v) in dict.iter() {
            let k: String = k.extract()?;
            if !v.is_none() {
                let v = toml_value(&format!("{key} ({k})"), &v)?;
                table.insert(k, v);
            }
        }
        return Ok(toml::Value::Table(table));
    }
    Err(bad())
}

/// The settings of a Python dict, checked as the study file's `[scenario]` section is.
fn settings_of(settings: Option<&Bound<'_, PyDict>>) -> PyResult<ScenarioSettings> {
    let mut table = toml::Table::new();
    if let Some(settings) = settings {
        for (key, value) in settings.iter() {
            let key: String = key.extract()?;
            if !value.is_none() {
                let v = toml_value(&key, &value)?;
                table.insert(key, v);
            }
        }
    }
    // The sections are read one by one, so that an error names the section and its field.
    let curve = table
        .remove("curve")
        .map(CurveSetting::from_toml)
        .transpose()
        .map_err(to_py_err)?;
    let settings: ScenarioSettings =
        read_table(&table, &toml::Table::new(), "scenario", str::to_string).map_err(to_py_err)?;
    Ok(ScenarioSettings { curve, ..settings })
}

#[pymethods]
impl PyRunScenario {
    #[new]
    #[pyo3(signature = (settings=None, *, wheel=None, rail=None, track=None, yaw_damper=None))]
    fn new(
        settings: Option<Bound<'_, PyDict>>,
        wheel: Option<PyRef<'_, PyProfile>>,
        rail: Option<PyRef<'_, PyProfile>>,
        track: Option<PyRef<'_, PyTrack>>,
        yaw_damper: Option<PyRef<'_, PyDamper>>,
    ) -> PyResult<Self> {
        let settings = settings_of(settings.as_ref())?;
        if settings.per_sample_track.is_some() {
            return Err(to_py_err(LocoError::param(
                "per_sample_track",
                "a batch setting: give it to loco.run_batch",
            )));
        }
        let given = GivenObjects {
            wheel: wheel.map(|p| p.inner.clone()),
            rail: rail.map(|p| p.inner.clone()),
            track: track.map(|t| Arc::new(t.inner.clone())),
            yaw_damper: yaw_damper.map(|d| d.inner),
        };
        let inner = settings.resolve(given, Path::new(".")).map_err(to_py_err)?;
        Ok(Self { inner })
    }

    /// Running speed, m/s.
    #[getter]
    fn speed(&self) -> f64 {
        self.inner.speed
    }

    /// Distance run, m.
    #[getter]
    fn distance(&self) -> f64 {
        self.inner.distance
    }

    /// Output sampling rate, Hz.
    #[getter]
    fn output_rate(&self) -> f64 {
        self.inner.run.output_rate
    }

    fn __repr__(&self) -> String {
        format!(
            "RunScenario(wheel='{}', rail='{}', speed={} m/s, distance={} m)",
            self.inner.wheel.name(),
            self.inner.rail.name(),
            self.inner.speed,
            self.inner.distance
        )
    }
}

/// Every scenario setting that has a default, at its default (`ScenarioSettings::defaults`, the
/// only defaults): `{setting: value}` with the study file's names.
#[pyfunction]
fn scenario_defaults(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let table = toml::Table::try_from(ScenarioSettings::defaults())
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    let out = PyDict::new(py);
    for (key, value) in table {
        out.set_item(key, py_value(py, &value)?)?;
    }
    Ok(out)
}

fn py_value<'py>(py: Python<'py>, value: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        toml::Value::Boolean(b) => b.into_pyobject(py)?.to_owned().into_any(),
        toml::Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        toml::Value::Float(x) => x.into_pyobject(py)?.into_any(),
        toml::Value::String(s) => s.into_pyobject(py)?.into_any(),
        toml::Value::Array(items) => {
            let items: PyResult<Vec<Bound<'py, PyAny>>> =
                items.iter().map(|v| py_value(py, v)).collect();
            PyTuple::new(py, items?)?.into_any()
        }
        other => {
            return Err(crate::errors::InternalError::new_err(format!(
                "unexpected default {other}"
            )))
        }
    })
}

/// The study's scenarios as `(name, wheel, rail)` built-in profile names (`presets::SCENARIOS`).
#[pyfunction]
fn scenario_presets() -> Vec<(&'static str, &'static str, &'static str)> {
    SCENARIOS.to_vec()
}

/// The names of the creep models a scenario accepts (`CreepModel::NAMES`).
#[pyfunction]
fn creep_model_names() -> Vec<&'static str> {
    CreepModel::NAMES.to_vec()
}

/// The names of the integration schemes a scenario accepts (`Integrator::NAMES`).
#[pyfunction]
fn integrator_names() -> Vec<&'static str> {
    Integrator::NAMES.to_vec()
}

/// Each integration scheme's default step, s (`Integrator::default_step`): a scenario that
/// names a scheme without a step runs at it.
#[pyfunction]
fn integrator_steps() -> Vec<(&'static str, f64)> {
    Integrator::ALL
        .iter()
        .map(|scheme| (scheme.name(), scheme.default_step()))
        .collect()
}

/// Adds the class and its function to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyRunScenario>()?;
    m.add_function(wrap_pyfunction!(creep_model_names, m)?)?;
    m.add_function(wrap_pyfunction!(integrator_names, m)?)?;
    m.add_function(wrap_pyfunction!(integrator_steps, m)?)?;
    m.add_function(wrap_pyfunction!(scenario_defaults, m)?)?;
    m.add_function(wrap_pyfunction!(scenario_presets, m)?)?;
    Ok(())
}
