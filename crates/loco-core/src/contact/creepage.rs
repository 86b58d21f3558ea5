//! Creepages: the rigid slip between wheel and rail at a contact, divided by the rolling speed.
//!
//! General definition (Kalker; Shabana, Zaazaa & Sugiyama, *Railroad Vehicle Dynamics*, 2008,
//! §5): with `v_c = v + ω × r − v_rail` the velocity (m/s) of the wheel material at the contact
//! point relative to the rail material there (`v`, `ω`: velocity of the wheel body's reference
//! point and its angular velocity, rad/s; `r`: contact point relative to that reference point),
//! and the contact frame `(t₁, t₂, n)` (t₁ rolling direction, t₂ lateral, both in the contact
//! plane, n the normal pointing from the rail into the wheel):
//!
//! ```text
//! ξ = v_c · t₁ / V       longitudinal creepage (–)
//! η = v_c · t₂ / V       lateral creepage (–)
//! φ = ω · n / V          spin creepage (1/m); the rail does not rotate on straight track
//! ```
//!
//! with V > 0 the forward speed (m/s). Frames follow docs/CONVENTIONS.md (x forward, y left, z up).
//! The forces of [`super::kalker`] and [`super::fastsim`] oppose these creepages: a driven wheel
//! (surface moving backward relative to the rail, ξ < 0) receives a forward Fx.
//!
//! For a wheelset running at speed V with yaw ψ, yaw rate ψ̇, lateral velocity ẏ, roll rate ϕ̇ and
//! spin Ω = V/r₀ about its axle, a contact on side s (+1 left, −1 right) at lateral offset l from
//! the wheelset centre, rolling radius r and contact angle γ, the general definition reduces to
//! the classical linearised formulae (Garg & Dukkipati, *Dynamics of Railway Vehicle Systems*,
//! 1984, ch. 5, with y to the left):
//!
//! ```text
//! ξ ≈ 1 − r/r₀ − l ψ̇ / V                (rolling radius difference, yaw rate)
//! η ≈ ((ẏ + r ϕ̇)/V − ψ) cos γ            (lateral velocity, roll rate, yaw angle)
//! φ ≈ (ψ̇ cos γ)/V − s sin γ / r₀         (yaw rate, contact-angle spin)
//! ```
//!
//! [`WheelsetMotion::creepages`] evaluates the general definition (no small-angle approximation
//! in ψ and γ) so the vehicle model and the tests share one code path.

use super::kalker::Creepages;
use crate::error::{check_finite, check_positive, Result};

/// A 3-vector in the track frame (x forward, y left, z up).
pub type Vec3 = [f64; 3];

/// Scalar product of two track-frame vectors.
#[inline]
pub fn dot(a: &Vec3, b: &Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &Vec3, b: &Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Orthonormal contact frame, unit vectors in the track frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFrame {
    /// Rolling direction t₁ (in the contact plane).
    pub longitudinal: Vec3,
    /// Lateral direction t₂ = n × t₁ (in the contact plane).
    pub lateral: Vec3,
    /// Normal n, from the rail into the wheel.
    pub normal: Vec3,
}

/// Which wheel of the wheelset.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The wheel at +y.
    Left,
    /// The wheel at −y.
    Right,
}

impl Side {
    /// +1 for the left wheel, −1 for the right one.
    pub fn sign(self) -> f64 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }
}

impl ContactFrame {
    /// Frame of a contact on `side` with contact angle `contact_angle` (rad, measured in the track
    /// frame, i.e. including the wheelset roll; positive when the normal force on the wheel has a
    /// lateral component toward the track centre) on a wheel yawed by `yaw` (rad): the track axes
    /// rotated by the contact angle about x (toward the centre) and then by the yaw about z.
    pub fn new(side: Side, contact_angle: f64, yaw: f64) -> Self {
        Self::from_sin_cos(side, contact_angle.sin_cos(), yaw.sin_cos())
    }

