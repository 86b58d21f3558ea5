//! Dampers: Maxwell elements, the frequency-selective (FSD) yaw damper, the hydraulic orifice
//! model and a bench that drives any of them.
//!
//! # Interface for the vehicle model
//! A [`Damper`] is an immutable, `Copy` parameter value (validated on construction; presets
//! [`Damper::yd1`], [`Damper::yd2`], [`Damper::fsd`]). Its state lives with the caller:
//!
//! - **Continuous states**: [`Damper::n_states`] (≤ [`MAX_STATES`]) values that the vehicle's
//!   integrator owns and integrates with its own states; [`Damper::initial_states`] fills them
//!   (zero: no force at zero elongation). Maxwell: `[x_d]`, the deflection of the damper element;
//!   FSD with mass: `[x_d, ẋ_d]`; hydraulic: `[x_d]`.
//! - **Discrete state**: a small `Copy` [`DamperDiscreteState`] (FSD valve scale factor, trigger
//!   filters and decision, the hydraulic valve's chamber volume), from
//!   [`Damper::initial_discrete`], updated by [`Damper::advance`] once per *accepted* time step
//!   (never inside the stages of a Runge-Kutta step or a rejected step). The hydraulic valve is
//!   integrated there (implicit Euler, with the force at the end of the step): slow against the
//!   step (its fastest rate, laminar conductance over chamber compliance, is about 10² 1/s).
//! - **Force**: [`Damper::evaluate`] is pure and allocation-free: from the elongation `x` (m, the
//!   change of the distance between the two attachment points from its static value), the
//!   elongation rate (m/s), the continuous states and the discrete state it returns the force (N)
//!   and writes the state derivatives into `dstates`.
//!
//! **Sign**: the force is positive in **tension**: it resists elongation (positive when `x` or
//! `ẋ` grows), so it pulls the two attachment points toward each other. The vehicle applies
//! `+F·e` to the body at the first end and `-F·e` to the other, with `e` the unit vector from the
//! first end to the second.
//!
//! **Step size**: [`Damper::fastest_rate_per_s`] is the magnitude of the fastest internal pole; an
//! explicit integrator needs roughly `dt·rate < 2.7` (RK4). The spec's FSD with its 15 kg
//! equivalent mass has a pole near `-c2/m = -5.3e4 1/s` (dt < 5e-5 s); the Maxwell presets are
//! slow (`k/c` = 28–113 1/s). [`Damper::for_step`] gives the law an explicit integrator with a
//! given step uses (below).
//!
//! # Reduced laws for a step
//! An explicit integrator carries an internal pole of rate `r` (1/s) at step `dt` when
//! `r·dt ≤` [`MAX_RATE_STEP`]. [`Damper::for_step`] returns the law itself when its fastest pole
//! fits, and otherwise a reduced law (singular perturbations), or a typed `step` error:
//!
//! 1. **FSD without its mass.** The FSD's equivalent mass (15 kg against 15 kN/mm and up to
//!    800 kN·s/m) adds a pole at −c2/m ≈ −5·10⁴ 1/s, a 19 µs lag. Its effect on the force at
//!    frequency f is of relative order m·(2πf)²/k: 0.4 % at 10 Hz, 10⁻⁴ at 2 Hz. When the pole
//!    does not fit, the mass is left out (and the massless law is checked again below).
//! 2. **Rigid series spring.** A Maxwell element (series spring `k`, N/m, damper `c`, N·s/m; a
//!    massless FSD alike with `c(s)`) has an internal pole at `−k/c`. SPEC §6 reaches
//!    `k/c = 5·10³ 1/s` (C_sy = 10 kN·s/m with K_ncsy = 50 kN/mm). When even the slowest pole,
//!    `k/c_max` with `c_max` the largest slope of the law, does not fit (`k/c_max·dt >`
//!    [`MAX_RATE_STEP`]), the spring is far stiffer than the damper at every frequency a vehicle
//!    responds to and the element is the pure damper `F = c·ẋ` (the limit `c/k → 0`, no internal
//!    state). Error bound, from the complex stiffness of the Maxwell element
//!    `k·iωc/(k + iωc) = iωc/(1 + iε)` with `ε = ωc/k` (ω in rad/s):
//!    - dissipation: the equivalent damping is `c/(1 + ε²)`, so the rigid form dissipates a
//!      fraction `ε²` more energy per cycle;
//!    - force: the Maxwell force lags the damper force by `atan ε`, the difference is at most `ε`
//!      times the force amplitude (the series spring's in-phase stiffness `k·ε²/(1 + ε²)` is left
//!      out).
//!
//!    As `k/c_max·dt > 2.5`, `ε < ω·dt/2.5`: at a 1 ms step ε < 0.005 at 2 Hz, 0.025 at 10 Hz and
//!    0.05 at 20 Hz (dissipation 2.5·10⁻⁵, 6·10⁻⁴, 2.5·10⁻³). At the C_sy/K_ncsy corner itself
//!    (`c/k = 2·10⁻⁴ s`) ε is half of that.
//! 3. A law stiff only in part of its range (a blow-off slope much smaller than the slope below
//!    the knee) or whose slope has no upper bound (the hydraulic orifice law) is refused with a
//!    typed `step` error giving the longest step that fits.
//!
//! The bench keeps the full model.
//!
//! ```
//! use loco_core::dampers::{Damper, MAX_STATES};
//! let damper = Damper::fsd();
//! let mut states = [0.0; MAX_STATES];
//! let mut dstates = [0.0; MAX_STATES];
//! let n = damper.n_states();
//! damper.initial_states(&mut states[..n]);
//! let mut discrete = damper.initial_discrete();
//! let (dt, x, v) = (1e-5, 1e-3, 0.01);
//! let force = damper.evaluate(x, v, &states[..n], &discrete, &mut dstates[..n]);
//! // ... the integrator advances `states` with `dstates`, then, once the step is accepted:
//! damper.advance(&mut discrete, dt, dt, x, v, &states[..n]);
//! assert!(force > 0.0);
//! ```
//!
//! Submodules: [`maxwell`] (linear or blow-off law), [`fsd`] (the FSD and its state machine),
//! [`fsd_trigger`] (frequency estimation and hysteresis, the choice of trigger),
//! [`frequency_valve`] (the hydraulic frequency valve, trigger `"hydraulic"`), [`hydraulic`] (orifice model, optional
//! frequency valve), [`bench`](mod@bench) (sine, sweep or recorded excitation, equivalent values).

