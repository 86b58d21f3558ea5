//! The frequency-selective (FSD) yaw damper: a Maxwell damper whose damping switches between a
//! low value `c1` below the cut-off frequency `f_p` and a high value `c2` above it.
//!
//! # The four modules (spec §4)
//! 1. **Damping modules** c1 (valve open) and c2 (valve closed), linear laws.
//! 2. **Frequency valve**: open (flow through the bypass, low damping) or closed (high damping).
//! 3. **Trigger**, one of [`FsdTrigger`]: `"rms-frequency"` ([`super::fsd_trigger`]) estimates
//!    the frequency of the stroke and decides "low" or "high" with a hysteresis band around
//!    `f_p`; `"hydraulic"` ([`super::frequency_valve`]) is the mechanism: the damper force fills
//!    an auxiliary chamber through an orifice and its piston opens the bypass past its stroke
//!    (decision "low" while it is open). Either way the decision drives the same scale factor.
//! 4. **Scale factor** `s ∈ [0, 1]`: the damping is `c(s) = c1 + s·(c2 - c1)`; `s` moves toward
//!    the trigger's decision (1 for "high", 0 for "low") at the rate `1/switching_delay`, so a
//!    complete switch takes exactly the switching delay and a reversal half-way starts from where
//!    the valve is (no jump of the force).
//!
//! # State machine (discrete state, updated once per accepted time step)
//! Two coupled machines. The **trigger decision** `D ∈ {low, high}` (see
//! [`super::fsd_trigger`]): `low → high` when the estimated frequency exceeds `f_p·(1 + h)`,
//! `high → low` when it falls below `f_p·(1 - h)`, held otherwise, during the warm-up and while
//! the stroke is below the minimum rms. The **valve**, with the scale factor `s` as its timer:
//!
//! | valve state | scale factor | event | next state |
//! |---|---|---|---|
//! | `Open` | `s = 0` | `D` becomes high | `Closing` |
//! | `Closing` | `s` rises by `dt/delay` per step | `s` reaches 1 | `Closed` |
//! | `Closing` | | `D` becomes low | `Opening`, from the current `s` |
//! | `Closed` | `s = 1` | `D` becomes low | `Opening` |
//! | `Opening` | `s` falls by `dt/delay` per step | `s` reaches 0 | `Open` |
//! | `Opening` | | `D` becomes high | `Closing`, from the current `s` |
//!
//! - Start: `Closed` (s = 1, high damping c2, the damping of YD2: the state that keeps the bogie
//!   stable while nothing is known about the motion) unless [`FsdParams::start_closed`] is false;
//!   the trigger holds its start decision during its warm-up (0.75 s) and while the stroke is too
//!   small to judge, so a low-frequency stroke opens the valve about 0.8 s after the start.
//! - Timer: `s` changes by `dt/switching_delay_s` per step, so `Open → Closed` takes the delay.
//! - The scale factor is piecewise constant over a time step (the integrator's force stays a pure
//!   function of its states within the step).
//!
//! # Continuous model
//! The equivalent mass `m` sits at the node between the series spring `k` and the damper:
//! `F = k·(x - x_d)`, `m·ẍ_d = F - c(s)·ẋ_d`; states `[x_d, ẋ_d]`. With `m = 0` the node is
//! massless and the state is `[x_d]` with `ẋ_d = F/c(s)`. The closed form for a sine at ω is the
//! complex stiffness `k·(iωc - mω²)/(k - mω² + iωc)`. The mass adds a fast pole near `-c2/m`
//! (5.3e4 1/s for the spec values): explicit integrators need `dt < 2.78·m/c2 ≈ 5e-5 s`
//! ([`FsdDamper::fastest_rate_per_s`]).

use super::frequency_valve::HydraulicValve;
use super::fsd_trigger::{FsdTrigger, FsdTriggerParams, TriggerMemory};
use super::valve_design::ValveDesign;
use crate::error::{check_non_negative, check_positive, Result};
use crate::LocoError;
use std::sync::OnceLock;

pub use super::fsd_params::FsdParams;

/// Position of the frequency valve, derived from the scale factor and the trigger's decision.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValveState {
    /// s = 0: low damping c1.
    Open,
    /// 0 < s < 1 and moving toward 1.
    Closing,
    /// s = 1: high damping c2.
    Closed,
    /// 0 < s < 1 and moving toward 0.
    Opening,
}

/// A validated FSD damper; see the module documentation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FsdDamper {
    params: FsdParams,
    /// Series spring taken as rigid (the reduced law of [`super::Damper::for_step`], massless
    /// only): the force is `c(s)·ẋ`, no internal state.
    rigid_series: bool,
}

