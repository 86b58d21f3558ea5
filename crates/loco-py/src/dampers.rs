//! Bindings of `loco_core::dampers`: the `Damper` class and its constructors (the presets are
//! `damper_presets.rs`, the bench `damper_bench.rs`). Python arguments are SI (N·s/m, N/m, kg,
//! Hz, s, m, m², kg/m³, m²/s).

use crate::errors::run_detached;
use loco_core::dampers::{
    BlowOff, Damper, FsdDamper, FsdParams, FsdTrigger, FsdTriggerParams, HydraulicDamper,
    HydraulicFrequencyValve, HydraulicParams, HydraulicValve, HydraulicValveParams, MaxwellDamper,
    MaxwellParams, REFERENCE_STROKE_AMPLITUDE_M,
};
use loco_core::LocoError as CoreError;
use numpy::{IntoPyArray, PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A float array handed to Python.
pub(crate) type Arr<'py> = Bound<'py, PyArray1<f64>>;

/// A validated damper (immutable). Build it with `maxwell`, `fsd`, `hydraulic` or a preset.
#[pyclass(frozen, name = "Damper", module = "loco._loco")]
#[derive(Clone)]
pub struct PyDamper {
    pub inner: Damper,
}

#[pymethods]
impl PyDamper {
    /// "maxwell", "fsd" or "hydraulic".
    #[getter]
    fn kind(&self) -> &'static str {
        match self.inner {
            Damper::Maxwell(_) => "maxwell",
            Damper::Fsd(_) => "fsd",
            Damper::Hydraulic(_) => "hydraulic",
        }
    }

    /// Number of continuous internal states.
    #[getter]
    fn n_states(&self) -> usize {
        self.inner.n_states()
    }

    /// Magnitude of the fastest internal pole (1/s).
    #[getter]
    fn fastest_rate(&self) -> f64 {
        self.inner.fastest_rate_per_s()
    }

    /// The parameters as a dict (SI units, names as in the constructor).
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        match self.inner {
            Damper::Maxwell(m) => {
                let p = m.params();
                d.set_item("damping", p.damping_nspm)?;
                d.set_item("series_stiffness", p.series_stiffness_npm)?;
                d.set_item("knee_velocity", p.blow_off.map(|b| b.knee_velocity_mps))?;
                d.set_item(
                    "blow_off_damping",
                    p.blow_off.map(|b| b.blow_off_damping_nspm),
                )?;
            }
            Damper::Fsd(f) => {
                let p = f.params();
                d.set_item("low_damping", p.low_damping_nspm)?;
                d.set_item("high_damping", p.high_damping_nspm)?;
                d.set_item("equivalent_mass", p.equivalent_mass_kg)?;
                d.set_item("equivalent_stiffness", p.equivalent_stiffness_npm)?;
                d.set_item("cutoff_frequency", p.cutoff_frequency_hz)?;
                d.set_item("switching_delay", p.switching_delay_s)?;
                d.set_item("start_closed", p.start_closed)?;
                d.set_item("trigger", p.trigger.name())?;
                match &p.trigger {
                    FsdTrigger::RmsFrequency(t) => set_trigger(&d, t)?,
                    FsdTrigger::Hydraulic(v) => set_valve(&d, v)?,
                }
            }
            Damper::Hydraulic(h) => {
                let p = h.params();
                d.set_item("piston_area", p.piston_area_m2)?;
                d.set_item("rod_area", p.rod_area_m2)?;
                d.set_item("rebound_orifice_area", p.rebound_orifice_area_m2)?;
                d.set_item("compression_orifice_area", p.compression_orifice_area_m2)?;
                d.set_item("bottom_valve_area", p.bottom_valve_area_m2)?;
                d.set_item("oil_density", p.oil_density_kgpm3)?;
                d.set_item("oil_kinematic_viscosity", p.oil_kinematic_viscosity_m2ps)?;
                d.set_item("flow_coefficient", p.flow_coefficient)?;
                d.set_item("series_stiffness", p.series_stiffness_npm)?;
                let valve = p.frequency_valve;
                d.set_item("open_area_ratio", valve.map(|v| v.open_area_ratio))?;
                d.set_item("cutoff_frequency", valve.map(|v| v.cutoff_frequency_hz))?;
                d.set_item("switching_delay", valve.map(|v| v.switching_delay_s))?;
                if let Some(v) = valve {
                    d.set_item("start_closed", v.start_closed)?;
                    set_trigger(&d, &v.trigger)?;
                }
            }
        }
        Ok(d)
    }

    /// The law and its main parameters in engineering units (`parameters()` has them all, SI).
    fn __repr__(&self) -> String {
        match self.inner {
            Damper::Maxwell(m) => {
                let p = m.params();
                let blow_off = p.blow_off.map_or(String::new(), |b| {
                    format!(
                        ", blow-off above {} m/s at {} kN·s/m",
                        b.knee_velocity_mps,
                        b.blow_off_damping_nspm / 1e3
                    )
                });
                format!(
                    "Damper(maxwell, c={} kN·s/m, k_series={} kN/mm{blow_off})",
                    p.damping_nspm / 1e3,
                    p.series_stiffness_npm / 1e6
                )
            }
            Damper::Fsd(f) => {
                let p = f.params();
                format!(
                    "Damper(fsd, c1={} kN·s/m, c2={} kN·s/m, f_p={} Hz, delay={} s, k={} kN/mm, m={} kg)",
                    p.low_damping_nspm / 1e3,
                    p.high_damping_nspm / 1e3,
                    p.cutoff_frequency_hz,
                    p.switching_delay_s,
                    p.equivalent_stiffness_npm / 1e6,
                    p.equivalent_mass_kg
                )
            }
            Damper::Hydraulic(h) => {
                let p = h.params();
                let valve = p.frequency_valve.map_or(String::new(), |v| {
                    format!(", frequency valve at {} Hz", v.cutoff_frequency_hz)
                });
                format!(
                    "Damper(hydraulic, piston={} cm², rebound orifice={} mm², k_series={} kN/mm{valve})",
                    p.piston_area_m2 * 1e4,
                    p.rebound_orifice_area_m2 * 1e6,
                    p.series_stiffness_npm / 1e6
                )
            }
        }
    }
}

