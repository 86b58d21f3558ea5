//! The vehicle's frequency response to track irregularities: complex transfer functions from each
//! irregularity channel (vertical profile, alignment, cross level, gauge) to any recorded channel.
//!
//! Input convention: a channel `u(s) = Re(U e^{iks})` along the track (m; k = 2πf/V rad/m at
//! frequency f Hz and speed V m/s). Wheelset w, `x_w` m ahead of the vehicle origin, meets at
//! time t the track at `s = V t + x_w`, so it sees `U e^{ik x_w} e^{iωt}`: the trailing wheelsets
//! see the leading one's input delayed by `(x_1 − x_w)/V`. Its rails move by
//! [`Channel::rails`]` · u` and their slopes by `ik` times that. The transfer function is the
//! complex amplitude of the output per unit complex amplitude of `U` **at the vehicle origin**
//! (x = 0), in output unit per m: `z(t) = Re(H U e^{iωt})`.
//!
//! Method: `H(f) = C (iωI − A)⁻¹ B u(f) + D u(f)` with the matrices of
//! [`crate::vehicle::analysis::track_input`], solved in the Hessenberg basis of A ([`crate::vehicle::analysis::shifted_hessenberg`]):
//! O(n³) once, O(n²) per frequency. The response is that of the linear model; it describes the
//! steady state of the running vehicle only where A is stable (see [`crate::vehicle::analysis::linearise`]).

use crate::error::{check_cancel, LocoError, Result};
use crate::track::Channel;
use crate::vehicle::analysis::shifted_hessenberg::{ShiftedHessenberg, C64};
use crate::vehicle::analysis::track_input::{TrackInputModel, RAIL_INPUTS};
use crate::vehicle::model::layout::N_WHEELSETS;
use nalgebra::DMatrix;
use std::f64::consts::PI;
use std::sync::atomic::AtomicBool;

/// Transfer functions `H[output][input](f)`, output unit per m of irregularity.
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencyResponse {
    /// Frequencies, Hz.
    pub frequencies: Vec<f64>,
    /// Input channels.
    pub inputs: Vec<Channel>,
    /// Output channel names.
    pub outputs: Vec<String>,
    /// `h[(o · inputs + i) · frequencies + f]`.
    pub h: Vec<C64>,
    /// Running speed, m/s.
    pub speed: f64,
    /// Longitudinal position of each wheelset ahead of the vehicle origin, m (the delays).
    pub wheelset_x: [f64; N_WHEELSETS],
}

impl FrequencyResponse {
    /// H of output `o`, input `i` at frequency index `f`.
    pub fn at(&self, o: usize, i: usize, f: usize) -> C64 {
        self.h[(o * self.inputs.len() + i) * self.frequencies.len() + f]
    }
}

/// The input and output matrices of one channel and wheelset in the reduced basis.
#[derive(Debug, Clone)]
struct ChannelColumns {
    /// Qᵀ B · rails (positions) and Qᵀ B · rails (slopes), length n.
    position: Vec<f64>,
    slope: Vec<f64>,
    /// D · rails for the selected outputs (positions, slopes).
    d_position: Vec<f64>,
    d_slope: Vec<f64>,
}

/// A linear model prepared for frequency responses to a set of outputs.
#[derive(Debug, Clone)]
pub struct ResponseSolver {
    hessenberg: ShiftedHessenberg,
    /// C Q for the selected outputs, row-major m×n.
    cq: Vec<f64>,
    /// `columns[channel][wheelset]`.
    columns: Vec<Vec<ChannelColumns>>,
    outputs: Vec<String>,
    wheelset_x: [f64; N_WHEELSETS],
    speed: f64,
}

/// Most frequencies of one response: each costs about 0.5 ms (one Hessenberg solve per
/// frequency, measured on the default vehicle), so 10⁵ are under a minute, and they already
/// resolve 0–100 Hz every 1 mHz, finer than the half-power width of any mode damped above
/// 0.01 % at 1 Hz; more is a mistake (a grid in mHz meant as Hz, ...).
pub const MAX_FREQUENCIES: usize = 100_000;

