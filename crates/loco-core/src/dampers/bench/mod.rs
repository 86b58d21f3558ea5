//! The damper bench: drives a [`Damper`] with a prescribed elongation (sine, linear sweep or a
//! recorded motion), integrates its internal states with classical RK4 at a small fixed step and
//! records time, displacement, velocity, force and the valve's scale factor.
//!
//! For a sine `x = A·sin(ωt)` it also returns the equivalent linear element over the last full
//! cycles: writing `F ≈ k_eq·x + c_eq·ẋ`, orthogonality over whole periods gives
//! `k_eq = (2/(A·T_n))·∫F·sin(ωt)dt` (in-phase part) and `c_eq = (2/(A·ω·T_n))·∫F·cos(ωt)dt`
//! (quadrature part), with `T_n` the duration of the cycles used, and the energy dissipated per
//! cycle `∮F·dx = ∫F·ẋ dt / n` (J), `π·c_eq·ω·A²` for a linear element. The integrals use every
//! integration step (rectangle rule on whole periods, exact to round-off for smooth periodic
//! integrands).
//!
//! Step: `dt ≤ 1/rate` with the damper's [`Damper::fastest_rate_per_s`] (well inside RK4's
//! stability limit of 2.78) and at least `steps_per_cycle` per period.

mod stepping;

use super::Damper;
use crate::error::{check_positive, Result};
use crate::LocoError;
use std::f64::consts::TAU;
use stepping::{check_run_length, drive, run_recorded, substeps};

/// Highest bench frequency, Hz. The damper laws are lumped (no oil-column inertia or wave
/// effects, the valve's own dynamics only as modelled), meant for the vehicle's content: its
/// rigid bodies end below about 100 Hz (the frequency response stops at 1 kHz for the same
/// reason), and a bench beyond that is outside every law's validity.
pub const MAX_FREQUENCY_HZ: f64 = 1_000.0;

/// Largest bench amplitude, m: half the about 0.5 m a yaw damper measures between its pins, so
/// beyond the stroke of any damper the laws describe (the study's dampers move by millimetres).
pub const MAX_AMPLITUDE_M: f64 = 0.25;

/// `value` checked to be positive and at most `max` (in `unit`); errors name `name` and say
/// `why` the bound is there.
fn check_bounded(name: &str, value: f64, max: f64, unit: &str, why: &str) -> Result<f64> {
    let v = check_positive(name, value)?;
    if v > max {
        return Err(LocoError::param(
            name,
            format!("{v} {unit} is above {max} {unit}, {why}"),
        ));
    }
    Ok(v)
}

/// `value` (Hz) checked to be positive and at most [`MAX_FREQUENCY_HZ`].
fn check_frequency(name: &str, value: f64) -> Result<f64> {
    let why = "beyond the lumped damper laws' range";
    check_bounded(name, value, MAX_FREQUENCY_HZ, "Hz", why)
}

/// `value` (m) checked to be positive and at most [`MAX_AMPLITUDE_M`].
fn check_amplitude(name: &str, value: f64) -> Result<f64> {
    check_bounded(
        name,
        value,
        MAX_AMPLITUDE_M,
        "m",
        "beyond any damper's stroke",
    )
}

/// The prescribed elongation of the damper.
#[derive(Debug, Clone, PartialEq)]
pub enum BenchMotion {
    /// `x = amplitude·sin(2π·frequency·t)` for `cycles` periods.
    Sine {
        /// Frequency (Hz), > 0.
        frequency_hz: f64,
        /// Amplitude (m), > 0.
        amplitude_m: f64,
        /// Number of periods, >= 1.
        cycles: usize,
    },
    /// Linear frequency sweep `x = A·sin(2π(f0·t + (f1 - f0)·t²/(2T)))` over `duration_s`.
    Sweep {
        /// Start frequency (Hz), > 0.
        start_frequency_hz: f64,
        /// End frequency (Hz), > 0.
        end_frequency_hz: f64,
        /// Amplitude (m), > 0.
        amplitude_m: f64,
        /// Duration (s), > 0.
        duration_s: f64,
    },
    /// A recorded elongation, linearly interpolated (velocity constant in each interval).
    Recorded {
        /// Strictly increasing sample times (s), at least two.
        time_s: Vec<f64>,
        /// Elongation at those times (m).
        displacement_m: Vec<f64>,
    },
}

/// Numerical settings of the bench.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BenchOptions {
    /// Minimum number of integration steps per period (sine, sweep at its end frequency).
    pub steps_per_cycle: usize,
    /// Samples recorded per period (sine); for a sweep per period at the end frequency.
    pub samples_per_cycle: usize,
    /// Number of last full cycles used for the equivalent values (sine), >= 1.
    pub equivalent_cycles: usize,
}

impl Default for BenchOptions {
    fn default() -> Self {
        Self {
            steps_per_cycle: 4000,
            samples_per_cycle: 400,
            equivalent_cycles: 2,
        }
    }
}

