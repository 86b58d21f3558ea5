//! Time integration of one run and the output channels it records.
//!
//! The channels (names, units, how each is read) are one [`ChannelSet`] built from the vehicle
//! structure; [`run`] records every channel of it at each output sample, or only the metrics'
//! channels where nothing else is kept ([`Recorded`]).

use crate::error::{check_non_negative, check_positive, LocoError, Result};
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::output::channel_set::ChannelSet;
use crate::vehicle::output::long_step_range::LongStepRange;
use crate::vehicle::system::damper_elements::decaying_states;
use crate::vehicle::system::simulation::VehicleSystem;
use crate::vehicle::time::decaying_states::DecayingStates;
use crate::vehicle::time::exponential_rk4::ExponentialRk4;
use crate::vehicle::time::integrator::{Integrator, OdeSystem, Rk4Workspace, REFERENCE_STEP};
use crate::vehicle::time::stiff_linear_part::{gearbox_bearings, StiffLinearPart};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Channel of the carbody floor lateral acceleration used for W_y and A_yc.
pub const CARBODY_LATERAL: &str = "carbody_floor_ay_front";
/// Channel of the carbody floor vertical acceleration used for W_z.
pub const CARBODY_VERTICAL: &str = "carbody_floor_az_front";
/// Channel of the bogie frame lateral acceleration used for A_yb.
pub const BOGIE_LATERAL: &str = "frame1_ay_wheelset1";

/// The channels [`crate::vehicle::output::run_metrics::run_metrics`] reads: what a run records when only its metrics are kept.
pub const METRIC_CHANNELS: [&str; 3] = [CARBODY_LATERAL, CARBODY_VERTICAL, BOGIE_LATERAL];

/// Settings of the time integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSettings {
    /// Integration step, s (fixed; see the convergence study in docs/model/integrator.md); by default the
    /// scheme's [`Integrator::default_step`].
    pub step: f64,
    /// The scheme that takes the steps.
    pub integrator: Integrator,
    /// Output sampling rate, Hz (a whole number of steps per sample: the step is shortened to
    /// fit, [`steps_per_sample`]).
    pub output_rate: f64,
    /// Simulated time recorded, s.
    pub duration: f64,
    /// Time integrated before recording starts, s: start transients (a damper's valve leaving its
    /// defined start state) settle without entering the record, whose time starts at 0 after it.
    pub settle: f64,
}

impl Default for RunSettings {
    fn default() -> Self {
        Self {
            step: Integrator::default().default_step(),
            integrator: Integrator::default(),
            output_rate: 500.0,
            duration: 9.0,
            settle: 0.0,
        }
    }
}

/// Recorded channels of a run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RunOutput {
    /// Output sampling rate, Hz.
    pub sampling_rate: f64,
    /// Sample times, s.
    pub time: Vec<f64>,
    /// Channel names, in the order of `channels`.
    pub names: Vec<String>,
    /// One vector per channel, same length as `time`.
    pub channels: Vec<Vec<f64>>,
}

impl RunOutput {
    /// The channel called `name`.
    pub fn channel(&self, name: &str) -> Option<&[f64]> {
        self.names
            .iter()
            .position(|n| n == name)
            .map(|i| self.channels[i].as_slice())
    }
}

/// Which channels a run records.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Recorded {
    /// Every channel of the vehicle's [`ChannelSet`] (a run whose time histories are returned).
    #[default]
    Every,
    /// Only those the run metrics read ([`METRIC_CHANNELS`]): a batch sample whose time
    /// histories are not returned. The metrics are the same bits either way; a sample of every
    /// channel costs 2.5 % of a default run and 5 MB per 500 m.
    Metrics,
}

/// Names of the channels [`run`] records for a vehicle of this structure, in order (see
/// [`ChannelSet`] for their units and kinds). The batch binary checks a study's channels against
/// it before running anything.
pub fn channel_names(structure: &VehicleStructure) -> Result<Vec<String>> {
    Ok(ChannelSet::new(structure)?.names())
}

/// Whole steps per output sample at `output_rate` (Hz) for a step of at most `step` (s): the
/// step is shortened to fit, never lengthened, since `step` is the one the stability check
/// ([`crate::vehicle::analysis::stiffest_mode::stable_step`]) and the dampers' laws were made for. The tolerance
/// keeps exact ratios (500 Hz at 2 ms) from rounding up to one step more.
pub fn steps_per_sample(output_rate: f64, step: f64) -> usize {
    ((1.0 / (output_rate * step)) - 1e-9).ceil().max(1.0) as usize
}

