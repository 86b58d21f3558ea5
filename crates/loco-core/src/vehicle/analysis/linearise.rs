//! Linearisation of the locomotive about its static equilibrium at a running speed, for the
//! eigenvalue analysis: `ẏ ≈ A (y − y₀)`; the least damped mode and the linear critical speed.
//!
//! The state matrix is formed by central finite differences of the full nonlinear right-hand side
//! (contact table, Hertz, FASTSIM, dampers' internal states), so it is the Jacobian of exactly the
//! model that the time integration runs. [`least_damped`] and the linear critical speed
//! ([`crate::vehicle::analysis::linear_critical_speed`]) take its eigenvalues from nalgebra's real Schur
//! decomposition ([`eigenvalues`]; frequencies `|Im λ|/2π`, damping ratios `−Re λ/|λ|`);
//! `loco.eigen` in Python also wants the mode shapes and uses numpy/LAPACK.
//!
//! The difference steps ([`LinearisationSettings`]). A central difference is the derivative the
//! time domain sees only if its step lies on a plateau of the right-hand side along that
//! coordinate: larger than its small-scale structure, smaller than the scale of its smooth
//! nonlinearity (Kelley, *Implicit Filtering*, SIAM 2011; Nocedal and Wright, *Numerical
//! Optimization*, 2nd ed., §8.1). The coordinates fall into two groups:
//!
//! - Through the Hertz approach (81 µm at the static load): a wheelset's vertical position and
//!   roll, the rails' heights. `N ∝ δ^1.5` is smooth; the columns agree within 1e-4 for steps up
//!   to 1e-5 and move by 1.3–1.7 % at 5e-5 (9–11 % at 2e-4), a secant over 60 % of δ, while the
//!   time domain's approach varies by micrometres. These, and every other displacement (linear
//!   suspension), take `step` = 1e-7: the tangent. A roll step of 5e-5 alone moves the S_low cross
//!   level response at 150 m by +15 %.
//! - Across the contact and through the creepages: a wheelset's lateral position (read from the
//!   contact table on 0.1 mm cells) and yaw (lateral creepage, contact lead), the rails' lateral
//!   positions, and every velocity (creepages `v/V`). The table is piecewise linear and FASTSIM's
//!   discrete stick/slip elements make the creep forces piecewise smooth at the rolling
//!   equilibrium (spin creepage from the contact angle): on S_norm the longitudinal, spin-rate
//!   and yaw-rate columns take one value for steps up to 1e-6 and another, 2.5–2.7 % away, for
//!   5e-5 … 1e-3 (which agree within 0.3 %). The time domain's lateral amplitudes (0.06–0.9 mm)
//!   span several cells and its creepages (about 1e-4) that structure, so these would take
//!   `contact_step` = [`HALF_TABLE_CELL`] (5e-5: one table cell, a creepage of 1e-6 at 200 km/h).
//!
//! Measured against the time domain (0.2 mm sinusoids, `tests/verification/frequency_response.rs`,
//! docs/model/frequency_response.md): one step of 1e-7 for everything puts S_norm + YD1 alignment at 20 m at
//! −11.4 % / −5.4° (carbody); one step of 5e-5 for everything passes it but takes S_low cross
//! level at 150 m to +5.7 % (the Hertz secant of the roll columns: a roll step of 5e-5 alone gives
//! +15 %). The two groups ([`LinearisationSettings::two_groups`]) pass both (+1.2 % / +2.5°,
//! −4.5 % / −0.1°; S_low cross level 150 m +0.0 %) and every alignment and cross-level case of
//! YD1/YD2 but one: S_high + YD2 cross level at 40 m, carbody −6.3 % / +2.9° (a small response,
//! 1.6e-3 m/s²; +1.2 % with 1e-7), and S_high cross level at 150 m moves from 0.0 to −1.6 %.
//! Not understood yet, and a lead: with y₀ on a grid point a central difference of the piecewise
//! linear table gives the same slope for any step up to half a cell, yet the lateral column's step
//! matters (S_norm + YD1 20 m: −11.4 → −7.3 % from that column alone); half a cell is exactly
//! where a contact slot present at only one neighbouring grid point switches on (the lookup's
//! lone-slot rule), so a step of 5e-5 may be reading a second contact point, which is physics at
//! 0.9 mm of amplitude but an accident of the step. So the default stays one step of 1e-7 (the
//! documentation's linear results), and `two_groups` is the candidate.

use crate::error::{check_positive, LocoError, Result};
use crate::vehicle::model::layout::{wheelset, N_DOF, N_WHEELSETS, Y, YAW};
use crate::vehicle::system::simulation::VehicleSystem;
use crate::vehicle::system::statics::{static_equilibrium, StaticsSettings};
use crate::vehicle::time::integrator::OdeSystem;
use nalgebra::linalg::balancing::balance_parlett_reinsch;
use nalgebra::{Complex, DMatrix, Schur};

/// Half the default contact table's grid step, m (5e-5): a central difference of this half-width
/// spans one table cell; the default `contact_step`.
pub const HALF_TABLE_CELL: f64 = 0.5 * 1e-4;

