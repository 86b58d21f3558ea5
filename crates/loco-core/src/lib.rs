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
//! - [`util`]: input files read as UTF-8 text ([`util::text_file`]), comma-separated tables with
//!   a header row ([`util::csv_table`]), TOML tables read field by field ([`util::toml_fields`]),
//!   the per-process store of pure builds ([`util::kept`]).

pub mod batch;
pub mod contact;
pub mod dampers;
pub mod error;
pub mod metrics;
pub(crate) mod simd;
pub mod track;
pub mod util;
pub mod vehicle;

pub use error::{LocoError, Result};
