//! The `loco.LocoError` exception hierarchy and the one helper that runs core code without the GIL.
//!
//! Every `loco_core::LocoError` variant maps to exactly one Python class here; the classes also
//! derive from the matching built-in (`ValueError`, `OSError`, `RuntimeError`) so that generic
//! handlers keep working.

use loco_core::LocoError as CoreError;
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyboardInterrupt};
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};

create_exception!(
    _loco,
    LocoError,
    PyException,
    "Base class of every error raised by loco."
);
create_exception!(
    _loco,
    ParameterError,
    LocoError,
    "A parameter or input array is not physical or has the wrong shape; the message names it."
);
create_exception!(
    _loco,
    ProfileFormatError,
    LocoError,
    "A profile, track or study file is malformed; the message names the file and line."
);
create_exception!(
    _loco,
    LocoIOError,
    LocoError,
    "A file could not be read or written."
);
create_exception!(
    _loco,
    ContactError,
    LocoError,
    "The wheel-rail contact search failed."
);
create_exception!(
    _loco,
    SimulationError,
    LocoError,
    "A time integration failed; subclasses say how."
);
create_exception!(
    _loco,
    DivergenceError,
    SimulationError,
    "The integration produced non-finite states or runaway amplitudes."
);
create_exception!(
    _loco,
    DerailmentError,
    SimulationError,
    "A wheel climbed past its flange."
);
create_exception!(
    _loco,
    InternalError,
    LocoError,
    "A bug in loco (a Rust panic caught at the boundary); please report it."
);

/// Converts a core error into the Python exception of its class.
#[allow(dead_code)] // used by the binding files as they land
pub fn to_py_err(err: CoreError) -> PyErr {
    let msg = err.to_string();
    match err {
        CoreError::InvalidParameter { .. } | CoreError::InvalidInput { .. } => {
            ParameterError::new_err(msg)
        }
        CoreError::Parse { .. } => ProfileFormatError::new_err(msg),
        CoreError::Io { .. } => LocoIOError::new_err(msg),
        CoreError::Contact(_) => ContactError::new_err(msg),
        CoreError::Diverged { .. } => DivergenceError::new_err(msg),
        CoreError::Derailed { .. } => DerailmentError::new_err(msg),
        CoreError::Interrupted => PyKeyboardInterrupt::new_err(msg),
    }
}

/// Runs `work` with the GIL released, turns a core error into its Python exception and a panic
/// into `InternalError`, so that no Rust panic ever unwinds into Python.
///
/// Inputs must already be copied into owned Rust values (the closure cannot touch Python objects).
#[allow(dead_code)] // used by the binding files as they land
pub fn run_detached<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce() -> Result<T, CoreError> + Send,
{
    let outcome = py.detach(move || catch_unwind(AssertUnwindSafe(work)));
    match outcome {
        Ok(result) => result.map_err(to_py_err),
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            Err(InternalError::new_err(format!(
                "internal error (Rust panic): {what}"
            )))
        }
    }
}

/// Adds the exception classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("LocoError", py.get_type::<LocoError>())?;
    m.add("ParameterError", py.get_type::<ParameterError>())?;
    m.add("ProfileFormatError", py.get_type::<ProfileFormatError>())?;
    m.add("LocoIOError", py.get_type::<LocoIOError>())?;
    m.add("ContactError", py.get_type::<ContactError>())?;
    m.add("SimulationError", py.get_type::<SimulationError>())?;
    m.add("DivergenceError", py.get_type::<DivergenceError>())?;
    m.add("DerailmentError", py.get_type::<DerailmentError>())?;
    m.add("InternalError", py.get_type::<InternalError>())?;
    Ok(())
}
