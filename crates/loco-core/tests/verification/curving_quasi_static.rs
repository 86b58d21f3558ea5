//! Quasi-static curving on a conical wheel and knife-edge rails against the classical linear
//! theory: a free wheelset's pure-rolling offset (the wheel-rail contact alone, solved for its
//! equilibrium) and a two-axle bogie with primary yaw stiffness (the whole locomotive run into
//! a steady curve).

use crate::record::Record;
use loco_core::contact::builtin::conical::conical_pair;
use loco_core::track::CurveDirection;
use loco_core::track::RailIrregularity;
use loco_core::vehicle::model::elements::BodyStates;
use loco_core::vehicle::model::layout::*;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::wheel_channels::{wheelset_channel, WheelsetQuantity};
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::wheel_rail::{ContactMode, WheelForces, WheelRail};
use loco_core::vehicle::scenarios::scenario::Scenario;
use loco_core::vehicle::scenarios::scenario_contact::build_wheel_rail;

use crate::curve_support::cone::{half_distance, research, run_cone, run_cone_towards, G};

/// The wheel-rail wrench (N, N·m, on the wheelset about its centre, track frame) of wheelset 1
/// at `pose` = [lateral y (m), vertical z (m), roll φ (rad), yaw ψ (rad) relative to the radial
/// direction, spin rate beyond V/r0 (rad/s)] running at `speed` on a curve of radius `radius`
/// (its frame turns at V/R, what `VehicleSystem` adds to the wheelset's yaw rate on a curve).
fn wheelset_wrench(
    wr: &WheelRail,
    pose: &[f64; 5],
    speed: f64,
    radius: f64,
) -> ([f64; 6], [WheelForces; 2]) {
    let body = body_wheelset(0);
    let mut states = BodyStates::default();
    states.position[body] = [0.0, pose[0], pose[1], pose[2], 0.0, pose[3]];
    states.velocity[body] = [0.0, 0.0, 0.0, 0.0, pose[4], speed / radius];
    let mut wrenches = [[0.0; 6]; N_BODIES];
    let mut out = [WheelForces::default(); 2];
    wr.apply(
        0,
        0.0,
        &states,
        &wr.rail_plane(&RailIrregularity::default(), speed),
        speed,
        ContactMode::Rolling,
        &mut wrenches,
        &mut out,
    )
    .unwrap();
    (wrenches[body], out)
}

/// The quasi-static pose of a free wheelset (no suspension, axle load `load` N, no lateral
/// load) by Newton's method on the lateral force, vertical force, roll, yaw and spin moments.
fn free_wheelset_pose(wr: &WheelRail, load: f64, speed: f64, radius: f64) -> [f64; 5] {
    wheelset_pose(wr, load, speed, radius, None)
}

/// As [`free_wheelset_pose`], with the lateral position held at `held_y` (m) when given (the
/// lateral force then stays unbalanced and the yaw is held radial).
fn wheelset_pose(
    wr: &WheelRail,
    load: f64,
    speed: f64,
    radius: f64,
    held_y: Option<f64>,
) -> [f64; 5] {
    let residual = |p: &[f64; 5]| {
        let (w, _) = wheelset_wrench(wr, p, speed, radius);
        match held_y {
            None => [
                w[Y] / load,
                w[Z] / load - 1.0,
                w[3] / load,
                w[5] / load,
                w[4] / load,
            ],
            Some(y) => [p[0] - y, w[Z] / load - 1.0, w[3] / load, p[3], w[4] / load],
        }
    };
    let steps = [1e-7, 1e-8, 1e-7, 1e-7, 1e-5];
    let mut p = [0.0, -1e-4, 0.0, 0.0, 0.0];
    for _ in 0..60 {
        let r = residual(&p);
        if r.iter().all(|v| v.abs() < 1e-9) {
            return p;
        }
        let mut j = nalgebra::SMatrix::<f64, 5, 5>::zeros();
        for k in 0..5 {
            let mut q = p;
            q[k] += steps[k];
            let rq = residual(&q);
            for i in 0..5 {
                j[(i, k)] = (rq[i] - r[i]) / steps[k];
            }
        }
        let dx = j.lu().solve(&nalgebra::SVector::<f64, 5>::from(r)).unwrap();
        for k in 0..5 {
            p[k] -= dx[k];
        }
    }
    panic!("free wheelset: no equilibrium, residual {:?}", residual(&p));
}

