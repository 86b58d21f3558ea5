//! One run of the locomotive on a track: the first-order system integrated in time.
//!
//! State vector `y = [q (90) | q̇ (90) | damper internal states]`, in m, rad, m/s, rad/s and the
//! damper module's units. The reference frame moves along the track at the running speed V;
//! wheelset `w` is at distance `s = s_start + V·t + x_w` along the track.

use super::damper_elements::{damper_law, law_for_step, DamperElement};
use super::elements::{BodyStates, Wrenches};
use super::integrator::OdeSystem;
use super::layout::{body_wheelset, N_BODIES, N_DOF, N_WHEELSETS};
use super::structure::VehicleStructure;
use super::wheel_rail::{WheelForces, WheelRail};
use crate::dampers::{Damper, DamperDiscreteState, MAX_STATES};
use crate::error::{LocoError, Result};
use crate::track::{RailIrregularity, TrackIrregularity};
use std::sync::Arc;

/// The system integrated in time: vehicle, dampers, contact, track and speed.
#[derive(Debug, Clone)]
pub struct VehicleSystem {
    pub structure: Arc<VehicleStructure>,
    pub dampers: Vec<DamperElement>,
    pub discrete: Vec<DamperDiscreteState>,
    pub wheel_rail: Arc<WheelRail>,
    pub track: Arc<TrackIrregularity>,
    /// Running speed V, m/s.
    pub speed: f64,
    /// Track distance of the vehicle origin at t = 0, m.
    pub start_distance: f64,
    /// Tangential contact stiffness (N/m) used instead of creep in the static search; 0 in runs.
    pub static_stiffness: f64,
    /// Number of continuous states.
    n_states: usize,
    /// First error met inside a right-hand side (reported after the step).
    pub error: Option<LocoError>,
    // Workspaces (no allocation in the time loop).
    pub(crate) body_states: BodyStates,
    wrenches: Wrenches,
    gen_force: Vec<f64>,
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
            let law = law_for_step(damper_law(placement, yaw_damper)?, dt)?;
            let rate = law.fastest_rate_per_s();
            if rate * dt > 2.5 {
                return Err(LocoError::param(
                    "step",
                    format!(
                        "{dt} s is too long for damper `{}` (internal rate {rate:.3e} 1/s); use < {:.2e} s",
                        placement.name,
                        2.5 / rate
                    ),
                ));
            }
            let n = law.n_states();
            dampers.push(DamperElement {
                placement: placement.clone(),
                law,
                state_offset: offset,
                static_elongation: 0.0,
            });
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
            speed,
            start_distance,
            static_stiffness: 0.0,
            n_states: offset,
            error: None,
            body_states: BodyStates::default(),
            wrenches: [[0.0; 6]; N_BODIES],
            gen_force: vec![0.0; N_DOF],
            wheel_forces: [[WheelForces::default(); 2]; N_WHEELSETS],
            damper_forces: vec![0.0; n_dampers],
        })
    }

    /// Number of continuous states (coordinates, velocities, damper states).
    pub fn len_states(&self) -> usize {
        self.n_states
    }

    /// Track distance of wheelset `w` at time `t` (s), m.
    pub fn wheelset_distance(&self, w: usize, t: f64) -> f64 {
        self.start_distance + self.speed * t + self.structure.layout.wheelset_x[w]
    }

    /// Generalized forces `Q(q, q̇)` (N, N·m) at time `t` with damper states from `y`; also fills
    /// the body states, wheel forces and damper forces, and the damper state rates into `dy`.
    fn forces(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        let (q, rest) = y.split_at(N_DOF);
        let qd = &rest[..N_DOF];
        self.structure.body_states(q, qd, &mut self.body_states);
        self.wrenches = [[0.0; 6]; N_BODIES];
        self.structure
            .add_structural_forces(&self.body_states, self.speed, &mut self.wrenches);
        // Dampers carry no static force: the static search leaves them out.
        let statics = self.static_stiffness > 0.0;
        for (i, damper) in self.dampers.iter().enumerate().filter(|_| !statics) {
            let (x, v) = damper.stroke(&self.body_states);
            let n = damper.law.n_states();
            let o = damper.state_offset;
            let mut rates = [0.0; MAX_STATES];
            let force = damper
                .law
                .evaluate(x, v, &y[o..o + n], &self.discrete[i], &mut rates[..n]);
            dy[o..o + n].copy_from_slice(&rates[..n]);
            damper.apply(&self.body_states, force, &mut self.wrenches);
            self.damper_forces[i] = force;
        }
        for w in 0..N_WHEELSETS {
            let rails = if statics {
                RailIrregularity::default()
            } else {
                self.track.at(self.wheelset_distance(w, t))
            };
            let result = self.wheel_rail.apply(
                w,
                t,
                &self.body_states,
                &rails,
                self.speed,
                self.static_stiffness,
                &mut self.wrenches,
                &mut self.wheel_forces[w],
            );
            if let Err(e) = result {
                self.error.get_or_insert(e);
            }
        }
        self.structure
            .generalized_forces(&self.wrenches, &mut self.gen_force);
    }

    /// Generalized forces for a state (used by the static search and the linearisation).
    pub fn generalized_force(&mut self, t: f64, y: &[f64], out: &mut [f64]) {
        let mut dy = vec![0.0; self.n_states];
        self.forces(t, y, &mut dy);
        out[..N_DOF].copy_from_slice(&self.gen_force);
    }

    /// Checks a state after a step: finite, bounded; errors say when and where.
    pub fn check_state(&self, t: f64, y: &[f64]) -> Result<()> {
        if let Some(i) = y.iter().position(|v| !v.is_finite()) {
            let names = super::layout::dof_names();
            let location = if i < N_DOF {
                names[i].clone()
            } else if i < 2 * N_DOF {
                format!("{} (velocity)", names[i - N_DOF])
            } else {
                "damper internal state".to_string()
            };
            return Err(LocoError::Diverged {
                time: t,
                location,
                reason: "state is not finite".into(),
            });
        }
        for w in 0..N_WHEELSETS {
            let lateral = self.body_states.position[body_wheelset(w)][1];
            if lateral.abs() > 0.05 {
                return Err(LocoError::Derailed {
                    time: t,
                    location: format!("wheelset{}", w + 1),
                    reason: format!("lateral displacement {lateral:.4} m beyond the flanges"),
                });
            }
        }
        Ok(())
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
        let (q, rest) = y.split_at(N_DOF);
        self.structure
            .body_states(q, &rest[..N_DOF], &mut self.body_states);
        // Dampers carry no static force: the static search leaves them out.
        let statics = self.static_stiffness > 0.0;
        for (i, damper) in self.dampers.iter().enumerate().filter(|_| !statics) {
            let (x, v) = damper.stroke(&self.body_states);
            let o = damper.state_offset;
            let n = damper.law.n_states();
            damper
                .law
                .advance(&mut self.discrete[i], t, dt, x, v, &y[o..o + n]);
        }
    }
}
