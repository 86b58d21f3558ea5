//! Registry of built-in profiles: the CN60 rail (as rolled, and ground at the gauge corner) and the JM3-type wheel states of the study, and
//! ([`conical`]) a conical wheel on a knife-edge rail of any equivalent conicity.
//!
//! The geometry and its sources are documented next to each profile ([`cn60`], [`jm3`]); the
//! equivalent conicities the wheel states give on CN60 are asserted by this module's tests.

pub mod cn60;
pub mod conical;
pub mod jm3;

use super::profile::Profile;
use crate::error::{LocoError, Result};

/// Names accepted by [`builtin_profile`].
pub fn builtin_names() -> &'static [&'static str] {
    &[
        "cn60",
        "cn60-gauge-ground",
        "jm3-new",
        "jm3-thin-flange",
        "jm3-worn",
    ]
}

/// The built-in profile called `name`; the error lists the available names.
pub fn builtin_profile(name: &str) -> Result<Profile> {
    if let Some(state) = jm3::builtin_state(name) {
        return jm3::jm3(name, &state);
    }
    match name {
        "cn60" => cn60::cn60(),
        "cn60-gauge-ground" => cn60::cn60_gauge_ground(),
        _ => Err(LocoError::param(
            "name",
            format!(
                "no built-in profile '{name}'; available: [{}]",
                builtin_names().join(", ")
            ),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::conicity::equivalent_conicity;
    use crate::contact::delta_r::DeltaR;
    use crate::contact::{rolling_radius_difference, ContactGeometry, ContactSearchParams};
    use crate::contact::{TrackSetup, WheelsetSetup};

    #[test]
    fn unknown_name_lists_the_available_ones() {
        let err = builtin_profile("no-such-profile").unwrap_err();
        assert!(err.to_string().contains("available"));
        for name in builtin_names() {
            assert_eq!(builtin_profile(name).unwrap().name(), *name);
        }
    }

    /// The study's scenarios (SPEC §2): JM3 states on CN60 inclined 1:40, 1435 mm gauge at
    /// 16 mm, 1493 mm between nominal contact points, EN 15302 nonlinear method at 3 mm, within
    /// the standard's ± min(0.05, 0.5·tan γe). `jm3-new` is untuned; the tuned parameters of the
    /// other two are the tread slope (thin flange) and the band radius and slope (worn).
    #[test]
    fn jm3_states_on_cn60_have_the_scenario_conicities() {
        let rail = builtin_profile("cn60").unwrap();
        let ys: Vec<f64> = (0..=240).map(|i| -0.012 + 1e-4 * i as f64).collect();
        for (name, target) in [
            ("jm3-thin-flange", 0.04),
            ("jm3-new", 0.10),
            ("jm3-worn", 0.70),
        ] {
            let wheel = builtin_profile(name).unwrap();
            let geometry = ContactGeometry::symmetric(
                &wheel,
                &rail,
                &TrackSetup::default(),
                &WheelsetSetup::default(),
                &ContactSearchParams::default(),
            )
            .unwrap();
            let dr = rolling_radius_difference(&geometry, &ys).unwrap();
            let tan = equivalent_conicity(&DeltaR::new(ys.clone(), dr).unwrap(), 0.003).unwrap();
            let tolerance = f64::min(0.05, 0.5 * target);
            eprintln!("{name}: tan γe(3 mm) = {tan:.4} (target {target})");
            assert!(
                (tan - target).abs() <= tolerance,
                "{name}: {tan} vs {target}"
            );
        }
    }
}
