//! The outcome of one sample of a batch: a status code that survives a CSV file or a numpy array.

use crate::error::LocoError;

/// How one sample of a batch ended. The numeric codes ([`SampleStatus::code`]) are stable: they
/// are written to the batch binary's CSV and returned to Python as an integer array.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SampleStatus {
    /// The run finished and its metrics are valid.
    Ok,
    /// The sample's parameters were refused when the run was assembled (e.g. a damper too stiff
    /// for the integration step).
    InvalidParameter,
    /// The integration diverged (non-finite state, runaway amplitude).
    Diverged,
    /// A wheel climbed past its flange.
    Derailed,
    /// The wheel-rail contact search failed.
    Contact,
    /// A bug: a panic inside the sample, caught so that the rest of the batch completes.
    Internal,
    /// The batch was cancelled before or while this sample ran.
    Interrupted,
    /// The static equilibrium the run starts from was not found.
    Equilibrium,
}

impl SampleStatus {
    /// Every status, in code order.
    pub const ALL: [SampleStatus; 8] = [
        SampleStatus::Ok,
        SampleStatus::InvalidParameter,
        SampleStatus::Diverged,
        SampleStatus::Derailed,
        SampleStatus::Contact,
        SampleStatus::Internal,
        SampleStatus::Interrupted,
        SampleStatus::Equilibrium,
    ];

    /// Stable numeric code: 0 ok, 1 invalid parameter, 2 diverged, 3 derailed, 4 contact,
    /// 5 internal error, 6 interrupted, 7 no static equilibrium.
    pub fn code(self) -> i32 {
        match self {
            SampleStatus::Ok => 0,
            SampleStatus::InvalidParameter => 1,
            SampleStatus::Diverged => 2,
            SampleStatus::Derailed => 3,
            SampleStatus::Contact => 4,
            SampleStatus::Internal => 5,
            SampleStatus::Interrupted => 6,
            SampleStatus::Equilibrium => 7,
        }
    }

    /// Short name used in CSV files and summaries.
    pub fn name(self) -> &'static str {
        match self {
            SampleStatus::Ok => "ok",
            SampleStatus::InvalidParameter => "invalid_parameter",
            SampleStatus::Diverged => "diverged",
            SampleStatus::Derailed => "derailed",
            SampleStatus::Contact => "contact",
            SampleStatus::Internal => "internal_error",
            SampleStatus::Interrupted => "interrupted",
            SampleStatus::Equilibrium => "equilibrium",
        }
    }

    /// The status of a sample that failed with `error`.
    pub fn from_error(error: &LocoError) -> Self {
        match error {
            LocoError::InvalidParameter { .. }
            | LocoError::InvalidParameterInFile { .. }
            | LocoError::OutOfRange { .. }
            | LocoError::InvalidInput { .. }
            | LocoError::Parse { .. }
            | LocoError::Io { .. } => SampleStatus::InvalidParameter,
            LocoError::Contact(_) => SampleStatus::Contact,
            LocoError::Diverged { .. } => SampleStatus::Diverged,
            LocoError::Derailed { .. } => SampleStatus::Derailed,
            LocoError::Interrupted => SampleStatus::Interrupted,
            LocoError::Equilibrium { .. } => SampleStatus::Equilibrium,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_distinct_and_ordered() {
        for (i, s) in SampleStatus::ALL.iter().enumerate() {
            assert_eq!(s.code(), i as i32);
        }
        let diverged = LocoError::Diverged {
            time: 1.0,
            location: "x".into(),
            reason: "y".into(),
        };
        assert_eq!(SampleStatus::from_error(&diverged), SampleStatus::Diverged);
        assert_eq!(
            SampleStatus::from_error(&LocoError::Interrupted).name(),
            "interrupted"
        );
        let equilibrium = LocoError::Equilibrium {
            iterations: 50,
            residual: 1.0,
            reason: "z".into(),
        };
        assert_eq!(
            SampleStatus::from_error(&equilibrium),
            SampleStatus::Equilibrium
        );
        assert_ne!(
            SampleStatus::Equilibrium.code(),
            SampleStatus::Diverged.code()
        );
    }
}
