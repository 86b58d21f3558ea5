//! Running a batch: one simulation per row of the parameter matrix, in parallel with rayon on an
//! explicit number of threads.
//!
//! Determinism: every sample is a function of (base vehicle, scenario, its row, seed, its index)
//! alone. Shared inputs (contact tables, the synthesised track) are built once before the
//! parallel part and only read; with `per_sample_track` the track of sample `i` is synthesised
//! from ChaCha stream `i` of the seed. Results are collected in row order, so a batch gives the
//! same numbers bit for bit on any thread count and in any scheduling order.

use super::columns::{check_matrix, check_rows, check_speeds, resolve_columns, row_speed, Column};
use super::status::SampleStatus;
use crate::error::{LocoError, Result};
use crate::metrics::RunMetrics;
use crate::track::TrackIrregularity;
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::output::run::{Recorded, RunOutput};
use crate::vehicle::params::parameters::ParameterSet;
use crate::vehicle::rail_contact::wheel_rail::WheelRail;
use crate::vehicle::runs::simulate::run_prepared;
use crate::vehicle::scenarios::scenario::{build_track, Scenario, TrackSpec};
use crate::vehicle::scenarios::scenario_contact::shared_wheel_rail;
use crate::vehicle::system::run_statistics::RunStatistics;
use rayon::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// What a batch runs: a base vehicle and scenario, and a matrix of per-sample values.
#[derive(Debug, Clone)]
pub struct BatchSpec {
    /// Vehicle parameters every sample starts from.
    pub base: ParameterSet,
    /// Wheel, rail, speed, distance, track, yaw damper and settings of every sample.
    pub scenario: Scenario,
    /// Column names: vehicle file keys, study names (`K_px` …) or `speed` (m/s).
    pub names: Vec<String>,
    /// Row-major values, `n_samples × names.len()`, SI units.
    pub values: Vec<f64>,
    /// Synthesise a different track for every sample (ChaCha stream = sample index) instead of
    /// one track shared by all samples (common random numbers, the default for studies).
    pub per_sample_track: bool,
    /// With `per_sample_track`, the ChaCha stream of each sample's track (default, `None`: the
    /// sample's index). A campaign that runs its design in chunks passes each sample's index in
    /// the whole design, so a chunk draws the same tracks as the whole batch would.
    pub track_streams: Option<Vec<u64>>,
    /// Indices of the samples whose time histories are returned.
    pub histories: Vec<usize>,
}

/// Counters shared with the caller while a batch runs: progress to show, and a flag to cancel.
#[derive(Debug, Default)]
pub struct BatchMonitor {
    /// Samples in the batch, once known (0 before): a study run sets it when its inputs are
    /// read and checked, for a progress bar's length.
    pub total: AtomicUsize,
    /// Samples finished (successfully or not).
    pub done: AtomicUsize,
    /// Samples that failed.
    pub failed: AtomicUsize,
    /// Set to stop the batch: running samples end with `Interrupted`, the rest are not started.
    pub cancel: AtomicBool,
}

/// The result of a batch, rows in sample order.
#[derive(Debug, Clone)]
pub struct BatchOutput {
    /// Number of samples.
    pub n_samples: usize,
    /// Names of the metric columns ([`RunMetrics::names`]).
    pub metric_names: Vec<&'static str>,
    /// Row-major metrics, `n_samples × metric_names.len()`; NaN for failed samples.
    pub metrics: Vec<f64>,
    /// Outcome of each sample.
    pub status: Vec<SampleStatus>,
    /// Cost of each sample ([`RunStatistics::NAMES`]): counts of a failed sample are 0, its wall
    /// time is measured.
    pub statistics: Vec<RunStatistics>,
    /// Error message of each failed sample (empty for successful ones).
    pub messages: Vec<String>,
    /// Time histories of the samples asked for, `(index, output)` in ascending index order.
    pub histories: Vec<(usize, RunOutput)>,
}

impl BatchOutput {
    /// Number of samples that did not finish with [`SampleStatus::Ok`].
    pub fn n_failed(&self) -> usize {
        self.status
            .iter()
            .filter(|s| **s != SampleStatus::Ok)
            .count()
    }

