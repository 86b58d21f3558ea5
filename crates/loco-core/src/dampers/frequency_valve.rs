//! The FSD's frequency valve as a hydraulic mechanism (trigger `"hydraulic"`): an auxiliary
//! chamber filled through a constant orifice by the pressure across the main piston, whose
//! spring-returned piston opens the bypass when it passes its opening stroke.
//!
//! # Model
//! - Pressure difference across the main piston `Δp = F/A_p` (Pa; F the damper force, N, A_p the
//!   main piston area, m²).
//! - A double-acting auxiliary piston (area `A_a`, m²) between two chambers, centred by a return
//!   spring `k_s` (N/m); one constant orifice (area `A_o`, m²) connects it to the two sides of the
//!   main piston. Its displaced volume `V = A_a·y` (m³, y the auxiliary piston's travel) follows
//!   `dV/dt = Q(Δp - s·V)` with the spring's back pressure per volume `s = k_s/A_a²` (Pa/m³) and
//!   the orifice law of [`super::hydraulic`] (laminar in series with turbulent, Merritt 1967):
//!   `p = Q/K_lam + ρ/(2·C_d²·A_o²)·Q·|Q|`, inverted in closed form.
//! - The bypass is commanded open while `|V| ≥ V_o = A_a·y_o` (y_o the opening stroke, m); the
//!   FSD's scale factor then moves toward it at `1/switching_delay` (the spec's 0.05 s), as with
//!   the rms-frequency trigger ([`super::fsd`]). The low/high damping modules with the spec's
//!   equivalent mass and stiffness are those of [`super::fsd`].
//! - Per accepted step of `dt` (s) the volume is advanced by implicit Euler with the force at the
//!   end of the step (`Q` at the new volume): one closed-form root, unconditionally stable.
//!
//! Why it selects frequency: through a turbulent orifice `Q ∝ √Δp`. For a sine stroke of
//! amplitude X at ω with the valve closed, `Δp = P·sin ωt` with `P = X·|Z₂(ω)|/A_p` (`Z₂` the
//! complex stiffness of the closed module, `|Z₂| ≈ c2·ω` below the series spring's corner). A
//! half-cycle passes `V_½ = C_d·A_o·√(2P/ρ)·I/ω`, `I = ∫₀^π √sin θ dθ = 2.39628`, so
//! `V_½ ∝ √(X/ω)`: a slow stroke fills the chamber, a fast one reverses first. With no spring the
//! piston swings ±V_½/2 about its centre. The spring sets a pressure threshold
//! `p_o = k_s·y_o/A_a`: below it the piston cannot be held at its opening stroke however slowly
//! the stroke moves, so very slow, small strokes (drift) keep the valve closed. A small fast
//! dither on a slow stroke adds flow back and forth that nearly cancels over its cycles; only a
//! dither whose pressure reverses the flow in every cycle starves the slow filling (by about
//! `√(P_slow/P_dither)` for a dither much larger than the slow pressure).
//!
//! # Derivation of the parameters (amplitude X_r, cut-off f_p)
//! The cut-off `f_c(X)` is the frequency of a sine stroke of amplitude X above which the steady
//! (antisymmetric, periodic) orbit of V with the valve closed stays inside `±V_o`. Given the
//! geometry (A_p, A_a, y_o), the oil and the closed module (c2, k, m):
//! 1. `P(ω, X) = X·|k·(iωc2 - mω²)/(k - mω² + iωc2)|/A_p`.
//! 2. Spring: once open, the low-damping module (c1) makes the pressure, `P₁(ω, X)` as in 1.
//!    with c1. The valve must then stay open: the c1 pressure must hold the piston at its
//!    opening stroke against the spring, `P₁ ≥ p_o`. The spring is sized so that this holds at
//!    the reference amplitude down to the lowest holding frequency f_l, `p_o = P₁(2πf_l, X_r)`,
//!    so `k_s = A_a·P₁(2πf_l, X_r)/y_o`. Default `f_l = f_p/4` = 0.5 Hz, the rms-frequency
//!    trigger's high-pass corner, which it sets for the same reason (ignore slow drift). (Sized
//!    on the closed module instead, the open valve at 1.2 Hz could not hold itself open: the
//!    pressure falls by c2/c1 = 4 when it opens.) From closed, quasi-statically, the valve then
//!    opens down to about `f_l·c1/c2` at X_r.
//! 3. Orifice: `f_c(X_r) = f_p`. Turbulent estimate without spring: the orbit reaches V_o when
//!    `V_½ = 2·V_o`, `A_o ≈ 2·V_o·ω_p/(C_d·I·√(2P/ρ))`; with the spring and the laminar term the
//!    orbit is solved by shooting over half a period (RK4, [`ORBIT_STEPS`] steps) and `A_o` by
//!    bisection around that estimate.
//! 4. A cut-off the derivation cannot reach (`f_l ≥ f_p`; `p_o ≥ P(ω_p, X_r)`, where the spring
//!    alone would hold the valve closed at f_p; no orifice in the bracket) is refused naming the
//!    field.
//!
//! Amplitude dependence: `V_½ ∝ √(X·|Z₂|)/ω`, so with `|Z₂| ≈ c2·ω` the cut-off grows in
//! proportion to the amplitude (twice the stroke, twice f_c); the series spring (corner
//! k/c2 = 3 Hz) slows that growth at high frequency, and the spring threshold raises the lower
//! limit f_l at small amplitudes. [`HydraulicValve::opening_band_hz`] gives both.
//!
//! # The derived valve at X_r = 0.26 mm (spec FSD modules)
//! Orifice 0.73 mm² (Ø0.96 mm), spring 19.6 kN/m (opening pressure 0.083 MPa). Opening band
//! (sine strokes, closed orbit, [`HydraulicValve::opening_band_hz`]): 0.13–2.0 Hz at 0.26 mm,
//! 0.35–0.80 Hz at 0.1 mm, 0.065–3.2 Hz at 0.5 mm, none up to 0.08 mm. Below its cut-off the
//! valve opens late in each stroke and closes near the reversal (the piston must swing back past
//! the other opening stroke with the valve closed): the force shows c2 "teeth" at every reversal
//! and the valve is open about 35 % of the time at 1.2 Hz, 0.26 mm (the damper bench stage). A
//! valve that times each half-cycle cannot stay open across reversals as the rms-frequency
//! estimate does; in exchange a dither barely moves it (bench, `valve_bench.py`).
//!
//! # Geometry (not in the spec; no published dimensions of such a valve were found)
//! Main piston Ø50 mm (the yaw damper bore of [`super::hydraulic`]). The auxiliary piston and
//! chamber sit in a housing on the piston rod below the main piston, inside the bore, as in the
//! frequency-dependent valves of Tenneco US 6 918 473 ("Stroke dependent bypass", 2005) and
//! WO 2019/182863 A1 (floating piston between two accumulation chambers with a bleed channel):
//! estimate Ø30 mm auxiliary piston (a 10 mm housing wall in the Ø50 mm bore) and 3 mm opening
//! stroke (V_o = 2.1 cm³). Oil ISO VG 32 (ρ = 870 kg/m³, ν = 32 mm²/s) and C_d = 0.61 as in
//! [`super::hydraulic`].

