//! Linear analysis about equilibrium: the state matrix and its eigenvalues, the modes and the rules
//! that name them, the linear critical speed, the stiffest mode and the step it allows, the model
//! with the track as input, its transfer functions and output spectra.

pub mod creep_decay;
pub mod frequency_response;
pub mod linear_critical_speed;
pub mod linearise;
pub mod mode_rules;
pub mod modes;
pub mod response_psd;
pub mod shifted_hessenberg;
pub mod stiffest_mode;
pub mod track_input;
