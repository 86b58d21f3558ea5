//! The one error type of `loco-core`.
//!
//! Every fallible function of the crate returns [`Result<T>`]. The Python bindings map each variant
//! to one exception class of the `loco.LocoError` hierarchy (see `crates/loco-py/src/errors.rs`), so
//! a new failure mode needs a variant here and nothing else.

use thiserror::Error;

/// Every error `loco-core` can report. Messages name the offending field, file or time.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LocoError {
    /// A scalar parameter is not physical: NaN, infinite, non-positive, out of range,
    /// or inconsistent with another one (`c1 < c2`, ...). `name` is the parameter's name.
    #[error("invalid parameter `{name}`: {reason}")]
    InvalidParameter { name: String, reason: String },

    /// A parameter is outside the physical range of its schema entry (`vehicle/parameter_schema`):
    /// `value`, `min`, `max` in `unit`. A research value outside is allowed only explicitly, by
    /// listing the key in the vehicle file's `allow_out_of_range`.
    #[error("parameter `{name}` = {} {unit} is outside its physical range [{}, {}] {unit}; to study it anyway, list its key in the vehicle file's `allow_out_of_range` (docs/vehicle_parameters.md)", number(*.value), number(*.min), number(*.max))]
    OutOfRange {
        name: String,
        value: f64,
        min: f64,
        max: f64,
        unit: String,
    },

    /// A parameter of a file is unusable where the file states it: a value of the wrong type (a
    /// string where a number is expected, ...), an unknown key or field, a unit of another
    /// quantity, a non-finite value or a fractional count. `name` is the parameter's key, `line`
    /// its 1-based line in the file `path` (0: not found). A parameter error, not a format error:
    /// the file is valid TOML and the fault is the one parameter's.
    #[error("{path}:{line}: invalid parameter `{name}`: {reason}")]
    InvalidParameterInFile {
        path: String,
        line: usize,
        name: String,
        reason: String,
    },

    /// An array or record is unusable: wrong shape or length, too short, NaN inside,
    /// not monotonic. `name` names the argument (and the row or column where it helps).
    #[error("invalid input `{name}`: {reason}")]
    InvalidInput { name: String, reason: String },

    /// A file was read but its content is malformed (or not UTF-8 text). `kind` says which
    /// kind of file (each maps to its own Python class), `line` is 1-based (0: the whole file).
    #[error("{path}:{line}: {reason}")]
    Parse {
        kind: FileKind,
        path: String,
        line: usize,
        reason: String,
    },

    /// A file could not be read or written.
    #[error("cannot access `{path}`: {reason}")]
    Io { path: String, reason: String },

    /// The wheel-rail contact search failed (no contact, profiles do not overlap, ...).
    #[error("contact: {0}")]
    Contact(String),

    /// A time integration produced non-finite states or runaway amplitudes.
    /// `time` is the simulated time in s, `location` the body or coordinate concerned.
    #[error("simulation diverged at t = {time:.4} s ({location}): {reason}")]
    Diverged {
        time: f64,
        location: String,
        reason: String,
    },

    /// The static equilibrium a run or a linearisation starts from was not found: the Newton
    /// search stopped after `iterations` iterations with the residual generalized force
    /// `residual` (N, N·m) above its tolerance.
    #[error("static equilibrium not found after {iterations} Newton iterations (residual {residual:.3e} N): {reason}")]
    Equilibrium {
        iterations: usize,
        residual: f64,
        reason: String,
    },

    /// A wheel climbed past its flange (or lost contact for good).
    #[error("derailment at t = {time:.4} s ({location}): {reason}")]
    Derailed {
        time: f64,
        location: String,
        reason: String,
    },

    /// The caller asked the computation to stop (Ctrl-C from Python, ...).
    #[error("interrupted")]
    Interrupted,
}

/// The kinds of input file, each with its own Python error class (`loco.FileFormatError` and its
/// subclasses), so that a malformed track file is not reported as a malformed profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// A wheel or rail profile (text, SIMPACK `.prw`/`.prr`).
    Profile,
    /// A vehicle parameter file (TOML).
    Vehicle,
    /// A track file: a measured irregularity CSV or a CSV of curve sections.
    Track,
    /// A batch study file (TOML) or samples file (CSV).
    Study,
}

