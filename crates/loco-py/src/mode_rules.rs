//! Bindings of `loco_core::vehicle::analysis::mode_rules`: the carbody and bogie mode rules and the pick
//! among a linearised vehicle's modes (`loco.Eigen.carbody_mode`, `bogie_mode`), and the rule of
//! the least damped mode (`loco.eigen`, `Eigen.least_damped`).

use crate::errors::to_py_err;
use loco_core::error::LocoError;
use loco_core::vehicle::analysis::linearise::{least_damped_index, LeastDamped};
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

/// The oscillatory modes among eigenvalues of real parts `re` and imaginary parts `im` (1/s),
/// by the core's rule (one of each conjugate pair): their indices, frequencies (Hz) and damping
/// ratios (–).
#[pyfunction]
fn oscillatory_modes(
    re: PyReadonlyArray1<'_, f64>,
    im: PyReadonlyArray1<'_, f64>,
) -> PyResult<(Vec<usize>, Vec<f64>, Vec<f64>)> {
    let (re, im) = (re.as_array(), im.as_array());
    if re.len() != im.len() {
        return Err(to_py_err(LocoError::input(
            "eigenvalues",
            format!("{} real and {} imaginary parts", re.len(), im.len()),
        )));
    }
    let mut out = (Vec::new(), Vec::new(), Vec::new());
    for (i, (&r, &m)) in re.iter().zip(im.iter()).enumerate() {
        if let Some(mode) = LeastDamped::of(r, m) {
            out.0.push(i);
            out.1.push(mode.frequency);
            out.2.push(mode.damping_ratio);
        }
    }
    Ok(out)
}

/// The index of the least damped mode with a frequency in `band` (Hz) among modes of the given
/// frequencies (Hz) and damping ratios (–), by the core's rule; None when the band has none.
#[pyfunction]
fn least_damped_mode(
    frequencies: PyReadonlyArray1<'_, f64>,
    damping_ratios: PyReadonlyArray1<'_, f64>,
    band: (f64, f64),
) -> PyResult<Option<usize>> {
    let (f, z) = (frequencies.as_array(), damping_ratios.as_array());
    if f.len() != z.len() {
        return Err(to_py_err(LocoError::input(
            "modes",
            format!("{} frequencies and {} damping ratios", f.len(), z.len()),
        )));
    }
    let modes: Vec<LeastDamped> = f
        .iter()
        .zip(z.iter())
        .map(|(&frequency, &damping_ratio)| LeastDamped {
            frequency,
            damping_ratio,
        })
        .collect();
    Ok(least_damped_index(&modes, band))
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(mode_rules, m)?)?;
    m.add_function(wrap_pyfunction!(select_mode, m)?)?;
    m.add_function(wrap_pyfunction!(oscillatory_modes, m)?)?;
    m.add_function(wrap_pyfunction!(least_damped_mode, m)?)?;
    Ok(())
}
