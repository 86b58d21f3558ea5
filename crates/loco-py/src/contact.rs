//! Bindings of `loco_core::contact`'s profiles: load, built-ins, evaluation (the wheelset's
//! contact geometry is `wheelset_contact.rs`).

use crate::errors::run_detached;
use loco_core::contact::{builtin_names, builtin_profile, load_profile, Profile, ProfileKind};
use loco_core::LocoError as CoreError;
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArrayLike1};
use pyo3::prelude::*;
use std::path::PathBuf;

/// A wheel or rail profile (points in m, profile frame: y toward the field side, z up).
#[pyclass(name = "Profile", module = "loco._loco", frozen)]
pub struct PyProfile {
    pub inner: Profile,
}

/// Copies a 1-D array-like of floats.
pub(crate) fn to_vec(values: &PyArrayLike1<'_, f64, AllowTypeChange>) -> PyResult<Vec<f64>> {
    Ok(values.as_slice()?.to_vec())
}

#[pymethods]
impl PyProfile {
    /// A profile from points `y`, `z` in m; `kind` is 'wheel' or 'rail'.
    #[new]
    fn new(
        py: Python<'_>,
        name: String,
        kind: String,
        y: PyArrayLike1<'_, f64, AllowTypeChange>,
        z: PyArrayLike1<'_, f64, AllowTypeChange>,
    ) -> PyResult<Self> {
        let (y, z) = (to_vec(&y)?, to_vec(&z)?);
        let inner = run_detached(py, move || {
            let kind = ProfileKind::parse("kind", &kind)?;
            Profile::new(name, kind, &y, &z)
        })?;
        Ok(Self { inner })
    }

    /// The profile's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name().to_string()
    }

    /// 'wheel' or 'rail'.
    #[getter]
    fn kind(&self) -> &'static str {
        self.inner.kind().as_str()
    }

    /// Lateral coordinates of the points, m.
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.inner.y().to_vec().into_pyarray(py)
    }

    /// Heights of the points, m (up).
    #[getter]
    fn z<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.inner.z().to_vec().into_pyarray(py)
    }

    /// Height z (m) at each lateral position `y` (m).
    fn height<'py>(
        &self,
        py: Python<'py>,
        y: PyArrayLike1<'py, f64, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.map(py, y, |p, v| p.height(v))
    }

    /// Slope dz/dy at each lateral position `y` (m).
    fn slope<'py>(
        &self,
        py: Python<'py>,
        y: PyArrayLike1<'py, f64, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.map(py, y, |p, v| p.slope(v))
    }

    /// Signed curvature (1/m, positive where the profile bends upward) at each `y` (m).
    fn curvature<'py>(
        &self,
        py: Python<'py>,
        y: PyArrayLike1<'py, f64, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.map(py, y, |p, v| p.curvature(v))
    }

    /// The profile smoothed by a cubic smoothing spline of smoothing `length` (m, e.g. 2e-3).
    fn smoothed(&self, py: Python<'_>, length: f64) -> PyResult<Self> {
        let profile = self.inner.clone();
        let inner = run_detached(py, move || profile.smoothed(length))?;
        Ok(Self { inner })
    }

    fn __repr__(&self) -> String {
        let (lo, hi) = self.inner.y_range();
        format!(
            "Profile(name={:?}, kind={:?}, points={}, y=[{:.4}, {:.4}] m)",
            self.inner.name(),
            self.inner.kind().as_str(),
            self.inner.y().len(),
            lo,
            hi
        )
    }
}

impl PyProfile {
    fn map<'py>(
        &self,
        py: Python<'py>,
        y: PyArrayLike1<'py, f64, AllowTypeChange>,
        f: fn(&Profile, f64) -> Result<f64, CoreError>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let y = to_vec(&y)?;
        let profile = self.inner.clone();
        let out: Vec<f64> = run_detached(py, move || y.iter().map(|&v| f(&profile, v)).collect())?;
        Ok(out.into_pyarray(py))
    }
}

/// Loads a profile file: SIMPACK `.prw`/`.prr`, or two-column text in mm (then `kind` is needed).
#[pyfunction]
#[pyo3(signature = (path, kind=None, drop_backtracking=false))]
fn load_profile_file(
    py: Python<'_>,
    path: PathBuf,
    kind: Option<String>,
    drop_backtracking: bool,
) -> PyResult<PyProfile> {
    let inner = run_detached(py, move || {
        let kind = kind.map(|k| ProfileKind::parse("kind", &k)).transpose()?;
        load_profile(&path, kind, drop_backtracking)
    })?;
    Ok(PyProfile { inner })
}

/// The built-in profile `name`.
#[pyfunction]
fn builtin_profile_named(py: Python<'_>, name: String) -> PyResult<PyProfile> {
    let inner = run_detached(py, move || builtin_profile(&name))?;
    Ok(PyProfile { inner })
}

/// Names of the built-in profiles.
#[pyfunction]
fn builtin_profile_names() -> Vec<String> {
    builtin_names().iter().map(|s| s.to_string()).collect()
}

/// A conical wheel and a knife-edge rail whose equivalent conicity is `conicity` (–, in (0, 1]):
/// Δr = 2·conicity·y exactly; no flange (for linear analyses).
#[pyfunction]
fn conical_profiles(conicity: f64) -> PyResult<(PyProfile, PyProfile)> {
    let (wheel, rail) = loco_core::contact::builtin::conical::conical_pair(conicity)
        .map_err(crate::errors::to_py_err)?;
    Ok((PyProfile { inner: wheel }, PyProfile { inner: rail }))
}

/// A JM3-type wheel of tread slope `tread_slope` (–), band radius `band_radius` (m, `inf`: a
/// straight cone) and flange thickness `flange_thickness` (m); bad fields refused by name.
#[pyfunction]
fn jm3_tread_profile(
    tread_slope: f64,
    band_radius: f64,
    flange_thickness: f64,
) -> PyResult<PyProfile> {
    let state = loco_core::contact::builtin::jm3::TreadState {
        flange_thickness,
        tread_slope,
        band_radius,
    };
    let inner =
        loco_core::contact::builtin::jm3::tread(&state).map_err(crate::errors::to_py_err)?;
    Ok(PyProfile { inner })
}

/// The built-in JM3 wheels' tread states as `(name, tread_slope (–), band_radius (m),
/// flange_thickness (m))`, the core's one list.
#[pyfunction]
fn jm3_builtin_states() -> Vec<(&'static str, f64, f64, f64)> {
    loco_core::contact::builtin::jm3::BUILTIN
        .iter()
        .map(|(n, s)| (*n, s.tread_slope, s.band_radius, s.flange_thickness))
        .collect()
}

/// Adds this file's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyProfile>()?;
    m.add_function(wrap_pyfunction!(load_profile_file, m)?)?;
    m.add_function(wrap_pyfunction!(builtin_profile_named, m)?)?;
    m.add_function(wrap_pyfunction!(builtin_profile_names, m)?)?;
    m.add_function(wrap_pyfunction!(conical_profiles, m)?)?;
    m.add_function(wrap_pyfunction!(jm3_tread_profile, m)?)?;
    m.add_function(wrap_pyfunction!(jm3_builtin_states, m)?)?;
    Ok(())
}
