//! Bindings of `loco_core::dampers`.

use pyo3::prelude::*;

/// Adds this file's functions and classes to the module.
pub fn register(_m: &Bound<'_, PyModule>) -> PyResult<()> {
    Ok(())
}
