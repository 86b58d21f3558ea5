//! Linearisation of the locomotive about its static equilibrium at a running speed, for the
//! eigenvalue analysis: `ẏ ≈ A (y − y₀)`; the least damped mode and the linear critical speed.
//!
//! The state matrix is formed by central finite differences of the full nonlinear right-hand side
//! (contact table, Hertz, FASTSIM, dampers' internal states), so it is the Jacobian of exactly the
//! model that the time integration runs. [`least_damped`] and [`linear_critical_speed`] take its
//! eigenvalues from nalgebra's real Schur decomposition ([`eigenvalues`]; frequencies `|Im λ|/2π`,
//! damping ratios `−Re λ/|λ|`); `loco.eigen` in Python also wants the mode shapes and uses
//! numpy/LAPACK.

use super::integrator::OdeSystem;
use super::scenario::{PerfectTrackVehicle, Scenario};
use super::simulation::VehicleSystem;
use super::statics::{static_equilibrium, StaticsSettings};
use super::structure::IntoVehicle;
use crate::error::{check_positive, LocoError, Result};
use nalgebra::linalg::balancing::balance_parlett_reinsch;
use nalgebra::{Complex, DMatrix, Schur};

/// Relative perturbation of each state for the central differences (scaled by the state's size
/// with a floor: 1e-7 m, rad, m/s, rad/s), small against the 0.1 mm contact table grid.
const PERTURBATION: f64 = 1e-7;

/// The state matrix `A` (row-major n×n) at the static equilibrium and the equilibrium state.
pub fn linearise(system: &mut VehicleSystem) -> Result<(Vec<f64>, Vec<f64>)> {
    let y0 = static_equilibrium(system, &StaticsSettings::default())?.state;
    let n = system.dimension();
    let mut a = vec![0.0; n * n];
    let mut y = y0.clone();
    let mut plus = vec![0.0; n];
    let mut minus = vec![0.0; n];
    for j in 0..n {
        let h = PERTURBATION * (1.0 + y0[j].abs());
        y[j] = y0[j] + h;
        system.derivatives(0.0, &y, &mut plus);
        y[j] = y0[j] - h;
        system.derivatives(0.0, &y, &mut minus);
        y[j] = y0[j];
        for i in 0..n {
            a[i * n + j] = (plus[i] - minus[i]) / (2.0 * h);
        }
    }
    if let Some(e) = system.error.take() {
        return Err(e);
    }
    Ok((a, y0))
}

/// Most Francis QR sweeps, in total over all eigenvalues, before the Schur decomposition gives up:
/// two to three per eigenvalue is typical (Golub and Van Loan, Matrix Computations, §7.5), so this
/// is a wide margin for the vehicle's ~200 states.
const MAX_QR_SWEEPS: usize = 100_000;

/// Eigenvalues `λ` (1/s for a state matrix) of the row-major n×n matrix `a`, in no particular
/// order, complex ones in conjugate pairs: nalgebra's Parlett-Reinsch balancing (the vehicle's
/// state matrix mixes entries of order 1 with contact stiffness over mass, ~1e8 1/s²), Hessenberg
/// reduction and implicit double-shift QR. Fails on a wrong size, a non-finite entry or a QR
/// that does not converge.
pub fn eigenvalues(a: &[f64], n: usize) -> Result<Vec<Complex<f64>>> {
    if a.len() != n * n {
        return Err(LocoError::input(
            "matrix",
            format!("expected {n}×{n} entries, got {}", a.len()),
        ));
    }
    if a.iter().any(|v| !v.is_finite()) {
        return Err(LocoError::input("matrix", "has a non-finite entry"));
    }
    let mut matrix = DMatrix::from_row_slice(n, n, a);
    // A diagonal similarity: the eigenvalues are unchanged, their accuracy is not.
    balance_parlett_reinsch(&mut matrix);
    let schur = Schur::try_new(matrix, f64::EPSILON, MAX_QR_SWEEPS).ok_or_else(|| {
        LocoError::input(
            "matrix",
            format!("QR iteration did not converge in {MAX_QR_SWEEPS} sweeps"),
        )
    })?;
    Ok(schur.complex_eigenvalues().iter().copied().collect())
}

/// The least damped oscillatory mode of a state matrix in a frequency band.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeastDamped {
    /// Frequency `|Im λ|/2π`, Hz.
    pub frequency: f64,
    /// Damping ratio `−Re λ/|λ|` (–); negative: the mode grows.
    pub damping_ratio: f64,
}

/// The least damped oscillatory mode of the row-major n×n state matrix `a` with a frequency in
/// `band` (Hz), as `loco.eigen(...).least_damped()` picks it; `None` when the band has no mode.
pub fn least_damped(a: &[f64], n: usize, band: (f64, f64)) -> Result<Option<LeastDamped>> {
    let modes = eigenvalues(a, n)?
        .into_iter()
        // One of each conjugate pair; real (overdamped) roots are not modes of oscillation.
        .filter(|e| e.im > 1e-6)
        .map(|e| LeastDamped {
            frequency: e.im / (2.0 * std::f64::consts::PI),
            damping_ratio: -e.re / e.re.hypot(e.im),
        })
        .filter(|m| (band.0..=band.1).contains(&m.frequency));
    Ok(modes.min_by(|a, b| a.damping_ratio.total_cmp(&b.damping_ratio)))
}

/// Search settings of the linear critical speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearSearch {
    /// Bracket of the bisection, m/s.
    pub low: f64,
    pub high: f64,
    /// Width of the final bracket, m/s.
    pub tolerance: f64,
    /// Frequency band of the modes considered, Hz (hunting and body modes, not drift).
    pub band: (f64, f64),
}

impl Default for LinearSearch {
    /// The defaults of `loco.critical_speed`: 20–110 m/s, 0.5 m/s, 0.3–20 Hz.
    fn default() -> Self {
        Self {
            low: 20.0,
            high: 110.0,
            tolerance: 0.5,
            band: (0.3, 20.0),
        }
    }
}

/// Linear critical speed (m/s): where the least damped mode in the band loses its damping, by
/// bisection of the linearisation about equilibrium on perfect track. `+∞` when the vehicle is
/// stable at `high`, `low` when it is already unstable there.
pub fn linear_critical_speed(
    vehicle: impl IntoVehicle,
    scenario: &Scenario,
    search: &LinearSearch,
) -> Result<f64> {
    scenario.validate()?;
    let low = check_positive("low", search.low)?;
    let high = check_positive("high", search.high)?;
    let tolerance = check_positive("tolerance", search.tolerance)?;
    if high <= low {
        return Err(LocoError::param(
            "high",
            format!("must exceed low ({low} m/s), got {high} m/s"),
        ));
    }
    let vehicle = PerfectTrackVehicle::new(vehicle, scenario)?;
    let zeta = |speed: f64| -> Result<f64> {
        let mut system = vehicle.system(speed)?;
        let (a, _) = linearise(&mut system)?;
        let mode = least_damped(&a, system.len_states(), search.band)?;
        mode.map(|m| m.damping_ratio)
            .ok_or_else(|| LocoError::param("band", "no mode in the frequency band"))
    };
    let (mut low, mut high) = (low, high);
    if zeta(high)? > 0.0 {
        return Ok(f64::INFINITY);
    }
    if zeta(low)? <= 0.0 {
        return Ok(low);
    }
    while high - low > tolerance {
        let mid = 0.5 * (low + high);
        if zeta(mid)? > 0.0 {
            low = mid;
        } else {
            high = mid;
        }
    }
    Ok(0.5 * (low + high))
}

#[cfg(test)]
#[path = "linearise_tests.rs"]
mod tests;
