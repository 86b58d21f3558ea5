//! The Maxwell damper: a viscous damper in series with a spring (the series stiffness of the
//! damper's rubber joints, brackets and oil compressibility), with a linear or piecewise-linear
//! (blow-off) force-velocity law.
//!
//! Model: the spring deflects by `x - x_d`, where `x` (m) is the damper's total elongation and
//! `x_d` (m) the deflection of the damper element, the one continuous state. The force (N,
//! positive in tension) is `F = k·(x - x_d)` and the damper element moves at the velocity whose
//! damper force equals it: `dx_d/dt = v(F)`, the inverse of the force-velocity law. The state
//! equation is explicit and needs no mass at the node between spring and damper.
//!
//! Closed form (linear law, sine motion at angular frequency ω): the complex stiffness is
//! `k·iωc/(k + iωc)`, so the equivalent damping is `c/(1 + (ωc/k)²)` and the equivalent stiffness
//! `k·(ωc/k)²/(1 + (ωc/k)²)`; the bench tests check these.

use crate::error::{check_positive, Result};
use crate::LocoError;

/// A piecewise-linear force-velocity law: damping `damping_nspm` up to the knee (blow-off)
/// velocity, then the smaller slope `blow_off_damping_nspm` (relief valve open).
///
/// Real yaw dampers open a relief valve at a few cm/s (Alonso, Giménez and Gomez, "Yaw damper
/// modelling and its influence on railway dynamic stability", Vehicle System Dynamics 49(9),
/// 2011, characteristics with a knee near 0.01–0.03 m/s and a post-knee slope of a few % of the
/// initial one). The spec's YD1/YD2/FSD values are linear, so the presets have no knee.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlowOff {
    /// Piston velocity at which the relief valve opens (m/s), > 0.
    pub knee_velocity_mps: f64,
    /// Slope of the force-velocity law above the knee (N·s/m), > 0.
    pub blow_off_damping_nspm: f64,
}

/// Parameters of a [`MaxwellDamper`] (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaxwellParams {
    /// Damping below the knee (N·s/m), > 0.
    pub damping_nspm: f64,
    /// Series stiffness of the damper and its joints (N/m), > 0.
    pub series_stiffness_npm: f64,
    /// Optional blow-off (relief) above a knee velocity; `None` is a linear law.
    pub blow_off: Option<BlowOff>,
}

impl Default for MaxwellParams {
    /// The spec's conventional yaw damper YD2: 800 kN·s/m, series stiffness 22.5 kN/mm, linear.
    fn default() -> Self {
        Self {
            damping_nspm: 800e3,
            series_stiffness_npm: 22.5e6,
            blow_off: None,
        }
    }
}

/// A validated Maxwell damper; see the module documentation for the model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaxwellDamper {
    params: MaxwellParams,
    /// Force at the knee (N), `damping·knee_velocity`, or infinity for a linear law.
    knee_force_n: f64,
    /// Series spring taken as rigid (the reduced law of [`super::Damper::for_step`]): the force
    /// is the damper element's at the elongation rate, no internal state.
    rigid_series: bool,
}

impl MaxwellDamper {
    /// Validates the parameters: damping, series stiffness, knee velocity and blow-off damping
    /// finite and > 0; the blow-off damping must not exceed the damping below the knee.
    pub fn new(params: MaxwellParams) -> Result<Self> {
        check_positive("damping_nspm", params.damping_nspm)?;
        check_positive("series_stiffness_npm", params.series_stiffness_npm)?;
        let mut knee_force_n = f64::INFINITY;
        if let Some(blow_off) = params.blow_off {
            check_positive("knee_velocity_mps", blow_off.knee_velocity_mps)?;
            check_positive("blow_off_damping_nspm", blow_off.blow_off_damping_nspm)?;
            if blow_off.blow_off_damping_nspm > params.damping_nspm {
                return Err(LocoError::param(
                    "blow_off_damping_nspm",
                    format!(
                        "must not exceed damping_nspm ({}), got {}",
                        params.damping_nspm, blow_off.blow_off_damping_nspm
                    ),
                ));
            }
            knee_force_n = params.damping_nspm * blow_off.knee_velocity_mps;
        }
        Ok(Self {
            params,
            knee_force_n,
            rigid_series: false,
        })
    }

    /// Conventional yaw damper YD1 of the spec: 200 kN·s/m, series stiffness 22.5 kN/mm.
    pub fn yd1() -> Self {
        Self::linear(200e3, 22.5e6)
    }

    /// Conventional yaw damper YD2 of the spec: 800 kN·s/m, series stiffness 22.5 kN/mm.
    pub fn yd2() -> Self {
        Self::linear(800e3, 22.5e6)
    }

