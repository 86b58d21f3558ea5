//! What an accelerometer fixed to a body reads: the specific force (acceleration less gravity)
//! at a point, in the body's own axes.
//!
//! The model's coordinates are relative to each body's track frame (on a designed curve, the
//! frame at the body's distance, rolled by the cant; on straight track, the fixed ground frame),
//! so the acceleration channels of kind `acceleration` are the point's acceleration relative to
//! that frame: in a steady curve they read 0. An accelerometer reads instead
//!
//! f = R_bᵀ (ä_rel + f_frame),
//!
//! where `ä_rel` is the point's acceleration relative to its frame (the `acceleration` channel's
//! vector), `f_frame` what an accelerometer fixed to the frame reads — laterally
//! g sin θ + V²κ cos θ, vertically g cos θ − V²κ sin θ, θ the frame's roll on the cant (negative in
//! a left curve, whose outer right rail is raised; κ > 0 there)
//! ([`crate::vehicle::curving::track_frame::CurvedTrack::frame_specific_force`]; (0, 0, g) on straight track) — and
//! `R_b` the body's small rotation (roll φ, pitch χ, yaw ψ) against its frame, taken to first
//! order: `R_bᵀ v = v − θ × v`. Laterally that is f_y = (ä_rel,y + f_frame,y) + φ f_z − ψ f_x:
//! the body's roll adds g φ, the share of gravity a rolled accelerometer senses. The Coriolis
//! term of the frame's yaw rate (V κ times the relative velocity, < 10⁻³ m/s² here) is left out.

use crate::vehicle::system::simulation::VehicleSystem;

/// What a body's accelerometers share at one instant: the specific force of its track frame
/// (frame axes) and the body's small rotation against that frame. Formed once per body and
/// sample, then [`Self::reading`] per measuring point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyAxes {
    /// What an accelerometer fixed to the body's track frame reads, m/s² (frame axes).
    frame: [f64; 3],
    /// The body's roll, pitch and yaw against its track frame, rad.
    theta: [f64; 3],
}

impl BodyAxes {
    /// The axes of `body` in the state `y` (after the evaluation the sample is taken from).
    pub fn of(system: &VehicleSystem, y: &[f64], body: usize) -> Self {
        let s = &system.structure;
        let frame = match &system.curve {
            Some(curve) => curve.frame_specific_force(&system.frame_work, body),
            None => [0.0, 0.0, s.gravity],
        };
        let motion = s.bodies[body].map.apply(y);
        Self {
            frame,
            theta: [motion[3], motion[4], motion[5]],
        }
    }

    /// The specific force (m/s², body axes) an accelerometer reads at a point whose
    /// acceleration `relative` to the track frame (m/s², frame axes) is given.
    pub fn reading(&self, relative: [f64; 3]) -> [f64; 3] {
        let f = [
            relative[0] + self.frame[0],
            relative[1] + self.frame[1],
            relative[2] + self.frame[2],
        ];
        let t = self.theta;
        let turn = [
            t[1] * f[2] - t[2] * f[1],
            t[2] * f[0] - t[0] * f[2],
            t[0] * f[1] - t[1] * f[0],
        ];
        [f[0] - turn[0], f[1] - turn[1], f[2] - turn[2]]
    }
}
