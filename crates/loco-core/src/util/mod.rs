//! Helpers below every physics module: input files read as UTF-8 text, header-row CSV tables and
//! TOML tables read with errors naming file, line and field, and the per-process store of pure
//! builds keyed by their inputs, the message of a caught panic.

pub mod csv_table;
pub mod kept;
pub mod panic_message;
pub mod text_file;
pub mod toml_fields;
