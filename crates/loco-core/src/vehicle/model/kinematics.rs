//! Small-motion kinematics of the bodies: each body's absolute motion as a sparse linear map of
//! the generalized coordinates.
//!
//! A body's motion is the 6-vector (x, y, z, roll, pitch, yaw) of its centre of gravity: m and rad,
//! small perturbations about the nominal configuration. For a free body the map selects six
//! coordinates; for a body defined relative to a parent (hollow shaft, traction rod, rotary arm)
//! it adds the parent's motion carried to the joint (`u_joint = u_parent + θ_parent × r_joint`) to
//! the relative coordinates. Velocities use the same map (it is constant).

use crate::simd::vec3;
use crate::vehicle::model::layout::N_DOF;

/// One row of a sparse map: (coordinate index, coefficient) pairs.
pub type SparseRow = Vec<(usize, f64)>;

/// The motion map of one body: `u = T q`, six sparse rows.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionMap {
    /// Rows for x, y, z (m) and roll, pitch, yaw (rad).
    rows: [SparseRow; 6],
    /// `Some(first)` when the rows select the six coordinates from `first` with coefficient 1
    /// (a free body): the map is then a copy, taken without walking the rows (same values, as
    /// `1·q` is `q`).
    free: Option<usize>,
    /// The rows one after the other, and where each ends in it: the time loop walks one slice
    /// instead of six vectors (same terms in the same order, so the same sums).
    flat: Vec<(usize, f64)>,
    ends: [usize; 6],
    /// One more than the largest coordinate index in the rows: the length the coordinates
    /// must have, checked once per call instead of at every term (the terms' bounds checks
    /// were a sixth of the body states' and generalized forces' instructions).
    min_len: usize,
}

/// A dense 6×N_DOF map used while building (compressed to [`MotionMap`] afterwards).
#[derive(Debug, Clone)]
pub struct DenseMap(pub Vec<[f64; N_DOF]>);

impl DenseMap {
    /// A free body whose six coordinates start at `first`.
    pub fn free(first: usize) -> Self {
        let mut m = DenseMap(vec![[0.0; N_DOF]; 6]);
        for k in 0..6 {
            m.0[k][first + k] = 1.0;
        }
        m
    }

    /// A body attached to `parent` at the joint `r_joint` (m, from the parent's centre of gravity,
    /// vehicle axes), with its centre of gravity at `r_cg` (m, from the joint). `inherit[k]` says
    /// whether rotation k (roll, pitch, yaw) follows the parent; `relative` lists
    /// (motion component 0..6, coordinate index) of the body's own coordinates.
    // Each index addresses the same column of several rows at once.
    #[allow(clippy::needless_range_loop)]
    pub fn attached(
        parent: &DenseMap,
        r_joint: [f64; 3],
        r_cg: [f64; 3],
        inherit: [bool; 3],
        relative: &[(usize, usize)],
    ) -> Self {
        let p = &parent.0;
        let mut m = DenseMap(vec![[0.0; N_DOF]; 6]);
        for j in 0..N_DOF {
            let parent_rot = [p[3][j], p[4][j], p[5][j]];
            let joint = add([p[0][j], p[1][j], p[2][j]], cross(parent_rot, r_joint));
            for k in 0..3 {
                m.0[k][j] = joint[k];
                if inherit[k] {
                    m.0[3 + k][j] = parent_rot[k];
                }
            }
        }
        for &(component, index) in relative {
            m.0[component][index] += 1.0;
        }
        // Carry the joint motion to the centre of gravity with the body's own rotation.
        for j in 0..N_DOF {
            let rot = [m.0[3][j], m.0[4][j], m.0[5][j]];
            let arm = cross(rot, r_cg);
            for k in 0..3 {
                m.0[k][j] += arm[k];
            }
        }
        m
    }

    /// Compresses to sparse rows, dropping exact zeros.
    pub fn compress(&self) -> MotionMap {
        let row = |k: usize| -> SparseRow {
            self.0[k]
                .iter()
                .enumerate()
                .filter(|(_, c)| **c != 0.0)
                .map(|(j, c)| (j, *c))
                .collect()
        };
        MotionMap::new([row(0), row(1), row(2), row(3), row(4), row(5)])
    }
}

