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

use crate::error::{check_non_negative, check_positive, Result};
use crate::vehicle::model::bodies::{side_y, Body, Layout, RodGeometry};
use crate::vehicle::model::elements::{Attachment, BumpStop, Bushing};
use crate::vehicle::model::layout::*;
use crate::vehicle::params::parameters::ParameterSet;

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

struct Reader<'a>(&'a ParameterSet);

impl Reader<'_> {
    fn pos(&self, key: &str) -> Result<f64> {
        check_positive(key, self.0.get(key)?)
    }
    fn non_neg(&self, key: &str) -> Result<f64> {
        check_non_negative(key, self.0.get(key)?)
    }
    /// A count of elements; the parameter set has checked it is a whole number in `0..=16`.
    fn count(&self, key: &str) -> Result<usize> {
        Ok(self.non_neg(key)? as usize)
    }
    /// A count of elements the vehicle cannot do without (springs, mounts, bearings): at least 1.
    fn count_pos(&self, key: &str) -> Result<usize> {
        Ok(self.pos(key)? as usize)
    }
}

fn attach(bodies: &[Body], body_a: usize, body_b: usize, point: [f64; 3]) -> Attachment {
    attach2(bodies, body_a, point, body_b, point)
}

fn attach2(
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

fn bushing(name: String, at: Attachment, stiffness: [f64; 3]) -> Bushing {
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

/// Builds every element.
pub fn build_suspension(p: &ParameterSet, layout: &Layout, bodies: &[Body]) -> Result<Suspension> {
    let r = Reader(p);
    let r0 = layout.wheel_radius;
    let mut s = Suspension::default();
    let sides = ["left", "right"];

    // Primary suspension, per axle box.
    let box_semi = r.pos("primary.spring_lateral_semi_spacing")?;
    let arm_length = r.pos("rotary_arm.arm_length")?;
    let node_torsion = r.non_neg("rotary_arm.node_stiffness_torsional")?;
    let node = [
        r.pos("rotary_arm.node_stiffness_longitudinal")?,
        r.pos("rotary_arm.node_stiffness_lateral")?,
        r.pos("rotary_arm.node_stiffness_vertical")?,
    ];
    let spring_kz = r.pos("primary.axle_box_spring_vertical_stiffness")?;
    let spring_shear = r.non_neg("primary.axle_box_spring_shear_stiffness")?;
    let spring_height = r.pos("primary.axle_box_spring_height")?;
    let pvd_semi = r.pos("primary.vertical_damper_lateral_semi_spacing")?;
    let pvd_c = r.pos("primary.vertical_damper_damping")?;
    let pvd_k = r.pos("primary.vertical_damper_series_stiffness")?;
    let pvd_n = r.non_neg("primary.vertical_dampers_per_axle_box")?;
    for w in 0..N_WHEELSETS {
        let b = bogie_of(w);
        let xw = layout.wheelset_x[w];
        let inward = -layout.outward_sign(w);
        for (side, side_name) in sides.iter().enumerate() {
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
                count: pvd_n,
            });
        }
    }

    // Secondary suspension, per bogie.
    let n_flexicoil = r.count_pos("secondary.flexicoil_springs_per_side")?;
    let fc = [
        r.pos("secondary.flexicoil_longitudinal_stiffness")?,
        r.pos("secondary.flexicoil_lateral_stiffness")?,
        r.pos("secondary.flexicoil_vertical_stiffness")?,
    ];
    let fc_bending = r.non_neg("secondary.flexicoil_bending_stiffness")?;
    let fc_semi = r.pos("secondary.flexicoil_lateral_semi_spacing")?;
    let fc_spacing = r.non_neg("secondary.flexicoil_longitudinal_spacing")?;
    let fc_bottom = r.pos("secondary.flexicoil_bottom_height")?;
    let fc_top = r.pos("secondary.flexicoil_top_height")?;
    let lat_c = r.pos("secondary.lateral_damper_damping")?;
    let lat_k = r.pos("secondary.lateral_damper_series_stiffness")?;
    let n_lat = r.count("secondary.lateral_dampers_per_bogie")?;
    let lat_h = r.pos("secondary.lateral_damper_height")?;
    let yaw_c = r.pos("secondary.yaw_damper_damping")?;
    let yaw_k = r.pos("secondary.yaw_damper_series_stiffness")?;
    let yaw_semi = r.pos("secondary.yaw_damper_lateral_semi_spacing")?;
    let yaw_len = r.pos("secondary.yaw_damper_length")?;
    let yaw_h = r.pos("secondary.yaw_damper_height")?;
    let yaw_n = r.non_neg("secondary.yaw_dampers_per_side")?;
    let svd_c = r.pos("secondary.vertical_damper_damping")?;
    let svd_k = r.pos("secondary.vertical_damper_series_stiffness")?;
    let svd_semi = r.pos("secondary.vertical_damper_lateral_semi_spacing")?;
    let svd_n = r.non_neg("secondary.vertical_dampers_per_side")?;
    let bump_clearance = r.pos("secondary.bump_stop_clearance")?;
    let bump_k = r.pos("secondary.bump_stop_stiffness")?;
    let bump_h = r.pos("secondary.bump_stop_height")?;
    let bump_hard_d = r.pos("secondary.bump_stop_hardening_deflection")?;
    let bump_hard_k = r.pos("secondary.bump_stop_hardening_stiffness")?;
    let rod = RodGeometry::from_parameters(p)?;
    // The carbody pivot is a joint in the model (the rod's own coordinates are rotations about
    // it), so the pivot bushing's translational compliance is put in series with the frame end's.
    let series = |a: f64, b: f64| a * b / (a + b);
    let rod_k = [
        series(
            r.pos("traction_rod.carbody_bushing_stiffness_x")?,
            r.pos("traction_rod.frame_bushing_stiffness_x")?,
        ),
        series(
            r.pos("traction_rod.carbody_bushing_stiffness_y")?,
            r.pos("traction_rod.frame_bushing_stiffness_y")?,
        ),
        series(
            r.pos("traction_rod.carbody_bushing_stiffness_z")?,
            r.pos("traction_rod.frame_bushing_stiffness_z")?,
        ),
    ];
    // Rubber's hysteresis as a damping time on the same series spring (two Kelvin nodes of one
    // time constant in series are one of it): without it the rods' 49 Hz modes ring for seconds.
    let rod_tau = r.non_neg("traction_rod.bushing_damping_time")?;
    let rod_c = rod_k.map(|k| rod_tau * k);
    for b in 0..N_BOGIES {
        let xb = layout.bogie_x[b];
        let fr = body_frame(b);
        let cb = BODY_CARBODY;
        let tag = format!("bogie{}", b + 1);
        for (side, side_name) in sides.iter().enumerate() {
            let y = side_y(side, fc_semi);
            for i in 0..n_flexicoil {
                let dx = if n_flexicoil == 1 {
                    0.0
                } else {
                    fc_spacing * (i as f64 / (n_flexicoil - 1) as f64 - 0.5)
                };
                // Shear of a coil is measured at mid-height, where a rigid rotation of frame
                // and carbody together leaves it unstrained.
                let mid = 0.5 * (fc_bottom + fc_top);
                let mut spring = bushing(
                    format!("flexicoil_{tag}_{side_name}_{}", i + 1),
                    attach(bodies, fr, cb, [xb + dx, y, mid]),
                    fc,
                );
                spring.rotational_stiffness = [fc_bending, fc_bending, 0.0];
                spring.on_load_path = true;
                s.bushings.push(spring);
            }
            let yv = side_y(side, svd_semi);
            s.dampers.push(DamperPlacement {
                name: format!("secondary_vertical_damper_{tag}_{side_name}"),
                role: DamperRole::SecondaryVertical,
                at: attach2(bodies, fr, [xb, yv, fc_bottom], cb, [xb, yv, fc_top]),
                direction: [0.0, 0.0, 1.0],
                damping: svd_c,
                series_stiffness: svd_k,
                count: svd_n,
            });
            // Yaw damper: frame end at the bogie centre, carbody end one damper length outboard.
            let yy = side_y(side, yaw_semi);
            let out = xb.signum();
            s.dampers.push(DamperPlacement {
                name: format!("yaw_damper_{tag}_{side_name}"),
                role: DamperRole::Yaw,
                at: attach2(
                    bodies,
                    fr,
                    [xb, yy, yaw_h],
                    cb,
                    [xb + out * yaw_len, yy, yaw_h],
                ),
                direction: [out, 0.0, 0.0],
                damping: yaw_c,
                series_stiffness: yaw_k,
                count: yaw_n,
            });
        }
        for i in 0..n_lat {
            let dx = if n_lat == 1 {
                0.0
            } else {
                0.5 * (i as f64 / (n_lat - 1) as f64 - 0.5)
            };
            s.dampers.push(DamperPlacement {
                name: format!("secondary_lateral_damper_{tag}_{}", i + 1),
                role: DamperRole::SecondaryLateral,
                at: attach2(
                    bodies,
                    fr,
                    [xb + dx, -0.3, lat_h],
                    cb,
                    [xb + dx, 0.3, lat_h],
                ),
                direction: [0.0, 1.0, 0.0],
                damping: lat_c,
                series_stiffness: lat_k,
                count: 1.0,
            });
        }
        s.bump_stops.push(BumpStop {
            name: format!("lateral_bump_stop_{tag}"),
            at: attach(bodies, fr, cb, [xb, 0.0, bump_h]),
            clearance: bump_clearance,
            stiffness: bump_k,
            hardening_deflection: bump_hard_d,
            hardening_stiffness: bump_hard_k,
        });
        let rod_end = rod.frame_end(layout, b);
        s.bushings.push(Bushing {
            damping: rod_c,
            ..bushing(
                format!("traction_rod_{tag}"),
                attach(bodies, fr, body_traction_rod(b), rod_end),
                rod_k,
            )
        });
    }

    // Drive: motor mounts, gearbox bearings, six-link coupling.
    let mounts = r.count_pos("traction_motor.suspension_points_per_motor")?;
    let per_mount = |key: &str| -> Result<f64> { Ok(r.non_neg(key)? / mounts as f64) };
    let mount_k = [
        per_mount("traction_motor.suspension_stiffness_x")?,
        per_mount("traction_motor.suspension_stiffness_y")?,
        per_mount("traction_motor.suspension_stiffness_z")?,
    ];
    let mount_c = [
        per_mount("traction_motor.suspension_damping_x")?,
        per_mount("traction_motor.suspension_damping_y")?,
        per_mount("traction_motor.suspension_damping_z")?,
    ];
    let mount_dx = r.non_neg("traction_motor.suspension_point_longitudinal_offset")?;
    let mount_dy = r.non_neg("traction_motor.suspension_point_lateral_semi_spacing")?;
    let mount_dz = p.get("traction_motor.suspension_point_vertical_offset")?;
    let bearings = r.count_pos("hollow_shaft.bearings_per_shaft")? as f64;
    let bearing_semi = r.non_neg("hollow_shaft.bearing_semi_spacing")?;
    let bearing_radial = r.pos("hollow_shaft.bearing_radial_stiffness")?;
    let bearing_axial = r.pos("hollow_shaft.bearing_axial_stiffness")?;
    let bearing_damping_time = r.non_neg("hollow_shaft.bearing_damping_time")?;
    let coupling_radial = r.pos("hollow_shaft.coupling_radial_stiffness")?;
    let coupling_lateral = r.pos("hollow_shaft.coupling_lateral_stiffness")?;
    let coupling_angular = r.pos("hollow_shaft.coupling_angular_stiffness")?;
    let coupling_c_radial = r.non_neg("hollow_shaft.coupling_damping_radial")?;
    let coupling_c_lateral = r.non_neg("hollow_shaft.coupling_damping_lateral")?;
    // Two bearings at ±semi-spacing resist tilting of the shaft in the gearbox.
    let bearing_tilt = bearings * bearing_radial * bearing_semi * bearing_semi;
    // Radial path motor -> bearings -> shaft -> coupling -> wheel: springs in series.
    let radial = series(bearings * bearing_radial, coupling_radial);
    for w in 0..N_WHEELSETS {
        let b = bogie_of(w);
        let m = body_motor(w);
        let hs = body_hollow_shaft(w);
        let ws = body_wheelset(w);
        let tag = format!("wheelset{}", w + 1);
        let mpos = bodies[m].position;
        for i in 0..mounts {
            let sx = if i % 2 == 0 { 1.0 } else { -1.0 };
            let sy = if (i / 2) % 2 == 0 { 1.0 } else { -1.0 };
            let mut mount = bushing(
                format!("motor_mount_{tag}_{}", i + 1),
                attach(
                    bodies,
                    body_frame(b),
                    m,
                    [
                        mpos[0] + sx * mount_dx,
                        mpos[1] + sy * mount_dy,
                        mpos[2] + mount_dz,
                    ],
                ),
                mount_k,
            );
            mount.damping = mount_c;
            mount.on_load_path = true;
            s.bushings.push(mount);
        }
        let axle = [layout.wheelset_x[w], 0.0, r0];
        let mut bearing = bushing(
            format!("{GEARBOX_BEARINGS}_{tag}"),
            attach(bodies, m, hs, axle),
            [radial, bearings * bearing_axial, radial],
        );
        // Rolling bearings damp in proportion to their stiffness, c = β·k; radially the soft
        // coupling in series governs, with its own damping.
        let axial_damping = bearing_damping_time * bearings * bearing_axial;
        bearing.damping = [coupling_c_radial, axial_damping, coupling_c_radial];
        bearing.rotational_stiffness = [bearing_tilt, 0.0, bearing_tilt];
        let tilt_damping = bearing_damping_time * bearing_tilt;
        bearing.rotational_damping = [tilt_damping, 0.0, tilt_damping];
        bearing.on_load_path = true;
        s.bushings.push(bearing);
        let mut coupling = bushing(
            format!("six_link_coupling_{tag}"),
            attach(bodies, ws, hs, axle),
            [0.0, coupling_lateral, 0.0],
        );
        coupling.damping = [0.0, coupling_c_lateral, 0.0];
        coupling.rotational_stiffness = [coupling_angular, 0.0, coupling_angular];
        s.bushings.push(coupling);
    }
    Ok(s)
}
