//! Wheel-rail forces on the four wheelsets: elastic normal contact, creepages and FASTSIM.
//!
//! Everything geometric is done in the rails' plane at the wheelset ([`crate::vehicle::rail_contact::rail_plane`]): on a
//! cross level the two rails stand at different heights, the plane is rolled by θ, and the
//! wheelset's pose relative to the rails (lateral `y'`, which includes `h0·θ`, and roll `φ − θ`)
//! is what the contact table is read at; contact points and frames come back into the track frame
//! rotated by θ. Each wheel reads the table at the wheelset's position relative to its own rail
//! (so gauge irregularities move each contact on its own), and at the wheelset's roll relative
//! to the rails (the table's relative-roll layers, `contact::table`). The table gives the pose
//! (rise, roll) at which the wheel just touches and up to two contact points per wheel (tread and
//! flange) with their geometry. The normal contact is elastic: the interference of a point is how
//! far the wheel sits below that pose at that point (`rise + roll·l + z_rail − z − φ·l − gap`,
//! all in the plane), its normal part `δ = interference·cos γ` gives the Hertz force
//! `N = K_H δ^{3/2}` (K_H from the curvatures at the point) plus a small normal damping `c_n δ̇`
//! (δ̇ from the slip velocity along the normal) that keeps the unsprung masses from ringing on
//! the stiff contact.
//!
//! Creepages follow the general definition of `contact::creepage`: the wheel's angular velocity
//! about its rolled and yawed axle, the contact offsets rotated with the rails, so rolled rails
//! give no rolling-radius difference. A yawed wheel touches a steep flange ahead of or behind its
//! axle (`contact::creepage::contact_lead`, 17 mm at 15 mrad on a flange); the contact point is
//! placed there, which gives the flange's lateral creepage and the lead's yaw moment (Manchester
//! normal force in flange contact within 1 % with it, 5–32 % high without). The vertical
//! velocity of a wheel following a vertical irregularity is along the rail's longitudinal slope,
//! not a slip, so the rail surface's velocity (the plane's vertical and roll rates) is
//! subtracted. FASTSIM gives the tangential forces in the contact plane.

use crate::contact::creepage::{
    contact_lead_sin_cos, creepages_of_slip, dot, slip_velocity, BodyVelocity, ContactFrame, Side,
};
use crate::contact::fastrip::Fastrip;
use crate::contact::fastsim::Fastsim;
use crate::contact::fastsim_table::FastsimTable;
use crate::contact::hertz_table::HertzShapeTable;
use crate::contact::kalker::{CreepForces, Creepages};
use crate::contact::table::ContactTable;
use crate::error::{LocoError, Result};
use crate::simd::multiversion;
use crate::track::RailIrregularity;
use crate::vehicle::model::elements::{BodyStates, Wrenches};
use crate::vehicle::model::layout::{body_wheelset, N_WHEELSETS, PITCH, ROLL, YAW};
use crate::vehicle::rail_contact::rail_plane::RailPlane;
use pending_contact::{add_forces, Creep, Pending};
use std::sync::Arc;

/// Settings of the wheel-rail contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelRailSettings {
    /// Wheel-rail friction coefficient μ (–).
    pub friction: f64,
    /// Contact modulus E* = E / (2(1 − ν²)) of steel on steel, Pa.
    pub contact_modulus: f64,
    /// Viscous damping of the normal contact, N·s/m per contact.
    pub normal_damping: f64,
    /// Nominal rolling radius r0, m.
    pub nominal_radius: f64,
    /// Half the lateral distance between the nominal contact points, b, m: the rails' roll on a
    /// cross level c is atan(c / 2b).
    pub contact_half_distance: f64,
}

/// How the tangential contact forces are found: by creep while running, or held in the static
/// equilibrium search (set by [`crate::vehicle::system::statics::StaticsSettings`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum ContactMode {
    /// Running: creep forces (FASTSIM).
    #[default]
    Rolling,
    /// Static search: nothing rolls; each patch is held by a tangential spring of
    /// `tangential_stiffness` (N/m) and the brakes hold the spin.
    Held { tangential_stiffness: f64 },
}

/// Forces at one wheel, for outputs (track frame, on the wheel).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelForces {
    /// Vertical wheel-rail force Q, N (positive: rail pushes the wheel up).
    pub vertical: f64,
    /// Lateral wheel-rail force Y, N (+ left).
    pub lateral: f64,
    /// Longitudinal force, N (+ forward).
    pub longitudinal: f64,
    /// Number of points in contact (0, 1, 2).
    pub points_in_contact: u8,
    /// Wear number T·γ, N (J/m): the frictional work per distance rolled of the creep forces
    /// and the spin moment on their creepages, −(Fx ξ + Fy η + Mz φ), summed over the loaded
    /// points; 0 in the static search. Pearce & Sherratt's T·γ (Wear 144 (1991) 343–351) leaves
    /// the spin term out; with spin-coupled creep forces (FASTSIM) that partial sum can go
    /// slightly negative on a wheel (−0.5 N seen in a 1200 m curve), the whole sum cannot.
    pub wear_number: f64,
    /// Largest contact angle of the loaded points in the rails' plane, rad (positive toward the
    /// flange, see `ContactPoint::contact_angle`); 0 when no point is loaded.
    pub contact_angle: f64,
}

