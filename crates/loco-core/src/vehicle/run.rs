//! Time integration of one run and the output channels it records.
//!
//! Channels (SI): carbody floor lateral and vertical acceleration at the two Sperling points (floor
//! above each bogie centre, `carbody.sperling_point_lateral_offset` to the left), bogie frame lateral
//! acceleration at the frame centre and above each wheelset, wheelset lateral displacement and
//! yaw, wheel-rail forces Q, Y and Y/Q of all eight wheels, the force of every damper (N) and the
//! frequency-valve scale factor of each yaw damper (0 open, 1 closed), then the curving channels
//! (per wheel ΔQ/Q0, T·γ, contact angle, flange contact; per wheelset ΣY; named in
//! [`super::wheel_channels`]). [`channel_names`] lists them in the order [`run`] records them.

use super::integrator::{OdeSystem, Rk4Workspace};
use super::kinematics::point_motion;
use super::layout::*;
use super::simulation::VehicleSystem;
use super::structure::VehicleStructure;
use super::suspension::DamperRole;
use super::wheel_channels::{
    wheel_channel, wheelset_channel, WheelsetQuantity, CURVING_WHEEL_QUANTITIES,
    WHEELSET_MOTION_QUANTITIES, WHEEL_FORCE_QUANTITIES,
};
use crate::error::{check_non_negative, check_positive, LocoError, Result};
use std::sync::atomic::{AtomicBool, Ordering};

/// Settings of the time integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSettings {
    /// Integration step, s (RK4, fixed; see the convergence study in the README).
    pub step: f64,
    /// Output sampling rate, Hz (a whole number of steps per sample).
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
            step: 1e-3,
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

/// Where the acceleration channels are measured.
#[derive(Debug)]
pub(crate) struct Probes {
    /// (name, body, point from the body's centre of gravity, m, component 0..3).
    acceleration: Vec<(String, usize, [f64; 3], usize)>,
    /// Recorded damper quantities: (damper index, quantity), in [`DAMPER_CHANNELS`] order.
    dampers: Vec<(usize, DamperQuantity)>,
}

/// A recorded quantity of a damper.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum DamperQuantity {
    /// Force, N (channel `<damper>_force`).
    Force,
    /// Frequency-valve scale factor, – (channel `<damper>_valve`).
    Valve,
    /// Stroke (elongation from the static length), m (channel `<damper>_stroke`).
    Stroke,
}

/// The damper channels, in order: the force of the yaw and secondary lateral dampers, the valve
/// of the yaw dampers, then the force of the primary and secondary vertical dampers (added
/// later, so appended to keep the positions of the older channels), then the strokes of the
/// yaw and secondary lateral dampers (the frequency response's outputs, issue 11).
const DAMPER_CHANNELS: [(&[DamperRole], DamperQuantity); 4] = [
    (
        &[DamperRole::Yaw, DamperRole::SecondaryLateral],
        DamperQuantity::Force,
    ),
    (&[DamperRole::Yaw], DamperQuantity::Valve),
    (
        &[DamperRole::PrimaryVertical, DamperRole::SecondaryVertical],
        DamperQuantity::Force,
    ),
    (
        &[DamperRole::Yaw, DamperRole::SecondaryLateral],
        DamperQuantity::Stroke,
    ),
];

pub(crate) fn probes(s: &VehicleStructure) -> Result<Probes> {
    let p = &s.parameters;
    let floor = p.get("carbody.floor_height")? - s.bodies[BODY_CARBODY].position[2];
    let side = p.get("carbody.sperling_point_lateral_offset")?;
    let along = p.get("carbody.sperling_point_longitudinal_offset")?;
    let mut acceleration = Vec::new();
    for (x, tag) in [(along, "front"), (-along, "rear")] {
        for (axis, component) in [("ay", Y), ("az", Z)] {
            acceleration.push((
                format!("carbody_floor_{axis}_{tag}"),
                BODY_CARBODY,
                [x, side, floor],
                component,
            ));
        }
    }
    for b in 0..N_BOGIES {
        let body = body_frame(b);
        acceleration.push((format!("frame{}_ay_centre", b + 1), body, [0.0; 3], Y));
        for w in 2 * b..2 * b + 2 {
            let dx = s.layout.wheelset_x[w] - s.layout.bogie_x[b];
            acceleration.push((
                format!("frame{}_ay_wheelset{}", b + 1, w + 1),
                body,
                [dx, 0.0, 0.0],
                Y,
            ));
        }
    }
    let mut dampers = Vec::new();
    for (roles, quantity) in DAMPER_CHANNELS {
        for &role in roles {
            for (i, placement) in s.suspension.dampers.iter().enumerate() {
                if placement.role == role {
                    dampers.push((i, quantity));
                }
            }
        }
    }
    Ok(Probes {
        acceleration,
        dampers,
    })
}

/// Names of the channels [`run`] records for a vehicle of this structure, in order (accelerations m/s², wheelset
/// displacement m and yaw rad, wheel forces N, Y/Q –, damper forces N, valve scale factors –).
/// The one source of the names: the batch binary checks a study's channels against it before
/// running anything.
pub fn channel_names(structure: &VehicleStructure) -> Result<Vec<String>> {
    Ok(names_of(structure, &probes(structure)?))
}

