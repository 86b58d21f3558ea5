//! The bushings' forces, four elements in lockstep.
//!
//! Why: the 50 bushings of the default vehicle took 18 % of a run (callgrind, etdrk4 at 2 ms),
//! each a few hundred scalar operations of 3-vector algebra that the compiler left scalar.
//! Elements of one kind (on the load path, whose axes turn with their ends, or off it) do the
//! same operations on different numbers, so four of them are computed in lockstep, as
//! `contact/fastsim_lanes.rs` does for FASTSIM's strips: one AVX register per quantity in the
//! AVX copy of [`compute`] (see the module `simd`), two SSE2 ones in the baseline copy. Each
//! lane does [`Bushing::apply`]'s IEEE operations in its order (no fused multiply-add, no
//! reordering). The forces are then added to the wrenches element by element in the elements'
//! order, the scalar loop's, so every wrench sums the same terms in the same order: the same
//! bits.

use crate::simd::vec3::{add, cross, neg, products_difference, products_sum, scaled, sub};
use crate::simd::{multiversion, target_cfg_f, Four, Plain};
use crate::vehicle::model::elements::{BodyStates, Bushing, Wrenches};
use crate::vehicle::model::pair_lanes::{pair_motion, store, v3, W};
use std::cell::RefCell;

/// The constants of `W` elements of one kind, lane `l` of each array the `l`-th element's;
/// lanes without an element join body 0 to itself with zeros, and their forces are dropped.
#[derive(Debug, Clone, Default)]
struct Quad {
    body_a: [usize; W],
    body_b: [usize; W],
    point_a: [[f64; W]; 3],
    point_b: [[f64; W]; 3],
    /// Minus the stiffnesses, as [`Bushing::apply`] multiplies them (`-k * d`).
    neg_stiffness: [[f64; W]; 3],
    damping: [[f64; W]; 3],
    neg_rotational_stiffness: [[f64; W]; 3],
    rotational_damping: [[f64; W]; 3],
    turns_a: [[f64; W]; 3],
    turns_b: [[f64; W]; 3],
}

/// What `W` elements add to their bodies: the force on B (−force on A), the moments of the
/// force at the turned arms on B and on A, and the moments added to B (subtracted from A) after.
#[derive(Debug, Clone, Copy, Default)]
struct QuadForces {
    force: [[f64; W]; 3],
    moment_b: [[f64; W]; 3],
    moment_a: [[f64; W]; 3],
    own_b: [[f64; W]; 3],
    own_a: [[f64; W]; 3],
}

/// Where an element's forces are, in the elements' order.
#[derive(Debug, Clone, Copy)]
struct Slot {
    /// Index into the computed [`QuadForces`] (the load-path quads first) and the lane.
    quad: usize,
    lane: usize,
    body_a: usize,
    body_b: usize,
    /// Whether the element adds moments of its own after the force's (every load-path element,
    /// and those off it with a rotational stiffness or damping).
    turning_moments: bool,
}

/// The bushings of a structure, grouped by kind into lanes.
#[derive(Debug, Clone, Default)]
pub struct BushingLanes {
    /// Elements on the load path, then those off it.
    on_load_path: Vec<Quad>,
    off_load_path: Vec<Quad>,
    slots: Vec<Slot>,
}

thread_local! {
    /// The forces of one evaluation, between computing them by kind and adding them in order:
    /// one buffer per thread (the structure is shared by a batch's threads), kept between
    /// evaluations so that none allocates.
    static FORCES: RefCell<Vec<QuadForces>> = const { RefCell::new(Vec::new()) };
}

