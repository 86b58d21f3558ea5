//! One side of the wheelset (a wheel over its rail) prepared for the contact search, in its
//! "side frame": lateral coordinate `u` toward that side's field side, z up (see
//! [`super::geometry`]). Holds the wheel samples, the installed (inclined, placed) rail and the
//! gap function h(t) = Zrot(t) − R(u(t)) whose minima are the contact points.

use super::geometry::{ContactPoint, WheelContact};
use super::profile::Profile;
use super::setup::{ContactSearchParams, TrackSetup, WheelsetSetup};
use super::spline::CubicSpline;
use crate::error::{LocoError, Result};

/// One side (wheel + rail) prepared for the search, in its side frame.
#[derive(Debug, Clone)]
pub(super) struct Side {
    pub(super) wheel: Profile,
    /// Nominal radius r0 of this wheel, m.
    r0: f64,
    /// Lateral distance from the wheelset centre to the wheel profile origin, m.
    wheel_offset: f64,
    /// Wheel sample abscissae on the wheel profile, m.
    t: Vec<f64>,
    /// Sample points relative to the wheelset centre before roll: U = offset + t, Z = z(t) − r0.
    big_u: Vec<f64>,
    big_z: Vec<f64>,
    /// Installed rail: height (m, 0 at the rail top) as a function of u (m) in the side frame.
    rail: CubicSpline,
    rail_range: (f64, f64),
    /// Maps installed coordinates back to the loaded rail profile: u = y' + shift_u, with
    /// (y', z') the profile rotated by the inclination, z = z' + shift_z.
    shift_u: f64,
    shift_z: f64,
    inclination: f64,
}

/// Result of minimising the gap on one side for a pose.
#[derive(Debug, Clone, Copy)]
pub(super) struct SideMin {
    /// Minimum of Zrot − R over the wheel (the gap without the wheelset's height), m.
    pub h: f64,
    /// d h / d φ_side at the minimum (envelope theorem), m/rad.
    pub dh_droll: f64,
}

impl Side {
    pub(super) fn new(
        wheel: &Profile,
        rail: &Profile,
        track: &TrackSetup,
        wheelset: &WheelsetSetup,
        r0: f64,
        params: &ContactSearchParams,
    ) -> Result<Self> {
        let wheel_offset = wheelset.taping_line_half_spacing();
        let (t0, t1) = wheel.y_range();
        let samples = ((t1 - t0) / params.wheel_sample_spacing).ceil();
        if samples > 1e6 {
            return Err(LocoError::param(
                "wheel_sample_spacing",
                format!("gives {samples} samples across the wheel profile (at most 1e6)"),
            ));
        }
        let n = samples as usize + 1;
        let mut t = Vec::with_capacity(n);
        let mut big_u = Vec::with_capacity(n);
        let mut big_z = Vec::with_capacity(n);
        let spline = wheel.spline();
        let mut hint = 0;
        for k in 0..n {
            let tk = (t0 + (t1 - t0) * k as f64 / (n - 1) as f64).min(t1);
            hint = spline.interval(tk, hint);
            t.push(tk);
            big_u.push(wheel_offset + tk);
            big_z.push(spline.eval_in(hint, tk).value - r0);
        }
        let (rail_spline, shift_u, shift_z) = install_rail(rail, track)?;
        Ok(Self {
            wheel: wheel.clone(),
            r0,
            wheel_offset,
            t,
            big_u,
            big_z,
            rail_range: rail_spline.range(),
            rail: rail_spline,
            shift_u,
            shift_z,
            inclination: track.rail_inclination,
        })
    }

