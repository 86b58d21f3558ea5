//! `loco-core`: the physics of the `loco` railway vehicle dynamics toolkit, in pure Rust.
//!
//! Units are SI throughout (m, kg, s, N, rad) unless a doc comment says otherwise.
//! Modules, one concept each:
//!
//! - [`error`]: the crate's one error enum, [`LocoError`].
//! - [`contact`]: wheel and rail profiles, contact geometry and tables, equivalent conicity
//!   (EN 15302), Hertz ellipses, creepages, Kalker's linear theory and FASTSIM.
//! - [`track`]: track irregularity spectra, synthesis and measured irregularity files.
//! - [`metrics`]: PSD, Sperling ride index, bogie frame stability criteria, comfort.
//! - [`dampers`]: Maxwell dampers, the frequency-selective (FSD) yaw damper, hydraulic model, bench.
//! - [`vehicle`]: the 90-DOF locomotive: parameters, bodies, suspension, equations of motion.
//! - [`batch`]: many runs in parallel (rayon), failed samples flagged, deterministic.
//! - [`text_file`]: input files read as UTF-8 text, other encodings refused by file and byte.
//! - [`csv_table`]: comma-separated tables with a header row, errors naming file and line.

pub mod batch;
pub mod contact;
pub mod csv_table;
pub mod dampers;
pub mod error;
pub mod kept;
pub mod metrics;
pub mod text_file;
pub mod toml_fields;
pub mod track;
pub mod vehicle;

pub use error::{LocoError, Result};
