//! Bindings of `loco_core::vehicle::params::input_ranges`: the plausible ranges of a vehicle's inputs
//! (`loco.uncertainty.ranges`).

use crate::errors::to_py_err;
use crate::vehicle_handle::PyVehicle;
use loco_core::vehicle::params::input_ranges::{
    input_ranges as core_ranges, DEFAULT_UNCERTAINTY_TOML,
};
use pyo3::prelude::*;

/// One range: key, nominal, low, high, unit, kind, why, source.
type RangeTuple = (String, f64, f64, f64, String, String, String, String);

/// The embedded ranges file of the default vehicle (TOML text).
#[pyfunction]
fn default_uncertainty_toml() -> &'static str {
    DEFAULT_UNCERTAINTY_TOML
}

/// The ranges of the ranges file `text` (None: the embedded one; `origin` names it in errors)
/// for the built `vehicle` (its values after overrides are the nominal values).
#[pyfunction]
#[pyo3(signature = (vehicle, text=None, origin=None))]
fn input_ranges(
    vehicle: PyRef<'_, PyVehicle>,
    text: Option<&str>,
    origin: Option<&str>,
) -> PyResult<Vec<RangeTuple>> {
    let text = text.unwrap_or(DEFAULT_UNCERTAINTY_TOML);
    let origin = origin.unwrap_or("<embedded default_uncertainty.toml>");
    let ranges = core_ranges(&vehicle.structure.parameters, text, origin).map_err(to_py_err)?;
    Ok(ranges
        .into_iter()
        .map(|r| {
            (
                r.key, r.nominal, r.low, r.high, r.unit, r.kind, r.why, r.source,
            )
        })
        .collect())
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(default_uncertainty_toml, m)?)?;
    m.add_function(wrap_pyfunction!(input_ranges, m)?)?;
    Ok(())
}
