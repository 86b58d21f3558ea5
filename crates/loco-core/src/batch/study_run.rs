//! One study file run end to end: the study and samples read and checked, the batch run, the
//! metrics CSV and the kept time histories written. `loco-batch` and `loco batch` both call
//! [`run_study`]; they differ only in how they show progress (they poll the [`BatchMonitor`]).

use super::study_csv::{self, Samples};
use super::study_file::load_study;
use super::{run_batch, BatchMonitor, BatchSpec, SampleStatus};
use crate::vehicle::model::structure::VehicleStructure;
use crate::vehicle::output::run::channel_names;
use crate::Result;
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;

/// What a study run wrote, and how its samples ended.
#[derive(Debug, Clone)]
pub struct StudySummary {
    /// Samples run.
    pub n_samples: usize,
    /// How many samples ended with each status (only the statuses that occurred).
    pub statuses: Vec<(SampleStatus, usize)>,
    /// The metrics CSV written.
    pub metrics_file: PathBuf,
    /// The time-history CSVs written, in sample order.
    pub history_files: Vec<PathBuf>,
}

/// Runs the study file `study` over the samples CSV `samples` on `threads` threads (0: one per
/// core; the results do not depend on it) and writes the metrics CSV `output`, with the time
/// histories the study keeps in `<output stem>_history_<i>.csv`.
///
/// Everything that can be checked before the batch is: that `output` can be written, the study
/// file, the samples, and the history channels' names (a typo fails at once, listing the
/// channels). `monitor` reports progress (its `total` is set once the inputs are checked) and
/// cancels the batch.
pub fn run_study(
    study: &Path,
    samples: &Path,
    output: &Path,
    threads: usize,
    monitor: &BatchMonitor,
) -> Result<StudySummary> {
    study_csv::check_output(output)?;
    let study = load_study(study)?;
    let Samples { names, values } = study_csv::read_samples(samples)?;
    if let Some(wanted) = &study.channels {
        // The names depend only on the vehicle's structure: the base vehicle's lists them.
        let structure = VehicleStructure::new(study.base.clone())?;
        study_csv::select_channels(wanted, &channel_names(&structure)?)?;
    }
    monitor
        .total
        .store(values.len() / names.len(), Ordering::Relaxed);
    let spec = BatchSpec {
        base: study.base,
        scenario: study.scenario,
        names,
        values,
        per_sample_track: study.per_sample_track,
        track_streams: None,
        histories: study.histories,
    };
    let result = run_batch(&spec, threads, monitor)?;
    let samples = Samples {
        names: spec.names,
        values: spec.values,
    };
    study_csv::write_metrics(output, &samples, &result)?;
    let stem = output.with_extension("");
    let mut history_files = Vec::with_capacity(result.histories.len());
    for (i, run) in &result.histories {
        let path = PathBuf::from(format!("{}_history_{i}.csv", stem.display()));
        study_csv::write_history(&path, run, study.channels.as_deref())?;
        history_files.push(path);
    }
    Ok(StudySummary {
        n_samples: result.n_samples,
        statuses: result.summary(),
        metrics_file: output.to_path_buf(),
        history_files,
    })
}
