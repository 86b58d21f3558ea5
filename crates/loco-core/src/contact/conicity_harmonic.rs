//! Equivalent conicity by harmonic linearisation (describing function) of Δr(y).
//!
//! The wheelset is assumed to swing sinusoidally, y = m + ŷ·sin φ, and Δr(y(φ)) is replaced by
//! its first harmonic. The conical wheelset with the same first harmonic has
//! 2·tan γe·ŷ = (1/π) ∫₀^{2π} Δr(m + ŷ sin φ) sin φ dφ, i.e.
//!
//! tan γe = (1 / (π·ŷ)) ∫_{−π/2}^{π/2} Δr(m + ŷ sin θ) sin θ dθ.
//!
//! This equals the least-squares slope of Δr against y weighted by the time a sinusoidal swing
//! spends at each y (the arcsine density 1/√(ŷ² − (y − m)²)), the weighting EN 15302 discusses
//! for its regression method. The centre m is where the swing's mean Δr vanishes (the bias term
//! of the dual-input describing function): 0 for a symmetric wheelset, the running position of an
//! asymmetric one. For a conical wheelset both this and the kinematic method
//! ([`super::conicity`]) give the cone angle; for a nonlinear Δr they differ, the kinematic
//! method being the standard's reference.

use super::delta_r::DeltaR;
use super::quadrature::integrate_pieces;
use crate::error::{check_positive, LocoError, Result};
use std::f64::consts::{FRAC_PI_2, PI};

/// Equivalent conicity tan γe (-) at amplitude `amplitude` (m) by harmonic linearisation.
///
/// Errors: [`LocoError::InvalidParameter`] naming `amplitude` when it is not positive or the
/// swing does not fit in the range sampled by `delta_r` with a vanishing mean Δr.
pub fn equivalent_conicity_harmonic(delta_r: &DeltaR, amplitude: f64) -> Result<f64> {
    let a = check_positive("amplitude", amplitude)?;
    let centre = swing_centre(delta_r, a)?;
    let first_harmonic = over_swing(delta_r, centre, a, |dr, s| dr * s);
    Ok(first_harmonic / (PI * a))
}

/// Equivalent conicity (-) at each of `amplitudes` (m) by harmonic linearisation.
pub fn conicity_curve_harmonic(delta_r: &DeltaR, amplitudes: &[f64]) -> Result<Vec<f64>> {
    amplitudes
        .iter()
        .map(|&a| equivalent_conicity_harmonic(delta_r, a))
        .collect()
}

/// ∫_{−π/2}^{π/2} g(Δr(m + ŷ sin θ), sin θ) dθ, with breaks at the Δr grid points.
fn over_swing(delta_r: &DeltaR, centre: f64, amplitude: f64, g: impl Fn(f64, f64) -> f64) -> f64 {
    let mut breaks = vec![-FRAC_PI_2];
    for &node in delta_r.y() {
        let s = (node - centre) / amplitude;
        if s > -1.0 && s < 1.0 {
            breaks.push(s.asin());
        }
    }
    breaks.push(FRAC_PI_2);
    integrate_pieces(&breaks, |theta| {
        let s = theta.sin();
        g(delta_r.value(centre + amplitude * s), s)
    })
}

/// The centre m (m) of a swing of amplitude `amplitude` whose mean Δr is zero, by bisection
/// between the extreme centres the sampled range allows.
fn swing_centre(delta_r: &DeltaR, amplitude: f64) -> Result<f64> {
    let (first, last) = delta_r.range();
    let (mut lo, mut hi) = (first + amplitude, last - amplitude);
    let out_of_range = || {
        LocoError::param(
            "amplitude",
            format!(
                "{amplitude} m: no swing within the Δr samples [{first}, {last}] m \
                 has a zero mean Δr"
            ),
        )
    };
    if lo > hi {
        return Err(out_of_range());
    }
    let mean = |m: f64| over_swing(delta_r, m, amplitude, |dr, _| dr);
    let (f_lo, f_hi) = (mean(lo), mean(hi));
    if f_lo == 0.0 {
        return Ok(lo);
    }
    if f_hi == 0.0 {
        return Ok(hi);
    }
    if (f_lo > 0.0) == (f_hi > 0.0) {
        return Err(out_of_range());
    }
    let rising = f_hi > 0.0;
    // The centre to 1e-12 of the amplitude: far below any effect on tan γe.
    while hi - lo > 1e-12 * amplitude {
        let mid = 0.5 * (lo + hi);
        if (mean(mid) > 0.0) == rising {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::super::conicity::equivalent_conicity;
    use super::*;

    fn sampled(half_width: f64, step: f64, f: impl Fn(f64) -> f64) -> DeltaR {
        let n = (2.0 * half_width / step).round() as usize;
        let y: Vec<f64> = (0..=n).map(|i| -half_width + i as f64 * step).collect();
        let dr = y.iter().map(|&v| f(v)).collect();
        DeltaR::new(y, dr).unwrap()
    }

    #[test]
    fn conical_and_offset_wheelsets_give_the_cone_angle() {
        let f = sampled(0.01, 1e-4, |y| 2.0 * 0.12 * y);
        let g = sampled(0.01, 1e-4, |y| 2.0 * 0.12 * y + 5e-4);
        for a in [1e-3, 3e-3, 7.5e-3] {
            assert!((equivalent_conicity_harmonic(&f, a).unwrap() - 0.12).abs() < 1e-12);
            assert!((equivalent_conicity_harmonic(&g, a).unwrap() - 0.12).abs() < 1e-12);
        }
    }

    #[test]
    fn cubic_term_adds_three_eighths() {
        // The first harmonic of 2βy³ at amplitude A is (3/2)βA³: tan γe = γ + (3/4)βA².
        let (gamma, beta) = (0.05, 2.0e4);
        let f = sampled(0.012, 1e-5, |y| 2.0 * gamma * y + 2.0 * beta * y.powi(3));
        for a in [1e-3, 3e-3, 6e-3] {
            let exact = gamma + 0.75 * beta * a * a;
            let got = equivalent_conicity_harmonic(&f, a).unwrap();
            assert!((got - exact).abs() < 1e-4 * exact, "{a}: {got} vs {exact}");
            // The kinematic method weights the large-Δr turning points less: a lower value.
            assert!(equivalent_conicity(&f, a).unwrap() < got);
        }
    }

    #[test]
    fn out_of_range_amplitude_is_refused() {
        let f = sampled(0.005, 1e-4, |y| 0.2 * y);
        let err = equivalent_conicity_harmonic(&f, 6e-3).unwrap_err();
        assert!(err.to_string().contains("amplitude"));
        let err = equivalent_conicity_harmonic(&f, 0.0).unwrap_err();
        assert!(err.to_string().contains("amplitude"));
        assert_eq!(conicity_curve_harmonic(&f, &[1e-3]).unwrap().len(), 1);
    }
}