/// Integrates `system` from the initial state `y` for `settings.duration` and records the
/// `recorded` channels. `cancel`, when set from another thread, stops the run with `Interrupted`.
pub fn run(
    system: &mut VehicleSystem,
    y: &mut [f64],
    settings: &RunSettings,
    recorded: Recorded,
    cancel: Option<&AtomicBool>,
) -> Result<RunOutput> {
    check_positive("step", settings.step)?;
    check_positive("output_rate", settings.output_rate)?;
    check_positive("duration", settings.duration)?;
    check_non_negative("settle", settings.settle)?;
    let steps_per_sample = steps_per_sample(settings.output_rate, settings.step);
    let dt = 1.0 / (settings.output_rate * steps_per_sample as f64);
    let n_samples = (settings.duration * settings.output_rate).floor() as usize + 1;
    let channel_set = match recorded {
        Recorded::Every => ChannelSet::new(&system.structure)?,
        Recorded::Metrics => ChannelSet::new(&system.structure)?.only(&METRIC_CHANNELS)?,
    };
    let names = channel_set.names();
    // Each channel reserved on its own: `vec![v; n]` clones `v`, and a clone of an empty vector
    // has no capacity, so all but one channel grew by doubling and copying.
    let mut channels: Vec<Vec<f64>> = (0..names.len())
        .map(|_| Vec::with_capacity(n_samples))
        .collect();
    let mut time = Vec::with_capacity(n_samples);

    let total_steps = (n_samples - 1) * steps_per_sample;
    let settle_steps = (settings.settle / dt).round() as usize;
    let t0 = settle_steps as f64 * dt;
    let is_sample =
        |n: usize| n >= settle_steps && (n - settle_steps).is_multiple_of(steps_per_sample);
    integrate(
        system,
        y,
        dt,
        settle_steps + total_steps,
        cancel,
        |n, _, _, _| {
            Ok(if is_sample(n) {
                Flow::Observe
            } else {
                Flow::Step
            })
        },
        |t, system, y, dy| {
            let mut c = 0;
            channel_set.sample(system, y, dy, |v| {
                channels[c].push(v);
                c += 1;
            });
            time.push(t - t0);
        },
    )?;
    Ok(RunOutput {
        sampling_rate: settings.output_rate,
        time,
        names,
        channels,
    })
}

/// What [`integrate`] does with the state of a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flow {
    /// Step on.
    Step,
    /// Pass the state and its derivatives to the observer, then step on.
    Observe,
    /// End the integration here.
    Stop,
}

/// The one time loop of the vehicle: RK4 steps of `dt` (s) from t = 0 and state `y`, at most
/// `steps` of them. Before each step `n` (at `t = n·dt`, and at the final state, n = `steps`)
/// `on_step(n, t, system, y)` decides: [`Flow::Observe`] calls `observe(t, system, y, ẏ)` with the
/// derivatives at that state (free with the step's first RK4 stage; one extra evaluation at the
/// final state), [`Flow::Stop`] ends the loop. Every step is checked by
/// [`VehicleSystem::finish_step`]; `cancel`, when set from another thread, stops the loop with
/// `Interrupted`.
pub fn integrate(
    system: &mut VehicleSystem,
    y: &mut [f64],
    dt: f64,
    steps: usize,
    cancel: Option<&AtomicBool>,
    mut on_step: impl FnMut(usize, f64, &mut VehicleSystem, &[f64]) -> Result<Flow>,
    mut observe: impl FnMut(f64, &VehicleSystem, &[f64], &[f64]),
) -> Result<()> {
    let mut workspace = Stepper::new(system, dt);
    let mut t = 0.0;
    for n in 0..=steps {
        let flow = on_step(n, t, system, y)?;
        if flow == Flow::Stop {
            break;
        }
        if n == steps {
            if flow == Flow::Observe {
                let mut dy = vec![0.0; system.dimension()];
                system.derivatives(t, y, &mut dy);
                observe(t, system, y, &dy);
            }
            break;
        }
        if cancel.is_some_and(|flag| flag.load(Ordering::Relaxed)) {
            return Err(LocoError::Interrupted);
        }
        let t_end = (n + 1) as f64 * dt;
        if flow == Flow::Observe {
            workspace.step(system, t, dt, t_end, y, |system, y0, dy0| {
                observe(t, system, y0, dy0);
            })?;
        } else {
            workspace.step(system, t, dt, t_end, y, |_, _, _| {})?;
        }
        t = t_end;
        system.statistics.steps += 1;
        system.finish_step(t, y)?;
    }
    Ok(())
}

/// The exponential scheme's linear part: the gearbox bearings and the dampers' decaying states.
type LinearPart = (Arc<StiffLinearPart>, Arc<DecayingStates>);

