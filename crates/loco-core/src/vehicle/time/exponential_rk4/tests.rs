use super::*;
use crate::vehicle::time::decaying_states::{DecayingState, DecayingStates};
use crate::vehicle::time::integrator::{OdeSystem, Rk4Workspace};
use crate::vehicle::time::stiff_linear_part::StiffLinearPart;

/// Two unit masses: `x0` on a spring to ground (`stiff`, 1/s², the linear part) and joined to
/// `x1` by a soft one; `x1` on its own spring (`rest`: linear and cubic stiffness, damping),
/// driven at 3 Hz; one first-order state (a lag of `x1`) after the velocities, as the dampers'
/// internal states are.
#[derive(Clone, Copy)]
struct Toy {
    stiff: f64,
    rest: [f64; 3],
    /// Rate of the lag state (1/s), and whether the scheme solves it exactly.
    lag: f64,
    lag_exact: bool,
}

impl Toy {
    /// `x1` on a soft hardening spring with light damping.
    fn soft(stiff: f64) -> Self {
        Self {
            stiff,
            rest: [900.0, 4e5, 0.8],
            lag: 20.0,
            lag_exact: false,
        }
    }

    /// `x1` on a stiff linear spring (1000 rad/s) with damping, left to `N`.
    fn stiff_rest(stiff: f64) -> Self {
        Self {
            stiff,
            rest: [1e6, 0.0, 40.0],
            lag: 20.0,
            lag_exact: false,
        }
    }
}

impl OdeSystem for Toy {
    fn dimension(&self) -> usize {
        5
    }
    fn derivatives(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        let (x0, x1, v0, v1, s) = (y[0], y[1], y[2], y[3], y[4]);
        let [k1, k3, c1] = self.rest;
        let coupling = 400.0 * (x1 - x0);
        dy[0] = v0;
        dy[1] = v1;
        dy[2] = -self.stiff * x0 + coupling;
        dy[3] = -coupling - k1 * x1 - k3 * x1.powi(3) - c1 * v1
            + 50.0 * (2.0 * std::f64::consts::PI * 3.0 * t).sin();
        dy[4] = self.lag * (x1 - s);
    }
    fn after_step(&mut self, _t: f64, _dt: f64, _y: &[f64]) {}
}

fn toy_part(stiff: f64) -> Arc<StiffLinearPart> {
    Arc::new(StiffLinearPart::new(
        2,
        vec![vec![(0, 1.0)]],
        &[stiff],
        |rhs, x| x.copy_from_slice(rhs),
    ))
}

/// The toy from [`start`] over `duration` (s) in steps of `dt` (s), with the exponential scheme
/// (`x0`'s spring as the linear part) or RK4.
fn run(mut toy: Toy, exponential: bool, dt: f64, duration: f64) -> Vec<f64> {
    // The lag's elongation is x1.
    let lag = DecayingState {
        index: 4,
        rate: toy.lag,
        elongation: vec![(1, 1.0)],
        offset: 0.0,
    };
    let decaying = DecayingStates::new(2, if toy.lag_exact { vec![lag] } else { vec![] });
    let mut ws = ExponentialRk4::new(toy_part(toy.stiff), Arc::new(decaying), 5, dt);
    let mut rk4 = Rk4Workspace::new(5);
    let mut y = start();
    for n in 0..(duration / dt).round() as usize {
        let t = n as f64 * dt;
        if exponential {
            ws.step_observed(&mut toy, t, dt, (n + 1) as f64 * dt, &mut y, |_, _, _| {});
        } else {
            rk4.step(&mut toy, t, dt, &mut y);
        }
    }
    y
}

fn run_exponential(stiff: f64, dt: f64, duration: f64) -> Vec<f64> {
    run(Toy::soft(stiff), true, dt, duration)
}

fn run_rk4(stiff: f64, dt: f64, duration: f64) -> Vec<f64> {
    run(Toy::soft(stiff), false, dt, duration)
}

/// The soft mass displaced: the stiff spring is excited only through the coupling, as the
/// bearings are by the rest of the vehicle.
fn start() -> Vec<f64> {
    vec![0.0, 0.01, 0.0, 0.0, 0.0]
}

fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The propagator against the closed-form solution of `z̈ + ω² z = h0 + h1·t + h2·t²/2`, with
/// its first and second integrals.
#[test]
fn propagator_is_the_exact_solution() {
    let omega: f64 = 2000.0;
    let part = toy_part(omega * omega);
    let tau = 2e-3;
    let prop = part.propagator(tau);
    let (z0, v0, h0, h1, h2) = (1e-4, 0.3, 50.0, -2e4, 3e7);
    let mut out = [0.0; 2];
    prop.apply(&[z0, v0, h0, h1, h2], &mut out);
    let w2 = omega * omega;
    // Particular solution a + b·t + c·t², then the free oscillation matching z0, v0.
    let c = h2 / (2.0 * w2);
    let b = h1 / w2;
    let a = (h0 - 2.0 * c) / w2;
    let (c1, c2) = (z0 - a, (v0 - b) / omega);
    let (s, co) = ((omega * tau).sin(), (omega * tau).cos());
    let iz = a * tau
        + b * tau.powi(2) / 2.0
        + c * tau.powi(3) / 3.0
        + c1 * s / omega
        + c2 * (1.0 - co) / omega;
    let iiz = a * tau.powi(2) / 2.0
        + b * tau.powi(3) / 6.0
        + c * tau.powi(4) / 12.0
        + c1 * (1.0 - co) / w2
        + c2 * (tau - s / omega) / omega;
    // What the springs' part adds to the coordinates: (J B)⁻¹ ∫ż − ∫∫z, with J B = ω².
    let integral_rate =
        v0 * tau + h0 * tau.powi(2) / 2.0 + h1 * tau.powi(3) / 6.0 + h2 * tau.powi(4) / 24.0;
    let y = integral_rate / w2 - iiz;
    for (got, want) in out.iter().zip([iz, y]) {
        assert!(
            (got - want).abs() <= 1e-10 * want.abs(),
            "propagator {got:e}, closed form {want:e}"
        );
    }
}

/// Where RK4 is stable (a soft spring in the linear part; the part still carries the
/// kinematics `q̇`, so the scheme is not RK4 itself), it is about as accurate as RK4 against a
/// fine reference.
#[test]
fn as_accurate_as_rk4_on_a_soft_problem() {
    let stiff = 2500.0;
    let (dt, duration) = (2e-3, 1.0);
    let reference = run_rk4(stiff, 1e-5, duration);
    let e = distance(&run_exponential(stiff, dt, duration), &reference);
    let r = distance(&run_rk4(stiff, dt, duration), &reference);
    assert!(e < 4.0 * r, "ETDRK4 error {e:e}, RK4 error {r:e}");
}

/// A stiff spring at ω = 1885 rad/s (300 Hz) with a 2 ms step, ω·h = 3.8 beyond RK4's 2√2:
/// RK4 blows up, the exponential scheme follows a fine RK4 reference (0.01 ms).
#[test]
fn stable_and_accurate_beyond_the_rk4_limit() {
    let stiff = (2.0 * std::f64::consts::PI * 300.0f64).powi(2);
    let duration = 2.0;
    let reference = run_rk4(stiff, 1e-5, duration);
    let rk4 = run_rk4(stiff, 2e-3, duration);
    assert!(
        !rk4.iter().all(|v| v.is_finite() && v.abs() < 1.0),
        "RK4 stayed stable"
    );
    let e = run_exponential(stiff, 2e-3, duration);
    let scale = reference[1].abs().max(1e-3);
    assert!(
        distance(&e[..2], &reference[..2]) < 1e-3 * scale,
        "ETDRK4 {e:?}, reference {reference:?}"
    );
}

/// Fourth order on the coupled problem: halving the step cuts the error about sixteenfold
/// (at least eightfold accepted: the stiff scheme's order in the coupling may be lower).
#[test]
fn converges_with_high_order() {
    let stiff = (2.0 * std::f64::consts::PI * 300.0f64).powi(2);
    let duration = 1.0;
    let reference = run_rk4(stiff, 1e-5, duration);
    let e1 = distance(&run_exponential(stiff, 2e-3, duration), &reference);
    let e2 = distance(&run_exponential(stiff, 1e-3, duration), &reference);
    let order = (e1 / e2).log2();
    assert!(order > 3.0, "observed order {order} ({e1:e} -> {e2:e})");
}

