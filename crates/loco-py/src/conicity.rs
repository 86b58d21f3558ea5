//! Bindings of `loco_core::contact::{conicity, conicity_harmonic}`: equivalent conicity of a
//! sampled rolling radius difference Δr(y).

use crate::errors::run_detached;
use loco_core::contact::conicity::{conicity_curve, kinematic_oscillation};
use loco_core::contact::conicity_harmonic::conicity_curve_harmonic;
use loco_core::contact::delta_r::DeltaR;
use loco_core::LocoError as CoreError;
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArrayLike1};
use pyo3::prelude::*;

/// Copies a 1-D array-like of floats (any strides).
fn to_vec(values: &PyArrayLike1<'_, f64, AllowTypeChange>) -> PyResult<Vec<f64>> {
    Ok(values.as_array().iter().copied().collect())
}

/// Equivalent conicity (-) at each amplitude in `amplitudes` (m) of the Δr(y) sampled as `dr`
/// (m) at the strictly increasing `y` (m); `method` is 'nonlinear' (EN 15302 kinematic) or
/// 'harmonic' (first-harmonic linearisation).
#[pyfunction]
#[pyo3(signature = (y, dr, amplitudes, method = "nonlinear"))]
fn conicity_from_delta_r<'py>(
    py: Python<'py>,
    y: PyArrayLike1<'_, f64, AllowTypeChange>,
    dr: PyArrayLike1<'_, f64, AllowTypeChange>,
    amplitudes: PyArrayLike1<'_, f64, AllowTypeChange>,
    method: &str,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (y, dr, amplitudes) = (to_vec(&y)?, to_vec(&dr)?, to_vec(&amplitudes)?);
    let method = method.to_string();
    let values = run_detached(py, move || {
        let f = DeltaR::new(y, dr)?;
        match method.as_str() {
            "nonlinear" => conicity_curve(&f, &amplitudes),
            "harmonic" => conicity_curve_harmonic(&f, &amplitudes),
            other => Err(CoreError::param(
                "method",
                format!("'{other}' is not 'nonlinear' or 'harmonic'"),
            )),
        }
    })?;
    Ok(values.into_pyarray(py))
}

/// The kinematic oscillation at `amplitude` (m): (tan γe, y_min, y_max), the turning points in
/// m, by the nonlinear method of EN 15302.
#[pyfunction]
fn kinematic_swing(
    py: Python<'_>,
    y: PyArrayLike1<'_, f64, AllowTypeChange>,
    dr: PyArrayLike1<'_, f64, AllowTypeChange>,
    amplitude: f64,
) -> PyResult<(f64, f64, f64)> {
    let (y, dr) = (to_vec(&y)?, to_vec(&dr)?);
    run_detached(py, move || {
        let osc = kinematic_oscillation(&DeltaR::new(y, dr)?, amplitude)?;
        Ok((osc.tan_gamma_e, osc.y_min, osc.y_max))
    })
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(conicity_from_delta_r, m)?)?;
    m.add_function(wrap_pyfunction!(kinematic_swing, m)?)?;
    Ok(())
}