use super::damping_module::ClosedModule;
use crate::error::{check_positive, Result};
use rayon::prelude::*;
use std::f64::consts::{PI, TAU};

/// `∫₀^π √(sin θ) dθ` (the turbulent half-cycle filling integral).
pub const SQRT_SINE_INTEGRAL: f64 = 2.396_280_469_471_184;
/// RK4 steps per half period of the orbit solver.
pub const ORBIT_STEPS: usize = 400;
/// Laminar flow coefficient δ of a sharp-edged orifice (Merritt 1967), as in the orifice damper.
const LAMINAR_FLOW_COEFFICIENT: f64 = 0.2;

/// The yaw damper stroke amplitude of the S_low carbody sway (m), measured by
/// `experiments/fsd_reference_stroke.py` (S_low, 200 km/h, YD1, cn-hsr seed 0, 0.5–2 Hz band,
/// median of the four yaw dampers) with the rails rolled with the track: 0.261 mm (the dampers
/// gave 0.316, 0.355, 0.195 and 0.207 mm), here to 0.01 mm.
pub const REFERENCE_STROKE_AMPLITUDE_M: f64 = 0.26e-3;

/// Physical parameters of the valve (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicValveParams {
    /// Main piston area A_p on which the damper force makes the pressure (m²), > 0.
    pub piston_area_m2: f64,
    /// Constant orifice area A_o (m²), > 0.
    pub orifice_area_m2: f64,
    /// Discharge coefficient C_d of the orifice, > 0.
    pub flow_coefficient: f64,
    /// Oil density ρ (kg/m³), > 0.
    pub oil_density_kgpm3: f64,
    /// Oil kinematic viscosity ν (m²/s), > 0.
    pub oil_kinematic_viscosity_m2ps: f64,
    /// Auxiliary piston area A_a (m²), > 0.
    pub aux_piston_area_m2: f64,
    /// Travel of the auxiliary piston at which the bypass opens, y_o (m), > 0.
    pub opening_stroke_m: f64,
    /// Return spring stiffness k_s (N/m), > 0.
    pub spring_stiffness_npm: f64,
}

