//! Parameters: the parameter file and its schema (unit, kind, physical range, what each key
//! affects), the typed sections the model builders read, the units a file may state a value in, the input ranges of the study, the study's
//! scenarios and yaw dampers by name, and the out-of-range parameters a model failure names.
//! The embedded TOML files (default vehicle, schema, uncertainty ranges) sit beside their readers.

pub mod input_ranges;
pub mod parameter_schema;
pub mod parameters;
pub mod presets;
pub mod sections;
pub mod suspects;
pub mod units;
