//! Static equilibrium of the vehicle on the track under gravity, the state every run starts from.
//!
//! Newton's method on `Q(q, q̇ = 0) = 0` with a finite-difference Jacobian and a backtracking line
//! search. Nothing rolls in the static state, so creep forces are replaced by a tangential contact
//! stiffness that holds each wheel where it stands (patches do not slide, [`ContactMode::Held`]),
//! which also fixes the otherwise free longitudinal position of the vehicle. The equilibrium is
//! that on perfect track (runs start before the irregularities' run-in). Dampers carry no static
//! force: their elongation in equilibrium becomes their reference. A search that does not
//! converge, whose Jacobian is singular or whose equilibrium lies beyond the bounds a run may
//! reach is a [`LocoError::Equilibrium`] with its iterations, residual and the coordinate
//! concerned; out-of-range parameters of the vehicle are named as suspects
//! ([`crate::vehicle::params::suspects`]).
//!
//! The equilibrium keeps its Jacobian: with the mass matrix it gives the vehicle's stiffest mode
//! and the RK4 step a run may take ([`crate::vehicle::analysis::stiffest_mode`], computed only by the callers that
//! step in time).

use crate::error::{check_positive, LocoError, Result};
use crate::vehicle::model::layout::{dof_names, wheelset, N_DOF, N_WHEELSETS, Z};
use crate::vehicle::params::suspects::with_suspects;
use crate::vehicle::rail_contact::wheel_rail::ContactMode;
use crate::vehicle::system::simulation::VehicleSystem;
use nalgebra::{DMatrix, DVector};

/// Settings of the static-equilibrium search. [`Default`] gives the values every run uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticsSettings {
    /// Converged when the norm of the residual generalized forces is below this fraction of the
    /// vehicle's weight (–). Default 1e-8: about 8 mN on the 0.85 MN locomotive.
    pub tolerance: f64,
    /// Most Newton iterations before the search fails (a handful is typical). Default 50.
    pub max_iterations: usize,
    /// Smallest fraction of the Newton step the backtracking line search tries (halving from
    /// 1) before it accepts the step anyway (–). Default 1e-4.
    pub line_search_floor: f64,
    /// Forward-difference step of the Jacobian, m or rad. Default 1e-7: small against the
    /// 0.1 mm contact table grid, large against round-off in forces of ~1e5 N.
    pub difference_step: f64,
    /// Tangential contact stiffness holding each patch, N/m. Default 1e8: of the order of
    /// Mindlin's tangential stiffness of a loaded wheel-rail patch (8·G·a/(2−ν) ≈ 1e8–1e9 N/m for
    /// a ≈ 6 mm).
    pub tangential_stiffness: f64,
}

impl Default for StaticsSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-8,
            max_iterations: 50,
            line_search_floor: 1e-4,
            difference_step: 1e-7,
            tangential_stiffness: 1e8,
        }
    }
}

impl StaticsSettings {
    /// Checks every setting; the error names the field.
    pub fn validate(&self) -> Result<()> {
        check_positive("statics.tolerance", self.tolerance)?;
        check_positive("statics.line_search_floor", self.line_search_floor)?;
        check_positive("statics.difference_step", self.difference_step)?;
        check_positive("statics.tangential_stiffness", self.tangential_stiffness)?;
        if self.max_iterations == 0 || self.line_search_floor >= 1.0 {
            return Err(LocoError::param(
                "statics",
                "max_iterations must be >= 1 and line_search_floor < 1",
            ));
        }
        Ok(())
    }

    /// The contact mode of the search.
    pub fn contact_mode(&self) -> ContactMode {
        ContactMode::Held {
            tangential_stiffness: self.tangential_stiffness,
        }
    }
}

/// A static equilibrium and how it was found.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Initial state vector of a run: coordinates at equilibrium, velocities and damper states 0.
    pub state: Vec<f64>,
    /// Newton iterations taken.
    pub iterations: usize,
    /// Norm of the residual generalized forces at the equilibrium, N (and N·m).
    pub residual: f64,
    /// The Jacobian ∂Q/∂q (N/m, N·m/rad; column j is the derivative by coordinate j) of the last
    /// Newton iteration, with the patches held and no damping: the stiffness the step check
    /// ([`crate::vehicle::analysis::stiffest_mode`]) reads.
    pub jacobian: DMatrix<f64>,
}

/// Initial guess of a wheel's static penetration into the rail, m (Hertz, ≈ 100 kN per wheel).
const PENETRATION_GUESS: f64 = 1e-4;

