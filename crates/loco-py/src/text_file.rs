//! Input files read as UTF-8 text by the core's one rule (`loco_core::util::text_file`), for the files
//! Python reads itself (the vehicle file).

use crate::errors::run_detached;
use loco_core::error::FileKind;
use pyo3::prelude::*;

/// The content of the file at `path` as text, checked to be UTF-8 (a UTF-8 byte-order mark
/// skipped); `kind` (`profile`, `vehicle`, `track`, `study`) chooses the error class of a file
/// that is not UTF-8.
#[pyfunction]
fn read_text_file(py: Python<'_>, path: String, kind: String) -> PyResult<String> {
    run_detached(py, move || {
        let kind = FileKind::from_name(&kind, "kind")?;
        loco_core::util::text_file::read_text(std::path::Path::new(&path), kind)
    })
}

/// Adds the function to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(read_text_file, m)?)
}
