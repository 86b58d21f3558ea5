//! One run of the locomotive on a track: the first-order system integrated in time.
//!
//! State vector `y = [q (90) | q̇ (90) | damper internal states]`, in m, rad, m/s, rad/s and the
//! damper module's units. The reference frame moves along the track at the running speed V(t);
//! wheelset `w` is at distance `s = s_start + ∫V dt + x_w` along the track.
//!
//! The speed follows a [`SpeedProfile`]: constant in a run; a speed ramp (the nonlinear critical
//! speed, [`crate::vehicle::runs::critical_speed`]) holds V0 until the ramp is started at t0 and then lowers it at
//! a constant deceleration `a`: `V(t) = V0 − a·max(t − t0, 0)` and
//! `s = s_start + V0·t − a·max(t − t0, 0)²/2 + x_w`.
//! The speed is imposed as a slowly varying parameter: creepages, rolling spin, gyroscopic moments
//! and the track position all follow it, while the inertia forces of the deceleration itself
//! (`m·a` on every body, a braking force the real vehicle's brakes would supply) are left out.

use crate::dampers::{Damper, DamperDiscreteState};
use crate::error::{LocoError, Result};
use crate::track::{RailIrregularity, TrackIrregularity};
use crate::vehicle::curving::track_frame::{CurvedTrack, FrameWork};
use crate::vehicle::model::elements::{BodyStates, Wrenches};
use crate::vehicle::model::layout::{body_wheelset, N_BODIES, N_DOF, N_WHEELSETS, YAW};
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::rail_contact::rail_planes::RailPlanes;
use crate::vehicle::rail_contact::wheel_rail::{ContactMode, WheelForces, WheelRail};
use crate::vehicle::system::damper_elements::{law_for_step, DamperElement};
use crate::vehicle::system::run_statistics::RunStatistics;
use crate::vehicle::system::states_cache::StatesCache;
use crate::vehicle::time::integrator::{Integrator, OdeSystem};
use std::sync::Arc;

pub use crate::vehicle::system::state_check::{
    DERAILED_LATERAL, RUNAWAY_DISPLACEMENT, RUNAWAY_ROTATION,
};

/// Running speed against time: constant, or a ramp that holds its start speed until it is started
/// and then decelerates at a constant rate (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpeedProfile {
    /// Constant speed, m/s.
    Constant(f64),
    /// Speed `speed` (m/s) until `start` (s; `None`: not yet started), then falling at
    /// `deceleration` (m/s²).
    Ramp {
        speed: f64,
        deceleration: f64,
        start: Option<f64>,
    },
}

impl SpeedProfile {
    /// A ramp from `speed` (m/s) at `deceleration` (m/s²), not yet started.
    pub fn ramp(speed: f64, deceleration: f64) -> Self {
        Self::Ramp {
            speed,
            deceleration,
            start: None,
        }
    }

    /// Starts the ramp at time `t` (s); a constant speed stays constant.
    pub fn start_ramp(&mut self, t: f64) {
        if let Self::Ramp { start, .. } = self {
            *start = Some(t);
        }
    }

    /// Speed at t = 0 (the start speed of a ramp), m/s.
    pub fn initial_speed(&self) -> f64 {
        match *self {
            Self::Constant(speed) | Self::Ramp { speed, .. } => speed,
        }
    }

    /// Running speed at time `t` (s), m/s.
    #[inline]
    pub fn speed_at(&self, t: f64) -> f64 {
        match *self {
            Self::Constant(speed) => speed,
            Self::Ramp {
                speed,
                deceleration,
                start,
            } => speed - deceleration * ramp_time(start, t),
        }
    }

    /// Distance run from t = 0 to time `t` (s), m.
    #[inline]
    pub fn distance_at(&self, t: f64) -> f64 {
        match *self {
            Self::Constant(speed) => speed * t,
            Self::Ramp {
                speed,
                deceleration,
                start,
            } => {
                let ramp = ramp_time(start, t);
                speed * t - 0.5 * deceleration * ramp * ramp
            }
        }
    }
}

