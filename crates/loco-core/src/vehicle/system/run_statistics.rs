//! What a run cost: evaluations of the equations of motion, time steps, Newton iterations of the
//! static equilibrium and wall time. Counted on the [`crate::vehicle::system::simulation::VehicleSystem`] as it
//! works; they never feed back into the physics, so results stay bit-identical.

/// Cost statistics of one run (or of a batch sample).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RunStatistics {
    /// Evaluations of the force model (right-hand side), in the static search and in time.
    pub rhs_evaluations: u64,
    /// Time steps integrated (RK4, settling steps included).
    pub steps: u64,
    /// Newton iterations of the static equilibrium search.
    pub newton_iterations: u64,
    /// Wall time of the run, s: equilibrium, integration and metrics (a batch sample also counts
    /// building its vehicle).
    pub wall_time: f64,
}

impl RunStatistics {
    /// Names of the statistics, in [`RunStatistics::values`] order (the columns of batch rows and
    /// the keys in Python).
    pub const NAMES: [&'static str; 4] =
        ["rhs_evaluations", "steps", "newton_iterations", "wall_time"];

    /// The statistics as numbers, in [`RunStatistics::NAMES`] order (counts exact below 2⁵³).
    pub fn values(&self) -> [f64; 4] {
        [
            self.rhs_evaluations as f64,
            self.steps as f64,
            self.newton_iterations as f64,
            self.wall_time,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_values_line_up() {
        let s = RunStatistics {
            rhs_evaluations: 4,
            steps: 1,
            newton_iterations: 3,
            wall_time: 0.5,
        };
        let by_name: Vec<(&str, f64)> = RunStatistics::NAMES.into_iter().zip(s.values()).collect();
        assert_eq!(
            by_name,
            [
                ("rhs_evaluations", 4.0),
                ("steps", 1.0),
                ("newton_iterations", 3.0),
                ("wall_time", 0.5)
            ]
        );
    }
}
