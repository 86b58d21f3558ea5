//! Fixed-step Runge–Kutta integration of the vehicle's first-order equations: the classical RK4
//! (the reference) and the exponential ETDRK4 (the default).
//!
//! A fixed step: the wheel-rail contact and the FASTSIM creep forces are smooth between steps but
//! expensive, an adaptive method would spend its savings on step rejections at flange contact, and
//! a fixed step gives output at a fixed rate and results that are bit-identical run to run.
//!
//! **The reference**, [`Integrator::Rk4`] at 1 ms ([`REFERENCE_STEP`]), from the
//! convergence study `scripts/verify/convergence_study.py`: over the nominal vehicle and Latin-hypercube
//! samples of the six SPEC §6 parameters, halving it changes W_y (S_low) by at most 0.001 % and
//! A_yb (S_high) by at most 0.06 %; the stiffest modes (hollow-shaft tilt in its gearbox
//! bearings, ≈ 320 Hz; wheelset on the Hertz contact) stay inside RK4's stability region at that
//! step. A Maxwell damper whose internal pole k/c is too fast for the step (SPEC §6 reaches
//! 5·10³ 1/s) is integrated as the pure damper, its series spring rigid, with the error bound of
//! [`crate::dampers`]; `tests/verification/parameter_box.rs` runs every damper corner of the box and checks
//! the step convergence on every CI run.
//!
//! **The default**, [`Integrator::ExponentialRk4`] at 2 ms ([`crate::vehicle::time::exponential_rk4`]), takes
//! RK4's stages for everything but the gearbox bearings' springs and the linear Maxwell dampers'
//! series springs, which it solves exactly ([`crate::vehicle::time::stiff_linear_part`],
//! [`crate::vehicle::time::decaying_states`]), so that a 2 ms step is stable with the damper laws of the 1 ms
//! reference: `tests/verification/exponential_step.rs` keeps W_y, A_yb and the A_yc PSD peak within 0.5 % of
//! the reference over the SPEC §6 box on the study's 500 m runs, and halving its step changes
//! W_y by at most 0.011 % and A_yb by at most 0.2 % (the convergence study). Steps are cut to 1 ms
//! while a wheel is outside its pair's smooth contact range ([`crate::vehicle::output::long_step_range`]). Solved exactly, the
//! bearings' modes keep only their physical damping (`hollow_shaft.bearing_damping_time`), which
//! brings a steady curve to rest (`tests/verification/curving.rs`); RK4 at 1 ms damps them numerically as well.
//!
//! Discrete states (the FSD valve) are advanced once per accepted step through
//! [`OdeSystem::after_step`].

/// The reference step of the classical RK4 ([`Integrator::Rk4`]), s: the convergence study's
/// (`scripts/verify/convergence_study.py`), against which the exponential scheme is checked.
pub const REFERENCE_STEP: f64 = 1e-3;

/// The default step of [`Integrator::ExponentialRk4`], s: with the gearbox
/// bearings solved exactly the vehicle is stable at 2 ms, and 500 Hz output stays on whole steps
/// (`tests/verification/exponential_step.rs`).
pub const EXPONENTIAL_STEP: f64 = 2e-3;

/// The time integration scheme of a run, both with a fixed step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Integrator {
    /// The classical RK4 ([`Rk4Workspace`]): the reference, at [`REFERENCE_STEP`].
    Rk4,
    /// ETDRK4 with the gearbox bearings' stiff springs and the linear dampers' series springs
    /// solved exactly ([`crate::vehicle::time::exponential_rk4`]), at [`EXPONENTIAL_STEP`]: the
    /// default, 1.6–1.8× faster than the reference and within 0.5 % of it in W_y, A_yb and the
    /// A_yc PSD peak over the SPEC §6 box on 500 m runs (`tests/verification/exponential_step.rs`).
    #[default]
    ExponentialRk4,
}

