//! Contact tables: the rigid contact state on a uniform grid of lateral displacements, for the
//! vehicle model's time loop.
//!
//! Interpolation is **linear on a fine uniform grid** (default 0.1 mm over ±15 mm): the contact
//! quantities jump where the contact moves from tread to flange, and a cubic interpolant would
//! overshoot there; on a 0.1 mm grid linear interpolation errors elsewhere are far below the
//! profiles' own accuracy. Because the grid is uniform the lookup is an index computation (no
//! search), well under 100 ns (bench `contact_table`).
//!
//! Relative roll. The rigid pose rolls the wheelset until both wheels touch; a running wheelset
//! rolls a little more or less relative to its rails (elastic load transfer, and on a gauge
//! irregularity each wheel is read at its own rail's offset, where the rigid roll differs: on the
//! conformal worn tread, 0.43 rad/m of rigid roll against lateral position). Measured in
//! `tests/verification/rolled_rails.rs`: up to 2.5e-4 rad on S_high, 5e-5 on S_norm and S_low — enough to
//! move a conformal contact point by a tenth of a millimetre and the study's S_high metrics by
//! about 2 %. So each wheel's contact is also solved at the rigid roll ± [`ROLL_LAYER`], each
//! wheel lowered onto its own rail ([`ContactGeometry::solve_rolled`]), and
//! [`ContactTable::lookup_wheel`] interpolates in the wheelset's roll as well (bilinear, clamped
//! to the layers; beyond them the vehicle's interference term carries the rest of the roll).
//!
//! Each wheel keeps two slots (field-side/tread and gauge-side/flange point, see
//! [`WheelContact`]); while building, a single contact point is put in the slot whose position on
//! the wheel at the neighbouring grid point is nearest, so that each slot varies continuously.
//! Where a slot exists at only one of the two grid points around `y`, the lookup returns it only
//! in the half cell nearer to that point.

use super::geometry::{
    ContactGeometry, ContactPoint, ContactWorkspace, WheelContact, WheelsetContact,
};
use crate::error::{check_finite, check_positive, LocoError, Result};

/// Grid of a contact table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactTableParams {
    /// Smallest lateral displacement, m (−0.015).
    pub y_min: f64,
    /// Largest lateral displacement, m (+0.015).
    pub y_max: f64,
    /// Grid step, m (1e-4).
    pub step: f64,
}

impl Default for ContactTableParams {
    fn default() -> Self {
        Self {
            y_min: -0.015,
            y_max: 0.015,
            step: 1e-4,
        }
    }
}

/// Roll (rad) of the relative-roll layers about the rigid pose: the table holds the wheels'
/// contact at the rigid roll and at ± this.
pub const ROLL_LAYER: f64 = 1e-3;

/// Contact states on a uniform grid of lateral displacements.
#[derive(Debug, Clone)]
pub struct ContactTable {
    y_min: f64,
    step: f64,
    rows: Vec<WheelsetContact>,
    /// Per layer (rigid roll − and + [`ROLL_LAYER`]), per row, per wheel: the rise (m) at which
    /// that wheel touches and its contact.
    rolled: [Vec<[(f64, WheelContact); 2]>; 2],
}

/// One wheel's contact read from a table at a roll of the wheelset relative to its rails.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelLookup {
    /// Roll of the wheelset at which the points hold, rad: the asked roll, clamped to the
    /// layers around the rigid pose.
    pub roll: f64,
    /// Rise of the wheelset centre from its centred pose at which this wheel touches, m.
    pub rise: f64,
    /// The wheel's contact points at that pose.
    pub contact: WheelContact,
}

