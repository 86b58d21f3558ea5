//! Target power spectral densities of track irregularities.
//!
//! Every spectrum here is returned **one-sided over spatial frequency f (1/m)** in SI units,
//! m²/(1/m), so that the variance of an irregularity over a band is `∫ S(f) df`.
//!
//! Sources:
//! - [`TrackSpectrum::CnHsr`]: TB/T 3352-2014, "PSD of ballastless track irregularities of
//!   high-speed railway" (China), also published by Kang Xiong, Liu Xiubo, Li Hongyan et al.,
//!   Scientia Sinica Technologica 44(7), 2014. Piecewise power law `S(f) = A / fⁿ` in
//!   mm²/(1/m), f in 1/m, valid for wavelengths 2–200 m. The coefficient table is checked for
//!   continuity at its breakpoints in the tests (a transcription error would break it).
//! - [`TrackSpectrum::GermanLow`] / [`TrackSpectrum::GermanHigh`]: the German high-speed
//!   track spectra (low and high interference) as used throughout vehicle dynamics
//!   (e.g. Zhai, *Vehicle–Track Coupled Dynamics*, Springer 2020, ch. 3):
//!   `Sv = Av·Ωc²/((Ω²+Ωr²)(Ω²+Ωc²))`, `Sa = Aa·Ωc²/((Ω²+Ωr²)(Ω²+Ωc²))`,
//!   `Sc = (Av/b²)·Ωc²Ω²/((Ω²+Ωr²)(Ω²+Ωc²)(Ω²+Ωs²))`, `Sg = Ag·Ωc²Ω²/((Ω²+Ωr²)(Ω²+Ωc²)(Ω²+Ωs²))`
//!   in m²/(rad/m) with Ω in rad/m, Ωc = 0.8246, Ωr = 0.0206, Ωs = 0.4380 rad/m, b = 0.75 m.
//!   Conventions we adopt (the usual reading, stated because the sources are terse): the
//!   spectra are one-sided in Ω, so `S(f) = 2π·S(Ω = 2πf)`; `Sc` is the spectrum of the
//!   cross-level *angle* (rad) over the rail spacing 2b, so the height difference between the
//!   rails has `S = (2b)²·Sc`.

use crate::error::{LocoError, Result};

/// The four irregularities a track spectrum describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Channel {
    /// Vertical profile (longitudinal level): mean height of the two rails, m, + up.
    Vertical,
    /// Alignment: mean lateral position of the two rails, m, + left.
    Alignment,
    /// Cross level: height of the left rail minus the right rail, m.
    CrossLevel,
    /// Gauge deviation: gauge minus nominal gauge, m (+ wider).
    Gauge,
}

impl Channel {
    /// All four channels in storage order.
    pub const ALL: [Channel; 4] = [
        Channel::Vertical,
        Channel::Alignment,
        Channel::CrossLevel,
        Channel::Gauge,
    ];

    /// Snake-case name used in files, Python and error messages.
    pub fn name(self) -> &'static str {
        match self {
            Channel::Vertical => "vertical",
            Channel::Alignment => "alignment",
            Channel::CrossLevel => "cross_level",
            Channel::Gauge => "gauge",
        }
    }

    /// Parses a channel name as given by [`Channel::name`].
    pub fn from_name(name: &str) -> Result<Self> {
        Channel::ALL
            .into_iter()
            .find(|c| c.name() == name)
            .ok_or_else(|| {
                LocoError::param(
                    "channel",
                    format!("unknown channel `{name}` (vertical, alignment, cross_level, gauge)"),
                )
            })
    }

    /// Index in [`Channel::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// How a unit value of the channel moves the rails, as (y_left, z_left, y_right, z_right)
    /// (m per m): `z_left = v + c/2`, `z_right = v − c/2`, `y_left = a + g/2`,
    /// `y_right = a − g/2` (cross level c is left minus right height; gauge widening g moves each
    /// rail outward by g/2, y being + left). The one definition: the track's rails are built from
    /// it and the frequency response feeds it to the linear model.
    pub fn rails(self) -> [f64; 4] {
        match self {
            Channel::Vertical => [0.0, 1.0, 0.0, 1.0],
            Channel::Alignment => [1.0, 0.0, 1.0, 0.0],
            Channel::CrossLevel => [0.0, 0.5, 0.0, -0.5],
            Channel::Gauge => [0.5, 0.0, -0.5, 0.0],
        }
    }
}

/// A piecewise power law `S(f) = A_i / f^{n_i}` for `f` in `[breaks[i-1], breaks[i])`, in
/// mm²/(1/m) with f in 1/m (the units of TB/T 3352-2014).
struct PowerLaw {
    /// Breakpoints between segments, 1/m (one fewer than segments).
    breaks: &'static [f64],
    /// Coefficients A, mm²/(1/m)·(1/m)ⁿ.
    a: &'static [f64],
    /// Exponents n.
    n: &'static [f64],
}

