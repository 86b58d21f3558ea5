//! The track-following frames of a curved track: every body's coordinates are relative to the
//! track frame at its own distance s along the design (`track::design`), which runs along the
//! centre line at rail-top level, yawed by the heading Ψ(s) and rolled by the cant θ(s).
//!
//! What this adds to the equations of motion (SI units throughout):
//!
//! - **Suspension in one frame.** Elements join bodies whose frames differ (a bogie 5 m ahead of
//!   the carbody sees the track yawed by κ·5 m and the centre line moved by κ·(5 m)²/2). Their
//!   forces are formed in the frame of the vehicle's origin (the reference frame at s_r): each
//!   free body's frame offset from it (lateral Y = ∫(Ψ − Ψ(s_r)) ds, yaw ΔΨ, roll Δθ, all
//!   expressed in the rolled reference frame) is a rigid motion written into its coordinates, and
//!   the motion maps carry it to the attached bodies, so a vehicle that follows the track strains
//!   no element. The offsets' rates (ΔΨ̇ = V(κ_j − κ_r), Ẏ = V(ΔΨ − κ_r x_j), Δθ̇ = V(θ'_j − θ'_r))
//!   are what a yaw damper sees at curve entry. The wrenches are then turned into each body's
//!   own frame (`w − rot × w`, small angles).
//! - **Inertia of the moving frame.** On each body, in its own frame: gravity on the cant
//!   (−m g sin θ laterally, −m g cos θ vertically) and the centripetal d'Alembert force of the
//!   frame's acceleration V²κ (horizontal, outward: −m V²κ cos θ laterally, +m V²κ sin θ
//!   vertically); the frame's yaw acceleration in a clothoid, −I_z V² dκ/ds; the gyroscopic
//!   moments of the spinning parts from the frame's yaw rate V κ and roll rate V dθ/ds.
//! - **Rolling on a curve.** A wheelset's absolute yaw rate is its own plus the frame's V κ cos θ;
//!   it enters the creepages, so the outer wheel's contact point runs V κ b faster and pure
//!   rolling needs the rolling radius difference Δr = 2 b r0 κ.
//!
//! Left out (small, said here so they are not mistaken for modelled): Coriolis forces of the
//! bodies' velocities relative to their frames (2 V κ ẏ ≲ 1e-3 m/s²), centrifugal products of
//! inertia of the frame rotation ((V κ)² (I_z − I_y) sin θ), the roll acceleration at the kinks
//! of a linear run-off (a step of the roll rate), and the frame's roll rate in the creepages (the
//! wheel and the rails roll together about the rail-top line, which cancels at the tread).

use crate::simd::multiversion;
use crate::track::{DesignPoint, TrackDesign};
use crate::vehicle::model::elements::BodyStates;
use crate::vehicle::model::layout::{body_frame, body_motor, BODY_CARBODY, CARBODY};
use crate::vehicle::model::layout::{body_hollow_shaft, body_rotary_arm, body_traction_rod};
use crate::vehicle::model::layout::{
    body_wheelset, frame, motor, wheelset, N_BODIES, N_BOGIES, N_WHEELSETS,
};
use crate::vehicle::model::structure::VehicleStructure;
use std::sync::Arc;

/// The free bodies whose coordinates carry their frame offsets: (first coordinate, body).
fn free_bodies() -> [(usize, usize); 1 + N_BOGIES + 2 * N_WHEELSETS] {
    let mut out = [(CARBODY, BODY_CARBODY); 1 + N_BOGIES + 2 * N_WHEELSETS];
    for b in 0..N_BOGIES {
        out[1 + b] = (frame(b), body_frame(b));
    }
    for w in 0..N_WHEELSETS {
        out[1 + N_BOGIES + w] = (wheelset(w), body_wheelset(w));
        out[1 + N_BOGIES + N_WHEELSETS + w] = (motor(w), body_motor(w));
    }
    out
}

/// A body's mass properties and nominal place as the frame terms need them.
#[derive(Debug, Clone, Copy)]
struct FrameBody {
    mass: f64,
    /// Yaw moment of inertia, kg·m².
    yaw_inertia: f64,
    /// Nominal centre of gravity (x, y, z above rail top), m.
    position: [f64; 3],
    /// Spin angular momentum per running speed, kg·m.
    spin: f64,
}

/// A designed track and what the vehicle's frames need of it.
#[derive(Debug, Clone)]
pub struct CurvedTrack {
    pub design: Arc<TrackDesign>,
    bodies: Vec<FrameBody>,
    gravity: f64,
    /// The distinct distances (m) of the bodies' nominal centres ahead of the vehicle origin,
    /// the origin's own (0) first: bodies at one distance (a wheelset, its motor, its rotary
    /// arms) share one look-up of the design per evaluation.
    stations: Vec<f64>,
    /// Each body's index into `stations`.
    station_of: Vec<usize>,
    /// The bodies attached to a free one: (body, parent, nominal x_body − x_parent in m).
    attached: Vec<(usize, usize, [f64; 3])>,
    /// The bodies with spinning parts (spin momentum not 0), in order.
    spinning: Vec<usize>,
}

