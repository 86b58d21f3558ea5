//! Test access to the EN 15302 benchmark files of the shared reference data (never shipped).
//!
//! The data live outside the repository (`shared/data/en15302`, see its README): found through the
//! environment variable `LOCO_SHARED_DATA` or in an ancestor directory of the crate holding
//! `shared/data`. Tests skip with a message when they are absent.

use std::path::PathBuf;

/// The benchmark cases E1…E9.
pub(crate) const BENCHMARK_CASES: &[usize] = &[1, 2, 3, 4, 5, 6, 7, 8, 9];

/// One row of `ben_E*.dat`, converted to SI.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ReferenceRow {
    /// Wheelset amplitude ŷ (m).
    pub amplitude: f64,
    /// Reference equivalent conicity (-).
    pub tan_gamma_e: f64,
    /// Lower limit: the tighter of the two lower tolerance limits of the file (-).
    pub lower: f64,
    /// Upper limit: the tighter of the two upper tolerance limits of the file (-).
    pub upper: f64,
}

/// A benchmark case: Δr(y) in SI and the reference results.
#[derive(Debug, Clone)]
pub(crate) struct BenchmarkCase {
    /// Lateral displacements (m).
    pub y: Vec<f64>,
    /// Rolling radius difference (m).
    pub dr: Vec<f64>,
    pub reference: Vec<ReferenceRow>,
}

/// `shared/data` if it can be found.
pub(crate) fn shared_data_dir() -> Option<PathBuf> {
    if let Some(dir) = std::env::var_os("LOCO_SHARED_DATA") {
        let dir = PathBuf::from(dir);
        return dir.is_dir().then_some(dir);
    }
    let start = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    start
        .ancestors()
        .map(|a| a.join("shared").join("data"))
        .find(|p| p.is_dir())
}

/// The first lateral grid point (mm) of each case's Δr file (step 0.1 mm), from the README.
fn grid_start_mm(case: usize) -> f64 {
    match case {
        4 | 8 => -7.1,
        6 => -6.9,
        _ => -6.8,
    }
}

fn numbers(text: &str) -> Vec<f64> {
    text.split_whitespace()
        .map(|t| t.parse::<f64>().expect("number in benchmark file"))
        .collect()
}

/// Case `case` (1…9), `None` when the shared data are absent; panics on malformed files (tests).
pub(crate) fn benchmark_case(case: usize) -> Option<Result<BenchmarkCase, String>> {
    let dir = shared_data_dir()?.join("en15302");
    let dr_text = std::fs::read_to_string(dir.join(format!("dr_E{case}.dat"))).ok()?;
    let ben_text = std::fs::read_to_string(dir.join(format!("ben_E{case}.dat"))).ok()?;
    let dr: Vec<f64> = numbers(&dr_text).iter().map(|v| v * 1e-3).collect();
    let start = grid_start_mm(case);
    let y = (0..dr.len())
        .map(|i| (start + 0.1 * i as f64) * 1e-3)
        .collect();
    let columns = numbers(&ben_text);
    if !columns.len().is_multiple_of(6) {
        return Some(Err(format!("ben_E{case}.dat: not 6 columns")));
    }
    let reference = columns
        .chunks(6)
        .map(|c| ReferenceRow {
            amplitude: c[0] * 1e-3,
            tan_gamma_e: c[1],
            upper: c[2].min(c[4]),
            lower: c[3].max(c[5]),
        })
        .collect();
    Some(Ok(BenchmarkCase { y, dr, reference }))
}
