//! The points in contact of a wheelset's two wheels between their normal contact and their creep
//! forces. [`crate::vehicle::rail_contact::wheel_rail::WheelRail::apply`] finds the points of both wheels before it
//! computes any creep force: each point's chain of long operations (the Hertz table's logarithm
//! and exponential, the cube root of the semi-axes, the divisions) then has the other wheel's as
//! an independent neighbour that the processor overlaps, where FASTSIM's hundreds of operations
//! stood between them (paired run times about 2 % lower). The forces are added in the points'
//! order, so the sums are those of one point at a time.

use crate::contact::creepage::ContactFrame;
use crate::contact::kalker::{CreepForces, Creepages};
use crate::vehicle::model::elements::{add_force_at, Wrenches};
use crate::vehicle::rail_contact::wheel_rail::{CreepSolver, WheelForces};

/// A point in contact, waiting for its creep forces.
#[derive(Debug, Clone, Copy)]
pub(in crate::vehicle) struct Pending {
    /// The wheel (0 left, 1 right).
    pub(in crate::vehicle) side: usize,
    /// From the wheelset centre, track axes (m).
    pub(in crate::vehicle) offset: [f64; 3],
    pub(in crate::vehicle) frame: ContactFrame,
    /// Normal force (N).
    pub(in crate::vehicle) normal: f64,
    /// Contact angle in the rails' plane (rad).
    pub(in crate::vehicle) contact_angle: f64,
    pub(in crate::vehicle) creep: Creep,
}

/// The tangential contact of a pending point: its creepages and semi-axes (m), or the static
/// search's spring forces (N).
#[derive(Debug, Clone, Copy)]
pub(in crate::vehicle) enum Creep {
    Rolling(Creepages, f64, f64),
    Held(CreepForces),
}

impl Default for Pending {
    fn default() -> Self {
        Self {
            side: 0,
            offset: [0.0; 3],
            frame: ContactFrame {
                longitudinal: [0.0; 3],
                lateral: [0.0; 3],
                normal: [0.0; 3],
            },
            normal: 0.0,
            contact_angle: 0.0,
            creep: Creep::Held(CreepForces::default()),
        }
    }
}

/// Adds the forces of the points `pending`, in their order, on the wheelset `body` to
/// `wrenches` and to each wheel's `forces`: each point's creep forces (by `creep`, friction
/// coefficient `friction`) and then its terms, as one point at a time did.
pub(in crate::vehicle) fn add_forces(
    pending: &[Pending],
    creep: &CreepSolver,
    friction: f64,
    body: usize,
    wrenches: &mut Wrenches,
    forces: &mut [WheelForces; 2],
) {
    for p in pending {
        let (tangential, wear_number) = match p.creep {
            Creep::Held(held) => (held, 0.0),
            Creep::Rolling(c, a, b) => {
                let t = creep.creep_forces(a, b, p.normal, friction, &c);
                (
                    t,
                    -(t.fx * c.longitudinal + t.fy * c.lateral + t.mz * c.spin),
                )
            }
        };
        let frame = &p.frame;
        let f: [f64; 3] = std::array::from_fn(|k| {
            p.normal * frame.normal[k]
                + tangential.fx * frame.longitudinal[k]
                + tangential.fy * frame.lateral[k]
        });
        // `offset` is the contact point from the wheelset centre in track axes at the
        // wheelset's pose (the table's roll, the yaw's −ψ·l): the lever arm as it is, not one
        // to be turned by the wheelset's rotation again. Turning it again moved every load by
        // r0·φ across the rail head (0.7 mm at 1.2 mrad of roll).
        add_force_at(wrenches, body, p.offset, f);
        for k in 0..3 {
            wrenches[body][3 + k] += tangential.mz * frame.normal[k];
        }
        let forces = &mut forces[p.side];
        forces.vertical += f[2];
        forces.lateral += f[1];
        forces.longitudinal += f[0];
        forces.wear_number += wear_number;
        forces.contact_angle = if forces.points_in_contact == 0 {
            p.contact_angle
        } else {
            forces.contact_angle.max(p.contact_angle)
        };
        forces.points_in_contact += 1;
    }
}
