//! Bindings of `loco_core::vehicle`: the parameter file, names of bodies and coordinates.

use crate::errors::run_detached;
use loco_core::vehicle::layout::{body_names as core_body_names, dof_names as core_dof_names};
use loco_core::vehicle::parameters::{ParameterSet, DEFAULT_VEHICLE_TOML, STUDY_PARAMETERS};
use loco_core::vehicle::structure::VehicleStructure;
use pyo3::prelude::*;
use std::collections::BTreeMap;

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

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(default_vehicle_toml, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_total_mass, m)?)?;
    m.add_function(wrap_pyfunction!(study_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(dof_names, m)?)?;
    m.add_function(wrap_pyfunction!(body_names, m)?)?;
    Ok(())
}
