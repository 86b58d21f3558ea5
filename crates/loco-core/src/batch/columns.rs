//! The columns of a batch's parameter matrix and the checks that run before any simulation.
//!
//! A column is a vehicle parameter (a file key `section.name` or one of the six study names of
//! SPEC §6, `K_px` …) or the run's speed (`speed`, m/s). The whole matrix is checked before the
//! batch starts, so that a typo or a NaN fails at once with the row and column named instead of
//! turning into hundreds of failed samples.

use crate::error::{LocoError, Result};
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::params::parameter_schema::{spec, unknown_key_reason, Affects};
use crate::vehicle::params::parameters::{resolve_name, ParameterSet};
use crate::vehicle::scenarios::run_limits::MIN_SPEED;
use crate::vehicle::scenarios::scenario::MAX_SPEED;
use rayon::prelude::*;
use std::sync::Arc;

/// Name of the column that sets the running speed of each sample, m/s.
pub const SPEED_COLUMN: &str = "speed";

/// What one column of the parameter matrix sets.
#[derive(Debug, Clone, PartialEq)]
pub enum Column {
    /// A vehicle parameter by its file key (study aliases resolved).
    Vehicle(String),
    /// The running speed, m/s.
    Speed,
}

impl Column {
    /// True when the column sets a vehicle parameter (the sample's structure must be built).
    pub fn is_vehicle(&self) -> bool {
        matches!(self, Column::Vehicle(_))
    }

    /// True when the column changes what the wheel-rail contact is built from (the parameter's
    /// schema entry `affects` the contact): the contact tables can then not be shared across
    /// samples.
    pub fn changes_contact(&self) -> bool {
        self.affects(Affects::Contact)
    }

    /// True when the column's parameter changes `what` (its schema entry); the speed changes
    /// none of the vehicle's parts.
    pub fn affects(&self, what: Affects) -> bool {
        match self {
            Column::Vehicle(key) => spec(key).is_some_and(|s| s.affects(what)),
            Column::Speed => false,
        }
    }
}

/// Resolves column names against the base vehicle; unknown and repeated names are refused.
pub fn resolve_columns(base: &ParameterSet, names: &[String]) -> Result<Vec<Column>> {
    let mut columns = Vec::with_capacity(names.len());
    for (j, name) in names.iter().enumerate() {
        let column = if name == SPEED_COLUMN {
            Column::Speed
        } else {
            let key = resolve_name(name);
            if spec(key).is_none() || base.parameter(key).is_none() {
                return Err(LocoError::input(
                    format!("names[{j}]"),
                    format!(
                        "'{name}': {}; a column is a vehicle file key (section.name), a study \
                         name (K_px, K_py, C_sx, C_sy, K_ncsx, K_ncsy) or '{SPEED_COLUMN}'",
                        unknown_key_reason(key)
                    ),
                ));
            }
            Column::Vehicle(key.to_string())
        };
        if columns.contains(&column) {
            return Err(LocoError::input(
                format!("names[{j}]"),
                format!("'{name}' sets the same parameter as an earlier column"),
            ));
        }
        columns.push(column);
    }
    Ok(columns)
}

/// The label of cell (row, column) used in error messages.
fn cell(row: usize, j: usize, name: &str) -> String {
    format!("params[row {row}, column {j} '{name}']")
}

/// Checks the shape and the finiteness of `values` (row-major, `n_rows × names.len()`).
pub fn check_matrix(names: &[String], values: &[f64]) -> Result<usize> {
    let k = names.len();
    if k == 0 {
        return Err(LocoError::input("names", "at least one column is needed"));
    }
    if !values.len().is_multiple_of(k) {
        return Err(LocoError::input(
            "params",
            format!("{} values do not fill rows of {k} columns", values.len()),
        ));
    }
    let n = values.len() / k;
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        let (row, j) = (i / k, i % k);
        return Err(LocoError::input(
            cell(row, j, &names[j]),
            format!("must be finite, got {}", values[i]),
        ));
    }
    Ok(n)
}

/// The vehicle parameters of one row: the base set with the row's vehicle columns applied.
pub fn row_parameters(
    base: &ParameterSet,
    columns: &[Column],
    row: &[f64],
) -> Result<ParameterSet> {
    let mut set = base.clone();
    for (column, &value) in columns.iter().zip(row) {
        if let Column::Vehicle(key) = column {
            set.set(key, value)?;
        }
    }
    Ok(set)
}

/// The running speed of one row (m/s): its speed column, or `default`.
pub fn row_speed(columns: &[Column], row: &[f64], default: f64) -> f64 {
    columns
        .iter()
        .zip(row)
        .find(|(c, _)| **c == Column::Speed)
        .map_or(default, |(_, &v)| v)
}

