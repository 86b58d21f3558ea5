//! The locomotive's structure: bodies, mass matrix and suspension built from a parameter set, and
//! the forces that do not involve the wheel-rail contact or the dampers' internal states (gravity,
//! gyroscopic moments, springs, bushings, bump stops).

use crate::error::Result;
use crate::vehicle::model::bodies::{build_bodies, Body, Layout};
use crate::vehicle::model::bushing_lanes::BushingLanes;
use crate::vehicle::model::damper_lanes::DamperLanes;
use crate::vehicle::model::elements::{Attachment, BodyStates, Wrenches};
use crate::vehicle::model::kinematics::{point_motion, sub};
use crate::vehicle::model::layout::{N_BODIES, N_DOF};
use crate::vehicle::model::mass::MassMatrix;
use crate::vehicle::model::suspension::{build_suspension, Suspension};
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::params::sections::VehicleSections;
use std::sync::Arc;

/// Everything about the vehicle that does not change during a run.
#[derive(Debug, Clone)]
pub struct VehicleStructure {
    /// The parameters it was built from.
    pub parameters: ParameterSet,
    /// The same parameters as typed sections, checked (what the builders read).
    pub sections: VehicleSections,
    pub layout: Layout,
    pub bodies: Vec<Body>,
    pub mass: MassMatrix,
    pub suspension: Suspension,
    /// Gravitational acceleration, m/s².
    pub gravity: f64,
    /// `suspension.bushings` grouped for the time loop (the same forces, same bits).
    bushing_lanes: BushingLanes,
    /// `suspension.dampers`' kinematics in lanes (the same strokes and arms, same bits).
    pub(crate) damper_lanes: DamperLanes,
}

/// A vehicle as the model's entry points take it: a parameter set, built on the way in, or a
/// structure already built and shared (the Python `Vehicle` handle, a batch's checked rows), which
/// is used as it is and not rebuilt.
pub trait IntoVehicle {
    /// The built vehicle; a non-physical parameter is refused by name.
    fn into_vehicle(self) -> Result<Arc<VehicleStructure>>;
}

impl IntoVehicle for ParameterSet {
    fn into_vehicle(self) -> Result<Arc<VehicleStructure>> {
        Ok(Arc::new(VehicleStructure::new(self)?))
    }
}

impl IntoVehicle for Arc<VehicleStructure> {
    fn into_vehicle(self) -> Result<Arc<VehicleStructure>> {
        Ok(self)
    }
}

impl VehicleStructure {
    /// Builds and checks the structure; a non-physical parameter is refused by name.
    pub fn new(parameters: ParameterSet) -> Result<Self> {
        let sections = VehicleSections::read(&parameters)?;
        let layout = Layout::new(&sections);
        let bodies = build_bodies(&sections, &layout)?;
        let mass = MassMatrix::assemble(
            &bodies
                .iter()
                .map(|b| (&b.map, b.mass, b.inertia))
                .collect::<Vec<_>>(),
        )
        .map_err(|e| crate::vehicle::params::suspects::with_suspects(e, &parameters))?;
        let suspension = build_suspension(&sections, &layout, &bodies)?;
        let gravity = sections.track.gravity;
        let bushing_lanes = BushingLanes::new(&suspension.bushings);
        let damper_lanes = DamperLanes::new(&suspension.dampers);
        Ok(Self {
            parameters,
            sections,
            layout,
            bodies,
            mass,
            suspension,
            gravity,
            bushing_lanes,
            damper_lanes,
        })
    }

    /// Total mass of the 25 bodies, kg.
    pub fn total_mass(&self) -> f64 {
        self.bodies.iter().map(|b| b.mass).sum()
    }

    /// Mean axle load, N: the vehicle's weight (its wheelsets included) over its wheelsets, the
    /// `W` of the linear contact theory's gravitational stiffness.
    pub fn mean_axle_load(&self) -> f64 {
        self.total_mass() * self.gravity / crate::vehicle::model::layout::N_WHEELSETS as f64
    }

    /// Body motions and velocities from coordinates `q` (m, rad) and velocities `qd`.
    pub fn body_states(&self, q: &[f64], qd: &[f64], out: &mut BodyStates) {
        for (i, body) in self.bodies.iter().enumerate() {
            (out.position[i], out.velocity[i]) = body.map.apply_both(q, qd);
        }
    }

    /// Adds gravity, gyroscopic moments of the spinning parts at running speed `speed` (m/s) and
    /// the forces of all springs, bushings and bump stops to `wrenches`.
    pub fn add_structural_forces(&self, states: &BodyStates, speed: f64, wrenches: &mut Wrenches) {
        for (i, body) in self.bodies.iter().enumerate() {
            wrenches[i][2] -= body.mass * self.gravity;
            if body.spin_momentum_per_speed != 0.0 {
                // A rotor with angular momentum H about y: the yaw rate tips H and needs a roll
                // moment, the roll rate a yaw moment (dH/dt = H·(−ψ̇, 0, φ̇)).
                let h = body.spin_momentum_per_speed * speed;
                let v = &states.velocity[i];
                wrenches[i][3] += h * v[5];
                wrenches[i][5] -= h * v[3];
            }
        }
        self.bushing_lanes
            .apply(&self.suspension.bushings, states, wrenches);
        for stop in &self.suspension.bump_stops {
            stop.apply(states, wrenches);
        }
    }

