//! Hydraulic orifice model of a (twin-tube) damper in series with its joint stiffness, with an
//! optional frequency valve (bypass) that makes it a hydraulic FSD damper.
//!
//! # Flow paths
//! Piston area `A_p`, rod area `A_r`, annulus `A_a = A_p - A_r`. Piston velocity `v > 0` is
//! extension (rebound), the damper's elongation.
//! - Rebound: the annulus chamber shrinks, `Q = A_a·v` flows through the rebound orifice:
//!   `F = A_a·Δp_reb(A_a·v)`.
//! - Compression: `A_a·|v|` flows through the piston's compression orifice into the annulus and the
//!   rod volume `A_r·|v|` through the bottom (foot) valve into the reservoir:
//!   `F = A_r·Δp_bottom(A_r·v) + A_a·Δp_comp(A_a·v)`.
//!
//! # Orifice law
//! `Δp(Q) = Q/K_lam + ρ/(2·C_d²·A²)·Q·|Q|`: the turbulent (sharp-edged) orifice equation, where
//! the force grows with the square of the velocity, in series with the laminar resistance of the
//! same orifice at low Reynolds number, `K_lam = 2·δ²·d_h·A/μ` with `δ = 0.2` and `d_h` the
//! hydraulic diameter (Merritt, *Hydraulic Control Systems*, Wiley 1967, §2.6). The laminar term is
//! physical and small (a few kN·s/m) but it makes the inverse law Lipschitz at zero force, which an
//! explicit integrator needs. Each direction is thus `F = c_lin·v + b·v·|v|`, solved in closed form
//! for `v(F)`.
//!
//! # Frequency valve
//! With a [`HydraulicFrequencyValve`], bypass passages open beside every orifice when the FSD valve
//! is open, so every effective flow area grows by the factor `open_area_ratio` (blended by the FSD
//! scale factor `s`, 0 open, 1 closed: `A·(1 + (1 - s)·(ratio - 1))`), from the same trigger and
//! state machine as [`super::fsd`]. The turbulent force goes with `1/A²`, so the default ratio 2
//! gives the spec's c2/c1 = 4.
//!
//! # Default geometry (a yaw damper)
//! Piston Ø50 mm and rod Ø25 mm (the bore of railway yaw dampers, e.g. Koni 05/09 series and the
//! damper of Alonso, Giménez and Gomez, VSD 49(9), 2011). Rebound orifice Ø0.7 mm; compression
//! piston (non-return) orifice Ø3 mm; bottom valve Ø0.307 mm, sized so that compression and rebound
//! give the same force within 1 % (yaw dampers are symmetric). Sharp-edged orifice `C_d = 0.61`
//! (Merritt §2.6; handbooks give 0.6–0.7); ISO VG 32 hydraulic oil, `ρ = 870 kg/m³`,
//! `ν = 32 mm²/s` at 40 °C (ISO 3448 defines the grade by this viscosity); series stiffness
//! 22.5 kN/mm (spec). This gives `b ≈ 2.5e7 N·s²/m²`: 25 kN at 0.031 m/s (1 Hz, 5 mm) and an
//! orifice-alone equivalent damping `8·b·A·ω/(3π) ≈ 670 kN·s/m` there, of the order of YD2.
//!
//! Equivalent damping of the default damper with its joint on the bench (kN·s/m; it grows with
//! amplitude and frequency, as a quadratic law must, until the series stiffness takes over):
//!
//! | frequency | 2 mm | 5 mm |
//! |---|---|---|
//! | 0.5 Hz | 138 | 338 |
//! | 1 Hz | 268 | 619 |
//! | 2 Hz | 453 | 767 |
//! | 4 Hz | 430 | 402 |

use super::fsd_trigger::FsdTriggerParams;
use crate::error::{check_positive, Result};
use crate::LocoError;
use std::f64::consts::PI;

/// Laminar flow coefficient δ of a sharp-edged orifice at low Reynolds number (Merritt 1967).
const LAMINAR_FLOW_COEFFICIENT: f64 = 0.2;

/// The area (m²) of a circle of diameter `d` (m).
fn circle_area(diameter_m: f64) -> f64 {
    PI / 4.0 * diameter_m * diameter_m
}

