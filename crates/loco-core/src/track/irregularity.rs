//! The track irregularity the vehicle model reads: four channels on a uniform grid along the
//! track, converted to left and right rail positions, interpolated in the time loop.

use super::spectrum::{Channel, TrackSpectrum};
use crate::error::{check_non_negative, check_positive, LocoError, Result};
use std::sync::Arc;

/// Rail irregularities at one distance along the track (track frame: y left, z up).
///
/// Positions in m; `d*_ds` are their derivatives with respect to distance (m/m), so that a
/// wheelset running at speed V (m/s) sees the rail velocity `V · d/ds`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RailIrregularity {
    /// Lateral position of the left rail, m (+ left).
    pub y_left: f64,
    /// Vertical position of the left rail, m (+ up).
    pub z_left: f64,
    /// Lateral position of the right rail, m (+ left).
    pub y_right: f64,
    /// Vertical position of the right rail, m (+ up).
    pub z_right: f64,
    /// d(y_left)/ds, m/m.
    pub dy_left_ds: f64,
    /// d(z_left)/ds, m/m.
    pub dz_left_ds: f64,
    /// d(y_right)/ds, m/m.
    pub dy_right_ds: f64,
    /// d(z_right)/ds, m/m.
    pub dz_right_ds: f64,
}

/// Track irregularities of a straight track on a uniform grid of distances `0, h, 2h, …`.
///
/// Stored per grid node as the four rail positions and their slopes, so that [`Self::at`] reads
/// two adjacent nodes and evaluates a cubic Hermite interpolant: positions and slopes are
/// continuous (no force steps for an adaptive integrator), the call allocates nothing.
/// Before s = 0 the track is perfect; beyond the last node the rails stay at their last
/// position (use [`Self::check_covers`] to make sure a run stays on the data).
#[derive(Debug, Clone, PartialEq)]
pub struct TrackIrregularity {
    /// Grid step, m.
    step: f64,
    /// Per node: y_left, z_left, y_right, z_right (m) then their slopes (m/m).
    nodes: Vec<[f64; 8]>,
    /// Length of the cosine run-in taper, m.
    run_in: f64,
    /// The target spectrum of a synthesised track (None for a measured one).
    spectrum: Option<TrackSpectrum>,
    /// The file rows of a measured track, for errors that name a line.
    origin: Option<Arc<TrackOrigin>>,
}

/// The rows of the file a measured track was read from.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackOrigin {
    /// The file's path as given.
    pub path: String,
    /// Line number (1-based) of each data row.
    pub lines: Vec<usize>,
    /// Each row's vertical, alignment, cross level and gauge (m), indexed by [`Channel::index`].
    pub channels: [Vec<f64>; 4],
}

impl TrackIrregularity {
    /// Builds a track from the four channels (vertical profile, alignment, cross level, gauge;
    /// m, indexed by [`Channel::index`]) and their slopes (m/m) sampled every `step` m from
    /// s = 0, after multiplying by a cosine run-in `w(s) = (1 − cos(π s / run_in)) / 2` over
    /// the first `run_in` m (0: none) so the vehicle enters the irregular track smoothly.
    ///
    /// Rails: `z_left = v + c/2`, `z_right = v − c/2`, `y_left = a + g/2`,
    /// `y_right = a − g/2` (cross level c is left minus right height, gauge widening g moves
    /// each rail outward by g/2).
    pub fn from_channels(
        step: f64,
        values: &[Vec<f64>; 4],
        slopes: &[Vec<f64>; 4],
        run_in: f64,
        spectrum: Option<TrackSpectrum>,
    ) -> Result<Self> {
        check_positive("step", step)?;
        check_non_negative("run_in", run_in)?;
        let n = values[0].len();
        if n < 2 {
            return Err(LocoError::input(
                "irregularity",
                format!("needs at least 2 grid points, got {n}"),
            ));
        }
        for c in Channel::ALL {
            let (v, d) = (&values[c.index()], &slopes[c.index()]);
            if v.len() != n || d.len() != n {
                return Err(LocoError::input(
                    c.name(),
                    format!("length {} / {} differs from {n}", v.len(), d.len()),
                ));
            }
            crate::error::check_all_finite(c.name(), v)?;
            crate::error::check_all_finite(c.name(), d)?;
        }
        let nodes = (0..n)
            .map(|i| {
                let s = i as f64 * step;
                let (w, dw) = taper(s, run_in);
                let ch = |c: Channel| values[c.index()][i] * w;
                let dch = |c: Channel| slopes[c.index()][i] * w + values[c.index()][i] * dw;
                let mut node = [0.0; 8];
                for c in Channel::ALL {
                    let (value, slope) = (ch(c), dch(c));
                    for (k, weight) in c.rails().into_iter().enumerate() {
                        node[k] += weight * value;
                        node[k + 4] += weight * slope;
                    }
                }
                node
            })
            .collect();
        Ok(Self {
            step,
            nodes,
            run_in,
            spectrum,
            origin: None,
        })
    }

