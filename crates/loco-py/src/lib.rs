//! `loco._loco`: the private native module of the `loco` Python package.
//!
//! Bindings only: each file converts and checks Python inputs into owned Rust values, calls
//! `loco-core` through [`errors::run_detached`] (GIL released, errors mapped, panics caught) and
//! returns numpy arrays by moving their buffers. No physics lives here.

mod batch;
mod conicity;
mod contact;
mod creep;
mod damper_bench;
mod damper_presets;
mod dampers;
mod errors;
mod frequency_response;
mod input_ranges;
mod metrics;
mod mode_rules;
mod names;
mod scenario;
mod schema;
mod text_file;
mod track;
mod vehicle;
mod vehicle_handle;
mod wheelset_contact;

use pyo3::prelude::*;

/// The native module. The public API is the `loco` package that wraps it.
#[pymodule]
fn _loco(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    errors::register(m)?;
    contact::register(m)?;
    wheelset_contact::register(m)?;
    conicity::register(m)?;
    creep::register(m)?;
    track::register(m)?;
    metrics::register(m)?;
    names::register(m)?;
    dampers::register(m)?;
    damper_presets::register(m)?;
    damper_bench::register(m)?;
    scenario::register(m)?;
    vehicle_handle::register(m)?;
    vehicle::register(m)?;
    mode_rules::register(m)?;
    input_ranges::register(m)?;
    schema::register(m)?;
    frequency_response::register(m)?;
    batch::register(m)?;
    text_file::register(m)?;
    Ok(())
}