impl MotionMap {
    /// The map of six sparse rows (x, y, z, roll, pitch, yaw).
    pub fn new(rows: [SparseRow; 6]) -> Self {
        let first = rows[0].first().map(|&(j, _)| j);
        let free = first.filter(|&first| {
            rows.iter()
                .enumerate()
                .all(|(k, row)| row.as_slice() == [(first + k, 1.0)])
        });
        let flat: Vec<(usize, f64)> = rows.iter().flatten().copied().collect();
        let mut ends = [0; 6];
        let mut end = 0;
        for (e, row) in ends.iter_mut().zip(&rows) {
            end += row.len();
            *e = end;
        }
        let min_len = flat.iter().map(|&(j, _)| j + 1).max().unwrap_or(0);
        Self {
            rows,
            free,
            flat,
            ends,
            min_len,
        }
    }

    /// Row `k`'s (coordinate index, coefficient) pairs in [`Self::flat`].
    #[inline]
    fn row(&self, k: usize) -> &[(usize, f64)] {
        let start = if k == 0 { 0 } else { self.ends[k - 1] };
        &self.flat[start..self.ends[k]]
    }

    /// Rows for x, y, z (m) and roll, pitch, yaw (rad): (coordinate index, coefficient).
    pub fn rows(&self) -> &[SparseRow; 6] {
        &self.rows
    }

    /// The body motion `T q` for coordinates (or velocities) `q`.
    #[inline]
    pub fn apply(&self, q: &[f64]) -> [f64; 6] {
        if let Some(f) = self.free {
            let q = &q[f..f + 6];
            return [q[0], q[1], q[2], q[3], q[4], q[5]];
        }
        self.check(q);
        let mut u = [0.0; 6];
        for (k, u) in u.iter_mut().enumerate() {
            *u = self.row(k).iter().map(|&(j, c)| c * q[j]).sum();
        }
        u
    }

    /// Panics unless `x` holds every coordinate of the rows (one check before the rows'
    /// accesses, with a clear message).
    #[inline(always)]
    fn check(&self, x: &[f64]) {
        assert!(
            x.len() >= self.min_len,
            "MotionMap: fewer coordinates than its rows read"
        );
    }

    /// [`Self::apply`] to coordinates `q` and velocities `qd` in one pass over the rows (each
    /// sum as `Iterator::sum` takes it: from −0, term by term).
    #[inline]
    pub fn apply_both(&self, q: &[f64], qd: &[f64]) -> ([f64; 6], [f64; 6]) {
        if let Some(f) = self.free {
            let (q, qd) = (&q[f..f + 6], &qd[f..f + 6]);
            return (
                [q[0], q[1], q[2], q[3], q[4], q[5]],
                [qd[0], qd[1], qd[2], qd[3], qd[4], qd[5]],
            );
        }
        self.check(q);
        self.check(qd);
        let (mut u, mut v) = ([0.0; 6], [0.0; 6]);
        for k in 0..6 {
            let (mut a, mut b) = (-0.0, -0.0);
            for &(j, c) in self.row(k) {
                a += c * q[j];
                b += c * qd[j];
            }
            u[k] = a;
            v[k] = b;
        }
        (u, v)
    }

    /// Adds the generalized force `Tᵀ w` of the body wrench `w` (N, N·m) to `gen_force`.
    #[inline]
    pub fn add_transpose(&self, wrench: &[f64; 6], gen_force: &mut [f64]) {
        if let Some(f) = self.free {
            for (g, w) in gen_force[f..f + 6].iter_mut().zip(wrench) {
                if *w != 0.0 {
                    *g += w;
                }
            }
            return;
        }
        self.check(gen_force);
        for (k, &w) in wrench.iter().enumerate() {
            if w != 0.0 {
                for &(j, c) in self.row(k) {
                    gen_force[j] += c * w;
                }
            }
        }
    }
}

/// Cross product a × b (`simd::vec3`'s, which the lanes share).
#[inline]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    vec3::cross(a, b)
}

/// Sum a + b.
#[inline]
pub fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    vec3::add(a, b)
}

/// Difference a − b.
#[inline]
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    vec3::sub(a, b)
}

/// Dot product.
#[inline]
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    vec3::dot(a, b)
}

