//! `loco-batch`: runs a batch of locomotive simulations without Python.
//!
//! ```text
//! loco-batch study.toml samples.csv -o metrics.csv [--threads N] [--quiet]
//! ```
//!
//! The study file (see [`loco_core::batch::study_file`]) gives the vehicle, the scenario and the
//! outputs; the samples CSV has a header of parameter names (vehicle keys, K_px … K_ncsy, or
//! `speed`) and one row of SI values per sample. The metrics CSV has one row per sample with its
//! status; time histories of the samples listed in the study go to
//! `<metrics stem>_history_<i>.csv`; their channel names are checked before the batch starts,
//! so a typo fails at once with the list of channels. The numbers are the same, bit for bit, as
//! `loco batch` and `loco.run_batch` on the same input.

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use loco_core::batch::{run_study, BatchMonitor};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::Ordering;
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
    let monitor = BatchMonitor::default();
    // Its length is set once the study's inputs are read and checked.
    let bar = if cli.quiet {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(0)
    };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} runs  {per_sec}  eta {eta}  {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let start = Instant::now();
    let threads = usize::from(cli.threads);
    let summary = std::thread::scope(|scope| {
        let worker =
            scope.spawn(|| run_study(&cli.study, &cli.samples, &cli.output, threads, &monitor));
        while !worker.is_finished() {
            std::thread::sleep(Duration::from_millis(100));
            bar.set_length(monitor.total.load(Ordering::Relaxed) as u64);
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
    let n = summary.n_samples;
    bar.set_length(n as u64);
    bar.set_position(n as u64);
    bar.finish();
    let statuses: Vec<String> = summary
        .statuses
        .iter()
        .map(|(s, k)| format!("{k} {}", s.name()))
        .collect();
    let seconds = start.elapsed().as_secs_f64();
    eprintln!(
        "loco-batch: {n} samples in {seconds:.2} s ({:.2} runs/s): {}; wrote {}",
        n as f64 / seconds,
        statuses.join(", "),
        summary.metrics_file.display()
    );
    Ok(())
}
