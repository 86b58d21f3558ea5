//! The 25 rigid bodies: mass properties, nominal positions and motion maps, built from the
//! parameter file.
//!
//! Nominal positions are in the vehicle frame (x forward from the midpoint between the bogie
//! centres, y left, z up from rail-top level), in m, in the static equilibrium on the track.

use crate::error::{check_positive, Result};
use crate::vehicle::model::kinematics::{DenseMap, MotionMap};
use crate::vehicle::model::layout::*;
use crate::vehicle::params::sections::{TractionRodSection, VehicleSections};

/// One rigid body.
#[derive(Debug, Clone)]
pub struct Body {
    /// Name as in [`body_names`].
    pub name: String,
    /// Mass in kg.
    pub mass: f64,
    /// Principal moments of inertia about the centre of gravity (roll, pitch, yaw axes), kg·m².
    pub inertia: [f64; 3],
    /// Nominal centre of gravity, vehicle frame, m.
    pub position: [f64; 3],
    /// Absolute motion of the centre of gravity as a map of the generalized coordinates.
    pub map: MotionMap,
    /// Angular momentum about the body's y axis per unit running speed, kg·m (H = this × V):
    /// spinning wheelsets, hollow shafts and motor rotors; 0 for the others.
    pub spin_momentum_per_speed: f64,
}

/// Geometry shared by the builders of bodies and suspension elements.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    /// Nominal wheel rolling radius, m.
    pub wheel_radius: f64,
    /// Longitudinal positions of the bogie centres, m (bogie 1 ahead).
    pub bogie_x: [f64; 2],
    /// Longitudinal positions of the wheelsets, m (wheelset 1 ahead).
    pub wheelset_x: [f64; 4],
}

impl Layout {
    /// The layout of a vehicle of these sections.
    pub fn new(sections: &VehicleSections) -> Self {
        let half_bogie = sections.layout.bogie_half_distance;
        let half_base = sections.layout.half_wheelbase;
        let bogie_x = [half_bogie, -half_bogie];
        let wheelset_x = [
            half_bogie + half_base,
            half_bogie - half_base,
            -half_bogie + half_base,
            -half_bogie - half_base,
        ];
        Self {
            wheel_radius: sections.track.wheel_rolling_radius,
            bogie_x,
            wheelset_x,
        }
    }

    /// +1 when the bogie centre of wheelset `w` lies behind it (wheelset at the bogie's front
    /// end), −1 otherwise: the direction from the wheelset toward its bogie centre is `−sign`.
    pub fn outward_sign(&self, w: usize) -> f64 {
        (self.wheelset_x[w] - self.bogie_x[bogie_of(w)]).signum()
    }
}

/// Lateral position of side `s` (0 left, 1 right) for a semi-spacing `b`, m.
pub fn side_y(side: usize, semi_spacing: f64) -> f64 {
    if side == 0 {
        semi_spacing
    } else {
        -semi_spacing
    }
}

/// (name, mass, inertia, position, spin momentum per speed) while building.
type BodyRecord = (String, f64, [f64; 3], [f64; 3], f64);

