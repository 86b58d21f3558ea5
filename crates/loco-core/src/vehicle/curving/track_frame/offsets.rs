//! Each body's track frame at one vehicle position and speed (`super`'s module documentation):
//! the design at every station, each body's frame offset from the reference frame and the frame
//! terms that do not depend on the state. Computed twice per step (the frame slots keep them for
//! the RK stages sharing a time), so its cost is a curved run's main extra besides the contact.

use super::forces::W;
use super::{free_bodies, CurvedTrack, FrameLoad, FrameWork};
use crate::simd::multiversion;
use crate::track::DesignPoint;
use crate::vehicle::model::kinematics::{add, cross};
use crate::vehicle::model::layout::N_BODIES;

/// [`CurvedTrack::compute_frames_plain`] compiled for the baseline and for AVX (see the module
/// `simd`): the same operations in the same order (no fused multiply-add), in AVX's
/// three-operand forms that spare the copies the two-operand ones need, and some pairs of the
/// offsets' rows four wide.
#[multiversion(targets("x86_64+avx"))]
fn compute_frames_copy(track: &CurvedTrack, s_r: f64, speed: f64, work: &mut FrameWork) {
    track.compute_frames_plain(s_r, speed, work);
}

impl CurvedTrack {
    /// The frames at (`s_r`, `speed`) into `work`'s active slot: the design at every body and
    /// each body's frame offset from the reference frame.
    pub(super) fn compute_frames(&self, s_r: f64, speed: f64, work: &mut FrameWork) {
        compute_frames_copy(self, s_r, speed, work);
    }

    #[inline(always)]
    pub(super) fn compute_frames_plain(&self, s_r: f64, speed: f64, work: &mut FrameWork) {
        let slot = &mut work.slots[work.active];
        let stations = slot.station_points.iter_mut().zip(&mut slot.station_roll);
        let stations = stations.zip(&mut slot.station_roll_bits);
        let stations = stations.zip(&mut work.piece_hints);
        let terms_of = Some((self as *const Self as usize, speed.to_bits()));
        let same_terms = slot.terms_of == terms_of;
        slot.terms_of = terms_of;
        let mut kept = [false; N_BODIES + 1];
        let stations = stations.zip(&mut kept);
        for (((((point, roll), bits), hint), keep), x) in stations.zip(&self.stations) {
            let fresh = self.design.at_from(s_r + x, hint);
            *keep = same_terms && same_terms_bits(point, &fresh);
            *point = fresh;
            if *bits != Some(point.roll.to_bits()) {
                *roll = point.roll.sin_cos();
                *bits = Some(point.roll.to_bits());
            }
        }
        let r = slot.station_points[0];
        let (st, ct) = slot.station_roll[0];
        let roll_rate_r = speed * r.roll_rate;
        for (_, body) in free_bodies() {
            let p = &slot.station_points[self.station_of[body]];
            let x = self.bodies[body].position;
            let d_psi = p.heading - r.heading;
            let lateral = p.heading_integral - r.heading_integral - r.heading * x[0];
            let rot = [p.roll - r.roll, d_psi * st, d_psi * ct];
            let d_psi_rate = speed * (p.curvature - r.curvature);
            let lateral_rate = speed * (d_psi - r.curvature * x[0]);
            let rot_rate = [
                speed * p.roll_rate - roll_rate_r,
                d_psi_rate * st + d_psi * ct * roll_rate_r,
                d_psi_rate * ct - d_psi * st * roll_rate_r,
            ];
            let arm = [0.0, x[1], x[2]];
            let trans = add([0.0, lateral * ct, -lateral * st], cross(rot, arm));
            let trans_rate = add(
                [
                    0.0,
                    lateral_rate * ct - lateral * st * roll_rate_r,
                    -lateral_rate * st - lateral * ct * roll_rate_r,
                ],
                cross(rot_rate, arm),
            );
            // A free body's map is the identity on its coordinates: the offset is its state.
            slot.offset_states.position[body] =
                [trans[0], trans[1], trans[2], rot[0], rot[1], rot[2]];
            slot.offset_states.velocity[body] = [
                trans_rate[0],
                trans_rate[1],
                trans_rate[2],
                rot_rate[0],
                rot_rate[1],
                rot_rate[2],
            ];
        }
        // The attached bodies (hollow shafts, traction rods, rotary arms with their wheelset's
        // pitch) take their parent's rigid motion: their maps applied to the offsets' coordinates
        // give u = u_parent + θ_parent × (x_body − x_parent), evaluated here directly (the maps'
        // sparse rows cost five times as much; tests compare both).
        for &(body, parent, arm) in &self.attached {
            for states in [
                &mut slot.offset_states.position,
                &mut slot.offset_states.velocity,
            ] {
                let u = states[parent];
                let t = add([u[0], u[1], u[2]], cross([u[3], u[4], u[5]], arm));
                states[body] = [t[0], t[1], t[2], u[3], u[4], u[5]];
            }
        }
        let v2 = speed * speed;
        let g = self.gravity;
        for (i, body) in self.bodies.iter().enumerate() {
            let o = &slot.offset_states.position[i];
            let rot = [o[3], o[4], o[5]];
            let k = self.station_of[i];
            let mg = body.mass * g;
            if kept[k] {
                // The same operations on the same bits as below, the others kept.
                let (q, l) = (&mut slot.lanes[i / W], i % W);
                for (lane, v) in q.rot.iter_mut().zip(rot) {
                    lane[l] = v;
                }
                q.gravity[0][l] = -mg * rot[1];
                q.gravity[1][l] = slot.cant_gravity[i] + mg * rot[0];
                continue;
            }
            let p = &slot.station_points[k];
            let (s, c) = slot.station_roll[k];
            let a = v2 * p.curvature;
            slot.cant_gravity[i] = -mg * s;
            let gravity = [
                -mg * rot[1],
                slot.cant_gravity[i] + mg * rot[0],
                mg - mg * c,
            ];
            let centripetal = [-body.mass * a * c, body.mass * a * s];
            let (q, l) = (&mut slot.lanes[i / W], i % W);
            for k in 0..3 {
                q.rot[k][l] = rot[k];
                q.gravity[k][l] = gravity[k];
            }
            q.centripetal[0][l] = centripetal[0];
            q.centripetal[1][l] = centripetal[1];
            q.yaw_acceleration[l] = body.yaw_inertia * v2 * p.curvature_rate;
            slot.loads[i] = FrameLoad {
                yaw_rate: speed * p.curvature * c,
                roll_rate: speed * p.roll_rate,
                spin: body.spin * speed,
            };
        }
    }
}

/// Whether the state-independent frame terms of `a` and `b` are the same bits: curvature, its
/// rate, roll and roll rate (the heading and its integral enter only the offsets).
#[inline]
fn same_terms_bits(a: &DesignPoint, b: &DesignPoint) -> bool {
    let bits =
        |p: &DesignPoint| [p.curvature, p.curvature_rate, p.roll, p.roll_rate].map(f64::to_bits);
    bits(a) == bits(b)
}
