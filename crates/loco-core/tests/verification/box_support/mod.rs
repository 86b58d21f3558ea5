//! The SPEC §6 parameter box as the integration tests sample it: the two opposite corners of
//! the six parameters and the four damper corners, and the default vehicle with overrides.

use loco_core::vehicle::params::parameters::ParameterSet;

/// The softest bogie: least yaw damping, softest primary, the stiff-spring lateral damper (in
/// its rigid form at 1 ms, compliant at 0.5 ms).
pub const SOFT_CORNER: [(&str, f64); 6] = [
    ("K_px", 10e6),
    ("K_py", 2e6),
    ("C_sx", 200e3),
    ("C_sy", 10e3),
    ("K_ncsx", 10e6),
    ("K_ncsy", 50e6),
];

/// The stiffest bogie.
pub const STIFF_CORNER: [(&str, f64); 6] = [
    ("K_px", 50e6),
    ("K_py", 10e6),
    ("C_sx", 1200e3),
    ("C_sy", 60e3),
    ("K_ncsx", 50e6),
    ("K_ncsy", 10e6),
];

/// Corners of C_sy × K_ncsy (10–60 kN·s/m × 10–50 kN/mm) paired with those of C_sx × K_ncsx
/// (200–1200 kN·s/m × 10–50 kN/mm): four vehicles cover all four corners of both.
pub fn damper_corners() -> Vec<[(&'static str, f64); 4]> {
    [(10e3, 10e6), (10e3, 50e6), (60e3, 10e6), (60e3, 50e6)]
        .iter()
        .zip([(200e3, 10e6), (200e3, 50e6), (1200e3, 10e6), (1200e3, 50e6)])
        .map(|(&(c_sy, k_sy), (c_sx, k_sx))| {
            [
                ("C_sy", c_sy),
                ("K_ncsy", k_sy),
                ("C_sx", c_sx),
                ("K_ncsx", k_sx),
            ]
        })
        .collect()
}

/// The default vehicle with `overrides`.
pub fn vehicle(overrides: &[(&str, f64)]) -> ParameterSet {
    let mut p = ParameterSet::default_vehicle();
    for (name, value) in overrides {
        p.set(name, *value).unwrap();
    }
    p
}