    /// How many samples ended in each status that occurred, in code order.
    pub fn summary(&self) -> Vec<(SampleStatus, usize)> {
        SampleStatus::ALL
            .iter()
            .map(|&s| (s, self.status.iter().filter(|&&t| t == s).count()))
            .filter(|(_, n)| *n > 0)
            .collect()
    }

    /// Metrics of sample `i`.
    pub fn row(&self, i: usize) -> &[f64] {
        let m = self.metric_names.len();
        &self.metrics[i * m..(i + 1) * m]
    }
}

/// What every sample shares, built once.
struct Shared {
    columns: Vec<Column>,
    /// Contact of the base vehicle, or None when a column changes the contact.
    wheel_rail: Option<Arc<WheelRail>>,
    /// The shared track, or None when every sample gets its own.
    track: Option<Arc<TrackIrregularity>>,
}

/// Runs a batch on `threads` threads (0: one per core). Input errors (unknown column, NaN, a
/// non-physical row) are returned before anything runs and name the row and column; a sample
/// that fails while running gets a status and NaN metrics and the batch goes on.
pub fn run_batch(spec: &BatchSpec, threads: usize, monitor: &BatchMonitor) -> Result<BatchOutput> {
    let n = check_matrix(&spec.names, &spec.values)?;
    let columns = resolve_columns(&spec.base, &spec.names)?;
    spec.scenario.validate()?;
    if let Some(&i) = spec.histories.iter().find(|&&i| i >= n) {
        return Err(LocoError::input(
            "histories",
            format!("sample index {i} is out of range for {n} samples"),
        ));
    }
    if let Some(streams) = &spec.track_streams {
        if !spec.per_sample_track || streams.len() != n {
            return Err(LocoError::input(
                "track_streams",
                format!(
                    "needs per_sample_track and one stream per sample ({n}), got {} with \
                     per_sample_track = {}",
                    streams.len(),
                    spec.per_sample_track
                ),
            ));
        }
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| LocoError::param("threads", e.to_string()))?;
    pool.install(|| {
        // The base vehicle first, so that a non-physical base is reported as itself, not as row 0.
        let base = Arc::new(VehicleStructure::new(spec.base.clone())?);
        // Each row's vehicle, built once: by the check of its values, then run.
        let vehicles: Vec<Arc<VehicleStructure>> = if columns.iter().any(Column::is_vehicle) {
            check_rows(&spec.base, &spec.names, &columns, &spec.values)?
        } else {
            // No row changes the vehicle: only the speeds need checking, the base is built.
            check_speeds(&spec.names, &columns, &spec.values)?;
            vec![Arc::clone(&base); n]
        };
        let shared = prepare(spec, columns, base)?;
        let k = spec.names.len();
        let results: Vec<SampleResult> = spec
            .values
            .par_chunks(k)
            .zip(vehicles)
            .enumerate()
            .map(|(i, (row, vehicle))| {
                let result = run_sample_caught(spec, &shared, i, row, vehicle, monitor);
                if result.status != SampleStatus::Ok {
                    monitor.failed.fetch_add(1, Ordering::Relaxed);
                }
                monitor.done.fetch_add(1, Ordering::Relaxed);
                result
            })
            .collect();
        if monitor.cancel.load(Ordering::Relaxed) {
            return Err(LocoError::Interrupted);
        }
        Ok(collect(n, results))
    })
}

fn prepare(spec: &BatchSpec, columns: Vec<Column>, base: Arc<VehicleStructure>) -> Result<Shared> {
    let wheel_rail = if columns.iter().any(Column::changes_contact) {
        None
    } else {
        Some(shared_wheel_rail(&base.parameters, &spec.scenario)?)
    };
    let track = match (&spec.scenario.track, spec.per_sample_track) {
        (TrackSpec::Synthetic(_), true) => None,
        _ => Some(Arc::new(build_track(&spec.scenario, &base)?)),
    };
    Ok(Shared {
        columns,
        wheel_rail,
        track,
    })
}

