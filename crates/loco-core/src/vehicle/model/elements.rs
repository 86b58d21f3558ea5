//! Linear elastic suspension elements between two bodies and the lateral bump stop.
//!
//! Each element joins a point on body A to a point on body B (points in m from each body's centre
//! of gravity, vehicle axes). Forces are in N, moments in N·m, stiffnesses in N/m and N·m/rad,
//! damping in N·s/m. Springs are unstressed in the nominal configuration; runs start from the
//! static equilibrium under gravity, where they carry the vehicle's weight. The moment of every
//! force uses the rotated lever arm `r + θ × r`, which gives the geometric (gravity) stiffness of
//! loaded springs, e.g. the `m·g·h` roll moment of a carbody whose centre of gravity sits above
//! its springs.

use crate::vehicle::model::kinematics::{add, cross, point_motion, sub};
use crate::vehicle::model::layout::N_BODIES;

/// Motion (m, rad) and velocity (m/s, rad/s) of every body's centre of gravity.
#[derive(Debug, Clone)]
pub struct BodyStates {
    pub position: [[f64; 6]; N_BODIES],
    pub velocity: [[f64; 6]; N_BODIES],
}

impl Default for BodyStates {
    fn default() -> Self {
        Self {
            position: [[0.0; 6]; N_BODIES],
            velocity: [[0.0; 6]; N_BODIES],
        }
    }
}

/// Forces and moments on every body's centre of gravity (N, N·m).
pub type Wrenches = [[f64; 6]; N_BODIES];

/// Adds force `f` (N) acting at `r` (m from the centre of gravity) of `body` with motion `u`.
#[inline]
pub fn add_force(wrenches: &mut Wrenches, body: usize, u: &[f64; 6], r: [f64; 3], f: [f64; 3]) {
    add_force_at(wrenches, body, add(r, cross([u[3], u[4], u[5]], r)), f);
}

/// Adds force `f` (N) acting at the lever arm `arm` (m from the centre of gravity, track axes,
/// already turned with the body) of `body`.
#[inline]
pub fn add_force_at(wrenches: &mut Wrenches, body: usize, arm: [f64; 3], f: [f64; 3]) {
    let m = cross(arm, f);
    let w = &mut wrenches[body];
    w[0] += f[0];
    w[1] += f[1];
    w[2] += f[2];
    w[3] += m[0];
    w[4] += m[1];
    w[5] += m[2];
}

/// Two attachment points: which bodies and where.
#[derive(Debug, Clone, PartialEq)]
pub struct Attachment {
    pub body_a: usize,
    /// Point on A, m from A's centre of gravity.
    pub point_a: [f64; 3],
    pub body_b: usize,
    /// Point on B, m from B's centre of gravity.
    pub point_b: [f64; 3],
}

impl Attachment {
    /// Displacement and velocity of the point on B relative to the point on A (m, m/s).
    #[inline]
    pub fn relative_motion(&self, s: &BodyStates) -> ([f64; 3], [f64; 3]) {
        let da = point_motion(&s.position[self.body_a], self.point_a);
        let db = point_motion(&s.position[self.body_b], self.point_b);
        let va = point_motion(&s.velocity[self.body_a], self.point_a);
        let vb = point_motion(&s.velocity[self.body_b], self.point_b);
        (sub(db, da), sub(vb, va))
    }

    /// Displacement and velocity of the point on B relative to the point on A (m, m/s), with
    /// both points' rotated lever arms (m) for [`Self::apply_pair_at`]: the rotation `θ × r`
    /// is the same in the displacement and in the arm, so it is formed once.
    #[inline]
    fn motion_and_arms(&self, s: &BodyStates) -> ([f64; 3], [f64; 3], [[f64; 3]; 2]) {
        let (pa, pb) = (&s.position[self.body_a], &s.position[self.body_b]);
        let turn_a = cross([pa[3], pa[4], pa[5]], self.point_a);
        let turn_b = cross([pb[3], pb[4], pb[5]], self.point_b);
        let d = sub(
            add([pb[0], pb[1], pb[2]], turn_b),
            add([pa[0], pa[1], pa[2]], turn_a),
        );
        let va = point_motion(&s.velocity[self.body_a], self.point_a);
        let vb = point_motion(&s.velocity[self.body_b], self.point_b);
        (
            d,
            sub(vb, va),
            [add(self.point_a, turn_a), add(self.point_b, turn_b)],
        )
    }

    /// Applies `f` (N) on B and `−f` on A at the arms of [`Self::motion_and_arms`].
    // Always inlined: the damper loop calls it for every damper and evaluation, and the plain
    // hint was not taken (a call and the arms passed through memory each time).
    #[inline(always)]
    pub(crate) fn apply_pair_at(&self, arms: &[[f64; 3]; 2], f: [f64; 3], wrenches: &mut Wrenches) {
        add_force_at(wrenches, self.body_b, arms[1], f);
        add_force_at(wrenches, self.body_a, arms[0], [-f[0], -f[1], -f[2]]);
    }

    /// Applies `f` (N) on B and `−f` on A.
    #[inline]
    pub fn apply_pair(&self, s: &BodyStates, f: [f64; 3], wrenches: &mut Wrenches) {
        add_force(
            wrenches,
            self.body_b,
            &s.position[self.body_b],
            self.point_b,
            f,
        );
        add_force(
            wrenches,
            self.body_a,
            &s.position[self.body_a],
            self.point_a,
            [-f[0], -f[1], -f[2]],
        );
    }
}

