//! Which creep model a run uses, by name: `fastsim` (Kalker's FASTSIM at every evaluation, the
//! study's method and the default), `fastrip` (FaStrip, strip theory with spin) or `table`
//! (FASTSIM tabulated once per run). The names are defined here once; every front end (the batch
//! study file, the Python `Scenario(creep=...)`) passes them through [`CreepModel::from_name`].

use crate::contact::fastrip::{Fastrip, FastripParams};
use crate::contact::fastsim::{Fastsim, FastsimParams};
use crate::contact::fastsim_table::{FastsimTable, FastsimTableParams};
use crate::error::{LocoError, Result};
use crate::vehicle::rail_contact::wheel_rail::CreepSolver;
use std::sync::Arc;

/// The creep model of a run. Every model uses the scenario's [`FastsimParams`] grid (nx, ny),
/// Kalker factor and material.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum CreepModel {
    /// FASTSIM at every evaluation (SPEC §2: the study's method).
    #[default]
    Fastsim,
    /// FaStrip at every evaluation (`contact::fastrip`; the traction bound is always elliptic).
    Fastrip,
    /// FASTSIM interpolated from a table of this resolution, built once (`contact::fastsim_table`).
    Table(FastsimTableParams),
}

impl CreepModel {
    /// The names [`CreepModel::from_name`] accepts, in the order of the variants.
    pub const NAMES: [&'static str; 3] = ["fastsim", "fastrip", "table"];

    /// The model of a name (`table` with the default resolution); an unknown name is an error
    /// naming the field `creep`.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "fastsim" => Ok(Self::Fastsim),
            "fastrip" => Ok(Self::Fastrip),
            "table" => Ok(Self::Table(FastsimTableParams::default())),
            other => Err(LocoError::param(
                "creep",
                format!("expected one of {:?}, got '{other}'", Self::NAMES),
            )),
        }
    }

    /// The model's name (one of [`CreepModel::NAMES`]).
    pub fn name(&self) -> &'static str {
        match self {
            Self::Fastsim => Self::NAMES[0],
            Self::Fastrip => Self::NAMES[1],
            Self::Table(_) => Self::NAMES[2],
        }
    }

    /// The solver of this model for the parameters `params` (checked).
    pub fn solver(&self, params: FastsimParams) -> Result<CreepSolver> {
        Ok(match self {
            Self::Fastsim => CreepSolver::Direct(Fastsim::new(params)?),
            Self::Fastrip => CreepSolver::Strip(Fastrip::new(FastripParams::from(params))?),
            Self::Table(table) => {
                CreepSolver::Tabulated(Arc::new(FastsimTable::new(params, *table)?))
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_build_their_solver() {
        for name in CreepModel::NAMES {
            let model = CreepModel::from_name(name).unwrap();
            assert_eq!(model.name(), name);
            let solver = model.solver(FastsimParams::default()).unwrap();
            assert!(
                matches!(
                    (model, solver),
                    (CreepModel::Fastsim, CreepSolver::Direct(_))
                        | (CreepModel::Fastrip, CreepSolver::Strip(_))
                        | (CreepModel::Table(_), CreepSolver::Tabulated(_))
                ),
                "{name}"
            );
        }
        assert_eq!(CreepModel::default(), CreepModel::Fastsim);
    }

    #[test]
    fn unknown_name_names_the_field() {
        match CreepModel::from_name("FASTSIM").unwrap_err() {
            LocoError::InvalidParameter { name, reason } => {
                assert_eq!(name, "creep");
                assert!(reason.contains("fastrip"), "{reason}");
            }
            other => panic!("expected an invalid parameter, got {other}"),
        }
    }
}