impl FsdDamper {
    /// Validates: c1, c2, k, f_p, delay finite and > 0, m finite and >= 0, c1 < c2, trigger.
    pub fn new(params: FsdParams) -> Result<Self> {
        check_positive("low_damping_nspm", params.low_damping_nspm)?;
        check_positive("high_damping_nspm", params.high_damping_nspm)?;
        if params.low_damping_nspm >= params.high_damping_nspm {
            return Err(LocoError::param(
                "low_damping_nspm",
                format!(
                    "c1 must be < c2 (high_damping_nspm = {}), got {}",
                    params.high_damping_nspm, params.low_damping_nspm
                ),
            ));
        }
        check_non_negative("equivalent_mass_kg", params.equivalent_mass_kg)?;
        check_positive("equivalent_stiffness_npm", params.equivalent_stiffness_npm)?;
        check_positive("cutoff_frequency_hz", params.cutoff_frequency_hz)?;
        check_positive("switching_delay_s", params.switching_delay_s)?;
        params.trigger.validate()?;
        Ok(Self {
            params,
            rigid_series: false,
        })
    }

    /// The spec's FSD yaw damper (§4).
    pub fn spec() -> Self {
        Self {
            params: FsdParams::default(),
            rigid_series: false,
        }
    }

    /// The spec's FSD with the hydraulic valve derived for its f_p at the measured reference
    /// stroke ([`super::frequency_valve::REFERENCE_STROKE_AMPLITUDE_M`]); derived once.
    pub fn spec_hydraulic() -> Self {
        static DERIVED: OnceLock<FsdDamper> = OnceLock::new();
        *DERIVED.get_or_init(|| {
            Self::spec()
                .with_hydraulic_valve(super::frequency_valve::REFERENCE_STROKE_AMPLITUDE_M)
                .expect("the spec's valve design is reachable (tested)")
        })
    }

    /// The same damper with the hydraulic valve derived for its f_p at the stroke amplitude
    /// `reference_stroke_amplitude_m` (m), the default geometry and f_l = f_p/4.
    pub fn with_hydraulic_valve(&self, reference_stroke_amplitude_m: f64) -> Result<Self> {
        let design = ValveDesign {
            cutoff_frequency_hz: self.params.cutoff_frequency_hz,
            lowest_holding_frequency_hz: self.params.cutoff_frequency_hz / 4.0,
            ..ValveDesign::spec(reference_stroke_amplitude_m)
        };
        let valve = design.derive(&self.params.closed_module(), &self.params.open_module())?;
        Ok(self.with_trigger(FsdTrigger::Hydraulic(valve)))
    }

    /// The same damper with another trigger.
    pub fn with_trigger(&self, trigger: FsdTrigger) -> Self {
        Self {
            params: FsdParams {
                trigger,
                ..self.params
            },
            ..*self
        }
    }

    /// The hydraulic valve, if that is the trigger.
    pub fn hydraulic_valve(&self) -> Option<&HydraulicValve> {
        match &self.params.trigger {
            FsdTrigger::Hydraulic(v) => Some(v),
            FsdTrigger::RmsFrequency(_) => None,
        }
    }

    /// The validated parameters.
    pub fn params(&self) -> &FsdParams {
        &self.params
    }

    /// Whether the series spring is taken as rigid (see [`super::Damper::for_step`]).
    pub fn has_rigid_series(&self) -> bool {
        self.rigid_series
    }

    /// The same damper without its equivalent mass.
    pub(crate) fn without_mass(self) -> Self {
        Self {
            params: FsdParams {
                equivalent_mass_kg: 0.0,
                ..self.params
            },
            ..self
        }
    }

    /// The same (massless) damper with its series spring rigid.
    pub(crate) fn with_rigid_series(self) -> Self {
        Self {
            rigid_series: true,
            ..self
        }
    }

    /// Number of continuous states: 2 (`x_d`, `ẋ_d`) with a mass, 1 (`x_d`) without, 0 with a
    /// rigid series spring.
    pub fn n_states(&self) -> usize {
        if self.rigid_series {
            0
        } else if self.params.equivalent_mass_kg > 0.0 {
            2
        } else {
            1
        }
    }

    /// Damping (N·s/m) at scale factor `s` (0 = open, 1 = closed).
    #[inline]
    pub fn damping_at(&self, scale_factor: f64) -> f64 {
        let p = &self.params;
        p.low_damping_nspm + scale_factor * (p.high_damping_nspm - p.low_damping_nspm)
    }

    /// Force (N, tension positive) and state derivatives for elongation `x` (m).
    #[inline]
    pub fn evaluate(
        &self,
        elongation_m: f64,
        states: &[f64],
        scale_factor: f64,
        dstates: &mut [f64],
    ) -> f64 {
        let p = &self.params;
        let force_n = p.equivalent_stiffness_npm * (elongation_m - states[0]);
        let damping = self.damping_at(scale_factor);
        if p.equivalent_mass_kg > 0.0 {
            dstates[0] = states[1];
            dstates[1] = (force_n - damping * states[1]) / p.equivalent_mass_kg;
        } else {
            dstates[0] = force_n / damping;
        }
        force_n
    }

