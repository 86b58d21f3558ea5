//! The AVX lanes of [`super::BushingLanes`]: four elements' [`Bushing::apply`] in one register.
//!
//! Each operation is named as the AVX instruction of one IEEE operation per lane, in the scalar
//! code's order; the helpers are `unsafe fn`s enabling AVX (the crate's Rust version predates
//! safe ones), called only from [`compute_avx`], whose caller has checked the processor.
//!
//! [`Bushing::apply`]: crate::vehicle::model::elements::Bushing::apply

use super::{BushingLanes, Quad, QuadForces, W};
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::layout::N_BODIES;
use std::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_castpd128_pd256, _mm256_insertf128_pd, _mm256_loadu_pd,
    _mm256_mul_pd, _mm256_permute2f128_pd, _mm256_set1_pd, _mm256_storeu_pd, _mm256_sub_pd,
    _mm256_unpackhi_pd, _mm256_unpacklo_pd, _mm256_xor_pd, _mm_loadu_pd,
};

/// Every quad's forces into `forces`, the load-path quads first, four elements in one AVX
/// register.
#[target_feature(enable = "avx")]
pub(super) unsafe fn compute_avx(
    lanes: &BushingLanes,
    states: &BodyStates,
    forces: &mut Vec<QuadForces>,
) {
    let n = lanes.on_load_path.len();
    forces.resize(n + lanes.off_load_path.len(), QuadForces::default());
    let (on, off) = forces.split_at_mut(n);
    for (quad, out) in lanes.on_load_path.iter().zip(on) {
        quad_forces::<true>(quad, states, out);
    }
    for (quad, out) in lanes.off_load_path.iter().zip(off) {
        quad_forces::<false>(quad, states, out);
    }
}

pub(in crate::vehicle) type V3 = [__m256d; 3];

// The lane-wise operations: each an IEEE operation per lane, as the scalar code's.
#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn mul(a: __m256d, b: __m256d) -> __m256d {
    _mm256_mul_pd(a, b)
}

#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn dif(a: __m256d, b: __m256d) -> __m256d {
    _mm256_sub_pd(a, b)
}

#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn sum(a: __m256d, b: __m256d) -> __m256d {
    _mm256_add_pd(a, b)
}

/// [`super::kinematics::cross`] lane by lane (the same products and differences).
#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn cross(a: V3, b: V3) -> V3 {
    [
        dif(mul(a[1], b[2]), mul(a[2], b[1])),
        dif(mul(a[2], b[0]), mul(a[0], b[2])),
        dif(mul(a[0], b[1]), mul(a[1], b[0])),
    ]
}

#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn add(a: V3, b: V3) -> V3 {
    [sum(a[0], b[0]), sum(a[1], b[1]), sum(a[2], b[2])]
}

#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn sub(a: V3, b: V3) -> V3 {
    [dif(a[0], b[0]), dif(a[1], b[1]), dif(a[2], b[2])]
}

/// `a·b − c·d` component by component.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn products_difference(a: V3, b: V3, c: V3, d: V3) -> V3 {
    sub(
        [mul(a[0], b[0]), mul(a[1], b[1]), mul(a[2], b[2])],
        [mul(c[0], d[0]), mul(c[1], d[1]), mul(c[2], d[2])],
    )
}

/// `a·b + c·d` component by component.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn products_sum(a: V3, b: V3, c: V3, d: V3) -> V3 {
    add(
        [mul(a[0], b[0]), mul(a[1], b[1]), mul(a[2], b[2])],
        [mul(c[0], d[0]), mul(c[1], d[1]), mul(c[2], d[2])],
    )
}

/// `s·x` component by component.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn scaled(s: __m256d, x: V3) -> V3 {
    [mul(s, x[0]), mul(s, x[1]), mul(s, x[2])]
}

/// The bodies' 6-vectors, one body per lane: `[k]` holds component `k` of the four bodies.
/// Each vector is loaded whole (four and two values) and transposed in registers: fewer
/// instructions than twenty-four values gathered one by one, the same values.
#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn gather6(
    bodies: &[usize; W],
    of: &[[f64; 6]; N_BODIES],
) -> [__m256d; 6] {
    let rows = [
        &of[bodies[0]],
        &of[bodies[1]],
        &of[bodies[2]],
        &of[bodies[3]],
    ];
    // Components 0..4 (each row holds six contiguous f64): a 4×4 transpose.
    let r: [__m256d; 4] = [
        _mm256_loadu_pd(rows[0].as_ptr()),
        _mm256_loadu_pd(rows[1].as_ptr()),
        _mm256_loadu_pd(rows[2].as_ptr()),
        _mm256_loadu_pd(rows[3].as_ptr()),
    ];
    let (t0, t1) = (
        _mm256_unpacklo_pd(r[0], r[1]),
        _mm256_unpackhi_pd(r[0], r[1]),
    );
    let (t2, t3) = (
        _mm256_unpacklo_pd(r[2], r[3]),
        _mm256_unpackhi_pd(r[2], r[3]),
    );
    // Components 4 and 5: rows 0 and 2, rows 1 and 3 side by side, then interleaved.
    let tail = |row: &[f64; 6]| _mm_loadu_pd(row[4..].as_ptr());
    let u02 = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(tail(rows[0])), tail(rows[2]));
    let u13 = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(tail(rows[1])), tail(rows[3]));
    [
        _mm256_permute2f128_pd::<0x20>(t0, t2),
        _mm256_permute2f128_pd::<0x20>(t1, t3),
        _mm256_permute2f128_pd::<0x31>(t0, t2),
        _mm256_permute2f128_pd::<0x31>(t1, t3),
        _mm256_unpacklo_pd(u02, u13),
        _mm256_unpackhi_pd(u02, u13),
    ]
}