/// The frequency valve of a hydraulic FSD damper: bypasses open at low frequency.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicFrequencyValve {
    /// Effective flow area with the valve open over that with it closed, > 1.
    pub open_area_ratio: f64,
    /// Cut-off frequency f_p (Hz), > 0.
    pub cutoff_frequency_hz: f64,
    /// Time for a complete switch (s), > 0.
    pub switching_delay_s: f64,
    /// Valve state at start: true = closed (bypass shut, high damping).
    pub start_closed: bool,
    /// Tuning of the trigger.
    pub trigger: FsdTriggerParams,
}

/// Parameters of a [`HydraulicDamper`] (SI units); the default is documented in the module.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicParams {
    /// Piston area A_p (m²), > 0.
    pub piston_area_m2: f64,
    /// Rod area A_r (m²), 0 < A_r < A_p.
    pub rod_area_m2: f64,
    /// Rebound orifice area in the piston (m²), > 0.
    pub rebound_orifice_area_m2: f64,
    /// Compression orifice area in the piston (m²), > 0.
    pub compression_orifice_area_m2: f64,
    /// Bottom (foot) valve orifice area (m²), > 0.
    pub bottom_valve_area_m2: f64,
    /// Oil density ρ (kg/m³), > 0.
    pub oil_density_kgpm3: f64,
    /// Kinematic viscosity of the oil ν (m²/s), > 0.
    pub oil_kinematic_viscosity_m2ps: f64,
    /// Turbulent flow (discharge) coefficient C_d, > 0.
    pub flow_coefficient: f64,
    /// Series stiffness of the damper and its joints (N/m), > 0.
    pub series_stiffness_npm: f64,
    /// Optional frequency valve (hydraulic FSD); `None`: a conventional damper.
    pub frequency_valve: Option<HydraulicFrequencyValve>,
}

impl Default for HydraulicParams {
    fn default() -> Self {
        Self {
            piston_area_m2: circle_area(0.050),
            rod_area_m2: circle_area(0.025),
            rebound_orifice_area_m2: circle_area(0.7e-3),
            compression_orifice_area_m2: circle_area(3.0e-3),
            bottom_valve_area_m2: circle_area(0.307e-3),
            oil_density_kgpm3: 870.0,
            oil_kinematic_viscosity_m2ps: 32e-6,
            flow_coefficient: 0.61,
            series_stiffness_npm: 22.5e6,
            frequency_valve: None,
        }
    }
}

/// `F = linear·v + quadratic·v·|v|` for one direction of motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionLaw {
    /// Laminar part (N·s/m).
    pub linear_nspm: f64,
    /// Turbulent part (N·s²/m²).
    pub quadratic_ns2pm2: f64,
}

impl DirectionLaw {
    const ZERO: Self = Self {
        linear_nspm: 0.0,
        quadratic_ns2pm2: 0.0,
    };

    /// Speed (m/s, >= 0) at which this law carries force magnitude `force_n` (>= 0).
    #[inline]
    fn speed(&self, force_n: f64) -> f64 {
        // Root of b·v² + c·v - F = 0 written without cancellation.
        let (c, b) = (self.linear_nspm, self.quadratic_ns2pm2);
        2.0 * force_n / (c + (c * c + 4.0 * b * force_n).sqrt())
    }
}

/// A validated hydraulic damper. See the module documentation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicDamper {
    params: HydraulicParams,
    /// Laws (rebound, compression) with the valve closed (s = 1) and open (s = 0), cached so
    /// that the force evaluation outside a valve transition costs no square root of areas.
    closed_laws: (DirectionLaw, DirectionLaw),
    open_laws: (DirectionLaw, DirectionLaw),
}

