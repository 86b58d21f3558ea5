//! Nonlinear critical speed by a speed ramp-down after a disturbance.
//!
//! The vehicle runs on perfect track at the scenario's speed V0 with every wheelset displaced
//! laterally by `disturbance` at t = 0, on its rails: rise and roll follow the contact table, so a
//! large disturbance starts with the equilibrium's wheel loads, not with the wheel sunk into the
//! rail's flange region. Start well above the linear critical speed with a large disturbance: a
//! vehicle can have several limit cycles, and the nonlinear critical speed is the lowest speed at
//! which any of them survives (with a worn profile tried during development, S_high with YD1 at
//! 1.05 times its linear critical speed had a 1 mm and a 3.3 mm cycle: a 5 mm disturbance settled
//! on the first, which died out near the linear critical speed, 8 mm, the default, on the second,
//! which survived 20 m/s lower; from 1.3 times the linear critical speed both found the second).
//! The speed is held at V0 for at least `hold` seconds and until the hunting amplitude has settled
//! (two successive windows within 5 %: the motion is on its limit cycle), at most `max_hold`
//! seconds; then it falls linearly at `deceleration` down to `end_speed`. Creepages, rolling spin,
//! gyroscopic moments and the track position follow the ramp (see [`crate::vehicle::system::simulation`], where the
//! speed is a slowly varying imposed parameter).
//!
//! The hunting amplitude is measured in sliding windows of `window` seconds (hop half a window):
//! half the peak-to-peak lateral displacement of each wheelset, the largest of the four. The
//! vehicle does not hunt at V0 when a window ending after `hold` is below `threshold`; the limit
//! cycle has died out at the first window of the ramp below `threshold`, and the nonlinear
//! critical speed is the speed at that window's start. Once the cycle is gone the motion decays at
//! the hunting mode's linear damping (slowly at first: the ramp passes the fold of the cycle), so
//! the detection comes later than the fold and the result is low by about `deceleration` times
//! the collapse time, 2–3 s: the measured results of S_high with YD1 at three decelerations
//! are in the documentation of Python's `loco.stability.ramp_down`, where a test reruns them;
//! halve the deceleration to check.
//!
//! Theory: on worn (high-conicity) wheels the hunting bifurcation is subcritical, so a limit
//! cycle survives below the linear critical speed down to a fold; the ramp-down follows it to the
//! fold, so the nonlinear critical speed is at or below the linear one (Polach, "On non-linear
//! methods of bogie stability assessment using computer simulations", Proc. IMechE Part F, 2006).

use crate::error::{check_positive, LocoError, Result};
use crate::vehicle::analysis::stiffest_mode::in_equilibrium_at_stable_step;
use crate::vehicle::model::layout::{wheelset, N_WHEELSETS, ROLL, Y, Z};
use crate::vehicle::model::structure::IntoVehicle;
use crate::vehicle::output::run::{integrate, Flow};
use crate::vehicle::scenarios::perfect_track::PerfectTrackVehicle;
use crate::vehicle::scenarios::scenario::{Scenario, TrackSpec};
use crate::vehicle::system::simulation::{SpeedProfile, VehicleSystem};
use crate::vehicle::system::statics::StaticsSettings;
use std::collections::VecDeque;
use std::sync::atomic::AtomicBool;

/// Relative change between successive windows below which the hunting has settled (–).
const SETTLED: f64 = 0.05;

/// Settings of the ramp (SI units); the start speed is the scenario's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RampSettings {
    /// Speed at which the ramp ends if the vehicle still hunts, m/s (> 0, below the start).
    pub end_speed: f64,
    /// Deceleration of the ramp, m/s².
    pub deceleration: f64,
    /// Shortest time at the start speed before the ramp, s (at least one window).
    pub hold: f64,
    /// Longest time at the start speed waiting for the amplitude to settle, s.
    pub max_hold: f64,
    /// Lateral displacement of every wheelset at t = 0, m (within ±10 mm).
    pub disturbance: f64,
    /// Length of the amplitude windows, s.
    pub window: f64,
    /// Amplitude below which the vehicle does not hunt, m.
    pub threshold: f64,
}

