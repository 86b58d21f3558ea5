//! Two bodies' attachment points in relative motion, `W` pairs in lockstep: what the bushings'
//! and the dampers' lanes ([`super::bushing_lanes`], [`super::damper_lanes`]) both start from.
//!
//! Written over a lane set [`Four`] with `simd::vec3`'s algebra (the scalar `kinematics`
//! functions are that algebra's `f64` instance), so every lane does
//! `Attachment::motion_and_arms`'s IEEE operations in its order. Everything here is
//! `#[inline(always)]`: it is compiled into the kernels' baseline and AVX copies.

use crate::simd::vec3::{add, cross, sub};
use crate::simd::Four;
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::layout::N_BODIES;

/// Elements per lane group.
pub(in crate::vehicle) const W: usize = 4;

/// A 3-vector of `W` elements in the lane set `S`, component `k` of each in `[k]`.
pub(in crate::vehicle) type V3<S> = [<S as Four>::V; 3];

/// Two bodies' attachment points in relative motion, `W` pairs.
pub(in crate::vehicle) struct PairMotion<S: Four> {
    /// Each body's small rotation (rad) and rotation rate (rad/s), body a then body b.
    pub(in crate::vehicle) rot: [V3<S>; 2],
    pub(in crate::vehicle) rate: [V3<S>; 2],
    /// Displacement (m) and velocity (m/s) of b's point against a's.
    pub(in crate::vehicle) d: V3<S>,
    pub(in crate::vehicle) v: V3<S>,
    /// Each point's lever arm from its body's centre, turned with the body (m).
    pub(in crate::vehicle) arm: [V3<S>; 2],
}

/// The bodies' 6-vectors, one body per lane: `[k]` holds component `k` of the `W` bodies.
#[inline(always)]
fn gather6<S: Four>(set: S, bodies: &[usize; W], of: &[[f64; 6]; N_BODIES]) -> [S::V; 6] {
    set.rows_to_lanes([
        &of[bodies[0]],
        &of[bodies[1]],
        &of[bodies[2]],
        &of[bodies[3]],
    ])
}

/// The motion of the points `point_a` on bodies `a` and `point_b` on bodies `b` (lane `l` one
/// pair), in the scalar code's operations and order.
#[inline(always)]
pub(in crate::vehicle) fn pair_motion<S: Four>(
    set: S,
    a: &[usize; W],
    b: &[usize; W],
    point_a: &[[f64; W]; 3],
    point_b: &[[f64; W]; 3],
    s: &BodyStates,
) -> PairMotion<S> {
    let (ua, ub) = (gather6(set, a, &s.position), gather6(set, b, &s.position));
    let (wa, wb) = (gather6(set, a, &s.velocity), gather6(set, b, &s.velocity));
    let (point_a, point_b) = (v3(set, point_a), v3(set, point_b));
    let rot_a = [ua[3], ua[4], ua[5]];
    let rot_b = [ub[3], ub[4], ub[5]];
    let turn_a = cross(rot_a, point_a);
    let turn_b = cross(rot_b, point_b);
    let d = sub(
        add([ub[0], ub[1], ub[2]], turn_b),
        add([ua[0], ua[1], ua[2]], turn_a),
    );
    let rate_a = [wa[3], wa[4], wa[5]];
    let rate_b = [wb[3], wb[4], wb[5]];
    let va = add([wa[0], wa[1], wa[2]], cross(rate_a, point_a));
    let vb = add([wb[0], wb[1], wb[2]], cross(rate_b, point_b));
    PairMotion {
        rot: [rot_a, rot_b],
        rate: [rate_a, rate_b],
        d,
        v: sub(vb, va),
        arm: [add(point_a, turn_a), add(point_b, turn_b)],
    }
}

/// A quad's constant 3-vector as lanes (lane `l` from index `l` of each array).
#[inline(always)]
pub(in crate::vehicle) fn v3<S: Four>(set: S, a: &[[f64; W]; 3]) -> V3<S> {
    [set.load(&a[0]), set.load(&a[1]), set.load(&a[2])]
}

/// Stores the lanes of a 3-vector into `out` (lane `l` at index `l` of each array).
#[inline(always)]
pub(in crate::vehicle) fn store<S: Four>(set: S, x: V3<S>, out: &mut [[f64; W]; 3]) {
    set.store(x[0], &mut out[0]);
    set.store(x[1], &mut out[1]);
    set.store(x[2], &mut out[2]);
}
