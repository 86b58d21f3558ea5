//! Where the time loop keeps its long step: the lateral range of smooth contact geometry.
//!
//! The exponential scheme's 2 ms step keeps the reference's metrics (within the 0.5 % gate)
//! while the contact point moves smoothly over the tread. Where it jumps (the flange taking
//! over, 45–70° within one 0.1 mm table node, or a second tread point) the wheel-rail force
//! changes direction within a millimetre, and on the flange the contact's lateral stiffness
//! (Hertz stiffness times sin²γ, 10⁸–10⁹ N/m against a wheelset's 2 t) makes a mode the long
//! step follows poorly; there the step is cut into parts no longer than the reference. Each
//! wheel is measured against its own rail (a gauge deviation moves the flanges).
//!
//! The range is the pair's own: from the table, the first jump of a touching point's contact
//! angle less [`FLANGE_APPROACH`], but never below EN 15302's 3 mm reference amplitude
//! ([`TREAD_RANGE`]), within which the long step is measured accurate on every study profile,
//! the worn wheel's tread jump at 1.7 mm included. On CN60: 13.1 mm for the thin flange (jump to
//! the flange at 15.1 mm; its wheelsets wander 3–8 mm on a low-conicity tread that stays linear
//! there), 5.9 mm for the new wheel (flange at 7.9 mm), 3 mm for the worn one (jump at 1.7 mm).
//! With 3 mm for every pair, S_low runs took 28 % more steps.
//!
//! The long step itself is taken only where it resolves the creep forces' decay
//! ([`crate::vehicle::analysis::stiffest_mode::stable_step`], [`crate::vehicle::analysis::creep_decay`]): at 10 m/s (`λ h` = 1.82 at
//! 2 ms) a vehicle running at 5–9 mm in a curve on a cone rang at 0.6 m/s² with it, where it
//! rests at 1 ms (tests/verification/curving_quasi_static.rs).

use crate::vehicle::model::layout::{wheelset, N_DOF, N_WHEELSETS, Y};
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use crate::vehicle::system::simulation::VehicleSystem;

/// Distance (m) before the first jump of the contact point within which the step is already
/// cut: a wheelset hunting at 8 mm and 5 Hz moves 0.5 mm per 2 ms step, and a gauge
/// deviation of ±2 mm moves one wheel's table position by 1 mm.
pub const FLANGE_APPROACH: f64 = 2e-3;

/// Lateral range (m) in which the long step is kept on any wheel/rail pair: EN 15302's reference
/// amplitude of the equivalent conicity, the bound of quasi-linear tread running.
pub const TREAD_RANGE: f64 = 3e-3;

/// Change of a touching point's contact angle between two table nodes (rad) that counts as a
/// jump: 5°, where the study's treads change by 0.05° (new, thin flange) to 0.18° (worn flange
/// root) per 0.1 mm node and their jumps by 19–51°.
pub const CONTACT_JUMP: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// The lateral range of a wheel/rail pair in which the long step holds, m: `[towards the left
/// flange (+y), towards the right flange (−y)]`, each wheel's table position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LongStepRange(pub [f64; 2]);

impl LongStepRange {
    /// The range of `wheel_rail`'s contact table (its half range where no point jumps).
    pub fn of(wheel_rail: &WheelRail) -> Self {
        let table = wheel_rail.table();
        let (_, half_range) = table.y_range();
        let n = (half_range / table.step()).floor() as usize;
        let angles = |y: f64| {
            table
                .lookup(y)
                .wheels
                .map(|w| w.touching().map(|p| p.contact_angle))
        };
        Self(std::array::from_fn(|side| {
            let sign = if side == 0 { 1.0 } else { -1.0 };
            let jump = (1..=n).map(|i| i as f64 * table.step()).find(|&y| {
                let (before, after) = (angles(sign * (y - table.step())), angles(sign * y));
                before.iter().zip(&after).any(|(a, b)| match (a, b) {
                    (Some(a), Some(b)) => (a - b).abs() > CONTACT_JUMP,
                    _ => true,
                })
            });
            let smooth = jump.unwrap_or(half_range) - FLANGE_APPROACH;
            smooth.max(TREAD_RANGE)
        }))
    }

    /// Whether every wheel of state `y` at time `t` (s), and moving on at its wheelset's lateral
    /// velocity `ahead` (s) later, is inside the range.
    pub fn holds(&self, system: &VehicleSystem, t: f64, y: &[f64], ahead: f64) -> bool {
        (0..N_WHEELSETS).all(|w| {
            let rails = system.rails_at(w, t);
            let now = y[wheelset(w) + Y];
            let later = now + ahead * y[N_DOF + wheelset(w) + Y];
            [now, later].iter().all(|&p| {
                let (left, right) = (p - rails.y_left, p - rails.y_right);
                left.max(right) <= self.0[0] && -left.min(right) <= self.0[1]
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::params::parameters::ParameterSet;
    use crate::vehicle::scenarios::scenario::Scenario;
    use crate::vehicle::scenarios::scenario_contact::build_wheel_rail;
    use crate::vehicle::scenarios::scenario_settings::{DEFAULT_DISTANCE, DEFAULT_SPEED};

    fn range(name: &str) -> [f64; 2] {
        let scenario = Scenario::study(name, DEFAULT_SPEED, DEFAULT_DISTANCE, 1).unwrap();
        let wheel_rail = build_wheel_rail(&ParameterSet::default_vehicle(), &scenario).unwrap();
        LongStepRange::of(&wheel_rail).0
    }

    /// The first jumps of the touching points' contact angles, read off `loco.contact.geometry`
    /// on a 0.1 mm grid (the flange at 15.1 mm for the thin flange and 7.9 mm for the new wheel;
    /// the worn wheel's right contact point leaves the tread's middle for its field side at
    /// 1.7 mm), less the approach, at least the tread range; both sides alike (symmetric pairs).
    #[test]
    fn each_study_pair_keeps_the_long_step_up_to_its_first_contact_jump() {
        for (name, expected) in [("S_low", 13.1e-3), ("S_norm", 5.9e-3), ("S_high", 3e-3)] {
            let [left, right] = range(name);
            assert!((left - expected).abs() < 1e-9, "{name}: {left}");
            assert!((right - expected).abs() < 1e-9, "{name}: {right}");
        }
    }
}
