//! The Chinese 60 kg/m rail (CN60, GB/T 2585 / TB/T 2344 section) head, from its documented arcs.
//!
//! # Geometry and sources
//!
//! - Head top built from three tangent circular arcs: crown R300, then R80, then R13 at the
//!   gauge corner (the study's §2; the same construction as UIC60, whose arcs are R300/R80/R13
//!   with a 1:20 head flank, as documented e.g. by the GENSYS profile manual "create_UIC60").
//! - Head width 73 mm, rail height 176 mm, foot width 150 mm (manufacturers' CN60 data sheets).
//!   The head width is taken where the R13 arc meets the head flank, as in the UIC60 drawing
//!   (72 mm there).
//! - Head flanks at 1:20, the head widening downward (as in UIC60). This keeps the profile a
//!   function z(y) after the 1:40 inclination toward the track centre (a flank steeper than
//!   1:40 the other way would fold over), which the contact search needs.
//! - The lateral extent of the R300 crown is not given by the sources at hand: 20 mm (±10 mm),
//!   as UIC60's 20.456 mm. With the R13 arc ending at the half head width 36.5 mm, tangency then
//!   fixes where R80 ends (±26.7 mm).
//!
//! Only the head matters for the contact geometry: the profile covers the head top and 25 mm of
//! each flank (the gauge point, 16 mm below the top, lies on the flank). Frame: the rail profile
//! frame of [`super::super::profile`] (upright, gauge side at low y), origin at the top of the
//! crown.

use crate::contact::profile::{Profile, ProfileKind};
use crate::contact::profile_builder::ProfileBuilder;
use crate::error::Result;

/// Crown radius (m).
const CROWN_RADIUS: f64 = 0.300;
/// Intermediate head radius (m).
const SHOULDER_RADIUS: f64 = 0.080;
/// Gauge corner radius (m).
const CORNER_RADIUS: f64 = 0.013;
/// Half the lateral extent of the R300 crown (m), see the module doc.
const CROWN_HALF_WIDTH: f64 = 0.010;
/// Half the head width, where the gauge corner meets the flank (m): 73 mm / 2.
const HEAD_HALF_WIDTH: f64 = 0.0365;
/// Head flank inclination (run/rise) from the vertical: 1:20.
const FLANK_SLOPE: f64 = 1.0 / 20.0;
/// Length of flank kept on each side (m).
const FLANK_LENGTH: f64 = 0.025;
/// Sampling of the arcs and lines (m of path length).
const SPACING: f64 = 1.0e-4;

/// Shoulder radius on the gauge side of the ground rail [`cn60_gauge_ground`], m.
pub const GROUND_SHOULDER_RADIUS: f64 = 0.060;

/// The CN60 rail profile, upright (to be inclined 1:40 by the track set-up).
pub fn cn60() -> Result<Profile> {
    head("cn60", SHOULDER_RADIUS)
}

/// CN60 ground at the gauge corner, upright: the gauge side's R80 shoulder replaced by an R60
/// one ([`GROUND_SHOULDER_RADIUS`]) between the unchanged R300 crown and R13 corner, the head
/// width and flanks kept; the field side is CN60's.
///
/// Grinding the gauge shoulder lowers the head toward the gauge corner (by 0.05 mm 15 mm from
/// the centre line, 0.21 mm at 20 mm, 0.49 mm at 25 mm and 0.66 mm over the whole gauge corner
/// from 30 mm on; asserted by the tests), so a new wheel's contact cannot climb toward its flange root as early: the
/// anti-hunting (gauge-corner relief) grinding that railways apply to lower the conicity of new
/// wheels on over-ground rail. The radius is a judgement: R60 is the gauge-side shoulder radius
/// commonly quoted for the Chinese 60N profile (TB/T 2344.1-2020, the re-profiled 60 kg/m head
/// introduced against low-conicity carbody hunting, as summarised in the Chinese rail-profile
/// literature; the standard itself was not at hand), applied here to the CN60 head alone.
pub fn cn60_gauge_ground() -> Result<Profile> {
    head("cn60-gauge-ground", GROUND_SHOULDER_RADIUS)
}