fn set_trigger(d: &Bound<'_, PyDict>, t: &FsdTriggerParams) -> PyResult<()> {
    d.set_item("hysteresis_ratio", t.hysteresis_ratio)?;
    d.set_item("highpass_corner", t.highpass_corner_hz)?;
    d.set_item("averaging_time", t.averaging_time_s)?;
    d.set_item("min_stroke_rms", t.min_stroke_rms_m)?;
    d.set_item("warmup_time", t.warmup_time_s)
}

fn set_valve(d: &Bound<'_, PyDict>, v: &HydraulicValve) -> PyResult<()> {
    let p = v.params();
    d.set_item("valve_piston_area", p.piston_area_m2)?;
    d.set_item("orifice_area", p.orifice_area_m2)?;
    d.set_item("valve_flow_coefficient", p.flow_coefficient)?;
    d.set_item("valve_oil_density", p.oil_density_kgpm3)?;
    d.set_item(
        "valve_oil_kinematic_viscosity",
        p.oil_kinematic_viscosity_m2ps,
    )?;
    d.set_item("aux_piston_area", p.aux_piston_area_m2)?;
    d.set_item("opening_stroke", p.opening_stroke_m)?;
    d.set_item("spring_stiffness", p.spring_stiffness_npm)?;
    d.set_item("opening_volume", v.opening_volume_m3())?;
    d.set_item("opening_pressure", v.opening_pressure_pa())
}

/// A Maxwell damper: damping (N·s/m) in series with a stiffness (N/m), optional blow-off.
#[pyfunction]
#[pyo3(signature = (damping, series_stiffness, knee_velocity=None, blow_off_damping=None))]
fn damper_maxwell(
    py: Python<'_>,
    damping: f64,
    series_stiffness: f64,
    knee_velocity: Option<f64>,
    blow_off_damping: Option<f64>,
) -> PyResult<PyDamper> {
    run_detached(py, move || {
        let blow_off = match (knee_velocity, blow_off_damping) {
            (None, None) => None,
            (Some(knee_velocity_mps), Some(blow_off_damping_nspm)) => Some(BlowOff {
                knee_velocity_mps,
                blow_off_damping_nspm,
            }),
            _ => {
                return Err(CoreError::param(
                    "knee_velocity",
                    "give knee_velocity and blow_off_damping together",
                ))
            }
        };
        let damper = MaxwellDamper::new(MaxwellParams {
            damping_nspm: damping,
            series_stiffness_npm: series_stiffness,
            blow_off,
        })?;
        Ok(PyDamper {
            inner: Damper::Maxwell(damper),
        })
    })
}

