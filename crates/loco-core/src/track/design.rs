//! Designed track geometry: the alignment the track-following frame follows (straights, clothoid
//! transitions, circular curves) with its cant, as a list of sections.
//!
//! Each section is a straight, a circular curve (radius R, m; cant c, m; direction left or
//! right) or a transition between its neighbours. In a transition the curvature changes linearly
//! with the distance s (a clothoid) from the end value of the section before to the start value of
//! the section after (a straight, or the track's ends, count as κ = 0 and c = 0), and the cant
//! changes linearly over its run-off (the whole transition by default, or a shorter run-off
//! centred in it). Signs: curvature κ > 0 for a curve to the left (centre of curvature at +y);
//! the cant raises the outer rail, so the track plane's roll θ (positive: left rail higher, the
//! convention of `vehicle::rail_contact::rail_plane`) is `θ = −sign(κ)·atan(c / 2b)` with 2b the distance
//! between the nominal contact points. Beyond the last section the end values continue (a run
//! may end inside a steady curve; after a design that ends straight it runs on straight track,
//! and a scenario refuses a run that would leave a design ending in a curve); before the first,
//! its start values.
//!
//! Along s the design gives κ(s), dκ/ds, θ(s), dθ/ds, the heading Ψ(s) = ∫κ ds and its
//! integral ∫Ψ ds (exact for the piecewise linear κ): the track frame of a body at s yaws at
//! V·κ, and the lateral offset of the centre line at s₂ from the tangent at s₁ is
//! `∫_{s₁}^{s₂} (Ψ − Ψ(s₁)) ds` (small angles: a vehicle spans a heading change of κ·20 m).

use crate::error::{check_positive, LocoError, Result};

/// Largest cant the model accepts, m (EN 13803 allows at most 180–200 mm on ballasted track).
pub const MAX_CANT: f64 = 0.2;

/// Direction of a curve, seen in the running direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveDirection {
    Left,
    Right,
}

impl CurveDirection {
    /// `left` or `right`; `field` names the setting in the error.
    pub fn from_name(name: &str, field: &str) -> Result<Self> {
        match name {
            "left" => Ok(Self::Left),
            "right" => Ok(Self::Right),
            other => Err(LocoError::param(
                field,
                format!("expected left or right, got '{other}'"),
            )),
        }
    }

    /// +1 for a left curve, −1 for a right one.
    pub fn sign(self) -> f64 {
        match self {
            Self::Left => 1.0,
            Self::Right => -1.0,
        }
    }
}

/// Radius of [`DesignSection::reference_curve`], m.
pub const REFERENCE_CURVE_RADIUS: f64 = 1200.0;
/// Radius of [`DesignSection::study_curve`], m.
pub const STUDY_CURVE_RADIUS: f64 = 3000.0;

/// One section of the design as a user gives it (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DesignSection {
    /// A straight of `length` m.
    Straight { length: f64 },
    /// A clothoid transition of `length` m with linear cant run-off over `cant_run_off` m
    /// (`None`: the whole transition), centred in it.
    Transition {
        length: f64,
        cant_run_off: Option<f64>,
    },
    /// A circular curve of `length` m, radius `radius` m and cant `cant` m.
    Curve {
        length: f64,
        radius: f64,
        cant: f64,
        direction: CurveDirection,
    },
}

impl DesignSection {
    /// The curve the speed benchmarks, the run fingerprints and the curving tests share: 10 m
    /// straight, a 60 m clothoid with linear cant run-off, then 1000 m of R = [`REFERENCE_CURVE_RADIUS`] with `cant`
    /// (m) toward `direction` (the benchmark: 0.1 m, left).
    pub fn reference_curve(cant: f64, direction: CurveDirection) -> Vec<Self> {
        Self::entry_curve(REFERENCE_CURVE_RADIUS, cant, direction)
    }

    /// The curve of the speed benchmark on a curve like the curving study's (`studies/curving.py`,
    /// R = 3000 m with 60 mm cant and a 60 m transition): at 200 km/h about 97 mm of cant
    /// deficiency, inside the study's 0–150 mm, where [`Self::reference_curve`] has about 290 mm.
    pub fn study_curve(direction: CurveDirection) -> Vec<Self> {
        Self::entry_curve(STUDY_CURVE_RADIUS, 0.06, direction)
    }

    /// 10 m straight, a 60 m clothoid with linear cant run-off, then 1000 m of radius `radius`
    /// (m) with `cant` (m) toward `direction`.
    pub fn entry_curve(radius: f64, cant: f64, direction: CurveDirection) -> Vec<Self> {
        vec![
            Self::Straight { length: 10.0 },
            Self::Transition {
                length: 60.0,
                cant_run_off: None,
            },
            Self::Curve {
                length: 1000.0,
                radius,
                cant,
                direction,
            },
        ]
    }

