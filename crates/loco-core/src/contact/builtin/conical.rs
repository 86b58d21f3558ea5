//! A conical wheel on a knife-edge rail: the textbook contact of a given equivalent conicity.
//!
//! The wheel tread is a straight cone of slope λ through the taping line; the rail head is a
//! sharp crown (10 mm radius between 80° flanks), so the contact point stays at the crown and
//! the rolling radius difference is exactly Δr = 2λy over the whole tread: the equivalent
//! conicity is λ at every amplitude, whatever the rail inclination. There is no flange, so this
//! pair is for linear analyses (eigenvalues, critical speed against conicity) and kinematic
//! checks, not for runs that reach the flanges.

use crate::contact::profile::{Profile, ProfileKind};
use crate::contact::profile_builder::ProfileBuilder;
use crate::error::{LocoError, Result};

/// Name of the knife-edge rail: on it a wheel needs no flange
/// (`contact::profile_plausibility::pair_implausibility`).
pub const KNIFE_EDGE: &str = "knife edge";

/// Largest equivalent conicity accepted (–): a 45° cone, well beyond worn wheels (~0.7).
pub const MAX_CONICITY: f64 = 1.0;

/// Lateral extent of the cone, m, centred on the taping line. The wheelset rolls on the knife
/// edges by φ = λy/(l − λr0) (Wickens), which moves the contact across the wheel by
/// y + r0·φ = y·l/(l − λr0): 3.2·y at λ = 0.8 and 7·y at λ = 1 (l = 0.75 m, r0 = 0.625 m),
/// plus the crown's offset (the contact sits where the crown's slope is λ). A ±15 mm table at
/// λ = 1 then reaches about 0.14 m from the taping line; ±0.25 m leaves room for wider tables.
const CONE_WIDTH: f64 = 0.5;

/// The (wheel, rail) pair whose equivalent conicity is `conicity` (–, in (0, 1]).
pub fn conical_pair(conicity: f64) -> Result<(Profile, Profile)> {
    if !(conicity.is_finite() && conicity > 0.0 && conicity <= MAX_CONICITY) {
        return Err(LocoError::param(
            "conicity",
            format!("must be in (0, {MAX_CONICITY}], got {conicity}"),
        ));
    }
    let start = -0.5 * CONE_WIDTH;
    let wheel = ProfileBuilder::new(start, start * conicity, conicity.atan())
        .line(CONE_WIDTH * (1.0 + conicity * conicity).sqrt())
        .build(&format!("cone {conicity}"), ProfileKind::Wheel, 5e-4)?;
    let flank = 80f64.to_radians();
    let rail = ProfileBuilder::new(-0.02, -0.04, flank)
        .line(0.03)
        .arc(0.01, -2.0 * flank)
        .line(0.03)
        .build(KNIFE_EDGE, ProfileKind::Rail, 2e-4)?;
    Ok((wheel, rail))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::conicity::equivalent_conicity;
    use crate::contact::delta_r::DeltaR;
    use crate::contact::{rolling_radius_difference, ContactGeometry, ContactSearchParams};
    use crate::contact::{TrackSetup, WheelsetSetup};

    #[test]
    fn pair_has_the_requested_equivalent_conicity() {
        let ys: Vec<f64> = (0..=240).map(|i| -0.012 + 1e-4 * i as f64).collect();
        for target in [0.05, 0.2, 0.4, 0.7] {
            let (wheel, rail) = conical_pair(target).unwrap();
            let geometry = ContactGeometry::symmetric(
                &wheel,
                &rail,
                &TrackSetup::default(),
                &WheelsetSetup::default(),
                &ContactSearchParams::default(),
            )
            .unwrap();
            let dr = rolling_radius_difference(&geometry, &ys).unwrap();
            let delta_r = DeltaR::new(ys.clone(), dr).unwrap();
            for amplitude in [0.002, 0.003, 0.006] {
                let tan = equivalent_conicity(&delta_r, amplitude).unwrap();
                assert!(
                    (tan / target - 1.0).abs() < 0.02,
                    "λ = {target}, amplitude {amplitude}: tan γe = {tan}"
                );
            }
        }
    }

    #[test]
    fn non_physical_conicity_is_refused_by_name() {
        for bad in [0.0, -0.1, f64::NAN, 1.5] {
            let err = conical_pair(bad).unwrap_err().to_string();
            assert!(err.contains("conicity"), "{err}");
        }
    }
}
