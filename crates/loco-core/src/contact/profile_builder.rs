//! Profiles built from straight lines and tangent circular arcs (documented geometry such as the
//! CN60 rail head: crown R300, then R80, then R13 at the gauge corner).
//!
//! A path starts at a point with a tangent direction; each segment continues tangentially from the
//! end of the previous one: a line of given length, or an arc of given radius turned through a
//! given signed angle. [`ProfileBuilder::build`] samples the path at a given arc-length spacing and
//! returns a [`Profile`] (which requires y strictly increasing along the path).
//!
//! Angles are in rad. The direction is the angle of the tangent from the +y axis toward +z
//! (counter-clockwise in the (y, z) plane of the profile frame). A positive arc angle turns the
//! tangent counter-clockwise (the path bends upward when running toward +y), a negative one
//! clockwise (a convex cap such as a rail crown when running toward +y).

use super::profile::{Profile, ProfileKind};
use crate::error::{check_finite, check_positive, LocoError, Result};

/// One segment of a path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Segment {
    /// A straight line of `length` m along the current direction.
    Line {
        /// Length along the path, m (> 0).
        length: f64,
    },
    /// A circular arc of `radius` m turning the direction by `angle` rad (sign: see module doc).
    Arc {
        /// Radius, m (> 0).
        radius: f64,
        /// Turned angle, rad (≠ 0); the arc length is `radius·|angle|`.
        angle: f64,
    },
}

/// Builder of a profile from tangent lines and arcs.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileBuilder {
    start_y: f64,
    start_z: f64,
    start_direction: f64,
    segments: Vec<Segment>,
}

impl ProfileBuilder {
    /// A path starting at (`y`, `z`) in m with tangent `direction` in rad.
    pub fn new(y: f64, z: f64, direction: f64) -> Self {
        Self {
            start_y: y,
            start_z: z,
            start_direction: direction,
            segments: Vec::new(),
        }
    }

    /// Appends a straight line of `length` m.
    pub fn line(mut self, length: f64) -> Self {
        self.segments.push(Segment::Line { length });
        self
    }

    /// Appends an arc of `radius` m turning by `angle` rad (positive: counter-clockwise).
    pub fn arc(mut self, radius: f64, angle: f64) -> Self {
        self.segments.push(Segment::Arc { radius, angle });
        self
    }

    /// The segments so far.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// End point (y, z) in m and end direction in rad of the whole path.
    pub fn end(&self) -> Result<(f64, f64, f64)> {
        self.validate()?;
        let mut state = (self.start_y, self.start_z, self.start_direction);
        for seg in &self.segments {
            state = advance(state, seg, segment_length(seg));
        }
        Ok(state)
    }