/// A frequency-selective damper; defaults are the spec's FSD. `trigger` is a name of
/// `FsdTrigger::NAMES`; for "hydraulic" the valve is derived at `reference_stroke_amplitude`
/// (m, default the measured one) and any of the valve overrides given replace a derived value.
#[pyfunction]
#[pyo3(signature = (low_damping, high_damping, equivalent_mass, equivalent_stiffness,
    cutoff_frequency, switching_delay, start_closed, hysteresis_ratio, highpass_corner,
    averaging_time, min_stroke_rms, warmup_time, trigger, reference_stroke_amplitude,
    orifice_area, aux_piston_area, opening_stroke, spring_stiffness))]
#[allow(clippy::too_many_arguments)]
fn damper_fsd(
    py: Python<'_>,
    low_damping: f64,
    high_damping: f64,
    equivalent_mass: f64,
    equivalent_stiffness: f64,
    cutoff_frequency: f64,
    switching_delay: f64,
    start_closed: bool,
    hysteresis_ratio: f64,
    highpass_corner: f64,
    averaging_time: f64,
    min_stroke_rms: f64,
    warmup_time: f64,
    trigger: String,
    reference_stroke_amplitude: Option<f64>,
    orifice_area: Option<f64>,
    aux_piston_area: Option<f64>,
    opening_stroke: Option<f64>,
    spring_stiffness: Option<f64>,
) -> PyResult<PyDamper> {
    run_detached(py, move || {
        let damper = FsdDamper::new(FsdParams {
            low_damping_nspm: low_damping,
            high_damping_nspm: high_damping,
            equivalent_mass_kg: equivalent_mass,
            equivalent_stiffness_npm: equivalent_stiffness,
            cutoff_frequency_hz: cutoff_frequency,
            switching_delay_s: switching_delay,
            start_closed,
            trigger: FsdTrigger::RmsFrequency(FsdTriggerParams {
                highpass_corner_hz: highpass_corner,
                averaging_time_s: averaging_time,
                hysteresis_ratio,
                min_stroke_rms_m: min_stroke_rms,
                warmup_time_s: warmup_time,
            }),
        })?;
        let damper = if FsdTrigger::check_name(&trigger)? == FsdTrigger::HYDRAULIC {
            let derived = damper.with_hydraulic_valve(
                reference_stroke_amplitude.unwrap_or(REFERENCE_STROKE_AMPLITUDE_M),
            )?;
            let p = *derived.hydraulic_valve().expect("just derived").params();
            let valve = HydraulicValve::new(HydraulicValveParams {
                orifice_area_m2: orifice_area.unwrap_or(p.orifice_area_m2),
                aux_piston_area_m2: aux_piston_area.unwrap_or(p.aux_piston_area_m2),
                opening_stroke_m: opening_stroke.unwrap_or(p.opening_stroke_m),
                spring_stiffness_npm: spring_stiffness.unwrap_or(p.spring_stiffness_npm),
                ..p
            })?;
            derived.with_trigger(FsdTrigger::Hydraulic(valve))
        } else {
            damper
        };
        Ok(PyDamper {
            inner: Damper::Fsd(damper),
        })
    })
}

/// The names of the FSD triggers, the default first.
#[pyfunction]
fn fsd_trigger_names() -> Vec<&'static str> {
    FsdTrigger::NAMES.to_vec()
}

/// The measured reference stroke amplitude of the hydraulic valve's derivation (m).
#[pyfunction]
fn fsd_reference_stroke_amplitude() -> f64 {
    REFERENCE_STROKE_AMPLITUDE_M
}