/// Builds the 25 bodies in body-number order.
pub fn build_bodies(p: &VehicleSections, layout: &Layout) -> Result<Vec<Body>> {
    let r0 = layout.wheel_radius;
    let mut dense: Vec<DenseMap> = Vec::with_capacity(N_BODIES);
    let mut bodies: Vec<BodyRecord> = Vec::with_capacity(N_BODIES);
    let names = body_names();

    // Carbody.
    dense.push(DenseMap::free(CARBODY));
    bodies.push((
        names[BODY_CARBODY].clone(),
        p.carbody.mass,
        [
            p.carbody.roll_inertia,
            p.carbody.pitch_inertia,
            p.carbody.yaw_inertia,
        ],
        [0.0, 0.0, p.carbody.cog_height],
        0.0,
    ));
    // Bogie frames.
    for b in 0..N_BOGIES {
        dense.push(DenseMap::free(frame(b)));
        bodies.push((
            names[body_frame(b)].clone(),
            p.bogie_frame.mass,
            [
                p.bogie_frame.roll_inertia,
                p.bogie_frame.pitch_inertia,
                p.bogie_frame.yaw_inertia,
            ],
            [layout.bogie_x[b], 0.0, p.bogie_frame.cog_height],
            0.0,
        ));
    }
    // Wheelsets: the spin coordinate is the rotation beyond steady rolling at V / r0.
    let wheelset_spin = p.wheelset.spin_inertia;
    for w in 0..N_WHEELSETS {
        dense.push(DenseMap::free(wheelset(w)));
        bodies.push((
            names[body_wheelset(w)].clone(),
            p.wheelset.mass,
            [
                p.wheelset.roll_inertia,
                wheelset_spin,
                p.wheelset.yaw_inertia,
            ],
            [layout.wheelset_x[w], 0.0, r0],
            wheelset_spin / r0,
        ));
    }
    // Traction motors: frame-suspended, centre of gravity offset from the axle toward the bogie
    // centre; the rotor turns at gear_ratio times the wheel speed in the opposite sense (one
    // gear stage), which sets the sign of its gyroscopic moment.
    let motor_offset = p.traction_motor.cog_longitudinal_offset;
    let rotor = p.traction_motor.rotor_spin_inertia * p.traction_motor.gear_ratio;
    for w in 0..N_WHEELSETS {
        dense.push(DenseMap::free(motor(w)));
        bodies.push((
            names[body_motor(w)].clone(),
            p.traction_motor.mass,
            [
                p.traction_motor.roll_inertia,
                p.traction_motor.pitch_inertia,
                p.traction_motor.yaw_inertia,
            ],
            [
                layout.wheelset_x[w] - layout.outward_sign(w) * motor_offset,
                0.0,
                p.traction_motor.cog_height,
            ],
            -rotor / r0,
        ));
    }
    // Hollow shafts: concentric with the axle; x, z and spin follow the wheelset, lateral, roll
    // and yaw are their own (relative) coordinates.
    let hollow_spin = p.hollow_shaft.spin_inertia;
    for w in 0..N_WHEELSETS {
        let parent = dense[body_wheelset(w)].clone();
        let i = hollow_shaft(w);
        dense.push(DenseMap::attached(
            &parent,
            [0.0; 3],
            [0.0; 3],
            [true, true, true],
            &[(Y, i), (ROLL, i + 1), (YAW, i + 2)],
        ));
        bodies.push((
            names[body_hollow_shaft(w)].clone(),
            p.hollow_shaft.mass,
            [
                p.hollow_shaft.roll_inertia,
                hollow_spin,
                p.hollow_shaft.yaw_inertia,
            ],
            [layout.wheelset_x[w], 0.0, r0],
            hollow_spin / r0,
        ));
    }
    // Traction rods: pivot on a carbody bracket, pitch and yaw relative to the carbody; the rod
    // runs from the pivot toward the vehicle end to its bushing on the frame.
    let rod = RodGeometry::new(&p.traction_rod)?;
    let carbody_cg = bodies[BODY_CARBODY].3;
    for b in 0..N_BOGIES {
        let pivot = rod.carbody_end(layout, b);
        let frame_end = rod.frame_end(layout, b);
        let half = [
            0.5 * (frame_end[0] - pivot[0]),
            0.0,
            0.5 * (frame_end[2] - pivot[2]),
        ];
        let joint = [
            pivot[0] - carbody_cg[0],
            pivot[1] - carbody_cg[1],
            pivot[2] - carbody_cg[2],
        ];
        let parent = dense[BODY_CARBODY].clone();
        let i = traction_rod(b);
        dense.push(DenseMap::attached(
            &parent,
            joint,
            half,
            [true, true, true],
            &[(PITCH, i), (YAW, i + 1)],
        ));
        let pitch = p.traction_rod.pitch_inertia;
        let yaw = p.traction_rod.yaw_inertia;
        let mass = p.traction_rod.mass;
        // The file gives inertias about the pivot; move them to the centre of gravity.
        let arm2 = half[0] * half[0] + half[2] * half[2];
        bodies.push((
            names[body_traction_rod(b)].clone(),
            mass,
            [
                1e-3 * pitch.max(yaw),
                (pitch - mass * arm2).max(1e-3 * pitch),
                (yaw - mass * arm2).max(1e-3 * yaw),
            ],
            [pivot[0] + half[0], 0.0, pivot[2] + half[2]],
            0.0,
        ));
    }
    // Rotary arms with their axle boxes: ride on the axle at the axle box (roll and yaw follow
    // the wheelset, the axle box does not spin) and turn about the axle by their own coordinate.
    let box_semi = p.primary.spring_lateral_semi_spacing;
    let arm_pitch = p.rotary_arm.pitch_inertia;
    for w in 0..N_WHEELSETS {
        for side in 0..2 {
            let parent = dense[body_wheelset(w)].clone();
            let y = side_y(side, box_semi);
            dense.push(DenseMap::attached(
                &parent,
                [0.0, y, 0.0],
                [0.0; 3],
                [true, false, true],
                &[(PITCH, rotary_arm(w, side))],
            ));
            bodies.push((
                names[body_rotary_arm(w, side)].clone(),
                p.rotary_arm.mass,
                // Roll about the axle-box axis is small; yaw equals pitch for a slender arm in
                // the x-z plane turning about a transverse axis (engineering estimate).
                [0.1 * arm_pitch, arm_pitch, arm_pitch],
                [layout.wheelset_x[w], y, r0],
                0.0,
            ));
        }
    }

    Ok(dense
        .iter()
        .zip(bodies)
        .map(|(map, (name, mass, inertia, position, spin))| Body {
            name,
            mass,
            inertia,
            position,
            map: map.compress(),
            spin_momentum_per_speed: spin,
        })
        .collect())
}