impl PowerLaw {
    /// Value in mm²/(1/m).
    fn eval_mm2(&self, f: f64) -> f64 {
        let i = self.breaks.iter().take_while(|&&b| f >= b).count();
        self.a[i] / f.powf(self.n[i])
    }
}

/// TB/T 3352-2014 coefficients (ballastless track, high-speed lines).
const CN_VERTICAL: PowerLaw = PowerLaw {
    breaks: &[0.0187, 0.0474, 0.1533],
    a: &[1.0544e-5, 3.5588e-3, 1.9784e-2, 3.9488e-4],
    n: &[3.3891, 1.9271, 1.3643, 3.4516],
};
const CN_ALIGNMENT: PowerLaw = PowerLaw {
    breaks: &[0.0450, 0.1234],
    a: &[3.9513e-3, 1.1047e-2, 7.5633e-4],
    n: &[1.8670, 1.5354, 2.8171],
};
const CN_CROSS_LEVEL: PowerLaw = PowerLaw {
    breaks: &[0.0258, 0.1163],
    a: &[3.6148e-3, 4.3685e-2, 4.5867e-3],
    n: &[1.7278, 1.0461, 2.0939],
};
const CN_GAUGE: PowerLaw = PowerLaw {
    breaks: &[0.1090, 0.2938],
    a: &[5.4978e-2, 5.0701e-3, 1.8778e-4],
    n: &[0.8282, 1.9037, 4.5948],
};

/// Parameters of a German track spectrum.
struct German {
    /// Vertical roughness coefficient Av, m·rad.
    av: f64,
    /// Alignment roughness coefficient Aa, m·rad.
    aa: f64,
    /// Gauge roughness coefficient Ag, m·rad.
    ag: f64,
}

const GERMAN_LOW: German = German {
    av: 4.032e-7,
    aa: 2.119e-7,
    ag: 5.32e-8,
};
const GERMAN_HIGH: German = German {
    av: 1.080e-6,
    aa: 6.125e-7,
    ag: 1.032e-7,
};
/// Cut-off wavenumbers of the German spectra, rad/m.
const OMEGA_C: f64 = 0.8246;
const OMEGA_R: f64 = 0.0206;
const OMEGA_S: f64 = 0.4380;
/// Half the distance between the rolling circles used by the German cross-level spectrum, m.
const HALF_SPACING_B: f64 = 0.75;

impl German {
    /// One-sided PSD in m²/(1/m) at spatial frequency `f` (1/m).
    fn eval(&self, channel: Channel, f: f64) -> f64 {
        let w = 2.0 * std::f64::consts::PI * f;
        let w2 = w * w;
        let base = OMEGA_C * OMEGA_C / ((w2 + OMEGA_R * OMEGA_R) * (w2 + OMEGA_C * OMEGA_C));
        let high_pass = w2 / (w2 + OMEGA_S * OMEGA_S);
        let per_rad = match channel {
            Channel::Vertical => self.av * base,
            Channel::Alignment => self.aa * base,
            // Angle spectrum (Av/b²) converted to the height difference over 2b.
            Channel::CrossLevel => {
                self.av / (HALF_SPACING_B * HALF_SPACING_B)
                    * base
                    * high_pass
                    * (2.0 * HALF_SPACING_B).powi(2)
            }
            Channel::Gauge => self.ag * base * high_pass,
        };
        2.0 * std::f64::consts::PI * per_rad
    }
}

/// A target spectrum for the four track irregularities.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TrackSpectrum {
    /// Chinese high-speed ballastless track, TB/T 3352-2014.
    CnHsr,
    /// German high-speed track, low interference.
    GermanLow,
    /// German high-speed track, high interference.
    GermanHigh,
}