impl HydraulicDamper {
    /// Validates every field (finite, > 0; rod area < piston area; valve fields).
    pub fn new(params: HydraulicParams) -> Result<Self> {
        check_positive("piston_area_m2", params.piston_area_m2)?;
        check_positive("rod_area_m2", params.rod_area_m2)?;
        if params.rod_area_m2 >= params.piston_area_m2 {
            return Err(LocoError::param(
                "rod_area_m2",
                format!(
                    "must be < piston_area_m2 ({}), got {}",
                    params.piston_area_m2, params.rod_area_m2
                ),
            ));
        }
        check_positive("rebound_orifice_area_m2", params.rebound_orifice_area_m2)?;
        check_positive(
            "compression_orifice_area_m2",
            params.compression_orifice_area_m2,
        )?;
        check_positive("bottom_valve_area_m2", params.bottom_valve_area_m2)?;
        check_positive("oil_density_kgpm3", params.oil_density_kgpm3)?;
        check_positive(
            "oil_kinematic_viscosity_m2ps",
            params.oil_kinematic_viscosity_m2ps,
        )?;
        check_positive("flow_coefficient", params.flow_coefficient)?;
        check_positive("series_stiffness_npm", params.series_stiffness_npm)?;
        if let Some(valve) = params.frequency_valve {
            if !(valve.open_area_ratio.is_finite() && valve.open_area_ratio > 1.0) {
                return Err(LocoError::param(
                    "open_area_ratio",
                    format!("must be finite and > 1, got {}", valve.open_area_ratio),
                ));
            }
            check_positive("cutoff_frequency_hz", valve.cutoff_frequency_hz)?;
            check_positive("switching_delay_s", valve.switching_delay_s)?;
            valve.trigger.validate()?;
        }
        Ok(Self::with_cache(params))
    }

    /// Builds the damper and its cached laws from already validated parameters.
    fn with_cache(params: HydraulicParams) -> Self {
        let mut damper = Self {
            params,
            closed_laws: (DirectionLaw::ZERO, DirectionLaw::ZERO),
            open_laws: (DirectionLaw::ZERO, DirectionLaw::ZERO),
        };
        damper.closed_laws = damper.laws(1.0);
        damper.open_laws = damper.laws(0.0);
        damper
    }

    /// The laws at scale factor `s`, from the cache at the ends of the valve travel.
    #[inline]
    pub fn laws_at(&self, scale_factor: f64) -> (DirectionLaw, DirectionLaw) {
        if scale_factor >= 1.0 {
            self.closed_laws
        } else if scale_factor <= 0.0 {
            self.open_laws
        } else {
            self.laws(scale_factor)
        }
    }

    /// The validated parameters.
    pub fn params(&self) -> &HydraulicParams {
        &self.params
    }

    /// Pressure-drop law `Δp = Q/K_lam + k_turb·Q|Q|` of one orifice: `(1/K_lam, k_turb)`.
    fn orifice(&self, area_m2: f64) -> (f64, f64) {
        let p = &self.params;
        let hydraulic_diameter_m = (4.0 * area_m2 / PI).sqrt();
        let viscosity_pas = p.oil_density_kgpm3 * p.oil_kinematic_viscosity_m2ps;
        let laminar_conductance = 2.0
            * LAMINAR_FLOW_COEFFICIENT
            * LAMINAR_FLOW_COEFFICIENT
            * hydraulic_diameter_m
            * area_m2
            / viscosity_pas;
        let cd_area = p.flow_coefficient * area_m2;
        (
            1.0 / laminar_conductance,
            p.oil_density_kgpm3 / (2.0 * cd_area * cd_area),
        )
    }

    /// Force laws (rebound, compression) with the frequency valve at scale factor `s`
    /// (0 open, 1 closed; ignored without a valve).
    pub fn laws(&self, scale_factor: f64) -> (DirectionLaw, DirectionLaw) {
        let p = &self.params;
        let area_factor = p.frequency_valve.map_or(1.0, |v| {
            1.0 + (1.0 - scale_factor.clamp(0.0, 1.0)) * (v.open_area_ratio - 1.0)
        });
        let annulus = p.piston_area_m2 - p.rod_area_m2;
        let rod = p.rod_area_m2;
        // A flow Q = A·v through an orifice with Δp = r·Q + t·Q|Q| acting on area A gives
        // F = A²·r·v + A³·t·v|v|.
        let (r_reb, t_reb) = self.orifice(p.rebound_orifice_area_m2 * area_factor);
        let (r_comp, t_comp) = self.orifice(p.compression_orifice_area_m2 * area_factor);
        let (r_bot, t_bot) = self.orifice(p.bottom_valve_area_m2 * area_factor);
        let rebound = DirectionLaw {
            linear_nspm: annulus.powi(2) * r_reb,
            quadratic_ns2pm2: annulus.powi(3) * t_reb,
        };
        let compression = DirectionLaw {
            linear_nspm: annulus.powi(2) * r_comp + rod.powi(2) * r_bot,
            quadratic_ns2pm2: annulus.powi(3) * t_comp + rod.powi(3) * t_bot,
        };
        (rebound, compression)
    }

