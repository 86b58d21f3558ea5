//! The dampers' strokes and lever arms, four dampers in lockstep.
//!
//! Why: every evaluation forms each damper's relative motion (`Attachment::relative_motion`)
//! and the turned lever arms of its force (`Attachment::apply_pair`): 5 % of a run (callgrind,
//! etdrk4 at 2 ms, 20 dampers), scalar 3-vector algebra that only depends on the bodies' states.
//! It is computed here for all dampers first, four in lockstep as the bushings' forces are
//! ([`crate::vehicle::model::bushing_lanes`]: each lane does the scalar code's IEEE operations in its order);
//! the laws, whose forces the arms carry, then run one damper at a time in the dampers' order,
//! and their forces are added to the wrenches in that order, so every sum is the same bits.

use crate::simd::vec3::dot;
use crate::simd::{multiversion, target_cfg_f, Four, Plain};
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::pair_lanes::{pair_motion, store, v3, W};
use crate::vehicle::model::suspension::DamperPlacement;
use std::cell::RefCell;

/// The attachments and axes of `W` dampers (lanes without a damper: body 0 to itself, zeros).
#[derive(Debug, Clone, Default)]
struct DamperQuad {
    body_a: [usize; W],
    body_b: [usize; W],
    point_a: [[f64; W]; 3],
    point_b: [[f64; W]; 3],
    direction: [[f64; W]; 3],
}

/// The motion of `W` dampers: the relative displacement and velocity of their points along
/// their axes (m, m/s), and the lever arms of their points turned with their bodies (m).
#[derive(Debug, Clone, Copy, Default)]
struct QuadMotion {
    along: [f64; W],
    rate: [f64; W],
    arm_a: [[f64; W]; 3],
    arm_b: [[f64; W]; 3],
}

/// The dampers' placements in lanes, damper `i` in lane `i % W` of quad `i / W`.
#[derive(Debug, Clone, Default)]
pub struct DamperLanes {
    quads: Vec<DamperQuad>,
}

/// The motions of every damper of one evaluation.
pub struct DamperMotions<'a>(&'a [QuadMotion]);

impl DamperMotions<'_> {
    /// Damper `i`'s elongation (m, from the static `static_elongation`) and its rate (m/s), as
    /// `DamperElement::stroke` forms them.
    #[inline]
    pub fn stroke(&self, i: usize, static_elongation: f64) -> (f64, f64) {
        let (q, l) = (&self.0[i / W], i % W);
        (q.along[l] - static_elongation, q.rate[l])
    }

    /// Damper `i`'s turned lever arms on A and B (m), as `Attachment::apply_pair` forms them.
    #[inline]
    pub fn arms(&self, i: usize) -> [[f64; 3]; 2] {
        let (q, l) = (&self.0[i / W], i % W);
        [
            [q.arm_a[0][l], q.arm_a[1][l], q.arm_a[2][l]],
            [q.arm_b[0][l], q.arm_b[1][l], q.arm_b[2][l]],
        ]
    }
}

thread_local! {
    /// One evaluation's motions: one buffer per thread (the structure is shared by a batch's
    /// threads), kept between evaluations so that none allocates.
    static MOTIONS: RefCell<Vec<QuadMotion>> = const { RefCell::new(Vec::new()) };
}

impl DamperLanes {
    /// The lanes of `placements`.
    pub fn new(placements: &[DamperPlacement]) -> Self {
        let quads = placements
            .chunks(W)
            .map(|chunk| {
                let mut q = DamperQuad::default();
                for (l, p) in chunk.iter().enumerate() {
                    q.body_a[l] = p.at.body_a;
                    q.body_b[l] = p.at.body_b;
                    for k in 0..3 {
                        q.point_a[k][l] = p.at.point_a[k];
                        q.point_b[k][l] = p.at.point_b[k];
                        q.direction[k][l] = p.direction[k];
                    }
                }
                q
            })
            .collect();
        Self { quads }
    }

    /// Calls `f` with the motions of the dampers `placements` (those the lanes were made of)
    /// in the bodies' `states`; with `skip`, with none (no damper is evaluated).
    pub fn with_motions<R>(
        &self,
        placements: &[DamperPlacement],
        states: &BodyStates,
        skip: bool,
        f: impl FnOnce(DamperMotions) -> R,
    ) -> R {
        debug_assert_eq!(placements.len().div_ceil(W), self.quads.len());
        MOTIONS.with_borrow_mut(|motions| {
            if skip {
                return f(DamperMotions(&[]));
            }
            motions.resize(self.quads.len(), QuadMotion::default());
            quad_motions(&self.quads, states, motions);
            f(DamperMotions(motions))
        })
    }
}

/// Every quad's motions into `out`, four dampers in lockstep: `Attachment::relative_motion`
/// (through `point_motion`) along the axis, and `apply_pair`'s arms.
/// In AVX registers in the AVX copy, as plain arrays in the baseline copy (the module `simd`).
#[multiversion(targets("x86_64+avx"))]
fn quad_motions(quads: &[DamperQuad], s: &BodyStates, out: &mut [QuadMotion]) {
    #[cfg(target_arch = "x86_64")]
    if target_cfg_f!(target_feature = "avx") {
        if let Some(avx) = crate::simd::Avx::detect() {
            return quad_motions_in(avx, quads, s, out);
        }
    }
    quad_motions_in(Plain, quads, s, out);
}

/// [`quad_motions`] in the lane set `set`.
#[inline(always)]
fn quad_motions_in<S: Four>(set: S, quads: &[DamperQuad], s: &BodyStates, out: &mut [QuadMotion]) {
    for (q, out) in quads.iter().zip(out) {
        let m = pair_motion(set, &q.body_a, &q.body_b, &q.point_a, &q.point_b, s);
        let n = v3(set, &q.direction);
        set.store(dot(m.d, n), &mut out.along);
        set.store(dot(m.v, n), &mut out.rate);
        store(set, m.arm[0], &mut out.arm_a);
        store(set, m.arm[1], &mut out.arm_b);
    }
}

#[cfg(test)]
mod tests;
