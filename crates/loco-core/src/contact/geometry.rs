//! Rigid contact geometry of a wheelset on a track (2-D, in the plane of the axle).
//!
//! For a lateral displacement `y` of the wheelset (m, track +y = left) the search finds the roll
//! and the vertical position at which both wheels touch their rails without penetrating: for
//! each side the gap (vertical distance wheel − rail) is minimised over the wheel profile, and the
//! roll is solved so that both minima are zero (safeguarded Newton iteration; the two minima
//! move in opposite directions with the roll, so the root is unique). Each wheel reports up to two
//! contact points: the touching minimum and a second, separate local minimum of the gap with its
//! (vertical) gap, so that tread and flange contact are both represented.
//!
//! For the equivalent conicity of EN 15302 the wheelset is instead only translated (no roll), see
//! [`ContactGeometry::rolling_radius_difference_unrolled`].
//!
//! Yaw is ignored: the problem is solved in the axle's vertical plane, exact for zero yaw. With
//! yaw angle ψ the contact points lead or lag (by about `r·tan δ·ψ` longitudinally) and their
//! lateral positions change by second-order amounts on the tread; in flange contact the effect is
//! larger (see the Manchester benchmark test for its size).
//!
//! Each side is worked in a "side frame": lateral coordinate `u` toward that side's field side
//! (`u = y` on the left, `u = −y` on the right), z up. The wheelset's roll `φ` (positive lifts the
//! left wheel) is `+φ` in the left side frame and `−φ` in the right one; the same code serves both.

use super::profile::{Profile, ProfileKind};
use super::setup::{ContactSearchParams, TrackSetup, WheelsetSetup, LEFT, RIGHT};
use super::side::Side;
use crate::error::{check_finite, LocoError, Result};

/// One contact point (touching or not) of one wheel.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactPoint {
    /// Vertical gap between wheel and rail at this point at the rigid pose, m (0 for the touching
    /// point, > 0 for a second point). The normal gap is about `gap · cos(contact_angle)`.
    pub gap: f64,
    /// Lateral position of the point relative to the wheelset centre, track axes (+ left), m.
    pub lateral: f64,
    /// Vertical position of the point relative to the wheelset centre, m (+ up, so ≈ −r).
    pub vertical: f64,
    /// Rolling radius at the point (wheel radius, distance to the axle), m.
    pub rolling_radius: f64,
    /// Contact angle, rad: angle of the common tangent in track axes, positive when the lateral
    /// part of the rail's normal force on the wheel points toward the track centre (flange
    /// contact ≈ +1.2). The normal on the left wheel is (−sin δ, cos δ) in (y, z) track axes, on
    /// the right wheel (+sin δ, cos δ).
    pub contact_angle: f64,
    /// Transverse curvature of the wheel profile at the point, 1/m, positive where the wheel is
    /// convex toward the rail, negative where it is concave (flange root, hollow tread).
    pub wheel_curvature: f64,
    /// Transverse curvature of the rail profile at the point, 1/m, positive where the rail is
    /// convex (crown: +1/0.3).
    pub rail_curvature: f64,
    /// Position of the point on the wheel profile, m (wheel profile frame, 0 = taping line,
    /// negative toward the flange).
    pub wheel_y: f64,
    /// Position of the point on the rail profile, m (rail profile frame as loaded, before
    /// inclination; negative toward the gauge side for origins on the head's centre line).
    pub rail_y: f64,
}

/// The contact points of one wheel. `points[0]` is the field-side (tread-side) point,
/// `points[1]` the gauge-side (flange-side) point when the gap has two separate minima; a single
/// minimum is reported in `points[0]` (contact tables re-assign it for continuity in `y`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelContact {
    /// Up to two contact points, see the type's documentation.
    pub points: [Option<ContactPoint>; 2],
}

impl WheelContact {
    /// The touching point (smallest gap).
    pub fn touching(&self) -> Option<&ContactPoint> {
        self.points
            .iter()
            .flatten()
            .min_by(|a, b| a.gap.total_cmp(&b.gap))
    }
}

/// Rigid contact state of the wheelset at one lateral displacement.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelsetContact {
    /// Lateral displacement of the wheelset centre, m (+ left).
    pub lateral_displacement: f64,
    /// Vertical displacement of the wheelset centre relative to its centred pose (y = 0), m, + up.
    pub rise: f64,
    /// Roll of the wheelset, rad, positive lifting the left wheel.
    pub roll: f64,
    /// Contact of the left and right wheels (`[LEFT, RIGHT]`).
    pub wheels: [WheelContact; 2],
}

