//! Bindings of `loco_core::vehicle::params::parameter_schema`: the vehicle's parameter schema as rows.

use loco_core::vehicle::params::parameter_schema::{schema, RETIRED};
use pyo3::prelude::*;

/// One schema row: key, SI unit, kind, min, max, affects, description, why, optional.
type SchemaRow = (
    &'static str,
    &'static str,
    &'static str,
    f64,
    f64,
    Vec<&'static str>,
    &'static str,
    &'static str,
    bool,
);

/// Every vehicle parameter of the schema, in key order.
#[pyfunction]
fn parameter_schema() -> Vec<SchemaRow> {
    schema()
        .iter()
        .map(|s| {
            (
                s.key.as_str(),
                s.unit.as_str(),
                s.kind.name(),
                s.min,
                s.max,
                s.affects.iter().map(|a| a.name()).collect(),
                s.description.as_str(),
                s.why.as_str(),
                s.optional,
            )
        })
        .collect()
}

/// Keys that are not vehicle parameters (any more), with the reason.
#[pyfunction]
fn retired_parameters() -> Vec<(&'static str, &'static str)> {
    RETIRED.to_vec()
}

/// Adds the functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(parameter_schema, m)?)?;
    m.add_function(wrap_pyfunction!(retired_parameters, m)?)?;
    Ok(())
}
