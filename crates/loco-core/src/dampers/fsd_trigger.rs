//! The trigger module of the FSD damper: estimates the frequency of the motion that carries the
//! damper's stroke and decides whether the excitation is below or above the cut-off `f_p`.
//!
//! # Estimator
//! The dominant frequency is taken as `f = (1/2π)·sqrt(<v²>/<x²>)`, the ratio of the rms velocity
//! to the rms displacement of the stroke. For one sine it is exact whatever the amplitude. For a
//! mixture of tones `x = Σ A_i sin(ω_i t)` it gives `ω² = Σ A_i²ω_i² / Σ A_i²`, an average weighted
//! by the square of each tone's displacement amplitude: a small fast ripple on a large slow stroke
//! barely moves it (1 Hz stroke + 5 Hz ripple of a tenth of its amplitude: 1.11 Hz), whereas
//! counting zero crossings would be fooled by every ripple crossing.
//!
//! - `x` and `v` are the elongation and elongation rate passed through the same second-order
//!   high-pass (two first-order stages, corner `highpass_corner_hz`), which removes the static
//!   length and slow drift (at the default 0.5 Hz corner a 0.3 Hz drift keeps 0.11 of its power,
//!   a 1 Hz stroke 0.94). A common filter on `x` and `v` leaves a single tone's ratio exact.
//! - Limits of the two-tone cases (analysis above, checked in the tests): a 5 Hz ripple up to a
//!   quarter of a 1 Hz stroke's amplitude keeps the valve open; a 5 Hz motion keeps it closed on
//!   a 0.3 Hz drift up to six times its amplitude.
//! - `<·>` is a second-order low-pass (two first-order stages, time constant
//!   `averaging_time_s` each) of the squared signals. The squares of `x` and `v` oscillate in
//!   antiphase at twice the excitation frequency; the two stages attenuate that ripple by
//!   `g = 1/(1 + (4π·f·τ)²)` and the estimate stays within about `±g`: ±3 % at 1.8 Hz, ±9 % at
//!   1 Hz, ±17 % at 0.7 Hz with the default 0.25 s (far from f_p, where it does not matter).
//!
//! Filters are discretised exactly for a first-order stage (`α = 1 - exp(-dt/τ)`), so the trigger
//! is independent of the time step as long as `dt` is small against `τ`.
//!
//! # Decision (hysteresis)
//! Above `f_p·(1 + hysteresis_ratio)` the excitation is "high" (valve closes), below
//! `f_p·(1 - hysteresis_ratio)` it is "low" (valve opens), in between the last decision holds.
//! The default ±10 % band is wider than the estimator ripple near `f_p` (±3 %), so a steady sine
//! at the cut-off cannot chatter. The decision also holds while the rms stroke is below
//! `min_stroke_rms_m` (the ratio is meaningless in noise) and during the first
//! `warmup_time_s` (the averages are not yet filled).

use super::frequency_valve::HydraulicValve;
use crate::error::{check_non_negative, check_positive, Result};

/// How the FSD decides its valve: the rms-frequency estimate of this module, or the hydraulic
/// mechanism of [`super::frequency_valve`]. The names ([`FsdTrigger::NAMES`]) are the one spelling
/// of every front end (Python `trigger=`, the study file's `fsd_trigger`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FsdTrigger {
    /// `"rms-frequency"`: frequency estimate sqrt(<v²>/<x²>) with hysteresis (this module).
    RmsFrequency(FsdTriggerParams),
    /// `"hydraulic"`: auxiliary chamber, orifice and spring-returned piston.
    Hydraulic(HydraulicValve),
}

impl FsdTrigger {
    /// Name of the rms-frequency estimator.
    pub const RMS_FREQUENCY: &'static str = "rms-frequency";
    /// Name of the hydraulic valve.
    pub const HYDRAULIC: &'static str = "hydraulic";
    /// Every trigger name, the default first.
    pub const NAMES: [&'static str; 2] = [Self::RMS_FREQUENCY, Self::HYDRAULIC];
    /// The default trigger's name (the spec's FSD preset).
    pub const DEFAULT: &'static str = Self::RMS_FREQUENCY;

    /// This trigger's name.
    pub fn name(&self) -> &'static str {
        match self {
            Self::RmsFrequency(_) => Self::RMS_FREQUENCY,
            Self::Hydraulic(_) => Self::HYDRAULIC,
        }
    }

    /// Checks the parameters of either kind.
    pub fn validate(&self) -> Result<()> {
        match self {
            Self::RmsFrequency(p) => p.validate(),
            // Validated on construction.
            Self::Hydraulic(_) => Ok(()),
        }
    }