impl WheelsetContact {
    /// Rolling radius difference left − right of the touching points, m (positive for y > 0 with
    /// positive conicity).
    pub fn rolling_radius_difference(&self) -> f64 {
        let r = |side: usize| {
            self.wheels[side]
                .touching()
                .map_or(f64::NAN, |p| p.rolling_radius)
        };
        r(LEFT) - r(RIGHT)
    }
}

/// Scratch buffers of the search (one per thread; reuse it in loops).
#[derive(Debug, Clone, Default)]
pub struct ContactWorkspace {
    gap: Vec<f64>,
}

/// A wheelset on a track with its profiles, ready to answer contact queries.
#[derive(Debug, Clone)]
pub struct ContactGeometry {
    sides: [Side; 2],
    params: ContactSearchParams,
    /// Wheelset centre height at y = 0, m.
    z_reference: f64,
    /// Roll at y = 0 (non-zero only for asymmetric set-ups), rad.
    roll_reference: f64,
}

impl ContactGeometry {
    /// Prepares the search. `wheels` and `rails` are `[LEFT, RIGHT]`, each in the profile frame
    /// (both as left-side profiles; the right side is mirrored here).
    pub fn new(
        wheels: [&Profile; 2],
        rails: [&Profile; 2],
        track: &TrackSetup,
        wheelset: &WheelsetSetup,
        params: &ContactSearchParams,
    ) -> Result<Self> {
        track.validate()?;
        wheelset.validate()?;
        params.validate()?;
        for (side, name) in [(LEFT, "left"), (RIGHT, "right")] {
            if wheels[side].kind() != ProfileKind::Wheel {
                return Err(LocoError::input(
                    format!("{name} wheel"),
                    format!("profile '{}' is a rail profile", wheels[side].name()),
                ));
            }
            if rails[side].kind() != ProfileKind::Rail {
                return Err(LocoError::input(
                    format!("{name} rail"),
                    format!("profile '{}' is a wheel profile", rails[side].name()),
                ));
            }
        }
        let make = |side: usize| {
            Side::new(
                wheels[side],
                rails[side],
                track,
                wheelset,
                wheelset.nominal_radius[side],
                params,
            )
        };
        let sides = [make(LEFT)?, make(RIGHT)?];
        let mut geometry = Self {
            sides,
            params: *params,
            z_reference: 0.0,
            roll_reference: 0.0,
        };
        let mut ws = ContactWorkspace::default();
        let (roll, z) = geometry.solve_pose(0.0, 0.0, &mut ws)?;
        geometry.z_reference = z;
        geometry.roll_reference = roll;
        Ok(geometry)
    }

    /// The same profiles on both sides (the right ones mirrored), the usual case.
    pub fn symmetric(
        wheel: &Profile,
        rail: &Profile,
        track: &TrackSetup,
        wheelset: &WheelsetSetup,
        params: &ContactSearchParams,
    ) -> Result<Self> {
        Self::new([wheel, wheel], [rail, rail], track, wheelset, params)
    }

    /// The search settings.
    pub fn params(&self) -> &ContactSearchParams {
        &self.params
    }

    /// Roll of the wheelset at y = 0, rad (0 for symmetric set-ups).
    pub fn roll_at_centre(&self) -> f64 {
        self.roll_reference
    }

    /// The rigid contact state at lateral displacement `y` (m, + left).
    pub fn solve(&self, y: f64) -> Result<WheelsetContact> {
        self.solve_with(y, self.roll_reference, &mut ContactWorkspace::default())
    }

    /// As [`Self::solve`], starting the roll iteration at `roll_guess` (rad) and reusing `ws`.
    pub fn solve_with(
        &self,
        y: f64,
        roll_guess: f64,
        ws: &mut ContactWorkspace,
    ) -> Result<WheelsetContact> {
        check_finite("y", y)?;
        let (roll, z) = self.solve_pose(y, roll_guess, ws)?;
        let mut wheels = [WheelContact::default(); 2];
        for (s, wheel) in wheels.iter_mut().enumerate() {
            let (u_ws, phi) = side_pose(s, y, roll);
            *wheel = self.sides[s].contacts(u_ws, phi, z, &self.params, &mut ws.gap)?;
            if s == RIGHT {
                for p in wheel.points.iter_mut().flatten() {
                    p.lateral = -p.lateral;
                }
            }
        }
        Ok(WheelsetContact {
            lateral_displacement: y,
            rise: z - self.z_reference,
            roll,
            wheels,
        })
    }

