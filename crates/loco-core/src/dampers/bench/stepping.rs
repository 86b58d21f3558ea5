//! Fixed-step RK4 integration of a damper's internal states under a prescribed elongation, with
//! the discrete state advanced after every step as the vehicle does.

use super::{BenchOptions, BenchRecord};
use crate::dampers::{Damper, DamperDiscreteState, MAX_STATES};
use crate::error::{check_all_finite, Result};
use crate::LocoError;

/// The most RK4 steps one bench run may take (about a minute of computing): beyond, the damper's
/// internal pole is too fast for the length of the motion and the run is refused.
const MAX_TOTAL_STEPS: f64 = 2e9;

/// Integration substeps per recorded sample of length `sample_dt` (s).
pub(super) fn substeps(
    sample_dt: f64,
    max_dt: f64,
    options: &BenchOptions,
    frequency_hz: f64,
) -> usize {
    let by_stability = (sample_dt / max_dt).ceil();
    let by_resolution = (sample_dt * frequency_hz * options.steps_per_cycle as f64).ceil();
    by_stability.max(by_resolution).max(1.0) as usize
}

/// Refuses a run of `total_steps` steps beyond [`MAX_TOTAL_STEPS`].
pub(super) fn check_run_length(total_steps: f64, damper: &Damper) -> Result<()> {
    if total_steps > MAX_TOTAL_STEPS {
        return Err(LocoError::input(
            "motion",
            format!(
                "needs {total_steps:.3e} integration steps (the damper's fastest internal pole is \
                 {:.3e} 1/s); shorten the motion or use a slower damper",
                damper.fastest_rate_per_s()
            ),
        ));
    }
    Ok(())
}

/// Integrates `n_samples · substeps` RK4 steps of `dt` (s) with the elongation `motion(t)`,
/// recording at every `substeps`-th step and calling `each_step(t, force, velocity)` at the start
/// of every step.
pub(super) fn drive(
    damper: &Damper,
    n_samples: usize,
    substeps: usize,
    dt: f64,
    motion: impl Fn(f64) -> (f64, f64),
    mut each_step: impl FnMut(f64, f64, f64),
) -> BenchRecord {
    let n = damper.n_states();
    let mut states = [0.0; MAX_STATES];
    damper.initial_states(&mut states[..n]);
    let mut discrete = damper.initial_discrete();
    let (x0, v0) = motion(0.0);
    damper.advance(&mut discrete, 0.0, 0.0, x0, v0, &states[..n]);
    let mut record = BenchRecord::default();
    let mut energy = 0.0;
    for sample in 0..=n_samples {
        let t_sample = (sample * substeps) as f64 * dt;
        let (x, v) = motion(t_sample);
        let mut scratch = [0.0; MAX_STATES];
        let force = damper.evaluate(x, v, &states[..n], &discrete, &mut scratch[..n]);
        push_sample(&mut record, t_sample, x, v, force, &discrete);
        if sample == n_samples {
            break;
        }
        for sub in 0..substeps {
            let t = (sample * substeps + sub) as f64 * dt;
            let force = rk4_step(damper, &motion, t, dt, &mut states[..n], &discrete);
            let (_, v) = motion(t);
            each_step(t, force, v);
            energy += force * v * dt;
            let (x_end, v_end) = motion(t + dt);
            damper.advance(&mut discrete, t + dt, dt, x_end, v_end, &states[..n]);
        }
    }
    record.dissipated_energy_j = energy;
    record
}

