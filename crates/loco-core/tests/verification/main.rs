//! The verification cases: every model part against something independent of it (closed forms,
//! published benchmarks, standards' cases), one module per case file, linked into one test
//! binary (`cargo test -p loco-core --release --test verification`). Each case records what it
//! measured ([`record`]); `scripts/docs/verification_docs.py` generates `docs/verification.md` from
//! those records.

mod record;

mod box_support;
mod curve_support;
mod manchester;
mod support;

mod batch;
mod bearing_damping;
mod conicity_en15302_profiles;
mod contact_geometry;
mod contact_reference_data;
mod curving;
mod curving_mirror;
mod curving_quasi_static;
mod curving_wheel_loads;
mod exponential_step;
mod fastsim_closed_form;
mod fastsim_contact_reference;
mod frequency_response;
mod hertz;
mod kinematic_wavelength;
mod manchester_normal_force;
mod parameter_box;
mod response_psd;
mod rolled_rails;
mod track_design;
mod vehicle_model;
mod vehicle_stability;