/// Time spent ramping at time `t` (s) by a ramp started at `start` (0 before or unstarted), s.
#[inline]
fn ramp_time(start: Option<f64>, t: f64) -> f64 {
    start.map_or(0.0, |t0| (t - t0).max(0.0))
}

/// The system integrated in time: vehicle, dampers, contact, track and speed.
#[derive(Debug, Clone)]
pub struct VehicleSystem {
    pub structure: Arc<VehicleStructure>,
    pub dampers: Vec<DamperElement>,
    pub discrete: Vec<DamperDiscreteState>,
    pub wheel_rail: Arc<WheelRail>,
    pub track: Arc<TrackIrregularity>,
    /// Running speed V against time, m/s.
    pub speed: SpeedProfile,
    /// Track distance of the vehicle origin at t = 0, m.
    pub start_distance: f64,
    /// Creep while running, or the patches held in the static search.
    pub contact_mode: ContactMode,
    /// Rail irregularities each wheelset sees in place of the track look-up (`None` in runs): the
    /// track as an input of the linearisation ([`crate::vehicle::analysis::track_input`]).
    pub rail_inputs: Option<[RailIrregularity; N_WHEELSETS]>,
    /// The designed curves the track frames follow (`None`: straight track, no frame terms).
    pub curve: Option<Arc<CurvedTrack>>,
    /// The curve terms' workspace (reference-frame states, the design at every body).
    pub(crate) frame_work: Box<FrameWork>,
    /// The scheme a run's time loop steps with (the stable-step check follows it).
    pub integrator: Integrator,
    /// Number of continuous states.
    n_states: usize,
    /// First error met inside a right-hand side (reported after the step).
    pub error: Option<LocoError>,
    /// Work done so far (evaluations, steps, Newton iterations; wall time is the caller's).
    pub statistics: RunStatistics,
    // Workspaces (no allocation in the time loop).
    pub(crate) body_states: BodyStates,
    /// The state `body_states` holds, for the next step's first stage.
    pub(crate) states_cache: StatesCache,
    wrenches: Wrenches,
    gen_force: Vec<f64>,
    /// The rails' plane under each wheelset at the last evaluation, for the next.
    rail_planes: RailPlanes,
    /// Wheel-rail forces of the last evaluation, per wheelset `[left, right]`.
    pub wheel_forces: [[WheelForces; 2]; N_WHEELSETS],
    pub(crate) damper_forces: Vec<f64>,
}

impl VehicleSystem {
    /// Assembles the system; `yaw_damper` replaces the yaw dampers' law (YD1, YD2, FSD, ...),
    /// `dt` is the integration step the dampers must be stable with (s).
    pub fn new(
        structure: Arc<VehicleStructure>,
        wheel_rail: Arc<WheelRail>,
        track: Arc<TrackIrregularity>,
        speed: f64,
        start_distance: f64,
        yaw_damper: Option<&Damper>,
        dt: f64,
    ) -> Result<Self> {
        let mut offset = 2 * N_DOF;
        let mut dampers = Vec::with_capacity(structure.suspension.dampers.len());
        for placement in &structure.suspension.dampers {
            let element = DamperElement {
                placement: placement.clone(),
                law: law_for_step(placement, yaw_damper, dt)?,
                state_offset: offset,
                static_elongation: 0.0,
            };
            let n = element.n_states();
            dampers.push(element);
            offset += n;
        }
        let discrete = dampers.iter().map(|d| d.law.initial_discrete()).collect();
        let n_dampers = dampers.len();
        Ok(Self {
            structure,
            dampers,
            discrete,
            wheel_rail,
            track,
            speed: SpeedProfile::Constant(speed),
            start_distance,
            contact_mode: ContactMode::Rolling,
            rail_inputs: None,
            curve: None,
            frame_work: Box::default(),
            integrator: Integrator::default(),
            n_states: offset,
            error: None,
            statistics: RunStatistics::default(),
            body_states: BodyStates::default(),
            states_cache: StatesCache::default(),
            wrenches: [[0.0; 6]; N_BODIES],
            gen_force: vec![0.0; N_DOF],
            rail_planes: RailPlanes::default(),
            wheel_forces: [[WheelForces::default(); 2]; N_WHEELSETS],
            damper_forces: vec![0.0; n_dampers],
        })
    }

