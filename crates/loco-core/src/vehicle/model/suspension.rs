//! Every suspension element of the locomotive, placed between named attachment points, built from
//! the parameter file (SPEC §1).
//!
//! Primary (frame to each axle box): the rotary-arm rubber node (longitudinal and lateral
//! positioning), the axle-box coil spring (vertical) and a primary vertical damper.
//! Secondary (carbody to each frame): flexicoil springs (vertical, lateral and longitudinal shear,
//! bending), secondary lateral dampers, yaw dampers, secondary vertical dampers, a lateral bump stop
//! with free clearance and the traction rod. Drive: each frame-suspended motor hangs from its frame;
//! its gearbox bearings carry the hollow shaft, whose six-link coupling drives the wheelset.
//!
//! The hollow shaft follows its wheelset in x, z and spin (SPEC §1 gives it lateral, roll and yaw
//! relative coordinates only), so the radial compliance of the six-link coupling, which in the real
//! drive sits between hollow shaft and wheel, is placed between hollow shaft and motor here: the
//! motor still moves with the frame and not with the axle, as a frame-suspended drive does.

use crate::error::Result;
use crate::vehicle::model::bodies::{side_y, Body, Layout};
use crate::vehicle::model::elements::{Attachment, BumpStop, Bushing};
use crate::vehicle::model::layout::*;
use crate::vehicle::params::sections::VehicleSections;

mod drive;
mod secondary;

/// Name prefix of the gearbox bearings (one element per wheelset, `gearbox_bearings_wheelset1`,
/// ...): the stiffest springs, integrated exactly by [`crate::vehicle::time::stiff_linear_part`].
pub const GEARBOX_BEARINGS: &str = "gearbox_bearings";

/// Where a damper sits; the vehicle model chooses its law (the yaw damper can be YD1, YD2, any
/// Maxwell damper or the FSD damper).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DamperRole {
    PrimaryVertical,
    SecondaryLateral,
    Yaw,
    SecondaryVertical,
}

/// A damper's placement and its Maxwell parameters from the file.
#[derive(Debug, Clone, PartialEq)]
pub struct DamperPlacement {
    pub name: String,
    pub role: DamperRole,
    pub at: Attachment,
    /// Unit vector from the point on A to the point on B (the damper's axis).
    pub direction: [f64; 3],
    /// Damping, N·s/m.
    pub damping: f64,
    /// Series stiffness of the damper and its joints, N/m.
    pub series_stiffness: f64,
    /// Identical dampers working in parallel on this line (the file's `*_dampers_per_*`): they
    /// share one set of internal states and their force is this many times one damper's.
    pub count: f64,
}

/// All suspension elements.
#[derive(Debug, Clone, Default)]
pub struct Suspension {
    pub bushings: Vec<Bushing>,
    pub bump_stops: Vec<BumpStop>,
    pub dampers: Vec<DamperPlacement>,
}

pub(super) fn attach(bodies: &[Body], body_a: usize, body_b: usize, point: [f64; 3]) -> Attachment {
    attach2(bodies, body_a, point, body_b, point)
}

pub(super) fn attach2(
    bodies: &[Body],
    body_a: usize,
    pa: [f64; 3],
    body_b: usize,
    pb: [f64; 3],
) -> Attachment {
    let rel = |b: usize, p: [f64; 3]| {
        let c = bodies[b].position;
        [p[0] - c[0], p[1] - c[1], p[2] - c[2]]
    };
    Attachment {
        body_a,
        point_a: rel(body_a, pa),
        body_b,
        point_b: rel(body_b, pb),
    }
}

pub(super) fn bushing(name: String, at: Attachment, stiffness: [f64; 3]) -> Bushing {
    let turns = |body: usize| {
        if body_pitch_is_spin(body) {
            [1.0, 0.0, 1.0]
        } else {
            [1.0; 3]
        }
    };
    Bushing {
        name,
        turns_with: [turns(at.body_a), turns(at.body_b)],
        on_load_path: false,
        at,
        stiffness,
        damping: [0.0; 3],
        rotational_stiffness: [0.0; 3],
        rotational_damping: [0.0; 3],
    }
}

/// The two sides' names, left (+y) first.
pub(super) const SIDES: [&str; 2] = ["left", "right"];

/// Two springs in series, N/m.
pub(super) fn series(a: f64, b: f64) -> f64 {
    a * b / (a + b)
}

/// Builds every element.
pub fn build_suspension(
    p: &VehicleSections,
    layout: &Layout,
    bodies: &[Body],
) -> Result<Suspension> {
    let mut s = Suspension::default();
    add_primary(p, layout, bodies, &mut s);
    secondary::add(p, layout, bodies, &mut s)?;
    drive::add(p, layout, bodies, &mut s);
    Ok(s)
}

/// The primary suspension, per axle box: the rotary arm's node, the coil spring and the
/// vertical damper.
fn add_primary(p: &VehicleSections, layout: &Layout, bodies: &[Body], s: &mut Suspension) {
    let r0 = layout.wheel_radius;
    let box_semi = p.primary.spring_lateral_semi_spacing;
    let arm_length = p.rotary_arm.arm_length;
    let node_torsion = p.rotary_arm.node_stiffness_torsional;
    let node = [
        p.rotary_arm.node_stiffness_longitudinal,
        p.rotary_arm.node_stiffness_lateral,
        p.rotary_arm.node_stiffness_vertical,
    ];
    let spring_kz = p.primary.axle_box_spring_vertical_stiffness;
    let spring_shear = p.primary.axle_box_spring_shear_stiffness;
    let spring_height = p.primary.axle_box_spring_height;
    let pvd_semi = p.primary.vertical_damper_lateral_semi_spacing;
    let pvd_c = p.primary.vertical_damper_damping;
    let pvd_k = p.primary.vertical_damper_series_stiffness;
    let pvd_n = p.primary.vertical_dampers_per_axle_box;
    for w in 0..N_WHEELSETS {
        let b = bogie_of(w);
        let xw = layout.wheelset_x[w];
        let inward = -layout.outward_sign(w);
        for (side, side_name) in SIDES.iter().enumerate() {
            let arm = body_rotary_arm(w, side);
            let fr = body_frame(b);
            let y = side_y(side, box_semi);
            let tag = format!("wheelset{}_{side_name}", w + 1);
            let mut arm_node = bushing(
                format!("rotary_arm_node_{tag}"),
                attach(bodies, fr, arm, [xw + inward * arm_length, y, r0]),
                node,
            );
            arm_node.rotational_stiffness = [0.0, node_torsion, 0.0];
            s.bushings.push(arm_node);
            s.bushings.push(Bushing {
                on_load_path: true,
                ..bushing(
                    format!("axle_box_spring_{tag}"),
                    attach(bodies, fr, arm, [xw, y, spring_height]),
                    [spring_shear, spring_shear, spring_kz],
                )
            });
            let yd = side_y(side, pvd_semi);
            s.dampers.push(DamperPlacement {
                name: format!("primary_vertical_damper_{tag}"),
                role: DamperRole::PrimaryVertical,
                at: attach2(bodies, arm, [xw, yd, r0], fr, [xw, yd, r0 + 0.3]),
                direction: [0.0, 0.0, 1.0],
                damping: pvd_c,
                series_stiffness: pvd_k,
                count: pvd_n as f64,
            });
        }
    }
}