fn residual(system: &mut VehicleSystem, q: &[f64], y: &mut [f64], out: &mut [f64]) -> f64 {
    y[..N_DOF].copy_from_slice(q);
    system.generalized_force(0.0, y, out);
    out.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// Solves `J d = r` by LU with partial pivoting; a pivot below 1e-14 of the largest entry means a
/// coordinate the contact and suspension leave unrestrained, or restrained 1e14 times less than
/// the stiffest one (the reason names it).
fn newton_step(jacobian: &DMatrix<f64>, r: &[f64]) -> std::result::Result<Vec<f64>, String> {
    let scale = jacobian.amax();
    let lu = jacobian.clone().lu();
    let pivots = lu.u().diagonal();
    // The pivot's row of U is a combination of the rows of J in the permuted order; its column
    // is the coordinate (columns are not permuted).
    if let Some(k) = pivots
        .iter()
        .position(|p| p.is_nan() || p.abs() <= 1e-14 * scale)
    {
        return Err(format!(
            "the Jacobian is singular at coordinate `{}`: it is unrestrained, or its stiffness is \
             below 1e-14 of the largest entry ({scale:.3e} N/m or N·m/rad)",
            dof_names()[k]
        ));
    }
    let step = lu
        .solve(&DVector::from_column_slice(r))
        .ok_or_else(|| "the Jacobian is singular".to_string())?;
    Ok(step.as_slice().to_vec())
}

/// Finds the static equilibrium with `settings`; sets the dampers' static elongations and the
/// system's Newton iteration count ([`crate::vehicle::system::run_statistics::RunStatistics`]). An error names
/// the vehicle's out-of-range parameters as suspects.
pub fn static_equilibrium(
    system: &mut VehicleSystem,
    settings: &StaticsSettings,
) -> Result<Equilibrium> {
    let found = search(system, settings);
    system.contact_mode = ContactMode::Rolling;
    found.map_err(|e| with_suspects(e, &system.structure.parameters))
}

fn jacobian(system: &mut VehicleSystem, q: &[f64], r: &[f64], h: f64) -> DMatrix<f64> {
    let mut y = vec![0.0; system.len_states()];
    let mut r_trial = vec![0.0; N_DOF];
    let mut jac = DMatrix::zeros(N_DOF, N_DOF);
    let mut q_pert = q.to_vec();
    for j in 0..N_DOF {
        q_pert[j] = q[j] + h;
        residual(system, &q_pert, &mut y, &mut r_trial);
        q_pert[j] = q[j];
        for i in 0..N_DOF {
            jac[(i, j)] = (r_trial[i] - r[i]) / h;
        }
    }
    jac
}

fn search(system: &mut VehicleSystem, settings: &StaticsSettings) -> Result<Equilibrium> {
    settings.validate()?;
    let n = system.len_states();
    let mut y = vec![0.0; n];
    let mut q = vec![0.0; N_DOF];
    for w in 0..N_WHEELSETS {
        q[wheelset(w) + Z] = -PENETRATION_GUESS;
    }
    system.contact_mode = settings.contact_mode();
    let weight = system.structure.total_mass() * system.structure.gravity;
    let mut r = vec![0.0; N_DOF];
    let mut r_trial = vec![0.0; N_DOF];
    let mut norm = residual(system, &q, &mut y, &mut r);
    let h = settings.difference_step;

    let mut iterations = 0;
    let mut last_jacobian = None;
    let mut converged = norm < settings.tolerance * weight;
    while !converged && iterations < settings.max_iterations {
        let jac = jacobian(system, &q, &r, h);
        let step = newton_step(&jac, &r).map_err(|reason| LocoError::Equilibrium {
            iterations,
            residual: norm,
            reason,
        })?;
        last_jacobian = Some(jac);
        let mut alpha = 1.0;
        loop {
            let trial: Vec<f64> = q.iter().zip(&step).map(|(a, d)| a - alpha * d).collect();
            let trial_norm = residual(system, &trial, &mut y, &mut r_trial);
            if trial_norm < norm || alpha < settings.line_search_floor {
                q = trial;
                norm = trial_norm;
                std::mem::swap(&mut r, &mut r_trial);
                break;
            }
            alpha *= 0.5;
        }
        iterations += 1;
        converged = norm < settings.tolerance * weight;
    }
    system.statistics.newton_iterations += iterations as u64;
    if !converged {
        return Err(LocoError::Equilibrium {
            iterations,
            residual: norm,
            reason: format!(
                "Newton search did not converge (tolerance {:.1e} of the weight {weight:.3e} N)",
                settings.tolerance
            ),
        });
    }
    if let Some(e) = system.error.take() {
        return Err(e);
    }
    y.fill(0.0);
    y[..N_DOF].copy_from_slice(&q);
    // An equilibrium a run would call divergence at its first step: the suspension does not
    // carry the weight (a body sinks or tilts beyond the bounds).
    if let Err(
        LocoError::Diverged {
            location, reason, ..
        }
        | LocoError::Derailed {
            location, reason, ..
        },
    ) = system.check_state(0.0, &y)
    {
        return Err(LocoError::Equilibrium {
            iterations,
            residual: norm,
            reason: format!(
                "the equilibrium lies beyond the bounds of a run at `{location}` ({reason}): the \
                 suspension does not hold the body there"
            ),
        });
    }
    let jacobian = last_jacobian.unwrap_or_else(|| jacobian(system, &q, &r, h));
    // Dampers: the equilibrium elongation is their rest length.
    let qd = vec![0.0; N_DOF];
    system
        .structure
        .body_states(&q, &qd, &mut system.body_states);
    system.states_cache.invalidate();
    for damper in &mut system.dampers {
        damper.static_elongation = 0.0;
        let (x, _) = damper.stroke(&system.body_states);
        damper.static_elongation = x;
    }
    Ok(Equilibrium {
        state: y,
        iterations,
        residual: norm,
        jacobian,
    })
}
