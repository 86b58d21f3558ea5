//! What moves in a mode: each body's share of the mode's kinetic energy, split into its six
//! motions.
//!
//! The 90 coordinates mix metres, radians and motions relative to a parent body (hollow shafts,
//! traction rods, rotary arms), so their squared amplitudes say little about which bodies move.
//! The mass matrix does: `M = Σ_b T_bᵀ D_b T_b` with `T_b` the map from the coordinates to body
//! `b`'s absolute motion (x, y, z in m; roll, pitch, yaw in rad, at its centre of gravity) and
//! `D_b = diag(m, m, m, Ixx, Iyy, Izz)` (principal axes along the vehicle's). For a complex mode
//! shape `q` the velocity amplitude is `λq`, so the mean kinetic energy of body `b` is
//! proportional to `Σ_k D_b[k]·|(T_b q)_k|²`: its share of the total, split into the six motions,
//! is independent of units and of how the coordinates are chosen.

use crate::error::{LocoError, Result};
use crate::vehicle::model::layout::N_DOF;
use crate::vehicle::model::structure::VehicleStructure;

/// The six motions of a body, in the order of its motion map.
pub const MOTIONS: [&str; 6] = [
    "longitudinal",
    "lateral",
    "vertical",
    "roll",
    "pitch",
    "yaw",
];

/// The kind of a body from its name: `wheelset3` → `wheelsets`, `rotary_arm2_left` →
/// `rotary_arms`, `carbody` → `carbody`.
pub fn body_kind(name: &str) -> String {
    let digit = |c: char| c.is_ascii_digit();
    // A trailing index, optionally followed by a side (`2_left`), is dropped.
    let indexed = ["_left", "_right"]
        .iter()
        .find_map(|side| name.strip_suffix(side))
        .filter(|stem| stem.ends_with(digit))
        .unwrap_or(name);
    let stem = indexed.trim_end_matches(digit);
    if stem == "carbody" {
        stem.to_string()
    } else {
        format!("{stem}s")
    }
}

/// Kinetic-energy shares of one mode.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeEnergy {
    /// Each body's share (–) of the mode's kinetic energy, in body order; sums to 1 (all zero
    /// for a mode without kinetic energy).
    pub bodies: Vec<f64>,
    /// Per body, the share (–) of its own energy in each of [`MOTIONS`] (zero for a body at
    /// rest).
    pub motions: Vec<[f64; 6]>,
}

/// The energy shares of the complex mode shape `re + i·im`, whose first 90 entries are the
/// coordinates (a state-space eigenvector may carry velocities and damper states after them).
pub fn mode_energy(structure: &VehicleStructure, re: &[f64], im: &[f64]) -> Result<ModeEnergy> {
    if re.len() != im.len() || re.len() < N_DOF {
        return Err(LocoError::input(
            "mode shape",
            format!(
                "real and imaginary parts need the same length of at least {N_DOF}, got {} and {}",
                re.len(),
                im.len()
            ),
        ));
    }
    if re.iter().chain(im).any(|v| !v.is_finite()) {
        return Err(LocoError::input("mode shape", "has a non-finite entry"));
    }
    let mut energy: Vec<[f64; 6]> = Vec::with_capacity(structure.bodies.len());
    for body in &structure.bodies {
        let [ixx, iyy, izz] = body.inertia;
        let diag = [body.mass, body.mass, body.mass, ixx, iyy, izz];
        let mut e = [0.0; 6];
        for (k, row) in body.map.rows().iter().enumerate() {
            let (mut u_re, mut u_im) = (0.0, 0.0);
            for &(j, c) in row {
                u_re += c * re[j];
                u_im += c * im[j];
            }
            e[k] = diag[k] * (u_re * u_re + u_im * u_im);
        }
        energy.push(e);
    }
    let per_body: Vec<f64> = energy.iter().map(|e| e.iter().sum()).collect();
    let total: f64 = per_body.iter().sum();
    let share = |v: f64, of: f64| if of > 0.0 { v / of } else { 0.0 };
    Ok(ModeEnergy {
        bodies: per_body.iter().map(|&e| share(e, total)).collect(),
        motions: energy
            .iter()
            .zip(&per_body)
            .map(|(e, &b)| e.map(|v| share(v, b)))
            .collect(),
    })
}

/// [`mode_energy`] of each mode shape `(re, im)`.
pub fn mode_energies(
    structure: &VehicleStructure,
    shapes: &[(&[f64], &[f64])],
) -> Result<Vec<ModeEnergy>> {
    shapes
        .iter()
        .map(|(re, im)| mode_energy(structure, re, im))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::model::layout::dof_names;
    use crate::vehicle::params::parameters::ParameterSet;

    #[test]
    fn kinds_group_indexed_bodies() {
        assert_eq!(body_kind("carbody"), "carbody");
        assert_eq!(body_kind("wheelset3"), "wheelsets");
        assert_eq!(body_kind("hollow_shaft1"), "hollow_shafts");
        assert_eq!(body_kind("rotary_arm2_left"), "rotary_arms");
        assert_eq!(body_kind("traction_rod2"), "traction_rods");
    }

    #[test]
    fn rigid_lateral_shift_moves_every_body_laterally_by_its_mass() {
        let structure = VehicleStructure::new(ParameterSet::default_vehicle()).unwrap();
        // Every free body's y, no relative motion: the kinetic energy of the total mass.
        let q: Vec<f64> = dof_names()
            .iter()
            .map(|n| if n.ends_with(".y") { 1.0 } else { 0.0 })
            .collect();
        let mut energy = 0.0;
        for i in 0..N_DOF {
            for j in 0..N_DOF {
                energy += q[i] * structure.mass.get(i, j) * q[j];
            }
        }
        let total = structure.total_mass();
        assert!(
            (energy - total).abs() <= 1e-12 * total,
            "{energy} vs {total}"
        );
        // Shares are the bodies' mass fractions, all lateral; the imaginary part adds nothing
        // when it is the same shape.
        let zero = vec![0.0; N_DOF];
        for im in [&zero, &q] {
            let e = mode_energy(&structure, &q, im).unwrap();
            assert!((e.bodies.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            for (b, body) in structure.bodies.iter().enumerate() {
                assert!(
                    (e.bodies[b] - body.mass / total).abs() < 1e-12,
                    "{}",
                    body.name
                );
                assert!((e.motions[b][1] - 1.0).abs() < 1e-12, "{}", body.name);
            }
        }
        assert!(mode_energy(&structure, &q, &q[..10]).is_err());
        let at_rest = mode_energy(&structure, &zero, &zero).unwrap();
        assert!(at_rest.bodies.iter().all(|&s| s == 0.0));
    }
}
