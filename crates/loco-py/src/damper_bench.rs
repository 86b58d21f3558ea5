//! Bindings of `loco_core::dampers::bench`: a damper driven by a sine, a sweep or a recorded
//! stroke on the test bench. Python arguments are SI (Hz, m, s); results are arrays per sample.

use crate::dampers::{Arr, PyDamper};
use crate::errors::run_detached;
use loco_core::dampers::bench::{self, BenchMotion, BenchOptions, BenchRecord};
use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;

type BenchTuple<'py> = (
    Arr<'py>,
    Arr<'py>,
    Arr<'py>,
    Arr<'py>,
    Arr<'py>,
    Arr<'py>,
    Option<(f64, f64, f64)>,
    f64,
    Arr<'py>,
);

fn to_tuple(py: Python<'_>, r: BenchRecord) -> BenchTuple<'_> {
    (
        r.time_s.into_pyarray(py),
        r.displacement_m.into_pyarray(py),
        r.velocity_mps.into_pyarray(py),
        r.force_n.into_pyarray(py),
        r.scale_factor.into_pyarray(py),
        r.estimated_frequency_hz.into_pyarray(py),
        r.equivalent
            .map(|e| (e.damping_nspm, e.stiffness_npm, e.energy_per_cycle_j)),
        r.dissipated_energy_j,
        r.valve_volume_m3.into_pyarray(py),
    )
}

fn options(
    steps_per_cycle: usize,
    samples_per_cycle: usize,
    equivalent_cycles: usize,
) -> BenchOptions {
    BenchOptions {
        steps_per_cycle,
        samples_per_cycle,
        equivalent_cycles,
    }
}

/// Sine bench: (time, displacement, velocity, force, scale factor, estimated frequency,
/// (c_eq, k_eq, energy per cycle), dissipated energy).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (damper, frequency, amplitude, cycles, steps_per_cycle, samples_per_cycle, equivalent_cycles))]
fn damper_bench_sine<'py>(
    py: Python<'py>,
    damper: &PyDamper,
    frequency: f64,
    amplitude: f64,
    cycles: usize,
    steps_per_cycle: usize,
    samples_per_cycle: usize,
    equivalent_cycles: usize,
) -> PyResult<BenchTuple<'py>> {
    let inner = damper.inner;
    let motion = BenchMotion::Sine {
        frequency_hz: frequency,
        amplitude_m: amplitude,
        cycles,
    };
    let opts = options(steps_per_cycle, samples_per_cycle, equivalent_cycles);
    let record = run_detached(py, move || bench::run(&inner, &motion, &opts))?;
    Ok(to_tuple(py, record))
}

/// Linear sweep bench; same tuple as the sine bench with no equivalent values.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (damper, start_frequency, end_frequency, amplitude, duration, steps_per_cycle, samples_per_cycle))]
fn damper_bench_sweep<'py>(
    py: Python<'py>,
    damper: &PyDamper,
    start_frequency: f64,
    end_frequency: f64,
    amplitude: f64,
    duration: f64,
    steps_per_cycle: usize,
    samples_per_cycle: usize,
) -> PyResult<BenchTuple<'py>> {
    let inner = damper.inner;
    let motion = BenchMotion::Sweep {
        start_frequency_hz: start_frequency,
        end_frequency_hz: end_frequency,
        amplitude_m: amplitude,
        duration_s: duration,
    };
    let opts = options(steps_per_cycle, samples_per_cycle, 1);
    let record = run_detached(py, move || bench::run(&inner, &motion, &opts))?;
    Ok(to_tuple(py, record))
}

/// Recorded-motion bench; same tuple as the sine bench with no equivalent values.
#[pyfunction]
fn damper_bench_recorded<'py>(
    py: Python<'py>,
    damper: &PyDamper,
    time: PyReadonlyArray1<'py, f64>,
    displacement: PyReadonlyArray1<'py, f64>,
) -> PyResult<BenchTuple<'py>> {
    let inner = damper.inner;
    let motion = BenchMotion::Recorded {
        time_s: time.as_array().to_vec(),
        displacement_m: displacement.as_array().to_vec(),
    };
    let record = run_detached(py, move || {
        bench::run(&inner, &motion, &BenchOptions::default())
    })?;
    Ok(to_tuple(py, record))
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(damper_bench_sine, m)?)?;
    m.add_function(wrap_pyfunction!(damper_bench_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(damper_bench_recorded, m)?)?;
    Ok(())
}