    /// Fills `gap` with h_k = Zrot_k − R(u_k) for every sample (∞ where the rail is absent).
    fn sample(&self, u_ws: f64, phi: f64, gap: &mut Vec<f64>) {
        let (s, c) = phi.sin_cos();
        gap.clear();
        let (lo, hi) = self.rail_range;
        let mut hint = 0;
        for k in 0..self.t.len() {
            let (bu, bz) = (self.big_u[k], self.big_z[k]);
            let u = u_ws + bu * c - bz * s;
            if u < lo || u > hi {
                gap.push(f64::INFINITY);
                continue;
            }
            hint = self.rail.interval(u, hint);
            gap.push(bu * s + bz * c - self.rail.eval_in(hint, u).value);
        }
    }

    /// Continuous h(t) = Zrot(t) − R(u(t)), its derivative and the point's (u, Zrot).
    pub(super) fn eval_h(&self, u_ws: f64, phi: f64, t: f64) -> Option<(f64, f64, f64, f64, f64)> {
        let (s, c) = phi.sin_cos();
        let w = self.wheel.spline().eval(t);
        let bu = self.wheel_offset + t;
        let bz = w.value - self.r0;
        let u = u_ws + bu * c - bz * s;
        let (lo, hi) = self.rail_range;
        if !(lo..=hi).contains(&u) {
            return None;
        }
        let r = self.rail.eval(u);
        let zrot = bu * s + bz * c;
        let du = c - w.slope * s;
        let dz = s + w.slope * c;
        let d2u = -w.second * s;
        let d2z = w.second * c;
        let h = zrot - r.value;
        let dh = dz - r.slope * du;
        let d2h = d2z - r.second * du * du - r.slope * d2u;
        Some((h, dh, d2h, u, zrot))
    }

    /// Refines the discrete minimum at sample `k` by Newton's method on h(t) within the
    /// neighbouring samples; returns (t, h).
    fn refine(&self, u_ws: f64, phi: f64, k: usize, gap: &[f64]) -> (f64, f64) {
        let n = self.t.len();
        let lo = self.t[k.saturating_sub(1)];
        let hi = self.t[(k + 1).min(n - 1)];
        let (mut best_t, mut best_h) = (self.t[k], gap[k]);
        let mut t = best_t;
        for _ in 0..8 {
            let Some((h, dh, d2h, _, _)) = self.eval_h(u_ws, phi, t) else {
                break;
            };
            if h < best_h {
                best_h = h;
                best_t = t;
            }
            if d2h <= 0.0 || dh.abs() < 1e-14 {
                break;
            }
            let next = (t - dh / d2h).clamp(lo, hi);
            if (next - t).abs() < 1e-12 {
                t = next;
                if let Some((h, ..)) = self.eval_h(u_ws, phi, t) {
                    if h < best_h {
                        best_h = h;
                        best_t = t;
                    }
                }
                break;
            }
            t = next;
        }
        (best_t, best_h)
    }

    /// Global minimum of h over the wheel for the pose, refined.
    pub(super) fn minimum(&self, u_ws: f64, phi: f64, gap: &mut Vec<f64>) -> Result<SideMin> {
        self.sample(u_ws, phi, gap);
        let k = lowest(gap)?;
        // Trial poses of the roll iteration may put the minimum at a profile end; only the
        // solved pose is checked (in `contacts`).
        if !gap[k].is_finite() {
            return self.check_interior(k, gap, u_ws).map(|_| unreachable_min());
        }
        let (t, h) = self.refine(u_ws, phi, k, gap);
        Ok(SideMin {
            h,
            dh_droll: self.dh_droll(u_ws, phi, t),
        })
    }

    /// Rolling radius (m) at the lowest point of the wheel over its rail for the pose: where a
    /// wheel lowered onto its rail on its own touches. Fails when that point is at the end of a
    /// profile (flange climbing past the rail) or the wheel does not overlap its rail.
    pub(super) fn touching_radius(&self, u_ws: f64, phi: f64, gap: &mut Vec<f64>) -> Result<f64> {
        self.sample(u_ws, phi, gap);
        let k = lowest(gap)?;
        self.check_interior(k, gap, u_ws)?;
        let (t, _) = self.refine(u_ws, phi, k, gap);
        Ok(self.r0 - self.wheel.spline().eval(t).value)
    }