    /// Refuses a name that is not in [`FsdTrigger::NAMES`], naming the field `trigger`.
    pub fn check_name(name: &str) -> Result<&'static str> {
        Self::NAMES.into_iter().find(|n| *n == name).ok_or_else(|| {
            crate::LocoError::param(
                "trigger",
                format!(
                    "unknown FSD trigger '{name}' (expected {})",
                    Self::NAMES.join(", ")
                ),
            )
        })
    }
}

impl Default for FsdTrigger {
    fn default() -> Self {
        Self::RmsFrequency(FsdTriggerParams::default())
    }
}

/// Tuning of the FSD trigger. The defaults are design values chosen from the estimator analysis
/// in the module documentation (no published trigger law exists for this abstract FSD model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FsdTriggerParams {
    /// Corner of the second-order high-pass on the stroke (Hz), > 0. Default 0.5 Hz = f_p/4.
    pub highpass_corner_hz: f64,
    /// Time constant of each of the two averaging stages of the mean squares (s), > 0.
    /// Default 0.25 s (half a period at f_p = 2 Hz).
    pub averaging_time_s: f64,
    /// Relative half-width of the hysteresis band around f_p, in [0, 1). Default 0.1.
    pub hysteresis_ratio: f64,
    /// Rms stroke (m) below which the decision is held, >= 0. Default 0.01 mm.
    pub min_stroke_rms_m: f64,
    /// Time after start (s) during which the start decision is held, >= 0. Default 0.75 s
    /// (three averaging time constants).
    pub warmup_time_s: f64,
}

impl Default for FsdTriggerParams {
    fn default() -> Self {
        Self {
            highpass_corner_hz: 0.5,
            averaging_time_s: 0.25,
            hysteresis_ratio: 0.1,
            min_stroke_rms_m: 1e-5,
            warmup_time_s: 0.75,
        }
    }
}

impl FsdTriggerParams {
    /// Checks every field (the error names it).
    pub fn validate(&self) -> Result<()> {
        check_positive("highpass_corner_hz", self.highpass_corner_hz)?;
        check_positive("averaging_time_s", self.averaging_time_s)?;
        check_non_negative("hysteresis_ratio", self.hysteresis_ratio)?;
        if self.hysteresis_ratio >= 1.0 {
            return Err(crate::LocoError::param(
                "hysteresis_ratio",
                format!("must be < 1, got {}", self.hysteresis_ratio),
            ));
        }
        check_non_negative("min_stroke_rms_m", self.min_stroke_rms_m)?;
        check_non_negative("warmup_time_s", self.warmup_time_s)?;
        Ok(())
    }
}

/// The trigger's memory: filter states, elapsed time and the current decision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TriggerMemory {
    /// False until the first update, which seeds the high-pass with the current elongation.
    pub started: bool,
    /// Time since the first update (s).
    pub elapsed_s: f64,
    /// Low-pass states of the two high-pass stages on the elongation (m).
    pub stroke_lowpass_m: [f64; 2],
    /// Low-pass states of the two high-pass stages on the elongation rate (m/s).
    pub rate_lowpass_mps: [f64; 2],
    /// Two-stage averaged square of the high-passed stroke (m²).
    pub stroke_mean_square_m2: [f64; 2],
    /// Two-stage averaged square of the high-passed rate (m²/s²).
    pub rate_mean_square_m2ps2: [f64; 2],
    /// Latest frequency estimate (Hz); NaN until the stroke is large enough to judge.
    pub estimated_frequency_hz: f64,
    /// Current decision: true when the excitation is judged above the cut-off (valve closed).
    pub high_frequency: bool,
    /// Hydraulic trigger only: volume displaced by the auxiliary piston from its centre (m³).
    pub valve_volume_m3: f64,
}

impl TriggerMemory {
    /// Memory at start with the given decision.
    pub fn new(high_frequency: bool) -> Self {
        Self {
            started: false,
            elapsed_s: 0.0,
            stroke_lowpass_m: [0.0; 2],
            rate_lowpass_mps: [0.0; 2],
            stroke_mean_square_m2: [0.0; 2],
            rate_mean_square_m2ps2: [0.0; 2],
            estimated_frequency_hz: f64::NAN,
            high_frequency,
            valve_volume_m3: 0.0,
        }
    }