fn circle_area(diameter_m: f64) -> f64 {
    PI / 4.0 * diameter_m * diameter_m
}

impl HydraulicValveParams {
    /// The documented geometry (module documentation); orifice and spring are placeholders that
    /// [`ValveDesign::derive`] replaces.
    pub fn default_geometry() -> Self {
        Self {
            piston_area_m2: circle_area(0.050),
            orifice_area_m2: circle_area(0.5e-3),
            flow_coefficient: 0.61,
            oil_density_kgpm3: 870.0,
            oil_kinematic_viscosity_m2ps: 32e-6,
            aux_piston_area_m2: circle_area(0.030),
            opening_stroke_m: 3e-3,
            spring_stiffness_npm: 1e4,
        }
    }
}

/// A validated valve with its orifice law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HydraulicValve {
    params: HydraulicValveParams,
    /// Laminar resistance 1/K_lam (Pa·s/m³).
    laminar: f64,
    /// Turbulent coefficient ρ/(2·C_d²·A_o²) (Pa·s²/m⁶).
    turbulent: f64,
    /// Spring back pressure per displaced volume k_s/A_a² (Pa/m³).
    spring_per_volume: f64,
    /// Displaced volume at the opening stroke A_a·y_o (m³).
    opening_volume_m3: f64,
}

impl HydraulicValve {
    /// Validates every field (finite, > 0), naming it.
    pub fn new(params: HydraulicValveParams) -> Result<Self> {
        let p = params;
        check_positive("valve_piston_area_m2", p.piston_area_m2)?;
        check_positive("orifice_area_m2", p.orifice_area_m2)?;
        check_positive("valve_flow_coefficient", p.flow_coefficient)?;
        check_positive("valve_oil_density_kgpm3", p.oil_density_kgpm3)?;
        check_positive(
            "valve_oil_kinematic_viscosity_m2ps",
            p.oil_kinematic_viscosity_m2ps,
        )?;
        check_positive("aux_piston_area_m2", p.aux_piston_area_m2)?;
        check_positive("opening_stroke_m", p.opening_stroke_m)?;
        check_positive("spring_stiffness_npm", p.spring_stiffness_npm)?;
        let hydraulic_diameter = (4.0 * p.orifice_area_m2 / PI).sqrt();
        let viscosity = p.oil_density_kgpm3 * p.oil_kinematic_viscosity_m2ps;
        let conductance = 2.0
            * LAMINAR_FLOW_COEFFICIENT
            * LAMINAR_FLOW_COEFFICIENT
            * hydraulic_diameter
            * p.orifice_area_m2
            / viscosity;
        let cd_area = p.flow_coefficient * p.orifice_area_m2;
        Ok(Self {
            params,
            laminar: 1.0 / conductance,
            turbulent: p.oil_density_kgpm3 / (2.0 * cd_area * cd_area),
            spring_per_volume: p.spring_stiffness_npm
                / (p.aux_piston_area_m2 * p.aux_piston_area_m2),
            opening_volume_m3: p.aux_piston_area_m2 * p.opening_stroke_m,
        })
    }

    /// The validated parameters.
    pub fn params(&self) -> &HydraulicValveParams {
        &self.params
    }

    /// Displaced volume at the opening stroke, V_o (m³).
    pub fn opening_volume_m3(&self) -> f64 {
        self.opening_volume_m3
    }

    /// Spring pressure at the opening stroke, p_o (Pa).
    pub fn opening_pressure_pa(&self) -> f64 {
        self.spring_per_volume * self.opening_volume_m3
    }

    /// Flow (m³/s) through a resistance `r` (Pa·s/m³) in series with the turbulent orifice, for
    /// the pressure `p` (Pa): root of `t·Q|Q| + r·Q = p` without cancellation.
    #[inline]
    fn flow_through(&self, resistance: f64, pressure_pa: f64) -> f64 {
        let magnitude = 2.0 * pressure_pa.abs()
            / (resistance
                + (resistance * resistance + 4.0 * self.turbulent * pressure_pa.abs()).sqrt());
        magnitude.copysign(pressure_pa)
    }

    /// Rate of the displaced volume (m³/s) at volume `v` (m³) and main-piston pressure `p` (Pa).
    #[inline]
    pub fn volume_rate(&self, volume_m3: f64, pressure_pa: f64) -> f64 {
        self.flow_through(
            self.laminar,
            pressure_pa - self.spring_per_volume * volume_m3,
        )
    }