    /// Number of continuous states (coordinates, velocities, damper states).
    pub fn len_states(&self) -> usize {
        self.n_states
    }

    /// Running speed at time `t` (s), m/s.
    #[inline]
    pub fn speed_at(&self, t: f64) -> f64 {
        self.speed.speed_at(t)
    }

    /// Track distance of the vehicle origin at time `t` (s), m.
    #[inline]
    pub fn vehicle_distance(&self, t: f64) -> f64 {
        self.start_distance + self.speed.distance_at(t)
    }

    /// Track distance of wheelset `w` at time `t` (s), m.
    #[inline]
    pub fn wheelset_distance(&self, w: usize, t: f64) -> f64 {
        self.start_distance + self.speed.distance_at(t) + self.structure.layout.wheelset_x[w]
    }

    /// The bodies' states from `y` at time `t`, and on a curve also their states in the reference
    /// frame the suspension sees (`track_frame`).
    fn update_body_states(&mut self, t: f64, y: &[f64]) {
        if !self.states_cache.holds(&self.structure, y) {
            let (q, rest) = y.split_at(N_DOF);
            self.structure
                .body_states(q, &rest[..N_DOF], &mut self.body_states);
            self.states_cache.invalidate();
        }
        if let Some(curve) = &self.curve {
            let s_r = self.vehicle_distance(t);
            curve.prepare(
                &self.structure,
                s_r,
                self.speed_at(t),
                &self.body_states,
                &mut self.frame_work,
            );
        }
    }

    /// Generalized forces `Q(q, q̇)` (N, N·m) at time `t` with damper states from `y`; also fills
    /// the body states, wheel forces and damper forces, and the damper state rates into `dy`.
    fn forces(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.statistics.rhs_evaluations += 1;
        self.update_body_states(t, y);
        self.wrenches = [[0.0; 6]; N_BODIES];
        let speed = self.speed_at(t);
        let states = match self.curve {
            Some(_) => &self.frame_work.states,
            None => &self.body_states,
        };
        self.structure
            .add_structural_forces(states, speed, &mut self.wrenches);
        // Dampers carry no static force: the static search leaves them out.
        let statics = matches!(self.contact_mode, ContactMode::Held { .. });
        let placements = &self.structure.suspension.dampers;
        let dampers = &self.dampers;
        let lanes = &self.structure.damper_lanes;
        lanes.with_motions(placements, states, statics, |motions| {
            for (i, damper) in dampers.iter().enumerate().filter(|_| !statics) {
                let (x, v) = motions.stroke(i, damper.static_elongation);
                let n = damper.n_states();
                let o = damper.state_offset;
                // The law writes every one of its state rates straight into `dy` (through a
                // buffer, each damper cost a library copy call).
                let force = damper.force(x, v, &y[o..o + n], &self.discrete[i], &mut dy[o..o + n]);
                damper.apply_at(&motions.arms(i), force, &mut self.wrenches);
                self.damper_forces[i] = force;
            }
        });
        if let Some(curve) = &self.curve {
            curve.add_frame_forces(&self.frame_work, &self.body_states, &mut self.wrenches);
        }
        for w in 0..N_WHEELSETS {
            // The wheelset's absolute yaw rate includes its track frame's (rolling on a curve);
            // its own is put back after the contact, not recomputed (no rounding).
            let own_yaw = self.body_states.velocity[body_wheelset(w)][YAW];
            if let Some(curve) = &self.curve {
                self.body_states.velocity[body_wheelset(w)][YAW] =
                    own_yaw + curve.wheelset_frame_yaw_rate(speed, &self.frame_work, w);
            }
            let plane = match &self.rail_inputs {
                Some(inputs) => self.wheel_rail.rail_plane(&inputs[w], speed),
                None if statics => self
                    .wheel_rail
                    .rail_plane(&RailIrregularity::default(), speed),
                None => {
                    let distance = self.wheelset_distance(w, t);
                    let planes = &mut self.rail_planes;
                    planes.plane(&self.track, &self.wheel_rail, w, distance, speed)
                }
            };
            let result = self.wheel_rail.apply(
                w,
                t,
                &self.body_states,
                &plane,
                speed,
                self.contact_mode,
                &mut self.wrenches,
                &mut self.wheel_forces[w],
            );
            self.body_states.velocity[body_wheelset(w)][YAW] = own_yaw;
            if let Err(e) = result {
                self.error.get_or_insert(e);
            }
        }
        self.structure
            .generalized_forces(&self.wrenches, &mut self.gen_force);
    }

