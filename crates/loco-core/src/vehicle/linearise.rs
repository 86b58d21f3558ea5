//! Linearisation of the locomotive about its static equilibrium at a running speed, for the
//! eigenvalue analysis: `ẏ ≈ A (y − y₀)`.
//!
//! The state matrix is formed by central finite differences of the full nonlinear right-hand side
//! (contact table, Hertz, FASTSIM, dampers' internal states), so it is the Jacobian of exactly the
//! model that the time integration runs. Eigenvalues are computed by the caller (numpy/LAPACK in
//! Python): frequencies `|Im λ|/2π`, damping ratios `−Re λ/|λ|`.

use super::integrator::OdeSystem;
use super::simulation::VehicleSystem;
use super::statics::static_equilibrium;
use crate::error::Result;

/// Relative perturbation of each state for the central differences (scaled by the state's size
/// with a floor: 1e-7 m, rad, m/s, rad/s), small against the 0.1 mm contact table grid.
const PERTURBATION: f64 = 1e-7;

/// The state matrix `A` (row-major n×n) at the static equilibrium and the equilibrium state.
pub fn linearise(system: &mut VehicleSystem) -> Result<(Vec<f64>, Vec<f64>)> {
    let y0 = static_equilibrium(system)?;
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
