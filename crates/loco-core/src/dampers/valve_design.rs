//! What the hydraulic frequency valve is derived for (a reference stroke amplitude and a cut-off
//! frequency, with the chosen geometry and oil), and the derivation of its spring and orifice
//! ([`ValveDesign::derive`]; the method is the module documentation of
//! [`super::frequency_valve`]).

use super::damping_module::ClosedModule;
use super::frequency_valve::{HydraulicValve, HydraulicValveParams, SQRT_SINE_INTEGRAL};
use crate::error::{check_positive, Result};
use crate::LocoError;
use std::f64::consts::TAU;

/// What the parameters are derived for, with the geometry that is chosen, not derived.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValveDesign {
    /// Reference stroke amplitude X_r (m), > 0.
    pub reference_stroke_amplitude_m: f64,
    /// Cut-off frequency at X_r, f_p (Hz), > 0.
    pub cutoff_frequency_hz: f64,
    /// Lowest frequency at which X_r holds the open valve open (c1 pressure against the
    /// spring), f_l (Hz), 0 < f_l < f_p.
    pub lowest_holding_frequency_hz: f64,
    /// Geometry and oil; its orifice area and spring stiffness are replaced by the derived ones.
    pub geometry: HydraulicValveParams,
}

impl ValveDesign {
    /// The spec's f_p = 2 Hz at the stroke amplitude `x_r` (m), f_l = f_p/4, default geometry.
    pub fn spec(reference_stroke_amplitude_m: f64) -> Self {
        Self {
            reference_stroke_amplitude_m,
            cutoff_frequency_hz: 2.0,
            lowest_holding_frequency_hz: 0.5,
            geometry: HydraulicValveParams::default_geometry(),
        }
    }

    /// Derives the spring and the orifice (module documentation) for the closed (c2) and open
    /// (c1) modules.
    pub fn derive(&self, closed: &ClosedModule, open: &ClosedModule) -> Result<HydraulicValve> {
        let x_r = check_positive(
            "reference_stroke_amplitude_m",
            self.reference_stroke_amplitude_m,
        )?;
        let f_p = check_positive("cutoff_frequency_hz", self.cutoff_frequency_hz)?;
        let f_l = check_positive(
            "lowest_holding_frequency_hz",
            self.lowest_holding_frequency_hz,
        )?;
        if f_l >= f_p {
            return Err(LocoError::param(
                "lowest_holding_frequency_hz",
                format!(
                    "{f_l} Hz must be below the cut-off {f_p} Hz: the spring would hold the \
                     valve closed at the cut-off"
                ),
            ));
        }
        let g = self.geometry;
        HydraulicValve::new(g)?; // geometry and oil checked, naming the field
        let pressure =
            |m: &ClosedModule, f: f64| m.force_amplitude(TAU * f, x_r) / g.piston_area_m2;
        let p_hold = pressure(open, f_l);
        let (p_ref, w) = (pressure(closed, f_p), TAU * f_p);
        if p_hold >= p_ref {
            return Err(LocoError::param(
                "lowest_holding_frequency_hz",
                format!(
                    "the holding pressure at {f_l} Hz ({p_hold:.3e} Pa) is not below the closed \
                     valve's pressure at the cut-off ({p_ref:.3e} Pa)"
                ),
            ));
        }
        let spring = g.aux_piston_area_m2 * p_hold / g.opening_stroke_m;
        let v_open = g.aux_piston_area_m2 * g.opening_stroke_m;
        let estimate = 2.0 * v_open * w
            / (g.flow_coefficient
                * SQRT_SINE_INTEGRAL
                * (2.0 * p_ref / g.oil_density_kgpm3).sqrt());
        let with = |area: f64| HydraulicValveParams {
            orifice_area_m2: area,
            spring_stiffness_npm: spring,
            ..g
        };
        // Reach of the orbit at f_p over the opening volume, increasing with the orifice.
        let reach = |area: f64| {
            HydraulicValve::new(with(area)).map(|v| v.orbit_peak_volume(p_ref, w) / v_open - 1.0)
        };
        let (mut lo, mut hi) = (estimate / 64.0, estimate * 64.0);
        if reach(lo)? > 0.0 || reach(hi)? < 0.0 {
            return Err(LocoError::param(
                "cutoff_frequency_hz",
                format!(
                    "no orifice between {lo:.3e} and {hi:.3e} m² gives a cut-off of {f_p} Hz at \
                     {x_r} m"
                ),
            ));
        }
        for _ in 0..60 {
            let mid = (lo * hi).sqrt();
            if reach(mid)? < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        HydraulicValve::new(with((lo * hi).sqrt()))
    }
}