    /// How each coordinate moves an attachment's two points against each other, for the linear
    /// parts the exponential scheme solves: per coordinate `j` with any motion, the point on B
    /// relative to the point on A (x, y, z in m) and B's rotation relative to A's (rad), per unit
    /// of `q_j` (the bodies' small-motion kinematics, as the elements form them).
    pub fn relative_motion_per_coordinate(&self, at: &Attachment) -> Vec<(usize, [f64; 6])> {
        let mut unit = [0.0; N_DOF];
        let mut out = Vec::new();
        for j in 0..N_DOF {
            unit[j] = 1.0;
            let ua = self.bodies[at.body_a].map.apply(&unit);
            let ub = self.bodies[at.body_b].map.apply(&unit);
            unit[j] = 0.0;
            let d = sub(point_motion(&ub, at.point_b), point_motion(&ua, at.point_a));
            let motion = [
                d[0],
                d[1],
                d[2],
                ub[3] - ua[3],
                ub[4] - ua[4],
                ub[5] - ua[5],
            ];
            if motion.iter().any(|v| *v != 0.0) {
                out.push((j, motion));
            }
        }
        out
    }

    /// Generalized forces `Q = Σ Tᵀ w` from body wrenches (overwrites `gen_force`).
    pub fn generalized_forces(&self, wrenches: &Wrenches, gen_force: &mut [f64]) {
        gen_force[..N_DOF].fill(0.0);
        for (i, body) in self.bodies.iter().enumerate().take(N_BODIES) {
            body.map.add_transpose(&wrenches[i], gen_force);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::model::kinematics::cross;
    use crate::vehicle::model::layout::*;

    fn structure() -> VehicleStructure {
        VehicleStructure::new(ParameterSet::default_vehicle()).unwrap()
    }

    /// Coordinates of a small rigid motion of the whole vehicle: translation t, rotation θ about
    /// the vehicle origin.
    fn rigid_motion(s: &VehicleStructure, t: [f64; 3], theta: [f64; 3]) -> Vec<f64> {
        let mut q = vec![0.0; N_DOF];
        let set_free = |q: &mut Vec<f64>, first: usize, body: usize| {
            let p = s.bodies[body].position;
            let d = cross(theta, p);
            for k in 0..3 {
                q[first + k] = t[k] + d[k];
                q[first + 3 + k] = theta[k];
            }
        };
        set_free(&mut q, CARBODY, BODY_CARBODY);
        for b in 0..N_BOGIES {
            set_free(&mut q, frame(b), body_frame(b));
        }
        for w in 0..N_WHEELSETS {
            set_free(&mut q, wheelset(w), body_wheelset(w));
            set_free(&mut q, motor(w), body_motor(w));
            for side in 0..2 {
                q[rotary_arm(w, side)] = theta[1];
            }
        }
        q
    }

    #[test]
    fn builds_with_twenty_five_bodies_and_total_mass() {
        let s = structure();
        assert_eq!(s.bodies.len(), N_BODIES);
        // Generalized mass of a rigid translation is the total mass, in all three directions.
        for axis in 0..3 {
            let mut t = [0.0; 3];
            t[axis] = 1.0;
            let q = rigid_motion(&s, t, [0.0; 3]);
            let mut mq = 0.0;
            for i in 0..N_DOF {
                for j in 0..N_DOF {
                    mq += q[i] * s.mass.get(i, j) * q[j];
                }
            }
            assert!(
                (mq - s.total_mass()).abs() < 1e-6 * s.total_mass(),
                "axis {axis}: {mq}"
            );
        }
        assert!((s.total_mass() - 75_418.0).abs() < 1.0);
    }

    #[test]
    fn rigid_motion_strains_no_element() {
        let s = structure();
        let q = rigid_motion(&s, [0.01, -0.02, 0.005], [1e-3, -2e-3, 3e-3]);
        let mut states = BodyStates::default();
        s.body_states(&q, &vec![0.0; N_DOF], &mut states);
        for bushing in &s.suspension.bushings {
            let (d, _) = bushing.at.relative_motion(&states);
            for k in 0..3 {
                assert!(d[k].abs() < 1e-12, "{} strained: {d:?}", bushing.name);
            }
        }
        for damper in &s.suspension.dampers {
            let (d, _) = damper.at.relative_motion(&states);
            let elongation: f64 = (0..3).map(|k| d[k] * damper.direction[k]).sum();
            assert!(elongation.abs() < 1e-12, "{} strained: {d:?}", damper.name);
        }
    }

    #[test]
    fn mass_matrix_blocks_follow_the_body_families() {
        let s = structure();
        let mut sizes = s.mass.block_sizes();
        sizes.sort_unstable();
        // 4 wheelset families of 6 + 3 + 2 = 11 coordinates, carbody + 2 rods = 10, frames and
        // motors 6 each (the free bodies decouple further into single coordinates or small blocks).
        assert_eq!(sizes.iter().sum::<usize>(), N_DOF);
        assert!(*sizes.last().unwrap() <= 11, "{sizes:?}");
    }

    #[test]
    fn a_non_physical_parameter_is_named() {
        // The schema refuses it first; allowed out of range, the model's own check names it.
        let mut p = ParameterSet::default_vehicle();
        let e = p.set("bogie_frame.mass", -1.0).unwrap_err();
        assert!(matches!(e, crate::LocoError::OutOfRange { .. }), "{e}");
        p.allow_out_of_range("bogie_frame.mass").unwrap();
        p.set("bogie_frame.mass", -1.0).unwrap();
        let e = VehicleStructure::new(p).unwrap_err();
        assert!(e.to_string().contains("bogie_frame.mass"), "{e}");
    }
}
