//! Bindings of `loco_core::track`: synthesis, measured files, target spectra, the track object.

use crate::errors::run_detached;
use loco_core::track::{
    load_csv, synthesize, Channel, MeasuredParams, SynthesisParams, TrackIrregularity,
    TrackSpectrum,
};
use numpy::{IntoPyArray, PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;

/// A track irregularity on a uniform grid (SI units: m, m/m).
#[pyclass(name = "Track", module = "loco._loco", frozen)]
pub struct PyTrack {
    pub inner: TrackIrregularity,
}

#[pymethods]
impl PyTrack {
    /// Length covered, m.
    #[getter]
    fn length(&self) -> f64 {
        self.inner.length()
    }

    /// Grid step, m.
    #[getter]
    fn step(&self) -> f64 {
        self.inner.step()
    }

    /// Cosine run-in length, m.
    #[getter]
    fn run_in(&self) -> f64 {
        self.inner.run_in()
    }

    /// Target spectrum name of a synthesised track, None for a measured one.
    #[getter]
    fn spectrum(&self) -> Option<&'static str> {
        self.inner.spectrum().map(TrackSpectrum::name)
    }

    /// Distances of the grid nodes, m.
    fn distance<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.inner.distance().into_pyarray(py)
    }

    /// One irregularity (`vertical`, `alignment`, `cross_level`, `gauge`) at the nodes, m.
    fn channel<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let channel = run_detached(py, || Channel::from_name(name))?;
        Ok(self.inner.channel(channel).into_pyarray(py))
    }

    /// One rail coordinate (`y_left`, `z_left`, `y_right`, `z_right`) at the nodes, m.
    fn rail<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let index = ["y_left", "z_left", "y_right", "z_right"]
            .iter()
            .position(|n| *n == name)
            .ok_or_else(|| {
                crate::errors::to_py_err(loco_core::LocoError::param(
                    "name",
                    format!("unknown rail coordinate `{name}` (y_left, z_left, y_right, z_right)"),
                ))
            })?;
        Ok(self.inner.rail(index).into_pyarray(py))
    }

    /// Rail irregularities at distance `s` (m): (y_left, z_left, y_right, z_right) in m and
    /// their derivatives d/ds in the same order.
    #[allow(clippy::type_complexity)]
    fn at(&self, s: f64) -> ((f64, f64, f64, f64), (f64, f64, f64, f64)) {
        let r = self.inner.at(s);
        (
            (r.y_left, r.z_left, r.y_right, r.z_right),
            (r.dy_left_ds, r.dz_left_ds, r.dy_right_ds, r.dz_right_ds),
        )
    }

    fn __repr__(&self) -> String {
        format!(
            "Track(spectrum={:?}, length={} m, step={} m, run_in={} m)",
            self.inner.spectrum().map(TrackSpectrum::name),
            self.inner.length(),
            self.inner.step(),
            self.inner.run_in()
        )
    }
}

/// Synthesises a track from a target spectrum (see `loco_core::track::synthesis`).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn synthesize_track(
    py: Python<'_>,
    spectrum: &str,
    length: f64,
    seed: u64,
    stream: u64,
    wavelength_min: f64,
    wavelength_max: f64,
    step: f64,
    run_in: f64,
) -> PyResult<PyTrack> {
    let spectrum = spectrum.to_string();
    let inner = run_detached(py, move || {
        synthesize(&SynthesisParams {
            spectrum: TrackSpectrum::from_name(&spectrum)?,
            length,
            seed,
            stream,
            wavelength_min,
            wavelength_max,
            step,
            run_in,
        })
    })?;
    Ok(PyTrack { inner })
}

/// Reads a measured irregularity CSV (distance m, four irregularities mm).
#[pyfunction]
#[pyo3(signature = (path, step=None, run_in=30.0, required_length=None))]
fn load_track(
    py: Python<'_>,
    path: &str,
    step: Option<f64>,
    run_in: f64,
    required_length: Option<f64>,
) -> PyResult<PyTrack> {
    let path = path.to_string();
    let inner = run_detached(py, move || {
        load_csv(
            &path,
            &MeasuredParams {
                step,
                run_in,
                required_length,
            },
        )
    })?;
    Ok(PyTrack { inner })
}

/// One-sided target PSD (m²/(1/m)) of `channel` of `spectrum` at spatial frequencies `f` (1/m).
#[pyfunction]
fn track_spectrum_psd<'py>(
    py: Python<'py>,
    spectrum: &str,
    channel: &str,
    f: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let f: Vec<f64> = f.as_array().iter().copied().collect();
    let (spectrum, channel) = (spectrum.to_string(), channel.to_string());
    let psd = run_detached(py, move || {
        let s = TrackSpectrum::from_name(&spectrum)?;
        let c = Channel::from_name(&channel)?;
        Ok(f.iter().map(|&x| s.psd(c, x)).collect::<Vec<f64>>())
    })?;
    Ok(psd.into_pyarray(py))
}

/// Target variance (m²) of `channel` of `spectrum` between `f_lo` and `f_hi` (1/m).
#[pyfunction]
fn track_spectrum_variance(
    py: Python<'_>,
    spectrum: &str,
    channel: &str,
    f_lo: f64,
    f_hi: f64,
) -> PyResult<f64> {
    let (spectrum, channel) = (spectrum.to_string(), channel.to_string());
    run_detached(py, move || {
        let s = TrackSpectrum::from_name(&spectrum)?;
        Ok(s.variance(Channel::from_name(&channel)?, f_lo, f_hi))
    })
}

/// Adds this file's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyTrack>()?;
    m.add_function(wrap_pyfunction!(synthesize_track, m)?)?;
    m.add_function(wrap_pyfunction!(load_track, m)?)?;
    m.add_function(wrap_pyfunction!(track_spectrum_psd, m)?)?;
    m.add_function(wrap_pyfunction!(track_spectrum_variance, m)?)?;
    Ok(())
}
