//! Plausibility of a wheel or rail profile: the checks that catch a file in the wrong unit, a
//! wheel given as the rail (or the reverse), a flangeless wheel and a stray point, before the
//! contact search fails on them with a message about something else.
//!
//! In the profile frame (`contact::profile`: y toward the field side, z up; a wheel's
//! `z = r0 − r(y)`, so its flange tip is its lowest point, on the low-y side):
//!
//! - **width** (the y span) between [`MIN_WIDTH`] and [`MAX_WIDTH`]: a wheel rim is about 135 mm
//!   wide (EN 13715's treads), a rail head about 70 mm (60E1: 72 mm, CN60: 73 mm); a file in
//!   metres read as millimetres (or the reverse) is 1000 times off and far outside;
//! - **height** (the z span) at most [`MAX_HEIGHT`]: a wheel's flange is about 28–36 mm high,
//!   a rail head's profile drops by some 10–40 mm from its top, a file 1000 times too large
//!   spans metres;
//! - a **wheel** has a **flange**: its lowest point lies inside the profile and at least
//!   [`MIN_FLANGE_HEIGHT`] below the field-side end (the flanges of the study's JM3 treads are
//!   about 27–32 mm high; a profile whose lowest point is at an end is a rail, or a wheel without
//!   a flange, which no contact table can keep on the track);
//! - a wheel's **tread is monotonic**: from the flange tip to the field side z never falls by more
//!   than [`MAX_HOLLOW`] (a hollow-worn tread's false flange is a few mm; a stray point is not);
//! - a **rail head falls away from its top**: from the highest point toward either end z never
//!   rises by more than [`MAX_REVERSAL`] (a wheel given as the rail rises again at its flange back).
//!
//! Every reason names the profile and what was found; the caller adds the file or the argument.

use super::profile::{Profile, ProfileKind};

/// Narrowest profile, m.
pub const MIN_WIDTH: f64 = 0.02;
/// Widest profile, m: a rim is about 135 mm wide and a rail head about 70 mm, and a file 1000
/// times off is 0.1 mm or 100 m wide, so any bound between catches it; 1 m leaves room for the
/// idealised 500 mm cone of [`super::builtin::conical`].
pub const MAX_WIDTH: f64 = 1.0;
/// Largest height span, m: a wheel's flange is about 28–36 mm high and a rail head's profile drops
/// by some 10–40 mm, while a file 1000 times too large spans tens of metres; 0.6 m leaves room
/// for the idealised cone (0.5 m high at its steepest, conicity 1).
pub const MAX_HEIGHT: f64 = 0.6;
/// Least flange height of a wheel (lowest point below the field-side end), m.
pub const MIN_FLANGE_HEIGHT: f64 = 0.015;
/// Deepest hollow of a wheel's tread (its false flange), m: above the limits a locomotive may run
/// on, a tread worn hollow 5/16 in (7.9 mm) in road service and 3/8 in (9.5 mm) in switching
/// service (US 49 CFR 229.75(g)), so every wheel in service passes and a stray point does not.
pub const MAX_HOLLOW: f64 = 0.010;
/// Largest rise of a rail head's flanks back toward its top, m: a measured head falls away from
/// its crown on both sides (a profilometer's noise is a fraction of a millimetre), while a wheel
/// read as the rail rises again by its flange height (25–36 mm) at the flange back.
pub const MAX_REVERSAL: f64 = 0.005;

/// Why `profile` is not a plausible profile of its kind, or None when it is.
pub fn implausibility(profile: &Profile) -> Option<String> {
    checked(profile, true)
}

/// Which of a run's `wheel` and `rail` is implausible (`"wheel"` or `"rail"`) and why, or None.
/// A wheel needs its flange on every rail but the knife edge of the idealised conical pair
/// ([`super::builtin::conical::KNIFE_EDGE`]), whose crown keeps the contact on the cone.
pub fn pair_implausibility(wheel: &Profile, rail: &Profile) -> Option<(&'static str, String)> {
    let needs_flange = rail.name() != super::builtin::conical::KNIFE_EDGE;
    if let Some(reason) = checked(wheel, needs_flange) {
        return Some(("wheel", reason));
    }
    implausibility(rail).map(|reason| ("rail", reason))
}

