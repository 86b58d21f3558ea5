//! The units a vehicle file may state a parameter in, and their factors to the SI unit the model
//! reads (the `unit` of the parameter's schema entry).
//!
//! A file states what its number means: `damping = { value = 25, unit = "kN·s/m", ... }` is read as
//! 25 000 N·s/m. A unit that is not a unit of the parameter's quantity (`kN/mm` on a damping) or
//! that is not known at all is refused, never ignored.

/// Accepted spellings for each SI unit of the schema: `(spelling, factor to SI)`. The first entry
/// is the SI spelling itself; ASCII spellings are accepted for people without `·` and `²`.
const UNITS: &[(&str, &[(&str, f64)])] = &[
    ("m", &[("m", 1.0), ("mm", 1e-3), ("cm", 1e-2)]),
    ("kg", &[("kg", 1.0), ("t", 1e3)]),
    (
        "kg·m²",
        &[
            ("kg·m²", 1.0),
            ("kg*m^2", 1.0),
            ("kg m^2", 1.0),
            ("kg.m^2", 1.0),
            ("t·m²", 1e3),
            ("t*m^2", 1e3),
        ],
    ),
    (
        "N/m",
        &[
            ("N/m", 1.0),
            ("N/mm", 1e3),
            ("kN/m", 1e3),
            ("kN/mm", 1e6),
            ("MN/m", 1e6),
        ],
    ),
    (
        "N·s/m",
        &[
            ("N·s/m", 1.0),
            ("N*s/m", 1.0),
            ("Ns/m", 1.0),
            ("N s/m", 1.0),
            ("kN·s/m", 1e3),
            ("kN*s/m", 1e3),
            ("kNs/m", 1e3),
            ("kN s/m", 1e3),
            ("MN·s/m", 1e6),
        ],
    ),
    (
        "N·m/rad",
        &[
            ("N·m/rad", 1.0),
            ("N*m/rad", 1.0),
            ("Nm/rad", 1.0),
            ("N m/rad", 1.0),
            ("kN·m/rad", 1e3),
            ("kN*m/rad", 1e3),
            ("kNm/rad", 1e3),
        ],
    ),
    (
        "Pa",
        &[("Pa", 1.0), ("N/m²", 1.0), ("MPa", 1e6), ("GPa", 1e9)],
    ),
    ("m/s²", &[("m/s²", 1.0), ("m/s^2", 1.0)]),
    ("1", &[("1", 1.0), ("-", 1.0)]),
    ("s", &[("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("us", 1e-6)]),
];

/// The spellings accepted for a parameter whose SI unit is `si_unit` (empty for an unknown one).
pub fn accepted(si_unit: &str) -> Vec<&'static str> {
    UNITS
        .iter()
        .find(|(si, _)| *si == si_unit)
        .map(|(_, spellings)| spellings.iter().map(|(s, _)| *s).collect())
        .unwrap_or_default()
}

/// The factor that turns a value stated in `unit` into `si_unit`, or None when `unit` is not a
/// unit of that quantity (surrounding blanks are ignored, spelling otherwise exact).
pub fn factor_to_si(unit: &str, si_unit: &str) -> Option<f64> {
    let unit = unit.trim();
    UNITS
        .iter()
        .find(|(si, _)| *si == si_unit)
        .and_then(|(_, spellings)| spellings.iter().find(|(s, _)| *s == unit))
        .map(|(_, f)| *f)
}

/// True when `si_unit` is one of the SI units this table knows.
pub fn is_known_si(si_unit: &str) -> bool {
    UNITS.iter().any(|(si, _)| *si == si_unit)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn engineering_units_convert_and_wrong_quantities_are_refused() {
        assert_eq!(factor_to_si("kN/mm", "N/m"), Some(1e6));
        assert_eq!(factor_to_si("kN·s/m", "N·s/m"), Some(1e3));
        assert_eq!(factor_to_si(" mm ", "m"), Some(1e-3));
        assert_eq!(factor_to_si("GPa", "Pa"), Some(1e9));
        assert_eq!(factor_to_si("t", "kg"), Some(1e3));
        // A damping is not a stiffness, and made-up units are not units.
        assert_eq!(factor_to_si("kN/mm", "N·s/m"), None);
        assert_eq!(factor_to_si("furlong", "m"), None);
        assert_eq!(factor_to_si("m", "furlong"), None);
        // Every SI unit accepts its own spelling first, with factor 1.
        for (si, spellings) in UNITS {
            assert_eq!(spellings[0], (*si, 1.0));
            assert!(is_known_si(si));
        }
    }
}