/// What the frames are at one vehicle position and speed: none of it depends on the state, so
/// it is kept for the RK stages that share a time (stages 2 and 3, stage 4 and the step's end, and
/// usually the next step's start) and computed twice per step instead of five times.
#[derive(Debug, Clone)]
struct FrameSlot {
    /// The track it was computed for (its address: a system given another track recomputes), and
    /// the bits of the origin's distance (m) and of the speed (m/s).
    key: Option<(usize, u64, u64)>,
    /// Each body's frame offset (its rotation part, rad) from the reference frame.
    offset_states: BodyStates,
    /// The design at each station (`CurvedTrack::stations`: at most one per body and the
    /// origin; body i's is `station_of[i]`) and sin θ, cos θ of its roll, read through the
    /// station index rather than copied per body.
    station_points: [DesignPoint; N_BODIES + 1],
    station_roll: [(f64, f64); N_BODIES + 1],
    /// The bits of the roll each station's sin and cos were taken of (constant cant keeps it,
    /// and the same bits give the same sin and cos).
    station_roll_bits: [Option<u64>; N_BODIES + 1],
    /// The frame terms of each body that do not depend on the state: those added to every
    /// wrench four bodies to a lane group, the spinning parts' in `loads`.
    lanes: [forces::ForceLanes; forces::GROUPS],
    loads: [FrameLoad; N_BODIES],
    /// −m g sin θ of each body (N), the lateral gravity less its state-dependent part.
    cant_gravity: [f64; N_BODIES],
    /// The track (address) and the speed's bits the terms were formed for: a station whose
    /// curvature, its rate, roll and roll rate keep their bits keeps its bodies' terms but for
    /// those of the offsets' rotation (in a steady curve, nearly all).
    terms_of: Option<(usize, u64)>,
}

/// A body's gyroscopic frame terms at one (distance, speed), each formed as `add_frame_forces`
/// used to form it inside every evaluation (same operations, same bits): the frame's yaw and
/// roll rates V κ cos θ and V dθ/ds (rad/s) and the spin momentum H = spin·V (N·m·s).
#[derive(Debug, Clone, Copy, Default)]
struct FrameLoad {
    yaw_rate: f64,
    roll_rate: f64,
    spin: f64,
}

impl Default for FrameSlot {
    fn default() -> Self {
        Self {
            key: None,
            offset_states: BodyStates::default(),
            station_points: [DesignPoint::default(); N_BODIES + 1],
            station_roll: [(0.0, 1.0); N_BODIES + 1],
            station_roll_bits: [None; N_BODIES + 1],
            lanes: [forces::ForceLanes::default(); forces::GROUPS],
            loads: [FrameLoad::default(); N_BODIES],
            cant_gravity: [0.0; N_BODIES],
            terms_of: None,
        }
    }
}

/// Workspaces and the last evaluation's frame data (no allocation in the time loop).
#[derive(Debug, Clone)]
pub struct FrameWork {
    /// Body states in the reference frame (what the suspension sees).
    pub states: BodyStates,
    /// The frames at the last two (distance, speed) pairs; `active` is the last evaluation's.
    slots: [FrameSlot; 2],
    active: usize,
    /// Each station's piece of the design in the last look-up, where the next one starts
    /// (`TrackDesign::at_from`: the vehicle moves on a little at a time).
    piece_hints: [usize; N_BODIES + 1],
}

impl Default for FrameWork {
    fn default() -> Self {
        Self {
            states: BodyStates::default(),
            slots: [FrameSlot::default(), FrameSlot::default()],
            active: 0,
            piece_hints: [0; N_BODIES + 1],
        }
    }
}

impl FrameWork {
    /// The frames of the last [`CurvedTrack::prepare`].
    fn slot(&self) -> &FrameSlot {
        &self.slots[self.active]
    }
}

