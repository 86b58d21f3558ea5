//! The secondary suspension of each bogie: flexicoil springs, secondary vertical, yaw and
//! lateral dampers, the lateral bump stop and the traction rod's node on the frame.

use super::{attach, attach2, bushing, series, DamperPlacement, DamperRole, Suspension, SIDES};
use crate::error::Result;
use crate::vehicle::model::bodies::{side_y, Body, Layout, RodGeometry};
use crate::vehicle::model::elements::{BumpStop, Bushing};
use crate::vehicle::model::layout::*;
use crate::vehicle::params::sections::VehicleSections;

/// Adds the secondary elements of both bogies to `s`; the rod's two ends must not coincide.
pub(super) fn add(
    p: &VehicleSections,
    layout: &Layout,
    bodies: &[Body],
    s: &mut Suspension,
) -> Result<()> {
    let n_flexicoil = p.secondary.flexicoil_springs_per_side;
    let fc = [
        p.secondary.flexicoil_longitudinal_stiffness,
        p.secondary.flexicoil_lateral_stiffness,
        p.secondary.flexicoil_vertical_stiffness,
    ];
    let fc_bending = p.secondary.flexicoil_bending_stiffness;
    let fc_semi = p.secondary.flexicoil_lateral_semi_spacing;
    let fc_spacing = p.secondary.flexicoil_longitudinal_spacing;
    let fc_bottom = p.secondary.flexicoil_bottom_height;
    let fc_top = p.secondary.flexicoil_top_height;
    let lat_c = p.secondary.lateral_damper_damping;
    let lat_k = p.secondary.lateral_damper_series_stiffness;
    let n_lat = p.secondary.lateral_dampers_per_bogie;
    let lat_h = p.secondary.lateral_damper_height;
    let yaw_c = p.secondary.yaw_damper_damping;
    let yaw_k = p.secondary.yaw_damper_series_stiffness;
    let yaw_semi = p.secondary.yaw_damper_lateral_semi_spacing;
    let yaw_len = p.secondary.yaw_damper_length;
    let yaw_h = p.secondary.yaw_damper_height;
    let yaw_n = p.secondary.yaw_dampers_per_side;
    let svd_c = p.secondary.vertical_damper_damping;
    let svd_k = p.secondary.vertical_damper_series_stiffness;
    let svd_semi = p.secondary.vertical_damper_lateral_semi_spacing;
    let svd_n = p.secondary.vertical_dampers_per_side;
    let bump_clearance = p.secondary.bump_stop_clearance;
    let bump_k = p.secondary.bump_stop_stiffness;
    let bump_h = p.secondary.bump_stop_height;
    let bump_hard_d = p.secondary.bump_stop_hardening_deflection;
    let bump_hard_k = p.secondary.bump_stop_hardening_stiffness;
    let rod = RodGeometry::new(&p.traction_rod)?;
    // The carbody pivot is a joint in the model (the rod's own coordinates are rotations about
    // it), so the pivot bushing's translational compliance is put in series with the frame end's.
    let rod_k = [
        series(
            p.traction_rod.carbody_bushing_stiffness_x,
            p.traction_rod.frame_bushing_stiffness_x,
        ),
        series(
            p.traction_rod.carbody_bushing_stiffness_y,
            p.traction_rod.frame_bushing_stiffness_y,
        ),
        series(
            p.traction_rod.carbody_bushing_stiffness_z,
            p.traction_rod.frame_bushing_stiffness_z,
        ),
    ];
    // Rubber's hysteresis as a damping time on the same series spring (two Kelvin nodes of one
    // time constant in series are one of it): without it the rods' 49 Hz modes ring for seconds.
    let rod_tau = p.traction_rod.bushing_damping_time;
    let rod_c = rod_k.map(|k| rod_tau * k);
    for b in 0..N_BOGIES {
        let xb = layout.bogie_x[b];
        let fr = body_frame(b);
        let cb = BODY_CARBODY;
        let tag = format!("bogie{}", b + 1);
        for (side, side_name) in SIDES.iter().enumerate() {
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
                count: svd_n as f64,
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
                count: yaw_n as f64,
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
    Ok(())
}