/// One classical RK4 step of the internal states; returns the force at the start of the step.
fn rk4_step(
    damper: &Damper,
    motion: &impl Fn(f64) -> (f64, f64),
    t: f64,
    dt: f64,
    states: &mut [f64],
    discrete: &DamperDiscreteState,
) -> f64 {
    let n = states.len();
    let mut k = [[0.0; MAX_STATES]; 4];
    let mut stage = [0.0; MAX_STATES];
    let mut force0 = 0.0;
    for i in 0..4 {
        let (t_i, weight) = match i {
            0 => (t, 0.0),
            1 | 2 => (t + 0.5 * dt, 0.5 * dt),
            _ => (t + dt, dt),
        };
        for j in 0..n {
            stage[j] = states[j] + if i == 0 { 0.0 } else { weight * k[i - 1][j] };
        }
        let (x, v) = motion(t_i);
        let force = damper.evaluate(x, v, &stage[..n], discrete, &mut k[i][..n]);
        if i == 0 {
            force0 = force;
        }
    }
    for j in 0..n {
        states[j] += dt / 6.0 * (k[0][j] + 2.0 * k[1][j] + 2.0 * k[2][j] + k[3][j]);
    }
    force0
}

fn push_sample(
    record: &mut BenchRecord,
    t: f64,
    x: f64,
    v: f64,
    force: f64,
    discrete: &DamperDiscreteState,
) {
    record.time_s.push(t);
    record.displacement_m.push(x);
    record.velocity_mps.push(v);
    record.force_n.push(force);
    record.scale_factor.push(discrete.scale_factor);
    record
        .estimated_frequency_hz
        .push(discrete.trigger.estimated_frequency_hz);
    record
        .valve_volume_m3
        .push(discrete.trigger.valve_volume_m3);
}

/// Drives the damper through a recorded motion, recording at the given sample times.
pub(super) fn run_recorded(
    damper: &Damper,
    time_s: &[f64],
    displacement_m: &[f64],
    max_dt: f64,
) -> Result<BenchRecord> {
    if time_s.len() < 2 || time_s.len() != displacement_m.len() {
        return Err(LocoError::input(
            "time_s",
            format!(
                "need at least two samples and as many displacements ({} times, {} displacements)",
                time_s.len(),
                displacement_m.len()
            ),
        ));
    }
    check_all_finite("time_s", time_s)?;
    check_all_finite("displacement_m", displacement_m)?;
    if let Some(i) = time_s.windows(2).position(|w| w[1] <= w[0]) {
        return Err(LocoError::input(
            "time_s",
            format!("must be strictly increasing (element {})", i + 1),
        ));
    }
    let duration = time_s[time_s.len() - 1] - time_s[0];
    check_run_length(duration / max_dt + time_s.len() as f64, damper)?;
    let n = damper.n_states();
    let mut states = [0.0; MAX_STATES];
    damper.initial_states(&mut states[..n]);
    let mut discrete = damper.initial_discrete();
    let mut record = BenchRecord::default();
    let slope =
        |i: usize| (displacement_m[i + 1] - displacement_m[i]) / (time_s[i + 1] - time_s[i]);
    let v0 = slope(0);
    damper.advance(
        &mut discrete,
        time_s[0],
        0.0,
        displacement_m[0],
        v0,
        &states[..n],
    );
    let mut energy = 0.0;
    for i in 0..time_s.len() {
        let v_here = slope(i.min(time_s.len() - 2));
        let mut scratch = [0.0; MAX_STATES];
        let force = damper.evaluate(
            displacement_m[i],
            v_here,
            &states[..n],
            &discrete,
            &mut scratch[..n],
        );
        push_sample(
            &mut record,
            time_s[i],
            displacement_m[i],
            v_here,
            force,
            &discrete,
        );
        if i + 1 == time_s.len() {
            break;
        }
        let interval = time_s[i + 1] - time_s[i];
        let substeps = (interval / max_dt).ceil().max(1.0) as usize;
        let dt = interval / substeps as f64;
        let (t0, x0, v) = (time_s[i], displacement_m[i], slope(i));
        let motion = |t: f64| (x0 + v * (t - t0), v);
        for sub in 0..substeps {
            let t = t0 + sub as f64 * dt;
            let force = rk4_step(damper, &motion, t, dt, &mut states[..n], &discrete);
            energy += force * v * dt;
            let (x_end, _) = motion(t + dt);
            damper.advance(&mut discrete, t + dt, dt, x_end, v, &states[..n]);
        }
    }
    record.dissipated_energy_j = energy;
    Ok(record)
}
