//! The contact compiled for AVX against its baseline compilation, and both against the contact
//! one point at a time, bit for bit.

use super::*;
use crate::vehicle::model::elements::add_force_at;
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::layout::{body_wheelset, N_BODIES, N_WHEELSETS};
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::rail_contact::creep_model::CreepModel;
use crate::vehicle::scenarios::scenario::Scenario;
use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;

/// A small deterministic generator of uniform numbers in [−1, 1).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        2.0 * ((self.0 >> 11) as f64 / (1u64 << 53) as f64) - 1.0
    }
}

/// Wheelset poses from the centre to flange contact and beyond the table (a derailment error),
/// sunk into the rails by up to 0.2 mm (loads up to a few hundred kN) or lifted off them.
fn states(r: &mut Uniform) -> BodyStates {
    let mut s = BodyStates::default();
    for w in 0..N_WHEELSETS {
        let body = body_wheelset(w);
        let lateral = if r.next() > 0.95 { 0.03 } else { 0.012 };
        s.position[body] = [
            1e-3 * r.next(),
            lateral * r.next(),
            -1e-4 + 1.2e-4 * r.next(),
            2e-3 * r.next(),
            10.0 * r.next(),
            3e-3 * r.next(),
        ];
        s.velocity[body] = [
            0.1 * r.next(),
            0.2 * r.next(),
            0.05 * r.next(),
            0.1 * r.next(),
            r.next(),
            0.1 * r.next(),
        ];
    }
    s
}

fn rails(r: &mut Uniform) -> RailIrregularity {
    RailIrregularity {
        y_left: 3e-3 * r.next(),
        z_left: 3e-3 * r.next(),
        y_right: 3e-3 * r.next(),
        z_right: 3e-3 * r.next(),
        dy_left_ds: 1e-3 * r.next(),
        dz_left_ds: 1e-3 * r.next(),
        dy_right_ds: 1e-3 * r.next(),
        dz_right_ds: 1e-3 * r.next(),
    }
}

/// The forces of one call: the result, the wrenches' bits and the wheel forces (their `Debug`
/// form tells every bit of a float apart, the sign of zero included).
fn forces(
    call: impl FnOnce(&mut Wrenches, &mut [WheelForces; 2]) -> Result<()>,
) -> (Result<()>, Vec<u64>, String) {
    let mut wrenches: Wrenches = [[0.0; 6]; N_BODIES];
    let mut out = [WheelForces::default(); 2];
    let result = call(&mut wrenches, &mut out);
    let bits = wrenches.iter().flatten().map(|v| v.to_bits()).collect();
    (result, bits, format!("{out:?}"))
}