impl Default for RampSettings {
    /// 0.5 m/s² (1.8 km/h per second) down to 20 m/s after 3–30 s at the start speed, 8 mm
    /// initial disturbance, 1 s windows, hunting above 0.5 mm.
    fn default() -> Self {
        Self {
            end_speed: 20.0,
            deceleration: 0.5,
            hold: 3.0,
            max_hold: 30.0,
            disturbance: 8e-3,
            window: 1.0,
            threshold: 5e-4,
        }
    }
}

/// How a ramp ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RampOutcome {
    /// The hunting limit cycle died out during the ramp.
    DiedOut,
    /// No hunting at the start speed: the critical speed is above it (for this disturbance).
    StableAtStart,
    /// Still hunting at the end speed: the critical speed is below it.
    HuntsAtEnd,
}

/// Result of a ramp: the critical speed and the amplitude record behind it.
#[derive(Debug, Clone, PartialEq)]
pub struct RampResult {
    pub outcome: RampOutcome,
    /// Nonlinear critical speed, m/s: `+∞` for [`RampOutcome::StableAtStart`], the end speed for
    /// [`RampOutcome::HuntsAtEnd`].
    pub critical_speed: f64,
    /// Speed at the centre of each window, m/s.
    pub window_speed: Vec<f64>,
    /// Hunting amplitude in each window, m.
    pub window_amplitude: Vec<f64>,
}

impl RampSettings {
    /// Checks the settings against the start speed `start` (m/s); errors name the field.
    pub fn validate(&self, start: f64) -> Result<()> {
        check_positive("end_speed", self.end_speed)?;
        if self.end_speed >= start {
            return Err(LocoError::param(
                "end_speed",
                format!(
                    "must be below the start speed ({start} m/s), got {}",
                    self.end_speed
                ),
            ));
        }
        check_positive("deceleration", self.deceleration)?;
        check_positive("window", self.window)?;
        check_positive("threshold", self.threshold)?;
        if !(self.hold.is_finite() && self.hold >= self.window) {
            return Err(LocoError::param(
                "hold",
                format!(
                    "must be at least one window ({} s), got {}",
                    self.window, self.hold
                ),
            ));
        }
        if !(self.max_hold.is_finite() && self.max_hold >= self.hold) {
            return Err(LocoError::param(
                "max_hold",
                format!(
                    "must be finite and at least hold ({} s), got {}",
                    self.hold, self.max_hold
                ),
            ));
        }
        if !(self.disturbance.abs() > self.threshold && self.disturbance.abs() <= 0.01) {
            return Err(LocoError::param(
                "disturbance",
                format!(
                    "must exceed the threshold ({} m) and stay within ±0.01 m, got {}",
                    self.threshold, self.disturbance
                ),
            ));
        }
        Ok(())
    }
}

