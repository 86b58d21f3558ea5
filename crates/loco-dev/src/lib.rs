//! Developer tools for the core: timing, output hashes and investigations of one run, each a
//! binary of this crate (`cargo run --release -p loco-dev --bin <name> -- ...`). They are not
//! part of the library; the criterion benches of `loco-core` and the scripts of `scripts/bench`
//! call some of them.
//!
//! - `sim_time`: one run's thread CPU time without its set-up;
//! - `run_fingerprint`: a hash of every output sample of the study case, to check a change
//!   bit for bit;
//! - `creep_replay` (feature `record-contacts`): FaStrip against FASTSIM on a run's own contacts;
//! - `creep_cost`: the creep models' cost per call on chosen cases and grids;
//! - `integrator_compare`: the schemes against each other on the study case;
//! - `full_linear_etd`: the exponential scheme with the whole linearised model as its linear part;
//! - `curve_rest`: the vehicle's rest state in a curve, and its stiffest modes.

pub mod study_case;