pub(crate) fn names_of(structure: &VehicleStructure, probes: &Probes) -> Vec<String> {
    let mut names: Vec<String> = probes.acceleration.iter().map(|p| p.0.clone()).collect();
    for w in 0..N_WHEELSETS {
        for q in WHEELSET_MOTION_QUANTITIES {
            names.push(wheelset_channel(w, q));
        }
    }
    for w in 0..N_WHEELSETS {
        for side in 0..2 {
            for q in WHEEL_FORCE_QUANTITIES {
                names.push(wheel_channel(w, side, q));
            }
        }
    }
    for &(i, quantity) in &probes.dampers {
        let name = &structure.suspension.dampers[i].name;
        names.push(match quantity {
            DamperQuantity::Force => format!("{name}_force"),
            DamperQuantity::Valve => format!("{name}_valve"),
            DamperQuantity::Stroke => format!("{name}_stroke"),
        });
    }
    // The curving channels, appended so every older channel keeps its position.
    for w in 0..N_WHEELSETS {
        for side in 0..2 {
            for q in CURVING_WHEEL_QUANTITIES {
                names.push(wheel_channel(w, side, q));
            }
        }
    }
    for w in 0..N_WHEELSETS {
        names.push(wheelset_channel(w, WheelsetQuantity::GuidingForce));
    }
    names
}

/// Integrates `system` from the initial state `y` for `settings.duration` and records the
/// channels. `cancel`, when set from another thread, stops the run with `Interrupted`.
pub fn run(
    system: &mut VehicleSystem,
    y: &mut [f64],
    settings: &RunSettings,
    cancel: Option<&AtomicBool>,
) -> Result<RunOutput> {
    check_positive("step", settings.step)?;
    check_positive("output_rate", settings.output_rate)?;
    check_positive("duration", settings.duration)?;
    check_non_negative("settle", settings.settle)?;
    let steps_per_sample = (1.0 / (settings.output_rate * settings.step))
        .round()
        .max(1.0) as usize;
    let dt = 1.0 / (settings.output_rate * steps_per_sample as f64);
    let n_samples = (settings.duration * settings.output_rate).floor() as usize + 1;
    let probes = probes(&system.structure)?;

    let names = names_of(&system.structure, &probes);
    let mut channels: Vec<Vec<f64>> = vec![Vec::with_capacity(n_samples); names.len()];
    let mut time = Vec::with_capacity(n_samples);

    let total_steps = (n_samples - 1) * steps_per_sample;
    let settle_steps = (settings.settle / dt).round() as usize;
    let t0 = settle_steps as f64 * dt;
    let is_sample = |n: usize| n >= settle_steps && (n - settle_steps) % steps_per_sample == 0;
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
            record(system, &probes, y, dy, &mut channels);
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
    let mut workspace = Rk4Workspace::new(system.dimension());
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
        if flow == Flow::Observe {
            workspace.step_observed(system, t, dt, y, |system, y0, dy0| {
                observe(t, system, y0, dy0);
            });
        } else {
            workspace.step(system, t, dt, y);
        }
        t = (n + 1) as f64 * dt;
        system.statistics.steps += 1;
        system.finish_step(t, y)?;
    }
    Ok(())
}

fn record(
    system: &VehicleSystem,
    probes: &Probes,
    y: &[f64],
    dy: &[f64],
    channels: &mut [Vec<f64>],
) {
    let mut c = 0;
    sample(system, probes, y, dy, |v| {
        channels[c].push(v);
        c += 1;
    });
}

/// One sample of every channel, in [`channel_names`] order, from state `y` and its derivatives
/// `dy` (the system's wheel and damper forces must be those of the evaluation that gave `dy`).
/// The one recording function: the runs record it and the frequency response linearises it.
pub(crate) fn sample(
    system: &VehicleSystem,
    probes: &Probes,
    y: &[f64],
    dy: &[f64],
    mut push: impl FnMut(f64),
) {
    let s = &system.structure;
    let acc = &dy[N_DOF..2 * N_DOF];
    for (_, body, point, component) in &probes.acceleration {
        let a = s.bodies[*body].map.apply(acc);
        push(point_motion(&a, *point)[*component]);
    }
    for w in 0..N_WHEELSETS {
        push(y[wheelset(w) + Y]);
        push(y[wheelset(w) + YAW]);
    }
    let static_load = s.total_mass() * s.gravity / (2 * N_WHEELSETS) as f64;
    for w in 0..N_WHEELSETS {
        for f in &system.wheel_forces[w] {
            for q in WHEEL_FORCE_QUANTITIES {
                push(q.value(f, static_load));
            }
        }
    }
    for &(i, quantity) in &probes.dampers {
        push(match quantity {
            DamperQuantity::Force => system.damper_forces[i],
            DamperQuantity::Valve => system.discrete[i].scale_factor,
            DamperQuantity::Stroke => {
                // On a curve the dampers act in the reference frame (`track_frame`).
                let states = match system.curve {
                    Some(_) => &system.frame_work.states,
                    None => &system.body_states,
                };
                system.dampers[i].stroke(states).0
            }
        });
    }
    for w in 0..N_WHEELSETS {
        for f in &system.wheel_forces[w] {
            for q in CURVING_WHEEL_QUANTITIES {
                push(q.value(f, static_load));
            }
        }
    }
    for [left, right] in &system.wheel_forces {
        push(left.lateral + right.lateral);
    }
}
