//! Bindings of `loco_core::metrics`: PSD, dominant frequency, Sperling, bogie stability,
//! comfort, the metrics row of a run.

use crate::errors::run_detached;
use loco_core::metrics::{
    bogie_stability as core_bogie_stability, comfort_nmv as core_comfort_nmv,
    dominant_frequency as core_dominant_frequency, sperling as core_sperling,
    weighted_rms as core_weighted_rms, welch_psd as core_welch_psd, ComfortWeighting, Direction,
    RideRating, RunMetrics, RunMetricsParams, RunRecords, SperlingParams, StabilityParams,
    WelchParams,
};
use loco_core::LocoError;
use numpy::{IntoPyArray, PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A pair of numpy arrays (frequencies, values).
type ArrayPair<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

/// Copies a numpy array into an owned vector (any strides).
fn owned(x: &PyReadonlyArray1<'_, f64>) -> Vec<f64> {
    x.as_array().iter().copied().collect()
}

/// Welch PSD: (frequencies Hz, density unit²/Hz).
#[pyfunction]
#[pyo3(signature = (x, fs, segment_len=None, overlap=0.5))]
fn welch_psd<'py>(
    py: Python<'py>,
    x: PyReadonlyArray1<'py, f64>,
    fs: f64,
    segment_len: Option<usize>,
    overlap: f64,
) -> PyResult<ArrayPair<'py>> {
    let x = owned(&x);
    let psd = run_detached(py, move || {
        core_welch_psd(
            &x,
            fs,
            &WelchParams {
                segment_len,
                overlap,
            },
        )
    })?;
    Ok((psd.frequency.into_pyarray(py), psd.density.into_pyarray(py)))
}

/// Dominant frequency (Hz) in [f_min, f_max] and the Welch PSD there.
#[pyfunction]
#[pyo3(signature = (x, fs, f_min, f_max, segment_len=None, overlap=0.5))]
fn dominant_frequency(
    py: Python<'_>,
    x: PyReadonlyArray1<'_, f64>,
    fs: f64,
    f_min: f64,
    f_max: f64,
    segment_len: Option<usize>,
    overlap: f64,
) -> PyResult<(f64, f64)> {
    let x = owned(&x);
    let d = run_detached(py, move || {
        core_dominant_frequency(
            &x,
            fs,
            f_min,
            f_max,
            &WelchParams {
                segment_len,
                overlap,
            },
        )
    })?;
    Ok((d.frequency, d.peak_density))
}

/// Sperling index: (segment values, mean, max).
#[pyfunction]
#[pyo3(signature = (acc, fs, direction, segment_duration=5.0, f_min=0.5, f_max=40.0))]
fn sperling<'py>(
    py: Python<'py>,
    acc: PyReadonlyArray1<'py, f64>,
    fs: f64,
    direction: &str,
    segment_duration: f64,
    f_min: f64,
    f_max: f64,
) -> PyResult<(Bound<'py, PyArray1<f64>>, f64, f64)> {
    let acc = owned(&acc);
    let direction = direction.to_string();
    let w = run_detached(py, move || {
        let params = SperlingParams {
            segment_duration,
            f_min,
            f_max,
        };
        core_sperling(&acc, fs, Direction::from_name(&direction)?, &params)
    })?;
    Ok((w.segments.into_pyarray(py), w.mean, w.max))
}

/// Ride quality grade of a locomotive by its Sperling index.
#[pyfunction]
fn locomotive_ride_rating(w: f64) -> &'static str {
    RideRating::locomotive(w).name()
}

/// Bogie frame stability statistics as a dict of named values.
#[pyfunction]
fn bogie_stability<'py>(
    py: Python<'py>,
    acc: PyReadonlyArray1<'py, f64>,
    fs: f64,
    speed: f64,
    bogie_mass: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let acc = owned(&acc);
    let s = run_detached(py, move || {
        core_bogie_stability(&acc, fs, speed, bogie_mass, &StabilityParams::default())
    })?;
    let d = PyDict::new(py);
    d.set_item("peak_lowpassed", s.peak_lowpassed)?;
    d.set_item("rms_lowpassed", s.rms_lowpassed)?;
    d.set_item("max_consecutive_cycles", s.max_consecutive_cycles)?;
    d.set_item("gbt_unstable", s.gbt_unstable)?;
    d.set_item("f0", s.f0)?;
    d.set_item("f0_psd_peak", s.f0_psd_peak)?;
    d.set_item("sliding_rms_max", s.sliding_rms_max)?;
    d.set_item("limit", s.limit)?;
    d.set_item("en_unstable", s.en_unstable)?;
    d.set_item("window_m", s.window_m)?;
    Ok(d)
}

