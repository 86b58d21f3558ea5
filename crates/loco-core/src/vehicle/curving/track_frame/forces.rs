//! The frame terms added to the wrenches in every evaluation on a curve (`super`'s module
//! documentation): the wrenches formed in the reference frame turned into each body's own frame,
//! gravity on the cant, the centripetal force, the clothoid's yaw acceleration and the spinning
//! parts' gyroscopic moments.
//!
//! Why lanes: turning 25 wrenches (two cross products each) cost about 70 instructions a body in
//! every evaluation, 2.7 % of a curved run. Every body does the same operations, so four bodies
//! are turned in lockstep (one AVX register per quantity in the AVX copy, see the module `simd`,
//! as `bushing_lanes.rs` does); the per-body constants are kept four to a lane group when the
//! frames are computed. Each lane does the scalar code's IEEE operations in its order (no fused
//! multiply-add, no reordering): the same bits.

use super::{CurvedTrack, FrameWork};
use crate::simd::vec3::{cross, sub};
use crate::simd::{multiversion, target_cfg_f, Four, Plain};
use crate::vehicle::model::elements::{BodyStates, Wrenches};
use crate::vehicle::model::layout::{N_BODIES, YAW};

/// Bodies per lane group.
pub(super) const W: usize = 4;
/// Lane groups covering every body (the last one partly).
pub(super) const GROUPS: usize = N_BODIES.div_ceil(W);
/// Lane groups whose four lanes are all bodies (the rest are turned one by one).
const FULL_GROUPS: usize = N_BODIES / W;

/// The state-independent terms of bodies `W·g … W·g + 3` (group g), lane l body `W·g + l`'s:
/// the rotation of its frame from the reference frame (rad), gravity in its own frame less the
/// reference vertical turned into it and the centripetal force (N), and the moment of the
/// frame's yaw acceleration I_z V² dκ/ds (N·m). Unused lanes hold zeros.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct ForceLanes {
    pub(super) rot: [[f64; W]; 3],
    pub(super) gravity: [[f64; W]; 3],
    pub(super) centripetal: [[f64; W]; 2],
    pub(super) yaw_acceleration: [f64; W],
}

/// Turns body `i`'s wrench into its own frame and adds its state-independent frame terms.
#[inline(always)]
fn turn(lanes: &[ForceLanes; GROUPS], i: usize, w: &mut [f64; 6]) {
    let (q, l) = (&lanes[i / W], i % W);
    let rot = [q.rot[0][l], q.rot[1][l], q.rot[2][l]];
    let f = [w[0], w[1], w[2]];
    let m = [w[3], w[4], w[5]];
    let f = sub(f, cross(rot, f));
    let m = sub(m, cross(rot, m));
    w[0] = f[0] + q.gravity[0][l];
    w[1] = f[1] + q.gravity[1][l] + q.centripetal[0][l];
    w[2] = f[2] + q.gravity[2][l] + q.centripetal[1][l];
    w[3] = m[0];
    w[4] = m[1];
    w[5] = m[2] - q.yaw_acceleration[l];
}

/// Every body's wrench turned and its terms added: the full lane groups four bodies in
/// lockstep, the rest one by one.
/// In AVX registers in the AVX copy, as plain arrays in the baseline copy (the module `simd`).
#[multiversion(targets("x86_64+avx"))]
fn turn_all(lanes: &[ForceLanes; GROUPS], wrenches: &mut Wrenches) {
    #[cfg(target_arch = "x86_64")]
    if target_cfg_f!(target_feature = "avx") {
        if let Some(avx) = crate::simd::Avx::detect() {
            return turn_all_in(avx, lanes, wrenches);
        }
    }
    turn_all_in(Plain, lanes, wrenches);
}

/// [`turn_all`] in the lane set `set`.
#[inline(always)]
fn turn_all_in<S: Four>(set: S, lanes: &[ForceLanes; GROUPS], wrenches: &mut Wrenches) {
    for (q, rows) in lanes[..FULL_GROUPS]
        .iter()
        .zip(wrenches.chunks_exact_mut(W))
    {
        let rows: &mut [[f64; 6]; W] = rows.try_into().expect("chunks of W rows");
        turn_group(set, q, rows);
    }
    for (i, w) in wrenches.iter_mut().enumerate().skip(FULL_GROUPS * W) {
        turn(lanes, i, w);
    }
}

/// [`turn`] of the four bodies of `rows`, lane by lane: the rows transposed into lanes of one
/// component each, turned, and transposed back.
#[inline(always)]
fn turn_group<S: Four>(set: S, q: &ForceLanes, rows: &mut [[f64; 6]; W]) {
    let c = set.rows_to_lanes([&rows[0], &rows[1], &rows[2], &rows[3]]);
    let rot = [
        set.load(&q.rot[0]),
        set.load(&q.rot[1]),
        set.load(&q.rot[2]),
    ];
    let f = sub([c[0], c[1], c[2]], cross(rot, [c[0], c[1], c[2]]));
    let m = sub([c[3], c[4], c[5]], cross(rot, [c[3], c[4], c[5]]));
    let out = [
        f[0] + set.load(&q.gravity[0]),
        f[1] + set.load(&q.gravity[1]) + set.load(&q.centripetal[0]),
        f[2] + set.load(&q.gravity[2]) + set.load(&q.centripetal[1]),
        m[0],
        m[1],
        m[2] - set.load(&q.yaw_acceleration),
    ];
    set.lanes_to_rows(out, rows);
}

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
        turn_all(&slot.lanes, wrenches);
        for &i in &self.spinning {
            // The structure's gyroscopic moments used the reference-frame rates; the absolute
            // ones add the own frame's yaw and roll rates.
            let load = &slot.loads[i];
            let w = &mut wrenches[i];
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Lanes and wrenches of every sign and size, from a fixed sequence.
    fn sample() -> ([ForceLanes; GROUPS], Wrenches) {
        let mut x = 0.37_f64;
        let mut next = || {
            x = (x * 997.0 + 0.123).fract();
            (x - 0.5) * 10f64.powi((x * 12.0) as i32 - 6)
        };
        let mut lanes = [ForceLanes::default(); GROUPS];
        for i in 0..N_BODIES {
            let (q, l) = (&mut lanes[i / W], i % W);
            for k in 0..3 {
                q.rot[k][l] = 1e-3 * next();
                q.gravity[k][l] = next();
            }
            q.centripetal[0][l] = next();
            q.centripetal[1][l] = next();
            q.yaw_acceleration[l] = next();
        }
        let mut wrenches = [[0.0; 6]; N_BODIES];
        for w in wrenches.iter_mut() {
            w.iter_mut().for_each(|c| *c = next());
        }
        // Signed zeros: the sums must keep them as the scalar code does.
        wrenches[3] = [-0.0, 0.0, -0.0, 0.0, -0.0, -0.0];
        (lanes, wrenches)
    }

    #[test]
    fn the_lanes_turn_every_wrench_as_one_body_at_a_time() {
        let (lanes, wrenches) = sample();
        let mut expected = wrenches;
        for (i, w) in expected.iter_mut().enumerate() {
            turn(&lanes, i, w);
        }
        let mut turned = wrenches;
        turn_all(&lanes, &mut turned);
        let mut plain = wrenches;
        turn_all_in(Plain, &lanes, &mut plain);
        for i in 0..N_BODIES {
            let bits = |w: &[f64; 6]| w.map(f64::to_bits);
            assert_eq!(bits(&turned[i]), bits(&expected[i]), "body {i}");
            assert_eq!(bits(&plain[i]), bits(&expected[i]), "plain lanes, body {i}");
        }
    }
}