impl BushingLanes {
    /// The lanes of `bushings` (each joining two different bodies).
    pub fn new(bushings: &[Bushing]) -> Self {
        let mut lanes = Self::default();
        let (on, off): (Vec<_>, Vec<_>) =
            (0..bushings.len()).partition(|&i| bushings[i].on_load_path);
        let mut slots = vec![None; bushings.len()];
        for (kind, indices) in [on, off].into_iter().enumerate() {
            for chunk in indices.chunks(W) {
                let mut quad = Quad::default();
                for (l, &i) in chunk.iter().enumerate() {
                    let b = &bushings[i];
                    assert_ne!(b.at.body_a, b.at.body_b, "{}: one body", b.name);
                    quad.body_a[l] = b.at.body_a;
                    quad.body_b[l] = b.at.body_b;
                    for k in 0..3 {
                        quad.point_a[k][l] = b.at.point_a[k];
                        quad.point_b[k][l] = b.at.point_b[k];
                        quad.neg_stiffness[k][l] = -b.stiffness[k];
                        quad.damping[k][l] = b.damping[k];
                        quad.neg_rotational_stiffness[k][l] = -b.rotational_stiffness[k];
                        quad.rotational_damping[k][l] = b.rotational_damping[k];
                        quad.turns_a[k][l] = b.turns_with[0][k];
                        quad.turns_b[k][l] = b.turns_with[1][k];
                    }
                    let rotational = b
                        .rotational_stiffness
                        .iter()
                        .chain(&b.rotational_damping)
                        .any(|k| *k != 0.0);
                    slots[i] = Some((kind, quad_index(&lanes, kind), l, rotational || kind == 0));
                }
                match kind {
                    0 => lanes.on_load_path.push(quad),
                    _ => lanes.off_load_path.push(quad),
                }
            }
        }
        let n_on = lanes.on_load_path.len();
        lanes.slots = slots
            .into_iter()
            .zip(bushings)
            .map(|(slot, b)| {
                let (kind, quad, lane, turning_moments) = slot.expect("every element has a lane");
                Slot {
                    quad: if kind == 0 { quad } else { n_on + quad },
                    lane,
                    body_a: b.at.body_a,
                    body_b: b.at.body_b,
                    turning_moments,
                }
            })
            .collect();
        lanes
    }

    /// Adds every element's forces to `wrenches`, as [`Bushing::apply`] on each element in
    /// turn (`bushings`, the elements the lanes were made of) would.
    pub fn apply(&self, bushings: &[Bushing], states: &BodyStates, wrenches: &mut Wrenches) {
        debug_assert_eq!(bushings.len(), self.slots.len());
        FORCES.with_borrow_mut(|forces| {
            compute(self, states, forces);
            for slot in &self.slots {
                add_in_order(slot, &forces[slot.quad], wrenches);
            }
        });
    }
}

/// Every quad's forces into `forces`, the load-path quads first: in AVX registers in the AVX
/// copy, as plain arrays in the baseline copy (the module `simd`).
#[multiversion(targets("x86_64+avx"))]
fn compute(lanes: &BushingLanes, states: &BodyStates, forces: &mut Vec<QuadForces>) {
    #[cfg(target_arch = "x86_64")]
    if target_cfg_f!(target_feature = "avx") {
        if let Some(avx) = crate::simd::Avx::detect() {
            return compute_in(avx, lanes, states, forces);
        }
    }
    compute_in(Plain, lanes, states, forces);
}

/// [`compute`] in the lane set `set`.
#[inline(always)]
fn compute_in<S: Four>(
    set: S,
    lanes: &BushingLanes,
    states: &BodyStates,
    forces: &mut Vec<QuadForces>,
) {
    let n = lanes.on_load_path.len();
    forces.resize(n + lanes.off_load_path.len(), QuadForces::default());
    let (on, off) = forces.split_at_mut(n);
    for (quad, out) in lanes.on_load_path.iter().zip(on) {
        quad_forces::<true, S>(set, quad, states, out);
    }
    for (quad, out) in lanes.off_load_path.iter().zip(off) {
        quad_forces::<false, S>(set, quad, states, out);
    }
}