/// How the tangential creep forces are computed.
// One solver per run, held by value: its size does not matter, a box would add an indirection to
// every creep-force call.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum CreepSolver {
    /// FASTSIM at every evaluation (the study's method, exact for its grid).
    Direct(Fastsim),
    /// FASTSIM's normalised results interpolated from a table built once (faster per call;
    /// force error about 2 % of μN, see `contact::fastsim_table`).
    Tabulated(Arc<FastsimTable>),
    /// FaStrip (strip theory with spin, see `contact::fastrip`) at every evaluation.
    Strip(Fastrip),
}

impl CreepSolver {
    #[inline]
    pub(in crate::vehicle) fn creep_forces(
        &self,
        a: f64,
        b: f64,
        n: f64,
        mu: f64,
        creep: &Creepages,
    ) -> CreepForces {
        #[cfg(feature = "record-contacts")]
        crate::vehicle::rail_contact::contact_recording::record(a, b, n, mu, creep);
        match self {
            CreepSolver::Direct(f) => f.creep_forces(a, b, n, mu, creep),
            CreepSolver::Tabulated(t) => t.creep_forces(a, b, n, mu, creep),
            CreepSolver::Strip(s) => s.creep_forces(a, b, n, mu, creep),
        }
    }
}

/// The contact of all wheels with a given table, creep solver and settings.
#[derive(Debug, Clone)]
pub struct WheelRail {
    table: ContactTable,
    creep: CreepSolver,
    settings: WheelRailSettings,
    /// Hertz shape functions, tabulated: curvatures change at every evaluation.
    hertz: HertzShapeTable,
    /// Rolling radius of the centred wheelset (mean of both wheels at y = 0), m: free rolling at
    /// speed V turns the wheelset at V / this, so a centred wheelset has no longitudinal creep.
    centred_radius: f64,
}

const SIDES: [Side; 2] = [Side::Left, Side::Right];

impl WheelRail {
    /// Wraps a contact table and a creep solver.
    pub fn new(table: ContactTable, creep: CreepSolver, settings: WheelRailSettings) -> Self {
        let centre = table.lookup(0.0);
        let radius = |side: usize| {
            centre.wheels[side]
                .touching()
                .map_or(settings.nominal_radius, |p| p.rolling_radius)
        };
        let centred_radius = 0.5 * (radius(0) + radius(1));
        Self {
            table,
            creep,
            settings,
            hertz: HertzShapeTable::new(),
            centred_radius,
        }
    }

    /// Rolling radius of the centred wheelset, m.
    pub fn centred_radius(&self) -> f64 {
        self.centred_radius
    }

    /// Half the lateral distance between the nominal contact points, m.
    pub fn contact_half_distance(&self) -> f64 {
        self.settings.contact_half_distance
    }

    /// The contact table.
    pub fn table(&self) -> &ContactTable {
        &self.table
    }

    /// The rails' plane of `rails` (the irregularities at a wheelset's position) seen at
    /// `speed` V (m/s): the frame [`Self::apply`] reads the table in.
    #[inline]
    pub fn rail_plane(&self, rails: &RailIrregularity, speed: f64) -> RailPlane {
        RailPlane::new(rails, self.settings.contact_half_distance, speed)
    }

    /// Adds the wheel-rail forces on wheelset `w` at time `t` (s, for error messages) to
    /// `wrenches`; `plane` is the rails' plane at the wheelset's position ([`Self::rail_plane`]),
    /// `speed` is V (m/s).
    /// [`ContactMode::Held`] replaces the creep forces by a tangential spring (N/m) at each
    /// contact and a brake on the spin, holding the wheels in the static equilibrium search.
    /// On a processor with AVX the same code runs compiled for it; the bits are the same either
    /// way (see [`apply_copy`]).
    #[allow(clippy::too_many_arguments)]
    pub fn apply(
        &self,
        w: usize,
        t: f64,
        states: &BodyStates,
        plane: &RailPlane,
        speed: f64,
        mode: ContactMode,
        wrenches: &mut Wrenches,
        out: &mut [WheelForces; 2],
    ) -> Result<()> {
        apply_copy(self, w, t, states, plane, speed, mode, wrenches, out)
    }