    /// As [`Self::new`] from the sines and cosines of the contact angle and the yaw (the vehicle
    /// has them at hand and saves the trigonometry).
    #[inline]
    pub fn from_sin_cos(side: Side, (sg, cg): (f64, f64), (sp, cp): (f64, f64)) -> Self {
        let s = side.sign();
        Self {
            longitudinal: [cp, sp, 0.0],
            lateral: [-sp * cg, cp * cg, s * sg],
            normal: [s * sg * sp, -s * sg * cp, cg],
        }
    }
}

/// Rigid-body velocity of the wheel.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyVelocity {
    /// Velocity of the body's reference point (m/s).
    pub velocity: Vec3,
    /// Angular velocity (rad/s).
    pub angular_velocity: Vec3,
}

/// Creepages from the wheel's rigid-body velocity, the contact point `contact_offset` (m, relative
/// to the body's reference point), the velocity of the rail material `rail_velocity` (m/s; zero
/// on a fixed rail, `V·d(irregularity)/ds` on an irregular one), the contact frame and the speed
/// `speed` V (m/s, > 0; not checked here).
#[inline]
pub fn creepages(
    body: &BodyVelocity,
    contact_offset: &Vec3,
    rail_velocity: &Vec3,
    frame: &ContactFrame,
    speed: f64,
) -> Creepages {
    let slip = slip_velocity(body, contact_offset, rail_velocity);
    creepages_of_slip(&slip, &body.angular_velocity, frame, speed)
}

/// Velocity `v_c = v + ω × r − v_rail` (m/s) of the wheel material at the contact point relative
/// to the rail material there; its part along the normal is the rate at which the bodies separate.
#[inline]
pub fn slip_velocity(body: &BodyVelocity, contact_offset: &Vec3, rail_velocity: &Vec3) -> Vec3 {
    let spin_velocity = cross(&body.angular_velocity, contact_offset);
    [
        body.velocity[0] + spin_velocity[0] - rail_velocity[0],
        body.velocity[1] + spin_velocity[1] - rail_velocity[1],
        body.velocity[2] + spin_velocity[2] - rail_velocity[2],
    ]
}

/// Creepages from the slip velocity `slip` (m/s) and the wheel's angular velocity `angular`
/// (rad/s) in the contact frame, at speed `speed` V (m/s, > 0).
#[inline]
pub fn creepages_of_slip(
    slip: &Vec3,
    angular: &Vec3,
    frame: &ContactFrame,
    speed: f64,
) -> Creepages {
    let inv_v = 1.0 / speed;
    Creepages {
        longitudinal: dot(slip, &frame.longitudinal) * inv_v,
        lateral: dot(slip, &frame.lateral) * inv_v,
        spin: dot(angular, &frame.normal) * inv_v,
    }
}

/// Motion of a wheelset on straight track, in the track frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelsetMotion {
    /// Forward speed V (m/s, > 0).
    pub speed: f64,
    /// Lateral velocity ẏ of the wheelset centre (m/s).
    pub lateral_velocity: f64,
    /// Vertical velocity ż of the wheelset centre (m/s).
    pub vertical_velocity: f64,
    /// Yaw angle ψ (rad).
    pub yaw: f64,
    /// Yaw rate ψ̇ (rad/s).
    pub yaw_rate: f64,
    /// Roll rate ϕ̇ (rad/s).
    pub roll_rate: f64,
    /// Spin about the axle Ω (rad/s; V/r₀ in pure rolling, positive when rolling forward).
    pub spin_rate: f64,
}

/// Where a wheel touches the rail, relative to the wheelset centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelContact {
    /// Which wheel.
    pub side: Side,
    /// Lateral position of the contact point along the axle (m, +left).
    pub lateral_position: f64,
    /// Rolling radius r at the contact point (m): the contact is r below the axle.
    pub rolling_radius: f64,
    /// Contact angle in the track frame (rad), see [`ContactFrame::new`].
    pub contact_angle: f64,
}