/// The band (lower, upper) (Hz) in which a steady sine stroke of each amplitude (m) opens the
/// hydraulic valve of an FSD (NaN, NaN where it opens nowhere).
#[pyfunction]
fn fsd_valve_opening_band<'py>(
    py: Python<'py>,
    damper: &PyDamper,
    amplitudes: PyReadonlyArray1<'py, f64>,
) -> PyResult<(Arr<'py>, Arr<'py>)> {
    let amplitudes = amplitudes.as_array().to_vec();
    let inner = damper.inner;
    let (lower, upper) = run_detached(py, move || {
        let fsd = match inner {
            Damper::Fsd(f) if f.hydraulic_valve().is_some() => f,
            _ => {
                return Err(CoreError::param(
                    "damper",
                    "needs an FSD with trigger \"hydraulic\"",
                ))
            }
        };
        let valve = fsd.hydraulic_valve().expect("checked");
        let closed = fsd.params().closed_module();
        let mut out = (Vec::new(), Vec::new());
        for band in valve.opening_bands_hz(&closed, &amplitudes)? {
            let (lo, hi) = band.unwrap_or((f64::NAN, f64::NAN));
            out.0.push(lo);
            out.1.push(hi);
        }
        Ok(out)
    })?;
    Ok((lower.into_pyarray(py), upper.into_pyarray(py)))
}

/// A hydraulic orifice damper; `open_area_ratio` adds a frequency valve (hydraulic FSD) with
/// the given cut-off, delay and start state and the default trigger.
#[pyfunction]
#[pyo3(signature = (piston_area, rod_area, rebound_orifice_area, compression_orifice_area,
    bottom_valve_area, oil_density, oil_kinematic_viscosity, flow_coefficient, series_stiffness,
    open_area_ratio, cutoff_frequency, switching_delay, start_closed))]
#[allow(clippy::too_many_arguments)]
fn damper_hydraulic(
    py: Python<'_>,
    piston_area: f64,
    rod_area: f64,
    rebound_orifice_area: f64,
    compression_orifice_area: f64,
    bottom_valve_area: f64,
    oil_density: f64,
    oil_kinematic_viscosity: f64,
    flow_coefficient: f64,
    series_stiffness: f64,
    open_area_ratio: Option<f64>,
    cutoff_frequency: f64,
    switching_delay: f64,
    start_closed: bool,
) -> PyResult<PyDamper> {
    run_detached(py, move || {
        let damper = HydraulicDamper::new(HydraulicParams {
            piston_area_m2: piston_area,
            rod_area_m2: rod_area,
            rebound_orifice_area_m2: rebound_orifice_area,
            compression_orifice_area_m2: compression_orifice_area,
            bottom_valve_area_m2: bottom_valve_area,
            oil_density_kgpm3: oil_density,
            oil_kinematic_viscosity_m2ps: oil_kinematic_viscosity,
            flow_coefficient,
            series_stiffness_npm: series_stiffness,
            frequency_valve: open_area_ratio.map(|open_area_ratio| HydraulicFrequencyValve {
                open_area_ratio,
                cutoff_frequency_hz: cutoff_frequency,
                switching_delay_s: switching_delay,
                start_closed,
                trigger: FsdTriggerParams::default(),
            }),
        })?;
        Ok(PyDamper {
            inner: Damper::Hydraulic(damper),
        })
    })
}

/// Default parameters of the hydraulic damper (SI), for the Python wrapper's defaults.
#[pyfunction]
fn damper_hydraulic_defaults(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    PyDamper {
        inner: Damper::Hydraulic(HydraulicDamper::fsd_default()),
    }
    .parameters(py)
}

/// Adds this file's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyDamper>()?;
    m.add_function(wrap_pyfunction!(damper_maxwell, m)?)?;
    m.add_function(wrap_pyfunction!(damper_fsd, m)?)?;
    m.add_function(wrap_pyfunction!(damper_hydraulic, m)?)?;
    m.add_function(wrap_pyfunction!(damper_hydraulic_defaults, m)?)?;
    m.add_function(wrap_pyfunction!(fsd_trigger_names, m)?)?;
    m.add_function(wrap_pyfunction!(fsd_reference_stroke_amplitude, m)?)?;
    m.add_function(wrap_pyfunction!(fsd_valve_opening_band, m)?)?;
    Ok(())
}
