//! Helpers below every physics module: input files read as UTF-8 text, header-row CSV tables and
//! TOML tables read with errors naming file, line and field, and the per-process store of pure
//! builds keyed by their inputs.

pub mod csv_table;
pub mod kept;
pub mod text_file;
pub mod toml_fields;