#[test]
fn free_conical_wheelset_rolls_round_a_curve_at_the_pure_rolling_offset() {
    // Wickens, Fundamentals of Rail Vehicle Dynamics (2003), and Iwnicki (ed.), Handbook of
    // Railway Vehicle Dynamics (2006), on the steady curving of a wheelset: a free wheelset with
    // coned wheels of conicity λ, with no lateral load, runs round a curve of radius R where its
    // rolling radius difference matches the outer rail's longer path, 2λy = 2 r0 l / R, so
    // y = r0 l / (λR) toward the outer rail, with neither longitudinal nor lateral creep (ψ = 0).
    // The conical pair has no flange: its clearance is the contact table's ±25 mm.
    let mut scenario = Scenario::study("S_norm", 30.0, 100.0, 0).unwrap();
    let (wheel, rail) = conical_pair(0.1).unwrap();
    scenario.wheel = wheel;
    scenario.rail = rail;
    let p = ParameterSet::default_vehicle();
    let wr = build_wheel_rail(&p, &scenario).unwrap();
    let load = VehicleStructure::new(p).unwrap().total_mass() * G / N_WHEELSETS as f64;
    // λ and l of this contact from its table: Δr/2y (the cone's slope as the wheelset rolls on
    // the rail crowns) and the contact points' half distance; r0 of the centred wheelset.
    let lambda = wr.table().lookup(1e-3).rolling_radius_difference() / 2e-3;
    let l = half_distance(&wr);
    let r0 = wr.centred_radius();
    let (lo, hi) = wr.table().y_range();
    let mut worst = 0.0_f64;
    for radius in [600.0, 1200.0, 3000.0] {
        let speed = 30.0;
        let pose = free_wheelset_pose(&wr, load, speed, radius);
        let expected = -r0 * l / (lambda * radius);
        // Longitudinal creep forces at the equilibrium against those of the same wheelset held
        // centred and radial (each ≈ f11 l / R): the offset removes them.
        let (_, at_rest) = wheelset_wrench(&wr, &pose, speed, radius);
        let (_, centred) = wheelset_wrench(&wr, &[0.0, pose[1], 0.0, 0.0, 0.0], speed, radius);
        for side in 0..2 {
            let (f, f0) = (at_rest[side].longitudinal, centred[side].longitudinal);
            println!("  wheel {side}: longitudinal {f:.2e} N (centred {f0:.0} N)");
            assert!(f0.abs() > 1e3 && f.abs() < 1e-3 * f0.abs(), "{f} vs {f0}");
        }
        println!(
            "R {radius} m: y {:.4e} m (r0 l/(λR) {expected:.4e}), yaw {:.2e} rad",
            pose[0], pose[3]
        );
        assert!(expected > lo && expected < hi);
        assert!(
            (pose[0] - expected).abs() < 2e-3 * expected.abs(),
            "{pose:?}"
        );
        // No lateral creep either: the wheelset stays radial (the small yaw left balances the
        // spin creep of the frame's yaw rate, 1/R on both wheels).
        assert!(pose[3].abs() < 1e-3 * l / radius, "yaw {}", pose[3]);
        worst = worst.max((pose[0] - expected).abs() / expected.abs());
    }
    Record::new("curve_free_wheelset_offset", file!())
        .count("radii", 3)
        .within("offset_deviation", worst, "", 2, "<", 2e-3)
        .check();
}

/// Linear contact coefficients of the wheelset at its static pose on straight track, from the
/// model's own wheel-rail wrench (the inputs the linear theory takes as given): per wheelset
/// 2 f22 = ∂F_y/∂ψ (lateral creep), 2 f11 l² = −∂M_z/∂(1/R) (longitudinal creep of the frame's
/// yaw rate) and the gravitational stiffness k_g = −∂F_y/∂y.
fn contact_coefficients(wr: &WheelRail, load: f64, speed: f64) -> (f64, f64, f64) {
    let rest = free_wheelset_pose(wr, load, speed, f64::INFINITY);
    let at = |k: usize, d: f64, radius: f64| {
        let mut p = rest;
        p[k] += d;
        wheelset_wrench(wr, &p, speed, radius).0
    };
    let h = 1e-5;
    let f22 = (at(3, h, f64::INFINITY)[Y] - at(3, -h, f64::INFINITY)[Y]) / (4.0 * h);
    let l = half_distance(wr);
    let f11 = -(at(3, 0.0, 1.0 / h)[5] - at(3, 0.0, -1.0 / h)[5]) / (2.0 * h) / (2.0 * l * l);
    // The wheelset settles vertically and in roll at each lateral position.
    let fy = |y: f64| {
        let p = wheelset_pose(wr, load, speed, f64::INFINITY, Some(y));
        wheelset_wrench(wr, &p, speed, f64::INFINITY).0[Y]
    };
    let kg = -(fy(1e-4) - fy(-1e-4)) / 2e-4;
    (f11, f22, kg)
}