/// Highest frequency of a response, Hz. The model's bodies are rigid: its first flexible modes
/// (a wheelset's first bending, a bogie frame's first torsion) lie near 50–100 Hz, and the track
/// spectra's shortest wavelength (1 m) is passed at 111 Hz at the model's top speed (400 km/h);
/// 1 kHz leaves a decade above both.
pub const MAX_FREQUENCY: f64 = 1_000.0;

/// Checks frequencies: 1 to [`MAX_FREQUENCIES`] of them, every one finite, positive and at
/// most [`MAX_FREQUENCY`] (Hz).
pub fn check_frequencies(frequencies: &[f64]) -> Result<()> {
    if frequencies.is_empty() {
        return Err(LocoError::param("frequencies", "must not be empty"));
    }
    if frequencies.len() > MAX_FREQUENCIES {
        return Err(LocoError::param(
            "frequencies",
            format!(
                "{} frequencies; at most {MAX_FREQUENCIES} (each costs about 0.5 ms, and \
                 {MAX_FREQUENCIES} resolve 0–100 Hz every 1 mHz)",
                frequencies.len()
            ),
        ));
    }
    match frequencies
        .iter()
        .position(|f| !(f.is_finite() && *f > 0.0 && *f <= MAX_FREQUENCY))
    {
        Some(i) => Err(LocoError::param(
            format!("frequencies[{i}]"),
            format!(
                "must be finite, positive and at most {MAX_FREQUENCY} Hz (the rigid-body \
                 model's range), got {}",
                frequencies[i]
            ),
        )),
        None => Ok(()),
    }
}

/// Indices of the named outputs among the model's channels; an unknown name is an error
/// naming it and the list of channels.
pub fn output_indices(model: &TrackInputModel, outputs: &[String]) -> Result<Vec<usize>> {
    if outputs.is_empty() {
        return Err(LocoError::param("outputs", "must not be empty"));
    }
    outputs
        .iter()
        .map(|name| {
            model.outputs.iter().position(|o| o == name).ok_or_else(|| {
                LocoError::param(
                    "outputs",
                    format!(
                        "unknown channel `{name}`; the model records: {}",
                        model.outputs.join(", ")
                    ),
                )
            })
        })
        .collect()
}

impl ResponseSolver {
    /// Prepares `model` for the named outputs (errors name an unknown channel).
    pub fn new(model: &TrackInputModel, outputs: &[String]) -> Result<Self> {
        let rows = output_indices(model, outputs)?;
        let n = model.n;
        let p = model.n_inputs;
        let hessenberg = ShiftedHessenberg::new(&model.a, n);
        let q = hessenberg.basis();
        let b = DMatrix::from_row_slice(n, p, &model.b);
        let qtb = q.transpose() * b;
        let c_sel = DMatrix::from_fn(rows.len(), n, |i, j| model.c[rows[i] * n + j]);
        let cq_matrix = c_sel * q;
        let cq = (0..rows.len())
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .map(|(i, j)| cq_matrix[(i, j)])
            .collect();
        let columns = Channel::ALL
            .iter()
            .map(|channel| {
                let rails = channel.rails();
                (0..N_WHEELSETS)
                    .map(|w| {
                        let col = |k: usize| w * RAIL_INPUTS + k;
                        let reduced = |offset: usize| -> Vec<f64> {
                            (0..n)
                                .map(|i| (0..4).map(|k| qtb[(i, col(offset + k))] * rails[k]).sum())
                                .collect()
                        };
                        let feed = |offset: usize| -> Vec<f64> {
                            rows.iter()
                                .map(|&r| {
                                    (0..4)
                                        .map(|k| model.d[r * p + col(offset + k)] * rails[k])
                                        .sum()
                                })
                                .collect()
                        };
                        ChannelColumns {
                            position: reduced(0),
                            slope: reduced(4),
                            d_position: feed(0),
                            d_slope: feed(4),
                        }
                    })
                    .collect()
            })
            .collect();
        Ok(Self {
            hessenberg,
            cq,
            columns,
            outputs: outputs.to_vec(),
            wheelset_x: model.wheelset_x,
            speed: model.speed,
        })
    }

