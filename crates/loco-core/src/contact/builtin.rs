//! Registry of built-in profiles (the CN60 rail and the JM3 wheel states of the study).
//!
//! Owned by the conicity work (issue 2 part B), which fills [`builtin_names`] and
//! [`builtin_profile`]; this file only fixes the signatures the Python `loco.profiles.builtin`
//! calls, and ships an empty registry until then.

use super::profile::Profile;
use crate::error::{LocoError, Result};

/// Names accepted by [`builtin_profile`].
pub fn builtin_names() -> &'static [&'static str] {
    &[]
}

/// The built-in profile called `name`; the error lists the available names.
pub fn builtin_profile(name: &str) -> Result<Profile> {
    Err(LocoError::param(
        "name",
        format!(
            "no built-in profile '{name}'; available: [{}]",
            builtin_names().join(", ")
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_name_lists_the_available_ones() {
        let err = builtin_profile("no-such-profile").unwrap_err();
        assert!(err.to_string().contains("available"));
    }
}
