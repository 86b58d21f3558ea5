//! 3-vector algebra written once over [`Real`]: one vector (`f64` components) or `W` vectors in
//! lockstep ([`super::Lanes`] components). `vehicle::model::kinematics` is the `f64` instance, the
//! bushings', dampers' and frames' lanes the lane instance, so the lanes do the scalar code's
//! operations in its order by construction.

use super::Real;

/// Cross product a × b.
#[inline(always)]
pub(crate) fn cross<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Sum a + b.
#[inline(always)]
pub(crate) fn add<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// Difference a − b.
#[inline(always)]
pub(crate) fn sub<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Dot product, (a0·b0 + a1·b1) + a2·b2.
#[inline(always)]
pub(crate) fn dot<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `s·x` component by component.
#[inline(always)]
pub(crate) fn scaled<T: Real>(s: T, x: [T; 3]) -> [T; 3] {
    [s * x[0], s * x[1], s * x[2]]
}

/// −x component by component (exact).
#[inline(always)]
pub(crate) fn neg<T: Real>(x: [T; 3]) -> [T; 3] {
    [-x[0], -x[1], -x[2]]
}

/// `a·b − c·d` component by component.
#[inline(always)]
pub(crate) fn products_difference<T: Real>(a: [T; 3], b: [T; 3], c: [T; 3], d: [T; 3]) -> [T; 3] {
    sub(
        [a[0] * b[0], a[1] * b[1], a[2] * b[2]],
        [c[0] * d[0], c[1] * d[1], c[2] * d[2]],
    )
}

/// `a·b + c·d` component by component.
#[inline(always)]
pub(crate) fn products_sum<T: Real>(a: [T; 3], b: [T; 3], c: [T; 3], d: [T; 3]) -> [T; 3] {
    add(
        [a[0] * b[0], a[1] * b[1], a[2] * b[2]],
        [c[0] * d[0], c[1] * d[1], c[2] * d[2]],
    )
}