    /// A linear Maxwell damper from literal, known-valid values (presets only).
    fn linear(damping_nspm: f64, series_stiffness_npm: f64) -> Self {
        Self {
            params: MaxwellParams {
                damping_nspm,
                series_stiffness_npm,
                blow_off: None,
            },
            knee_force_n: f64::INFINITY,
            rigid_series: false,
        }
    }

    /// The validated parameters.
    pub fn params(&self) -> &MaxwellParams {
        &self.params
    }

    /// Whether the series spring is taken as rigid (see [`super::Damper::for_step`]).
    pub fn has_rigid_series(&self) -> bool {
        self.rigid_series
    }

    /// The same damper with its series spring rigid.
    pub(crate) fn with_rigid_series(self) -> Self {
        Self {
            rigid_series: true,
            ..self
        }
    }

    /// Damper force (N) of the damper element at piston velocity `velocity_mps`.
    pub fn damper_force(&self, velocity_mps: f64) -> f64 {
        let c = self.params.damping_nspm;
        match self.params.blow_off {
            Some(b) if velocity_mps.abs() > b.knee_velocity_mps => {
                velocity_mps.signum()
                    * (self.knee_force_n
                        + b.blow_off_damping_nspm * (velocity_mps.abs() - b.knee_velocity_mps))
            }
            _ => c * velocity_mps,
        }
    }

    /// Piston velocity (m/s) at which the damper element carries `force_n`: the inverse law.
    pub fn damper_velocity(&self, force_n: f64) -> f64 {
        match self.params.blow_off {
            Some(b) if force_n.abs() > self.knee_force_n => {
                force_n.signum()
                    * (b.knee_velocity_mps
                        + (force_n.abs() - self.knee_force_n) / b.blow_off_damping_nspm)
            }
            _ => force_n / self.params.damping_nspm,
        }
    }

    /// Force (N, tension positive) and the damper deflection rate (m/s) for elongation `x` (m)
    /// and damper deflection `x_d` (m).
    #[inline]
    pub fn force_and_rate(&self, elongation_m: f64, damper_deflection_m: f64) -> (f64, f64) {
        let force_n = self.params.series_stiffness_npm * (elongation_m - damper_deflection_m);
        (force_n, self.damper_velocity(force_n))
    }

    /// Fastest decay rate of the internal state (1/s): `k/c_min` (the blow-off slope is the
    /// smallest damping, hence the fastest spring-damper time constant); 0 with a rigid series
    /// spring (no internal state).
    pub fn fastest_rate_per_s(&self) -> f64 {
        if self.rigid_series {
            return 0.0;
        }
        let c_min = self
            .params
            .blow_off
            .map_or(self.params.damping_nspm, |b| b.blow_off_damping_nspm);
        self.params.series_stiffness_npm / c_min
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_names_the_field() {
        let bad = MaxwellParams {
            damping_nspm: -1.0,
            ..MaxwellParams::default()
        };
        let err = MaxwellDamper::new(bad).unwrap_err().to_string();
        assert!(err.contains("damping_nspm"), "{err}");
        let bad = MaxwellParams {
            series_stiffness_npm: f64::NAN,
            ..MaxwellParams::default()
        };
        assert!(MaxwellDamper::new(bad)
            .unwrap_err()
            .to_string()
            .contains("series_stiffness_npm"));
        let bad = MaxwellParams {
            blow_off: Some(BlowOff {
                knee_velocity_mps: 0.02,
                blow_off_damping_nspm: 1e9,
            }),
            ..MaxwellParams::default()
        };
        assert!(MaxwellDamper::new(bad)
            .unwrap_err()
            .to_string()
            .contains("blow_off_damping_nspm"));
    }

    #[test]
    fn blow_off_law_is_continuous_and_inverts() {
        let damper = MaxwellDamper::new(MaxwellParams {
            blow_off: Some(BlowOff {
                knee_velocity_mps: 0.02,
                blow_off_damping_nspm: 40e3,
            }),
            ..MaxwellParams::default()
        })
        .unwrap();
        // Knee force 800e3·0.02 = 16 kN; at 0.05 m/s: 16 kN + 40e3·0.03 = 17.2 kN.
        assert!((damper.damper_force(0.02) - 16e3).abs() < 1e-9);
        assert!((damper.damper_force(-0.05) + 17.2e3).abs() < 1e-9);
        for v in [-0.3, -0.02, -0.001, 0.0, 0.01, 0.0201, 0.5] {
            let back = damper.damper_velocity(damper.damper_force(v));
            assert!((back - v).abs() < 1e-12, "{v} -> {back}");
        }
    }
}
