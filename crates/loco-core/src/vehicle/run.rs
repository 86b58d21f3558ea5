//! Time integration of one run and the output channels it records.
//!
//! Channels (SI): carbody floor lateral and vertical acceleration at the two Sperling points (floor
//! above each bogie centre, `carbody.sperling_point_lateral_offset` to the left), bogie frame lateral
//! acceleration at the frame centre and above each wheelset, wheelset lateral displacement and
//! yaw, wheel-rail forces Q, Y and Y/Q of all eight wheels, the force of every damper (N) and the
//! frequency-valve scale factor of each yaw damper (0 open, 1 closed). [`channel_names`] lists
//! them in the order [`run`] records them.

use super::integrator::{OdeSystem, Rk4Workspace};
use super::kinematics::point_motion;
use super::layout::*;
use super::simulation::VehicleSystem;
use super::suspension::DamperRole;
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
struct Probes {
    /// (name, body, point from the body's centre of gravity, m, component 0..3).
    acceleration: Vec<(String, usize, [f64; 3], usize)>,
    /// Dampers whose force is recorded: yaw, secondary lateral, primary vertical, secondary
    /// vertical (the first two kept first so that older channel positions do not move).
    force_dampers: Vec<usize>,
    /// Yaw dampers, whose frequency-valve scale factor is recorded.
    yaw_dampers: Vec<usize>,
    /// Primary and secondary vertical dampers, whose force is recorded after the valve channels
    /// (added later, so appended to keep the positions of the older channels).
    vertical_dampers: Vec<usize>,
}

fn probes(system: &VehicleSystem) -> Result<Probes> {
    let s = &system.structure;
    let p = &s.parameters;
    let floor = p.get("carbody.floor_height")? - s.bodies[BODY_CARBODY].position[2];
    let side = p.get("carbody.sperling_point_lateral_offset")?;
    let mut acceleration = Vec::new();
    for (b, tag) in ["front", "rear"].iter().enumerate() {
        let x = s.layout.bogie_x[b];
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
    let by_role = |role: DamperRole| {
        system
            .dampers
            .iter()
            .enumerate()
            .filter(|(_, d)| d.placement.role == role)
            .map(|(i, _)| i)
            .collect::<Vec<_>>()
    };
    let roles = |roles: [DamperRole; 2]| roles.into_iter().flat_map(by_role).collect();
    Ok(Probes {
        acceleration,
        force_dampers: roles([DamperRole::Yaw, DamperRole::SecondaryLateral]),
        yaw_dampers: by_role(DamperRole::Yaw),
        vertical_dampers: roles([DamperRole::PrimaryVertical, DamperRole::SecondaryVertical]),
    })
}

/// Names of the channels [`run`] records for `system`, in order (accelerations m/s², wheelset
/// displacement m and yaw rad, wheel forces N, Y/Q –, damper forces N, valve scale factors –).
/// The one source of the names: the batch binary checks a study's channels against it before
/// running anything.
pub fn channel_names(system: &VehicleSystem) -> Result<Vec<String>> {
    Ok(names_of(system, &probes(system)?))
}

fn names_of(system: &VehicleSystem, probes: &Probes) -> Vec<String> {
    let mut names: Vec<String> = probes.acceleration.iter().map(|p| p.0.clone()).collect();
    for w in 0..N_WHEELSETS {
        names.push(format!("wheelset{}_y", w + 1));
        names.push(format!("wheelset{}_yaw", w + 1));
    }
    for w in 0..N_WHEELSETS {
        for side in ["left", "right"] {
            for q in ["Q", "Y", "YQ"] {
                names.push(format!("wheel{}_{side}_{q}", w + 1));
            }
        }
    }
    let damper = |i: usize| &system.dampers[i].placement.name;
    for &i in &probes.force_dampers {
        names.push(format!("{}_force", damper(i)));
    }
    for &i in &probes.yaw_dampers {
        names.push(format!("{}_valve", damper(i)));
    }
    for &i in &probes.vertical_dampers {
        names.push(format!("{}_force", damper(i)));
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
    let probes = probes(system)?;

    let names = names_of(system, &probes);
    let mut channels: Vec<Vec<f64>> = vec![Vec::with_capacity(n_samples); names.len()];
    let mut time = Vec::with_capacity(n_samples);

    let mut workspace = Rk4Workspace::new(system.dimension());
    let mut dy = vec![0.0; system.dimension()];
    let mut t = 0.0;
    let total_steps = (n_samples - 1) * steps_per_sample;
    let settle_steps = (settings.settle / dt).round() as usize;
    let last = settle_steps + total_steps;
    let t0 = settle_steps as f64 * dt;
    for step in 0..=last {
        let sample = step >= settle_steps && (step - settle_steps) % steps_per_sample == 0;
        if step == last {
            if sample {
                // Accelerations at the last sample time: one evaluation of the right-hand side.
                system.derivatives(t, y, &mut dy);
                record(system, &probes, y, &dy, &mut channels);
                time.push(t - t0);
            }
            break;
        }
        if let Some(flag) = cancel {
            if flag.load(Ordering::Relaxed) {
                return Err(LocoError::Interrupted);
            }
        }
        if sample {
            // Accelerations at the sample time are the first RK4 stage of the step from it.
            workspace.step_observed(system, t, dt, y, |system, y0, dy0| {
                record(system, &probes, y0, dy0, &mut channels);
            });
            time.push(t - t0);
        } else {
            workspace.step(system, t, dt, y);
        }
        t = (step + 1) as f64 * dt;
        system.finish_step(t, y)?;
    }
    Ok(RunOutput {
        sampling_rate: settings.output_rate,
        time,
        names,
        channels,
    })
}

fn record(
    system: &VehicleSystem,
    probes: &Probes,
    y: &[f64],
    dy: &[f64],
    channels: &mut [Vec<f64>],
) {
    let s = &system.structure;
    let acc = &dy[N_DOF..2 * N_DOF];
    let mut c = 0;
    let mut push = |v: f64| {
        channels[c].push(v);
        c += 1;
    };
    for (_, body, point, component) in &probes.acceleration {
        let a = s.bodies[*body].map.apply(acc);
        push(point_motion(&a, *point)[*component]);
    }
    for w in 0..N_WHEELSETS {
        push(y[wheelset(w) + Y]);
        push(y[wheelset(w) + YAW]);
    }
    for w in 0..N_WHEELSETS {
        for f in &system.wheel_forces[w] {
            push(f.vertical);
            push(f.lateral);
            push(if f.vertical > 0.0 {
                f.lateral / f.vertical
            } else {
                0.0
            });
        }
    }
    for &i in &probes.force_dampers {
        push(system.damper_forces[i]);
    }
    for &i in &probes.yaw_dampers {
        push(system.discrete[i].scale_factor);
    }
    for &i in &probes.vertical_dampers {
        push(system.damper_forces[i]);
    }
}
