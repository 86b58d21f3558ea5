//! The frame terms added to the wrenches in every evaluation on a curve (`super`'s module
//! documentation): the wrenches formed in the reference frame turned into each body's own frame,
//! gravity on the cant, the centripetal force, the clothoid's yaw acceleration and the spinning
//! parts' gyroscopic moments.

use super::super::elements::{BodyStates, Wrenches};
use super::super::kinematics::{cross, sub};
use super::super::layout::YAW;
use super::{CurvedTrack, FrameWork};

impl CurvedTrack {
    /// Turns the wrenches formed in the reference frame (gravity, structure, dampers) into each
    /// body's own frame and adds the frame terms: gravity on the cant, the centripetal force,
    /// the frame's yaw acceleration and the spinning parts' gyroscopic moments. `relative` are
    /// the body states relative to their own frames.
    pub fn add_frame_forces(
        &self,
        work: &FrameWork,
        relative: &BodyStates,
        wrenches: &mut Wrenches,
    ) {
        let slot = work.slot();
        for (i, body) in self.bodies.iter().enumerate() {
            let o = &slot.offset_states.position[i];
            let rot = [o[3], o[4], o[5]];
            let w = &mut wrenches[i];
            let f = [w[0], w[1], w[2]];
            let m = [w[3], w[4], w[5]];
            let f = sub(f, cross(rot, f));
            let m = sub(m, cross(rot, m));
            let load = &slot.loads[i];
            w[0] = f[0] + load.gravity[0];
            w[1] = f[1] + load.gravity[1] + load.centripetal[0];
            w[2] = f[2] + load.gravity[2] + load.centripetal[1];
            w[3] = m[0];
            w[4] = m[1];
            w[5] = m[2] - load.yaw_acceleration;
            if body.spin != 0.0 {
                // The structure's gyroscopic moments used the reference-frame rates; the
                // absolute ones add the own frame's yaw and roll rates.
                let h = load.spin;
                let common = &work.states.velocity[i];
                let own = &relative.velocity[i];
                let yaw = own[YAW] + load.yaw_rate;
                let roll = own[3] + load.roll_rate;
                w[3] += h * (yaw - common[YAW]);
                w[5] -= h * (roll - common[3]);
            }
        }
    }
}
