//! The inputs of every creep-force call a run makes, kept on the calling thread (feature
//! `record-contacts`, off by default): the contacts a vehicle really meets, so that creep models
//! can be timed on them (`loco-dev`'s `creep_replay`) rather than on a few chosen cases, for
//! FaStrip's cost per contact against FASTSIM's; which part of each model runs (the
//! projection, the slip-zone sums, the fallback beyond |φ'| = 1) depends on the creepages, so a
//! ratio from one case says little about a run.

use crate::contact::kalker::Creepages;
use std::cell::RefCell;

/// One creep-force call: the Hertz semi-axes (m), the normal force (N), the friction coefficient
/// and the creepages, as the creep model received them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactCall {
    /// Semi-axis along the rolling direction a, m.
    pub a: f64,
    /// Lateral semi-axis b, m.
    pub b: f64,
    /// Normal force N, N.
    pub normal_force: f64,
    /// Friction coefficient μ, –.
    pub mu: f64,
    /// Longitudinal, lateral (–) and spin (1/m) creepages.
    pub creepages: Creepages,
}

thread_local! {
    static CALLS: RefCell<Vec<ContactCall>> = const { RefCell::new(Vec::new()) };
}

/// Keeps one call's inputs (the creep solver's entry, every call).
pub(in crate::vehicle) fn record(
    a: f64,
    b: f64,
    normal_force: f64,
    mu: f64,
    creepages: &Creepages,
) {
    CALLS.with_borrow_mut(|calls| {
        calls.push(ContactCall {
            a,
            b,
            normal_force,
            mu,
            creepages: *creepages,
        })
    });
}

/// The calls this thread recorded since the last `take`, in their order; the record is emptied.
pub fn take() -> Vec<ContactCall> {
    CALLS.with_borrow_mut(std::mem::take)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_recorded_call_is_taken_once_and_in_order() {
        let _ = take();
        let c = |s: f64| Creepages {
            longitudinal: 1e-4,
            lateral: -2e-3,
            spin: s,
        };
        record(6e-3, 4e-3, 8e4, 0.3, &c(0.1));
        record(5e-3, 3e-3, 7e4, 0.35, &c(-0.2));
        let calls = take();
        assert_eq!(calls.len(), 2);
        assert_eq!((calls[0].a, calls[1].creepages.spin), (6e-3, -0.2));
        assert!(take().is_empty());
    }
}