/// A scheme's workspace.
enum Scheme {
    Rk4(Rk4Workspace),
    Exponential(Box<ExponentialRk4>),
}

impl Scheme {
    /// The workspace of `system.integrator` for steps of `dt` (s); `linear` is the linear part
    /// the exponential scheme solves (built once per run and shared).
    fn new(system: &VehicleSystem, dt: f64, linear: &Option<LinearPart>) -> Self {
        match linear {
            None => Self::Rk4(Rk4Workspace::new(system.dimension())),
            Some((bearings, dampers)) => Self::Exponential(Box::new(ExponentialRk4::new(
                Arc::clone(bearings),
                Arc::clone(dampers),
                system.dimension(),
                dt,
            ))),
        }
    }
}

/// How long (s) the step stays cut after a wheel was last outside its smooth contact range: half
/// a period of S_high's hunting (3.9–4.4 Hz: 0.11–0.13 s), so that a wheelset hunting beyond the
/// range, which leaves it on one side and comes back beyond it on the other half a cycle later,
/// runs the whole cycle on the short step instead of switching twice a cycle. The switching put
/// the long step's error into every cycle: at the box corner C_sy 10 kN·s/m, K_ncsy 10 kN/mm,
/// C_sx 200 kN·s/m, K_ncsx 10 kN/mm on S_high (hunting, A_yb 6.5 m/s²) A_yb was 1.1 % off RK4 at
/// 0.25 ms, 0.2 % with the hold (as the scheme at 1 ms throughout); 0.05 s was not enough.
const CUT_HOLD: f64 = 0.12;

/// The time loop's stepping: the run's step, cut into `parts` whole parts no longer than
/// [`REFERENCE_STEP`] while a wheel is outside the pair's [`LongStepRange`].
struct Stepper {
    long: Scheme,
    /// The parts and their workspace (`None` when the step is no longer than the reference).
    cut: Option<(usize, Scheme)>,
    /// Where the long step holds.
    range: LongStepRange,
    /// Time (s) until which the step stays cut after a wheel was last found outside the range.
    cut_until: f64,
}

impl Stepper {
    fn new(system: &VehicleSystem, dt: f64) -> Self {
        let linear = (system.integrator == Integrator::ExponentialRk4).then(|| {
            (
                Arc::new(gearbox_bearings(&system.structure)),
                Arc::new(decaying_states(&system.structure, &system.dampers)),
            )
        });
        // The tolerance keeps a step of exactly the reference whole.
        let parts = (dt / REFERENCE_STEP * (1.0 - 1e-9)).ceil() as usize;
        Self {
            long: Scheme::new(system, dt, &linear),
            cut: (parts > 1).then(|| (parts, Scheme::new(system, dt / parts as f64, &linear))),
            range: LongStepRange::of(&system.wheel_rail),
            cut_until: f64::NEG_INFINITY,
        }
    }

    /// One step of `dt` from `t` to `t_end` (s), `observe` at its start; the parts but the last
    /// are checked and counted here, the last (or the whole step) by the caller.
    fn step(
        &mut self,
        system: &mut VehicleSystem,
        t: f64,
        dt: f64,
        t_end: f64,
        y: &mut [f64],
        observe: impl FnOnce(&VehicleSystem, &[f64], &[f64]),
    ) -> Result<()> {
        if self.cut.is_some() && !self.range.holds(system, t, y, dt) {
            self.cut_until = t + CUT_HOLD;
        }
        match &mut self.cut {
            Some((parts, scheme)) if t < self.cut_until => {
                let h = dt / *parts as f64;
                let at = |i: usize| if i == *parts { t_end } else { t + i as f64 * h };
                step_with(scheme, system, t, h, at(1), y, observe);
                for i in 1..*parts {
                    system.statistics.steps += 1;
                    system.finish_step(at(i), y)?;
                    step_with(scheme, system, at(i), h, at(i + 1), y, |_, _, _| {});
                }
            }
            _ => step_with(&mut self.long, system, t, dt, t_end, y, observe),
        }
        Ok(())
    }
}

/// One step of either scheme (the same signature).
fn step_with(
    scheme: &mut Scheme,
    system: &mut VehicleSystem,
    t: f64,
    dt: f64,
    t_end: f64,
    y: &mut [f64],
    observe: impl FnOnce(&VehicleSystem, &[f64], &[f64]),
) {
    match scheme {
        Scheme::Rk4(ws) => ws.step_observed(system, t, dt, t_end, y, observe),
        Scheme::Exponential(ws) => ws.step_observed(system, t, dt, t_end, y, observe),
    }
}
