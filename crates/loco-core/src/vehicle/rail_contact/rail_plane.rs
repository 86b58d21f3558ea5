//! The rails' plane at a wheelset: the one frame in which the contact table is read.
//!
//! The contact table is solved on level rails (`contact::table`): rise, roll and contact points of
//! a rigid wheelset against two rails at the same height. On a track with cross level the two
//! rails at a wheelset stand at different heights, `z_left − z_right = c`, so the line through
//! their nominal contact points (2b apart, `track.contact_point_half_distance`) is rolled by
//! `θ = atan(c / 2b)` about the track's x axis. The rail plane is the track frame rolled by θ
//! about the point O on the track centre line at rail-top height (`y_c = (y_left + y_right)/2`,
//! `z_c = (z_left + z_right)/2`); in it the rails are level again (to within the product of the
//! gauge deviation and θ, which is kept) and the table applies unchanged. Everything the contact
//! needs is taken into this plane and back in one place:
//!
//! - the wheelset's pose relative to the rails: its centre, at height `h0` (the centred rolling
//!   radius) above the rail-top line when centred, has the lateral coordinate
//!   `y' = (y − y_c) cos θ + (h0 + z − z_c) sin θ`, so a wheelset that rolls with the rails about
//!   the rail-top line sits at `y = −h0 θ` in the track frame and at `y' = 0` in the table; its
//!   roll relative to the rails is `φ − θ`;
//! - the contact points and the contact frames are the table's, rotated by θ back into the track
//!   frame: the normals lean by θ, so a wheel load W gets the downhill component `W θ`;
//! - the creepages are formed in the track frame with the wheel's true angular velocity (its spin
//!   axis rolled by the full φ) and the rotated contact offsets, so the rails' roll no longer
//!   appears as a spurious rolling-radius difference `θ·l/r0` (the error this corrects: the spin
//!   vector was rolled by φ while the offsets kept the table's level pose);
//! - the rail surface's velocity at the contact point, the proxy for the contact point's
//!   longitudinal lead on a sloping rail (see `wheel_rail`), is that of the rolling rail plane:
//!   `V·dz_c/ds` upward plus `θ̇ x̂ × (c − O)` with `θ̇ = V dθ/ds`, which at the tread reduces to
//!   each rail's own vertical rate and adds the rails' roll rate at a flange point below the
//!   rail top.
//!
//! The table is read at the table's own relative roll (the rigid pose); the elastic penetrations
//! roll the wheelset relative to the rails by a little more (about 1e-4 rad, measured in
//! `tests/verification/rolled_rails.rs` for every scenario and in flange contact), which moves a contact point
//! by about r0 times that (< 0.1 mm, the table's grid step), so the table needs no relative-roll
//! axis.

use crate::track::RailIrregularity;

/// Index of the left and right rail in per-side arrays.
const LEFT: usize = 0;
const RIGHT: usize = 1;

/// The rails' plane at one wheelset and one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailPlane {
    /// Roll θ of the rails' plane about x, rad (positive: left rail higher).
    pub roll: f64,
    sin: f64,
    cos: f64,
    /// Lateral position of the origin O (track centre line), m (+ left).
    pub y_centre: f64,
    /// Height of the origin O (mean rail-top height), m (+ up).
    pub z_centre: f64,
    /// Roll rate θ̇ of the plane seen by a wheelset running at V, rad/s.
    pub roll_rate: f64,
    /// Vertical velocity of the origin seen at V, `V dz_c/ds`, m/s.
    pub vertical_rate: f64,
    /// Lateral offset of each rail from the centre line, `y_side − y_c` (half the gauge
    /// deviation, ± per side), m.
    rail_offset: [f64; 2],
    /// Height of each rail's nominal contact point in the plane (zero to first order), m.
    rail_height: [f64; 2],
}

/// The pose of a wheelset in the rails' plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanePose {
    /// Lateral displacement of the wheelset centre from the track centre line, m (+ left).
    pub lateral: f64,
    /// Vertical displacement of the centre from its nominal height `h0` above the rails, m.
    pub vertical: f64,
    /// Roll relative to the rails, rad.
    pub roll: f64,
}

