//! The 90 degrees of freedom of the locomotive and which body each belongs to.
//!
//! Order of the generalized coordinates `q` (SPEC §1):
//!
//! | range | body | coordinates |
//! |---|---|---|
//! | 0–5 | carbody | x, y, z, roll, pitch, yaw |
//! | 6–17 | bogie frames 1, 2 | 6 each |
//! | 18–41 | wheelsets 1–4 | x, y, z, roll, spin (rotation about the axle beyond rolling), yaw |
//! | 42–65 | traction motors 1–4 | 6 each |
//! | 66–77 | hollow shafts 1–4 | lateral, roll, yaw relative to their wheelset |
//! | 78–81 | traction rods 1, 2 | pitch, yaw relative to the carbody |
//! | 82–89 | axle-box rotary arms 1–8 | rotation about the wheelset axle |
//!
//! Bogie 1 and wheelset 1 lead (largest x); wheelsets 1, 2 are in bogie 1, 3, 4 in bogie 2.
//! Arm `2·w + s` belongs to wheelset `w`, side `s` (0 left, 1 right). Translations in m, rotations
//! in rad, all as small perturbations about the nominal configuration moving at the running speed.

/// Number of generalized coordinates.
pub const N_DOF: usize = 90;
/// Number of rigid bodies.
pub const N_BODIES: usize = 25;
/// Number of bogies, wheelsets, rotary arms.
pub const N_BOGIES: usize = 2;
pub const N_WHEELSETS: usize = 4;
pub const N_ARMS: usize = 8;

/// Indices of the six coordinates of a free body.
pub const X: usize = 0;
pub const Y: usize = 1;
pub const Z: usize = 2;
pub const ROLL: usize = 3;
pub const PITCH: usize = 4;
pub const YAW: usize = 5;

/// First coordinate of the carbody.
pub const CARBODY: usize = 0;

/// First coordinate of bogie frame `b` (0 or 1).
pub const fn frame(b: usize) -> usize {
    6 + 6 * b
}

/// First coordinate of wheelset `w` (0..4).
pub const fn wheelset(w: usize) -> usize {
    18 + 6 * w
}

/// First coordinate of traction motor `w` (one per wheelset).
pub const fn motor(w: usize) -> usize {
    42 + 6 * w
}

/// First of the three relative coordinates (lateral, roll, yaw) of hollow shaft `w`.
pub const fn hollow_shaft(w: usize) -> usize {
    66 + 3 * w
}

/// First of the two relative coordinates (pitch, yaw) of traction rod `b`.
pub const fn traction_rod(b: usize) -> usize {
    78 + 2 * b
}

/// The coordinate of rotary arm `2·w + side`.
pub const fn rotary_arm(w: usize, side: usize) -> usize {
    82 + 2 * w + side
}

/// The bogie that carries wheelset `w`.
pub const fn bogie_of(w: usize) -> usize {
    w / 2
}

/// What a coordinate measures, for the bounds a run checks its motion against.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoordinateKind {
    /// A lateral or vertical displacement, m.
    Translation,
    /// A longitudinal displacement, m. The reference frame moves at the imposed speed while the
    /// vehicle coasts (no traction), so hunting and rolling resistance let the whole vehicle fall
    /// slowly behind the frame (≈ 0.01 m/s² while hunting): only the motion relative to the
    /// carbody is bounded.
    Longitudinal,
    /// A rotation, rad.
    Rotation,
    /// A wheelset's rotation about its axle beyond steady rolling, rad: it accumulates the
    /// longitudinal creep of a whole run and has no bound.
    Spin,
}

/// The kind of coordinate `i` (0..[`N_DOF`]) in the order of the table above.
pub const fn coordinate_kind(i: usize) -> CoordinateKind {
    let six_dof_end = hollow_shaft(0);
    if i < six_dof_end {
        let local = i % 6;
        if i >= wheelset(0) && i < motor(0) && local == PITCH {
            CoordinateKind::Spin
        } else if local == X {
            CoordinateKind::Longitudinal
        } else if local < ROLL {
            CoordinateKind::Translation
        } else {
            CoordinateKind::Rotation
        }
    } else if i < traction_rod(0) && (i - six_dof_end).is_multiple_of(3) {
        CoordinateKind::Translation
    } else {
        CoordinateKind::Rotation
    }
}