/// Equivalent linear element of a sine test over the last full cycles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Equivalent {
    /// Quadrature (velocity-proportional) part c_eq (N·s/m).
    pub damping_nspm: f64,
    /// In-phase (displacement-proportional) part k_eq (N/m).
    pub stiffness_npm: f64,
    /// Energy dissipated per cycle (J).
    pub energy_per_cycle_j: f64,
}

/// What the bench records.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BenchRecord {
    /// Sample times (s).
    pub time_s: Vec<f64>,
    /// Elongation (m).
    pub displacement_m: Vec<f64>,
    /// Elongation rate (m/s).
    pub velocity_mps: Vec<f64>,
    /// Force (N, positive in tension).
    pub force_n: Vec<f64>,
    /// Frequency-valve scale factor (0 open, 1 closed; 1 without a valve).
    pub scale_factor: Vec<f64>,
    /// Trigger's frequency estimate (Hz; NaN without a valve or before it can judge).
    pub estimated_frequency_hz: Vec<f64>,
    /// Hydraulic trigger: volume displaced by the auxiliary piston (m³; 0 for other dampers).
    pub valve_volume_m3: Vec<f64>,
    /// Equivalent values (sine motion only).
    pub equivalent: Option<Equivalent>,
    /// Total energy dissipated over the run, `∫F·ẋ dt` (J).
    pub dissipated_energy_j: f64,
}

/// Runs `damper` through `motion`.
pub fn run(damper: &Damper, motion: &BenchMotion, options: &BenchOptions) -> Result<BenchRecord> {
    if options.steps_per_cycle < 8 || options.samples_per_cycle < 4 {
        return Err(LocoError::param(
            "steps_per_cycle",
            "need at least 8 steps and 4 samples per cycle",
        ));
    }
    let max_dt = 1.0 / damper.fastest_rate_per_s();
    match motion {
        BenchMotion::Sine {
            frequency_hz,
            amplitude_m,
            cycles,
        } => {
            let f = check_frequency("frequency_hz", *frequency_hz)?;
            let a = check_amplitude("amplitude_m", *amplitude_m)?;
            if *cycles < 1 || options.equivalent_cycles < 1 || options.equivalent_cycles > *cycles {
                return Err(LocoError::param(
                    "cycles",
                    format!(
                        "need cycles >= equivalent_cycles >= 1, got {cycles} and {}",
                        options.equivalent_cycles
                    ),
                ));
            }
            let w = TAU * f;
            let period = 1.0 / f;
            let substeps = substeps(
                period / options.samples_per_cycle as f64,
                max_dt,
                options,
                f,
            );
            let n_samples = cycles * options.samples_per_cycle;
            check_run_length((n_samples * substeps) as f64, damper)?;
            let dt = period / (options.samples_per_cycle * substeps) as f64;
            let first_averaged_step =
                (cycles - options.equivalent_cycles) * options.samples_per_cycle * substeps;
            let mut sums = [0.0; 3];
            let mut step_index = 0usize;
            let mut record = drive(
                damper,
                n_samples,
                substeps,
                dt,
                |t| (a * (w * t).sin(), a * w * (w * t).cos()),
                |t, force, v| {
                    if step_index >= first_averaged_step {
                        sums[0] += force * (w * t).sin() * dt;
                        sums[1] += force * (w * t).cos() * dt;
                        sums[2] += force * v * dt;
                    }
                    step_index += 1;
                },
            );
            let duration = options.equivalent_cycles as f64 * period;
            record.equivalent = Some(Equivalent {
                stiffness_npm: 2.0 * sums[0] / (a * duration),
                damping_nspm: 2.0 * sums[1] / (a * w * duration),
                energy_per_cycle_j: sums[2] / options.equivalent_cycles as f64,
            });
            Ok(record)
        }
        BenchMotion::Sweep {
            start_frequency_hz,
            end_frequency_hz,
            amplitude_m,
            duration_s,
        } => {
            let f0 = check_frequency("start_frequency_hz", *start_frequency_hz)?;
            let f1 = check_frequency("end_frequency_hz", *end_frequency_hz)?;
            let a = check_amplitude("amplitude_m", *amplitude_m)?;
            let duration = check_positive("duration_s", *duration_s)?;
            let f_max = f0.max(f1);
            let sample_dt = 1.0 / (f_max * options.samples_per_cycle as f64);
            let n_samples = (duration / sample_dt).ceil() as usize;
            let substeps = substeps(sample_dt, max_dt, options, f_max);
            check_run_length(n_samples as f64 * substeps as f64, damper)?;
            let dt = duration / (n_samples * substeps) as f64;
            let rate = (f1 - f0) / duration;
            Ok(drive(
                damper,
                n_samples,
                substeps,
                dt,
                |t| {
                    let phase = TAU * (f0 * t + 0.5 * rate * t * t);
                    let w = TAU * (f0 + rate * t);
                    (a * phase.sin(), a * w * phase.cos())
                },
                |_, _, _| {},
            ))
        }
        BenchMotion::Recorded {
            time_s,
            displacement_m,
        } => run_recorded(damper, time_s, displacement_m, max_dt),
    }
}