impl TrackSpectrum {
    /// Name used in Python and files: `cn-hsr`, `german-low`, `german-high`.
    pub fn name(self) -> &'static str {
        match self {
            TrackSpectrum::CnHsr => "cn-hsr",
            TrackSpectrum::GermanLow => "german-low",
            TrackSpectrum::GermanHigh => "german-high",
        }
    }

    /// Parses a name as given by [`TrackSpectrum::name`].
    pub fn from_name(name: &str) -> Result<Self> {
        [Self::CnHsr, Self::GermanLow, Self::GermanHigh]
            .into_iter()
            .find(|s| s.name() == name)
            .ok_or_else(|| {
                LocoError::param(
                    "spectrum",
                    format!("unknown spectrum `{name}` (cn-hsr, german-low, german-high)"),
                )
            })
    }

    /// One-sided PSD of `channel` at spatial frequency `f` (1/m, > 0), in m²/(1/m).
    pub fn psd(self, channel: Channel, f: f64) -> f64 {
        if f <= 0.0 || !f.is_finite() {
            return 0.0;
        }
        match self {
            TrackSpectrum::CnHsr => {
                let law = match channel {
                    Channel::Vertical => &CN_VERTICAL,
                    Channel::Alignment => &CN_ALIGNMENT,
                    Channel::CrossLevel => &CN_CROSS_LEVEL,
                    Channel::Gauge => &CN_GAUGE,
                };
                law.eval_mm2(f) * 1e-6
            }
            TrackSpectrum::GermanLow => GERMAN_LOW.eval(channel, f),
            TrackSpectrum::GermanHigh => GERMAN_HIGH.eval(channel, f),
        }
    }

    /// Variance (m²) of `channel` between spatial frequencies `f_lo` and `f_hi` (1/m):
    /// `∫ S(f) df` by composite Simpson's rule in ln f (the spectra are smooth in ln f).
    pub fn variance(self, channel: Channel, f_lo: f64, f_hi: f64) -> f64 {
        self.variance_with(channel, f_lo, f_hi, 64)
    }

    /// [`Self::variance`] with `intervals` Simpson intervals per smooth piece (even).
    pub(crate) fn variance_with(
        self,
        channel: Channel,
        f_lo: f64,
        f_hi: f64,
        intervals: usize,
    ) -> f64 {
        if f_hi <= f_lo || f_lo <= 0.0 {
            return 0.0;
        }
        // The breakpoints make the integrand only piecewise smooth: integrate piece by piece.
        let mut edges = vec![f_lo];
        if self == TrackSpectrum::CnHsr {
            let law = match channel {
                Channel::Vertical => &CN_VERTICAL,
                Channel::Alignment => &CN_ALIGNMENT,
                Channel::CrossLevel => &CN_CROSS_LEVEL,
                Channel::Gauge => &CN_GAUGE,
            };
            edges.extend(law.breaks.iter().copied().filter(|&b| b > f_lo && b < f_hi));
        }
        edges.push(f_hi);
        edges
            .windows(2)
            .map(|w| simpson_log(|f| self.psd(channel, f), w[0], w[1], intervals))
            .sum()
    }
}

/// `∫_a^b g(f) df` by composite Simpson's rule on u = ln f (`g(f) df = g(e^u) e^u du`).
fn simpson_log(g: impl Fn(f64) -> f64, a: f64, b: f64, intervals: usize) -> f64 {
    let (ua, ub) = (a.ln(), b.ln());
    let h = (ub - ua) / intervals as f64;
    let term = |u: f64| {
        let f = u.exp();
        g(f) * f
    };
    let mut sum = term(ua) + term(ub);
    for i in 1..intervals {
        let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += weight * term(ua + i as f64 * h);
    }
    sum * h / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cn_table_is_continuous_at_breakpoints() {
        // The published fits join within about 1 %; a mistyped digit would not.
        for law in [&CN_VERTICAL, &CN_ALIGNMENT, &CN_CROSS_LEVEL, &CN_GAUGE] {
            for (i, &b) in law.breaks.iter().enumerate() {
                let left = law.a[i] / b.powf(law.n[i]);
                let right = law.a[i + 1] / b.powf(law.n[i + 1]);
                assert!(
                    (left / right - 1.0).abs() < 0.02,
                    "break {b}: {left} vs {right}"
                );
            }
        }
    }

    #[test]
    fn cn_vertical_band_variance_matches_closed_form() {
        // ∫ A f^-n df = A (f_b^(1-n) - f_a^(1-n)) / (1-n), piece by piece, in mm².
        let edges: [f64; 5] = [0.005, 0.0187, 0.0474, 0.1533, 0.5];
        let mut exact = 0.0;
        for i in 0..4 {
            let (a, n) = (CN_VERTICAL.a[i], CN_VERTICAL.n[i]);
            exact += a * (edges[i + 1].powf(1.0 - n) - edges[i].powf(1.0 - n)) / (1.0 - n);
        }
        let numeric = TrackSpectrum::CnHsr.variance(Channel::Vertical, 0.005, 0.5) * 1e6;
        // 64 Simpson intervals per piece: ~3e-6 relative error on the steepest piece.
        assert!((numeric / exact - 1.0).abs() < 1e-5, "{numeric} vs {exact}");
    }

    #[test]
    fn german_vertical_matches_hand_value() {
        // Ω = 2π·0.1 = 0.6283 rad/m: Av Ωc²/((Ω²+Ωr²)(Ω²+Ωc²)) = 4.032e-7·0.67996/
        // ((0.394784+0.000424)(0.394784+0.679965)) = 6.4547e-7 m²/(rad/m); ×2π = 4.0556e-6.
        let s = TrackSpectrum::GermanLow.psd(Channel::Vertical, 0.1);
        assert!((s / 4.0556e-6 - 1.0).abs() < 1e-4, "{s}");
    }

    #[test]
    fn names_round_trip() {
        for s in [
            TrackSpectrum::CnHsr,
            TrackSpectrum::GermanLow,
            TrackSpectrum::GermanHigh,
        ] {
            assert_eq!(TrackSpectrum::from_name(s.name()).unwrap(), s);
        }
        for c in Channel::ALL {
            assert_eq!(Channel::from_name(c.name()).unwrap(), c);
        }
        assert!(TrackSpectrum::from_name("us-class-6").is_err());
    }
}