/// [`pair_motion`]'s callers.
pub(in crate::vehicle) const BUSHINGS: u8 = 0;
pub(in crate::vehicle) const DAMPERS: u8 = 1;

/// Two bodies' attachment points in relative motion, four pairs per register
/// (`Attachment::motion_and_arms`; the bushings' and the dampers' lanes share it).
pub(in crate::vehicle) struct PairMotion {
    /// Each body's small rotation (rad) and rotation rate (rad/s), body a then body b.
    pub(in crate::vehicle) rot: [V3; 2],
    pub(in crate::vehicle) rate: [V3; 2],
    /// Displacement (m) and velocity (m/s) of b's point against a's.
    pub(in crate::vehicle) d: V3,
    pub(in crate::vehicle) v: V3,
    /// Each point's lever arm from its body's centre, turned with the body (m).
    pub(in crate::vehicle) arm: [V3; 2],
}

/// The motion of the points `point_a` on bodies `a` and `point_b` on bodies `b` (lane `l` one
/// pair), in the scalar code's operations and order.
///
/// `USER` gives each caller its own copy ([`BUSHINGS`], [`DAMPERS`]): the dampers' single call
/// is then inlined whichever codegen unit the callers land in. One shared copy was left out of
/// line when a change elsewhere put the bushings' and the dampers' callers in one unit (6.6e6
/// more instructions per run); `#[inline(always)]` is not allowed with `#[target_feature]`.
#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn pair_motion<const USER: u8>(
    a: &[usize; W],
    b: &[usize; W],
    point_a: &[[f64; W]; 3],
    point_b: &[[f64; W]; 3],
    s: &BodyStates,
) -> PairMotion {
    let (ua, ub) = (gather6(a, &s.position), gather6(b, &s.position));
    let (wa, wb) = (gather6(a, &s.velocity), gather6(b, &s.velocity));
    let (point_a, point_b) = (v3(point_a), v3(point_b));
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

/// A quad's constant 3-vector as three registers (lane `l` from index `l` of each array).
#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn v3(a: &[[f64; W]; 3]) -> V3 {
    // Each array is four contiguous f64 a reference holds: one unaligned load reads them.
    [
        _mm256_loadu_pd(a[0].as_ptr()),
        _mm256_loadu_pd(a[1].as_ptr()),
        _mm256_loadu_pd(a[2].as_ptr()),
    ]
}

/// Stores the lanes of a 3-vector into `out` (lane `l` at index `l` of each array).
#[target_feature(enable = "avx")]
#[inline]
pub(in crate::vehicle) unsafe fn store(x: V3, out: &mut [[f64; W]; 3]) {
    // Each array is four contiguous f64 a mutable reference holds.
    for (o, x) in out.iter_mut().zip(x) {
        _mm256_storeu_pd(o.as_mut_ptr(), x);
    }
}

/// The forces of one quad into `out`, [`Bushing::apply`]'s operations lane by lane
/// (`ON_LOAD_PATH` its corotational branch).
#[target_feature(enable = "avx")]
#[inline]
unsafe fn quad_forces<const ON_LOAD_PATH: bool>(q: &Quad, s: &BodyStates, out: &mut QuadForces) {
    let m = pair_motion::<BUSHINGS>(&q.body_a, &q.body_b, &q.point_a, &q.point_b, s);
    let ([rot_a, rot_b], [rate_a, rate_b], [arm_a, arm_b]) = (m.rot, m.rate, m.arm);
    let (d, v) = (m.d, m.v);
    let (neg_k, c) = (v3(&q.neg_stiffness), v3(&q.damping));
    let (neg_kr, cr) = (v3(&q.neg_rotational_stiffness), v3(&q.rotational_damping));
    let (rotation, rate) = (sub(rot_b, rot_a), sub(rate_b, rate_a));
    let moment = products_difference(neg_kr, rotation, cr, rate);
    let f = if ON_LOAD_PATH {
        let (ma, mb) = (v3(&q.turns_a), v3(&q.turns_b));
        let half = _mm256_set1_pd(0.5);
        let theta = scaled(half, products_sum(rot_a, ma, rot_b, mb));
        let d_local = sub(d, cross(theta, d));
        let f_local = products_difference(neg_k, d_local, c, v);
        let f = add(f_local, cross(theta, f_local));
        let couple = cross(d, f);
        let half_couple = scaled(half, couple);
        store(sub(moment, half_couple), &mut out.own_b);
        store(add(moment, half_couple), &mut out.own_a);
        f
    } else {
        store(moment, &mut out.own_b);
        store(moment, &mut out.own_a);
        products_difference(neg_k, d, c, v)
    };
    store(f, &mut out.force);
    store(cross(arm_b, f), &mut out.moment_b);
    // −f lane by lane (exact, as the scalar code's `[-f[0], -f[1], -f[2]]`).
    let sign = _mm256_set1_pd(-0.0);
    let neg_f = [
        _mm256_xor_pd(f[0], sign),
        _mm256_xor_pd(f[1], sign),
        _mm256_xor_pd(f[2], sign),
    ];
    store(cross(arm_a, neg_f), &mut out.moment_a);
}
