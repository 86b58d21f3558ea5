//! A study's CSV files: samples in, metrics and status out, time histories out.
//!
//! Numbers are written with Rust's shortest round-trip formatting, so a reader that parses them
//! back (Python's `float`, pandas) gets the same `f64` bit for bit.

use crate::batch::BatchOutput;
use crate::util::csv_table::CsvTable;
use crate::vehicle::output::run::RunOutput;
use crate::vehicle::system::run_statistics::RunStatistics;
use crate::{LocoError, Result};
use std::fmt::Write as _;
use std::path::Path;

/// A samples file: a header of column names and one row of values (SI) per sample.
pub struct Samples {
    pub names: Vec<String>,
    /// Row-major values.
    pub values: Vec<f64>,
}

/// Reads a samples CSV (comma separated, `#` comments and blank lines skipped). Errors name
/// the file and line.
pub fn read_samples(path: &Path) -> Result<Samples> {
    let label = path.display().to_string();
    let text = crate::util::text_file::read_text(path, crate::error::FileKind::Study)?;
    let table = CsvTable::parse(&text, &label, crate::error::FileKind::Study)?;
    let mut values = Vec::new();
    for (line, cells) in &table.rows {
        for (cell, name) in cells.iter().zip(&table.names) {
            let value: f64 = cell.parse().map_err(|_| {
                table.error(*line, format!("column '{name}': '{cell}' is not a number"))
            })?;
            values.push(value);
        }
    }
    if values.is_empty() {
        return Err(table.error(0, "no sample rows"));
    }
    let names = table.names.iter().map(|n| n.to_string()).collect();
    Ok(Samples { names, values })
}

/// Checks, before any work, that the metrics file `path` can be written: it is not a directory,
/// its directory exists, and a file can be created there (a probe file, removed at once). The
/// history files go to the same directory. An error names the option `--output`.
pub fn check_output(path: &Path) -> Result<()> {
    let refuse =
        |reason: String| LocoError::param("--output", format!("{}: {reason}", path.display()));
    if path.is_dir() {
        return Err(refuse(
            "is a directory; give the metrics file to write".into(),
        ));
    }
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        let what = if dir.exists() {
            "is not a directory"
        } else {
            "does not exist"
        };
        return Err(refuse(format!(
            "its directory {} {what} (create it first)",
            dir.display()
        )));
    }
    let probe = dir.join(format!(".loco-batch-probe-{}", std::process::id()));
    std::fs::write(&probe, b"")
        .and_then(|()| std::fs::remove_file(&probe))
        .map_err(|e| refuse(format!("cannot write into {}: {e}", dir.display())))
}

fn write(path: &Path, text: &str) -> Result<()> {
    std::fs::write(path, text).map_err(|e| LocoError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    })
}

/// Writes one row per sample: `sample`, the parameters, the metrics, the run statistics
/// ([`RunStatistics::NAMES`]), `status`, `message`.
pub fn write_metrics(path: &Path, samples: &Samples, output: &BatchOutput) -> Result<()> {
    let mut text = String::from("sample");
    for name in samples
        .names
        .iter()
        .map(String::as_str)
        .chain(output.metric_names.iter().copied())
        .chain(RunStatistics::NAMES)
    {
        let _ = write!(text, ",{name}");
    }
    text.push_str(",status,message\n");
    let k = samples.names.len();
    for i in 0..output.n_samples {
        let _ = write!(text, "{i}");
        for v in samples.values[i * k..(i + 1) * k]
            .iter()
            .chain(output.row(i))
            .chain(&output.statistics[i].values())
        {
            let _ = write!(text, ",{v}");
        }
        // Messages are free text: quote them and double inner quotes (RFC 4180).
        let message = output.messages[i].replace('"', "\"\"").replace('\n', " ");
        let _ = writeln!(text, ",{},\"{message}\"", output.status[i].name());
    }
    write(path, &text)
}

/// Positions in `available` of the `wanted` channels; an unknown name is an error on
/// `output.channels` that lists the available ones.
pub fn select_channels(wanted: &[String], available: &[String]) -> Result<Vec<usize>> {
    wanted
        .iter()
        .map(|w| {
            available.iter().position(|n| n == w).ok_or_else(|| {
                LocoError::param(
                    "output.channels",
                    format!("no channel '{w}'; available: {}", available.join(", ")),
                )
            })
        })
        .collect()
}

/// Writes the time histories of one sample: `time` then the channels (all, or those named).
pub fn write_history(path: &Path, run: &RunOutput, channels: Option<&[String]>) -> Result<()> {
    let selected: Vec<usize> = match channels {
        None => (0..run.names.len()).collect(),
        Some(wanted) => select_channels(wanted, &run.names)?,
    };
    let mut text = String::from("time");
    for &c in &selected {
        let _ = write!(text, ",{}", run.names[c]);
    }
    text.push('\n');
    for (s, t) in run.time.iter().enumerate() {
        let _ = write!(text, "{t}");
        for &c in &selected {
            let _ = write!(text, ",{}", run.channels[c][s]);
        }
        text.push('\n');
    }
    write(path, &text)
}