    /// Moves the scale factor toward the trigger's decision after a step of `dt_s` (s), then
    /// lets the trigger judge the end of the step: the stroke (rms-frequency) or the damper
    /// force `force_n` (N, hydraulic).
    pub fn advance_valve(
        &self,
        trigger: &mut TriggerMemory,
        scale_factor: &mut f64,
        dt_s: f64,
        elongation_m: f64,
        elongation_rate_mps: f64,
        force_n: f64,
    ) {
        let p = &self.params;
        match &p.trigger {
            FsdTrigger::RmsFrequency(t) => advance_scale_factor(
                trigger,
                scale_factor,
                t,
                p.cutoff_frequency_hz,
                p.switching_delay_s,
                dt_s,
                elongation_m,
                elongation_rate_mps,
            ),
            FsdTrigger::Hydraulic(valve) => {
                ramp_scale_factor(
                    scale_factor,
                    trigger.high_frequency,
                    dt_s,
                    p.switching_delay_s,
                );
                if dt_s > 0.0 && force_n.is_finite() {
                    trigger.valve_volume_m3 = valve.step(trigger.valve_volume_m3, force_n, dt_s);
                }
                trigger.high_frequency = !valve.is_open(trigger.valve_volume_m3);
            }
        }
    }

    /// The force (N) at the end of a step from the elongation rate (m/s), the continuous states
    /// and the scale factor (what the hydraulic valve's pressure comes from).
    #[inline]
    pub fn force_from_states(
        &self,
        elongation_m: f64,
        rate_mps: f64,
        states: &[f64],
        s: f64,
    ) -> f64 {
        if self.rigid_series {
            self.damping_at(s) * rate_mps
        } else {
            self.params.equivalent_stiffness_npm * (elongation_m - states[0])
        }
    }

    /// Valve position from the scale factor and the trigger's decision.
    pub fn valve_state(scale_factor: f64, high_frequency: bool) -> ValveState {
        if scale_factor <= 0.0 {
            if high_frequency {
                ValveState::Closing
            } else {
                ValveState::Open
            }
        } else if scale_factor >= 1.0 {
            if high_frequency {
                ValveState::Closed
            } else {
                ValveState::Opening
            }
        } else if high_frequency {
            ValveState::Closing
        } else {
            ValveState::Opening
        }
    }

    /// Fastest decay rate of the internal states (1/s), for the choice of an explicit step; 0
    /// with a rigid series spring (no internal state).
    pub fn fastest_rate_per_s(&self) -> f64 {
        let p = &self.params;
        let (m, k) = (p.equivalent_mass_kg, p.equivalent_stiffness_npm);
        if self.rigid_series {
            0.0
        } else if m > 0.0 {
            let c = p.high_damping_nspm;
            let discriminant = c * c - 4.0 * m * k;
            if discriminant >= 0.0 {
                (c + discriminant.sqrt()) / (2.0 * m)
            } else {
                (k / m).sqrt()
            }
        } else {
            k / p.low_damping_nspm
        }
    }
}

/// The valve and scale-factor update shared by the FSD and the hydraulic frequency valve: the
/// valve moves during the step that just ended toward the decision in force during it, then the
/// trigger judges the stroke; a decision taken at the end of step n acts from step n + 1 on, and
/// a complete switch ends exactly `switching_delay_s` after the decision.
#[allow(clippy::too_many_arguments)]
pub(crate) fn advance_scale_factor(
    trigger: &mut TriggerMemory,
    scale_factor: &mut f64,
    trigger_params: &FsdTriggerParams,
    cutoff_frequency_hz: f64,
    switching_delay_s: f64,
    dt_s: f64,
    elongation_m: f64,
    elongation_rate_mps: f64,
) {
    ramp_scale_factor(
        scale_factor,
        trigger.high_frequency,
        dt_s,
        switching_delay_s,
    );
    trigger.update(
        trigger_params,
        cutoff_frequency_hz,
        dt_s,
        elongation_m,
        elongation_rate_mps,
    );
}

/// Moves the scale factor during a step of `dt_s` (s) toward the decision (1 closed for
/// "high", 0 open) at `1/switching_delay_s` (1/s).
#[inline]
pub(crate) fn ramp_scale_factor(
    scale_factor: &mut f64,
    high_frequency: bool,
    dt_s: f64,
    switching_delay_s: f64,
) {
    let target = if high_frequency { 1.0 } else { 0.0 };
    let step = dt_s.max(0.0) / switching_delay_s;
    *scale_factor = if target > *scale_factor {
        (*scale_factor + step).min(target)
    } else {
        (*scale_factor - step).max(target)
    };
}

#[cfg(test)]
mod tests;