/// The forces of one quad into `out`, [`Bushing::apply`]'s operations lane by lane
/// (`ON_LOAD_PATH` its corotational branch).
#[inline(always)]
fn quad_forces<const ON_LOAD_PATH: bool, S: Four>(
    set: S,
    q: &Quad,
    s: &BodyStates,
    out: &mut QuadForces,
) {
    let m = pair_motion(set, &q.body_a, &q.body_b, &q.point_a, &q.point_b, s);
    let ([rot_a, rot_b], [rate_a, rate_b], [arm_a, arm_b]) = (m.rot, m.rate, m.arm);
    let (d, v) = (m.d, m.v);
    let (neg_k, c) = (v3(set, &q.neg_stiffness), v3(set, &q.damping));
    let (neg_kr, cr) = (
        v3(set, &q.neg_rotational_stiffness),
        v3(set, &q.rotational_damping),
    );
    let (rotation, rate) = (sub(rot_b, rot_a), sub(rate_b, rate_a));
    let moment = products_difference(neg_kr, rotation, cr, rate);
    let f = if ON_LOAD_PATH {
        let (ma, mb) = (v3(set, &q.turns_a), v3(set, &q.turns_b));
        let half = set.splat(0.5);
        let theta = scaled(half, products_sum(rot_a, ma, rot_b, mb));
        let d_local = sub(d, cross(theta, d));
        let f_local = products_difference(neg_k, d_local, c, v);
        let f = add(f_local, cross(theta, f_local));
        let couple = cross(d, f);
        let half_couple = scaled(half, couple);
        store(set, sub(moment, half_couple), &mut out.own_b);
        store(set, add(moment, half_couple), &mut out.own_a);
        f
    } else {
        store(set, moment, &mut out.own_b);
        store(set, moment, &mut out.own_a);
        products_difference(neg_k, d, c, v)
    };
    store(set, f, &mut out.force);
    store(set, cross(arm_b, f), &mut out.moment_b);
    // −f lane by lane (exact, as the scalar code's `[-f[0], -f[1], -f[2]]`).
    store(set, cross(arm_a, neg(f)), &mut out.moment_a);
}

/// The index the next quad of `kind` (0 on the load path) gets among its kind's.
fn quad_index(lanes: &BushingLanes, kind: usize) -> usize {
    match kind {
        0 => lanes.on_load_path.len(),
        _ => lanes.off_load_path.len(),
    }
}

/// Adds one element's forces in [`Bushing::apply`]'s order: force and its moment on B, the
/// same on A, then the element's own moments on B and A. B and A are different bodies, so each
/// wrench entry gets its terms in that order when it is taken whole.
#[inline(always)]
fn add_in_order(slot: &Slot, forces: &QuadForces, wrenches: &mut Wrenches) {
    let l = slot.lane;
    let (wb, wa) = two_mut(wrenches, slot.body_b, slot.body_a);
    for k in 0..3 {
        wb[k] += forces.force[k][l];
        wa[k] += -forces.force[k][l];
    }
    if slot.turning_moments {
        for k in 0..3 {
            wb[3 + k] = wb[3 + k] + forces.moment_b[k][l] + forces.own_b[k][l];
            wa[3 + k] = wa[3 + k] + forces.moment_a[k][l] - forces.own_a[k][l];
        }
    } else {
        for k in 0..3 {
            wb[3 + k] += forces.moment_b[k][l];
            wa[3 + k] += forces.moment_a[k][l];
        }
    }
}

/// Mutable references to two different entries `i` and `j` of `w`.
#[inline(always)]
fn two_mut<T>(w: &mut [T], i: usize, j: usize) -> (&mut T, &mut T) {
    if i < j {
        let (low, high) = w.split_at_mut(j);
        (&mut low[i], &mut high[0])
    } else {
        let (low, high) = w.split_at_mut(i);
        (&mut high[0], &mut low[j])
    }
}

#[cfg(test)]
mod tests;