/// Default `step` of the Hertz-side coordinates and the rest, m, rad or m/m.
pub const HERTZ_STEP: f64 = 1e-7;

/// How the model is linearised: the central-difference steps of the state and input matrices
/// (module documentation). Each is scaled by `1 + |y₀|` for a state of equilibrium value `y₀`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearisationSettings {
    /// Half-width of the differences of the wheelsets' vertical positions and rolls, every other
    /// displacement (m, rad), the dampers' internal states and the rails' heights and slopes
    /// (m, m/m). Default [`HERTZ_STEP`].
    pub step: f64,
    /// Half-width of the differences of the wheelsets' lateral positions and yaws (m, rad), the
    /// rails' lateral positions (m) and every velocity (m/s, rad/s). Default [`HERTZ_STEP`];
    /// [`HALF_TABLE_CELL`] in [`Self::two_groups`].
    pub contact_step: f64,
}

impl Default for LinearisationSettings {
    /// One step of [`HERTZ_STEP`] for every coordinate (module documentation: why not yet
    /// [`Self::two_groups`]).
    fn default() -> Self {
        Self::uniform(HERTZ_STEP)
    }
}

impl LinearisationSettings {
    /// The two groups of the module documentation: [`HERTZ_STEP`] on the Hertz side,
    /// [`HALF_TABLE_CELL`] across the contact and for the velocities.
    pub fn two_groups() -> Self {
        Self {
            step: HERTZ_STEP,
            contact_step: HALF_TABLE_CELL,
        }
    }

    /// One step for every state and input.
    pub fn uniform(step: f64) -> Self {
        Self {
            step,
            contact_step: step,
        }
    }

    /// The settings with both steps checked (finite, > 0).
    pub fn checked(&self) -> Result<Self> {
        Ok(Self {
            step: check_positive("step", self.step)?,
            contact_step: check_positive("contact_step", self.contact_step)?,
        })
    }

    /// Half-width of the difference of state `j` (layout: displacements, then velocities from
    /// `N_DOF`, then the dampers' states) about its equilibrium value `y0`.
    pub fn state_step(&self, j: usize, y0: f64) -> f64 {
        let across_contact = (wheelset(0)..wheelset(N_WHEELSETS)).contains(&j)
            && matches!((j - wheelset(0)) % 6, Y | YAW);
        let base = if across_contact || (N_DOF..2 * N_DOF).contains(&j) {
            self.contact_step
        } else {
            self.step
        };
        base * (1.0 + y0.abs())
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
    let settings = settings.checked()?;
    let y0 = static_equilibrium(system, &StaticsSettings::default())?.state;
    let n = system.dimension();
    let mut a = vec![0.0; n * n];
    let mut y = y0.clone();
    let mut plus = vec![0.0; n];
    let mut minus = vec![0.0; n];
    for j in 0..n {
        let h = settings.state_step(j, y0[j]);
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

/// Imaginary part (1/s) above which an eigenvalue is an oscillatory mode: one of each conjugate
/// pair; real (overdamped) roots are not modes of oscillation.
pub const OSCILLATORY_IMAG: f64 = 1e-6;

/// An oscillatory mode of a state matrix: its frequency and damping ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeastDamped {
    /// Frequency `|Im λ|/2π`, Hz.
    pub frequency: f64,
    /// Damping ratio `−Re λ/|λ|` (–); negative: the mode grows.
    pub damping_ratio: f64,
}

impl LeastDamped {
    /// The mode of the eigenvalue `re + i·im` (1/s), `None` when it is not oscillatory (`im`
    /// at most [`OSCILLATORY_IMAG`]: real, or the lower of a conjugate pair).
    pub fn of(re: f64, im: f64) -> Option<Self> {
        (im > OSCILLATORY_IMAG).then(|| Self {
            frequency: im / (2.0 * std::f64::consts::PI),
            damping_ratio: -re / re.hypot(im),
        })
    }
}

/// The rule of the least damped mode: the index in `modes` of the one with the lowest damping
/// ratio among those with a frequency in `band` (Hz; the first of equals), `None` when the band
/// has none. Python's `Eigen.least_damped` applies this same rule.
pub fn least_damped_index(modes: &[LeastDamped], band: (f64, f64)) -> Option<usize> {
    modes
        .iter()
        .enumerate()
        .filter(|(_, m)| (band.0..=band.1).contains(&m.frequency))
        .min_by(|a, b| a.1.damping_ratio.total_cmp(&b.1.damping_ratio))
        .map(|(i, _)| i)
}

/// The least damped oscillatory mode of the row-major n×n state matrix `a` with a frequency in
/// `band` (Hz), by [`least_damped_index`]; `None` when the band has no mode.
pub fn least_damped(a: &[f64], n: usize, band: (f64, f64)) -> Result<Option<LeastDamped>> {
    let modes: Vec<LeastDamped> = eigenvalues(a, n)?
        .into_iter()
        .filter_map(|e| LeastDamped::of(e.re, e.im))
        .collect();
    Ok(least_damped_index(&modes, band).map(|i| modes[i]))
}

#[cfg(test)]
mod tests;
