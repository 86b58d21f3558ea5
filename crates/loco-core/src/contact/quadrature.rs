//! Gauss–Legendre quadrature on the sub-intervals of a smooth-by-pieces integrand.
//!
//! The conicity integrals are smooth between the Δr grid points (mapped into the integration
//! variable) but only continuous across them, so they are integrated interval by interval with a
//! fixed Gauss rule: exact for polynomials of degree 2n − 1 and exponentially convergent for the
//! analytic pieces.

use std::sync::OnceLock;

/// Number of Gauss points per sub-interval.
const POINTS: usize = 8;

/// Nodes on [−1, 1] and weights of the `POINTS`-point Gauss–Legendre rule.
fn rule() -> &'static ([f64; POINTS], [f64; POINTS]) {
    static RULE: OnceLock<([f64; POINTS], [f64; POINTS])> = OnceLock::new();
    RULE.get_or_init(|| {
        let mut nodes = [0.0; POINTS];
        let mut weights = [0.0; POINTS];
        let n = POINTS as f64;
        for k in 0..POINTS {
            // Newton on P_n from the Chebyshev-like first guess; converges in a few steps.
            let mut x = (std::f64::consts::PI * (k as f64 + 0.75) / (n + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (p, dp) = legendre(POINTS, x);
                derivative = dp;
                let step = p / dp;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            let (_, dp) = legendre(POINTS, x);
            derivative = if dp != 0.0 { dp } else { derivative };
            nodes[k] = x;
            weights[k] = 2.0 / ((1.0 - x * x) * derivative * derivative);
        }
        (nodes, weights)
    })
}

/// P_n(x) and its derivative by the three-term recurrence.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p_prev, mut p) = (1.0, x);
    for k in 2..=n {
        let k = k as f64;
        let next = ((2.0 * k - 1.0) * x * p - (k - 1.0) * p_prev) / k;
        p_prev = p;
        p = next;
    }
    let dp = n as f64 * (x * p - p_prev) / (x * x - 1.0);
    (p, dp)
}

/// ∫ f over [breaks[0], breaks[last]], one Gauss rule per interval between consecutive breaks
/// (which must be non-decreasing; empty intervals contribute nothing).
pub(crate) fn integrate_pieces(breaks: &[f64], mut f: impl FnMut(f64) -> f64) -> f64 {
    let (nodes, weights) = rule();
    let mut total = 0.0;
    for w in breaks.windows(2) {
        let half = 0.5 * (w[1] - w[0]);
        if half <= 0.0 {
            continue;
        }
        let mid = 0.5 * (w[1] + w[0]);
        let mut piece = 0.0;
        for (x, weight) in nodes.iter().zip(weights) {
            piece += weight * f(mid + half * x);
        }
        total += half * piece;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_polynomials_and_accurate_for_smooth_functions() {
        let (_, weights) = rule();
        assert!((weights.iter().sum::<f64>() - 2.0).abs() < 1e-14);
        // Degree 15 is integrated exactly: ∫_0^1 x^15 = 1/16.
        let p = integrate_pieces(&[0.0, 1.0], |x| x.powi(15));
        assert!((p - 1.0 / 16.0).abs() < 1e-15);
        // ∫_0^π sin = 2 over three pieces.
        let s = integrate_pieces(&[0.0, 1.0, 1.0, std::f64::consts::PI], f64::sin);
        assert!((s - 2.0).abs() < 1e-13);
    }
}
