//! The 90-DOF B0-B0 locomotive (SPEC §1): parameters, bodies, suspension, contact, equations of
//! motion, runs and their analyses, one folder per layer. A layer uses only the layers before it
//! in this list (`tests/api/test_module_graph.py` checks that no modules use each other):
//!
//! - [`params`]: the parameter file (embedded default vehicle, overrides by name), its schema
//!   (unit, kind, physical range, what each key affects), units, input ranges and presets.
//! - [`model`]: the 90 coordinates and 25 bodies, kinematics, mass, suspension elements, the
//!   bogie mass and the assembled [`model::structure::VehicleStructure`].
//! - [`rail_contact`]: the wheel-rail forces ([`rail_contact::wheel_rail::WheelRail`]), the creep
//!   model by name, the rails' plane at a wheelset, the irregularities the contact can follow.
//! - [`curving`]: the track frame each body's coordinates are measured from on a curve.
//! - [`time`]: the ODE trait, RK4 and the exponential RK4 with the parts it solves exactly.
//! - [`system`]: [`system::simulation::VehicleSystem`], the equations of motion, and the static
//!   equilibrium every run starts from.
//! - [`output`]: a run ([`output::run::run`]) and what it records: channels, accelerometers,
//!   wheel channels, the metrics of a run.
//! - [`scenarios`]: a scenario's settings resolved once, its cost bounds and its contact.
//! - [`analysis`]: the state matrix, modes, the stiffest mode, the linear critical speed, the
//!   track-input model, its transfer functions and output spectra.
//! - [`runs`]: `simulate`, `linearised` and the nonlinear critical speed of a scenario.

pub mod analysis;
pub mod curving;
pub mod model;
pub mod output;
pub mod params;
pub mod rail_contact;
pub mod runs;
pub mod scenarios;
pub mod system;
pub mod time;
