//! The run scenario as a native object: wheel and rail, speed, distance, track, yaw damper and
//! integration settings, checked once and then shared by `simulate`, `linearise` and `run_batch`.

use crate::contact::PyProfile;
use crate::dampers::PyDamper;
use crate::errors::to_py_err;
use crate::track::PyTrack;
use loco_core::contact::fastsim::FastsimParams;
use loco_core::contact::fastsim_table::FastsimTableParams;
use loco_core::contact::setup::TrackSetup;
use loco_core::track::{SynthesisParams, TrackSpectrum};
use loco_core::vehicle::run::RunSettings;
use loco_core::vehicle::scenario::{Scenario, TrackSpec};
use pyo3::prelude::*;
use std::sync::Arc;

/// A checked run scenario (SI units). The track is `track` when given, perfect when
/// `track_kind == "perfect"`, else synthesised from `spectrum`, `seed` and `band` (m);
/// `creep_table` selects tabulated FASTSIM (default table resolution) instead of the direct one;
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
        output_rate=500.0, fastsim_grid=(10, 10), creep_table=false, initial_lateral_offset=0.0,
        lead_in=0.0,
        gauge=1.435, gauge_height=0.016, rail_inclination=None
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
        creep_table: bool,
        initial_lateral_offset: f64,
        lead_in: f64,
        gauge: f64,
        gauge_height: f64,
        rail_inclination: Option<f64>,
    ) -> PyResult<Self> {
        let track = match (track, track_kind.as_str()) {
            (Some(t), _) => TrackSpec::Given(Arc::new(t.inner.clone())),
            (None, "perfect") => TrackSpec::Perfect,
            (None, "synthetic") => TrackSpec::Synthetic(SynthesisParams {
                spectrum: TrackSpectrum::from_name(&spectrum).map_err(to_py_err)?,
                seed,
                wavelength_min: band.0,
                wavelength_max: band.1,
                ..SynthesisParams::default()
            }),
            (None, other) => {
                return Err(to_py_err(loco_core::LocoError::param(
                    "track_kind",
                    format!("expected 'synthetic' or 'perfect', got '{other}'"),
                )))
            }
        };
        let inner = Scenario {
            wheel: wheel.inner.clone(),
            rail: rail.inner.clone(),
            track_setup: TrackSetup {
                gauge,
                gauge_height,
                rail_inclination: rail_inclination
                    .unwrap_or(TrackSetup::default().rail_inclination),
            },
            speed,
            distance,
            lead_in,
            track,
            yaw_damper: yaw_damper.map(|d| d.inner),
            run: RunSettings {
                step,
                output_rate,
                ..RunSettings::default()
            },
            fastsim: FastsimParams {
                nx: fastsim_grid.0,
                ny: fastsim_grid.1,
                ..FastsimParams::default()
            },
            creep_table: creep_table.then(FastsimTableParams::default),
            initial_lateral_offset,
        };
        inner.validate().map_err(to_py_err)?;
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

/// Adds the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyRunScenario>()?;
    Ok(())
}
