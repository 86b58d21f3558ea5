//! Linearisation of the locomotive about its static equilibrium at a running speed, for the
//! eigenvalue analysis: `ẏ ≈ A (y − y₀)`; the least damped mode and the linear critical speed.
//!
//! The state matrix is formed by central finite differences of the full nonlinear right-hand side
//! (contact table, Hertz, FASTSIM, dampers' internal states), so it is the Jacobian of exactly the
//! model that the time integration runs. [`least_damped`] and [`linear_critical_speed`] take its
//! eigenvalues from nalgebra's real Schur decomposition ([`eigenvalues`]; frequencies `|Im λ|/2π`,
//! damping ratios `−Re λ/|λ|`); `loco.eigen` in Python also wants the mode shapes and uses
//! numpy/LAPACK.
//!
//! The difference step ([`LinearisationSettings`]). The contact table stores the wheel–rail
//! contact on a uniform grid of lateral displacements (0.1 mm) and interpolates linearly between
//! grid points, so below one cell it is piecewise linear: a central difference much smaller than
//! a cell (the default 1e-7) returns the slope of the one cell the equilibrium falls in, which
//! jumps from cell to cell and differs from the slope of the smooth contact geometry by
//! O(cell × curvature). A central difference spanning exactly one cell (±half a cell, 5e-5) is
//! the derivative of the table smoothed by a one-cell box, i.e. of the quadratic B-spline through
//! the table points: continuous in the equilibrium position and second-order accurate for the
//! smooth geometry the table samples. That is the usual rule for differencing a function known to
//! a finite resolution: the increment must exceed the scale of its small-scale structure (Kelley,
//! *Implicit Filtering*, SIAM 2011; Nocedal and Wright, *Numerical Optimization*, 2nd ed., §8.1).
//! A larger step is a secant, an amplitude-dependent equivalent linearisation, as equivalent
//! conicity is defined at a stated lateral amplitude (EN 15302) and a describing function at a
//! stated input amplitude (Gelb and Vander Velde, *Multiple-Input Describing Functions*, 1968).
//! Measured on the S_norm YD1 alignment case at 20 m (README, "Frequency response"): −11.4 % /
//! −5.4° (carbody) against the time domain with 1e-7, −3.5 % / +0.9° with 5e-5. The default is
//! still 1e-7: the full matrix with half a cell ([`HALF_TABLE_CELL`]) passes every alignment case
//! but takes S_low cross level at 150 m out of the 5 % band (+5.7 %, README), and it raises the
//! S_high linear critical speeds by 3.7–4.6 %.

use super::integrator::OdeSystem;
use super::scenario::{PerfectTrackVehicle, Scenario};
use super::simulation::VehicleSystem;
use super::statics::{static_equilibrium, StaticsSettings};
use super::structure::IntoVehicle;
use crate::error::{check_positive, LocoError, Result};
use nalgebra::linalg::balancing::balance_parlett_reinsch;
use nalgebra::{Complex, DMatrix, Schur};

/// Half the default contact table's grid step, m (5e-5): the central-difference step that spans
/// one table cell (module documentation).
pub const HALF_TABLE_CELL: f64 = 0.5 * 1e-4;

/// How the model is linearised: the central-difference step of the state and input matrices
/// (module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearisationSettings {
    /// Half-width of the central differences, in each state's unit (m, rad, m/s, rad/s) and for
    /// the rail inputs (m, m/m), scaled by `1 + |y₀|` for a state of equilibrium value `y₀`.
    /// Default 1e-7 (the step the README's linear results were computed with);
    /// [`HALF_TABLE_CELL`] is the one-cell secant.
    pub step: f64,
}

impl Default for LinearisationSettings {
    fn default() -> Self {
        Self { step: 1e-7 }
    }
}

impl LinearisationSettings {
    /// The settings with `step` checked (finite, > 0).
    pub fn checked(&self) -> Result<Self> {
        Ok(Self {
            step: check_positive("step", self.step)?,
        })
    }
}

/// The state matrix `A` (row-major n×n) at the static equilibrium and the equilibrium state,
/// with the default [`LinearisationSettings`].
pub fn linearise(system: &mut VehicleSystem) -> Result<(Vec<f64>, Vec<f64>)> {
    linearise_with(system, &LinearisationSettings::default())
}

/// [`linearise`] with the given settings.
pub fn linearise_with(
    system: &mut VehicleSystem,
    settings: &LinearisationSettings,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let step = settings.checked()?.step;
    let y0 = static_equilibrium(system, &StaticsSettings::default())?.state;
    let n = system.dimension();
    let mut a = vec![0.0; n * n];
    let mut y = y0.clone();
    let mut plus = vec![0.0; n];
    let mut minus = vec![0.0; n];
    for j in 0..n {
        let h = step * (1.0 + y0[j].abs());
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
    /// How the model is linearised at each speed.
    pub linearisation: LinearisationSettings,
}

impl Default for LinearSearch {
    /// The defaults of `loco.critical_speed`: 20–110 m/s, 0.5 m/s, 0.3–20 Hz.
    fn default() -> Self {
        Self {
            low: 20.0,
            high: 110.0,
            tolerance: 0.5,
            band: (0.3, 20.0),
            linearisation: LinearisationSettings::default(),
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
        let (a, _) = linearise_with(&mut system, &search.linearisation)?;
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