/// A stiff spring left in the rest (`x1` at 1000 rad/s, ω·h = 2 at 2 ms, inside RK4's limit)
/// keeps RK4's stability, and at ω·h = 1 its accuracy: the linear part carries the kinematics
/// of the stiff springs' part only. (With all coordinates' kinematics in it the scheme blew up
/// here, error 5·10⁹.) At ω·h = 2 its error, 2·10⁻⁶ of a 10⁻² start, is larger than RK4's,
/// which damps that mode away numerically.
#[test]
fn a_stiff_rest_keeps_rk4_stability() {
    let toy = Toy::stiff_rest(2500.0);
    let run = |dt: f64, exponential: bool| run(toy, exponential, dt, 1.0);
    let reference = run(1e-5, false);
    let stable = distance(&run(2e-3, true), &reference);
    assert!(stable < 1e-5, "ETDRK4 error {stable:e} at 2 ms");
    let e = distance(&run(1e-3, true), &reference);
    let r = distance(&run(1e-3, false), &reference);
    assert!(e < 4.0 * r, "ETDRK4 error {e:e}, RK4 error {r:e}");
}

/// A lag state at 5000 1/s (a Maxwell damper's deflection at SPEC §6's fastest k/c), r·h = 10
/// at 2 ms, beyond RK4's real-axis limit (2.785): in the explicit stages it blows up, solved
/// exactly as a decaying state it follows a fine RK4 reference, with the scheme's order.
#[test]
fn a_fast_lag_solved_exactly_is_stable_and_accurate() {
    let stiff = (2.0 * std::f64::consts::PI * 300.0f64).powi(2);
    let toy = |exact: bool| Toy {
        lag: 5000.0,
        lag_exact: exact,
        ..Toy::soft(stiff)
    };
    let duration = 1.0;
    let reference = run(toy(false), false, 1e-5, duration);
    let explicit = run(toy(false), true, 2e-3, duration);
    assert!(
        !explicit.iter().all(|v| v.is_finite() && v.abs() < 1.0),
        "the lag in the explicit stages stayed stable"
    );
    let exact = run(toy(true), true, 2e-3, duration);
    let e1 = distance(&exact, &reference);
    let e2 = distance(&run(toy(true), true, 1e-3, duration), &reference);
    // The lag itself to 10⁻³ of its value, and no more error in the whole state than the same
    // toy with its slow lag (20 1/s) in the explicit stages.
    let lag_error = (exact[4] - reference[4]).abs();
    assert!(
        lag_error < 1e-3 * reference[4].abs(),
        "lag {exact:?}, reference {reference:?}"
    );
    let slow = distance(
        &run_exponential(stiff, 2e-3, duration),
        &run_rk4(stiff, 1e-5, duration),
    );
    assert!(e1 < 1.05 * slow, "error {e1:e}, with the slow lag {slow:e}");
    let order = (e1 / e2).log2();
    assert!(order > 3.0, "observed order {order} ({e1:e} -> {e2:e})");
}

/// The dispatched loops (the AVX copy where the processor has it) give the bits of the loops
/// compiled for the baseline.
#[test]
fn dispatched_loops_give_the_bits_of_the_plain_ones() {
    // 203 states (not a multiple of the lanes), with zeros of both signs, tiny and huge values.
    let v = |seed: f64| -> Vec<f64> {
        (0..203)
            .map(|i| match i % 17 {
                0 => 0.0,
                1 => -0.0,
                2 => 1e-300,
                3 => -3e250,
                _ => (i as f64 * seed).sin() * 10f64.powi(i % 9 - 4),
            })
            .collect()
    };
    let (y0, a, b, d) = (v(0.37), v(1.1), v(-0.53), v(2.9));
    let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    let c = [2e-3, 2e-6, 1.3e-9];
    for w in [&[&a[..]][..], &[&a[..], &b[..], &d[..]][..]] {
        let (mut plain, mut lanes) = (vec![0.0; 203], vec![0.0; 203]);
        polynomial(&mut plain, &y0, w, c);
        dispatched::polynomial(&mut lanes, &y0, w, c);
        assert_eq!(bits(&plain), bits(&lanes));
    }
    let (mut plain, mut lanes) = (vec![0.0; 203], vec![0.0; 203]);
    extrapolate(&mut plain, &a, &b);
    dispatched::extrapolate(&mut lanes, &a, &b);
    assert_eq!(bits(&plain), bits(&lanes));
    let mut plain = (vec![0.0; 203], vec![0.0; 203]);
    let mut lanes = plain.clone();
    let k = [&y0[..], &a[..], &b[..], &d[..]];
    quadratic(&mut plain.0, &mut plain.1, k, 2e-3);
    dispatched::quadratic(&mut lanes.0, &mut lanes.1, k, 2e-3);
    assert_eq!(bits(&plain.0), bits(&lanes.0));
    assert_eq!(bits(&plain.1), bits(&lanes.1));
}
