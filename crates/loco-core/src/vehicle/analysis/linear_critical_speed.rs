//! The linear critical speed: the lowest speed at which the least damped mode of the linearised
//! vehicle ([`crate::vehicle::analysis::linearise`]) in a frequency band loses its damping, on perfect track.
//!
//! Without a guess, bisection of the bracket `low`–`high` (about ten linearisations at the
//! defaults). With a guess ([`LinearSearch::guess`]), a bracket around it and interpolation
//! ([`narrow`]).

use crate::error::{check_cancel, check_positive, LocoError, Result};
use crate::vehicle::analysis::linearise::{least_damped, linearise_with, LinearisationSettings};
use crate::vehicle::model::structure::IntoVehicle;
use crate::vehicle::scenarios::perfect_track::PerfectTrackVehicle;
use crate::vehicle::scenarios::scenario::Scenario;
use std::sync::atomic::AtomicBool;

/// Search settings of the linear critical speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearSearch {
    /// Bracket of the bisection, m/s.
    pub low: f64,
    pub high: f64,
    /// Width of the final bracket, m/s.
    pub tolerance: f64,
    /// Frequency band of the modes considered, Hz (hunting and body modes, not drift).
    pub band: (f64, f64),
    /// How the model is linearised at each speed.
    pub linearisation: LinearisationSettings,
    /// A speed near the expected critical speed, m/s (inside `low`–`high`), or `None` (the
    /// default: bisection of the whole bracket). With a guess the search brackets the loss of
    /// damping around it (±4 tolerances, doubling outward until the sign changes) and narrows
    /// that bracket by interpolation ([`narrow`]): about four linearisations instead of ten
    /// where the guess is within a few metres per second, as when screening inputs about a
    /// nominal vehicle. Same result within `tolerance`.
    pub guess: Option<f64>,
}

impl Default for LinearSearch {
    /// The defaults of `loco.critical_speed`: 20–110 m/s, 0.5 m/s, 0.3–20 Hz.
    fn default() -> Self {
        Self {
            low: 20.0,
            high: 110.0,
            tolerance: 0.5,
            band: (0.3, 20.0),
            linearisation: LinearisationSettings::default(),
            guess: None,
        }
    }
}

/// Linear critical speed (m/s): where the least damped mode in the band loses its damping, by
/// bisection of the linearisation about equilibrium on perfect track. `+∞` when the vehicle is
/// stable at `high`, `low` when it is already unstable there.
pub fn linear_critical_speed(
    vehicle: impl IntoVehicle,
    scenario: &Scenario,
    search: &LinearSearch,
) -> Result<f64> {
    linear_critical_speed_cancellable(vehicle, scenario, search, None)
}

/// As [`linear_critical_speed`]; `cancel`, when set from another thread, stops the search with
/// `Interrupted` before its next linearisation.
pub fn linear_critical_speed_cancellable(
    vehicle: impl IntoVehicle,
    scenario: &Scenario,
    search: &LinearSearch,
    cancel: Option<&AtomicBool>,
) -> Result<f64> {
    scenario.validate()?;
    let low = check_positive("low", search.low)?;
    let high = check_positive("high", search.high)?;
    let tolerance = check_positive("tolerance", search.tolerance)?;
    if high <= low {
        return Err(LocoError::param(
            "high",
            format!("must exceed low ({low} m/s), got {high} m/s"),
        ));
    }
    // Validated above, before the search's own settings.
    let vehicle = PerfectTrackVehicle::of_valid(vehicle, scenario)?;
    let zeta = |speed: f64| -> Result<f64> {
        check_cancel(cancel)?;
        let mut system = vehicle.system(speed)?;
        let (a, _) = linearise_with(&mut system, &search.linearisation)?;
        let mode = least_damped(&a, system.len_states(), search.band)?;
        mode.map(|m| m.damping_ratio)
            .ok_or_else(|| LocoError::param("band", "no mode in the frequency band"))
    };
    if let Some(guess) = search.guess {
        if !(guess.is_finite() && (low..=high).contains(&guess)) {
            return Err(LocoError::param(
                "guess",
                format!("must lie in the bracket {low}–{high} m/s, got {guess}"),
            ));
        }
        return guessed(&zeta, low, high, tolerance, guess);
    }
    let (mut low, mut high) = (low, high);
    if zeta(high)? > 0.0 {
        return Ok(f64::INFINITY);
    }
    if zeta(low)? <= 0.0 {
        return Ok(low);
    }
    while high - low > tolerance {
        let mid = 0.5 * (low + high);
        // A tolerance below the spacing of floats near the speed: the bracket cannot shrink
        // further (`mid` is one of its ends), and the loop would never end.
        if mid <= low || mid >= high {
            break;
        }
        if zeta(mid)? > 0.0 {
            low = mid;
        } else {
            high = mid;
        }
    }
    Ok(0.5 * (low + high))
}