/// Where the traction rods sit: ends on the centre line, offsets along x from the bogie centre
/// (positive toward the locomotive's end), heights above rail top; all m.
#[derive(Debug, Clone, Copy)]
pub struct RodGeometry {
    pub carbody_end_offset: f64,
    pub frame_end_offset: f64,
    pub carbody_end_height: f64,
    pub frame_end_height: f64,
}

impl RodGeometry {
    /// The rod geometry of a section; the two ends must not coincide.
    pub fn new(rod: &TractionRodSection) -> Result<Self> {
        let g = Self {
            carbody_end_offset: rod.carbody_end_longitudinal_offset,
            frame_end_offset: rod.frame_end_longitudinal_offset,
            carbody_end_height: rod.carbody_end_height,
            frame_end_height: rod.frame_end_height,
        };
        let length = (g.frame_end_offset - g.carbody_end_offset)
            .hypot(g.frame_end_height - g.carbody_end_height);
        check_positive(
            "traction_rod.frame_end_longitudinal_offset (rod length)",
            length,
        )?;
        Ok(g)
    }

    /// Carbody-side pivot of rod `b`, vehicle frame, m.
    pub fn carbody_end(&self, layout: &Layout, b: usize) -> [f64; 3] {
        let out = layout.bogie_x[b].signum();
        [
            layout.bogie_x[b] + out * self.carbody_end_offset,
            0.0,
            self.carbody_end_height,
        ]
    }

    /// Frame-side end of rod `b`, vehicle frame, m.
    pub fn frame_end(&self, layout: &Layout, b: usize) -> [f64; 3] {
        let out = layout.bogie_x[b].signum();
        [
            layout.bogie_x[b] + out * self.frame_end_offset,
            0.0,
            self.frame_end_height,
        ]
    }
}
