use super::*;
use std::cell::Cell;

/// `guessed` on a damping ratio `zeta` with a root at `root`, counting the evaluations.
fn search(zeta: impl Fn(f64) -> f64, guess: f64) -> (f64, usize) {
    let calls = Cell::new(0);
    let counted = |v: f64| -> Result<f64> {
        calls.set(calls.get() + 1);
        Ok(zeta(v))
    };
    let v = guessed(&counted, 20.0, 110.0, 0.5, guess).unwrap();
    (v, calls.get())
}

#[test]
fn a_linear_loss_of_damping_is_found_in_four_evaluations() {
    let root = 61.3;
    let (v, calls) = search(|v| 0.002 * (root - v), 60.0);
    assert!((v - root).abs() <= 0.25, "{v}");
    assert_eq!(calls, 4);
}

#[test]
fn a_curved_loss_of_damping_is_found_within_the_tolerance() {
    // ζ(V) bending as a mode's damping does near its peak, and a kink where the least damped
    // mode changes: both within the tolerance of the root, in a few evaluations.
    let cases: [(&dyn Fn(f64) -> f64, f64); 3] = [
        (
            &|v| 0.05 - 1e-5 * (v - 20.0).powi(2),
            20.0 + (0.05f64 / 1e-5).sqrt(),
        ),
        (&|v| (0.04 - 0.001 * v).min(0.1 - 0.002 * v), 40.0),
        (&|v| (34.2 - v).powi(3), 34.2),
    ];
    for (zeta, root) in cases {
        for guess in [root - 15.0, root - 1.0, root, root + 3.0, root + 30.0] {
            let guess = guess.clamp(20.0, 110.0);
            let (v, calls) = search(zeta, guess);
            assert!((v - root).abs() <= 0.25, "root {root}, guess {guess}: {v}");
            assert!(
                calls <= 14,
                "root {root}, guess {guess}: {calls} evaluations"
            );
        }
    }
}

#[test]
fn stable_or_unstable_over_the_bracket_gives_its_bounds() {
    assert_eq!(search(|_| 0.01, 50.0).0, f64::INFINITY);
    assert_eq!(search(|_| -0.01, 50.0).0, 20.0);
}

#[test]
fn narrow_ends_on_a_zeta_that_steps() {
    // A jump of ζ across zero (no interpolation helps): bisection steps end it.
    let zeta = |v: f64| -> Result<f64> { Ok(if v < 47.77 { 0.3 } else { -0.3 }) };
    let v = narrow(&zeta, (20.0, 0.3), (110.0, -0.3), 0.5).unwrap();
    assert!((v - 47.77).abs() <= 0.25, "{v}");
}