impl ContactTable {
    /// Solves the geometry at every grid point (sweeping outward from the grid point nearest to
    /// y = 0, each solve warm-started from its neighbour).
    pub fn build(geometry: &ContactGeometry, params: &ContactTableParams) -> Result<Self> {
        check_finite("y_min", params.y_min)?;
        check_finite("y_max", params.y_max)?;
        check_positive("step", params.step)?;
        if params.y_max <= params.y_min {
            return Err(LocoError::param("y_max", "must be larger than y_min"));
        }
        let n = ((params.y_max - params.y_min) / params.step).round() as usize + 1;
        if !(2..=1_000_000).contains(&n) {
            return Err(LocoError::param(
                "step",
                format!("gives {n} grid points (2 .. 1e6)"),
            ));
        }
        let y_at = |i: usize| params.y_min + params.step * i as f64;
        let centre = ((0.0 - params.y_min) / params.step)
            .round()
            .clamp(0.0, (n - 1) as f64) as usize;
        let mut rows = vec![WheelsetContact::default(); n];
        let mut ws = ContactWorkspace::default();
        rows[centre] = geometry.solve_with(y_at(centre), geometry.roll_at_centre(), &mut ws)?;
        for i in (centre + 1)..n {
            let mut row = geometry.solve_with(y_at(i), rows[i - 1].roll, &mut ws)?;
            keep_slots_continuous(&mut row, &rows[i - 1]);
            rows[i] = row;
        }
        for i in (0..centre).rev() {
            let mut row = geometry.solve_with(y_at(i), rows[i + 1].roll, &mut ws)?;
            keep_slots_continuous(&mut row, &rows[i + 1]);
            rows[i] = row;
        }
        let rolled = [-ROLL_LAYER, ROLL_LAYER].map(|offset| -> Result<_> {
            let mut layer = vec![[(0.0, WheelContact::default()); 2]; n];
            let mut solve = |i: usize, neighbour: Option<&[(f64, WheelContact); 2]>| {
                let mut wheels = geometry.solve_rolled(y_at(i), rows[i].roll + offset, &mut ws)?;
                if let Some(prev) = neighbour {
                    for s in 0..2 {
                        keep_slot_continuous(&mut wheels[s].1, &prev[s].1);
                    }
                }
                Ok::<_, LocoError>(wheels)
            };
            layer[centre] = solve(centre, None)?;
            for i in (centre + 1)..n {
                layer[i] = solve(i, Some(&layer[i - 1]))?;
            }
            for i in (0..centre).rev() {
                layer[i] = solve(i, Some(&layer[i + 1]))?;
            }
            Ok(layer)
        });
        let [minus, plus] = rolled;
        Ok(Self {
            y_min: params.y_min,
            step: params.step,
            rows,
            rolled: [minus?, plus?],
        })
    }

    /// Range `(y_min, y_max)` of the grid, m. Lookups outside return the end values.
    pub fn y_range(&self) -> (f64, f64) {
        (
            self.y_min,
            self.y_min + self.step * (self.rows.len() - 1) as f64,
        )
    }

    /// Grid step, m.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The solved grid points.
    pub fn rows(&self) -> &[WheelsetContact] {
        &self.rows
    }

    /// Contact state at lateral displacement `y` (m, + left), interpolated linearly; `y` outside
    /// the grid is clamped to it (and a NaN `y` gives the first grid point): check
    /// [`Self::y_range`] for derailment.
    #[inline]
    pub fn lookup(&self, y: f64) -> WheelsetContact {
        let (i, w) = self.cell(y);
        let (a, b) = (&self.rows[i], &self.rows[i + 1]);
        let mut out = WheelsetContact {
            lateral_displacement: y,
            rise: lerp(a.rise, b.rise, w),
            roll: lerp(a.roll, b.roll, w),
            wheels: [WheelContact::default(); 2],
        };
        for s in 0..2 {
            out.wheels[s] = lerp_wheel(&a.wheels[s], &b.wheels[s], w);
        }
        out
    }

    /// The contact of the wheel on `side` (0 left, 1 right) at lateral displacement `y` (m)
    /// with the wheelset rolled by `roll` (rad, relative to the rails), interpolated in both.
    #[inline(always)]
    pub fn lookup_wheel(&self, y: f64, side: usize, roll: f64) -> WheelLookup {
        let (i, w) = self.cell(y);
        let (a, b) = (&self.rows[i], &self.rows[i + 1]);
        let rigid = lerp(a.roll, b.roll, w);
        let offset = (roll - rigid).clamp(-ROLL_LAYER, ROLL_LAYER);
        let offset = if offset.is_nan() { 0.0 } else { offset };
        let layer = &self.rolled[usize::from(offset > 0.0)];
        let f = offset.abs() / ROLL_LAYER;
        let (ra, rb) = (&layer[i][side], &layer[i + 1][side]);
        let at_rigid = lerp_wheel(&a.wheels[side], &b.wheels[side], w);
        let at_layer = lerp_wheel(&ra.1, &rb.1, w);
        WheelLookup {
            roll: rigid + offset,
            rise: lerp(lerp(a.rise, b.rise, w), lerp(ra.0, rb.0, w), f),
            contact: lerp_wheel(&at_rigid, &at_layer, f),
        }
    }

