//! The 90-DOF B0-B0 locomotive (SPEC §1): parameters, bodies, suspension, equations of motion.
//!
//! - [`parameters`]: the parameter file (embedded default vehicle, overrides by name), checked
//!   against [`parameter_schema`] (unit, kind, physical range, what each key affects) with
//!   [`units`] (the units a file may state a value in).
//! - [`layout`]: the 90 coordinates and 25 bodies, `dof_names()`.
//! - [`kinematics`]: small-motion maps from coordinates to body motions.
//! - [`bodies`]: mass properties and positions of the bodies.
//! - [`mass`]: the constant mass matrix and its block factorisation.
//! - [`elements`]: bushings, springs, bump stops.
//! - [`suspension`]: every suspension element placed on the vehicle.
//! - [`structure`]: the assembled vehicle and its gravity, gyroscopic and spring forces.
//! - [`integrator`]: fixed-step RK4.
//! - [`linearise`]: the state matrix about equilibrium, its eigenvalues (nalgebra) and the
//!   linear critical speed; [`critical_speed`]: the nonlinear critical speed by a speed ramp.
//! - [`modes`]: which bodies and motions carry a mode's kinetic energy; [`mode_rules`]: which
//!   mode is the carbody mode and which the bogie mode.
//! - [`track_input`], [`shifted_hessenberg`], [`frequency_response`], [`response_psd`]: the model
//!   linearised with the track as input, its transfer functions to every recorded channel and the
//!   output spectra on a random track.
//! - [`rail_plane`]: the rails' plane at a wheelset, in which the contact table is read (cross
//!   level rolls it); [`track_limits`]: which irregularities the contact can follow.
//! - [`scenario_settings`]: a scenario's user settings (TOML or keyword arguments) resolved once,
//!   with the only defaults ([`scenario_settings::ScenarioSettings::defaults`]); [`presets`]: the
//!   study's scenarios and yaw dampers by name;
//!   [`creep_model`]: the creep model of a run by name (`fastsim`, `fastrip`, `table`).
//! - [`statics`]: the static equilibrium every run starts from; [`stiffest_mode`]: the explicit
//!   step its stiffest mode allows; [`suspects`]: the out-of-range parameters a model failure names;
//!   [`run_statistics`]: what a run
//!   cost (evaluations, steps, Newton iterations, wall time); [`run_limits`]: the cost bounds a
//!   scenario must keep (lowest speed, most steps and samples, largest creep grid).
//! - [`wheel_channels`]: the per-wheel and per-wheelset channels (Q, Y, Y/Q, ΔQ/Q0, T·γ, contact
//!   angle, flange contact, ΣY), named once.

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
