//! The check of every step's state: divergence (a non-finite value, a runaway amplitude) and
//! derailment (a bounded vehicle with a wheelset beyond the flanges).
//!
//! Why two passes: the check runs after every step and almost always passes. The pass that
//! decides is branch-free over per-coordinate bounds tabulated at compile time (the coordinate
//! kinds were worked out per coordinate and step, 4.6·10³ instructions a step); only a state
//! that fails is walked again in order, by the one code that says what failed and where, so the
//! errors are those of a single ordered walk.

use crate::error::{LocoError, Result};
use crate::vehicle::model::layout::{
    coordinate_kind, dof_names, wheelset, CoordinateKind, CARBODY, N_DOF, N_WHEELSETS, X, Y,
};

/// Largest displacement of any coordinate in a run (longitudinal ones relative to the carbody),
/// m: suspension travel is tens of millimetres and the contact range ±25 mm, so a body a metre
/// away is a numerical blow-up, not a motion.
pub const RUNAWAY_DISPLACEMENT: f64 = 1.0;
/// Largest rotation of any coordinate but the wheelsets' spin, rad (29°), for the same reason.
pub const RUNAWAY_ROTATION: f64 = 0.5;
/// Lateral wheelset displacement beyond which a bounded state counts as derailed, m: twice the
/// contact tables' half range (±25 mm, which already covers flange climbing).
pub const DERAILED_LATERAL: f64 = 0.05;

/// Per coordinate: the bound on its amplitude (m or rad; ∞ for the unbounded spin).
const LIMITS: [f64; N_DOF] = {
    let mut limits = [0.0; N_DOF];
    let mut i = 0;
    while i < N_DOF {
        limits[i] = match coordinate_kind(i) {
            CoordinateKind::Translation | CoordinateKind::Longitudinal => RUNAWAY_DISPLACEMENT,
            CoordinateKind::Rotation => RUNAWAY_ROTATION,
            CoordinateKind::Spin => f64::INFINITY,
        };
        i += 1;
    }
    limits
};

/// Per coordinate: 1 where it is measured relative to the carbody's longitudinal position, else
/// 0 (then `q − x·0` is `q` up to the sign of a zero, which the amplitude drops).
const RELATIVE: [f64; N_DOF] = {
    let mut relative = [0.0; N_DOF];
    let mut i = 0;
    while i < N_DOF {
        if matches!(coordinate_kind(i), CoordinateKind::Longitudinal) {
            relative[i] = 1.0;
        }
        i += 1;
    }
    relative
};

/// Checks state `y` at time `t` (s), see `VehicleSystem::check_state`.
pub fn check_state(t: f64, y: &[f64]) -> Result<()> {
    if passes(y) {
        return Ok(());
    }
    explain(t, y)
}

/// Whether `y` passes every check of [`explain`]: the same comparisons, counted without early
/// exits or branches so that they run in packed registers.
#[inline]
fn passes(y: &[f64]) -> bool {
    // x·0 is 0 for a finite x and NaN otherwise, and sums of zeros stay zero; four partial sums
    // so that the loop packs.
    let mut zeros = [0.0; 4];
    let chunks = y.chunks_exact(4);
    let rest = chunks.remainder().iter().fold(0.0, |sum, v| sum + v * 0.0);
    for chunk in chunks {
        for (z, v) in zeros.iter_mut().zip(chunk) {
            *z += v * 0.0;
        }
    }
    if zeros.iter().sum::<f64>() + rest != 0.0 {
        return false;
    }
    let carbody_x = y[CARBODY + X];
    let beyond: usize = (0..N_DOF)
        .map(|i| usize::from((y[i] - carbody_x * RELATIVE[i]).abs() > LIMITS[i]))
        .sum();
    let off_rails: usize = (0..N_WHEELSETS)
        .map(|w| usize::from(y[wheelset(w) + Y].abs() > DERAILED_LATERAL))
        .sum();
    beyond + off_rails == 0
}

/// The first check that `y` fails, in order, as an error; `Ok` if none does.
fn explain(t: f64, y: &[f64]) -> Result<()> {
    if let Some(i) = y.iter().position(|v| !v.is_finite()) {
        let names = dof_names();
        let location = if i < N_DOF {
            names[i].clone()
        } else if i < 2 * N_DOF {
            format!("{} (velocity)", names[i - N_DOF])
        } else {
            "damper internal state".to_string()
        };
        return Err(LocoError::Diverged {
            time: t,
            location,
            reason: "state is not finite".into(),
        });
    }
    let carbody_x = y[CARBODY + X];
    for (i, &q) in y[..N_DOF].iter().enumerate() {
        let (q, limit, unit) = match coordinate_kind(i) {
            CoordinateKind::Translation => (q, RUNAWAY_DISPLACEMENT, "m"),
            CoordinateKind::Longitudinal => (q - carbody_x, RUNAWAY_DISPLACEMENT, "m"),
            CoordinateKind::Rotation => (q, RUNAWAY_ROTATION, "rad"),
            CoordinateKind::Spin => continue,
        };
        if q.abs() > limit {
            let relative = if coordinate_kind(i) == CoordinateKind::Longitudinal {
                " relative to the carbody"
            } else {
                ""
            };
            return Err(LocoError::Diverged {
                time: t,
                location: dof_names()[i].clone(),
                reason: format!(
                    "runaway amplitude {q:.4e} {unit}{relative} (bound ±{limit} {unit})"
                ),
            });
        }
    }
    for w in 0..N_WHEELSETS {
        let lateral = y[wheelset(w) + Y];
        if lateral.abs() > DERAILED_LATERAL {
            return Err(LocoError::Derailed {
                time: t,
                location: format!("wheelset{}", w + 1),
                reason: format!("lateral displacement {lateral:.4} m beyond the flanges"),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every coordinate at values about each bound (and NaN, ±∞): the fast pass agrees with
    /// the ordered walk on whether the state passes.
    #[test]
    fn the_fast_pass_agrees_with_the_ordered_walk() {
        let rest = vec![0.0; 2 * N_DOF + 3];
        let values = [
            0.0,
            -0.0,
            0.049,
            0.051,
            0.49,
            0.51,
            -0.99,
            1.01,
            -1.5,
            3.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for i in 0..rest.len() {
            for v in values {
                for carbody_x in [0.0, -3.0] {
                    let mut y = rest.clone();
                    y[CARBODY + X] = carbody_x;
                    y[i] = v;
                    let walked = explain(1.0, &y).is_ok();
                    assert_eq!(
                        passes(&y),
                        walked,
                        "coordinate {i} at {v}, carbody x {carbody_x}"
                    );
                    assert_eq!(check_state(1.0, &y).is_ok(), walked);
                }
            }
        }
    }
}
