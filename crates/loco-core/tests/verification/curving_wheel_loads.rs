//! Wheel loads in a steady curve at balanced cant against the roll-moment balance of the whole
//! vehicle (statics from the bodies' positions), on a conical wheel and knife-edge rails and on
//! the S_norm profiles.

use crate::record::Record;
use loco_core::track::RailIrregularity;
use loco_core::vehicle::model::elements::BodyStates;
use loco_core::vehicle::model::layout::*;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameters::ParameterSet;
use loco_core::vehicle::rail_contact::wheel_rail::{ContactMode, WheelForces};

use crate::curve_support::cone::{half_distance, run_cone, G};
use crate::curve_support::CurveRun;

/// The roll moments (N·m) about the vehicle origin's centre line at rail level in a steady
/// balanced curve, from the state at the end of a run.
#[derive(Debug, Clone, Copy)]
struct RollMoments {
    /// The rails' wheel loads at the nominal contact points ±l: −(outer − inner)·l plus the
    /// loads' offsets x²κ/2 (what a balance with fixed contacts assumes).
    nominal: f64,
    /// The rails' whole wrench on the wheelsets (every contact point where it is, the lateral
    /// forces at their heights, the spin moments), from `WheelRail::apply` at the final state.
    rails: f64,
    /// What the bodies need from the rails: their resultants normal to the track plane at
    /// their centres of gravity, less the spinning parts' gyroscopic moment V κ H.
    bodies: f64,
}

/// The rails' whole roll moment on the wheelsets of `r` (see [`RollMoments::rails`]): each
/// wheelset's contact wrench about its centre (its own frame, yawed x κ from the origin's)
/// moved to the origin's centre line at rail level.
fn rail_roll_moment(
    r: &CurveRun,
    structure: &VehicleStructure,
    states: &BodyStates,
    radius: f64,
    speed: f64,
) -> f64 {
    let kappa = 1.0 / radius;
    // Balanced cant: tan θ = V²κ/g; the wheelsets roll with their frames' yaw rate V κ cos θ.
    let theta = (speed * speed * kappa / G).atan();
    let mut moment = 0.0;
    for w in 0..N_WHEELSETS {
        let body = body_wheelset(w);
        let mut s = states.clone();
        s.velocity[body][5] += speed * kappa * theta.cos();
        let mut wrenches = [[0.0; 6]; N_BODIES];
        let mut out = [WheelForces::default(); 2];
        r.system
            .wheel_rail
            .apply(
                w,
                0.0,
                &s,
                &r.system
                    .wheel_rail
                    .rail_plane(&RailIrregularity::default(), speed),
                speed,
                ContactMode::Rolling,
                &mut wrenches,
                &mut out,
            )
            .unwrap();
        let m = wrenches[body];
        let x = structure.bodies[body].position[0];
        let psi = x * kappa;
        let lateral = states.position[body][1] + x * x * kappa / 2.0;
        let height = structure.bodies[body].position[2] + states.position[body][2];
        // In the origin's frame: M_x = M_x' − ψ M_y', F_y = F_y' + ψ F_x'; then r × F.
        moment += m[3] - psi * m[4] + lateral * m[2] - height * (m[1] + psi * m[0]);
    }
    moment
}

/// Outer minus inner wheel loads summed over the vehicle (N), measured, and as the roll-moment
/// balance of the whole vehicle about the centre line at rail level predicts it with the
/// contacts at ±l; the mean side load (N); and the roll moments. On a cone of conicity `lambda`
/// on knife-edge rails (0: the S_norm profiles).
fn load_balance(lambda: f64, radius: f64, speed: f64) -> (f64, f64, f64, RollMoments) {
    let p = ParameterSet::default_vehicle();
    let r = run_cone(p.clone(), lambda, radius, speed, 300.0);
    let structure = VehicleStructure::new(p).unwrap();
    let mut states = BodyStates::default();
    structure.body_states(&r.y[..N_DOF], &r.y[N_DOF..2 * N_DOF], &mut states);
    let kappa = 1.0 / radius;
    // At balanced cant each body's weight and centripetal force add to a force normal to the
    // track plane, m·√(g² + (V²κ)²), at its centre of gravity; the knife-edge rails hold the
    // contact points at ±l from the centre line. Everything in the vehicle origin's frame,
    // where the centre line at distance x lies x²κ/2 inward.
    let l = half_distance(&r.system.wheel_rail);
    let g_n = (G * G + (speed * speed * kappa).powi(2)).sqrt();
    let (mut weights, mut spin) = (0.0, 0.0);
    for (i, b) in structure.bodies.iter().enumerate() {
        let centre_line = b.position[0].powi(2) * kappa / 2.0;
        weights += b.mass * g_n * (b.position[1] + states.position[i][1] + centre_line);
        spin += b.spin_momentum_per_speed * speed;
    }
    let (mut inner, mut outer, mut supports) = (0.0, 0.0, 0.0);
    for w in 0..N_WHEELSETS {
        let f = r.system.wheel_forces[w];
        let x = structure.bodies[body_wheelset(w)].position[0];
        inner += f[0].vertical;
        outer += f[1].vertical;
        supports += (f[0].vertical + f[1].vertical) * x * x * kappa / 2.0;
    }
    // The spinning parts' angular momentum H (about the axles) turned at the frame's yaw rate
    // V κ needs the roll moment V κ H from the rails (gyroscopic load on the outer wheels).
    let gyroscopic = speed * kappa * spin;
    let predicted = -(weights - supports - gyroscopic) / l;
    let moments = RollMoments {
        nominal: -(outer - inner) * l + supports,
        rails: rail_roll_moment(&r, &structure, &states, radius, speed),
        bodies: weights - gyroscopic,
    };
    (outer - inner, predicted, 0.5 * (outer + inner), moments)
}