pub mod bench;
pub mod damping_module;
pub mod frequency_valve;
pub mod fsd;
pub mod fsd_params;
pub mod fsd_trigger;
pub mod hydraulic;
pub mod maxwell;
pub mod valve_design;

pub use damping_module::ClosedModule;
pub use frequency_valve::{HydraulicValve, HydraulicValveParams, REFERENCE_STROKE_AMPLITUDE_M};
pub use fsd::{FsdDamper, FsdParams, ValveState};
pub use fsd_trigger::{FsdTrigger, FsdTriggerParams, TriggerMemory};
pub use hydraulic::{HydraulicDamper, HydraulicFrequencyValve, HydraulicParams};
pub use maxwell::{BlowOff, MaxwellDamper, MaxwellParams};
pub use valve_design::ValveDesign;

use crate::error::{LocoError, Result};

/// The largest [`Damper::n_states`] of any damper: size fixed arrays with it.
pub const MAX_STATES: usize = 2;

/// Largest `rate·dt` of an internal pole (rate in 1/s, dt in s) that an explicit RK4 step
/// carries: inside RK4's real-axis stability limit (2.785) with a margin. The one threshold of
/// [`Damper::for_step`].
pub const MAX_RATE_STEP: f64 = 2.5;

/// Any damper of the crate; see the module documentation for the interface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Damper {
    /// Spring in series with a linear or blow-off damper.
    Maxwell(MaxwellDamper),
    /// Frequency-selective damper (c1/c2 switched by a frequency valve).
    Fsd(FsdDamper),
    /// Hydraulic orifice model in series with a spring, optionally with a frequency valve.
    Hydraulic(HydraulicDamper),
}

/// The discrete state of a damper, updated once per accepted step by [`Damper::advance`].
/// Dampers without a frequency valve keep it constant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DamperDiscreteState {
    /// Frequency-valve scale factor: 0 open (low damping), 1 closed (high damping); 1 for
    /// dampers without a valve.
    pub scale_factor: f64,
    /// The trigger's filters and decision (unused without a valve).
    pub trigger: TriggerMemory,
}

impl Damper {
    /// Conventional yaw damper YD1: Maxwell, 200 kN·s/m, 22.5 kN/mm.
    pub fn yd1() -> Self {
        Self::Maxwell(MaxwellDamper::yd1())
    }

    /// Conventional yaw damper YD2: Maxwell, 800 kN·s/m, 22.5 kN/mm.
    pub fn yd2() -> Self {
        Self::Maxwell(MaxwellDamper::yd2())
    }

    /// The spec's FSD yaw damper (c1 = 200, c2 = 800 kN·s/m, m = 15 kg, k = 15 kN/mm,
    /// f_p = 2 Hz, switching delay 0.05 s).
    pub fn fsd() -> Self {
        Self::Fsd(FsdDamper::spec())
    }