/// [`implausibility`], a wheel's flange checked only when `needs_flange`.
fn checked(profile: &Profile, needs_flange: bool) -> Option<String> {
    let (y, z) = (profile.y(), profile.z());
    let (name, kind) = (profile.name(), profile.kind().as_str());
    let width = y[y.len() - 1] - y[0];
    if !(MIN_WIDTH..=MAX_WIDTH).contains(&width) {
        return Some(format!(
            "{kind} profile '{name}' is {:.4} mm wide; a {kind} profile is {:.0}–{:.0} mm wide \
             (a file in m read as mm, or the reverse, is 1000 times off)",
            width * 1e3,
            MIN_WIDTH * 1e3,
            MAX_WIDTH * 1e3
        ));
    }
    let (lo, hi) = z
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if hi - lo > MAX_HEIGHT {
        return Some(format!(
            "{kind} profile '{name}' spans {:.1} mm in height; at most {:.0} mm is plausible",
            (hi - lo) * 1e3,
            MAX_HEIGHT * 1e3
        ));
    }
    match profile.kind() {
        ProfileKind::Wheel => wheel_problem(name, y, z, needs_flange),
        ProfileKind::Rail => rail_problem(name, y, z),
    }
}

fn wheel_problem(name: &str, y: &[f64], z: &[f64], needs_flange: bool) -> Option<String> {
    let n = z.len();
    let tip = (0..n).fold(0, |best, i| if z[i] < z[best] { i } else { best });
    let flange = z[n - 1] - z[tip];
    if needs_flange && (tip == 0 || tip == n - 1 || flange < MIN_FLANGE_HEIGHT) {
        return Some(format!(
            "wheel profile '{name}' has no flange: its lowest point (y = {:.1} mm) is {} and \
             {:.1} mm below its field-side end; a wheel's flange tip lies inside the profile, at \
             least {:.0} mm below the tread (is it a rail profile, or a flangeless wheel?)",
            y[tip] * 1e3,
            if tip == 0 || tip == n - 1 {
                "at an end of the profile"
            } else {
                "inside the profile"
            },
            flange * 1e3,
            MIN_FLANGE_HEIGHT * 1e3
        ));
    }
    let mut top = z[tip];
    for i in tip + 1..n {
        top = top.max(z[i]);
        if top - z[i] > MAX_HOLLOW {
            return Some(format!(
                "wheel profile '{name}': the tread is not monotonic: at y = {:.2} mm z falls \
                 {:.1} mm below the tread before it (at most {:.0} mm, a hollow tread's false \
                 flange); a stray point?",
                y[i] * 1e3,
                (top - z[i]) * 1e3,
                MAX_HOLLOW * 1e3
            ));
        }
    }
    None
}