#[test]
fn balanced_cant_wheel_loads_differ_by_the_roll_moment_of_the_outward_running_vehicle() {
    // At balanced cant the resultant on every body is normal to the track plane, but the wheel
    // loads are equal only if the vehicle's centre of mass sits over the middle of its wheel
    // contacts. The wheelsets run toward the outer rail (at least r0·l/(λR) for pure rolling,
    // more for a bogie with primary yaw stiffness), the sprung masses follow them, and the
    // spinning parts turning with the track need a roll moment (gyroscopic, outer wheels
    // loaded): ΔQ·l = W·e + V κ H, the roll-moment balance of the whole vehicle (statics,
    // hand-written here from the bodies' positions, not from the model's forces). The conical
    // wheel on knife-edge rails keeps the contacts at ±l, so the balance predicts ΔQ from the
    // bodies' lateral positions alone.
    let (mut worst_balance, mut near_centre) = (0.0_f64, 0.0_f64);
    for (radius, speed) in [(3000.0, 10.0), (3000.0, 30.0), (15000.0, 20.0)] {
        let (measured, predicted, mean, m) = load_balance(0.1, radius, speed);
        println!(
            "  roll moments: rails at ±l {:.0} N·m, rails' whole wrench {:.0} N·m, bodies {:.0} N·m",
            m.nominal, m.rails, m.bodies
        );
        println!(
            "R {radius} m, V {speed} m/s: outer - inner {measured:.0} N (moment balance \
             {predicted:.0} N), {:.2} % of the mean side load",
            100.0 * measured / mean
        );
        // Measured within 0.6 % of the balance (5632 / 5617 N, 6464 / 6424 N, 1115 / 1113 N);
        // the gyroscopic part (∝ V², 100 N to 900 N here) is in it. Before the contact offsets
        // were applied as the table gives them, the loads came out 11 % below the balance at
        // every radius and speed: the contact forces' lever arms, already in track axes at the
        // wheelset's pose, were turned by its roll again, a spurious roll moment r0·φ·ΣQ
        // (434 N·m at 3000 m, ∝ κ through the roll φ of the outward-running wheelsets, 81 N·m
        // at 15 km). Separating the wrench per wheelset found
        // it: the gap was r0·φ·ΣQ plus a 2 mm lever of ΣY within 1 %.
        assert!(measured > 0.0 && (measured - predicted).abs() < 0.02 * predicted);
        assert!((m.rails - m.bodies).abs() < 0.02 * m.bodies.abs(), "{m:?}");
        assert!(
            (m.rails - m.nominal).abs() < 0.02 * m.nominal.abs(),
            "{m:?}"
        );
        if radius > 10_000.0 {
            // The "equal within 1 %" where the vehicle runs near the centre line.
            assert!(measured < 0.01 * mean, "{measured} of {mean}");
            near_centre = measured / mean;
        }
        worst_balance = worst_balance.max((measured - predicted).abs() / predicted);
    }
    // The S_norm pair at R = 1200 m (the 4.1 % of `curving.rs`): the whole rail wrench closes
    // the bodies' balance the same way (measured 1400 against 1381 N·m, 1.4 %), so what the
    // balance at ±l misses (it explains 7.4 of the 15.3 kN) is where the contact points sit on
    // the rail heads and at what height the lateral forces act: 6.1 kN·m, the loads' resultant
    // about 8 mm inward of ±l over the vehicle's 740 kN (two-point contact on the leading outer
    // wheels, the gauge-side point well inside the tread's).
    let (measured, predicted, mean, m) = load_balance(0.0, 1200.0, 28.08);
    println!(
        "S_norm, R 1200 m: outer - inner {measured:.0} N (balance at ±l {predicted:.0} N), \
         {:.2} %; roll moments: rails at ±l {:.0} N·m, rails' whole wrench {:.0} N·m, bodies \
         {:.0} N·m",
        100.0 * measured / mean,
        m.nominal,
        m.rails,
        m.bodies
    );
    assert!((m.rails - m.bodies).abs() < 0.02 * m.bodies.abs(), "{m:?}");
    Record::new("curve_wheel_loads", file!())
        .within("cone_balance_deviation", worst_balance, "", 2, "<", 0.02)
        .within(
            "cone_unbalance_near_centre_line",
            near_centre,
            "",
            2,
            "<",
            0.01,
        )
        .value("s_norm_unbalance", measured / mean, "", 2)
        .within(
            "s_norm_rails_against_bodies",
            (m.rails - m.bodies).abs() / m.bodies.abs(),
            "",
            2,
            "<",
            0.02,
        )
        .check();
}
