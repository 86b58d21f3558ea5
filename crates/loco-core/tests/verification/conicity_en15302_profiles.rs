//! EN 15302 benchmark cases computed end to end: the standard's reference wheel profiles on its
//! reference rail, Δr(y) from our contact geometry, then the nonlinear kinematic conicity, compared
//! with the standard's Δr functions (`dr_E*.dat`) point by point and with its reference
//! conicities and tolerance limits (`ben_E*.dat`) at every amplitude it evaluates.
//!
//! # Set-up (EN 15302 Annex E and the shared data README)
//!
//! Back-to-back 1360 mm, taping lines 70 mm from the flange backs (the wheel files have the
//! flange back at y = −70 mm), wheel diameters 920 mm (E5–E8: 920 right / 918 left), rail profile
//! A as given: it is already inclined and drawn in the frame of the centred wheel, origin at the
//! nominal contact point (its z(0) = 0) with the gauge point (−32.5, −14) mm, i.e. 717.5 mm from the
//! track centre when the taping line is at 1360/2 + 70 = 750 mm. So the rail is placed by that point
//! at gauge 1435 mm (`gauge_height` = 14 mm below z = 0). The README's "1435.16 mm" is not a
//! second placement: combined with that point (as this test did before) it moves each rail 0.08 mm
//! outward, which lowers Δr for |y| ≤ 6 mm by 0.01–0.05 mm (median per wheel; up to 0.27 mm for
//! wheel A, more where it moves a contact jump across a grid point) and delays flange contact.
//!
//! # Δr is that of the wheelset translated without roll
//!
//! The standard's Δr functions are those of a wheelset displaced laterally without roll, each
//! wheel touching its rail at its own lowest point ([`rolling_radius_difference`]), not those of
//! the rigidly rolled wheelset of [`ContactGeometry::solve`]. Unrolled, our Δr agrees with
//! `dr_E*.dat` at the grid points to a median of 0.002–0.025 mm per case (90th percentile at most
//! 0.08 mm; the rest are contact jumps and the steep flange); rolled, the medians are 0.04–0.25 mm
//! and the 90th percentiles up to 2.5 mm. The roll is why the earlier, ignored version of this test
//! found Δr rising too early near the flange: at y = 6.4 mm (E1) the rolled wheelset has 1.0 mrad of
//! roll, which turns the flange r·φ ≈ 0.45 mm further toward the rail, and gives Δr = 12.8 mm; the
//! reference is 5.69 mm, the unrolled wheelset 5.76 mm. For E5–E8 the unequal radii alone roll the
//! wheelset 0.66 mrad at y = 0. Rolled (at either placement) 146–168 of the 594 amplitudes fall
//! outside the limits, unrolled at 1435 mm 4.
//!
//! # The four amplitudes the reference does not decide (E3)
//!
//! Wheel H on rail A has two contact jumps next to grid points of the standard's 0.1 mm Δr grid:
//! tread to flange root (Δr 0.125 → 2.386 mm) at y = 2.4962 mm, and onto the flange (3.33 → 9.16
//! mm) at y = 6.6989 mm in our geometry, 3.8 µm and 1.1 µm before the grid points 2.5 and 6.7 mm;
//! the reference has both just after them (its Δr(2.5 mm) = 0.125, Δr(6.7 mm) = 3.33 mm). Where the
//! jump falls is decided by a height difference of the two gap minima of 0.7 µm (0.18 µm per µm of
//! y). All E3 amplitudes from 2.5 to 3.3 mm and from 6.7 to 7.1 mm depend on that side: as set up,
//! 2.5, 2.6, 2.7 and 6.7 mm fall outside (2.5 mm: 0.078 against 0.025, limits [0.012, 0.037]) and
//! 2.8 and 6.8 mm are inside by less than 0.005; with both rails 10 µm further out E3 matches the
//! reference within 0.008 at every amplitude. E2 at 3.0 mm, whose jump is 0.9 µm before its grid
//! point on the reference's side, then flips the other way (0.025 against 0.058): no placement is
//! right for both to a µm. So the test accepts an amplitude outside the limits only when it comes
//! inside with the rails moved by a tenth of the grid step (10 µm) either way, and asserts that at
//! most these four need it. Everything else is inside as set up: 590 of the 594 amplitudes, largest
//! |tan γe − reference| 0.05 (E3 at 6.8 mm; E7 0.038, the other cases at most 0.022).

use crate::record::Record;
use crate::support;

use loco_core::contact::conicity::equivalent_conicity;
use loco_core::contact::delta_r::DeltaR;
use loco_core::contact::{
    load_profile, rolling_radius_difference, ContactGeometry, Profile, ProfileKind, TrackSetup,
    WheelsetSetup,
};