impl RailPlane {
    /// The plane of `rails` whose nominal contact points are `half_distance` (m) either side of
    /// the centre line, seen by a wheelset running at `speed` (m/s).
    #[inline]
    pub fn new(rails: &RailIrregularity, half_distance: f64, speed: f64) -> Self {
        let slope = (rails.z_left - rails.z_right) / (2.0 * half_distance);
        let (roll, sin, cos) = roll_of_slope(slope);
        let y_centre = 0.5 * (rails.y_left + rails.y_right);
        let z_centre = 0.5 * (rails.z_left + rails.z_right);
        // d/dt atan(Δz / 2b) at ds/dt = V.
        let roll_rate =
            speed * (rails.dz_left_ds - rails.dz_right_ds) / (2.0 * half_distance) * cos * cos;
        let rail_offset = [rails.y_left - y_centre, rails.y_right - y_centre];
        let height = |lateral: f64, z: f64| -lateral * sin + (z - z_centre) * cos;
        Self {
            roll,
            sin,
            cos,
            y_centre,
            z_centre,
            roll_rate,
            vertical_rate: speed * 0.5 * (rails.dz_left_ds + rails.dz_right_ds),
            rail_offset,
            rail_height: [
                height(half_distance + rail_offset[LEFT], rails.z_left),
                height(-half_distance + rail_offset[RIGHT], rails.z_right),
            ],
        }
    }

    /// Pose in the plane of a wheelset whose centre is displaced by `lateral`, `vertical` (m)
    /// and rolled by `roll` (rad) in the track frame, with its centre `h0` (m) above the rail
    /// tops in the nominal position.
    #[inline]
    pub fn pose(&self, lateral: f64, vertical: f64, roll: f64, h0: f64) -> PlanePose {
        let (dy, dz) = self.relative_to_origin(lateral, vertical, h0);
        PlanePose {
            lateral: dy * self.cos + dz * self.sin,
            vertical: -dy * self.sin + dz * self.cos - h0,
            roll: roll - self.roll,
        }
    }

    /// Position (y, z) of a wheelset centre relative to O in the track frame, m.
    #[inline]
    fn relative_to_origin(&self, lateral: f64, vertical: f64, h0: f64) -> (f64, f64) {
        (lateral - self.y_centre, h0 + vertical - self.z_centre)
    }

    /// Position (m) at which the contact table is read for the wheel on `side` (0 left, 1 right)
    /// of a wheelset at plane lateral displacement `lateral`: relative to that wheel's rail, so
    /// a gauge deviation moves each contact on its own.
    #[inline]
    pub fn table_position(&self, lateral: f64, side: usize) -> f64 {
        lateral - self.rail_offset[side]
    }

    /// Height (m, in the plane) of the rail on `side` at its nominal contact point.
    #[inline]
    pub fn rail_height(&self, side: usize) -> f64 {
        self.rail_height[side]
    }

    /// (sin θ, cos θ) of the plane's roll.
    #[inline]
    pub fn roll_sin_cos(&self) -> (f64, f64) {
        (self.sin, self.cos)
    }

    /// A vector (y, z components; x unchanged) of the plane in track-frame components.
    #[inline]
    pub fn to_track(&self, v: [f64; 3]) -> [f64; 3] {
        [
            v[0],
            v[1] * self.cos - v[2] * self.sin,
            v[1] * self.sin + v[2] * self.cos,
        ]
    }

    /// Velocity (m/s, track frame) of the rail surface passing through the point at `offset`
    /// (m, track frame) from the centre of a wheelset displaced by `lateral`, `vertical` (m):
    /// the plane's vertical rate plus its roll rate about O.
    #[inline]
    pub fn surface_velocity(
        &self,
        lateral: f64,
        vertical: f64,
        h0: f64,
        offset: &[f64; 3],
    ) -> [f64; 3] {
        let (dy, dz) = self.relative_to_origin(lateral, vertical, h0);
        let (cy, cz) = (dy + offset[1], dz + offset[2]);
        [
            0.0,
            -self.roll_rate * cz,
            self.vertical_rate + self.roll_rate * cy,
        ]
    }
}

/// θ = atan(x), sin θ, cos θ; by their series where |x| ≤ 0.02 (the track limits keep a run
/// there; truncation below 1e-15 relative), which spares three libm calls per wheelset and
/// right-hand side.
#[inline]
fn roll_of_slope(x: f64) -> (f64, f64, f64) {
    if x.abs() > 0.02 {
        let roll = x.atan();
        let (s, c) = roll.sin_cos();
        return (roll, s, c);
    }
    let x2 = x * x;
    let roll = x * (1.0 - x2 * (1.0 / 3.0 - x2 * (1.0 / 5.0 - x2 * (1.0 / 7.0 - x2 / 9.0))));
    let r2 = roll * roll;
    let sin = roll * (1.0 - r2 / 6.0 * (1.0 - r2 / 20.0 * (1.0 - r2 / 42.0)));
    let cos = 1.0 - r2 / 2.0 * (1.0 - r2 / 12.0 * (1.0 - r2 / 30.0));
    (roll, sin, cos)
}