    /// The minimum must lie inside the overlap of wheel and rail, else the wheel is off its rail.
    fn check_interior(&self, k: usize, gap: &[f64], u_ws: f64) -> Result<()> {
        let n = gap.len();
        let edge = k == 0 || k + 1 == n || !gap[k - 1].is_finite() || !gap[k + 1].is_finite();
        if !gap[k].is_finite() {
            return Err(LocoError::Contact(format!(
                "wheel '{}' does not overlap its rail at lateral position {u_ws} m",
                self.wheel.name()
            )));
        }
        if edge {
            return Err(LocoError::Contact(format!(
                "the contact of wheel '{}' reaches the end of a profile at lateral position {u_ws} \
                 m (flange climbing past the rail, or profiles too short)",
                self.wheel.name()
            )));
        }
        Ok(())
    }

    /// d h_min / d φ at wheel abscissa `t` (envelope theorem).
    fn dh_droll(&self, u_ws: f64, phi: f64, t: f64) -> f64 {
        let (s, c) = phi.sin_cos();
        let bu = self.wheel_offset + t;
        let bz = self.wheel.spline().eval(t).value - self.r0;
        let u = u_ws + bu * c - bz * s;
        let slope = self
            .rail
            .eval(u.clamp(self.rail_range.0, self.rail_range.1))
            .slope;
        (bu * c - bz * s) + slope * (bu * s + bz * c)
    }

    /// Contact points for the solved pose (centre height `z`).
    pub(super) fn contacts(
        &self,
        u_ws: f64,
        phi: f64,
        z: f64,
        params: &ContactSearchParams,
        gap: &mut Vec<f64>,
    ) -> Result<WheelContact> {
        self.sample(u_ws, phi, gap);
        let n = gap.len();
        if let Some((k, _)) = gap.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)) {
            self.check_interior(k, gap, u_ws)?;
        }
        // Discrete interior local minima, refined.
        let mut minima: Vec<(usize, f64, f64)> = Vec::new();
        for k in 1..n.saturating_sub(1) {
            if gap[k].is_finite() && gap[k] < gap[k - 1] && gap[k] <= gap[k + 1] {
                let (t, h) = self.refine(u_ws, phi, k, gap);
                minima.push((k, t, h));
            }
        }
        let Some(&global) = minima.iter().min_by(|a, b| a.2.total_cmp(&b.2)) else {
            return Err(LocoError::Contact(format!(
                "no contact for wheel '{}' at lateral position {u_ws} m",
                self.wheel.name()
            )));
        };
        // The second point: the lowest other minimum far enough away with a real hump between.
        let mut second: Option<(usize, f64, f64)> = None;
        for &m in &minima {
            if m.0 == global.0 || (m.1 - global.1).abs() < params.min_separation {
                continue;
            }
            let (a, b) = (m.0.min(global.0), m.0.max(global.0));
            let hump = gap[a..=b].iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            if hump - m.2 < params.min_prominence {
                continue;
            }
            if second.is_none_or(|s| m.2 < s.2) {
                second = Some(m);
            }
        }
        let point = |t: f64, h: f64| self.point(u_ws, phi, z, t, h);
        let first = point(global.1, global.2);
        Ok(match second {
            None => WheelContact {
                points: [Some(first), None],
            },
            Some(m) => {
                let other = point(m.1, m.2);
                // Field side (larger t) first.
                if global.1 > m.1 {
                    WheelContact {
                        points: [Some(first), Some(other)],
                    }
                } else {
                    WheelContact {
                        points: [Some(other), Some(first)],
                    }
                }
            }
        })
    }

    /// The contact quantities at wheel abscissa `t` (h = h(t)).
    fn point(&self, u_ws: f64, phi: f64, z: f64, t: f64, h: f64) -> ContactPoint {
        let (s, c) = phi.sin_cos();
        let w = self.wheel.spline().eval(t);
        let bu = self.wheel_offset + t;
        let bz = w.value - self.r0;
        let u = (u_ws + bu * c - bz * s).clamp(self.rail_range.0, self.rail_range.1);
        let r = self.rail.eval(u);
        // Back to the loaded rail profile: undo the placement, then the inclination.
        let (yi, zi) = (u - self.shift_u, r.value - self.shift_z);
        let (si, ci) = self.inclination.sin_cos();
        ContactPoint {
            gap: (z + h).max(0.0),
            lateral: bu * c - bz * s,
            vertical: bu * s + bz * c,
            rolling_radius: self.r0 - w.value,
            contact_angle: r.slope.atan(),
            wheel_curvature: w.second / (1.0 + w.slope * w.slope).powf(1.5),
            rail_curvature: -r.second / (1.0 + r.slope * r.slope).powf(1.5),
            wheel_y: t,
            rail_y: yi * ci + zi * si,
        }
    }
}