    /// The body of [`Self::apply`], inlined into each of its compilations.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn apply_on(
        &self,
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
        let spin = speed / self.centred_radius + v[PITCH];
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
            let r0 = self.centred_radius;
            wrenches[body][PITCH] -= static_stiffness * r0 * r0 * u[PITCH];
        }
        // The table is read in the rails' plane (see `rail_plane`).
        let h0 = self.centred_radius;
        let pose_in_plane = plane.pose(u[1], u[2], u[ROLL], h0);
        let (s_theta, c_theta) = plane.roll_sin_cos();
        let yaw_sin_cos = u[YAW].sin_cos();
        // Both wheels' points before any creep force (why: `pending_contact`).
        let mut pending = [Pending::default(); 4];
        let mut n_pending = 0;
        let mut sides_done = 0;
        let mut found = Ok(());
        'sides: for (side_index, side) in SIDES.iter().enumerate() {
            let s = side.sign();
            let y_rel = plane.table_position(pose_in_plane.lateral, side_index);
            let (lo, hi) = self.table.y_range();
            if !(lo..=hi).contains(&y_rel) {
                // A runaway state (numerical divergence) is told apart from this by
                // `VehicleSystem::finish_step`, which checks the state before reporting this error.
                found = Err(LocoError::Derailed {
                    time: t,
                    location: format!("wheelset{} {}", w + 1, side_name(*side)),
                    reason: format!(
                        "lateral position {y_rel:.4} m relative to the rail is beyond the contact \
                         table ({lo:.4} … {hi:.4} m): the flange has climbed or the state diverged"
                    ),
                });
                break 'sides;
            }
            let wheel = self
                .table
                .lookup_wheel(y_rel, side_index, pose_in_plane.roll);
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
                let hertz = match self.hertz.coefficients(
                    // Rolling-direction curvature of the wheel at a point whose normal is tilted
                    // by the contact angle from the radius (Meusnier): cos γ / r.
                    0.5 * cg / point.rolling_radius,
                    // A conformal point (flange root on the gauge corner) has a lateral relative
                    // curvature near zero; a floor of 1/(20 m) keeps the ellipse finite there.
                    (0.5 * (point.wheel_curvature + point.rail_curvature)).max(0.025),
                    self.settings.contact_modulus,
                ) {
                    Ok(hertz) => hertz,
                    Err(e) => {
                        found = Err(e);
                        break 'sides;
                    }
                };
                let normal = (hertz.load_from_approach(approach)
                    + self.settings.normal_damping * approach_rate)
                    .max(0.0);
                if normal == 0.0 {
                    continue;
                }
                let creep = if let ContactMode::Held {
                    tangential_stiffness: static_stiffness,
                } = mode
                {
                    // Static search: contact patches do not slide; displacement of the wheel
                    // surface at the contact (x − r·β, y + r·φ_el, in the rails' plane) against
                    // a tangential spring.
                    let dx = u[0] - point.rolling_radius * u[PITCH] - l * u[YAW];
                    let dy = pose_in_plane.lateral
                        + point.rolling_radius * (pose_in_plane.roll - wheel.roll);
                    Creep::Held(CreepForces {
                        fx: -static_stiffness * dx,
                        fy: -static_stiffness * dy * cg,
                        mz: 0.0,
                    })
                } else {
                    let (a, b) = hertz.semi_axes(normal);
                    Creep::Rolling(creepages_of_slip(&slip, &angular, &frame, speed), a, b)
                };
                pending[n_pending] = Pending {
                    side: side_index,
                    offset,
                    frame,
                    normal,
                    contact_angle: point.contact_angle,
                    creep,
                };
                n_pending += 1;
            }
            sides_done += 1;
        }
        let mut forces = [WheelForces::default(); 2];
        let friction = self.settings.friction;
        add_forces(
            &pending[..n_pending],
            &self.creep,
            friction,
            body,
            wrenches,
            &mut forces,
        );
        // A wheel's forces are reported once all its points are in (before an error or not).
        out[..sides_done].copy_from_slice(&forces[..sides_done]);
        found
    }
}

/// [`WheelRail::apply`], compiled for the baseline and for AVX (the `simd` module's dispatch).
/// Why AVX: the table look-up's interpolation of two contact points of nine quantities runs four
/// quantities per register instead of two, and the three-operand encoding spares the register
/// copies. The operations are the IEEE operations of the baseline code in its order (no fused
/// multiply-add, and Rust never contracts), and the library functions called are the same, so
/// the bits are.
#[multiversion(targets("x86_64+avx"))]
#[allow(clippy::too_many_arguments)]
fn apply_copy(
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
    contact.apply_on(w, t, states, plane, speed, mode, wrenches, out)
}

fn side_name(side: Side) -> &'static str {
    match side {
        Side::Left => "left wheel",
        Side::Right => "right wheel",
    }
}

/// Number of wheels.
pub const N_WHEELS: usize = 2 * N_WHEELSETS;

mod pending_contact;

#[cfg(test)]
mod tests;