/// (case, left wheel, right wheel, left diameter, right diameter in m, first grid point of
/// `dr_E{case}.dat` in mm), with the README's "right / left" assignment.
const CASES: &[(usize, &str, &str, f64, f64, f64)] = &[
    (1, "A", "A", 0.920, 0.920, -6.8),
    (2, "B", "B", 0.920, 0.920, -6.8),
    (3, "H", "H", 0.920, 0.920, -6.8),
    (4, "I", "I", 0.920, 0.920, -7.1),
    (5, "A", "A", 0.918, 0.920, -6.8),
    (6, "B", "B", 0.918, 0.920, -6.9),
    (7, "H", "H", 0.918, 0.920, -6.8),
    (8, "I", "I", 0.918, 0.920, -7.1),
    (9, "B", "A", 0.920, 0.920, -6.8),
];

/// Track gauge of the set-up (m), see the module documentation.
const GAUGE: f64 = 1.435;

/// Rail placement tolerance for amplitudes decided by a contact jump at a grid point: a tenth of
/// the standard's 0.1 mm Δr grid step, per rail (m).
const JUMP_PLACEMENT: f64 = 1e-5;

fn numbers(relative: &str) -> Option<Vec<f64>> {
    let text = std::fs::read_to_string(support::shared_file(relative)?).ok()?;
    Some(
        text.split_whitespace()
            .map(|t| t.parse().expect("number in benchmark file"))
            .collect(),
    )
}

/// Rows (amplitude m, reference, lower, upper) of `ben_E{case}.dat`, the limits the tighter of
/// the file's two pairs.
fn reference(case: usize) -> Option<Vec<[f64; 4]>> {
    let v = numbers(&format!("en15302/ben_E{case}.dat"))?;
    Some(
        v.chunks(6)
            .map(|c| [c[0] * 1e-3, c[1], c[3].max(c[5]), c[2].min(c[4])])
            .collect(),
    )
}

fn load(relative: &str, kind: ProfileKind) -> Option<Profile> {
    Some(load_profile(&support::shared_file(relative)?, Some(kind), false).unwrap())
}

/// The geometry of `case` with the rails `outward` (m) further out than the nominal placement.
fn geometry(case: usize, outward: f64) -> Option<ContactGeometry> {
    let &(_, left, right, d_left, d_right, _) = CASES.iter().find(|c| c.0 == case)?;
    let rail = load("en15302/SUIC519A.dat", ProfileKind::Rail)?;
    let wl = load(&format!("en15302/RUIC519{left}.dat"), ProfileKind::Wheel)?;
    let wr = load(&format!("en15302/RUIC519{right}.dat"), ProfileKind::Wheel)?;
    let top = rail.z().iter().copied().fold(f64::MIN, f64::max);
    let track = TrackSetup {
        gauge: GAUGE + 2.0 * outward,
        // 14 mm below the file's z = 0: the gauge point is the file's first point.
        gauge_height: 0.014 + top,
        rail_inclination: 0.0,
    };
    let wheelset = WheelsetSetup {
        back_to_back: 1.360,
        flange_back_offset: 0.070,
        nominal_radius: [0.5 * d_left, 0.5 * d_right],
    };
    let g = ContactGeometry::new(
        [&wl, &wr],
        [&rail, &rail],
        &track,
        &wheelset,
        &Default::default(),
    );
    Some(g.unwrap())
}

/// Our Δr (mm) against `dr_E*.dat` at its grid points. The files count y and Δr toward the
/// README's right wheel, ours toward the left: Δr_file(y) = −Δr_ours(−y).
#[test]
fn reference_profiles_give_the_reference_rolling_radius_difference() {
    let mut record = Record::new("conicity_profiles_delta_r", file!());
    let (mut lowest, mut highest) = (f64::INFINITY, 0.0_f64);
    for &(case, .., start_mm) in CASES {
        let (Some(g), Some(reference)) = (
            geometry(case, 0.0),
            numbers(&format!("en15302/dr_E{case}.dat")),
        ) else {
            return;
        };
        let ys: Vec<f64> = (0..reference.len())
            .map(|i| -(start_mm + 0.1 * i as f64) * 1e-3)
            .collect();
        let ours = rolling_radius_difference(&g, &ys).unwrap();
        let mut errors: Vec<f64> = ours
            .iter()
            .zip(&reference)
            .map(|(o, r)| (-o * 1e3 - r).abs())
            .collect();
        errors.sort_by(f64::total_cmp);
        let (median, p90) = (errors[errors.len() / 2], errors[errors.len() * 9 / 10]);
        eprintln!("E{case}: |Δr − reference| median {median:.4} mm, 90th percentile {p90:.4} mm");
        // The rolled wheelset fails both in every case (medians 0.04–0.25 mm).
        assert!(median < 0.03, "E{case}: median {median} mm");
        assert!(p90 < 0.1, "E{case}: 90th percentile {p90} mm");
        record = record
            .within(&format!("e{case}_median"), median, "mm", 2, "<", 0.03)
            .within(&format!("e{case}_p90"), p90, "mm", 2, "<", 0.1);
        (lowest, highest) = (lowest.min(median), highest.max(median));
    }
    record
        .value("lowest_median", lowest, "mm", 2)
        .value("highest_median", highest, "mm", 2)
        .check();
}