impl Integrator {
    /// The schemes' names in settings files and the Python API, in the order of the variants.
    pub const NAMES: [&'static str; 2] = ["rk4", "etdrk4"];

    /// Every scheme, in the order of [`Self::NAMES`].
    pub const ALL: [Self; 2] = [Self::Rk4, Self::ExponentialRk4];

    /// The scheme called `name` (one of [`Self::NAMES`]); anything else is an error naming
    /// `integrator`.
    pub fn from_name(name: &str) -> crate::error::Result<Self> {
        Self::ALL
            .into_iter()
            .find(|scheme| scheme.name() == name)
            .ok_or_else(|| {
                crate::error::LocoError::param(
                    "integrator",
                    format!("unknown scheme `{name}`; expected one of {:?}", Self::NAMES),
                )
            })
    }

    /// The scheme's name (one of [`Self::NAMES`]).
    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    /// The step the scheme runs at when none is given, s: RK4's reference step, or the
    /// exponential scheme's 2 ms.
    pub fn default_step(self) -> f64 {
        match self {
            Self::Rk4 => REFERENCE_STEP,
            Self::ExponentialRk4 => EXPONENTIAL_STEP,
        }
    }
}

/// A first-order system `ẏ = f(t, y)` with discrete updates between steps.
pub trait OdeSystem {
    /// Number of continuous states.
    fn dimension(&self) -> usize;
    /// Writes `f(t, y)` into `dydt`.
    fn derivatives(&mut self, t: f64, y: &[f64], dydt: &mut [f64]);
    /// Called after each accepted step with the new time and state (discrete updates, checks).
    fn after_step(&mut self, t: f64, dt: f64, y: &[f64]);
}

/// Preallocated stages of RK4.
#[derive(Debug, Clone)]
pub struct Rk4Workspace {
    k1: Vec<f64>,
    k2: Vec<f64>,
    k3: Vec<f64>,
    k4: Vec<f64>,
    stage: Vec<f64>,
}

impl Rk4Workspace {
    /// Workspace for a system of `n` states.
    pub fn new(n: usize) -> Self {
        Self {
            k1: vec![0.0; n],
            k2: vec![0.0; n],
            k3: vec![0.0; n],
            k4: vec![0.0; n],
            stage: vec![0.0; n],
        }
    }

    /// Advances `y` from `t` to `t + dt` (s) in one RK4 step.
    pub fn step<S: OdeSystem>(&mut self, system: &mut S, t: f64, dt: f64, y: &mut [f64]) {
        self.step_observed(system, t, dt, t + dt, y, |_, _, _| {});
    }

    /// [`Self::step`], calling `observe(system, y, ẏ)` with the derivatives at the start of the
    /// step, right after they are evaluated: outputs at the step's start come free with the first
    /// stage instead of costing one more evaluation (and the system's last-evaluation fields,
    /// such as the wheel forces, belong to that state). `t_end` (s) is the step's end as the
    /// caller counts time, `t + dt` up to the last bit: the last stage and `after_step` take it,
    /// so that what the system keeps for that time (the track frames of a curve) is found again
    /// by the next step, which starts at exactly `t_end` (a fixed-step run counts `(n + 1)·dt`,
    /// which differs from `t + dt` in the last bit in about a third of the steps).
    pub fn step_observed<S: OdeSystem>(
        &mut self,
        system: &mut S,
        t: f64,
        dt: f64,
        t_end: f64,
        y: &mut [f64],
        observe: impl FnOnce(&S, &[f64], &[f64]),
    ) {
        fn stage(out: &mut [f64], y: &[f64], h: f64, k: &[f64]) {
            for ((o, yi), ki) in out.iter_mut().zip(y).zip(k) {
                *o = yi + h * ki;
            }
        }
        system.derivatives(t, y, &mut self.k1);
        observe(system, y, &self.k1);
        stage(&mut self.stage, y, 0.5 * dt, &self.k1);
        system.derivatives(t + 0.5 * dt, &self.stage, &mut self.k2);
        stage(&mut self.stage, y, 0.5 * dt, &self.k2);
        system.derivatives(t + 0.5 * dt, &self.stage, &mut self.k3);
        stage(&mut self.stage, y, dt, &self.k3);
        system.derivatives(t_end, &self.stage, &mut self.k4);
        for (i, yi) in y.iter_mut().enumerate() {
            *yi += dt / 6.0 * (self.k1[i] + 2.0 * self.k2[i] + 2.0 * self.k3[i] + self.k4[i]);
        }
        system.after_step(t_end, dt, y);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Undamped oscillator ẍ = −ω² x.
    struct Oscillator {
        omega: f64,
    }

    impl OdeSystem for Oscillator {
        fn dimension(&self) -> usize {
            2
        }
        fn derivatives(&mut self, _t: f64, y: &[f64], dydt: &mut [f64]) {
            dydt[0] = y[1];
            dydt[1] = -self.omega * self.omega * y[0];
        }
        fn after_step(&mut self, _t: f64, _dt: f64, _y: &[f64]) {}
    }

    fn error_after_one_period(steps: usize) -> f64 {
        let omega = 2.0 * std::f64::consts::PI;
        let mut sys = Oscillator { omega };
        let mut ws = Rk4Workspace::new(2);
        let mut y = [1.0, 0.0];
        let dt = 1.0 / steps as f64;
        for i in 0..steps {
            ws.step(&mut sys, i as f64 * dt, dt, &mut y);
        }
        (y[0] - 1.0).abs() + y[1].abs() / omega
    }

    #[test]
    fn fourth_order_convergence() {
        let e1 = error_after_one_period(50);
        let e2 = error_after_one_period(100);
        let order = (e1 / e2).log2();
        assert!((order - 4.0).abs() < 0.2, "observed order {order}");
    }
}