    /// Damper force (N, positive in rebound) at piston velocity `v` (m/s) and scale factor `s`.
    pub fn damper_force(&self, velocity_mps: f64, scale_factor: f64) -> f64 {
        let (rebound, compression) = self.laws_at(scale_factor);
        let law = if velocity_mps >= 0.0 {
            rebound
        } else {
            compression
        };
        law.linear_nspm * velocity_mps + law.quadratic_ns2pm2 * velocity_mps * velocity_mps.abs()
    }

    /// Force (N, tension positive) and damper deflection rate (m/s) for elongation `x` (m),
    /// damper deflection `x_d` (m) and the precomputed laws at the current scale factor.
    #[inline]
    pub fn force_and_rate(
        &self,
        elongation_m: f64,
        damper_deflection_m: f64,
        laws: &(DirectionLaw, DirectionLaw),
    ) -> (f64, f64) {
        let force_n = self.params.series_stiffness_npm * (elongation_m - damper_deflection_m);
        let rate = if force_n >= 0.0 {
            laws.0.speed(force_n)
        } else {
            -laws.1.speed(-force_n)
        };
        (force_n, rate)
    }

    /// A hydraulic FSD: the default geometry with a frequency valve of the spec's FSD timing
    /// (f_p = 2 Hz, 0.05 s) and an open/closed area ratio 2 (c2/c1 = 4, as the spec's FSD).
    pub fn fsd_default() -> Self {
        Self::with_cache(HydraulicParams {
            frequency_valve: Some(HydraulicFrequencyValve {
                open_area_ratio: 2.0,
                cutoff_frequency_hz: 2.0,
                switching_delay_s: 0.05,
                start_closed: true,
                trigger: FsdTriggerParams::default(),
            }),
            ..HydraulicParams::default()
        })
    }

    /// Fastest decay rate of the internal state (1/s): `k/c_lin`, the slope at zero force
    /// (the laminar part is smallest with the valve open).
    pub fn fastest_rate_per_s(&self) -> f64 {
        let (rebound, compression) = self.laws(0.0);
        self.params.series_stiffness_npm / rebound.linear_nspm.min(compression.linear_nspm)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_geometry_is_symmetric_and_quadratic() {
        let damper = HydraulicDamper::new(HydraulicParams::default()).unwrap();
        let (rebound, compression) = damper.laws(1.0);
        let ratio = compression.quadratic_ns2pm2 / rebound.quadratic_ns2pm2;
        assert!((ratio - 1.0).abs() < 0.01, "compression/rebound = {ratio}");
        // Quadratic growth: doubling a (turbulent-range) velocity nearly quadruples the force.
        let f1 = damper.damper_force(0.02, 1.0);
        let f2 = damper.damper_force(0.04, 1.0);
        assert!((f2 / f1 - 4.0).abs() < 0.1, "{f1} {f2}");
        assert!(damper.damper_force(-0.02, 1.0) < 0.0);
        // Inverse law round trip.
        let laws = damper.laws(1.0);
        for v in [-0.05, -1e-4, 0.0, 3e-5, 0.03] {
            let force = damper.damper_force(v, 1.0);
            let k = damper.params().series_stiffness_npm;
            let (_, rate) = damper.force_and_rate(force / k, 0.0, &laws);
            assert!((rate - v).abs() < 1e-12 + 1e-9 * v.abs(), "{v} -> {rate}");
        }
    }

    #[test]
    fn validation_names_the_field() {
        let bad = HydraulicParams {
            rod_area_m2: 1.0,
            ..HydraulicParams::default()
        };
        let err = HydraulicDamper::new(bad).unwrap_err().to_string();
        assert!(err.contains("rod_area_m2"), "{err}");
        let bad = HydraulicParams {
            flow_coefficient: f64::NAN,
            ..HydraulicParams::default()
        };
        assert!(HydraulicDamper::new(bad)
            .unwrap_err()
            .to_string()
            .contains("flow_coefficient"));
    }
}