    /// The same track, remembering the file rows it was read from.
    pub fn with_origin(mut self, origin: TrackOrigin) -> Self {
        self.origin = Some(Arc::new(origin));
        self
    }

    /// The file rows of a measured track (None for a synthesised one).
    pub fn origin(&self) -> Option<&TrackOrigin> {
        self.origin.as_deref()
    }

    /// Rail irregularities at distance `s` (m). Cheap: two node reads and a cubic.
    #[inline]
    pub fn at(&self, s: f64) -> RailIrregularity {
        let last = self.nodes.len() - 1;
        let x = s / self.step;
        // NaN compares false everywhere and lands here too: a perfect track, not a panic.
        if x.is_nan() || x <= 0.0 {
            return RailIrregularity::default();
        }
        if x >= last as f64 {
            let p = &self.nodes[last];
            return RailIrregularity {
                y_left: p[0],
                z_left: p[1],
                y_right: p[2],
                z_right: p[3],
                ..Default::default()
            };
        }
        let i = x as usize;
        let t = x - i as f64;
        let (p0, p1) = (&self.nodes[i], &self.nodes[i + 1]);
        let h = self.step;
        let t2 = t * t;
        let t3 = t2 * t;
        let (h00, h10, h01, h11) = (
            2.0 * t3 - 3.0 * t2 + 1.0,
            t3 - 2.0 * t2 + t,
            -2.0 * t3 + 3.0 * t2,
            t3 - t2,
        );
        let (g00, g10, g11) = (
            (6.0 * t2 - 6.0 * t) / h,
            3.0 * t2 - 4.0 * t + 1.0,
            3.0 * t2 - 2.0 * t,
        );
        let value =
            |k: usize| h00 * p0[k] + h10 * h * p0[k + 4] + h01 * p1[k] + h11 * h * p1[k + 4];
        let slope = |k: usize| g00 * (p0[k] - p1[k]) + g10 * p0[k + 4] + g11 * p1[k + 4];
        RailIrregularity {
            y_left: value(0),
            z_left: value(1),
            y_right: value(2),
            z_right: value(3),
            dy_left_ds: slope(0),
            dz_left_ds: slope(1),
            dy_right_ds: slope(2),
            dz_right_ds: slope(3),
        }
    }

    /// The same track with every irregularity multiplied by `factor` (–), e.g. a synthesised
    /// track scaled down to amplitudes where the vehicle responds linearly.
    pub fn scaled(&self, factor: f64) -> Result<Self> {
        if !factor.is_finite() {
            return Err(LocoError::param(
                "factor",
                format!("must be finite, got {factor}"),
            ));
        }
        let mut track = self.clone();
        for node in &mut track.nodes {
            node.iter_mut().for_each(|v| *v *= factor);
        }
        Ok(track)
    }

    /// Errors unless the data covers distances up to `s_end` (m), naming both lengths.
    pub fn check_covers(&self, s_end: f64) -> Result<()> {
        if s_end.is_finite() && s_end <= self.length() {
            Ok(())
        } else {
            Err(LocoError::input(
                "track",
                format!(
                    "covers {:.3} m but the run needs {s_end:.3} m",
                    self.length()
                ),
            ))
        }
    }

    /// Length covered by the data, m.
    pub fn length(&self) -> f64 {
        (self.nodes.len() - 1) as f64 * self.step
    }

    /// Grid step, m.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// Number of grid nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Always false: a track has at least two nodes.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Run-in taper length, m.
    pub fn run_in(&self) -> f64 {
        self.run_in
    }

    /// Target spectrum of a synthesised track.
    pub fn spectrum(&self) -> Option<TrackSpectrum> {
        self.spectrum
    }

    /// Distances of the grid nodes, m.
    pub fn distance(&self) -> Vec<f64> {
        (0..self.nodes.len())
            .map(|i| i as f64 * self.step)
            .collect()
    }