/// A three-axis spring-damper with rotational stiffness (rubber bushing, coil spring, flexicoil,
/// coupling), stiffness and damping along the element's axes.
///
/// The element's axes turn with the mean rotation θ_m of its two ends (corotational): the force
/// is `f = R(θ_m)·(−K Rᵀd − C Rᵀv)` and each end gets the moment `−½ d × f`, the gradient of the
/// spring energy `½ (Rᵀd)ᵀ K (Rᵀd)` with respect to the ends' rotations. For the loaded springs
/// this is what makes a preload turn with the suspension: a carbody rolled with its bogies on a
/// cross level (or a cant) is pushed downhill by its weight times the roll and sags laterally,
/// and the element's forces exert no net moment on the vehicle (the `P·Δ` couple of a laterally
/// deflected loaded spring is taken by its ends). With a fixed-axis spring both were missing:
/// preloads stayed vertical in the track frame whatever the vehicle's roll.
///
/// Only the elements on the vehicle's load path turn ([`Bushing::on_load_path`]: axle-box
/// springs, flexicoils, motor mounts, gearbox bearings, 5.7–73 kN each in the static
/// equilibrium). The joints and couplings off it (rotary-arm nodes 0.2 kN, traction rods 0.4 kN,
/// six-link couplings 0) keep fixed axes: their corotational terms, preload times rotation, stay
/// below 1 N at the vehicle's rotations (< 1e-3 rad), and the time loop spares their cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Bushing {
    pub name: String,
    pub at: Attachment,
    /// Translational stiffness along x, y, z, N/m.
    pub stiffness: [f64; 3],
    /// Translational damping along x, y, z, N·s/m (rubber hysteresis as viscous; 0 for coils).
    pub damping: [f64; 3],
    /// Rotational stiffness about x, y, z for the relative rotation of B to A, N·m/rad.
    pub rotational_stiffness: [f64; 3],
    /// Rotational damping about x, y, z for the relative angular velocity of B to A,
    /// N·m·s/rad (0 but for the gearbox bearings' tilt).
    pub rotational_damping: [f64; 3],
    /// Which rotations of A and B turn the element's axes (1) and which do not (0): a
    /// wheelset's or hollow shaft's pitch coordinate is its spin, which turns no axle box.
    pub turns_with: [[f64; 3]; 2],
    /// Whether the element carries the vehicle's weight, so that its axes turn with its ends.
    pub on_load_path: bool,
}

impl Bushing {
    /// Adds the element's forces; returns the force on B (N).
    #[inline]
    pub fn apply(&self, s: &BodyStates, wrenches: &mut Wrenches) -> [f64; 3] {
        let (d, v, arms) = self.at.motion_and_arms(s);
        let (ua, ub) = (&s.position[self.at.body_a], &s.position[self.at.body_b]);
        let (wa, wb) = (&s.velocity[self.at.body_a], &s.velocity[self.at.body_b]);
        // Elastic and viscous moment about axis k from the relative rotation and its rate.
        let moment = |k: usize| {
            -self.rotational_stiffness[k] * (ub[3 + k] - ua[3 + k])
                - self.rotational_damping[k] * (wb[3 + k] - wa[3 + k])
        };
        if !self.on_load_path {
            let f: [f64; 3] =
                std::array::from_fn(|k| -self.stiffness[k] * d[k] - self.damping[k] * v[k]);
            self.at.apply_pair_at(&arms, f, wrenches);
            if self
                .rotational_stiffness
                .iter()
                .chain(&self.rotational_damping)
                .any(|k| *k != 0.0)
            {
                for k in 0..3 {
                    let m = moment(k);
                    wrenches[self.at.body_b][3 + k] += m;
                    wrenches[self.at.body_a][3 + k] -= m;
                }
            }
            return f;
        }
        let [ma, mb] = &self.turns_with;
        let theta: [f64; 3] =
            std::array::from_fn(|k| 0.5 * (ua[3 + k] * ma[k] + ub[3 + k] * mb[k]));
        let d_local = sub(d, cross(theta, d));
        // The velocity's own turning (θ × v) is a product of two small motions: left out.
        let f_local: [f64; 3] =
            std::array::from_fn(|k| -self.stiffness[k] * d_local[k] - self.damping[k] * v[k]);
        let f = add(f_local, cross(theta, f_local));
        self.at.apply_pair_at(&arms, f, wrenches);
        let couple = cross(d, f);
        for k in 0..3 {
            let m = moment(k);
            wrenches[self.at.body_b][3 + k] += m - 0.5 * couple[k];
            wrenches[self.at.body_a][3 + k] -= m + 0.5 * couple[k];
        }
        f
    }
}

/// A lateral bump stop: free over ±`clearance`, then a piecewise-linear progressive rubber
/// characteristic (`stiffness` up to `hardening_deflection`, `hardening_stiffness` beyond), along y.
#[derive(Debug, Clone, PartialEq)]
pub struct BumpStop {
    pub name: String,
    pub at: Attachment,
    /// Free lateral clearance, m.
    pub clearance: f64,
    /// Contact stiffness once the clearance is used up, N/m.
    pub stiffness: f64,
    /// Rubber compression beyond which the stop stiffens, m.
    pub hardening_deflection: f64,
    /// Stiffness beyond `hardening_deflection`, N/m.
    pub hardening_stiffness: f64,
}

impl BumpStop {
    /// Adds the stop's force; returns the lateral force on B (N).
    #[inline]
    pub fn apply(&self, s: &BodyStates, wrenches: &mut Wrenches) -> f64 {
        let (d, _) = self.at.relative_motion(s);
        let excess = d[1].abs() - self.clearance;
        if excess <= 0.0 {
            return 0.0;
        }
        let soft = excess.min(self.hardening_deflection);
        let hard = (excess - self.hardening_deflection).max(0.0);
        let fy = -(self.stiffness * soft + self.hardening_stiffness * hard) * d[1].signum();
        self.at.apply_pair(s, [0.0, fy, 0.0], wrenches);
        fy
    }
}
