//! Complete elliptic integrals and the shape of the Hertz ellipse that they determine.
//!
//! Kept apart from [`super::hertz`] because they are pure special functions: `K(m)`, `E(m)` by the
//! arithmetic-geometric mean, and the inversion of Hertz's curvature-ratio equation for the axis
//! ratio of the contact ellipse.

use std::f64::consts::PI;

/// Complete elliptic integrals `(K(m), E(m))` of parameter `m = k²` ∈ [0, 1), by the
/// arithmetic-geometric mean (Abramowitz & Stegun 17.6; converges quadratically).
pub fn elliptic_ke(m: f64) -> (f64, f64) {
    let mut a = 1.0;
    let mut b = (1.0 - m).sqrt();
    let mut c2 = m; // c_n² with c_0 = k
    let mut weight = 0.5; // 2^{n−1}
    let mut sum = weight * c2;
    for _ in 0..40 {
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
        let c = 0.5 * (a - b);
        let next_b = (a * b).sqrt();
        a = 0.5 * (a + b);
        b = next_b;
        c2 = c * c;
        weight *= 2.0;
        sum += weight * c2;
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// Ratio `g = c_minor/c_major` ∈ (0, 1] of the ellipse for the curvature ratio
/// `rho = A_min/A_max` ∈ (0, 1]: solves `ln((K − E)/(E/g² − K)) = ln rho` for ln g. The left side
/// increases monotonically with g and is nearly linear in ln g (g ≈ rho^{2/3} asymptotically), so
/// a secant iteration safeguarded by a bisection bracket converges in a handful of steps.
pub fn axis_ratio(rho: f64) -> f64 {
    if rho >= 1.0 {
        return 1.0;
    }
    let residual = |u: f64| {
        let g = u.exp();
        let (k, e) = elliptic_ke(1.0 - g * g);
        ((k - e) / (e / (g * g) - k)).ln() - rho.ln()
    };
    // 1e-12 brackets any physical wheel-rail ellipse.
    let (mut lo, mut hi) = (1e-12_f64.ln(), 0.0_f64);
    let mut u0 = (2.0 / 3.0 * rho.ln()).clamp(lo, hi);
    let mut r0 = residual(u0);
    let mut u1 = 0.9 * u0;
    for _ in 0..100 {
        let r1 = residual(u1);
        if r1 < 0.0 {
            lo = u1;
        } else {
            hi = u1;
        }
        if r1 == 0.0 || hi - lo < 1e-14 {
            break;
        }
        let mut next = if r1 != r0 {
            u1 - r1 * (u1 - u0) / (r1 - r0)
        } else {
            0.5 * (lo + hi)
        };
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - u1).abs() < 1e-14 {
            u1 = next;
            break;
        }
        (u0, r0, u1) = (u1, r1, next);
    }
    u1.exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(x: f64, y: f64) -> f64 {
        (x - y).abs() / y.abs()
    }

    #[test]
    fn elliptic_integrals_match_known_values() {
        // A&S table 17.1: K(0.5) = 1.854074677, E(0.5) = 1.350643881.
        let (k, e) = elliptic_ke(0.5);
        assert!((k - 1.854_074_677).abs() < 1e-9);
        assert!((e - 1.350_643_881).abs() < 1e-9);
        let (k0, e0) = elliptic_ke(0.0);
        assert!((k0 - PI / 2.0).abs() < 1e-15 && (e0 - PI / 2.0).abs() < 1e-15);
    }

    #[test]
    fn axis_ratio_solves_the_curvature_equation() {
        assert_eq!(axis_ratio(1.0), 1.0); // circle (the equation is 0/0 there)
        for i in 1..=60 {
            let rho = 10f64.powf(-6.0 * i as f64 / 60.0);
            let g = axis_ratio(rho);
            let (k, e) = elliptic_ke(1.0 - g * g);
            let got = (k - e) / (e / (g * g) - k);
            assert!(rel(got, rho) < 1e-9, "rho = {rho}: {got}");
        }
    }
}