/// The search from a guess: a bracket around `guess` where the damping ratio `zeta` changes sign
/// (half-width four tolerances, doubled outward until it does, clamped to `low`–`high`), then
/// [`narrow`]. `+∞` when stable at `high`, `low` when unstable there, as the bisection.
fn guessed(
    zeta: &dyn Fn(f64) -> Result<f64>,
    low: f64,
    high: f64,
    tolerance: f64,
    guess: f64,
) -> Result<f64> {
    let mut width = 4.0 * tolerance;
    let mut lo = (guess - width).max(low);
    let mut hi = (guess + width).min(high);
    let mut z_lo = zeta(lo)?;
    let mut z_hi = zeta(hi)?;
    while z_lo <= 0.0 {
        if lo <= low {
            return Ok(low);
        }
        (hi, z_hi) = (lo, z_lo);
        width *= 2.0;
        lo = (lo - width).max(low);
        z_lo = zeta(lo)?;
    }
    while z_hi > 0.0 {
        if hi >= high {
            return Ok(f64::INFINITY);
        }
        (lo, z_lo) = (hi, z_hi);
        width *= 2.0;
        hi = (hi + width).min(high);
        z_hi = zeta(hi)?;
    }
    narrow(zeta, (lo, z_lo), (hi, z_hi), tolerance)
}

/// Narrows a bracket `(speed, ζ)` with `ζ > 0` at the low end and `ζ ≤ 0` at the high end to
/// `tolerance` and returns its midpoint. Each round interpolates the root linearly and evaluates
/// a pair of speeds 0.45 tolerances either side of it, so where `ζ` is nearly linear over the
/// bracket one round ends the search; a round that does not halve the bracket is followed by a
/// bisection step, so the search ends however `ζ` bends (Dekker's safeguard, as in Brent,
/// *Algorithms for Minimization without Derivatives*, Prentice-Hall 1973, ch. 4).
pub fn narrow(
    zeta: &dyn Fn(f64) -> Result<f64>,
    mut lo: (f64, f64),
    mut hi: (f64, f64),
    tolerance: f64,
) -> Result<f64> {
    let mut bisect = false;
    while hi.0 - lo.0 > tolerance {
        let width = hi.0 - lo.0;
        let speeds: Vec<f64> = if bisect {
            vec![0.5 * (lo.0 + hi.0)]
        } else {
            let root = lo.0 + width * lo.1 / (lo.1 - hi.1);
            let half = 0.45 * tolerance;
            [root - half, root + half]
                .into_iter()
                .map(|v| v.clamp(lo.0, hi.0))
                .filter(|&v| v > lo.0 && v < hi.0)
                .collect()
        };
        if speeds.is_empty() {
            // The interpolated pair fell on the ends (floats): the bracket cannot shrink.
            break;
        }
        for v in speeds {
            let z = zeta(v)?;
            // Points come in increasing speed: the first with ζ ≤ 0 closes the bracket.
            if z > 0.0 {
                lo = (v, z);
            } else {
                hi = (v, z);
                break;
            }
        }
        bisect = !bisect && hi.0 - lo.0 > 0.5 * width;
    }
    Ok(0.5 * (lo.0 + hi.0))
}

#[cfg(test)]
mod tests;