    /// Length of the section, m.
    pub fn length(&self) -> f64 {
        match *self {
            Self::Straight { length }
            | Self::Transition { length, .. }
            | Self::Curve { length, .. } => length,
        }
    }

    /// Signed curvature (1/m) and signed cant (m, + left rail higher) of a straight or curve.
    fn ends(&self) -> Option<(f64, f64)> {
        match *self {
            Self::Straight { .. } => Some((0.0, 0.0)),
            Self::Curve {
                radius,
                cant,
                direction,
                ..
            } => Some((direction.sign() / radius, -direction.sign() * cant)),
            Self::Transition { .. } => None,
        }
    }
}

/// One section resolved: κ and the signed cant linear in s within it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    /// Start distance, m.
    start: f64,
    /// Curvature at the start (1/m) and its gradient (1/m²).
    kappa: f64,
    kappa_slope: f64,
    /// Signed cant at the start of the run-off (m), its gradient (m/m) and the run-off's
    /// start and end distances (m).
    cant: f64,
    cant_slope: f64,
    run_off: (f64, f64),
    /// Heading Ψ (rad) and ∫Ψ ds (m) at the start.
    heading: f64,
    heading_integral: f64,
    /// Roll (rad) and cos² of the roll of a piece whose cant does not change (`cant_slope` is
    /// +0), worked out once: the track frames read the design at every body twice per step.
    fixed_roll: Option<(f64, f64)>,
}

/// Roll θ = atan(c / 2b) (rad) of a cant `cant` (m) over the contact half distance
/// `half_distance` b (m), and cos² θ.
fn roll_of(cant: f64, half_distance: f64) -> (f64, f64) {
    let slope = cant / (2.0 * half_distance);
    (slope.atan(), 1.0 / (1.0 + slope * slope))
}

/// The track's designed alignment and cant at one distance.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DesignPoint {
    /// Curvature κ, 1/m (+ left).
    pub curvature: f64,
    /// dκ/ds, 1/m².
    pub curvature_rate: f64,
    /// Roll θ of the track plane, rad (+ left rail higher).
    pub roll: f64,
    /// dθ/ds, rad/m.
    pub roll_rate: f64,
    /// Heading Ψ = ∫κ ds from the design's start, rad.
    pub heading: f64,
    /// ∫Ψ ds from the design's start, m.
    pub heading_integral: f64,
}

/// A checked design: the sections resolved into pieces.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackDesign {
    sections: Vec<DesignSection>,
    pieces: Vec<Piece>,
    /// Half the distance between the nominal contact points b, m (cant → roll).
    half_distance: f64,
    /// Distance at the design's end, m.
    end: f64,
}

/// The name of field `field` of section `i` (0-based) in errors.
fn section_field(i: usize, field: &str) -> String {
    format!("curve section {} ({field})", i + 1)
}

fn section_error(i: usize, field: &str, reason: impl Into<String>) -> LocoError {
    LocoError::param(section_field(i, field), reason)
}

impl TrackDesign {
    /// Checks and resolves `sections` for rails whose nominal contact points are
    /// `half_distance` (m) either side of the centre line; `min_radius` (m) is the smallest
    /// radius the contact table can follow (see [`min_radius_of`]). Errors name the section
    /// (1-based) and the field.
    pub fn new(sections: &[DesignSection], half_distance: f64, min_radius: f64) -> Result<Self> {
        check_sections(sections, min_radius)?;
        let ends = |i: Option<usize>| {
            i.and_then(|i| sections.get(i))
                .and_then(DesignSection::ends)
                .unwrap_or((0.0, 0.0))
        };
        let mut pieces = Vec::with_capacity(sections.len());
        let (mut s, mut heading, mut heading_integral) = (0.0, 0.0, 0.0);
        for (i, section) in sections.iter().enumerate() {
            let length = section.length();
            let piece = match *section {
                DesignSection::Transition { cant_run_off, .. } => {
                    let (k0, c0) = ends(i.checked_sub(1));
                    let (k1, c1) = ends(Some(i + 1));
                    let run = cant_run_off.unwrap_or(length);
                    let margin = 0.5 * (length - run);
                    Piece {
                        start: s,
                        kappa: k0,
                        kappa_slope: (k1 - k0) / length,
                        cant: c0,
                        cant_slope: (c1 - c0) / run,
                        run_off: (s + margin, s + margin + run),
                        heading,
                        heading_integral,
                        fixed_roll: None,
                    }
                }
                _ => {
                    let (k, c) = ends(Some(i));
                    Piece {
                        start: s,
                        kappa: k,
                        kappa_slope: 0.0,
                        cant: c,
                        cant_slope: 0.0,
                        run_off: (s, s + length),
                        heading,
                        heading_integral,
                        fixed_roll: None,
                    }
                }
            };
            // With a cant gradient of +0, `cant + cant_slope·along` is `cant + 0` at any
            // (finite, non-negative) `along`: the same bits as evaluating it in `at`.
            let mut piece = piece;
            if piece.cant_slope.to_bits() == 0 {
                piece.fixed_roll = Some(roll_of(piece.cant + 0.0, half_distance));
            }
            let (h, hi) = piece.heading_at(length);
            heading = h;
            heading_integral = hi;
            pieces.push(piece);
            s += length;
        }
        Ok(Self {
            sections: sections.to_vec(),
            pieces,
            half_distance,
            end: s,
        })
    }