    /// Grid cell `i` and weight `w` of `y` (m): clamped to the grid, a NaN reads the first cell.
    #[inline]
    fn cell(&self, y: f64) -> (usize, f64) {
        let last = self.rows.len() - 1;
        let x = ((y - self.y_min) / self.step).clamp(0.0, last as f64);
        let x = if x.is_nan() { 0.0 } else { x };
        let i = (x as usize).min(last - 1);
        (i, x - i as f64)
    }

    /// Rolling radius difference left − right (m) at each `ys` (m), from the table.
    pub fn rolling_radius_difference(&self, ys: &[f64]) -> Vec<f64> {
        ys.iter()
            .map(|&y| self.lookup(y).rolling_radius_difference())
            .collect()
    }
}

/// Rolling radius difference Δr = r_left − r_right (m) at each lateral displacement in `ys` (m)
/// as EN 15302 defines it for equivalent conicity: the wheelset is translated laterally without
/// roll and each wheel touches its rail at its own lowest point
/// ([`ContactGeometry::rolling_radius_difference_unrolled`]), solved exactly (no table).
///
/// Why not the rigidly rolled wheelset of [`ContactGeometry::solve`] (the vehicle model's
/// contact): the standard's benchmark Δr functions (`dr_E*.dat`, EN 15302 Annex E) are those of
/// the unrolled wheelset. From the reference profiles, unrolled Δr matches them at the grid points
/// to a median of 0.002–0.025 mm per case, rolled Δr only to 0.04–0.25 mm (and by up to 8 mm near
/// flange contact, where 0.5–1 mrad of roll turns the flange r·φ ≈ 0.25–0.45 mm further toward
/// the rail); see `tests/verification/conicity_en15302_profiles.rs`. On the tread the two differ little, but
/// a conformal worn tread (`jm3-worn` on CN60) rolls enough to change tan γe(3 mm) by 0.07.
pub fn rolling_radius_difference(geometry: &ContactGeometry, ys: &[f64]) -> Result<Vec<f64>> {
    let mut ws = ContactWorkspace::default();
    ys.iter()
        .map(|&y| geometry.rolling_radius_difference_unrolled(y, &mut ws))
        .collect()
}

#[inline]
fn lerp(a: f64, b: f64, w: f64) -> f64 {
    a + (b - a) * w
}

/// Interpolates a wheel's slots; a slot present at one end only is kept in its half.
#[inline(always)]
fn lerp_wheel(a: &WheelContact, b: &WheelContact, w: f64) -> WheelContact {
    let mut out = WheelContact::default();
    for k in 0..2 {
        out.points[k] = match (&a.points[k], &b.points[k]) {
            (Some(p), Some(q)) => Some(lerp_point(p, q, w)),
            (Some(p), None) if w < 0.5 => Some(*p),
            (None, Some(q)) if w >= 0.5 => Some(*q),
            _ => None,
        };
    }
    out
}

#[inline]
fn lerp_point(p: &ContactPoint, q: &ContactPoint, w: f64) -> ContactPoint {
    ContactPoint {
        gap: lerp(p.gap, q.gap, w),
        lateral: lerp(p.lateral, q.lateral, w),
        vertical: lerp(p.vertical, q.vertical, w),
        rolling_radius: lerp(p.rolling_radius, q.rolling_radius, w),
        contact_angle: lerp(p.contact_angle, q.contact_angle, w),
        wheel_curvature: lerp(p.wheel_curvature, q.wheel_curvature, w),
        rail_curvature: lerp(p.rail_curvature, q.rail_curvature, w),
        wheel_y: lerp(p.wheel_y, q.wheel_y, w),
        rail_y: lerp(p.rail_y, q.rail_y, w),
    }
}

/// Moves a lone contact point into the slot it occupied at the neighbouring grid point.
fn keep_slots_continuous(row: &mut WheelsetContact, neighbour: &WheelsetContact) {
    for s in 0..2 {
        keep_slot_continuous(&mut row.wheels[s], &neighbour.wheels[s]);
    }
}

/// As [`keep_slots_continuous`] for one wheel.
fn keep_slot_continuous(wheel: &mut WheelContact, neighbour: &WheelContact) {
    if let [Some(p), None] = wheel.points {
        let prev = &neighbour.points;
        let dist =
            |q: &Option<ContactPoint>| q.map_or(f64::INFINITY, |q| (q.wheel_y - p.wheel_y).abs());
        if dist(&prev[1]) < dist(&prev[0]) {
            wheel.points = [None, Some(p)];
        }
    }
}