impl CurvedTrack {
    /// The frames of `design` for the bodies of `structure`.
    pub fn new(design: Arc<TrackDesign>, structure: &VehicleStructure) -> Self {
        let bodies = structure
            .bodies
            .iter()
            .map(|b| FrameBody {
                mass: b.mass,
                yaw_inertia: b.inertia[2],
                position: b.position,
                spin: b.spin_momentum_per_speed,
            })
            .collect::<Vec<_>>();
        let mut stations = vec![0.0];
        let station_of = bodies
            .iter()
            .map(|b| {
                let x = b.position[0];
                // Bitwise equal distances give bitwise equal look-ups.
                match stations
                    .iter()
                    .position(|s: &f64| s.to_bits() == x.to_bits())
                {
                    Some(k) => k,
                    None => {
                        stations.push(x);
                        stations.len() - 1
                    }
                }
            })
            .collect();
        let mut parents = Vec::new();
        for w in 0..N_WHEELSETS {
            parents.push((body_hollow_shaft(w), body_wheelset(w)));
            for side in 0..2 {
                parents.push((body_rotary_arm(w, side), body_wheelset(w)));
            }
        }
        for b in 0..N_BOGIES {
            parents.push((body_traction_rod(b), BODY_CARBODY));
        }
        let attached = parents
            .into_iter()
            .map(|(body, parent)| {
                let (x, x0) = (bodies[body].position, bodies[parent].position);
                (body, parent, [x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]])
            })
            .collect();
        let spinning = (0..bodies.len())
            .filter(|&i| bodies[i].spin != 0.0)
            .collect();
        Self {
            design,
            bodies,
            spinning,
            gravity: structure.gravity,
            stations,
            station_of,
            attached,
        }
    }

    /// Fills `work` for the vehicle origin at distance `s_r` (m) running at `speed` (m/s): the
    /// design at every body and the body states seen in the reference frame, from the states
    /// `relative` to the bodies' own frames (`structure.body_states` of the coordinates).
    /// (`_structure`: the bodies are this track's own copy since the offsets no longer go
    /// through the motion maps; kept so callers need not change.)
    pub fn prepare(
        &self,
        _structure: &VehicleStructure,
        s_r: f64,
        speed: f64,
        relative: &BodyStates,
        work: &mut FrameWork,
    ) {
        let key = Some((self as *const Self as usize, s_r.to_bits(), speed.to_bits()));
        if let Some(k) = work.slots.iter().position(|slot| slot.key == key) {
            work.active = k;
        } else {
            // Replace the older slot, keep the last one (the stage before may come back).
            work.active = 1 - work.active;
            self.compute_frames(s_r, speed, work);
            work.slots[work.active].key = key;
        }
        let offset_states = &work.slots[work.active].offset_states;
        // The motion maps are linear: a body's state in the reference frame is its state
        // relative to its own frame plus its frame's offset (no second pass over the maps).
        add_states(&mut work.states, relative, offset_states);
    }

    /// The yaw rate of wheelset `w`'s track frame, V κ cos θ (rad/s), from the last
    /// [`Self::prepare`].
    #[inline]
    pub fn wheelset_frame_yaw_rate(&self, speed: f64, work: &FrameWork, w: usize) -> f64 {
        let slot = work.slot();
        let k = self.station_of[body_wheelset(w)];
        speed * slot.station_points[k].curvature * slot.station_roll[k].1
    }

    /// What an accelerometer fixed to `body`'s track frame reads (the frame's acceleration less
    /// gravity, in the frame's axes, m/s²) from the last [`Self::prepare`]: laterally
    /// g sin θ + V²κ cos θ, vertically g cos θ − V²κ sin θ (θ the frame's roll on the cant, the
    /// same terms the frame forces are formed of; the clothoid's small longitudinal and
    /// yaw-acceleration terms are left out).
    pub fn frame_specific_force(&self, work: &FrameWork, body: usize) -> [f64; 3] {
        let slot = work.slot();
        // The slot's key holds the bits of the speed it was prepared for.
        let speed = slot.key.map_or(0.0, |(_, _, v)| f64::from_bits(v));
        let k = self.station_of[body];
        let a = speed * speed * slot.station_points[k].curvature;
        let (s, c) = slot.station_roll[k];
        let g = self.gravity;
        [0.0, g * s + a * c, g * c - a * s]
    }
}

/// `sum = own + offset`, every position and velocity (one IEEE addition each, in any order:
/// the same bits). Five times per step: in the AVX copy (see the module `simd`) the compiler
/// takes four sums per instruction instead of two (0.8 % of a curved run less).
#[multiversion(targets("x86_64+avx"))]
fn add_states(sum: &mut BodyStates, own: &BodyStates, offset: &BodyStates) {
    add_states_plain(sum, own, offset);
}

#[inline(always)]
fn add_states_plain(sum: &mut BodyStates, own: &BodyStates, offset: &BodyStates) {
    let pairs = [
        (&mut sum.position, &own.position, &offset.position),
        (&mut sum.velocity, &own.velocity, &offset.velocity),
    ];
    for (sum, own, offset) in pairs {
        let (own, offset) = (own.as_flattened(), offset.as_flattened());
        for ((s, a), b) in sum.as_flattened_mut().iter_mut().zip(own).zip(offset) {
            *s = a + b;
        }
    }
}

mod forces;
mod offsets;

#[cfg(test)]
mod tests;
