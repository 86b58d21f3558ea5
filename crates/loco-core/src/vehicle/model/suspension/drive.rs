//! The drive: each frame-suspended motor's mounts on its frame, the gearbox bearings that
//! carry the hollow shaft in the motor, and the six-link coupling to the wheelset.

use super::{attach, bushing, series, Suspension, GEARBOX_BEARINGS};
use crate::vehicle::model::bodies::{Body, Layout};
use crate::vehicle::model::layout::*;
use crate::vehicle::params::sections::VehicleSections;

/// Adds the drive elements of the four wheelsets to `s`.
pub(super) fn add(p: &VehicleSections, layout: &Layout, bodies: &[Body], s: &mut Suspension) {
    let r0 = layout.wheel_radius;
    let mounts = p.traction_motor.suspension_points_per_motor;
    let per_mount = |value: f64| value / mounts as f64;
    let mount_k = [
        per_mount(p.traction_motor.suspension_stiffness_x),
        per_mount(p.traction_motor.suspension_stiffness_y),
        per_mount(p.traction_motor.suspension_stiffness_z),
    ];
    let mount_c = [
        per_mount(p.traction_motor.suspension_damping_x),
        per_mount(p.traction_motor.suspension_damping_y),
        per_mount(p.traction_motor.suspension_damping_z),
    ];
    let mount_dx = p.traction_motor.suspension_point_longitudinal_offset;
    let mount_dy = p.traction_motor.suspension_point_lateral_semi_spacing;
    let mount_dz = p.traction_motor.suspension_point_vertical_offset;
    let bearings = p.hollow_shaft.bearings_per_shaft as f64;
    let bearing_semi = p.hollow_shaft.bearing_semi_spacing;
    let bearing_radial = p.hollow_shaft.bearing_radial_stiffness;
    let bearing_axial = p.hollow_shaft.bearing_axial_stiffness;
    let bearing_damping_time = p.hollow_shaft.bearing_damping_time;
    let coupling_radial = p.hollow_shaft.coupling_radial_stiffness;
    let coupling_lateral = p.hollow_shaft.coupling_lateral_stiffness;
    let coupling_angular = p.hollow_shaft.coupling_angular_stiffness;
    let coupling_c_radial = p.hollow_shaft.coupling_damping_radial;
    let coupling_c_lateral = p.hollow_shaft.coupling_damping_lateral;
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
}