/// [`WheelRail::apply`]'s body before `pending_contact`: each point's creep forces and terms
/// right after its normal contact (the reference of the order of every sum).
#[allow(clippy::too_many_arguments)]
fn one_point_at_a_time(
    contact: &WheelRail,
    w: usize,
    t: f64,
    states: &BodyStates,
    plane: &RailPlane,
    speed: f64,
    mode: ContactMode,
    wrenches: &mut Wrenches,
    out: &mut [WheelForces; 2],
) -> Result<()> {
    let body = body_wheelset(w);
    let u = states.position[body];
    let v = states.velocity[body];
    let spin = speed / contact.centred_radius + v[PITCH];
    // Wheel angular velocity: spin about the rolled and yawed axle, plus roll and yaw rates.
    let angular = [v[ROLL] - spin * u[YAW], spin, v[YAW] + spin * u[ROLL]];
    let velocity = BodyVelocity {
        velocity: [speed + v[0], v[1], v[2]],
        angular_velocity: angular,
    };
    if let ContactMode::Held {
        tangential_stiffness: static_stiffness,
    } = mode
    {
        // Static search: the brakes hold the spin, otherwise the vehicle could roll away.
        let r0 = contact.centred_radius;
        wrenches[body][PITCH] -= static_stiffness * r0 * r0 * u[PITCH];
    }
    // The table is read in the rails' plane (see `rail_plane`).
    let h0 = contact.centred_radius;
    let pose_in_plane = plane.pose(u[1], u[2], u[ROLL], h0);
    let (s_theta, c_theta) = plane.roll_sin_cos();
    let yaw_sin_cos = u[YAW].sin_cos();
    for (side_index, side) in SIDES.iter().enumerate() {
        let s = side.sign();
        let y_rel = plane.table_position(pose_in_plane.lateral, side_index);
        let (lo, hi) = contact.table.y_range();
        if !(lo..=hi).contains(&y_rel) {
            // A runaway state (numerical divergence) is told apart from this by
            // `VehicleSystem::finish_step`, which checks the state before reporting this error.
            return Err(LocoError::Derailed {
                time: t,
                location: format!("wheelset{} {}", w + 1, side_name(*side)),
                reason: format!(
                    "lateral position {y_rel:.4} m relative to the rail is beyond the contact \
                     table ({lo:.4} … {hi:.4} m): the flange has climbed or the state diverged"
                ),
            });
        }
        let wheel = contact
            .table
            .lookup_wheel(y_rel, side_index, pose_in_plane.roll);
        let mut forces = WheelForces::default();
        for point in wheel.contact.points.iter().flatten() {
            let l = point.lateral;
            let interference = wheel.rise + wheel.roll * l + plane.rail_height(side_index)
                - pose_in_plane.vertical
                - pose_in_plane.roll * l
                - point.gap;
            if interference <= 0.0 {
                continue;
            }
            let (sg, cg) = point.contact_angle.sin_cos();
            let approach = interference * cg;
            // A yawed wheel touches a steep flange ahead of or behind its axle.
            let lead =
                contact_lead_sin_cos(*side, point.rolling_radius, (sg, cg), wheel.roll, u[YAW]);
            let offset = plane.to_track([lead - u[YAW] * l, l, point.vertical]);
            // The contact angle in the track frame is γ + s·θ.
            let in_track = (
                sg * c_theta + s * cg * s_theta,
                cg * c_theta - s * sg * s_theta,
            );
            let frame = ContactFrame::from_sin_cos(*side, in_track, yaw_sin_cos);
            let rail_surface = plane.surface_velocity(u[1], u[2], h0, &offset);
            let slip = slip_velocity(&velocity, &offset, &rail_surface);
            let approach_rate = -dot(&slip, &frame.normal);
            let hertz = contact.hertz.coefficients(
                // Rolling-direction curvature of the wheel at a point whose normal is tilted
                // by the contact angle from the radius (Meusnier): cos γ / r.
                0.5 * cg / point.rolling_radius,
                // A conformal point (flange root on the gauge corner) has a lateral relative
                // curvature near zero; a floor of 1/(20 m) keeps the ellipse finite there.
                (0.5 * (point.wheel_curvature + point.rail_curvature)).max(0.025),
                contact.settings.contact_modulus,
            )?;
            let normal = (hertz.load_from_approach(approach)
                + contact.settings.normal_damping * approach_rate)
                .max(0.0);
            if normal == 0.0 {
                continue;
            }
            let (tangential, wear_number) = if let ContactMode::Held {
                tangential_stiffness: static_stiffness,
            } = mode
            {
                // Static search: contact patches do not slide; displacement of the wheel
                // surface at the contact (x − r·β, y + r·φ_el, in the rails' plane) against
                // a tangential spring.
                let dx = u[0] - point.rolling_radius * u[PITCH] - l * u[YAW];
                let dy = pose_in_plane.lateral
                    + point.rolling_radius * (pose_in_plane.roll - wheel.roll);
                let held = CreepForces {
                    fx: -static_stiffness * dx,
                    fy: -static_stiffness * dy * cg,
                    mz: 0.0,
                };
                (held, 0.0)
            } else {
                let creep = creepages_of_slip(&slip, &angular, &frame, speed);
                let (a, b) = hertz.semi_axes(normal);
                let t = contact
                    .creep
                    .creep_forces(a, b, normal, contact.settings.friction, &creep);
                (
                    t,
                    -(t.fx * creep.longitudinal + t.fy * creep.lateral + t.mz * creep.spin),
                )
            };
            let f: [f64; 3] = std::array::from_fn(|k| {
                normal * frame.normal[k]
                    + tangential.fx * frame.longitudinal[k]
                    + tangential.fy * frame.lateral[k]
            });
            // `offset` is the contact point from the wheelset centre in track axes at the
            // wheelset's pose (the table's roll, the yaw's −ψ·l): the lever arm as it is,
            // not one to be turned by the wheelset's rotation again. Turning it again moved
            // every load by r0·φ across the rail head (0.7 mm at 1.2 mrad of roll).
            add_force_at(wrenches, body, offset, f);
            for k in 0..3 {
                wrenches[body][3 + k] += tangential.mz * frame.normal[k];
            }
            forces.vertical += f[2];
            forces.lateral += f[1];
            forces.longitudinal += f[0];
            forces.wear_number += wear_number;
            forces.contact_angle = if forces.points_in_contact == 0 {
                point.contact_angle
            } else {
                forces.contact_angle.max(point.contact_angle)
            };
            forces.points_in_contact += 1;
        }
        out[side_index] = forces;
    }
    Ok(())
}

/// Also the points of both wheels first (`pending_contact`) against one point at a time.
#[test]
fn the_avx_compilation_gives_the_bits_of_the_baseline() {
    #[cfg(target_arch = "x86_64")]
    if !std::arch::is_x86_feature_detected!("avx") {
        return;
    }
    let p = ParameterSet::default_vehicle();
    let mut r = Uniform(0x2545_f491_4f6c_dd1d);
    let modes = [
        ContactMode::Rolling,
        ContactMode::Held {
            tangential_stiffness: 1e7,
        },
    ];
    for (name, creep) in [
        ("S_high", CreepModel::Fastsim),
        ("S_low", CreepModel::Fastsim),
        ("S_high", CreepModel::Fastrip),
    ] {
        let scenario = Scenario {
            creep,
            ..Scenario::study(name, 55.0, 300.0, 1).unwrap()
        };
        let contact = shared_wheel_rail(&p, &scenario).unwrap();
        let (mut loaded, mut derailed) = (0, 0);
        for case in 0..400 {
            let s = states(&mut r);
            let speed = 55.0 * (1.0 + 0.2 * r.next());
            let mode = modes[usize::from(case % 7 == 0)];
            for w in 0..N_WHEELSETS {
                let plane = contact.rail_plane(&rails(&mut r), speed);
                let base =
                    forces(|wr, out| contact.apply_on(w, 1.0, &s, &plane, speed, mode, wr, out));
                #[cfg(target_arch = "x86_64")]
                {
                    // SAFETY: AVX was detected above.
                    let avx = forces(|wr, out| unsafe {
                        contact.apply_avx(w, 1.0, &s, &plane, speed, mode, wr, out)
                    });
                    assert_eq!(avx, base, "{name} {creep:?} case {case} wheelset {w}");
                }
                let reference = forces(|wr, out| {
                    one_point_at_a_time(&contact, w, 1.0, &s, &plane, speed, mode, wr, out)
                });
                assert_eq!(base, reference, "{name} {creep:?} case {case} wheelset {w}");
                loaded += usize::from(base.2.contains("points_in_contact: 2"));
                derailed += usize::from(base.0.is_err());
            }
        }
        // The cases reach two-point contact and the derailment error.
        assert!(loaded > 10 && derailed > 5, "{name}: {loaded} {derailed}");
    }
}