    fn validate(&self) -> Result<()> {
        check_finite("start y", self.start_y)?;
        check_finite("start z", self.start_z)?;
        check_finite("start direction", self.start_direction)?;
        if self.segments.is_empty() {
            return Err(LocoError::input("segments", "the path has no segment"));
        }
        for (i, seg) in self.segments.iter().enumerate() {
            match *seg {
                Segment::Line { length } => {
                    check_positive(&format!("segment {i} length"), length)?;
                }
                Segment::Arc { radius, angle } => {
                    check_positive(&format!("segment {i} radius"), radius)?;
                    check_finite(&format!("segment {i} angle"), angle)?;
                    if angle == 0.0 {
                        return Err(LocoError::param(
                            format!("segment {i} angle"),
                            "must not be 0",
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// Samples the path every `spacing` m of arc length (each segment's ends included) and returns
    /// the points `(y, z)` in m.
    pub fn points(&self, spacing: f64) -> Result<(Vec<f64>, Vec<f64>)> {
        self.validate()?;
        check_positive("spacing", spacing)?;
        let mut ys = vec![self.start_y];
        let mut zs = vec![self.start_z];
        let mut state = (self.start_y, self.start_z, self.start_direction);
        for seg in &self.segments {
            let length = segment_length(seg);
            // At least one step per segment; steps equal and at most `spacing`.
            let steps = (length / spacing).ceil().max(1.0) as usize;
            for k in 1..=steps {
                let (y, z, _) = advance(state, seg, length * k as f64 / steps as f64);
                ys.push(y);
                zs.push(z);
            }
            state = advance(state, seg, length);
        }
        Ok((ys, zs))
    }

    /// Samples the path every `spacing` m and builds a profile named `name` of kind `kind`.
    /// Fails if y does not increase strictly along the path (the profile must be a function z(y)).
    pub fn build(&self, name: &str, kind: ProfileKind, spacing: f64) -> Result<Profile> {
        let (y, z) = self.points(spacing)?;
        Profile::new(name, kind, &y, &z)
    }
}

fn segment_length(seg: &Segment) -> f64 {
    match *seg {
        Segment::Line { length } => length,
        Segment::Arc { radius, angle } => radius * angle.abs(),
    }
}

/// Position and direction after running `s` m (0 ≤ s ≤ length) along `seg` from `state`.
fn advance(state: (f64, f64, f64), seg: &Segment, s: f64) -> (f64, f64, f64) {
    let (y, z, dir) = state;
    match *seg {
        Segment::Line { .. } => (y + s * dir.cos(), z + s * dir.sin(), dir),
        Segment::Arc { radius, angle } => {
            let turn = angle.signum();
            // Centre of the arc: one radius to the left (ccw) or right (cw) of the tangent.
            let cy = y - turn * radius * dir.sin();
            let cz = z + turn * radius * dir.cos();
            let new_dir = dir + turn * s / radius;
            (
                cy + turn * radius * new_dir.sin(),
                cz - turn * radius * new_dir.cos(),
                new_dir,
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_arc_ends_where_geometry_says() {
        // From (0, 0) heading +y, a clockwise quarter circle of radius 1 ends at (1, -1) heading -z.
        let b = ProfileBuilder::new(0.0, 0.0, 0.0).arc(1.0, -std::f64::consts::FRAC_PI_2);
        let (y, z, d) = b.end().unwrap();
        assert!((y - 1.0).abs() < 1e-12 && (z + 1.0).abs() < 1e-12);
        assert!((d + std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        // Sampled points lie on the circle centred at (0, -1).
        let (ys, zs) = b.points(0.01).unwrap();
        for (y, z) in ys.iter().zip(&zs) {
            assert!(((y * y + (z + 1.0) * (z + 1.0)).sqrt() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn crown_between_lines_is_tangent_and_has_its_curvature() {
        // A rail-like crown: line rising at 0.1 rad, arc R = 0.3 m turning -0.2 rad, line falling.
        let p = ProfileBuilder::new(-0.04, -0.004, 0.1)
            .line(0.01)
            .arc(0.3, -0.2)
            .line(0.01)
            .build("crown", ProfileKind::Rail, 2e-4)
            .unwrap();
        let (lo, hi) = p.y_range();
        let mid = 0.5 * (lo + hi);
        // Top of the arc: slope 0, curvature -1/R (a cap).
        assert!(p.slope(mid).unwrap().abs() < 1e-3);
        assert!((p.curvature(mid).unwrap() + 1.0 / 0.3).abs() < 0.05 / 0.3);
        // The straight part keeps its slope tan(0.1).
        assert!((p.slope(lo + 0.003).unwrap() - 0.1_f64.tan()).abs() < 1e-4);
    }

    #[test]
    fn bad_segments_and_backward_paths_fail() {
        assert!(ProfileBuilder::new(0.0, 0.0, 0.0)
            .line(-1.0)
            .points(0.1)
            .is_err());
        assert!(ProfileBuilder::new(0.0, 0.0, 0.0)
            .arc(1.0, 0.0)
            .points(0.1)
            .is_err());
        assert!(ProfileBuilder::new(0.0, 0.0, 0.0).points(0.1).is_err());
        // A path turning back in y is not a profile z(y).
        let back = ProfileBuilder::new(0.0, 0.0, 0.0).arc(0.01, 3.0);
        assert!(back.build("u", ProfileKind::Wheel, 1e-3).is_err());
    }
}