fn rail_problem(name: &str, y: &[f64], z: &[f64]) -> Option<String> {
    let n = z.len();
    let crown = (0..n).fold(0, |best, i| if z[i] > z[best] { i } else { best });
    let sides = [
        (crown..n).collect::<Vec<_>>(),
        (0..=crown).rev().collect::<Vec<_>>(),
    ];
    for side in sides {
        let mut low = z[crown];
        for i in side {
            low = low.min(z[i]);
            if z[i] - low > MAX_REVERSAL {
                return Some(format!(
                    "rail profile '{name}' rises again by {:.1} mm at y = {:.2} mm after falling \
                     from its top: a rail head falls away from its top on both sides (at most \
                     {:.0} mm back); is it a wheel profile (a flange), or a stray point?",
                    (z[i] - low) * 1e3,
                    y[i] * 1e3,
                    MAX_REVERSAL * 1e3
                ));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::builtin::{builtin_names, builtin_profile};

    #[test]
    fn every_builtin_profile_is_plausible() {
        for name in builtin_names() {
            let p = builtin_profile(name).unwrap();
            assert_eq!(implausibility(&p), None, "{name}");
        }
    }

    #[test]
    fn every_jm3_tread_state_the_family_accepts_is_plausible() {
        use crate::contact::builtin::jm3::{
            conical_tread, tread, TreadState, MAX_CONE_SLOPE, MIN_BAND_RADIUS, MIN_CONE_SLOPE,
        };
        // The corners of the family's domain (some do not build: a steep band of small radius
        // does not fit between flange and outer tread) and the built-in states' ranges.
        let mut built = 0;
        for tread_slope in [MIN_CONE_SLOPE, 0.08, 0.125, MAX_CONE_SLOPE] {
            for band_radius in [MIN_BAND_RADIUS, 0.2, 0.8, f64::INFINITY] {
                for flange_thickness in [0.022, 0.026, 0.034] {
                    let state = TreadState {
                        flange_thickness,
                        tread_slope,
                        band_radius,
                    };
                    if let Ok(p) = tread(&state) {
                        assert_eq!(implausibility(&p), None, "{state:?}");
                        built += 1;
                    }
                }
            }
            let cone = conical_tread(tread_slope).unwrap();
            assert_eq!(implausibility(&cone), None, "cone {tread_slope}");
        }
        assert!(built >= 10, "only {built} states built");
    }

    #[test]
    fn the_idealised_cone_needs_no_flange_on_its_knife_edge_only() {
        use crate::contact::builtin::conical::{conical_pair, MAX_CONICITY};
        for conicity in [0.01, 0.1, 0.7, MAX_CONICITY] {
            let (cone, knife) = conical_pair(conicity).unwrap();
            assert_eq!(pair_implausibility(&cone, &knife), None, "{conicity}");
            let cn60 = builtin_profile("cn60").unwrap();
            let (field, why) = pair_implausibility(&cone, &cn60).unwrap();
            assert!(field == "wheel" && why.contains("has no flange"), "{why}");
        }
        let wheel = builtin_profile("jm3-worn").unwrap();
        let rail = builtin_profile("cn60-gauge-ground").unwrap();
        assert_eq!(pair_implausibility(&wheel, &rail), None);
    }

    #[test]
    fn units_swaps_missing_flanges_and_stray_points_are_named() {
        let wheel = builtin_profile("jm3-new").unwrap();
        let rail = builtin_profile("cn60").unwrap();
        let scaled = |p: &Profile, k: f64| {
            let y: Vec<f64> = p.y().iter().map(|v| v * k).collect();
            let z: Vec<f64> = p.z().iter().map(|v| v * k).collect();
            Profile::new(p.name(), p.kind(), &y, &z).unwrap()
        };
        for k in [1e-3, 1e3] {
            let why = implausibility(&scaled(&wheel, k)).unwrap();
            assert!(why.contains("wide"), "{why}");
            let why = implausibility(&scaled(&rail, k)).unwrap();
            assert!(why.contains("rail profile 'cn60'"), "{why}");
        }
        let as_rail = Profile::new("w", ProfileKind::Rail, wheel.y(), wheel.z()).unwrap();
        let why = implausibility(&as_rail).unwrap();
        assert!(why.contains("is it a wheel profile"), "{why}");
        let as_wheel = Profile::new("r", ProfileKind::Wheel, rail.y(), rail.z()).unwrap();
        let why = implausibility(&as_wheel).unwrap();
        assert!(why.contains("has no flange"), "{why}");
        // A flangeless wheel: the tread continued straight across the flange.
        let flat: Vec<f64> = wheel.y().iter().map(|y| -0.05 * y).collect();
        let flangeless = Profile::new("f", ProfileKind::Wheel, wheel.y(), &flat).unwrap();
        assert!(implausibility(&flangeless)
            .unwrap()
            .contains("has no flange"));
        // One point of the tread raised 50 mm (a smaller radius there).
        let mut z = wheel.z().to_vec();
        let i = wheel.y().iter().position(|&y| y > 0.02).unwrap();
        z[i] += 0.05;
        let spike = Profile::new("s", ProfileKind::Wheel, wheel.y(), &z).unwrap();
        let why = implausibility(&spike).unwrap();
        assert!(why.contains("not monotonic"), "{why}");
    }
}