/// Runs the ramp for a vehicle and scenario (wheel, rail, yaw damper, step, creep settings; the
/// start speed is `scenario.speed`, the track is perfect). `cancel`, when set from another
/// thread, stops the run with `Interrupted`.
pub fn nonlinear_critical_speed(
    vehicle: impl IntoVehicle,
    scenario: &Scenario,
    settings: &RampSettings,
    cancel: Option<&AtomicBool>,
) -> Result<RampResult> {
    scenario.validate()?;
    settings.validate(scenario.speed)?;
    let start_speed = scenario.speed;
    let longest = settings.max_hold + (start_speed - settings.end_speed) / settings.deceleration;
    let perfect = Scenario {
        track: TrackSpec::Perfect,
        distance: start_speed * longest,
        ..scenario.clone()
    };
    let vehicle = PerfectTrackVehicle::new(vehicle, &perfect)?;
    let build = |step: f64| -> Result<VehicleSystem> {
        let mut system = vehicle.system_with_step(start_speed, step)?;
        // The ramp starts when the hunting has settled (below); until then V stays V0.
        system.speed = SpeedProfile::ramp(start_speed, settings.deceleration);
        system.integrator = scenario.run.integrator;
        Ok(system)
    };
    // The scenario's step is the longest, as in a run (`simulate_prepared`).
    let (mut system, equilibrium, dt) =
        in_equilibrium_at_stable_step(scenario.run.step, &StaticsSettings::default(), build)?;
    let mut y = equilibrium.state;
    disturb(&system, &mut y, settings.disturbance);

    let steps_per_window = (settings.window / dt).round().max(2.0) as usize;
    let hop = steps_per_window.div_ceil(2);
    // Lateral displacement of the four wheelsets after each of the last `steps_per_window` steps.
    let mut history: VecDeque<[f64; N_WHEELSETS]> = VecDeque::with_capacity(steps_per_window);
    let mut result = RampResult {
        outcome: RampOutcome::HuntsAtEnd,
        critical_speed: settings.end_speed,
        window_speed: Vec::new(),
        window_amplitude: Vec::new(),
    };
    let mut ramping = false;
    integrate(
        &mut system,
        &mut y,
        dt,
        usize::MAX,
        cancel,
        |n, t, system, y| {
            if n > 0 {
                if history.len() == steps_per_window {
                    history.pop_front();
                }
                history.push_back(std::array::from_fn(|w| y[wheelset(w) + Y]));
            }
            if n >= steps_per_window && (n - steps_per_window).is_multiple_of(hop) {
                let amplitude = window_amplitude(&history);
                let window_start = (n - steps_per_window) as f64 * dt;
                let window_end = n as f64 * dt;
                let amplitudes = &mut result.window_amplitude;
                // The previous window that does not overlap this one (hop is half a window).
                let previous = amplitudes.len().checked_sub(2).map(|i| amplitudes[i]);
                amplitudes.push(amplitude);
                result
                    .window_speed
                    .push(system.speed_at(0.5 * (window_start + window_end)));
                if ramping {
                    if amplitude < settings.threshold {
                        result.outcome = RampOutcome::DiedOut;
                        result.critical_speed = system.speed_at(window_start);
                        return Ok(Flow::Stop);
                    }
                } else if window_end >= settings.hold - 0.5 * dt {
                    if amplitude < settings.threshold {
                        result.outcome = RampOutcome::StableAtStart;
                        result.critical_speed = f64::INFINITY;
                        return Ok(Flow::Stop);
                    }
                    let settled = previous.is_some_and(|p| (amplitude / p - 1.0).abs() < SETTLED);
                    if settled || window_end >= settings.max_hold - 0.5 * dt {
                        ramping = true;
                        system.speed.start_ramp(window_end);
                    }
                }
            }
            Ok(if system.speed_at(t) <= settings.end_speed {
                Flow::Stop
            } else {
                Flow::Step
            })
        },
        |_, _, _, _| {},
    )?;
    Ok(result)
}

/// Moves every wheelset laterally by `d` (m) along its rails (the ramp's and a scenario's initial
/// disturbance): its rise and roll change as the contact table's rigid pose does, which keeps
/// each wheel's interference with its rail.
pub(crate) fn disturb(system: &VehicleSystem, y: &mut [f64], d: f64) {
    let table = system.wheel_rail.table();
    for w in 0..N_WHEELSETS {
        let i = wheelset(w);
        let (from, to) = (table.lookup(y[i + Y]), table.lookup(y[i + Y] + d));
        y[i + Y] += d;
        y[i + Z] += to.rise - from.rise;
        y[i + ROLL] += to.roll - from.roll;
    }
}

/// Half the peak-to-peak lateral displacement in a window, the largest of the wheelsets, m.
fn window_amplitude(samples: &VecDeque<[f64; N_WHEELSETS]>) -> f64 {
    (0..N_WHEELSETS)
        .map(|w| {
            let (lo, hi) = samples
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
                    (lo.min(s[w]), hi.max(s[w]))
                });
            0.5 * (hi - lo)
        })
        .fold(0.0, f64::max)
}
