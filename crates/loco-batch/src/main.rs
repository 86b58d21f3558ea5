//! `loco-batch`: runs a batch of locomotive simulations without Python.
//!
//! ```text
//! loco-batch study.toml samples.csv -o metrics.csv [--threads N] [--quiet]
//! ```
//!
//! The study file (see `study.rs`) gives the vehicle, the scenario and the outputs; the samples
//! CSV has a header of parameter names (vehicle keys, K_px … K_ncsy, or `speed`) and one row of
//! SI values per sample. The metrics CSV has one row per sample with its status; time histories
//! of the samples listed in the study go to `<metrics stem>_history_<i>.csv`; their channel
//! names are checked before the batch starts, so a typo fails at once with the list of channels. The numbers are the
//! same, bit for bit, as `loco.run_batch` on the same input.

mod csv_io;
mod study;

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use loco_core::batch::{run_batch, BatchMonitor, BatchSpec};
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::output::run::channel_names;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::{Duration, Instant};

#[derive(Parser, Debug)]
#[command(
    name = "loco-batch",
    version,
    about = "Run a batch of loco simulations"
)]
struct Cli {
    /// Study file (TOML): vehicle, scenario, outputs.
    study: PathBuf,
    /// Samples (CSV): a header of parameter names, one row of SI values per sample.
    samples: PathBuf,
    /// Metrics file to write (CSV).
    #[arg(short, long, default_value = "metrics.csv")]
    output: PathBuf,
    /// Worker threads (0: one per core; at most 1024). The results do not depend on it.
    #[arg(short, long, default_value_t = 0, value_parser = clap::value_parser!(u16).range(..=1024))]
    threads: u16,
    /// No progress bar.
    #[arg(short, long)]
    quiet: bool,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("loco-batch: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: &Cli) -> loco_core::Result<()> {
    // Before any work: a metrics file that cannot be written must fail now, not after the batch.
    csv_io::check_output(&cli.output)?;
    let study = study::load_study(&cli.study)?;
    let samples = csv_io::read_samples(&cli.samples)?;
    if let Some(wanted) = &study.channels {
        // Check the history channels before the batch: a typo must fail now, not after hours of
        // simulation. The names depend only on the vehicle's structure: the base vehicle's lists
        // them.
        let structure = VehicleStructure::new(study.base.clone())?;
        csv_io::select_channels(wanted, &channel_names(&structure)?)?;
    }
    let n = samples.values.len() / samples.names.len();
    let spec = BatchSpec {
        base: study.base,
        scenario: study.scenario,
        names: samples.names.clone(),
        values: samples.values.clone(),
        per_sample_track: study.per_sample_track,
        track_streams: None,
        histories: study.histories.clone(),
    };
    let monitor = Arc::new(BatchMonitor::default());
    let bar = if cli.quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(n as u64)
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} runs  {per_sec}  eta {eta}  {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let start = Instant::now();
    let threads = usize::from(cli.threads);
    let output = std::thread::scope(|scope| {
        let worker = scope.spawn(|| run_batch(&spec, threads, &monitor));
        while !worker.is_finished() {
            std::thread::sleep(Duration::from_millis(100));
            bar.set_position(monitor.done.load(Ordering::Relaxed) as u64);
            let failed = monitor.failed.load(Ordering::Relaxed);
            if failed > 0 {
                bar.set_message(format!("{failed} failed"));
            }
        }
        worker.join().unwrap_or_else(|_| {
            Err(loco_core::LocoError::input(
                "batch",
                "internal error: the batch thread panicked",
            ))
        })
    })?;
    bar.set_position(n as u64);
    bar.finish();
    csv_io::write_metrics(&cli.output, &samples, &output)?;
    let stem = cli.output.with_extension("");
    for (i, run) in &output.histories {
        let path = PathBuf::from(format!("{}_history_{i}.csv", stem.display()));
        csv_io::write_history(&path, run, study.channels.as_deref())?;
    }
    let summary: Vec<String> = output
        .summary()
        .iter()
        .map(|(s, k)| format!("{k} {}", s.name()))
        .collect();
    eprintln!(
        "loco-batch: {n} samples in {:.2} s ({:.2} runs/s): {}; wrote {}",
        start.elapsed().as_secs_f64(),
        n as f64 / start.elapsed().as_secs_f64(),
        summary.join(", "),
        cli.output.display()
    );
    Ok(())
}
