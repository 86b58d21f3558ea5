//! Bindings of `loco_core::vehicle::params::presets`' yaw dampers: the presets by name and the
//! dampers the studies compare (`loco.dampers.PRESETS`, `COMPARED`).

use crate::dampers::PyDamper;
use loco_core::vehicle::params::presets;
use pyo3::prelude::*;

/// A yaw damper preset by name (`presets::DAMPER_PRESETS`: "YD1", "YD2", "FSD"), the FSD with
/// its `trigger` (`"rms-frequency"`, the default, or `"hydraulic"`).
#[pyfunction]
#[pyo3(signature = (name, trigger=None))]
fn damper_preset(name: &str, trigger: Option<&str>) -> PyResult<PyDamper> {
    let inner = presets::damper_preset(name, trigger).map_err(crate::errors::to_py_err)?;
    Ok(PyDamper { inner })
}

/// The names of the yaw damper presets, in the order the studies compare them.
#[pyfunction]
fn damper_preset_names() -> Vec<&'static str> {
    presets::DAMPER_PRESETS.to_vec()
}

/// The yaw dampers the studies compare by label (the presets and `FSD-H`, the FSD with the
/// hydraulic valve), in order.
#[pyfunction]
fn compared_dampers() -> Vec<(&'static str, PyDamper)> {
    presets::compared_dampers()
        .into_iter()
        .map(|(label, inner)| (label, PyDamper { inner }))
        .collect()
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(damper_preset, m)?)?;
    m.add_function(wrap_pyfunction!(damper_preset_names, m)?)?;
    m.add_function(wrap_pyfunction!(compared_dampers, m)?)?;
    Ok(())
}