    /// The rails under wheelset `w` at time `t` (s): the track's, or the linearisation's inputs.
    #[inline]
    pub(crate) fn rails_at(&self, w: usize, t: f64) -> RailIrregularity {
        match &self.rail_inputs {
            Some(inputs) => inputs[w],
            None => self.track.at(self.wheelset_distance(w, t)),
        }
    }

    /// Generalized forces for a state (used by the static search and the linearisation).
    pub fn generalized_force(&mut self, t: f64, y: &[f64], out: &mut [f64]) {
        let mut dy = vec![0.0; self.n_states];
        self.forces(t, y, &mut dy);
        out[..N_DOF].copy_from_slice(&self.gen_force);
    }

    /// Ends a step at time `t` (s) with state `y`: a non-finite or runaway state is divergence
    /// whatever the contact reported on the way (checked first), then an error met inside the
    /// step's evaluations (a wheel leaving its contact table) is returned.
    pub fn finish_step(&mut self, t: f64, y: &[f64]) -> Result<()> {
        let stage_error = self.error.take();
        let blame =
            |e| crate::vehicle::params::suspects::with_suspects(e, &self.structure.parameters);
        self.check_state(t, y).map_err(blame)?;
        stage_error.map_or(Ok(()), |e| Err(blame(e)))
    }

    /// Checks a state after a step; errors say when and where. A non-finite value or a runaway
    /// amplitude of any coordinate is numerical divergence ([`LocoError::Diverged`]); a wheelset
    /// beyond the flanges while everything else stays bounded has derailed
    /// ([`LocoError::Derailed`]).
    pub fn check_state(&self, t: f64, y: &[f64]) -> Result<()> {
        crate::vehicle::system::state_check::check_state(t, y)
    }
}

impl OdeSystem for VehicleSystem {
    fn dimension(&self) -> usize {
        self.n_states
    }

    fn derivatives(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.forces(t, y, dy);
        dy[..N_DOF].copy_from_slice(&y[N_DOF..2 * N_DOF]);
        self.structure
            .mass
            .solve(&self.gen_force, &mut dy[N_DOF..2 * N_DOF]);
    }

    fn after_step(&mut self, t: f64, dt: f64, y: &[f64]) {
        self.update_body_states(t, y);
        // The next step's first stage starts from this very state.
        self.states_cache.store(&self.structure, y);
        let states = match self.curve {
            Some(_) => &self.frame_work.states,
            None => &self.body_states,
        };
        // Dampers carry no static force: the static search leaves them out.
        let statics = matches!(self.contact_mode, ContactMode::Held { .. });
        // Only the valves have a discrete state to advance; the other dampers' strokes (a
        // relative motion each, 0.7 % of a run) went unused.
        let valves = self
            .dampers
            .iter()
            .enumerate()
            .filter(|(_, d)| d.law.has_valve());
        for (i, damper) in valves.filter(|_| !statics) {
            let (x, v) = damper.stroke(states);
            let o = damper.state_offset;
            let n = damper.n_states();
            damper
                .law
                .advance(&mut self.discrete[i], t, dt, x, v, &y[o..o + n]);
        }
    }
}