/// Placeholder never returned: `check_interior` fails for a non-finite minimum.
fn unreachable_min() -> SideMin {
    SideMin {
        h: f64::INFINITY,
        dh_droll: 0.0,
    }
}

/// Inclines the rail toward the track centre, keeps the part where it is still a function of u,
/// and places it: gauge point at u = gauge/2, top at z = 0. Returns the installed spline and the
/// shifts (u = y' + shift_u, z = z' + shift_z) from the inclined profile.
fn install_rail(rail: &Profile, track: &TrackSetup) -> Result<(CubicSpline, f64, f64)> {
    let (s, c) = track.rail_inclination.sin_cos();
    let ys: Vec<f64> = rail
        .y()
        .iter()
        .zip(rail.z())
        .map(|(y, z)| y * c - z * s)
        .collect();
    let zs: Vec<f64> = rail
        .y()
        .iter()
        .zip(rail.z())
        .map(|(y, z)| y * s + z * c)
        .collect();
    let top = (0..zs.len())
        .max_by(|&a, &b| zs[a].total_cmp(&zs[b]))
        .unwrap_or(0);
    let mut first = top;
    while first > 0 && ys[first - 1] < ys[first] {
        first -= 1;
    }
    let mut last = top;
    while last + 1 < ys.len() && ys[last + 1] > ys[last] {
        last += 1;
    }
    let name = format!("rail '{}' (inclined)", rail.name());
    let spline = CubicSpline::new(&name, &ys[first..=last], &zs[first..=last])?;
    let z_top = zs[top];
    let target = z_top - track.gauge_height;
    // Gauge point: first crossing of z = top − gauge_height from the top toward the gauge side.
    let mut k = top;
    while k > first && zs[k] > target {
        k -= 1;
    }
    if zs[k] > target {
        return Err(LocoError::input(
            format!("rail '{}'", rail.name()),
            format!(
                "the profile does not reach {} m below its top on the gauge side",
                track.gauge_height
            ),
        ));
    }
    // Bisection on the spline between samples k and k+1.
    let (mut a, mut b) = (ys[k], ys[k + 1]);
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if spline.eval(m).value > target {
            b = m;
        } else {
            a = m;
        }
    }
    let y_gauge = 0.5 * (a + b);
    let shift_u = 0.5 * track.gauge - y_gauge;
    let shift_z = -z_top;
    let u: Vec<f64> = ys[first..=last].iter().map(|y| y + shift_u).collect();
    let z: Vec<f64> = zs[first..=last].iter().map(|z| z + shift_z).collect();
    Ok((CubicSpline::new(&name, &u, &z)?, shift_u, shift_z))
}

/// Index of the smallest sampled gap (the wheel's lowest point over its rail).
fn lowest(gap: &[f64]) -> Result<usize> {
    gap.iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map(|(k, _)| k)
        .ok_or_else(|| LocoError::Contact("empty wheel profile".into()))
}