impl FileKind {
    /// The kind's name as front ends give it (`profile`, `vehicle`, `track`, `study`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Profile => "profile",
            Self::Vehicle => "vehicle",
            Self::Track => "track",
            Self::Study => "study",
        }
    }

    /// The kind named `name` ([`Self::name`]); an error names `field` and the accepted names.
    pub fn from_name(name: &str, field: &str) -> Result<Self> {
        [Self::Profile, Self::Vehicle, Self::Track, Self::Study]
            .into_iter()
            .find(|k| k.name() == name)
            .ok_or_else(|| {
                LocoError::param(
                    field,
                    format!("expected profile, vehicle, track or study, got '{name}'"),
                )
            })
    }
}

/// A number for a message: plain when of everyday size, otherwise in exponent form (`1e30`).
fn number(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Shorthand used throughout the crate.
pub type Result<T> = std::result::Result<T, LocoError>;

impl LocoError {
    /// An [`LocoError::InvalidParameter`] with the given name and reason.
    pub fn param(name: impl Into<String>, reason: impl Into<String>) -> Self {
        Self::InvalidParameter {
            name: name.into(),
            reason: reason.into(),
        }
    }

    /// An [`LocoError::InvalidInput`] with the given name and reason.
    pub fn input(name: impl Into<String>, reason: impl Into<String>) -> Self {
        Self::InvalidInput {
            name: name.into(),
            reason: reason.into(),
        }
    }

    /// A [`LocoError::Parse`] of a file of `kind` at `line` (1-based; 0: the whole file).
    pub fn parse(kind: FileKind, path: &str, line: usize, reason: impl Into<String>) -> Self {
        Self::Parse {
            kind,
            path: path.to_string(),
            line,
            reason: reason.into(),
        }
    }

    /// A [`LocoError::Parse`] for the TOML error `e` in `text`, the content of the file `path`,
    /// at the 1-based line where the error's span starts (a span starting a line counts that
    /// line; 0: no span).
    pub fn toml(kind: FileKind, path: &str, text: &str, e: &toml::de::Error) -> Self {
        Self::Parse {
            kind,
            path: path.to_string(),
            line: e
                .span()
                .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1)
                .unwrap_or(0),
            reason: e.message().to_string(),
        }
    }
}

/// `Interrupted` once `cancel` (set from another thread: Ctrl-C in Python) is set. Long loops call
/// it once per step, sample, frequency or bisection, so that a stop request ends them there.
pub fn check_cancel(cancel: Option<&std::sync::atomic::AtomicBool>) -> Result<()> {
    if cancel.is_some_and(|flag| flag.load(std::sync::atomic::Ordering::Relaxed)) {
        Err(LocoError::Interrupted)
    } else {
        Ok(())
    }
}

/// Checks that `value` is finite and strictly positive; the error names `name`.
pub fn check_positive(name: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(LocoError::param(
            name,
            format!("must be finite and > 0, got {value}"),
        ))
    }
}

/// Checks that `value` is finite and not negative; the error names `name`.
pub fn check_non_negative(name: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(LocoError::param(
            name,
            format!("must be finite and >= 0, got {value}"),
        ))
    }
}

/// Checks that `value` is finite; the error names `name`.
pub fn check_finite(name: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(LocoError::param(
            name,
            format!("must be finite, got {value}"),
        ))
    }
}

/// Checks that every element of `values` is finite; the error names `name` and the index.
pub fn check_all_finite(name: &str, values: &[f64]) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(LocoError::input(
            name,
            format!("element {i} is not finite ({})", values[i]),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_name_the_field() {
        let err = check_positive("wheel_radius", -1.0).unwrap_err();
        assert!(err.to_string().contains("wheel_radius"));
        assert!(check_positive("x", f64::NAN).is_err());
        assert!(check_non_negative("x", 0.0).is_ok());
        assert!(check_finite("x", f64::INFINITY).is_err());
        let err = check_all_finite("acc", &[1.0, f64::NAN]).unwrap_err();
        assert!(err.to_string().contains("element 1"));
    }
}