struct SampleResult {
    status: SampleStatus,
    message: String,
    metrics: Option<RunMetrics>,
    history: Option<RunOutput>,
    statistics: RunStatistics,
}

fn run_sample_caught(
    spec: &BatchSpec,
    shared: &Shared,
    i: usize,
    row: &[f64],
    structure: Arc<VehicleStructure>,
    monitor: &BatchMonitor,
) -> SampleResult {
    if monitor.cancel.load(Ordering::Relaxed) {
        return failure(
            SampleStatus::Interrupted,
            "not run: the batch was cancelled",
        );
    }
    let started = std::time::Instant::now();
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        run_sample(spec, shared, i, row, structure, monitor)
    }));
    let wall_time = started.elapsed().as_secs_f64();
    let mut result = match outcome {
        Ok(Ok((metrics, output, statistics))) => SampleResult {
            status: SampleStatus::Ok,
            message: String::new(),
            metrics: Some(metrics),
            history: spec.histories.contains(&i).then_some(output),
            statistics,
        },
        Ok(Err(e)) => {
            let mut failed = failure(SampleStatus::from_error(&e), &e.to_string());
            if let LocoError::Equilibrium { iterations, .. } = e {
                failed.statistics.newton_iterations = iterations as u64;
            }
            failed
        }
        Err(panic) => {
            let what = crate::util::panic_message::panic_message(panic.as_ref());
            failure(
                SampleStatus::Internal,
                &format!("internal error (panic): {what}"),
            )
        }
    };
    result.statistics.wall_time = wall_time;
    result
}

fn failure(status: SampleStatus, message: &str) -> SampleResult {
    SampleResult {
        status,
        message: message.to_string(),
        metrics: None,
        history: None,
        statistics: RunStatistics::default(),
    }
}

fn run_sample(
    spec: &BatchSpec,
    shared: &Shared,
    i: usize,
    row: &[f64],
    structure: Arc<VehicleStructure>,
    monitor: &BatchMonitor,
) -> Result<(RunMetrics, RunOutput, RunStatistics)> {
    let scenario = Scenario {
        speed: row_speed(&shared.columns, row, spec.scenario.speed),
        track: match &spec.scenario.track {
            TrackSpec::Synthetic(p) if spec.per_sample_track => {
                TrackSpec::Synthetic(crate::track::SynthesisParams {
                    stream: spec.track_streams.as_ref().map_or(i as u64, |s| s[i]),
                    ..*p
                })
            }
            other => other.clone(),
        },
        ..spec.scenario.clone()
    };
    let wheel_rail = match &shared.wheel_rail {
        Some(w) => Arc::clone(w),
        None => shared_wheel_rail(&structure.parameters, &scenario)?,
    };
    let track = match &shared.track {
        Some(t) => Arc::clone(t),
        None => Arc::new(build_track(&scenario, &structure)?),
    };
    // A sample whose time histories are not returned records only what its metrics read.
    let recorded = if spec.histories.contains(&i) {
        Recorded::Every
    } else {
        Recorded::Metrics
    };
    // The scenario was validated once, by `run_batch`.
    let result = run_prepared(
        structure,
        wheel_rail,
        track,
        &scenario,
        recorded,
        Some(&monitor.cancel),
    )?;
    Ok((result.metrics, result.output, result.statistics))
}

fn collect(n: usize, results: Vec<SampleResult>) -> BatchOutput {
    let metric_names = RunMetrics::names().to_vec();
    let m = metric_names.len();
    let mut out = BatchOutput {
        n_samples: n,
        metric_names,
        metrics: Vec::with_capacity(n * m),
        status: Vec::with_capacity(n),
        statistics: Vec::with_capacity(n),
        messages: Vec::with_capacity(n),
        histories: Vec::new(),
    };
    for (i, r) in results.into_iter().enumerate() {
        match r.metrics {
            Some(metrics) => out.metrics.extend(metrics.values()),
            None => out.metrics.extend(std::iter::repeat_n(f64::NAN, m)),
        }
        out.status.push(r.status);
        out.statistics.push(r.statistics);
        out.messages.push(r.message);
        if let Some(h) = r.history {
            out.histories.push((i, h));
        }
    }
    out
}
