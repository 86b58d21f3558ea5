//! Named parameters of a wheelset on a track for the contact search, with the study's defaults.

use crate::error::{check_finite, check_non_negative, check_positive, LocoError, Result};

/// Index of the left wheel / rail (at track +y) in per-side arrays.
pub const LEFT: usize = 0;
/// Index of the right wheel / rail (at track −y) in per-side arrays.
pub const RIGHT: usize = 1;

/// Where the rails are: gauge, gauge measuring height, inclination.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackSetup {
    /// Track gauge, m: distance between the gauge points of the two rails (1.435).
    pub gauge: f64,
    /// Depth of the gauge points below the top of the (inclined) rail, m: 0.016 for Chinese
    /// track (the study's CN60), 0.014 for EN 13848 / UIC track.
    pub gauge_height: f64,
    /// Inclination (cant) of each rail toward the track centre, rad: `atan(1/40)` for 1:40.
    /// Use 0 for rail profiles that are already canted (e.g. the Manchester benchmark UIC60).
    pub rail_inclination: f64,
}

impl Default for TrackSetup {
    /// The study's track: 1435 mm gauge measured 16 mm below the rail top, rails inclined 1:40.
    fn default() -> Self {
        Self {
            gauge: 1.435,
            gauge_height: 0.016,
            rail_inclination: (1.0_f64 / 40.0).atan(),
        }
    }
}

impl TrackSetup {
    /// Checks every field; errors name the field.
    pub fn validate(&self) -> Result<()> {
        check_positive("gauge", self.gauge)?;
        check_positive("gauge_height", self.gauge_height)?;
        check_finite("rail_inclination", self.rail_inclination)?;
        if self.rail_inclination.abs() > 0.2 {
            return Err(LocoError::param(
                "rail_inclination",
                format!(
                    "{} rad is not a rail inclination (|.| <= 0.2)",
                    self.rail_inclination
                ),
            ));
        }
        Ok(())
    }
}

/// Where the wheels are on their axle and their nominal radii.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetSetup {
    /// Back-to-back distance (flange-back spacing): between the inner faces of the two wheels,
    /// m. 1.353 for Chinese wheelsets (1.353 + 2·0.070 = 1.493 m between nominal contact points,
    /// as in the study), 1.360 for UIC.
    pub back_to_back: f64,
    /// Lateral distance from a wheel's inner face (flange back) to its profile origin (the
    /// taping line), m: 0.070 for S1002, EN 15302 and JM3 treads.
    pub flange_back_offset: f64,
    /// Wheel radius at the taping line, m, per wheel `[LEFT, RIGHT]` (0.625 for the study).
    pub nominal_radius: [f64; 2],
}

impl Default for WheelsetSetup {
    /// The study's locomotive wheelset: back-to-back 1353 mm, taping line 70 mm from the flange
    /// back, 625 mm rolling radius.
    fn default() -> Self {
        Self {
            back_to_back: 1.353,
            flange_back_offset: 0.070,
            nominal_radius: [0.625, 0.625],
        }
    }
}

impl WheelsetSetup {
    /// Half the lateral distance between the two taping lines, m.
    pub fn taping_line_half_spacing(&self) -> f64 {
        0.5 * self.back_to_back + self.flange_back_offset
    }

    /// Checks every field; errors name the field.
    pub fn validate(&self) -> Result<()> {
        check_positive("back_to_back", self.back_to_back)?;
        check_non_negative("flange_back_offset", self.flange_back_offset)?;
        check_positive("nominal_radius (left)", self.nominal_radius[LEFT])?;
        check_positive("nominal_radius (right)", self.nominal_radius[RIGHT])?;
        Ok(())
    }
}

/// Numerical settings of the contact search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSearchParams {
    /// Lateral spacing of the wheel points at which the gap is sampled before each minimum is
    /// refined by Newton's method on the splines, m (0.2 mm).
    pub wheel_sample_spacing: f64,
    /// Smallest lateral distance on the wheel between two reported contact points, m (2 mm):
    /// closer minima are one contact zone.
    pub min_separation: f64,
    /// Smallest rise of the gap between two minima for the second to count as a contact point
    /// of its own, m (10 µm): filters ripples of measured profiles.
    pub min_prominence: f64,
    /// Largest wheelset roll searched, rad (0.1).
    pub max_roll: f64,
    /// Tolerance on the difference of the two wheels' minimum gaps, m (1e-11).
    pub tolerance: f64,
}

impl Default for ContactSearchParams {
    fn default() -> Self {
        Self {
            wheel_sample_spacing: 2e-4,
            min_separation: 2e-3,
            min_prominence: 1e-5,
            max_roll: 0.1,
            tolerance: 1e-11,
        }
    }
}

impl ContactSearchParams {
    /// Checks every field; errors name the field.
    pub fn validate(&self) -> Result<()> {
        check_positive("wheel_sample_spacing", self.wheel_sample_spacing)?;
        check_non_negative("min_separation", self.min_separation)?;
        check_non_negative("min_prominence", self.min_prominence)?;
        check_positive("max_roll", self.max_roll)?;
        check_positive("tolerance", self.tolerance)?;
        Ok(())
    }
}
