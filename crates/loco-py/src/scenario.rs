//! The run scenario as a native object: wheel and rail, speed, distance, track, yaw damper and
//! integration settings, checked once and then shared by `simulate`, `linearise` and `run_batch`.

use crate::contact::PyProfile;
use crate::dampers::PyDamper;
use crate::errors::to_py_err;
use crate::track::PyTrack;
use loco_core::track::design_input::SectionSetting;
use loco_core::vehicle::creep_model::CreepModel;
use loco_core::vehicle::scenario::Scenario;
use loco_core::vehicle::scenario_settings::CurveSetting;
use loco_core::vehicle::scenario_settings::{GivenObjects, ScenarioSettings};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::Path;
use std::sync::Arc;

/// A checked run scenario (SI units). The track is `track` when given, perfect when
/// `track_kind == "perfect"`, else synthesised from `spectrum`, `seed` and `band` (m);
/// `creep` names the creep model (`fastsim`, `fastrip`, `table`: `CreepModel::NAMES`);
/// `lead_in` (m) is run before the recorded `distance` and not recorded.
#[pyclass(name = "RunScenario", module = "loco._loco", frozen)]
pub struct PyRunScenario {
    pub inner: Scenario,
}

#[pymethods]
impl PyRunScenario {
    #[new]
    #[pyo3(signature = (
        wheel, rail, speed, distance, *, track=None, track_kind="synthetic".to_string(),
        spectrum="cn-hsr".to_string(), seed=0, band=(2.0, 200.0), yaw_damper=None, step=1e-3,
        output_rate=500.0, fastsim_grid=(10, 10), creep="fastsim".to_string(), initial_lateral_offset=0.0,
        lead_in=0.0,
        gauge=1.435, gauge_height=0.016, rail_inclination=None, curve=None
    ))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        wheel: PyRef<'_, PyProfile>,
        rail: PyRef<'_, PyProfile>,
        speed: f64,
        distance: f64,
        track: Option<PyRef<'_, PyTrack>>,
        track_kind: String,
        spectrum: String,
        seed: u64,
        band: (f64, f64),
        yaw_damper: Option<PyRef<'_, PyDamper>>,
        step: f64,
        output_rate: f64,
        fastsim_grid: (usize, usize),
        creep: String,
        initial_lateral_offset: f64,
        lead_in: f64,
        gauge: f64,
        gauge_height: f64,
        rail_inclination: Option<f64>,
        curve: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        // A given track takes the place of `track_kind`; the synthesis settings only reach a
        // synthesised track (the Python layer always passes them).
        let synthetic = track.is_none() && track_kind == "synthetic";
        if track.is_none() && !synthetic && track_kind != "perfect" {
            return Err(to_py_err(loco_core::LocoError::param(
                "track_kind",
                format!("expected 'synthetic' or 'perfect', got '{track_kind}'"),
            )));
        }
        let settings = ScenarioSettings {
            speed: Some(speed),
            distance: Some(distance),
            lead_in: Some(lead_in),
            track: track.is_none().then_some(track_kind),
            spectrum: synthetic.then_some(spectrum),
            seed: synthetic.then_some(seed),
            band: synthetic.then_some([band.0, band.1]),
            step: Some(step),
            output_rate: Some(output_rate),
            fastsim_grid: Some([fastsim_grid.0, fastsim_grid.1]),
            creep: Some(creep),
            initial_lateral_offset: Some(initial_lateral_offset),
            gauge: Some(gauge),
            gauge_height: Some(gauge_height),
            rail_inclination,
            curve: curve.map(|c| curve_setting(&c)).transpose()?,
            ..ScenarioSettings::default()
        };
        let given = GivenObjects {
            wheel: Some(wheel.inner.clone()),
            rail: Some(rail.inner.clone()),
            track: track.map(|t| Arc::new(t.inner.clone())),
            yaw_damper: yaw_damper.map(|d| d.inner),
        };
        let inner = settings.resolve(given, Path::new(".")).map_err(to_py_err)?;
        Ok(Self { inner })
    }

    /// Running speed, m/s.
    #[getter]
    fn speed(&self) -> f64 {
        self.inner.speed
    }

    /// Distance run, m.
    #[getter]
    fn distance(&self) -> f64 {
        self.inner.distance
    }

    /// Output sampling rate, Hz.
    #[getter]
    fn output_rate(&self) -> f64 {
        self.inner.run.output_rate
    }

    fn __repr__(&self) -> String {
        format!(
            "RunScenario(wheel='{}', rail='{}', speed={} m/s, distance={} m)",
            self.inner.wheel.name(),
            self.inner.rail.name(),
            self.inner.speed,
            self.inner.distance
        )
    }
}

/// The names of the creep models a scenario accepts (`CreepModel::NAMES`).
#[pyfunction]
fn creep_model_names() -> Vec<&'static str> {
    CreepModel::NAMES.to_vec()
}

/// Adds the class and its function to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyRunScenario>()?;
    m.add_function(wrap_pyfunction!(creep_model_names, m)?)?;
    Ok(())
}

/// The `curve` keyword: a CSV path, or a sequence of dicts with the fields of
/// [`SectionSetting`] (`kind`, `length_m`, `radius_m`, `cant_mm`, `direction`,
/// `cant_run_off_m`); errors name the section and the field.
fn curve_setting(curve: &Bound<'_, PyAny>) -> PyResult<CurveSetting> {
    if let Ok(path) = curve.extract::<String>() {
        return Ok(CurveSetting::File(path));
    }
    let bad = |name: String, reason: String| to_py_err(loco_core::LocoError::param(name, reason));
    let mut sections = Vec::new();
    for (i, item) in curve.try_iter()?.enumerate() {
        let item = item?;
        let field = |name: &str| format!("curve section {} ({name})", i + 1);
        let dict = item.cast::<PyDict>().map_err(|_| {
            bad(
                format!("curve section {}", i + 1),
                "expected a dict of kind, length_m, radius_m, cant_mm, direction, cant_run_off_m"
                    .into(),
            )
        })?;
        let mut s = SectionSetting::default();
        for (key, value) in dict.iter() {
            let key: String = key.extract()?;
            let number = || {
                value
                    .extract::<f64>()
                    .map_err(|_| bad(field(&key), "expected a number".into()))
            };
            let text = || {
                value
                    .extract::<String>()
                    .map_err(|_| bad(field(&key), "expected a string".into()))
            };
            match key.as_str() {
                "kind" => s.kind = text()?,
                "direction" => s.direction = Some(text()?),
                "length_m" => s.length_m = number()?,
                "radius_m" => s.radius_m = Some(number()?),
                "cant_mm" => s.cant_mm = Some(number()?),
                "cant_run_off_m" => s.cant_run_off_m = Some(number()?),
                _ => return Err(bad(field(&key), "unknown field".into())),
            }
        }
        if !dict.contains("length_m")? {
            return Err(bad(field("length_m"), "missing".into()));
        }
        sections.push(s);
    }
    Ok(CurveSetting::Sections(sections))
}