    /// Feeds one accepted time step `dt_s` (s) ending at elongation `x` (m) and rate `v` (m/s);
    /// updates the estimate and the decision with the cut-off `cutoff_hz`.
    pub fn update(
        &mut self,
        params: &FsdTriggerParams,
        cutoff_hz: f64,
        dt_s: f64,
        elongation_m: f64,
        elongation_rate_mps: f64,
    ) {
        if !self.started {
            // The static length at start is taken as the stroke's centre: no high-pass transient.
            self.stroke_lowpass_m = [elongation_m, 0.0];
            self.started = true;
        }
        if dt_s.is_nan()
            || dt_s <= 0.0
            || !elongation_m.is_finite()
            || !elongation_rate_mps.is_finite()
        {
            return;
        }
        self.elapsed_s += dt_s;
        let highpass_tau = 1.0 / (std::f64::consts::TAU * params.highpass_corner_hz);
        let alpha_hp = 1.0 - (-dt_s / highpass_tau).exp();
        let alpha_avg = 1.0 - (-dt_s / params.averaging_time_s).exp();
        let x = highpass2(&mut self.stroke_lowpass_m, alpha_hp, elongation_m);
        let v = highpass2(&mut self.rate_lowpass_mps, alpha_hp, elongation_rate_mps);
        let msx = lowpass2(&mut self.stroke_mean_square_m2, alpha_avg, x * x);
        let msv = lowpass2(&mut self.rate_mean_square_m2ps2, alpha_avg, v * v);
        let gate = params.min_stroke_rms_m * params.min_stroke_rms_m;
        if msx.is_nan() || msx <= gate || msx <= 0.0 {
            return;
        }
        let f = (msv / msx).sqrt() / std::f64::consts::TAU;
        self.estimated_frequency_hz = f;
        if self.elapsed_s < params.warmup_time_s {
            return;
        }
        if f > cutoff_hz * (1.0 + params.hysteresis_ratio) {
            self.high_frequency = true;
        } else if f < cutoff_hz * (1.0 - params.hysteresis_ratio) {
            self.high_frequency = false;
        }
    }
}

/// Two cascaded first-order high-passes `y = u - lowpass(u)`; returns the output.
#[inline]
fn highpass2(lowpass: &mut [f64; 2], alpha: f64, input: f64) -> f64 {
    lowpass[0] += alpha * (input - lowpass[0]);
    let first = input - lowpass[0];
    lowpass[1] += alpha * (first - lowpass[1]);
    first - lowpass[1]
}

/// Two cascaded first-order low-passes; returns the output of the second.
#[inline]
fn lowpass2(state: &mut [f64; 2], alpha: f64, input: f64) -> f64 {
    state[0] += alpha * (input - state[0]);
    state[1] += alpha * (state[0] - state[1]);
    state[1]
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    /// Runs the trigger on `x(t)` for `duration` s at 1 kHz; returns the memory and the number
    /// of decision changes after the warm-up.
    fn run(
        x: impl Fn(f64) -> (f64, f64),
        start_high: bool,
        duration: f64,
    ) -> (TriggerMemory, usize) {
        let params = FsdTriggerParams::default();
        let mut memory = TriggerMemory::new(start_high);
        let dt = 1e-3;
        let mut changes = 0;
        let mut last = memory.high_frequency;
        let (x0, v0) = x(0.0);
        memory.update(&params, 2.0, 0.0, x0, v0);
        for i in 1..=(duration / dt) as usize {
            let (xi, vi) = x(i as f64 * dt);
            memory.update(&params, 2.0, dt, xi, vi);
            if memory.high_frequency != last {
                changes += 1;
                last = memory.high_frequency;
            }
        }
        (memory, changes)
    }

    #[test]
    fn single_tone_estimate_is_its_frequency() {
        for f in [0.7, 1.3, 3.0, 6.0] {
            let (m, _) = run(
                |t| {
                    (
                        3e-3 * (TAU * f * t).sin(),
                        3e-3 * TAU * f * (TAU * f * t).cos(),
                    )
                },
                true,
                20.0,
            );
            // Residual ripple of the two-stage average: the mean squares of x and v oscillate in
            // antiphase at 2f, attenuated by g = 1/(1 + (4πfτ)²), so the estimate stays within
            // about ±g of f.
            let g = 1.0 / (1.0 + (2.0 * TAU * f * 0.25_f64).powi(2));
            let err = (m.estimated_frequency_hz - f).abs() / f;
            assert!(
                err < 1.1 * g + 0.005,
                "f = {f}: estimate {}",
                m.estimated_frequency_hz
            );
            assert_eq!(m.high_frequency, f > 2.0, "f = {f}");
        }
    }

    #[test]
    fn no_chattering_at_the_cutoff() {
        for f in [1.9, 2.0, 2.1] {
            let (_, changes) = run(
                |t| {
                    (
                        2e-3 * (TAU * f * t).sin(),
                        2e-3 * TAU * f * (TAU * f * t).cos(),
                    )
                },
                true,
                30.0,
            );
            assert_eq!(
                changes, 0,
                "steady sine at {f} Hz inside the band changed the decision"
            );
        }
    }

    #[test]
    fn invalid_params_are_named() {
        let p = FsdTriggerParams {
            hysteresis_ratio: 1.5,
            ..Default::default()
        };
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("hysteresis_ratio"));
        let p = FsdTriggerParams {
            averaging_time_s: 0.0,
            ..Default::default()
        };
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("averaging_time_s"));
    }
}