/// Weighted rms (`wd` or `wb`): (5 s block values, rms, 95th percentile), m/s².
#[pyfunction]
fn weighted_rms<'py>(
    py: Python<'py>,
    acc: PyReadonlyArray1<'py, f64>,
    fs: f64,
    weighting: &str,
) -> PyResult<(Bound<'py, PyArray1<f64>>, f64, f64)> {
    let acc = owned(&acc);
    let weighting = weighting.to_string();
    let r = run_detached(py, move || {
        let w = match weighting.as_str() {
            "wd" => ComfortWeighting::Wd,
            "wb" => ComfortWeighting::Wb,
            other => {
                return Err(LocoError::param(
                    "weighting",
                    format!("must be `wd` or `wb`, got `{other}`"),
                ))
            }
        };
        core_weighted_rms(&acc, fs, w)
    })?;
    Ok((r.blocks.into_pyarray(py), r.rms, r.p95))
}

/// EN 12299 N_MV of floor accelerations (m/s²); absent directions count as zero.
#[pyfunction]
#[pyo3(signature = (fs, ax=None, ay=None, az=None))]
fn comfort_nmv(
    py: Python<'_>,
    fs: f64,
    ax: Option<PyReadonlyArray1<'_, f64>>,
    ay: Option<PyReadonlyArray1<'_, f64>>,
    az: Option<PyReadonlyArray1<'_, f64>>,
) -> PyResult<f64> {
    let (ax, ay, az) = (
        ax.map(|a| owned(&a)),
        ay.map(|a| owned(&a)),
        az.map(|a| owned(&a)),
    );
    run_detached(py, move || {
        core_comfort_nmv(ax.as_deref(), ay.as_deref(), az.as_deref(), fs)
    })
}

/// Names of the values `run_metrics` returns, in order.
#[pyfunction]
fn run_metric_names() -> Vec<&'static str> {
    RunMetrics::names().to_vec()
}

/// Every metric of one run, in the order of `run_metric_names()`.
#[pyfunction]
#[pyo3(signature = (fs, speed, carbody_lateral, bogie_lateral, bogie_mass, carbody_vertical=None))]
fn run_metrics<'py>(
    py: Python<'py>,
    fs: f64,
    speed: f64,
    carbody_lateral: PyReadonlyArray1<'py, f64>,
    bogie_lateral: PyReadonlyArray1<'py, f64>,
    bogie_mass: f64,
    carbody_vertical: Option<PyReadonlyArray1<'py, f64>>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let ayc = owned(&carbody_lateral);
    let ayb = owned(&bogie_lateral);
    let azc = carbody_vertical.map(|a| owned(&a));
    let values = run_detached(py, move || {
        let records = RunRecords {
            fs,
            speed,
            carbody_lateral: &ayc,
            carbody_vertical: azc.as_deref(),
            bogie_lateral: &ayb,
            bogie_mass,
        };
        RunMetrics::compute(&records, &RunMetricsParams::default()).map(|m| m.values())
    })?;
    Ok(values.into_pyarray(py))
}

/// Adds this file's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(welch_psd, m)?)?;
    m.add_function(wrap_pyfunction!(dominant_frequency, m)?)?;
    m.add_function(wrap_pyfunction!(sperling, m)?)?;
    m.add_function(wrap_pyfunction!(locomotive_ride_rating, m)?)?;
    m.add_function(wrap_pyfunction!(bogie_stability, m)?)?;
    m.add_function(wrap_pyfunction!(weighted_rms, m)?)?;
    m.add_function(wrap_pyfunction!(comfort_nmv, m)?)?;
    m.add_function(wrap_pyfunction!(run_metric_names, m)?)?;
    m.add_function(wrap_pyfunction!(run_metrics, m)?)?;
    Ok(())
}