    /// The sections as given.
    pub fn sections(&self) -> &[DesignSection] {
        &self.sections
    }

    /// Total length of the sections, m.
    pub fn length(&self) -> f64 {
        self.end
    }

    /// True when the design is straight and level everywhere (the curve terms vanish).
    pub fn is_straight(&self) -> bool {
        self.pieces
            .iter()
            .all(|p| p.kappa == 0.0 && p.kappa_slope == 0.0 && p.cant == 0.0 && p.cant_slope == 0.0)
    }
}

/// Checks `sections` on their own: at least one, positive lengths, finite radii of at least
/// `min_radius` (m; 0 checks only that they are finite and positive), cants within
/// [`MAX_CANT`], run-offs within their transitions. Errors name the section (1-based) and the
/// field.
pub fn check_sections(sections: &[DesignSection], min_radius: f64) -> Result<()> {
    if sections.is_empty() {
        return Err(LocoError::param("curve", "no sections"));
    }
    for (i, section) in sections.iter().enumerate() {
        check_positive(&section_field(i, "length_m"), section.length())?;
        match *section {
            DesignSection::Curve { radius, cant, .. } => {
                if !radius.is_finite() {
                    return Err(section_error(
                        i,
                        "radius_m",
                        format!(
                            "must be a finite number of metres, got {radius} (straight \
                                 track is a `straight` section)"
                        ),
                    ));
                }
                check_positive(&section_field(i, "radius_m"), radius)?;
                if radius < min_radius {
                    return Err(section_error(
                        i,
                        "radius_m",
                        format!(
                            "{radius} m is below {min_radius:.0} m, the smallest radius \
                                 the contact table can follow (its largest rolling radius \
                                 difference gives pure rolling down to that radius)"
                        ),
                    ));
                }
                if !(cant.is_finite() && (0.0..=MAX_CANT).contains(&cant)) {
                    return Err(section_error(
                        i,
                        "cant_mm",
                        format!(
                            "{:.1} mm is outside 0 … {:.0} mm",
                            cant * 1e3,
                            MAX_CANT * 1e3
                        ),
                    ));
                }
            }
            DesignSection::Transition {
                cant_run_off: Some(run_off),
                length,
            } => {
                check_positive(&section_field(i, "cant_run_off_m"), run_off)?;
                if run_off > length {
                    return Err(section_error(
                        i,
                        "cant_run_off_m",
                        format!(
                            "the transition ({length} m) is shorter than the cant run-off \
                                 asked for ({run_off} m)"
                        ),
                    ));
                }
            }
            _ => {}
        }
    }
    Ok(())
}

impl Piece {
    /// Heading (rad) and ∫Ψ ds (m) at `sigma` m into the piece.
    fn heading_at(&self, sigma: f64) -> (f64, f64) {
        let (k, k1) = (self.kappa, self.kappa_slope);
        (
            self.heading + k * sigma + 0.5 * k1 * sigma * sigma,
            self.heading_integral
                + self.heading * sigma
                + 0.5 * k * sigma * sigma
                + k1 * sigma * sigma * sigma / 6.0,
        )
    }
}

/// The smallest radius (m) a wheelset can run round in pure rolling on a contact whose largest
/// rolling radius difference (both wheels, within the table's range) is `max_radius_difference`
/// (m), for nominal radius `r0` (m) and contact half distance `b` (m): Δr/r0 = 2b/R.
pub fn min_radius_of(max_radius_difference: f64, r0: f64, b: f64) -> f64 {
    2.0 * b * r0 / max_radius_difference
}

mod at;

#[cfg(test)]
mod tests;
