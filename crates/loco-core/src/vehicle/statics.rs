//! Static equilibrium of the vehicle on the track under gravity, the state every run starts from.
//!
//! Newton's method on `Q(q, q̇ = 0) = 0` with a finite-difference Jacobian and a backtracking line
//! search. Nothing rolls in the static state, so creep forces are replaced by a tangential contact
//! stiffness that holds each wheel where it stands (patches do not slide), which also fixes the
//! otherwise free longitudinal position of the vehicle. The equilibrium is that on perfect track
//! (runs start before the irregularities' run-in). Dampers carry no static force: their
//! elongation in equilibrium becomes their reference.

use super::layout::{body_wheelset, wheelset, N_DOF, N_WHEELSETS, Z};
use super::linalg::Lu;
use super::simulation::VehicleSystem;
use crate::error::{LocoError, Result};

/// Tangential contact stiffness used in the static search, N/m: of the order of Mindlin's
/// tangential stiffness of a loaded wheel-rail patch (8·G·a/(2−ν) ≈ 1e8–1e9 N/m for a ≈ 6 mm).
pub const STATIC_TANGENTIAL_STIFFNESS: f64 = 1e8;

/// Initial guess of a wheel's static penetration into the rail, m (Hertz, ≈ 100 kN per wheel).
const PENETRATION_GUESS: f64 = 1e-4;

fn residual(system: &mut VehicleSystem, q: &[f64], y: &mut [f64], out: &mut [f64]) -> f64 {
    y[..N_DOF].copy_from_slice(q);
    system.generalized_force(0.0, y, out);
    out.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// Finds the static equilibrium and returns the initial state vector of a run (coordinates at
/// equilibrium, velocities zero, damper states zero); sets the dampers' static elongations.
pub fn static_equilibrium(system: &mut VehicleSystem) -> Result<Vec<f64>> {
    let n = system.len_states();
    let mut y = vec![0.0; n];
    let mut q = vec![0.0; N_DOF];
    for w in 0..N_WHEELSETS {
        q[wheelset(w) + Z] = -PENETRATION_GUESS;
    }
    system.static_stiffness = STATIC_TANGENTIAL_STIFFNESS;
    let weight = system.structure.total_mass() * system.structure.gravity;
    let mut r = vec![0.0; N_DOF];
    let mut r_trial = vec![0.0; N_DOF];
    let mut norm = residual(system, &q, &mut y, &mut r);

    let mut converged = false;
    for _iteration in 0..50 {
        if norm < 1e-8 * weight {
            converged = true;
            break;
        }
        let mut jac = vec![0.0; N_DOF * N_DOF];
        let mut q_pert = q.clone();
        for j in 0..N_DOF {
            let h = 1e-7;
            q_pert[j] = q[j] + h;
            residual(system, &q_pert, &mut y, &mut r_trial);
            q_pert[j] = q[j];
            for i in 0..N_DOF {
                jac[i * N_DOF + j] = (r_trial[i] - r[i]) / h;
            }
        }
        let lu = Lu::new(jac, N_DOF, "static equilibrium Jacobian")?;
        let step = lu.solve(&r);
        let mut alpha = 1.0;
        loop {
            let trial: Vec<f64> = q.iter().zip(&step).map(|(a, d)| a - alpha * d).collect();
            let trial_norm = residual(system, &trial, &mut y, &mut r_trial);
            if trial_norm < norm || alpha < 1e-4 {
                q = trial;
                norm = trial_norm;
                std::mem::swap(&mut r, &mut r_trial);
                break;
            }
            alpha *= 0.5;
        }
    }
    system.static_stiffness = 0.0;
    if !converged {
        return Err(LocoError::Diverged {
            time: 0.0,
            location: "static equilibrium".into(),
            reason: format!(
                "Newton search did not converge (residual {norm:.3e} N against weight {weight:.3e} N)"
            ),
        });
    }
    if let Some(e) = system.error.take() {
        return Err(e);
    }
    y.fill(0.0);
    y[..N_DOF].copy_from_slice(&q);
    // Dampers: the equilibrium elongation is their rest length.
    let qd = vec![0.0; N_DOF];
    system
        .structure
        .body_states(&q, &qd, &mut system.body_states);
    for damper in &mut system.dampers {
        damper.static_elongation = 0.0;
        let (x, _) = damper.stroke(&system.body_states);
        damper.static_elongation = x;
    }
    debug_assert!(body_wheelset(0) < system.body_states.position.len());
    Ok(y)
}