impl WheelsetMotion {
    /// Creepages at `contact` on a fixed rail, by the general definition.
    pub fn creepages(&self, contact: &WheelContact) -> Creepages {
        let (sp, cp) = self.yaw.sin_cos();
        // Axle direction (yawed y axis); the spin Ω acts about it.
        let axle = [-sp, cp, 0.0];
        let body = BodyVelocity {
            velocity: [self.speed, self.lateral_velocity, self.vertical_velocity],
            angular_velocity: [
                self.roll_rate * cp + self.spin_rate * axle[0],
                self.roll_rate * sp + self.spin_rate * axle[1],
                self.yaw_rate,
            ],
        };
        let l = contact.lateral_position;
        let offset = [l * axle[0], l * axle[1], -contact.rolling_radius];
        let frame = ContactFrame::new(contact.side, contact.contact_angle, self.yaw);
        creepages(&body, &offset, &[0.0; 3], &frame, self.speed)
    }

    /// As [`Self::creepages`] with the inputs checked (the Python entry point).
    pub fn creepages_checked(&self, contact: &WheelContact) -> Result<Creepages> {
        check_positive("speed", self.speed)?;
        check_finite("lateral_velocity", self.lateral_velocity)?;
        check_finite("vertical_velocity", self.vertical_velocity)?;
        check_finite("yaw", self.yaw)?;
        check_finite("yaw_rate", self.yaw_rate)?;
        check_finite("roll_rate", self.roll_rate)?;
        check_finite("spin_rate", self.spin_rate)?;
        check_finite("lateral_position", contact.lateral_position)?;
        check_positive("rolling_radius", contact.rolling_radius)?;
        check_finite("contact_angle", contact.contact_angle)?;
        Ok(self.creepages(contact))
    }
}

/// Longitudinal position (m, + forward) of the contact point of a yawed wheel relative to the
/// vertical plane through its axle, to first order in the yaw ψ (rad):
/// `x = s·r·tan(γ − s·ϕ)·ψ`, with s the side's sign, r the rolling radius (m), γ the contact angle
/// in the track frame and ϕ the wheelset roll (rad; γ − s·ϕ is the profile's slope in the
/// wheelset frame). The 2-D contact geometry puts the point under the axle (x = 0); on the tread
/// the lead is a fraction of a mm, but a flange contact (γ ≈ 1.2 rad) yawed by 15 mrad leads by
/// about 17 mm. There the wheel material moves vertically at Ω·x, which the steep contact plane
/// turns into lateral creepage (Manchester benchmark A-2.2, flange cases: 0.04 against 0.006
/// without the lead; `tests/verification/manchester_normal_force.rs`). The vehicle model places its contact
/// points with it (`vehicle::rail_contact::wheel_rail`); [`WheelsetMotion::creepages`] does not.
pub fn contact_lead(
    side: Side,
    rolling_radius: f64,
    contact_angle: f64,
    roll: f64,
    yaw: f64,
) -> f64 {
    let s = side.sign();
    s * rolling_radius * (contact_angle - s * roll).tan() * yaw
}

/// [`contact_lead`] from the sine and cosine of the contact angle, for a small roll (|ϕ| ≲ 0.05
/// rad: the roll's sine and cosine by their series, below 1e-8 relative).
#[inline]
pub fn contact_lead_sin_cos(
    side: Side,
    rolling_radius: f64,
    (sg, cg): (f64, f64),
    roll: f64,
    yaw: f64,
) -> f64 {
    let s = side.sign();
    let r2 = roll * roll;
    let (sr, cr) = (s * roll * (1.0 - r2 / 6.0), 1.0 - r2 * (0.5 - r2 / 24.0));
    // tan(γ − s·ϕ) = sin(γ − sϕ) / cos(γ − sϕ).
    s * rolling_radius * (sg * cr - cg * sr) / (cg * cr + sg * sr) * yaw
}

#[cfg(test)]
mod tests {
    use super::*;

    const V: f64 = 30.0;
    const R0: f64 = 0.625;

    fn rolling() -> WheelsetMotion {
        WheelsetMotion {
            speed: V,
            spin_rate: V / R0,
            ..WheelsetMotion::default()
        }
    }

