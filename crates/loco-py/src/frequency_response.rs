//! Bindings of `loco_core::vehicle::{analysis::frequency_response, analysis::response_psd}`: transfer functions of
//! the linearised vehicle from track irregularity channels to recorded channels, and output
//! spectra on a random track.

use crate::errors::run_detached_monitored;
use crate::scenario::PyRunScenario;
use crate::vehicle_handle::PyVehicle;
use loco_core::track::{Channel, TrackSpectrum};
use loco_core::vehicle::analysis::frequency_response::{check_frequencies, ResponseSolver};
use loco_core::vehicle::analysis::response_psd::{response_psd_cancellable, PsdSettings};
use loco_core::vehicle::analysis::track_input::scenario_track_model;
use loco_core::LocoError;
use numpy::ndarray::{Array2, Array3};
use numpy::{Complex64, IntoPyArray, PyArray1, PyArray2, PyArray3, PyReadonlyArray1};
use pyo3::prelude::*;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// Input channel names parsed, errors naming the field `inputs`.
fn channels(inputs: &[String]) -> loco_core::Result<Vec<Channel>> {
    if inputs.is_empty() {
        return Err(LocoError::param("inputs", "must not be empty"));
    }
    inputs
        .iter()
        .map(|name| {
            Channel::from_name(name).map_err(|_| {
                LocoError::param(
                    "inputs",
                    format!(
                        "unknown irregularity channel `{name}` (vertical, alignment, cross_level, \
                         gauge)"
                    ),
                )
            })
        })
        .collect()
}

/// Transfer functions `H[output][input][frequency]` (output unit per m of irregularity at the
/// vehicle origin) of the vehicle linearised at the scenario's speed, that speed (m/s) and the
/// wheelsets' positions ahead of the origin (m).
#[pyfunction]
#[pyo3(signature = (
    vehicle, scenario, inputs, outputs, frequencies
))]
#[allow(clippy::too_many_arguments)]
fn frequency_response<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    scenario: PyRef<'py, PyRunScenario>,
    inputs: Vec<String>,
    outputs: Vec<String>,
    frequencies: PyReadonlyArray1<'py, f64>,
) -> PyResult<(Bound<'py, PyArray3<Complex64>>, f64, Vec<f64>)> {
    let scenario = scenario.inner.clone();
    let structure = std::sync::Arc::clone(&vehicle.structure);
    let frequencies = frequencies.as_array().to_vec();
    // On a worker thread, so that Ctrl-C (checked every 100 ms) stops it between frequencies.
    let cancel = Arc::new(AtomicBool::new(false));
    let worker_cancel = Arc::clone(&cancel);
    let work = move || {
        let inputs = channels(&inputs)?;
        check_frequencies(&frequencies)?;
        let model = scenario_track_model(structure, &scenario)?;
        let h = ResponseSolver::new(&model, &outputs)?.response_cancellable(
            &inputs,
            &frequencies,
            Some(&worker_cancel),
        )?;
        let shape = (outputs.len(), inputs.len(), frequencies.len());
        Ok((h.h, h.speed, h.wheelset_x.to_vec(), shape))
    };
    let (h, speed, wheelset_x, shape) = run_detached_monitored(py, work, &cancel, |_| Ok(()))?;
    let array = Array3::from_shape_vec(shape, h)
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok((array.into_pyarray(py), speed, wheelset_x))
}

/// One-sided output PSDs `[output][frequency]` (unit²/Hz), rms values over the grid (unit) and
/// the Sperling index W_y of the carbody floor (–) from the four channels of `spectrum` in the
/// wavelength `band` (m), amplitudes times `amplitude_scale`, and the damping ratio of the least
/// damped mode in 0.3–20 Hz (–, NaN when none: the spectra hold only when it is positive).
#[pyfunction]
#[pyo3(signature = (
    vehicle, scenario, outputs, frequencies, *, spectrum="cn-hsr".to_string(), band=(2.0, 200.0),
    amplitude_scale=1.0
))]
#[allow(clippy::too_many_arguments)]
fn response_psd<'py>(
    py: Python<'py>,
    vehicle: PyRef<'py, PyVehicle>,
    scenario: PyRef<'py, PyRunScenario>,
    outputs: Vec<String>,
    frequencies: PyReadonlyArray1<'py, f64>,
    spectrum: String,
    band: (f64, f64),
    amplitude_scale: f64,
) -> PyResult<PsdTuple<'py>> {
    let scenario = scenario.inner.clone();
    let structure = std::sync::Arc::clone(&vehicle.structure);
    let frequencies = frequencies.as_array().to_vec();
    let n_out = outputs.len();
    let cancel = Arc::new(AtomicBool::new(false));
    let worker_cancel = Arc::clone(&cancel);
    let work = move || {
        let settings = PsdSettings {
            spectrum: TrackSpectrum::from_name(&spectrum)?,
            wavelength_min: band.0,
            wavelength_max: band.1,
            amplitude_scale,
            ..PsdSettings::default()
        };
        settings.validate()?;
        check_frequencies(&frequencies)?;
        let model = scenario_track_model(structure, &scenario)?;
        response_psd_cancellable(
            &model,
            &outputs,
            &frequencies,
            &settings,
            Some(&worker_cancel),
        )
    };
    let result = run_detached_monitored(py, work, &cancel, |_| Ok(()))?;
    let nf = result.frequencies.len();
    let psd = Array2::from_shape_vec((n_out, nf), result.psd.concat())
        .map_err(|e| crate::errors::InternalError::new_err(e.to_string()))?;
    Ok((
        psd.into_pyarray(py),
        result.rms.into_pyarray(py),
        result.sperling_lateral,
        result.least_damping_ratio,
    ))
}

/// `(psd, rms, W_y)` of [`response_psd`].
type PsdTuple<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<f64>>,
    f64,
    f64,
);

/// Names of the four irregularity channels, in storage order (vertical, alignment, cross level,
/// gauge).
#[pyfunction]
fn irregularity_channels() -> Vec<&'static str> {
    Channel::ALL.iter().map(|c| c.name()).collect()
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(irregularity_channels, m)?)?;
    m.add_function(wrap_pyfunction!(frequency_response, m)?)?;
    m.add_function(wrap_pyfunction!(response_psd, m)?)?;
    Ok(())
}
