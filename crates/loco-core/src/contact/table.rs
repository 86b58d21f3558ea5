//! Contact tables: the rigid contact state on a uniform grid of lateral displacements, for the
//! vehicle model's time loop.
//!
//! Interpolation is **linear on a fine uniform grid** (default 0.1 mm over ±15 mm): the contact
//! quantities jump where the contact moves from tread to flange, and a cubic interpolant would
//! overshoot there; on a 0.1 mm grid linear interpolation errors elsewhere are far below the
//! profiles' own accuracy. Because the grid is uniform the lookup is an index computation (no
//! search), well under 100 ns (bench `contact_table`).
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

/// Contact states on a uniform grid of lateral displacements.
#[derive(Debug, Clone)]
pub struct ContactTable {
    y_min: f64,
    step: f64,
    rows: Vec<WheelsetContact>,
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
        Ok(Self {
            y_min: params.y_min,
            step: params.step,
            rows,
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
        let last = self.rows.len() - 1;
        let x = ((y - self.y_min) / self.step).clamp(0.0, last as f64);
        let x = if x.is_nan() { 0.0 } else { x };
        let i = (x as usize).min(last - 1);
        let w = x - i as f64;
        let (a, b) = (&self.rows[i], &self.rows[i + 1]);
        let mut out = WheelsetContact {
            lateral_displacement: y,
            rise: lerp(a.rise, b.rise, w),
            roll: lerp(a.roll, b.roll, w),
            wheels: [WheelContact::default(); 2],
        };
        for s in 0..2 {
            for k in 0..2 {
                out.wheels[s].points[k] = match (&a.wheels[s].points[k], &b.wheels[s].points[k]) {
                    (Some(p), Some(q)) => Some(lerp_point(p, q, w)),
                    (Some(p), None) if w < 0.5 => Some(*p),
                    (None, Some(q)) if w >= 0.5 => Some(*q),
                    _ => None,
                };
            }
        }
        out
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
/// the rail); see `tests/conicity_en15302_profiles.rs`. On the tread the two differ little, but
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
        let wheel = &mut row.wheels[s];
        if let [Some(p), None] = wheel.points {
            let prev = &neighbour.wheels[s].points;
            let dist = |q: &Option<ContactPoint>| {
                q.map_or(f64::INFINITY, |q| (q.wheel_y - p.wheel_y).abs())
            };
            if dist(&prev[1]) < dist(&prev[0]) {
                wheel.points = [None, Some(p)];
            }
        }
    }
}