/// Body numbers, in the order of [`body_names`].
pub const BODY_CARBODY: usize = 0;
pub const fn body_frame(b: usize) -> usize {
    1 + b
}
pub const fn body_wheelset(w: usize) -> usize {
    3 + w
}
pub const fn body_motor(w: usize) -> usize {
    7 + w
}
pub const fn body_hollow_shaft(w: usize) -> usize {
    11 + w
}
pub const fn body_traction_rod(b: usize) -> usize {
    15 + b
}
pub const fn body_rotary_arm(w: usize, side: usize) -> usize {
    17 + 2 * w + side
}
/// Whether a body's pitch coordinate is its spin beyond steady rolling (wheelsets, and the
/// hollow shafts whose spin follows them): a rotation that moves no attachment frame.
pub const fn body_pitch_is_spin(body: usize) -> bool {
    (body >= body_wheelset(0) && body < body_motor(0))
        || (body >= body_hollow_shaft(0) && body < body_traction_rod(0))
}

const SIDE: [&str; 2] = ["left", "right"];
const SIX: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];
const WHEELSET_SIX: [&str; 6] = ["x", "y", "z", "roll", "spin", "yaw"];

/// Names of the 25 bodies, in body-number order.
pub fn body_names() -> Vec<String> {
    let mut names = vec!["carbody".to_string()];
    names.extend((0..N_BOGIES).map(|b| format!("frame{}", b + 1)));
    names.extend((0..N_WHEELSETS).map(|w| format!("wheelset{}", w + 1)));
    names.extend((0..N_WHEELSETS).map(|w| format!("motor{}", w + 1)));
    names.extend((0..N_WHEELSETS).map(|w| format!("hollow_shaft{}", w + 1)));
    names.extend((0..N_BOGIES).map(|b| format!("traction_rod{}", b + 1)));
    for w in 0..N_WHEELSETS {
        for side in SIDE {
            names.push(format!("rotary_arm{}_{side}", w + 1));
        }
    }
    names
}

/// Names of the 90 coordinates, `body.coordinate`, in the order of `q`.
pub fn dof_names() -> Vec<String> {
    let mut names = Vec::with_capacity(N_DOF);
    let mut six = |body: String, coords: &[&str]| {
        for c in coords {
            names.push(format!("{body}.{c}"));
        }
    };
    six("carbody".into(), &SIX);
    for b in 0..N_BOGIES {
        six(format!("frame{}", b + 1), &SIX);
    }
    for w in 0..N_WHEELSETS {
        six(format!("wheelset{}", w + 1), &WHEELSET_SIX);
    }
    for w in 0..N_WHEELSETS {
        six(format!("motor{}", w + 1), &SIX);
    }
    for w in 0..N_WHEELSETS {
        six(
            format!("hollow_shaft{}", w + 1),
            &["y_rel", "roll_rel", "yaw_rel"],
        );
    }
    for b in 0..N_BOGIES {
        six(format!("traction_rod{}", b + 1), &["pitch_rel", "yaw_rel"]);
    }
    for w in 0..N_WHEELSETS {
        for side in SIDE {
            six(format!("rotary_arm{}_{side}", w + 1), &["rotation"]);
        }
    }
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ninety_unique_coordinates_in_index_order() {
        let names = dof_names();
        assert_eq!(names.len(), N_DOF);
        let unique: std::collections::BTreeSet<_> = names.iter().collect();
        assert_eq!(unique.len(), N_DOF);
        assert_eq!(names[CARBODY + YAW], "carbody.yaw");
        assert_eq!(names[frame(1) + Y], "frame2.y");
        assert_eq!(names[wheelset(3) + PITCH], "wheelset4.spin");
        assert_eq!(names[motor(0)], "motor1.x");
        assert_eq!(names[hollow_shaft(2) + 2], "hollow_shaft3.yaw_rel");
        assert_eq!(names[traction_rod(1)], "traction_rod2.pitch_rel");
        assert_eq!(names[rotary_arm(3, 1)], "rotary_arm4_right.rotation");
        assert_eq!(names[N_DOF - 1], "rotary_arm4_right.rotation");
    }

    #[test]
    fn coordinate_kinds_follow_the_names() {
        for (i, name) in dof_names().iter().enumerate() {
            let coordinate = name.split('.').nth(1).unwrap_or_default();
            let expected = match coordinate {
                "x" => CoordinateKind::Longitudinal,
                "y" | "z" | "y_rel" => CoordinateKind::Translation,
                "spin" => CoordinateKind::Spin,
                _ => CoordinateKind::Rotation,
            };
            assert_eq!(coordinate_kind(i), expected, "{name}");
        }
    }

    #[test]
    fn twenty_five_bodies() {
        let names = body_names();
        assert_eq!(names.len(), N_BODIES);
        assert_eq!(names[body_rotary_arm(2, 0)], "rotary_arm3_left");
        assert_eq!(names[body_traction_rod(0)], "traction_rod1");
        assert_eq!(names[body_hollow_shaft(3)], "hollow_shaft4");
    }
}