/// Displacement (m) of a material point at `r` (m, from the centre of gravity) of a body with
/// motion `u`: `u_trans + θ × r`. The same formula gives the velocity from the body velocity.
#[inline]
pub fn point_motion(u: &[f64; 6], r: [f64; 3]) -> [f64; 3] {
    add([u[0], u[1], u[2]], cross([u[3], u[4], u[5]], r))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attached_body_follows_parent_rigidly() {
        let parent = DenseMap::free(0);
        // Child joint 1 m ahead of the parent, centre of gravity 0.5 m above the joint, no own DOF.
        let child = DenseMap::attached(
            &parent,
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.5],
            [true, true, true],
            &[],
        )
        .compress();
        let parent = parent.compress();
        let mut q = [0.0; N_DOF];
        q[5] = 1e-3; // parent yaw
        q[3] = 2e-3; // parent roll
        let up = parent.apply(&q);
        let uc = child.apply(&q);
        // Same material point seen from both bodies.
        let from_parent = point_motion(&up, [1.0, 0.0, 0.5]);
        let from_child = point_motion(&uc, [0.0, 0.0, 0.0]);
        for k in 0..3 {
            assert!((from_parent[k] - from_child[k]).abs() < 1e-15);
        }
    }

    #[test]
    fn one_pass_over_both_vectors_gives_the_bits_of_two() {
        for map in [DenseMap::free(6).compress(), attached_child()] {
            let q: Vec<f64> = (0..N_DOF).map(|i| (i as f64 * 0.37).sin()).collect();
            let qd: Vec<f64> = (0..N_DOF).map(|i| -(i as f64 * 0.11).cos()).collect();
            // Zeros of both signs: an empty row and a sum of zeros keep their sign.
            let zeros: Vec<f64> = (0..N_DOF)
                .map(|i| if i % 2 == 0 { 0.0 } else { -0.0 })
                .collect();
            for (a, b) in [(&q, &qd), (&zeros, &q)] {
                let (u, v) = map.apply_both(a, b);
                let bits = |x: [f64; 6]| x.map(f64::to_bits);
                assert_eq!(bits(u), bits(map.apply(a)));
                assert_eq!(bits(v), bits(map.apply(b)));
            }
        }
    }

    /// A body attached to a free one with two coordinates of its own (40, 41), compressed.
    fn attached_child() -> MotionMap {
        let parent = DenseMap::free(6);
        DenseMap::attached(
            &parent,
            [0.3, -0.2, 0.1],
            [0.1, 0.0, 0.0],
            [true, false, true],
            &[(4, 40), (1, 41)],
        )
        .compress()
    }

    #[test]
    fn unchecked_terms_give_the_bits_of_the_indexed_rows() {
        let child = attached_child();
        let q: Vec<f64> = (0..N_DOF).map(|i| (i as f64 * 0.37).sin()).collect();
        let u = child.apply(&q);
        let w = [1.0, -2.0, 0.0, 0.3, -0.7, 0.9];
        let mut g: Vec<f64> = (0..N_DOF).map(|i| (i as f64 * 0.23).cos()).collect();
        let mut expected = g.clone();
        child.add_transpose(&w, &mut g);
        for (k, row) in child.rows().iter().enumerate() {
            let sum: f64 = row.iter().map(|&(j, c)| c * q[j]).sum();
            assert_eq!(u[k].to_bits(), sum.to_bits());
            for &(j, c) in row.iter().filter(|_| w[k] != 0.0) {
                expected[j] += c * w[k];
            }
        }
        assert_eq!(
            g.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            expected.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        // Coordinates that stop short of the rows are refused, not read past.
        let short = std::panic::catch_unwind(|| child.apply(&q[..41]));
        assert!(short.is_err());
    }

    #[test]
    fn transpose_is_the_adjoint() {
        let child = attached_child();
        let q: Vec<f64> = (0..N_DOF).map(|i| (i as f64 * 0.37).sin()).collect();
        let w = [1.0, -2.0, 0.5, 0.3, -0.7, 0.9];
        let u = child.apply(&q);
        let mut g = vec![0.0; N_DOF];
        child.add_transpose(&w, &mut g);
        let lhs: f64 = u.iter().zip(w).map(|(a, b)| a * b).sum();
        let rhs: f64 = g.iter().zip(&q).map(|(a, b)| a * b).sum();
        assert!((lhs - rhs).abs() < 1e-12);
    }
}
