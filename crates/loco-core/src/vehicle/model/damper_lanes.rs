//! The dampers' strokes and lever arms, four dampers per AVX register.
//!
//! Why: every evaluation forms each damper's relative motion (`Attachment::relative_motion`)
//! and the turned lever arms of its force (`Attachment::apply_pair`): 5 % of a run (callgrind,
//! etdrk4 at 2 ms, 20 dampers), scalar 3-vector algebra that only depends on the bodies' states.
//! It is computed here for all dampers first, four in lockstep as the bushings' forces are
//! ([`crate::vehicle::model::bushing_lanes`]: each lane does the scalar code's IEEE operations in its order);
//! the laws, whose forces the arms carry, then run one damper at a time in the dampers' order,
//! and their forces are added to the wrenches in that order, so every sum is the same bits.

use crate::vehicle::model::bushing_lanes::W;
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::kinematics::{add, cross, dot};
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
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx") {
                // SAFETY: the processor has just been found to support AVX, the only feature
                // the function enables.
                unsafe { avx::motions(&self.quads, states, motions) };
                return f(DamperMotions(motions));
            }
            scalar_motions(placements, states, motions);
            f(DamperMotions(motions))
        })
    }
}

/// The motions one damper at a time, with the scalar kinematics (where there is no AVX).
fn scalar_motions(placements: &[DamperPlacement], states: &BodyStates, motions: &mut [QuadMotion]) {
    for (i, p) in placements.iter().enumerate() {
        let (q, l) = (&mut motions[i / W], i % W);
        let (d, v) = p.at.relative_motion(states);
        q.along[l] = dot(d, p.direction);
        q.rate[l] = dot(v, p.direction);
        let (ua, ub) = (&states.position[p.at.body_a], &states.position[p.at.body_b]);
        let arm_a = add(p.at.point_a, cross([ua[3], ua[4], ua[5]], p.at.point_a));
        let arm_b = add(p.at.point_b, cross([ub[3], ub[4], ub[5]], p.at.point_b));
        for k in 0..3 {
            q.arm_a[k][l] = arm_a[k];
            q.arm_b[k][l] = arm_b[k];
        }
    }
}

#[cfg(target_arch = "x86_64")]
mod avx {
    use super::{DamperQuad, QuadMotion};
    use crate::vehicle::model::bushing_lanes::avx::{
        mul, pair_motion, store, sum, v3, DAMPERS, V3,
    };
    use crate::vehicle::model::elements::BodyStates;
    use std::arch::x86_64::{__m256d, _mm256_storeu_pd};

    /// `kinematics::dot` lane by lane: (x0·n0 + x1·n1) + x2·n2.
    #[target_feature(enable = "avx")]
    #[inline]
    unsafe fn dot(x: V3, n: V3) -> __m256d {
        sum(sum(mul(x[0], n[0]), mul(x[1], n[1])), mul(x[2], n[2]))
    }

    /// Every quad's motions into `out`, four dampers in one AVX register.
    #[target_feature(enable = "avx")]
    pub(super) unsafe fn motions(quads: &[DamperQuad], s: &BodyStates, out: &mut [QuadMotion]) {
        for (q, out) in quads.iter().zip(out) {
            // `Attachment::relative_motion` (through `point_motion`) and `apply_pair`'s arms.
            let m = pair_motion::<DAMPERS>(&q.body_a, &q.body_b, &q.point_a, &q.point_b, s);
            let n = v3(&q.direction);
            // Four contiguous f64 each, which the references hold.
            _mm256_storeu_pd(out.along.as_mut_ptr(), dot(m.d, n));
            _mm256_storeu_pd(out.rate.as_mut_ptr(), dot(m.v, n));
            store(m.arm[0], &mut out.arm_a);
            store(m.arm[1], &mut out.arm_b);
        }
    }
}

#[cfg(test)]
mod tests;