    /// The contact of each wheel with the wheelset at lateral displacement `y` (m) and roll
    /// `roll` (rad), each wheel lowered onto its own rail: per wheel `[LEFT, RIGHT]` the rise of
    /// the wheelset centre (m, from the centred pose) at which that wheel touches, and its
    /// points. At the rigid pose of [`Self::solve`] both rises are its rise; away from it the
    /// contact tables' relative-roll layers come from here.
    pub fn solve_rolled(
        &self,
        y: f64,
        roll: f64,
        ws: &mut ContactWorkspace,
    ) -> Result<[(f64, WheelContact); 2]> {
        check_finite("y", y)?;
        check_finite("roll", roll)?;
        let mut out = [(0.0, WheelContact::default()); 2];
        for (s, (rise, wheel)) in out.iter_mut().enumerate() {
            let (u_ws, phi) = side_pose(s, y, roll);
            let z = -self.sides[s].minimum(u_ws, phi, &mut ws.gap)?.h;
            *wheel = self.sides[s].contacts(u_ws, phi, z, &self.params, &mut ws.gap)?;
            if s == RIGHT {
                for p in wheel.points.iter_mut().flatten() {
                    p.lateral = -p.lateral;
                }
            }
            *rise = z - self.z_reference;
        }
        Ok(out)
    }

    /// Rolling radius difference r_left − r_right (m) at lateral displacement `y` (m) of the
    /// wheelset translated **without roll**, each wheel lowered onto its own rail: the Δr of
    /// EN 15302 (see [`super::table::rolling_radius_difference`]). [`Self::solve`] instead rolls
    /// the rigid wheelset until both wheels touch, as the vehicle model needs.
    pub fn rolling_radius_difference_unrolled(
        &self,
        y: f64,
        ws: &mut ContactWorkspace,
    ) -> Result<f64> {
        check_finite("y", y)?;
        let mut radius = [0.0; 2];
        for (s, r) in radius.iter_mut().enumerate() {
            let (u_ws, phi) = side_pose(s, y, 0.0);
            *r = self.sides[s].touching_radius(u_ws, phi, &mut ws.gap)?;
        }
        Ok(radius[LEFT] - radius[RIGHT])
    }

    /// Vertical gap (m) between wheel `side` (`LEFT`/`RIGHT`) and its rail at the wheel profile
    /// position `wheel_y` (m), with the wheelset in its rigid contact pose at displacement `y`
    /// (m): the gap function whose minima are the contact points.
    pub fn gap_at(&self, y: f64, side: usize, wheel_y: f64) -> Result<f64> {
        check_finite("y", y)?;
        check_finite("wheel_y", wheel_y)?;
        if side > RIGHT {
            return Err(LocoError::param("side", "must be 0 (left) or 1 (right)"));
        }
        let mut ws = ContactWorkspace::default();
        let (roll, z) = self.solve_pose(y, self.roll_reference, &mut ws)?;
        let (u_ws, phi) = side_pose(side, y, roll);
        let (lo, hi) = self.sides[side].wheel.y_range();
        let h = (lo..=hi)
            .contains(&wheel_y)
            .then(|| self.sides[side].eval_h(u_ws, phi, wheel_y))
            .flatten()
            .ok_or_else(|| {
                LocoError::input("wheel_y", format!("{wheel_y} m is not above the rail"))
            })?;
        Ok(z + h.0)
    }

    /// Roll (rad) and centre height (m) at which both wheels touch.
    fn solve_pose(&self, y: f64, roll_guess: f64, ws: &mut ContactWorkspace) -> Result<(f64, f64)> {
        let max = self.params.max_roll;
        // F(φ) = h_L − h_R, strictly increasing in φ.
        let mut eval = |phi: f64| -> Result<(f64, f64, f64)> {
            let (ul, pl) = side_pose(LEFT, y, phi);
            let (ur, pr) = side_pose(RIGHT, y, phi);
            let l = self.sides[LEFT].minimum(ul, pl, &mut ws.gap)?;
            let r = self.sides[RIGHT].minimum(ur, pr, &mut ws.gap)?;
            Ok((l.h - r.h, l.dh_droll + r.dh_droll, l.h))
        };
        let (mut lo, mut hi) = (-max, max);
        let mut phi = roll_guess.clamp(lo, hi);
        for _ in 0..100 {
            let (f, df, h_left) = eval(phi)?;
            if f.abs() < self.params.tolerance {
                return Ok((phi, -h_left));
            }
            if f > 0.0 {
                hi = phi;
            } else {
                lo = phi;
            }
            let newton = phi - f / df;
            phi = if df > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if hi - lo < 1e-15 {
                let (_, _, h_left) = eval(phi)?;
                return Ok((phi, -h_left));
            }
        }
        Err(LocoError::Contact(format!(
            "the roll iteration did not converge at y = {y} m"
        )))
    }
}

/// Lateral position (side frame) and roll (side frame) of the wheelset for side `s`.
#[inline]
fn side_pose(s: usize, y: f64, roll: f64) -> (f64, f64) {
    if s == LEFT {
        (y, roll)
    } else {
        (-y, -roll)
    }
}
