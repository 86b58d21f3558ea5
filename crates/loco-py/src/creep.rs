//! Bindings of `loco_core::contact::{hertz, creepage, kalker, fastsim, fastrip}` (public API:
//! `loco.creep`). Scalars in, tuples of floats out; the creep models are solver objects built
//! once from their parameters; every call goes through `run_detached`.

use crate::errors::{run_detached, to_py_err};
use loco_core::contact::creepage::{Side, WheelContact, WheelsetMotion};
use loco_core::contact::fastrip::{Fastrip, FastripParams};
use loco_core::contact::fastsim::{check_contact_inputs, Fastsim, FastsimParams, TractionBound};
use loco_core::contact::hertz::HertzCoefficients;
use loco_core::contact::hertz::{hertz_contact as core_hertz, ContactRadii, ElasticMaterial};
use loco_core::contact::kalker::{
    kalker_coefficients as core_kalker, linear_creep_forces_checked, Creepages,
};
use loco_core::LocoError;
use pyo3::prelude::*;

/// Grid size from Python: an int ≥ 1, named in the error.
fn grid_size(name: &str, n: i64) -> Result<usize, LocoError> {
    if (1..=10_000).contains(&n) {
        Ok(n as usize)
    } else {
        Err(LocoError::param(
            name,
            format!("must be in 1..=10000, got {n}"),
        ))
    }
}

fn traction_bound(bound: &str) -> Result<TractionBound, LocoError> {
    match bound {
        "parabolic" => Ok(TractionBound::Parabolic),
        "elliptic" => Ok(TractionBound::Elliptic),
        other => Err(LocoError::param(
            "bound",
            format!("must be \"parabolic\" or \"elliptic\", got {other:?}"),
        )),
    }
}

/// Hertz contact: (a, b, peak_pressure, approach) in m, m, Pa, m.
#[pyfunction]
#[pyo3(signature = (normal_force, r_wheel_rolling, r_wheel_transverse, r_rail_transverse, youngs_modulus, poisson_ratio))]
fn hertz_contact(
    py: Python<'_>,
    normal_force: f64,
    r_wheel_rolling: f64,
    r_wheel_transverse: f64,
    r_rail_transverse: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
) -> PyResult<(f64, f64, f64, f64)> {
    run_detached(py, move || {
        let radii = ContactRadii {
            wheel_rolling: r_wheel_rolling,
            wheel_transverse: r_wheel_transverse,
            rail_transverse: r_rail_transverse,
        };
        let material = ElasticMaterial {
            youngs_modulus,
            poisson_ratio,
        };
        let c = core_hertz(normal_force, &radii, &material)?;
        Ok((
            c.semi_axis_long,
            c.semi_axis_lat,
            c.peak_pressure,
            c.approach,
        ))
    })
}

/// Normal stiffness K_H (N·m^-1.5) of N = K_H·δ^1.5 for the given radii and material.
#[pyfunction]
#[pyo3(signature = (r_wheel_rolling, r_wheel_transverse, r_rail_transverse, youngs_modulus, poisson_ratio))]
fn hertz_stiffness(
    py: Python<'_>,
    r_wheel_rolling: f64,
    r_wheel_transverse: f64,
    r_rail_transverse: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
) -> PyResult<f64> {
    run_detached(py, move || {
        let radii = ContactRadii {
            wheel_rolling: r_wheel_rolling,
            wheel_transverse: r_wheel_transverse,
            rail_transverse: r_rail_transverse,
        };
        let material = ElasticMaterial {
            youngs_modulus,
            poisson_ratio,
        };
        Ok(HertzCoefficients::new(&radii, &material)?.stiffness())
    })
}

/// Kalker's (C11, C22, C23, C33) for a/b and ν.
#[pyfunction]
fn kalker_coefficients(py: Python<'_>, a_over_b: f64, nu: f64) -> PyResult<(f64, f64, f64, f64)> {
    run_detached(py, move || {
        let c = core_kalker(a_over_b, nu)?;
        Ok((c.c11, c.c22, c.c23, c.c33))
    })
}

/// Linear-theory (Fx, Fy, Mz) in N, N, N·m.
#[pyfunction]
#[pyo3(signature = (a, b, creepage_long, creepage_lat, spin, nu, shear_modulus))]
#[allow(clippy::too_many_arguments)] // mirrors the Python signature one to one
fn linear_creep_forces(
    py: Python<'_>,
    a: f64,
    b: f64,
    creepage_long: f64,
    creepage_lat: f64,
    spin: f64,
    nu: f64,
    shear_modulus: f64,
) -> PyResult<(f64, f64, f64)> {
    run_detached(py, move || {
        let creep = Creepages {
            longitudinal: creepage_long,
            lateral: creepage_lat,
            spin,
        };
        let f = linear_creep_forces_checked(a, b, shear_modulus, nu, &creep)?;
        Ok((f.fx, f.fy, f.mz))
    })
}

/// Creepages from Python's `(ξ, η, φ)`: longitudinal and lateral (–), spin (1/m).
fn to_creepages((longitudinal, lateral, spin): (f64, f64, f64)) -> Creepages {
    Creepages {
        longitudinal,
        lateral,
        spin,
    }
}

