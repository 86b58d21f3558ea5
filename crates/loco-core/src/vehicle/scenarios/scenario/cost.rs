//! The cost check of a scenario: its speed, step, output rate, creep grid and record length
//! against the bounds of [`crate::vehicle::scenarios::run_limits`], refused before any work.

use crate::error::{LocoError, Result};
use crate::vehicle::scenarios::run_limits::{
    min_output_rate, CREEP_GRID_TOLERANCE, MAX_CREEP_GRID_ELEMENTS, MAX_SAMPLES, MAX_STEPS,
    MIN_CREEP_GRID_SIDE, MIN_SPEED,
};
use crate::vehicle::scenarios::scenario::Scenario;

/// Checks the cost bounds of a scenario whose fields are already finite and positive.
pub fn check_cost(scenario: &Scenario) -> Result<()> {
    if scenario.speed < MIN_SPEED {
        return Err(LocoError::param(
            "speed",
            format!(
                "{} m/s is below the lowest speed {MIN_SPEED} m/s ({:.1} km/h): a run's cost \
                 per metre grows as 1/speed ({:.0} integration steps per metre here) and the \
                 creepages are singular at standstill",
                scenario.speed,
                MIN_SPEED * 3.6,
                1.0 / (scenario.speed * scenario.run.step)
            ),
        ));
    }
    let lowest_rate = min_output_rate();
    if scenario.run.output_rate <= lowest_rate {
        return Err(LocoError::param(
            "output_rate",
            format!(
                "{} Hz is too slow for the run's metrics: they evaluate frequencies up to {} Hz, \
                 so the output rate must exceed {lowest_rate} Hz",
                scenario.run.output_rate,
                lowest_rate / 2.0
            ),
        ));
    }
    let [nx, ny] = [scenario.fastsim.nx, scenario.fastsim.ny];
    if nx < MIN_CREEP_GRID_SIDE || ny < MIN_CREEP_GRID_SIDE {
        return Err(LocoError::param(
            "fastsim_grid",
            format!(
                "({nx}, {ny}) must have nx, ny >= {MIN_CREEP_GRID_SIDE}: a coarser grid moves the \
                 study's metrics by more than {:.0} % from their converged values (5 × 5 by \
                 5.6 %, 1 × 1 by 50 %; the default 10 × 10 by 2.3 %)",
                CREEP_GRID_TOLERANCE * 100.0
            ),
        ));
    }
    if nx.saturating_mul(ny) > MAX_CREEP_GRID_ELEMENTS {
        return Err(LocoError::param(
            "fastsim_grid",
            format!(
                "({nx}, {ny}) must have nx·ny <= {MAX_CREEP_GRID_ELEMENTS}: the creep model's \
                 cost grows with nx·ny (50 × 50 costs 15 times the default 10 × 10 per step) \
                 and its forces change by under 0.1 % of μN beyond 20 × 20"
            ),
        ));
    }
    let seconds = (scenario.lead_in + scenario.distance) / scenario.speed;
    let steps = seconds / scenario.run.step;
    if steps > MAX_STEPS {
        // Name the setting that makes the run long: a small step or a long, slow run.
        let field = if scenario.run.step < crate::vehicle::output::run::RunSettings::default().step
        {
            "step"
        } else {
            "distance"
        };
        return Err(LocoError::param(
            field,
            format!(
                "the run needs {steps:.0} integration steps ({seconds:.1} s simulated at a {} s \
                 step), beyond the {MAX_STEPS:.0e} of one run (about 40 min of one core): run \
                 a shorter distance, at a higher speed or with a larger step",
                scenario.run.step
            ),
        ));
    }
    let samples = scenario.distance / scenario.speed * scenario.run.output_rate;
    if samples < 1.0 {
        // A record shorter than one sample interval would run nothing and return nothing.
        return Err(LocoError::param(
            "distance",
            format!(
                "{} m at {} m/s is shorter than one output sample ({} s at {} Hz): the run \
                 would record nothing",
                scenario.distance,
                scenario.speed,
                1.0 / scenario.run.output_rate,
                scenario.run.output_rate
            ),
        ));
    }
    if samples > MAX_SAMPLES {
        return Err(LocoError::param(
            "output_rate",
            format!(
                "{} Hz over {:.1} s of record is {samples:.0} samples per channel, beyond the \
                 {MAX_SAMPLES:.0e} one run keeps in memory: lower the output rate or run several \
                 shorter distances",
                scenario.run.output_rate,
                scenario.distance / scenario.speed
            ),
        ));
    }
    Ok(())
}