    /// The volume after an accepted step of `dt` (s) from `volume` (m³) with the damper force
    /// `force` (N) at the step's end: implicit Euler, `Q` taken at the new volume.
    #[inline]
    pub fn step(&self, volume_m3: f64, force_n: f64, dt_s: f64) -> f64 {
        let net = force_n / self.params.piston_area_m2 - self.spring_per_volume * volume_m3;
        // p0 = Q·(r + s·dt) + t·Q|Q|
        let q = self.flow_through(self.laminar + self.spring_per_volume * dt_s, net);
        volume_m3 + dt_s * q
    }

    /// Whether the auxiliary piston is at or past its opening stroke (bypass open).
    #[inline]
    pub fn is_open(&self, volume_m3: f64) -> bool {
        volume_m3.abs() >= self.opening_volume_m3
    }

    /// Peak |V| (m³) of the antisymmetric periodic orbit under `p = P·sin ωt` (P in Pa, ω in
    /// rad/s), by shooting over half a period (RK4, [`ORBIT_STEPS`] steps).
    pub fn orbit_peak_volume(&self, pressure_amplitude_pa: f64, omega: f64) -> f64 {
        let bound = pressure_amplitude_pa / self.spring_per_volume;
        let half = |v0: f64, peak: &mut f64| {
            let dt = PI / omega / ORBIT_STEPS as f64;
            let mut v = v0;
            *peak = v0.abs();
            for i in 0..ORBIT_STEPS {
                let t = i as f64 * dt;
                let p = |t: f64| pressure_amplitude_pa * (omega * t).sin();
                let k1 = self.volume_rate(v, p(t));
                let k2 = self.volume_rate(v + 0.5 * dt * k1, p(t + 0.5 * dt));
                let k3 = self.volume_rate(v + 0.5 * dt * k2, p(t + 0.5 * dt));
                let k4 = self.volume_rate(v + dt * k3, p(t + dt));
                v += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
                *peak = peak.max(v.abs());
            }
            v
        };
        // g(v0) = V(T/2; v0) + v0 rises through 0 on [-bound, bound].
        let (mut lo, mut hi) = (-bound, bound);
        let mut peak = 0.0;
        for _ in 0..50 {
            let mid = 0.5 * (lo + hi);
            if half(mid, &mut peak) + mid < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        half(0.5 * (lo + hi), &mut peak);
        peak
    }

    /// The frequencies (Hz) between which a steady sine stroke of amplitude `x` (m) opens the
    /// valve (closed module `closed`), searched in [0.05, 50] Hz; `None` when it opens nowhere.
    pub fn opening_band_hz(&self, closed: &ClosedModule, x: f64) -> Option<(f64, f64)> {
        let opens = |f: f64| {
            let p = closed.force_amplitude(TAU * f, x) / self.params.piston_area_m2;
            self.orbit_peak_volume(p, TAU * f) >= self.opening_volume_m3
        };
        let grid: Vec<f64> = (0..=60)
            .map(|i| 0.05 * 1000f64.powf(i as f64 / 60.0))
            .collect();
        let open: Vec<bool> = grid.iter().map(|&f| opens(f)).collect();
        let first = open.iter().position(|&o| o)?;
        let last = open.iter().rposition(|&o| o)?;
        let edge = |mut inside: f64, mut outside: f64| {
            for _ in 0..40 {
                let mid = (inside * outside).sqrt();
                if opens(mid) {
                    inside = mid;
                } else {
                    outside = mid;
                }
            }
            (inside * outside).sqrt()
        };
        let lower = if first == 0 {
            grid[0]
        } else {
            edge(grid[first], grid[first - 1])
        };
        let upper = if last + 1 == grid.len() {
            grid[last]
        } else {
            edge(grid[last], grid[last + 1])
        };
        Some((lower, upper))
    }

    /// [`Self::opening_band_hz`] for each amplitude of `amplitudes` (m, each > 0; an error names
    /// `amplitudes` otherwise), in order, the amplitudes on rayon's threads (each band is its own
    /// search, so the bands do not depend on them).
    pub fn opening_bands_hz(
        &self,
        closed: &ClosedModule,
        amplitudes: &[f64],
    ) -> Result<Vec<Option<(f64, f64)>>> {
        for &x in amplitudes {
            check_positive("amplitudes", x)?;
        }
        Ok(amplitudes
            .par_iter()
            .map(|&x| self.opening_band_hz(closed, x))
            .collect())
    }
}

#[cfg(test)]
mod tests;