/// Equivalent conicity (−) at each amplitude of `ben_E{case}.dat` from our Δr on ±9 mm, sampled
/// on the standard's 0.1 mm grid; `None` where the swing leaves the samples.
fn conicities(g: &ContactGeometry, rows: &[[f64; 4]]) -> Vec<Option<f64>> {
    let ys: Vec<f64> = (0..=180).map(|i| -0.009 + 1e-4 * i as f64).collect();
    let f = DeltaR::new(ys.clone(), rolling_radius_difference(g, &ys).unwrap()).unwrap();
    rows.iter()
        .map(|row| match equivalent_conicity(&f, row[0]) {
            Ok(tan) => Some(tan),
            Err(err) => {
                assert!(err.to_string().contains("beyond the Δr samples"), "{err}");
                None
            }
        })
        .collect()
}

#[test]
fn reference_profiles_give_the_reference_conicities() {
    let (mut checked, mut e1_to_e4, mut jump_limited, mut outside) = (0, 0, 0, 0);
    // Largest |tan γe − reference| over all amplitudes, and over those inside at the nominal set-up.
    let (mut worst, mut worst_inside) = (0.0_f64, 0.0_f64);
    for &(case, ..) in CASES {
        let (Some(g), Some(rows)) = (geometry(case, 0.0), reference(case)) else {
            return;
        };
        let nominal = conicities(&g, &rows);
        let mut shifted: Option<[Vec<Option<f64>>; 2]> = None;
        let mut case_worst = 0.0_f64;
        for (k, (row, tan)) in rows.iter().zip(&nominal).enumerate() {
            let [amplitude, tan_ref, lower, upper] = *row;
            let inside = |t: Option<f64>| t.is_some_and(|t| t >= lower && t <= upper);
            let Some(tan) = *tan else { continue };
            checked += 1;
            e1_to_e4 += usize::from(case <= 4);
            case_worst = case_worst.max((tan - tan_ref).abs());
            if inside(Some(tan)) {
                worst_inside = worst_inside.max((tan - tan_ref).abs());
                continue;
            }
            let [out, inn] = shifted.get_or_insert_with(|| {
                [JUMP_PLACEMENT, -JUMP_PLACEMENT]
                    .map(|d| conicities(&geometry(case, d).unwrap(), &rows))
            });
            let rescued = inside(out[k]) || inside(inn[k]);
            let show = |t: Option<f64>| t.map_or("-".into(), |t| format!("{t:.4}"));
            eprintln!(
                "E{case} at {:.1} mm: {tan:.4}, reference {tan_ref} [{lower}, {upper}]; rails 10 µm \
                 out / in: {} / {}{}",
                amplitude * 1e3,
                show(out[k]),
                show(inn[k]),
                if rescued { " (contact jump at a grid point)" } else { "  OUTSIDE" }
            );
            jump_limited += usize::from(rescued);
            outside += usize::from(!rescued);
        }
        eprintln!("E{case}: largest |tan γe − reference| {case_worst:.4}");
        worst = worst.max(case_worst);
    }
    eprintln!(
        "E1–E9 from profiles: {checked} amplitudes checked ({e1_to_e4} of E1–E4), {outside} \
         outside the limits, {jump_limited} decided by a contact jump at a grid point; largest \
         |tan γe − reference| {worst:.4}, {worst_inside:.4} over the amplitudes inside as set up"
    );
    // Every amplitude of every case: 66 × 9 (none leaves the ±9 mm of Δr samples).
    assert_eq!((checked, e1_to_e4), (594, 264));
    assert_eq!(outside, 0, "amplitudes outside the tolerance limits");
    assert!(
        jump_limited <= 4,
        "{jump_limited} amplitudes need the rail tolerance"
    );
    Record::new("conicity_profiles_tan", file!())
        .count("amplitudes", checked)
        .count("inside_as_set_up", checked - jump_limited - outside)
        .count("inside_with_rails_moved", jump_limited)
        .within("outside", outside as f64, "", 1, "=", 0.0)
        .value("largest_deviation", worst, "", 2)
        .value("largest_deviation_inside", worst_inside, "", 2)
        .check();
}