/// The CN60 head with the shoulder radius `gauge_shoulder` (m) on the gauge side.
fn head(name: &str, gauge_shoulder: f64) -> Result<Profile> {
    // Angles of the surface normal from the vertical where each arc ends.
    let crown_end = (CROWN_HALF_WIDTH / CROWN_RADIUS).asin();
    let corner_end = (1.0 / FLANK_SLOPE).atan();
    // Tangent arcs share normals, so their centres lie on them: the corner arc's outer end sits
    // at y = (R300 − R80)·sin φ1 + (R80 − R13)·sin φ2 + R13·sin φ3 = half head width, giving φ2.
    let shoulder_end_for = |shoulder: f64| {
        ((HEAD_HALF_WIDTH
            - CORNER_RADIUS * corner_end.sin()
            - (CROWN_RADIUS - shoulder) * crown_end.sin())
            / (shoulder - CORNER_RADIUS))
            .asin()
    };
    let corner_z_for = |shoulder: f64, shoulder_end: f64| {
        let corner_centre_z = -CROWN_RADIUS
            + (CROWN_RADIUS - shoulder) * crown_end.cos()
            + (shoulder - CORNER_RADIUS) * shoulder_end.cos();
        corner_centre_z + CORNER_RADIUS * corner_end.cos()
    };
    let shoulder_end = shoulder_end_for(SHOULDER_RADIUS);
    let gauge_shoulder_end = shoulder_end_for(gauge_shoulder);
    let corner_end_z = corner_z_for(gauge_shoulder, gauge_shoulder_end);
    // Start at the bottom of the gauge-side flank, running up it (direction = φ3 from +y).
    let start_y = -HEAD_HALF_WIDTH - FLANK_LENGTH * corner_end.cos();
    let start_z = corner_end_z - FLANK_LENGTH * corner_end.sin();
    ProfileBuilder::new(start_y, start_z, corner_end)
        .line(FLANK_LENGTH)
        .arc(CORNER_RADIUS, -(corner_end - gauge_shoulder_end))
        .arc(gauge_shoulder, -(gauge_shoulder_end - crown_end))
        .arc(CROWN_RADIUS, -2.0 * crown_end)
        .arc(SHOULDER_RADIUS, -(shoulder_end - crown_end))
        .arc(CORNER_RADIUS, -(corner_end - shoulder_end))
        .line(FLANK_LENGTH)
        .build(name, ProfileKind::Rail, SPACING)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn head_is_73_mm_wide_with_its_top_at_the_origin() {
        let rail = cn60().unwrap();
        let top = rail
            .y()
            .iter()
            .zip(rail.z())
            .fold(
                (0.0, f64::MIN),
                |best, (&y, &z)| if z > best.1 { (y, z) } else { best },
            );
        // The highest sample is within one sampling step of the crown centre; the spline's top is
        // there: R300 drops (1e-4 m)²/(2·0.3 m) ≈ 2e-8 m over one step.
        assert!(top.0.abs() <= SPACING && top.1.abs() < 2e-8, "{top:?}");
        assert!(rail.height(0.0).unwrap().abs() < 2e-8);
        // Where the corner arcs meet the flanks, 73 mm apart, symmetric.
        let z_corner = rail.height(-HEAD_HALF_WIDTH).unwrap();
        assert!((rail.height(HEAD_HALF_WIDTH).unwrap() - z_corner).abs() < 1e-7);
        // The crown is the R300 arc: curvature −1/0.3 at the centre (convex).
        let curvature = rail.curvature(0.0).unwrap();
        assert!((curvature.abs() - 1.0 / CROWN_RADIUS).abs() < 0.05 / CROWN_RADIUS);
    }

    /// The ground head: the field side and the crown as CN60, the gauge side lower by the
    /// depths its documentation states, the corner still meeting the flank at the half width.
    #[test]
    fn gauge_ground_head_is_lower_at_the_gauge_side_only() {
        let (rail, ground) = (cn60().unwrap(), cn60_gauge_ground().unwrap());
        for y in [0.0, 0.005, 0.02, 0.03] {
            let (a, b) = (rail.height(y).unwrap(), ground.height(y).unwrap());
            assert!((a - b).abs() < 1e-9, "field side at {y}: {a} vs {b}");
        }
        let depth = |y: f64| rail.height(y).unwrap() - ground.height(y).unwrap();
        assert!(depth(-0.008).abs() < 1e-9);
        for (y, want) in [
            (-0.015, 0.05e-3),
            (-0.020, 0.21e-3),
            (-0.025, 0.49e-3),
            (-0.030, 0.66e-3),
        ] {
            assert!((depth(y) - want).abs() < 0.006e-3, "at {y}: {}", depth(y));
        }
        // The corner arc still ends on a 1:20 flank at the half head width.
        let slope = ground.slope(-HEAD_HALF_WIDTH - 0.0008).unwrap();
        assert!(
            (slope - 1.0 / FLANK_SLOPE).abs() < 1e-3 / FLANK_SLOPE,
            "{slope}"
        );
    }
}