    fn left(r: f64, gamma: f64) -> WheelContact {
        WheelContact {
            side: Side::Left,
            lateral_position: 0.7465,
            rolling_radius: r,
            contact_angle: gamma,
        }
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn pure_rolling_has_no_creepage() {
        let c = rolling().creepages(&left(R0, 0.0));
        assert!(close(c.longitudinal, 0.0) && close(c.lateral, 0.0) && close(c.spin, 0.0));
    }

    #[test]
    fn lateral_velocity_gives_lateral_creepage() {
        let m = WheelsetMotion {
            lateral_velocity: 0.3,
            ..rolling()
        };
        let c = m.creepages(&left(R0, 0.0));
        assert!(close(c.lateral, 0.3 / V) && close(c.longitudinal, 0.0));
        let gamma: f64 = 0.05;
        let c = m.creepages(&left(R0, gamma));
        assert!(close(c.lateral, 0.3 / V * gamma.cos()));
    }

    #[test]
    fn yaw_angle_gives_minus_sin_yaw() {
        let psi: f64 = 0.004;
        let m = WheelsetMotion {
            yaw: psi,
            ..rolling()
        };
        let c = m.creepages(&left(R0, 0.0));
        assert!(close(c.lateral, -psi.sin()));
        // The wheel heads at ψ to the track: only V cos ψ of the speed is rolled off (2nd order).
        assert!(close(c.longitudinal, psi.cos() - 1.0));
    }

    #[test]
    fn rolling_radius_difference_and_yaw_rate() {
        let dr = 0.002;
        let c_l = rolling().creepages(&left(R0 + dr, 0.0));
        assert!(close(c_l.longitudinal, -dr / R0));
        let right = WheelContact {
            side: Side::Right,
            lateral_position: -0.7465,
            ..left(R0 - dr, 0.0)
        };
        assert!(close(rolling().creepages(&right).longitudinal, dr / R0));
        // Yaw rate: the left contact moves back, the right one forward.
        let m = WheelsetMotion {
            yaw_rate: 0.1,
            ..rolling()
        };
        let c = m.creepages(&left(R0, 0.0));
        assert!(close(c.longitudinal, -0.7465 * 0.1 / V));
        assert!(close(c.spin, 0.1 / V));
    }

    #[test]
    fn contact_angle_spin_signs() {
        let gamma: f64 = 0.3;
        let c_l = rolling().creepages(&left(R0, gamma));
        assert!(close(c_l.spin, -gamma.sin() / R0));
        let right = WheelContact {
            side: Side::Right,
            lateral_position: -0.7465,
            ..left(R0, gamma)
        };
        assert!(close(rolling().creepages(&right).spin, gamma.sin() / R0));
    }

    #[test]
    fn lead_from_sine_and_cosine_is_the_lead() {
        for (side, gamma, roll) in [(Side::Left, 1.2, 0.004), (Side::Right, 0.05, -0.01)] {
            let exact = contact_lead(side, 0.63, gamma, roll, 0.015);
            let fast = contact_lead_sin_cos(side, 0.63, gamma.sin_cos(), roll, 0.015);
            assert!(
                (fast - exact).abs() < 1e-8 * exact.abs(),
                "{fast} vs {exact}"
            );
        }
    }

    #[test]
    fn frame_is_orthonormal_and_right_handed() {
        let f = ContactFrame::new(Side::Right, 0.4, -0.1);
        for v in [f.longitudinal, f.lateral, f.normal] {
            assert!(close(dot(&v, &v), 1.0));
        }
        assert!(close(dot(&f.longitudinal, &f.normal), 0.0));
        let t2 = cross(&f.normal, &f.longitudinal);
        assert!((0..3).all(|i| close(t2[i], f.lateral[i])));
        let bad = WheelsetMotion {
            speed: 0.0,
            ..rolling()
        };
        assert!(bad.creepages_checked(&left(R0, 0.0)).is_err());
    }
}
