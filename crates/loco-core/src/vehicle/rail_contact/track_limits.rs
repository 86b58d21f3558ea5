//! Which track irregularities the wheel-rail contact can follow: checked before a run, so a
//! measured file that the contact table cannot represent is refused with its line and value
//! instead of derailing or silently clamping part-way through.
//!
//! - Gauge: each wheel reads the table at the wheelset's position relative to its own rail, so a
//!   gauge deviation g shifts the two wheels' look-ups by ∓g/2. The table covers ±H (25 mm); a
//!   wheelset must still be able to cross its flangeway to flange contact on either side, so
//!   `|g|/2 + c_f ≤ H`, with c_f the flangeway clearance of the pair: the smallest lateral
//!   displacement at which the touching point's contact angle reaches [`FLANGE_ANGLE`].
//! - Cross level: the rails' plane ([`crate::vehicle::rail_contact::rail_plane`]) takes any roll of the rails, but the
//!   bodies' motions are small-rotation maps whose error grows as θ²; |θ| ≤ [`MAX_RAIL_ROLL`]
//!   keeps it below 4e-4 of the motion, and is far beyond the cross-level irregularity of a
//!   track in service (a few millimetres; cant belongs to the designed track geometry).

use crate::error::{FileKind, LocoError, Result};
use crate::track::{Channel, TrackIrregularity};
use crate::vehicle::rail_contact::wheel_rail::WheelRail;

/// Contact angle (rad) from which a touching point counts as on the flange.
pub const FLANGE_ANGLE: f64 = 0.8;

/// Largest roll of the rails' plane (rad) a run accepts: 30 mm of cross level over 1.493 m.
pub const MAX_RAIL_ROLL: f64 = 0.02;

/// The irregularities a wheel/rail pair's contact can follow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackLimits {
    /// Largest |gauge deviation|, m.
    pub gauge: f64,
    /// Largest |cross level|, m.
    pub cross_level: f64,
    /// Flangeway clearance of the pair, m (for messages).
    pub flangeway: f64,
}

impl TrackLimits {
    /// The limits of `wheel_rail`'s table and contact geometry.
    pub fn of(wheel_rail: &WheelRail) -> Self {
        let table = wheel_rail.table();
        let (_, half_range) = table.y_range();
        let on_flange = |y: f64| {
            table.lookup(y).wheels[0]
                .touching()
                .is_some_and(|p| p.contact_angle >= FLANGE_ANGLE)
        };
        let n = (half_range / table.step()).floor() as usize;
        let flangeway = (0..=n)
            .map(|i| i as f64 * table.step())
            .find(|&y| on_flange(y))
            .unwrap_or(half_range);
        Self {
            gauge: 2.0 * (half_range - flangeway).max(0.0),
            cross_level: 2.0 * wheel_rail.contact_half_distance() * MAX_RAIL_ROLL.tan(),
            flangeway,
        }
    }

    /// Checks every row of a measured track (naming the file's line) or every node of another.
    pub fn check(&self, track: &TrackIrregularity) -> Result<()> {
        let problem = |cross: f64, gauge: f64| -> Option<String> {
            if gauge.is_nan() || gauge.abs() > self.gauge {
                Some(format!(
                    "gauge deviation {:.2} mm is beyond the ±{:.2} mm the contact table follows \
                     (its ±25 mm less the flangeway clearance {:.2} mm, for each wheel)",
                    gauge * 1e3,
                    self.gauge * 1e3,
                    self.flangeway * 1e3
                ))
            } else if cross.is_nan() || cross.abs() > self.cross_level {
                Some(format!(
                    "cross level {:.2} mm is beyond the ±{:.2} mm (rails' roll ±{MAX_RAIL_ROLL} \
                     rad) the vehicle's small-rotation kinematics follow",
                    cross * 1e3,
                    self.cross_level * 1e3
                ))
            } else {
                None
            }
        };
        let (cross, gauge) = (Channel::CrossLevel.index(), Channel::Gauge.index());
        if let Some(origin) = track.origin() {
            for (k, &line) in origin.lines.iter().enumerate() {
                if let Some(reason) = problem(origin.channels[cross][k], origin.channels[gauge][k])
                {
                    return Err(LocoError::parse(
                        FileKind::Track,
                        &origin.path,
                        line,
                        reason,
                    ));
                }
            }
            return Ok(());
        }
        let (c, g) = (
            track.channel(Channel::CrossLevel),
            track.channel(Channel::Gauge),
        );
        for (k, (c, g)) in c.iter().zip(&g).enumerate() {
            if let Some(reason) = problem(*c, *g) {
                return Err(LocoError::input(
                    "track",
                    format!("at {:.2} m: {reason}", k as f64 * track.step()),
                ));
            }
        }
        Ok(())
    }
}