    /// Transfer functions from `inputs` to the prepared outputs at `frequencies` (Hz).
    pub fn response(
        &mut self,
        inputs: &[Channel],
        frequencies: &[f64],
    ) -> Result<FrequencyResponse> {
        self.response_cancellable(inputs, frequencies, None)
    }

    /// As [`Self::response`]; `cancel`, when set from another thread, stops it with
    /// `Interrupted` before the next frequency.
    pub fn response_cancellable(
        &mut self,
        inputs: &[Channel],
        frequencies: &[f64],
        cancel: Option<&AtomicBool>,
    ) -> Result<FrequencyResponse> {
        check_frequencies(frequencies)?;
        if inputs.is_empty() {
            return Err(LocoError::param("inputs", "must not be empty"));
        }
        let n = self.hessenberg.len();
        let (m, r, nf) = (self.outputs.len(), inputs.len(), frequencies.len());
        let mut h = vec![C64::new(0.0, 0.0); m * r * nf];
        let mut rhs = vec![vec![C64::new(0.0, 0.0); n]; r];
        let mut feed = vec![vec![C64::new(0.0, 0.0); m]; r];
        for (fi, &f) in frequencies.iter().enumerate() {
            check_cancel(cancel)?;
            let omega = 2.0 * PI * f;
            let k = omega / self.speed;
            for (ii, channel) in inputs.iter().enumerate() {
                rhs[ii].fill(C64::new(0.0, 0.0));
                feed[ii].fill(C64::new(0.0, 0.0));
                for (w, cols) in self.columns[channel.index()].iter().enumerate() {
                    // e^{ik x_w} times (position + ik · slope).
                    let delay = C64::from_polar(1.0, k * self.wheelset_x[w]);
                    let (pos, slope) = (delay, delay * C64::new(0.0, k));
                    let reduced = cols.position.iter().zip(&cols.slope);
                    for (x, (p, d)) in rhs[ii].iter_mut().zip(reduced) {
                        *x += pos * *p + slope * *d;
                    }
                    let direct = cols.d_position.iter().zip(&cols.d_slope);
                    for (x, (p, d)) in feed[ii].iter_mut().zip(direct) {
                        *x += pos * *p + slope * *d;
                    }
                }
            }
            self.hessenberg
                .solve_shifted(C64::new(0.0, omega), &mut rhs)?;
            for o in 0..m {
                let row = &self.cq[o * n..(o + 1) * n];
                for ii in 0..r {
                    let z: C64 = row.iter().zip(&rhs[ii]).map(|(c, x)| x * *c).sum();
                    h[(o * r + ii) * nf + fi] = z + feed[ii][o];
                }
            }
        }
        Ok(FrequencyResponse {
            frequencies: frequencies.to_vec(),
            inputs: inputs.to_vec(),
            outputs: self.outputs.clone(),
            h,
            speed: self.speed,
            wheelset_x: self.wheelset_x,
        })
    }
}

/// Transfer functions of a vehicle (parameter set or built structure) in a scenario from `inputs` to `outputs`
/// (recorded channel names) at `frequencies` (Hz): linearisation, reduction and solves.
pub fn frequency_response(
    vehicle: impl crate::vehicle::model::structure::IntoVehicle,
    scenario: &crate::vehicle::scenarios::scenario::Scenario,
    inputs: &[Channel],
    outputs: &[String],
    frequencies: &[f64],
) -> Result<FrequencyResponse> {
    check_frequencies(frequencies)?;
    if inputs.is_empty() {
        return Err(LocoError::param("inputs", "must not be empty"));
    }
    let model = crate::vehicle::analysis::track_input::scenario_track_model(vehicle, scenario)?;
    ResponseSolver::new(&model, outputs)?.response(inputs, frequencies)
}