    /// The spec's FSD with the hydraulic frequency valve (trigger `"hydraulic"`) derived for
    /// f_p = 2 Hz at [`REFERENCE_STROKE_AMPLITUDE_M`].
    pub fn fsd_hydraulic() -> Self {
        Self::Fsd(FsdDamper::spec_hydraulic())
    }

    /// Number of continuous states (≤ [`MAX_STATES`]; 0 with a rigid series spring).
    pub fn n_states(&self) -> usize {
        match self {
            Self::Maxwell(d) if d.has_rigid_series() => 0,
            Self::Maxwell(_) | Self::Hydraulic(_) => 1,
            Self::Fsd(d) => d.n_states(),
        }
    }

    /// Whether this is a reduced law with a rigid series spring ([`Damper::for_step`]).
    pub fn has_rigid_series(&self) -> bool {
        match self {
            Self::Maxwell(d) => d.has_rigid_series(),
            Self::Fsd(d) => d.has_rigid_series(),
            Self::Hydraulic(_) => false,
        }
    }

    /// The law an explicit integrator with step `dt` (s) uses: the law itself when its fastest
    /// internal pole fits the step (`rate·dt ≤` [`MAX_RATE_STEP`]), otherwise the reduced law of
    /// the module documentation (FSD without its mass; a series spring rigid, no internal state),
    /// or an `InvalidParameter` error on `step` when no reduced law applies.
    pub fn for_step(&self, dt: f64) -> Result<Self> {
        let fits = |law: &Self| law.fastest_rate_per_s() * dt <= MAX_RATE_STEP;
        let law = match *self {
            Self::Fsd(d) if d.params().equivalent_mass_kg > 0.0 && !fits(self) => {
                Self::Fsd(d.without_mass())
            }
            other => other,
        };
        if fits(&law) {
            return Ok(law);
        }
        // The slowest internal pole, k/c_max (validation keeps a blow-off slope at or below the
        // damping under the knee).
        let rigid = match law {
            Self::Maxwell(d) => {
                let p = d.params();
                (p.series_stiffness_npm / p.damping_nspm * dt > MAX_RATE_STEP)
                    .then(|| Self::Maxwell(d.with_rigid_series()))
            }
            Self::Fsd(d) => {
                let p = d.params();
                (p.equivalent_stiffness_npm / p.high_damping_nspm * dt > MAX_RATE_STEP)
                    .then(|| Self::Fsd(d.with_rigid_series()))
            }
            Self::Hydraulic(_) => None,
        };
        rigid.ok_or_else(|| {
            let fastest = law.fastest_rate_per_s();
            LocoError::param(
                "step",
                format!(
                    "{dt} s is too long for the damper (internal rate {fastest:.3e} 1/s, not stiff \
                     over its whole law); use < {:.2e} s",
                    MAX_RATE_STEP / fastest
                ),
            )
        })
    }

    /// The decay rate `r` (1/s) of the internal state where the law is linear in it, a linear
    /// Maxwell element with a compliant series spring (`ẋ_d = r·(x − x_d)`, `r = k/c`): the
    /// exponential scheme solves that state exactly at any step
    /// ([`crate::vehicle::time::exponential_rk4`]). `None` for every other law.
    pub fn linear_state_rate_per_s(&self) -> Option<f64> {
        match self {
            Self::Maxwell(d) if !d.has_rigid_series() && d.params().blow_off.is_none() => {
                Some(d.fastest_rate_per_s())
            }
            _ => None,
        }
    }

    /// Writes the initial continuous states (zero deflection and velocity: no force at rest).
    pub fn initial_states(&self, states: &mut [f64]) {
        states.iter_mut().for_each(|s| *s = 0.0);
    }

    /// The discrete state at start (valve position from the parameters' `start_closed`).
    pub fn initial_discrete(&self) -> DamperDiscreteState {
        let start_closed = match self {
            Self::Maxwell(_) => true,
            Self::Fsd(d) => d.params().start_closed,
            Self::Hydraulic(d) => d.params().frequency_valve.is_none_or(|v| v.start_closed),
        };
        DamperDiscreteState {
            scale_factor: if start_closed { 1.0 } else { 0.0 },
            trigger: TriggerMemory::new(start_closed),
        }
    }

