//! Reading a TOML table into a settings struct with the error naming the field: serde's message
//! names only the type (`invalid type: string "x", expected f64`), so the field to blame is found
//! by reading each key on its own. Used for the scenario settings of Python's `Scenario` and for
//! the curve sections of a study file and of Python.

use crate::error::{LocoError, Result};
use serde::de::DeserializeOwned;

/// `table` read as a `T`. An error is a [`LocoError::InvalidParameter`] naming, as `name(key)`,
/// the first key that is refused on its own when added to `base` (a table `T` accepts), else
/// `whole` (a required field missing, or fields that are wrong only together).
pub fn read_table<T: DeserializeOwned>(
    table: &toml::Table,
    base: &toml::Table,
    whole: &str,
    name: impl Fn(&str) -> String,
) -> Result<T> {
    let read = |table: toml::Table| toml::Value::Table(table).try_into::<T>();
    read(table.clone()).map_err(|e| {
        let key = table.iter().find(|(k, v)| {
            let mut one = base.clone();
            one.insert((*k).clone(), (*v).clone());
            read(one).is_err()
        });
        let field = key.map_or_else(|| whole.to_string(), |(k, _)| name(k));
        LocoError::param(field, e.message().trim().to_string())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Default, Deserialize, serde::Serialize)]
    #[serde(deny_unknown_fields)]
    struct Two {
        a: f64,
        b: Option<String>,
    }

    fn table(text: &str) -> toml::Table {
        toml::from_str(text).unwrap()
    }

    #[test]
    fn the_error_names_the_key_refused_on_its_own() {
        let base = toml::Table::try_from(Two::default()).unwrap();
        let name = |k: &str| format!("two ({k})");
        let e = read_table::<Two>(&table("a = 1.0\nb = 3"), &base, "two", name).unwrap_err();
        assert!(e.to_string().contains("`two (b)`"), "{e}");
        let e = read_table::<Two>(&table("a = 1.0\nc = 3"), &base, "two", name).unwrap_err();
        assert!(e.to_string().contains("`two (c)`") && e.to_string().contains("unknown field"));
        // A missing required field is no key's fault: the whole is named.
        let e = read_table::<Two>(&table("b = 'x'"), &base, "two", name).unwrap_err();
        assert!(
            e.to_string().contains("`two`") && e.to_string().contains("`a`"),
            "{e}"
        );
        let two = read_table::<Two>(&table("a = 2.0"), &base, "two", name).unwrap();
        assert_eq!(two.a, 2.0);
    }
}
