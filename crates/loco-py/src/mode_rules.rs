//! Bindings of `loco_core::vehicle::analysis::mode_rules`: the carbody and bogie mode rules and the pick
//! among a linearised vehicle's modes (`loco.Eigen.carbody_mode`, `bogie_mode`).

use crate::errors::to_py_err;
use loco_core::error::LocoError;
use loco_core::vehicle::analysis::mode_rules::{mode_rule, RatedMode, MODE_RULES};
use loco_core::vehicle::analysis::modes::{ModeEnergy, MOTIONS};
use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3};
use pyo3::prelude::*;

/// A rule's bounds: name, band (Hz), carbody share (least, largest), least wheelset, frame and
/// lateral-plane shares.
type RuleTuple = (&'static str, (f64, f64), (f64, f64), f64, f64, f64);

/// Every mode rule of the core with its bounds.
#[pyfunction]
fn mode_rules() -> Vec<RuleTuple> {
    MODE_RULES
        .iter()
        .map(|r| {
            (
                r.name,
                r.band,
                r.carbody_share,
                r.min_wheelset_share,
                r.min_frame_share,
                r.min_lateral_share,
            )
        })
        .collect()
}

/// The index of the mode the rule `rule` picks among modes of the given frequencies (Hz),
/// damping ratios (–), body energy shares (n_modes × n_bodies) and motion shares
/// (n_modes × n_bodies × 6) of bodies of the kinds `kinds`; None when it admits none.
#[pyfunction]
fn select_mode(
    rule: &str,
    kinds: Vec<String>,
    frequencies: PyReadonlyArray1<'_, f64>,
    damping_ratios: PyReadonlyArray1<'_, f64>,
    shares: PyReadonlyArray2<'_, f64>,
    motions: PyReadonlyArray3<'_, f64>,
) -> PyResult<Option<usize>> {
    let rule = mode_rule(rule).map_err(to_py_err)?;
    let (f, z) = (frequencies.as_array(), damping_ratios.as_array());
    let (s, m) = (shares.as_array(), motions.as_array());
    let n = f.len();
    let b = kinds.len();
    if z.len() != n || s.dim() != (n, b) || m.dim() != (n, b, MOTIONS.len()) {
        return Err(to_py_err(LocoError::input(
            "modes",
            format!(
                "{n} frequencies, {} damping ratios, shares {:?} and motions {:?} do not agree \
                 with {b} bodies",
                z.len(),
                s.dim(),
                m.dim()
            ),
        )));
    }
    let energies: Vec<ModeEnergy> = (0..n)
        .map(|i| ModeEnergy {
            bodies: s.row(i).to_vec(),
            motions: (0..b)
                .map(|j| std::array::from_fn(|k| m[[i, j, k]]))
                .collect(),
        })
        .collect();
    let modes: Vec<RatedMode<'_>> = energies
        .iter()
        .enumerate()
        .map(|(i, energy)| RatedMode {
            frequency: f[i],
            damping_ratio: z[i],
            energy,
        })
        .collect();
    let kinds: Vec<&str> = kinds.iter().map(String::as_str).collect();
    Ok(rule.pick(&modes, &kinds))
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(mode_rules, m)?)?;
    m.add_function(wrap_pyfunction!(select_mode, m)?)?;
    Ok(())
}
