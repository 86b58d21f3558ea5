//! The parameters of the frequency-selective damper ([`super::FsdDamper`]): its two damping
//! levels, the equivalent mass and series stiffness, the valve's cut-off and switching delay and
//! its trigger; the default is the spec's FSD (§4).

use super::damping_module::ClosedModule;
use super::fsd_trigger::FsdTrigger;

/// Parameters of an [`FsdDamper`](super::FsdDamper) (SI units). The default is the spec's FSD (§4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FsdParams {
    /// Equivalent damping at low frequency, valve open, c1 (N·s/m), > 0.
    pub low_damping_nspm: f64,
    /// Equivalent damping at high frequency, valve closed, c2 (N·s/m), > c1.
    pub high_damping_nspm: f64,
    /// Equivalent mass at the spring-damper node m (kg), >= 0 (0: massless Maxwell element).
    pub equivalent_mass_kg: f64,
    /// Equivalent (series) stiffness k (N/m), > 0.
    pub equivalent_stiffness_npm: f64,
    /// Cut-off frequency of the frequency valve f_p (Hz), > 0: the rms-frequency trigger's
    /// threshold; the hydraulic valve is derived for it ([`FsdDamper::with_hydraulic_valve`](super::FsdDamper::with_hydraulic_valve)).
    pub cutoff_frequency_hz: f64,
    /// Time for a complete switch of the valve (s), > 0.
    pub switching_delay_s: f64,
    /// Valve state at start: true = closed (high damping).
    pub start_closed: bool,
    /// The trigger and its parameters.
    pub trigger: FsdTrigger,
}

impl Default for FsdParams {
    /// Spec §4: c1 = 200 kN·s/m, c2 = 800 kN·s/m, m = 15 kg, k = 15 kN/mm, f_p = 2 Hz, 0.05 s.
    fn default() -> Self {
        Self {
            low_damping_nspm: 200e3,
            high_damping_nspm: 800e3,
            equivalent_mass_kg: 15.0,
            equivalent_stiffness_npm: 15e6,
            cutoff_frequency_hz: 2.0,
            switching_delay_s: 0.05,
            start_closed: true,
            trigger: FsdTrigger::default(),
        }
    }
}

impl FsdParams {
    /// The closed (high-damping, c2) module that makes the valve's pressure.
    pub fn closed_module(&self) -> ClosedModule {
        ClosedModule {
            damping_nspm: self.high_damping_nspm,
            stiffness_npm: self.equivalent_stiffness_npm,
            mass_kg: self.equivalent_mass_kg,
        }
    }

    /// The open (low-damping, c1) module.
    pub fn open_module(&self) -> ClosedModule {
        ClosedModule {
            damping_nspm: self.low_damping_nspm,
            ..self.closed_module()
        }
    }
}