/// The creep model of a [`PyCreepSolver`].
enum Solver {
    Fastsim(Fastsim),
    Fastrip(Fastrip),
}

/// A creep-force solver built once from its parameters (FASTSIM or FaStrip, with its material,
/// grid and coefficient factor), evaluated per contact by `creep_forces`.
#[pyclass(name = "CreepSolver", module = "loco._loco", frozen)]
pub struct PyCreepSolver {
    solver: Solver,
}

#[pymethods]
impl PyCreepSolver {
    /// FASTSIM for Poisson's ratio `nu` (–), shear modulus (Pa), grid `(nx, ny)`, traction
    /// bound and Kalker coefficient factor (–).
    #[staticmethod]
    fn fastsim(
        nu: f64,
        shear_modulus: f64,
        grid: (i64, i64),
        bound: &str,
        kalker_factor: f64,
    ) -> PyResult<Self> {
        let build = || -> Result<Fastsim, LocoError> {
            Fastsim::new(FastsimParams {
                nx: grid_size("grid[0]", grid.0)?,
                ny: grid_size("grid[1]", grid.1)?,
                kalker_factor,
                bound: traction_bound(bound)?,
                poisson_ratio: nu,
                shear_modulus,
            })
        };
        let solver = Solver::Fastsim(build().map_err(to_py_err)?);
        Ok(Self { solver })
    }

    /// FaStrip for Poisson's ratio `nu` (–), shear modulus (Pa), grid `(nx, ny)` and Kalker
    /// coefficient factor (–).
    #[staticmethod]
    fn fastrip(
        nu: f64,
        shear_modulus: f64,
        grid: (i64, i64),
        kalker_factor: f64,
    ) -> PyResult<Self> {
        let build = || -> Result<Fastrip, LocoError> {
            Fastrip::new(FastripParams {
                nx: grid_size("grid[0]", grid.0)?,
                ny: grid_size("grid[1]", grid.1)?,
                kalker_factor,
                poisson_ratio: nu,
                shear_modulus,
            })
        };
        let solver = Solver::Fastrip(build().map_err(to_py_err)?);
        Ok(Self { solver })
    }

    /// (Fx, Fy, Mz) in N, N, N·m for semi-axes `a`, `b` (m), `normal_force` (N), creepages
    /// `(ξ, η, φ)` and friction coefficient `mu`, the inputs checked first.
    fn creep_forces(
        &self,
        py: Python<'_>,
        a: f64,
        b: f64,
        normal_force: f64,
        creepages: (f64, f64, f64),
        mu: f64,
    ) -> PyResult<(f64, f64, f64)> {
        let solver = &self.solver;
        run_detached(py, move || {
            let creep = to_creepages(creepages);
            check_contact_inputs(a, b, normal_force, mu, &creep)?;
            let f = match solver {
                Solver::Fastsim(s) => s.creep_forces(a, b, normal_force, mu, &creep),
                Solver::Fastrip(s) => s.creep_forces(a, b, normal_force, mu, &creep),
            };
            Ok((f.fx, f.fy, f.mz))
        })
    }
}

/// Creepages (ξ, η, φ) of a wheelset contact on a fixed rail.
#[pyfunction]
#[pyo3(signature = (speed, lateral_velocity, yaw, yaw_rate, roll_rate, spin_rate, side, lateral_position, rolling_radius, contact_angle))]
#[allow(clippy::too_many_arguments)] // mirrors the Python signature one to one
fn wheelset_creepages(
    py: Python<'_>,
    speed: f64,
    lateral_velocity: f64,
    yaw: f64,
    yaw_rate: f64,
    roll_rate: f64,
    spin_rate: f64,
    side: String,
    lateral_position: f64,
    rolling_radius: f64,
    contact_angle: f64,
) -> PyResult<(f64, f64, f64)> {
    run_detached(py, move || {
        let side = match side.as_str() {
            "left" => Side::Left,
            "right" => Side::Right,
            other => {
                return Err(LocoError::param(
                    "side",
                    format!("must be \"left\" or \"right\", got {other:?}"),
                ))
            }
        };
        let motion = WheelsetMotion {
            speed,
            lateral_velocity,
            vertical_velocity: 0.0,
            yaw,
            yaw_rate,
            roll_rate,
            spin_rate,
        };
        let contact = WheelContact {
            side,
            lateral_position,
            rolling_radius,
            contact_angle,
        };
        let c = motion.creepages_checked(&contact)?;
        Ok((c.longitudinal, c.lateral, c.spin))
    })
}

/// Adds this file's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(hertz_contact, m)?)?;
    m.add_function(wrap_pyfunction!(hertz_stiffness, m)?)?;
    m.add_function(wrap_pyfunction!(kalker_coefficients, m)?)?;
    m.add_function(wrap_pyfunction!(linear_creep_forces, m)?)?;
    m.add_class::<PyCreepSolver>()?;
    m.add_function(wrap_pyfunction!(wheelset_creepages, m)?)?;
    Ok(())
}
