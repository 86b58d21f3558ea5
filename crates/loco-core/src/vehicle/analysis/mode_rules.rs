//! Which mode is the carbody mode and which the bogie mode: rules on a mode's frequency and the
//! kinetic-energy shares of [`crate::vehicle::analysis::modes`].
//!
//! The low-conicity problem of a locomotive is a lateral mode in which the carbody sways and
//! yaws on its secondary suspension while the wheelsets run kinematically under it (carbody
//! hunting, 0.5–2 Hz); the high-conicity problem is the hunting of the bogies and wheelsets
//! themselves, a few hertz, with the carbody nearly still (Iwnicki (ed.), *Handbook of Railway
//! Vehicle Dynamics*, 2nd ed., CRC 2019, ch. on stability: "body hunting" and "bogie hunting";
//! Wickens, *Fundamentals of Rail Vehicle Dynamics*, Swets & Zeitlinger 2003, ch. 5). Both are
//! lateral modes that the contact drives, so the wheelsets carry part of their energy; what sets
//! them apart is where the rest of the energy is. A rule admits the modes in its frequency band
//! whose energy shares pass its bounds and picks the least damped of them. The bounds were set
//! on the default vehicle at 200 km/h over conicity 0.01–0.7 (cones on knife-edge rails and the
//! S_low, S_norm and S_high pairs) and yaw damping 100–1000 kN·s/m: the carbody hunting mode
//! has 37–82 % of its energy in the carbody and 5–18 % in the wheelsets, the lower and upper
//! sway modes of the carbody on its springs 0–2 % in the wheelsets; the bogie hunting mode
//! 0–15 % in the carbody and 14–20 % in the frames, the motors' lateral modes on their mounts
//! 2–8 % in the frames.

use crate::error::{LocoError, Result};
use crate::vehicle::analysis::modes::{body_kind, ModeEnergy};

/// Indices of the lateral, roll and yaw motions in [`crate::vehicle::analysis::modes::MOTIONS`].
const LATERAL_PLANE: [usize; 3] = [1, 3, 5];

/// A rule that picks one mode of a linearised vehicle by its frequency and energy shares.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeRule {
    /// The rule's name (`carbody`, `bogie`).
    pub name: &'static str,
    /// Frequency band, Hz (inclusive).
    pub band: (f64, f64),
    /// Least and largest share (–) of the mode's kinetic energy in the carbody.
    pub carbody_share: (f64, f64),
    /// Least share (–) of the mode's kinetic energy in the wheelsets: the contact drives it.
    pub min_wheelset_share: f64,
    /// Least share (–) of the mode's kinetic energy in the bogie frames.
    pub min_frame_share: f64,
    /// Least share (–) of the mode's kinetic energy in lateral, roll and yaw motion, all bodies
    /// together: a lateral mode.
    pub min_lateral_share: f64,
}

/// The carbody-coupled lateral mode (carbody hunting): 0.3–3 Hz, at least 30 % of the energy in
/// the carbody and 2 % in the wheelsets, 80 % lateral, roll and yaw.
pub const CARBODY_MODE: ModeRule = ModeRule {
    name: "carbody",
    band: (0.3, 3.0),
    carbody_share: (0.3, 1.0),
    min_wheelset_share: 0.02,
    min_frame_share: 0.0,
    min_lateral_share: 0.8,
};

/// The bogie mode (bogie and wheelset hunting at high conicity): 1–10 Hz, at most 25 % of the
/// energy in the carbody, at least 10 % in the frames and 2 % in the wheelsets, 80 % lateral,
/// roll and yaw. At low conicity, where the kinematic motion lies in the carbody mode, it picks
/// the running gear's least damped lateral mode.
pub const BOGIE_MODE: ModeRule = ModeRule {
    name: "bogie",
    band: (1.0, 10.0),
    carbody_share: (0.0, 0.25),
    min_wheelset_share: 0.02,
    min_frame_share: 0.10,
    min_lateral_share: 0.8,
};

/// Every mode rule, by name.
pub const MODE_RULES: [ModeRule; 2] = [CARBODY_MODE, BOGIE_MODE];

/// The rule called `name`, or an error naming the known ones.
pub fn mode_rule(name: &str) -> Result<&'static ModeRule> {
    MODE_RULES.iter().find(|r| r.name == name).ok_or_else(|| {
        let known: Vec<&str> = MODE_RULES.iter().map(|r| r.name).collect();
        LocoError::param(
            "rule",
            format!("unknown mode rule `{name}` (known: {})", known.join(", ")),
        )
    })
}

/// One mode as the rules see it: frequency (Hz), damping ratio (–) and energy shares.
#[derive(Debug, Clone, Copy)]
pub struct RatedMode<'a> {
    pub frequency: f64,
    pub damping_ratio: f64,
    pub energy: &'a ModeEnergy,
}

impl ModeRule {
    /// Whether the rule admits a mode of `frequency` (Hz) with the energy shares `energy`, whose
    /// bodies are of the kinds `kinds` (as [`body_kind`] names them).
    pub fn admits(&self, frequency: f64, energy: &ModeEnergy, kinds: &[&str]) -> bool {
        let share_of = |kind: &str| -> f64 {
            kinds
                .iter()
                .zip(&energy.bodies)
                .filter(|(k, _)| **k == kind)
                .map(|(_, s)| s)
                .sum()
        };
        let lateral: f64 = energy
            .bodies
            .iter()
            .zip(&energy.motions)
            .map(|(s, m)| s * LATERAL_PLANE.iter().map(|&k| m[k]).sum::<f64>())
            .sum();
        let carbody = share_of("carbody");
        (self.band.0..=self.band.1).contains(&frequency)
            && (self.carbody_share.0..=self.carbody_share.1).contains(&carbody)
            && share_of("wheelsets") >= self.min_wheelset_share
            && share_of("frames") >= self.min_frame_share
            && lateral >= self.min_lateral_share
    }

    /// The index in `modes` of the least damped mode the rule admits (the first of equals),
    /// `None` when it admits none. `kinds` are the kinds of the bodies in the energies' order.
    pub fn pick(&self, modes: &[RatedMode<'_>], kinds: &[&str]) -> Option<usize> {
        modes
            .iter()
            .enumerate()
            .filter(|(_, m)| self.admits(m.frequency, m.energy, kinds))
            .min_by(|(_, a), (_, b)| a.damping_ratio.total_cmp(&b.damping_ratio))
            .map(|(i, _)| i)
    }
}

/// The kinds of the named bodies, for [`ModeRule::admits`].
pub fn body_kinds(names: &[String]) -> Vec<String> {
    names.iter().map(|n| body_kind(n)).collect()
}

#[cfg(test)]
mod tests;