#[test]
fn a_two_axle_bogie_takes_the_curve_as_the_linear_theory_gives() {
    // Boocock, "Steady-state motion of railway vehicles on curved track", J. Mech. Eng. Sci.
    // 11 (1969) 556-566 (also Wickens, Fundamentals of Rail Vehicle Dynamics, 2003): a
    // bogie frame with two coned wheelsets (semi-wheelbase a) on primary longitudinal springs
    // k_x at ±b (yaw stiffness k_ψ = 2 k_x b²) and lateral k_y, no lateral load, guided by
    // linear creep forces. Per wheelset i at x_i = ±a (y_i, ψ_i relative to its radial frame):
    //   2 f22 ψ_i − k_g y_i − F_i = 0,
    //   −2 f11 l (λ y_i / r0 + l / R) − k_ψ ε_i − (x_n − x_i) F_i = 0,
    // with ε_i = ψ_i + x_i/R − ψ_f the yaw relative to the frame, F_i = k_y Δ_i the primary
    // lateral force at the arm node x_n (0.5 m inboard of the axle on this rotary-arm bogie),
    // Δ_i = y_i + x_i²/2R + (ψ_i + x_i/R)(x_n − x_i) − y_f − ψ_f x_n; and the frame:
    //   Σ F_i = 0,  Σ (x_n F_i + k_ψ ε_i) = 0.
    // The model's bogie is made this one: the drive's couplings and the flexicoils' longitudinal
    // stiffness (the secondary yaw stiffness, 4.5e5 N·m/rad) are research-softened; what is
    // left of the secondary's yaw stiffness (the flexicoils' shear at ±0.3 m, 4e4 N·m/rad
    // against the primary's 3e7) is neglected. Balanced cant: no lateral load. The theory is
    // linear in the creepages; at R = 3000 m the leading wheelsets' creep forces are 25 % of
    // μQ with the study's μ = 0.3, where FASTSIM's saturation already lowers them by ~8 %
    // (measured: angle of attack 15 % above the theory's), so μ is raised to 5 here (research
    // value) to keep the contact in its linear range; with μ = 0.3 the same agreement holds at
    // R = 15 000 m (measured within 1 %).
    let (lambda, radius, speed) = (0.1, 3000.0, 20.0);
    let mut p = ParameterSet::default_vehicle();
    for key in [
        "hollow_shaft.coupling_lateral_stiffness",
        "hollow_shaft.coupling_angular_stiffness",
        "secondary.flexicoil_longitudinal_stiffness",
    ] {
        research(&mut p, key, 1.0);
    }
    research(&mut p, "track.wheel_rail_friction", 5.0);
    let get = |key: &str| p.get(key).unwrap();
    let (a, d) = (get("layout.half_wheelbase"), get("rotary_arm.arm_length"));
    let b = get("primary.spring_lateral_semi_spacing");
    let kx = 2.0 * get("rotary_arm.node_stiffness_longitudinal");
    let ky = 2.0 * get("rotary_arm.node_stiffness_lateral");
    let kpsi = kx * b * b;
    let r = run_cone(p.clone(), lambda, radius, speed, 300.0);
    let mirrored = run_cone_towards(
        p.clone(),
        lambda,
        radius,
        speed,
        300.0,
        CurveDirection::Right,
    );
    let wr = r.system.wheel_rail.clone();
    let structure = VehicleStructure::new(p).unwrap();
    let load = structure.total_mass() * G / N_WHEELSETS as f64;
    let frame_height = structure.bodies[body_frame(0)].position[2];
    let node_height = structure.layout.wheel_radius;
    let (f11, f22, kg) = contact_coefficients(&wr, load, speed);
    let lam = wr.table().lookup(1e-3).rolling_radius_difference() / 2e-3;
    let l = half_distance(&wr);
    let r0 = wr.centred_radius();
    println!("f11 {f11:.3e} N, f22 {f22:.3e} N, k_g {kg:.3e} N/m, λ {lam:.4}, l {l:.4} m");
    // Unknowns [y1, ψ1, y2, ψ2, y_f, ψ_f]; the equations are linear: J x = c.
    let kappa = 1.0 / radius;
    let mut j = nalgebra::SMatrix::<f64, 6, 6>::zeros();
    let mut c = nalgebra::SVector::<f64, 6>::zeros();
    for (i, xi) in [a, -a].into_iter().enumerate() {
        let xn = xi - xi.signum() * d;
        let (iy, ip) = (2 * i, 2 * i + 1);
        // Δ_i = dy·x + dc, as coefficients over the unknowns plus a constant.
        let mut delta = [0.0; 6];
        delta[iy] = 1.0;
        delta[ip] = xn - xi;
        delta[4] = -1.0;
        delta[5] = -xn;
        let delta_c = xi * xi * kappa / 2.0 + xi * kappa * (xn - xi);
        // Wheelset lateral.
        for k in 0..6 {
            j[(iy, k)] -= ky * delta[k];
            j[(ip, k)] -= (xn - xi) * ky * delta[k];
            j[(4, k)] += ky * delta[k];
            j[(5, k)] += xn * ky * delta[k];
        }
        j[(iy, ip)] += 2.0 * f22;
        j[(iy, iy)] -= kg;
        c[iy] += ky * delta_c;
        // Wheelset yaw: creep and the yaw spring ε_i = ψ_i + x_i κ − ψ_f.
        j[(ip, iy)] -= 2.0 * f11 * l * lam / r0;
        j[(ip, ip)] -= kpsi;
        j[(ip, 5)] += kpsi;
        c[ip] += 2.0 * f11 * l * l * kappa + kpsi * xi * kappa + (xn - xi) * ky * delta_c;
        // Frame: the reactions.
        c[4] -= ky * delta_c;
        c[5] -= xn * ky * delta_c - kpsi * xi * kappa;
        j[(5, ip)] += kpsi;
        j[(5, 5)] -= kpsi;
    }
    let x = j.lu().solve(&c).unwrap();
    let mut worst_pose = 0.0_f64;
    let names = ["y1", "ψ1", "y2", "ψ2", "y_f", "ψ_f"];
    for bogie in 0..N_BOGIES {
        let (w1, w2) = (2 * bogie, 2 * bogie + 1);
        let model = [
            r.y[wheelset(w1) + Y],
            r.y[wheelset(w1) + YAW],
            r.y[wheelset(w2) + Y],
            r.y[wheelset(w2) + YAW],
            // The theory's frame is planar, at the nodes' height (the axle's, r0); the model's
            // frame coordinate is at its centre of gravity, which its roll moves sideways.
            r.y[frame(bogie) + Y] + r.y[frame(bogie) + ROLL] * (frame_height - node_height),
            r.y[frame(bogie) + YAW],
        ];
        for k in 0..6 {
            let error = (model[k] - x[k]) / x[k];
            println!(
                "bogie {}: {} model {:+.4e}, theory {:+.4e} ({:+.2} %)",
                bogie + 1,
                names[k],
                model[k],
                x[k],
                100.0 * error
            );
            assert!(error.abs() < 0.02, "bogie {}: {}", bogie + 1, names[k]);
            worst_pose = worst_pose.max(error.abs());
        }
    }
    // Classical shape of the solution: the leading wheelset runs outward with its nose
    // outward (positive angle of attack), the trailing one nearer the centre, nose inward.
    assert!(x[0] < x[2] && x[2] < 0.0 && x[1] < 0.0 && x[3] > 0.0);
    // The recorded angle-of-attack channel (`wheelset<w>_yaw`, `vehicle::output::wheel_channels`; what
    // `loco curving` reports) is the theory's ψ_i, the yaw against the track tangent at each
    // wheelset, in a left curve and (mirrored, the sign flipped) in a right one. The theory
    // tells that definition apart from the two a model could slip into: the yaw against the
    // bogie frame's axis, ψ_i + x_i/R − ψ_f, or against the tangent at the vehicle's origin,
    // ψ_i + X_i/R (X_i the wheelset's distance from it, ±3.05 / ±5.95 m); both are far outside
    // the 2 % asserted (checked below, so this comparison can fail).
    let axles = [a, -a];
    let mut worst_channel = 0.0_f64;
    for (run, sign, side) in [(&r, 1.0, "left"), (&mirrored, -1.0, "right")] {
        for w in 0..N_WHEELSETS {
            let name = wheelset_channel(w, WheelsetQuantity::Yaw);
            let channel = *run.output.channel(&name).unwrap().last().unwrap();
            let theory = sign * x[2 * (w % 2) + 1];
            let error = (channel - theory) / theory;
            println!(
                "{side} curve: {name} {:+.4} mrad, theory {:+.4} mrad ({:+.2} %)",
                1e3 * channel,
                1e3 * theory,
                100.0 * error
            );
            assert!(error.abs() < 0.02, "{side} curve: {name}");
            worst_channel = worst_channel.max(error.abs());
            let to_frame = x[2 * (w % 2) + 1] + axles[w % 2] * kappa - x[5];
            let origin = structure.bodies[body_wheelset(w)].position[0];
            let to_origin = x[2 * (w % 2) + 1] + origin * kappa;
            for other in [to_frame, to_origin] {
                assert!(
                    (sign * other - theory).abs() > 0.2 * theory.abs(),
                    "{name}: {other}"
                );
            }
        }
    }
    Record::new("curve_two_axle_bogie", file!())
        .within("pose_deviation", worst_pose, "", 2, "<", 0.02)
        .within(
            "angle_of_attack_channel_deviation",
            worst_channel,
            "",
            2,
            "<",
            0.02,
        )
        .check();
}
