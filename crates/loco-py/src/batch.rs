//! Binding of `loco_core::batch`: `run_batch` with the GIL released, progress and Ctrl-C.

use crate::errors::{run_detached_monitored, InternalError};
use crate::scenario::PyRunScenario;
use crate::vehicle::channels_array;
use crate::vehicle_handle::PyVehicle;
use loco_core::batch::{run_batch as core_run_batch, run_study, BatchMonitor, BatchSpec};
use loco_core::vehicle::system::run_statistics::RunStatistics;
use loco_core::LocoError;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use std::path::PathBuf;
use std::sync::atomic::Ordering;
use std::sync::Arc;

/// Time histories of one kept sample: index, time (s), channel names, channels.
type History<'py> = (
    usize,
    Bound<'py, PyArray1<f64>>,
    Vec<String>,
    Bound<'py, PyArray2<f64>>,
);

/// What `run_batch` returns: metric names, metrics (n × m), status codes (n), messages (n),
/// the kept time histories and the run statistics (n × 4, columns `run_statistics_names()`).
type BatchTuple<'py> = (
    Vec<&'static str>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i32>>,
    Vec<String>,
    Vec<History<'py>>,
    Bound<'py, PyArray2<f64>>,
);

/// Runs one simulation of `vehicle` per row of `params` (n × k, SI; columns `names`) on `threads` threads
/// (0: one per core), see `loco.run_batch`. `progress(done, failed)` is called about every
/// 100 ms while the batch runs; Ctrl-C (or an exception from `progress`) cancels it.
#[pyfunction]
#[pyo3(signature = (
    vehicle, scenario, params, names, *, threads=0, per_sample_track=false, track_streams=None,
    histories=Vec::new(), progress=None
))]
#[allow(clippy::too_many_arguments)]
fn run_batch<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    scenario: PyRef<'py, PyRunScenario>,
    params: PyReadonlyArray2<'py, f64>,
    names: Vec<String>,
    threads: usize,
    per_sample_track: bool,
    track_streams: Option<Vec<u64>>,
    histories: Vec<usize>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<BatchTuple<'py>> {
    let columns = params.as_array().ncols();
    if columns != names.len() {
        return Err(crate::errors::to_py_err(LocoError::input(
            "params",
            format!(
                "has {} columns but {} names were given",
                columns,
                names.len()
            ),
        )));
    }
    // Logical (row-major) order whatever the array's memory layout.
    let values: Vec<f64> = params.as_array().iter().copied().collect();
    let scenario = scenario.inner.clone();
    let base = vehicle.parameters().clone();
    let monitor = Arc::new(BatchMonitor::default());
    let worker_monitor = Arc::clone(&monitor);
    let work = move || {
        let spec = BatchSpec {
            base,
            scenario,
            names,
            values,
            per_sample_track,
            track_streams,
            histories,
        };
        core_run_batch(&spec, threads, &worker_monitor)
    };
    let poll = |_py: Python<'_>| -> PyResult<()> {
        if let Some(callback) = &progress {
            callback.call1((
                monitor.done.load(Ordering::Relaxed),
                monitor.failed.load(Ordering::Relaxed),
            ))?;
        }
        Ok(())
    };
    let output = run_detached_monitored(py, work, &monitor.cancel, poll)?;
    let n = output.n_samples;
    let m = output.metric_names.len();
    let metrics = numpy::ndarray::Array2::from_shape_vec((n, m), output.metrics)
        .map_err(|e| InternalError::new_err(e.to_string()))?;
    let status: Vec<i32> = output.status.iter().map(|s| s.code()).collect();
    let columns = RunStatistics::NAMES.len();
    let statistics: Vec<f64> = output.statistics.iter().flat_map(|s| s.values()).collect();
    let statistics = numpy::ndarray::Array2::from_shape_vec((n, columns), statistics)
        .map_err(|e| InternalError::new_err(e.to_string()))?;
    let mut kept = Vec::with_capacity(output.histories.len());
    for (i, run) in output.histories {
        let (time, channel_names, channels) = channels_array(py, run)?;
        kept.push((i, time, channel_names, channels));
    }
    Ok((
        output.metric_names,
        metrics.into_pyarray(py),
        status.into_pyarray(py),
        output.messages,
        kept,
        statistics.into_pyarray(py),
    ))
}

/// What `run_study_file` returns: samples run, (status name, count) of the statuses that
/// occurred, the metrics CSV and the time-history CSVs written.
type StudyTuple = (usize, Vec<(&'static str, usize)>, PathBuf, Vec<PathBuf>);

/// Runs a study file over a samples CSV and writes the metrics CSV `output` (and the kept time
/// histories beside it), as `loco-batch` does; see `loco batch`. `progress(done, failed, total)`
/// is called about every 100 ms (`total` is 0 until the inputs are read and checked); Ctrl-C
/// (or an exception from `progress`) cancels the batch.
#[pyfunction]
#[pyo3(signature = (study, samples, output, *, threads=0, progress=None))]
fn run_study_file(
    py: Python<'_>,
    study: PathBuf,
    samples: PathBuf,
    output: PathBuf,
    threads: usize,
    progress: Option<Bound<'_, PyAny>>,
) -> PyResult<StudyTuple> {
    let monitor = Arc::new(BatchMonitor::default());
    let worker_monitor = Arc::clone(&monitor);
    let work = move || run_study(&study, &samples, &output, threads, &worker_monitor);
    let poll = |_py: Python<'_>| -> PyResult<()> {
        if let Some(callback) = &progress {
            callback.call1((
                monitor.done.load(Ordering::Relaxed),
                monitor.failed.load(Ordering::Relaxed),
                monitor.total.load(Ordering::Relaxed),
            ))?;
        }
        Ok(())
    };
    let summary = run_detached_monitored(py, work, &monitor.cancel, poll)?;
    let statuses = summary
        .statuses
        .iter()
        .map(|(s, k)| (s.name(), *k))
        .collect();
    Ok((
        summary.n_samples,
        statuses,
        summary.metrics_file,
        summary.history_files,
    ))
}

/// Names of the run statistics (`loco.SimulationResult.statistics` keys, batch columns).
#[pyfunction]
fn run_statistics_names() -> Vec<&'static str> {
    RunStatistics::NAMES.to_vec()
}

/// Status names by code (`status_names()[code]`).
#[pyfunction]
fn batch_status_names() -> Vec<&'static str> {
    loco_core::batch::SampleStatus::ALL
        .iter()
        .map(|s| s.name())
        .collect()
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run_batch, m)?)?;
    m.add_function(wrap_pyfunction!(run_study_file, m)?)?;
    m.add_function(wrap_pyfunction!(batch_status_names, m)?)?;
    m.add_function(wrap_pyfunction!(run_statistics_names, m)?)?;
    Ok(())
}