#[cfg(test)]
mod tests {
    use super::*;

    const B: f64 = 0.7465;
    const H0: f64 = 0.625;

    fn cross_level(c: f64, dc_ds: f64) -> RailIrregularity {
        RailIrregularity {
            z_left: 0.5 * c,
            z_right: -0.5 * c,
            dz_left_ds: 0.5 * dc_ds,
            dz_right_ds: -0.5 * dc_ds,
            ..RailIrregularity::default()
        }
    }

    #[test]
    fn series_match_the_functions() {
        for x in [-0.02, -1e-3, 0.0, 3e-4, 0.0199, 0.05] {
            let (roll, s, c) = roll_of_slope(x);
            let exact = f64::atan(x);
            assert!((roll - exact).abs() <= 1e-15 * exact.abs(), "{x}");
            assert!((s - exact.sin()).abs() <= 1e-15 * exact.abs(), "{x}");
            assert!((c - exact.cos()).abs() <= 1e-15, "{x}");
        }
    }

    #[test]
    fn level_rails_are_the_track_frame() {
        let rails = RailIrregularity {
            y_left: 0.002,
            y_right: 0.002,
            z_left: 0.001,
            z_right: 0.001,
            ..RailIrregularity::default()
        };
        let plane = RailPlane::new(&rails, B, 50.0);
        let pose = plane.pose(0.003, 0.0015, 0.01, H0);
        assert!((pose.lateral - 0.001).abs() < 1e-15);
        assert!((pose.vertical - 0.0005).abs() < 1e-15);
        assert_eq!(pose.roll, 0.01);
        assert_eq!(plane.to_track([1.0, 2.0, 3.0]), [1.0, 2.0, 3.0]);
        assert!(plane.rail_height(0).abs() < 1e-15 && plane.rail_height(1).abs() < 1e-15);
    }

    #[test]
    fn wheelset_rolled_with_the_rails_sits_at_minus_h0_theta() {
        // Hand calculation: 2 mm cross level over 2b = 1.493 m rolls the rails by
        // θ = atan(0.002 / 1.493) = 1.3396 mrad; a wheelset turned rigidly with them about the
        // rail-top line through O has its centre at (−h0 sin θ, h0 cos θ).
        let c = 0.002;
        let plane = RailPlane::new(&cross_level(c, 0.0), B, 50.0);
        let theta = (c / (2.0 * B)).atan();
        assert!((plane.roll - theta).abs() < 1e-15);
        let pose = plane.pose(-H0 * theta.sin(), H0 * (theta.cos() - 1.0), theta, H0);
        assert!(pose.lateral.abs() < 1e-15, "{}", pose.lateral);
        assert!(pose.vertical.abs() < 1e-15);
        assert!(pose.roll.abs() < 1e-18);
        // Both rails are level in the plane, the left wheel's table position is the plane's.
        assert!(plane.rail_height(0).abs() < 1e-15 && plane.rail_height(1).abs() < 1e-15);
        assert_eq!(plane.table_position(0.001, 0), 0.001);
    }

    #[test]
    fn normals_lean_downhill_and_surface_follows_each_rail() {
        let plane = RailPlane::new(&cross_level(0.002, 1e-4), B, 50.0);
        let theta = plane.roll;
        // A normal (0, 0, 1) of the plane leans toward −y (the low, right rail) by θ.
        let n = plane.to_track([0.0, 0.0, 1.0]);
        assert!((n[1] + theta.sin()).abs() < 1e-15 && (n[2] - theta.cos()).abs() < 1e-15);
        // At the left tread contact (b from O at rail-top height) the surface rises at the left
        // rail's own rate V·dz_left/ds (to the plane's cos² θ); a flange point 15 mm below the
        // rail top also moves laterally at θ̇ · 15 mm.
        let offset = [0.0, B, -H0];
        let v = plane.surface_velocity(0.0, 0.0, H0, &offset);
        let dz_left = 50.0 * 0.5e-4;
        assert!((v[2] - dz_left * theta.cos().powi(2)).abs() < 1e-12 * dz_left);
        assert!(v[1].abs() < 1e-18);
        let flange = [0.0, B - 0.03, -H0 - 0.015];
        let v = plane.surface_velocity(0.0, 0.0, H0, &flange);
        assert!((v[1] - plane.roll_rate * 0.015).abs() < 1e-15);
        assert!(theta > 0.0 && plane.roll_rate > 0.0);
    }
}
