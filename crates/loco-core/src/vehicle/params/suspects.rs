//! The parameters to blame when the model fails: a static equilibrium that is not found, a run
//! that diverges, a contact that cannot be set up. Within their physical ranges (the schema) the
//! parameters give a vehicle the model runs; a research value allowed outside its range
//! (`allow_out_of_range`) is the first suspect, so a failure of such a vehicle names every one
//! of them with its value and range.

use crate::error::LocoError;
use crate::vehicle::params::parameter_schema::spec;
use crate::vehicle::params::parameters::ParameterSet;

/// The parameters of `set` outside their physical range (each allowed explicitly), as
/// "`key` = value unit (range [min, max])", in key order.
pub fn outside_range(set: &ParameterSet) -> Vec<String> {
    set.allowed_out_of_range()
        .filter_map(|key| {
            let s = spec(key)?;
            let value = set.get(key).ok()?;
            (value < s.min || value > s.max).then(|| {
                format!(
                    "`{key}` = {value:e} {} (range [{:e}, {:e}])",
                    s.unit, s.min, s.max
                )
            })
        })
        .collect()
}

/// `err` with the suspects of `set` added to its reason: a failure of the model (equilibrium,
/// divergence, derailment, contact, an input of the contact set-up derived from the vehicle) of
/// a vehicle with parameters outside their range names them. Errors that already name one, input
/// errors of files, and interruptions are returned as they are.
pub fn with_suspects(err: LocoError, set: &ParameterSet) -> LocoError {
    let suspects = outside_range(set);
    let message = err.to_string();
    let named = set
        .allowed_out_of_range()
        .any(|key| message.contains(&format!("`{key}`")));
    if suspects.is_empty() || named {
        return err;
    }
    let note = format!(
        "; suspect: vehicle parameters outside their physical range: {}",
        suspects.join(", ")
    );
    match err {
        LocoError::Equilibrium {
            iterations,
            residual,
            reason,
        } => LocoError::Equilibrium {
            iterations,
            residual,
            reason: reason + &note,
        },
        LocoError::Diverged {
            time,
            location,
            reason,
        } => LocoError::Diverged {
            time,
            location,
            reason: reason + &note,
        },
        LocoError::Derailed {
            time,
            location,
            reason,
        } => LocoError::Derailed {
            time,
            location,
            reason: reason + &note,
        },
        LocoError::Contact(reason) => LocoError::Contact(reason + &note),
        LocoError::InvalidParameter { name, reason } => LocoError::InvalidParameter {
            name,
            reason: reason + &note,
        },
        LocoError::InvalidInput { name, reason } => LocoError::InvalidInput {
            name,
            reason: reason + &note,
        },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn research(mass: f64) -> ParameterSet {
        let mut set = ParameterSet::default_vehicle();
        set.allow_out_of_range("carbody.mass").unwrap();
        set.set("carbody.mass", mass).unwrap();
        set
    }

    #[test]
    fn only_values_outside_their_range_are_suspects() {
        assert!(outside_range(&ParameterSet::default_vehicle()).is_empty());
        // Allowed but inside: no suspect.
        assert!(outside_range(&research(50e3)).is_empty());
        let s = outside_range(&research(1e-30));
        assert_eq!(s.len(), 1);
        assert!(
            s[0].contains("`carbody.mass` = 1e-30 kg") && s[0].contains("1.5e4"),
            "{s:?}"
        );
    }

    #[test]
    fn model_failures_name_the_suspects_and_other_errors_are_left_alone() {
        let set = research(1e-30);
        let diverged = LocoError::Diverged {
            time: 0.001,
            location: "carbody.y".into(),
            reason: "runaway".into(),
        };
        let e = with_suspects(diverged, &set).to_string();
        assert!(
            e.contains("carbody.y") && e.contains("`carbody.mass` = 1e-30"),
            "{e}"
        );
        let named = LocoError::param("carbody.mass", "bad");
        assert_eq!(with_suspects(named.clone(), &set), named);
        assert_eq!(
            with_suspects(LocoError::Interrupted, &set),
            LocoError::Interrupted
        );
        let fine = ParameterSet::default_vehicle();
        let contact = LocoError::Contact("no overlap".into());
        assert_eq!(with_suspects(contact.clone(), &fine), contact);
    }
}