    /// One channel (after the run-in taper) at the grid nodes, m.
    pub fn channel(&self, channel: Channel) -> Vec<f64> {
        self.nodes
            .iter()
            .map(|p| match channel {
                Channel::Vertical => 0.5 * (p[1] + p[3]),
                Channel::Alignment => 0.5 * (p[0] + p[2]),
                Channel::CrossLevel => p[1] - p[3],
                Channel::Gauge => p[0] - p[2],
            })
            .collect()
    }

    /// One rail coordinate at the grid nodes, m: 0 y_left, 1 z_left, 2 y_right, 3 z_right.
    pub fn rail(&self, index: usize) -> Vec<f64> {
        self.nodes.iter().map(|p| p[index.min(3)]).collect()
    }
}

/// Cosine run-in weight and its derivative (1/m) at distance `s` (m).
fn taper(s: f64, run_in: f64) -> (f64, f64) {
    if run_in <= 0.0 || s >= run_in {
        return (1.0, 0.0);
    }
    let k = std::f64::consts::PI / run_in;
    (0.5 * (1.0 - (k * s).cos()), 0.5 * k * (k * s).sin())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A track whose vertical profile is sin(2π s / λ), other channels zero.
    fn sine_track(step: f64, n: usize, wavelength: f64, run_in: f64) -> TrackIrregularity {
        let k = 2.0 * std::f64::consts::PI / wavelength;
        let s: Vec<f64> = (0..n).map(|i| i as f64 * step).collect();
        let zero = vec![0.0; n];
        let values = [
            s.iter().map(|x| (k * x).sin()).collect(),
            zero.clone(),
            zero.clone(),
            zero.clone(),
        ];
        let slopes = [
            s.iter().map(|x| k * (k * x).cos()).collect(),
            zero.clone(),
            zero.clone(),
            zero,
        ];
        TrackIrregularity::from_channels(step, &values, &slopes, run_in, None).unwrap()
    }

    #[test]
    fn hermite_interpolation_follows_a_sine_between_nodes() {
        // 2 m wavelength (k = π /m) on a 0.1 m grid: cubic Hermite error bounds h⁴k⁴/384 =
        // 2.5e-5 for the value and √3/216·h³k⁴ = 7.8e-4 /m for the slope.
        let track = sine_track(0.1, 2001, 2.0, 0.0);
        let k = std::f64::consts::PI;
        for j in 0..997 {
            let s = 3.0 + j as f64 * 0.0371;
            let r = track.at(s);
            assert!((r.z_left - (k * s).sin()).abs() < 2.6e-5);
            assert!((r.z_right - (k * s).sin()).abs() < 2.6e-5);
            assert!((r.dz_left_ds - k * (k * s).cos()).abs() < 8e-4, "{s}");
            assert_eq!(r.y_left, 0.0);
        }
    }

    #[test]
    fn run_in_starts_from_zero_smoothly() {
        let track = sine_track(0.1, 2001, 20.0, 30.0);
        let r = track.at(1e-9);
        assert!(r.z_left.abs() < 1e-9 && r.dz_left_ds.abs() < 1e-6);
        assert_eq!(track.at(-5.0), RailIrregularity::default());
        assert_eq!(track.at(f64::NAN), RailIrregularity::default());
        // Past the run-in the taper is 1.
        let s = 45.3;
        assert!((track.at(s).z_left - (2.0 * std::f64::consts::PI * s / 20.0).sin()).abs() < 1e-5);
    }

    #[test]
    fn rails_from_cross_level_and_gauge() {
        let n = 11;
        let one = vec![1.0; n];
        let zero = vec![0.0; n];
        let values = [zero.clone(), zero.clone(), one.clone(), one.clone()];
        let slopes = [zero.clone(), zero.clone(), zero.clone(), zero];
        let track = TrackIrregularity::from_channels(1.0, &values, &slopes, 0.0, None).unwrap();
        let r = track.at(4.5);
        assert_eq!(
            (r.z_left, r.z_right, r.y_left, r.y_right),
            (0.5, -0.5, 0.5, -0.5)
        );
        assert!(track.check_covers(10.0).is_ok());
        let err = track.check_covers(10.5).unwrap_err().to_string();
        assert!(err.contains("10.500"), "{err}");
        assert_eq!(track.channel(Channel::CrossLevel), one);
    }
}