/// Checks every row for physical values by building its vehicle (in parallel, on the current
/// rayon pool) and returns the vehicles, one per row, for the runs. The first bad row (lowest
/// index) is reported with the column that caused it.
pub fn check_rows(
    base: &ParameterSet,
    names: &[String],
    columns: &[Column],
    values: &[f64],
) -> Result<Vec<Arc<VehicleStructure>>> {
    let k = columns.len();
    let built: Vec<Result<Arc<VehicleStructure>>> = values
        .par_chunks(k)
        .enumerate()
        .map(|(i, row)| check_row(base, names, columns, i, row))
        .collect();
    // In row order, so the error is the lowest row's whatever the thread count.
    built.into_iter().collect()
}

/// Checks the speed column of every row (the first bad row is reported): all a batch whose
/// columns set no vehicle parameter needs, its vehicle being the base one.
pub fn check_speeds(names: &[String], columns: &[Column], values: &[f64]) -> Result<()> {
    values
        .chunks(columns.len())
        .enumerate()
        .try_for_each(|(i, row)| check_row_speed(names, columns, i, row))
}

fn check_row_speed(names: &[String], columns: &[Column], i: usize, row: &[f64]) -> Result<()> {
    for (j, column) in columns.iter().enumerate() {
        if *column == Column::Speed && !(row[j] >= MIN_SPEED && row[j] <= MAX_SPEED) {
            return Err(LocoError::param(
                cell(i, j, &names[j]),
                format!(
                    "speed must be in [{MIN_SPEED}, {MAX_SPEED:.2}] m/s (3.6-400 km/h; below,                      a run's cost per metre grows as 1/speed), got {}",
                    row[j]
                ),
            ));
        }
    }
    Ok(())
}

fn check_row(
    base: &ParameterSet,
    names: &[String],
    columns: &[Column],
    i: usize,
    row: &[f64],
) -> Result<Arc<VehicleStructure>> {
    check_row_speed(names, columns, i, row)?;
    let name_error = |e: LocoError| -> LocoError {
        let (name, reason) = match &e {
            LocoError::InvalidParameter { name, reason } => (name, reason.clone()),
            LocoError::OutOfRange { name, .. } => (name, e.to_string()),
            _ => return e,
        };
        // Name the column whose parameter the vehicle refused, when it is one of the row's.
        let j = columns.iter().position(|c| match c {
            Column::Vehicle(key) => name.contains(key.as_str()),
            Column::Speed => false,
        });
        match (j, &e) {
            (
                Some(j),
                LocoError::OutOfRange {
                    value,
                    min,
                    max,
                    unit,
                    ..
                },
            ) => LocoError::OutOfRange {
                name: format!("{} {name}", cell(i, j, &names[j])),
                value: *value,
                min: *min,
                max: *max,
                unit: unit.clone(),
            },
            (Some(j), _) => LocoError::param(cell(i, j, &names[j]), format!("{name}: {reason}")),
            (None, _) => LocoError::param(format!("params[row {i}] {name}"), reason),
        }
    };
    let set = row_parameters(base, columns, row).map_err(name_error)?;
    // Building the vehicle checks every value it uses (positive masses, stiffnesses, dampings).
    Ok(Arc::new(VehicleStructure::new(set).map_err(name_error)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn resolves_aliases_speed_and_refuses_unknown_or_repeated() {
        let base = ParameterSet::default_vehicle();
        let cols = resolve_columns(&base, &names(&["K_py", "speed", "carbody.mass"])).unwrap();
        assert_eq!(
            cols[0],
            Column::Vehicle("rotary_arm.node_stiffness_lateral".into())
        );
        assert_eq!(cols[1], Column::Speed);
        let e = resolve_columns(&base, &names(&["K_py", "carbody.mas"])).unwrap_err();
        assert!(e.to_string().contains("names[1]") && e.to_string().contains("carbody.mas"));
        let e = resolve_columns(
            &base,
            &names(&["K_py", "rotary_arm.node_stiffness_lateral"]),
        )
        .unwrap_err();
        assert!(e.to_string().contains("names[1]"));
    }

    #[test]
    fn matrix_errors_name_row_and_column() {
        let n = names(&["K_px", "C_sx"]);
        assert_eq!(check_matrix(&n, &[1.0, 2.0, 3.0, 4.0]).unwrap(), 2);
        assert!(check_matrix(&n, &[1.0, 2.0, 3.0]).is_err());
        let e = check_matrix(&n, &[1.0, 2.0, 3.0, f64::NAN]).unwrap_err();
        let text = e.to_string();
        assert!(text.contains("row 1") && text.contains("column 1") && text.contains("C_sx"));
    }

    #[test]
    fn non_physical_rows_are_named() {
        let base = ParameterSet::default_vehicle();
        let n = names(&["C_sx", "speed"]);
        let cols = resolve_columns(&base, &n).unwrap();
        check_rows(&base, &n, &cols, &[8e5, 50.0, 2e5, 60.0]).unwrap();
        let e = check_rows(&base, &n, &cols, &[8e5, 50.0, -2e5, 60.0]).unwrap_err();
        let text = e.to_string();
        assert!(text.contains("row 1") && text.contains("C_sx"), "{text}");
        let e = check_rows(&base, &n, &cols, &[8e5, 500.0]).unwrap_err();
        assert!(e.to_string().contains("speed"), "{e}");
    }
}