    /// Force (N, positive in tension) for elongation `x` (m) and elongation rate (m/s), and the
    /// derivatives of the continuous states written into `dstates` (same length as `states`,
    /// [`Damper::n_states`]). Pure, no allocation.
    // Always inlined: the vehicle's damper loop calls it for every damper and evaluation, and
    // whether the plain hint was taken changed with unrelated code (3.5e1 instructions of call
    // overhead per damper, 1e7 per 500 m run).
    #[inline(always)]
    pub fn evaluate(
        &self,
        elongation_m: f64,
        elongation_rate_mps: f64,
        states: &[f64],
        discrete: &DamperDiscreteState,
        dstates: &mut [f64],
    ) -> f64 {
        // Series elements: the force depends on the elongation and the internal states only;
        // the elongation rate enters through the integration of the states, or directly when
        // the series spring is rigid (the damper element at the elongation rate).
        match self {
            Self::Maxwell(d) if d.has_rigid_series() => d.damper_force(elongation_rate_mps),
            Self::Fsd(d) if d.has_rigid_series() => {
                d.damping_at(discrete.scale_factor) * elongation_rate_mps
            }
            Self::Maxwell(d) => {
                let (force_n, rate) = d.force_and_rate(elongation_m, states[0]);
                dstates[0] = rate;
                force_n
            }
            Self::Fsd(d) => d.evaluate(elongation_m, states, discrete.scale_factor, dstates),
            Self::Hydraulic(d) => {
                let laws = d.laws_at(discrete.scale_factor);
                let (force_n, rate) = d.force_and_rate(elongation_m, states[0], &laws);
                dstates[0] = rate;
                force_n
            }
        }
    }

    /// Updates the discrete state after an accepted step of `dt_s` (s) that ended at time `t_s`
    /// (s) with elongation `x` (m), elongation rate (m/s) and continuous states `states`.
    pub fn advance(
        &self,
        discrete: &mut DamperDiscreteState,
        t_s: f64,
        dt_s: f64,
        elongation_m: f64,
        elongation_rate_mps: f64,
        states: &[f64],
    ) {
        let _ = t_s;
        match self {
            Self::Maxwell(_) => {}
            Self::Fsd(d) => {
                // The hydraulic valve's pressure is made by the force at the end of the step.
                let force_n = if d.hydraulic_valve().is_some() {
                    d.force_from_states(
                        elongation_m,
                        elongation_rate_mps,
                        states,
                        discrete.scale_factor,
                    )
                } else {
                    0.0
                };
                d.advance_valve(
                    &mut discrete.trigger,
                    &mut discrete.scale_factor,
                    dt_s,
                    elongation_m,
                    elongation_rate_mps,
                    force_n,
                )
            }
            Self::Hydraulic(d) => {
                if let Some(valve) = d.params().frequency_valve {
                    fsd::advance_scale_factor(
                        &mut discrete.trigger,
                        &mut discrete.scale_factor,
                        &valve.trigger,
                        valve.cutoff_frequency_hz,
                        valve.switching_delay_s,
                        dt_s,
                        elongation_m,
                        elongation_rate_mps,
                    );
                }
            }
        }
    }

    /// Whether the damper has a frequency valve: only then does [`Self::advance`] change its
    /// discrete state, so that the step's end need not form the other dampers' strokes.
    pub fn has_valve(&self) -> bool {
        match self {
            Self::Maxwell(_) => false,
            Self::Fsd(_) => true,
            Self::Hydraulic(d) => d.params().frequency_valve.is_some(),
        }
    }

    /// Valve position for dampers with a frequency valve, `None` otherwise.
    pub fn valve_state(&self, discrete: &DamperDiscreteState) -> Option<ValveState> {
        self.has_valve()
            .then(|| FsdDamper::valve_state(discrete.scale_factor, discrete.trigger.high_frequency))
    }

    /// Magnitude of the fastest internal pole (1/s), for the choice of an explicit time step.
    pub fn fastest_rate_per_s(&self) -> f64 {
        match self {
            Self::Maxwell(d) => d.fastest_rate_per_s(),
            Self::Fsd(d) => d.fastest_rate_per_s(),
            Self::Hydraulic(d) => d.fastest_rate_per_s(),
        }
    }
}

/// A Maxwell damper that is stiff only above its knee (800 kN·s/m, 22.5 MN/m series spring,
/// blow-off at 0.02 m/s to 4 kN·s/m): a law with no rigid form, for the tests of too long a step.
#[cfg(test)]
pub(crate) fn stiff_above_the_knee() -> Damper {
    Damper::Maxwell(
        MaxwellDamper::new(MaxwellParams {
            damping_nspm: 800e3,
            series_stiffness_npm: 22.5e6,
            blow_off: Some(BlowOff {
                knee_velocity_mps: 0.02,
                blow_off_damping_nspm: 4e3,
            }),
        })
        .unwrap(),
    )
}

#[cfg(test)]
mod tests;
