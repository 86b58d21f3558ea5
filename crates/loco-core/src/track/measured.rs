//! Measured track irregularity files.
//!
//! Format: CSV, one row per measuring point, columns `distance` (m), then `vertical`,
//! `alignment`, `cross_level`, `gauge` irregularities in **mm** (converted to m here, ×1e-3).
//! Lines starting with `#` and blank lines are ignored; a first line of five fields none of which
//! is a number is a header (a first line with some numbers and a field that is not one is an
//! error naming its line, not a header). Distances must increase strictly; they are shifted so the
//! first point is at s = 0. A gap between two rows longer than [`MAX_GAP_FACTOR`] times the
//! median spacing is refused, and so is a cosine run-in longer than the file. The data are resampled by linear interpolation onto a uniform grid (default step:
//! the median spacing of the file), slopes by centred differences, then a cosine run-in is
//! applied as for synthesised tracks.

use super::irregularity::{TrackIrregularity, TrackOrigin};
use crate::error::{check_non_negative, check_positive, FileKind, LocoError, Result};

/// Largest gap between two rows of a file, in multiples of its median spacing. Linear
/// interpolation across a gap of length g removes the irregularity's wavelengths shorter than
/// about 2g there: a file recorded every 0.25 m with a 2.5 m gap would lose the 1–5 m
/// wavelengths of the study's band over that stretch (a missing stretch, not a coarse record).
/// Ten times keeps files with uneven spacing (a few missed samples) readable.
pub const MAX_GAP_FACTOR: f64 = 10.0;

/// Options for reading a measured file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeasuredParams {
    /// Resampling step, m (None: the median spacing of the file).
    pub step: Option<f64>,
    /// Length of the cosine run-in, m.
    pub run_in: f64,
    /// Length the run needs, m: a shorter file is an error naming both lengths.
    pub required_length: Option<f64>,
}

impl Default for MeasuredParams {
    fn default() -> Self {
        Self {
            step: None,
            run_in: 30.0,
            required_length: None,
        }
    }
}

/// Reads and validates the file at `path`.
pub fn load_csv(path: &str, params: &MeasuredParams) -> Result<TrackIrregularity> {
    let text = crate::util::text_file::read_text(std::path::Path::new(path), FileKind::Track)?;
    parse_csv(&text, path, params)
}

/// Parses the content `text` of a file named `path` (used in error messages).
pub fn parse_csv(text: &str, path: &str, params: &MeasuredParams) -> Result<TrackIrregularity> {
    check_non_negative("run_in", params.run_in)?;
    let parse_err =
        |line: usize, reason: String| LocoError::parse(FileKind::Track, path, line, reason);
    let mut distance: Vec<f64> = Vec::new();
    let mut columns: [Vec<f64>; 4] = Default::default();
    let mut lines: Vec<usize> = Vec::new();
    let mut seen_data_line = false;
    for (index, raw) in text.lines().enumerate() {
        let line_no = index + 1;
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let numbers: std::result::Result<Vec<f64>, _> =
            fields.iter().map(|f| f.parse::<f64>()).collect();
        let numbers = match numbers {
            Ok(n) => n,
            Err(_) if !seen_data_line && fields.iter().all(|f| f.parse::<f64>().is_err()) => {
                if fields.len() != 5 {
                    return Err(parse_err(
                        line_no,
                        format!(
                            "a header of {} names; expected 5 (distance, vertical, alignment, \
                             cross_level, gauge)",
                            fields.len()
                        ),
                    ));
                }
                seen_data_line = true; // a header
                continue;
            }
            Err(e) => {
                let what = if seen_data_line {
                    String::new()
                } else {
                    " (a header row has no numbers)".to_string()
                };
                return Err(parse_err(
                    line_no,
                    format!("not a number: {e} in `{line}`{what}"),
                ));
            }
        };
        seen_data_line = true;
        if numbers.len() != 5 {
            return Err(parse_err(
                line_no,
                format!(
                    "expected 5 columns (distance, vertical, alignment, cross_level, gauge), got {}",
                    numbers.len()
                ),
            ));
        }
        if let Some(i) = numbers.iter().position(|v| !v.is_finite()) {
            let names = ["distance", "vertical", "alignment", "cross_level", "gauge"];
            return Err(parse_err(line_no, format!("`{}` is not finite", names[i])));
        }
        if let Some(&last) = distance.last() {
            if numbers[0] <= last {
                return Err(parse_err(
                    line_no,
                    format!(
                        "distance {} m does not increase (previous {last} m)",
                        numbers[0]
                    ),
                ));
            }
        }
        distance.push(numbers[0]);
        lines.push(line_no);
        for c in 0..4 {
            columns[c].push(numbers[c + 1] * 1e-3);
        }
    }
    if distance.len() < 2 {
        return Err(parse_err(
            0,
            format!("needs at least 2 data rows, got {}", distance.len()),
        ));
    }
    let origin = distance[0];
    distance.iter_mut().for_each(|d| *d -= origin);
    let length = distance[distance.len() - 1];
    let median = median_spacing(&distance);
    if let Some(k) =
        (1..distance.len()).find(|&k| distance[k] - distance[k - 1] > MAX_GAP_FACTOR * median)
    {
        return Err(parse_err(
            lines[k],
            format!(
                "a gap of {:.3} m after line {} is more than {MAX_GAP_FACTOR} times the file's \
                 median spacing ({median:.3} m): linear interpolation across it would remove the \
                 wavelengths shorter than about twice the gap; fill the gap or split the file",
                distance[k] - distance[k - 1],
                lines[k - 1]
            ),
        ));
    }
    if params.run_in > length {
        return Err(LocoError::param(
            "run_in",
            format!(
                "the cosine run-in of {} m is longer than {path}, which covers {length:.3} m",
                params.run_in
            ),
        ));
    }
    if let Some(required) = params.required_length {
        if required.is_nan() || length < required {
            return Err(LocoError::input(
                "track",
                format!("{path} covers {length:.3} m but the run needs {required:.3} m"),
            ));
        }
    }
    let step = match params.step {
        Some(h) => check_positive("step", h)?,
        None => median,
    };
    let nodes = (length / step).floor() + 1.0;
    if nodes > 5.0e7 {
        return Err(LocoError::param(
            "step",
            format!("{step} m over {length} m needs {nodes:.0} grid points (max 5e7)"),
        ));
    }
    let nodes = nodes as usize;
    if nodes < 2 {
        return Err(LocoError::param(
            "step",
            format!("{step} m is longer than the file's {length} m"),
        ));
    }
    let grid: Vec<f64> = (0..nodes).map(|i| i as f64 * step).collect();
    let values: [Vec<f64>; 4] = std::array::from_fn(|c| interpolate(&distance, &columns[c], &grid));
    let slopes: [Vec<f64>; 4] = std::array::from_fn(|c| centred_slopes(&values[c], step));
    Ok(
        TrackIrregularity::from_channels(step, &values, &slopes, params.run_in, None)?.with_origin(
            TrackOrigin {
                path: path.to_string(),
                lines,
                channels: columns,
            },
        ),
    )
}

/// Median of the spacings of increasing `x`.
fn median_spacing(x: &[f64]) -> f64 {
    let mut d: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    d.sort_by(f64::total_cmp);
    d[d.len() / 2]
}

/// Linear interpolation of (x, y) at increasing `at` (all within [x0, x_last]).
fn interpolate(x: &[f64], y: &[f64], at: &[f64]) -> Vec<f64> {
    let mut i = 0;
    at.iter()
        .map(|&s| {
            while i + 2 < x.len() && x[i + 1] < s {
                i += 1;
            }
            let t = ((s - x[i]) / (x[i + 1] - x[i])).clamp(0.0, 1.0);
            y[i] + t * (y[i + 1] - y[i])
        })
        .collect()
}

/// Centred differences (one-sided at the ends), per m.
fn centred_slopes(v: &[f64], step: f64) -> Vec<f64> {
    let n = v.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            (v[b] - v[a]) / ((b - a) as f64 * step)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::track::Channel;

    fn params() -> MeasuredParams {
        MeasuredParams {
            run_in: 0.0,
            ..Default::default()
        }
    }

    #[test]
    fn reads_converts_and_resamples() {
        let text = "# measured\ndistance,vertical,alignment,cross_level,gauge\n\
                    100.0, 1.0, 0, 0, 0\n100.5, 2.0, 0, 0, 0\n101.0, 3.0, 0, 0, 2.0\n";
        let track = parse_csv(text, "t.csv", &params()).unwrap();
        assert_eq!(track.step(), 0.5);
        assert_eq!(track.length(), 1.0);
        let v = track.channel(Channel::Vertical);
        assert!((v[1] - 2e-3).abs() < 1e-15);
        // Slope of the vertical profile: 1 mm per 0.5 m.
        assert!((track.at(0.5).dz_left_ds - 2e-3).abs() < 1e-12);
        let fine = parse_csv(
            text,
            "t.csv",
            &MeasuredParams {
                step: Some(0.25),
                ..params()
            },
        );
        assert!((fine.unwrap().channel(Channel::Vertical)[1] - 1.5e-3).abs() < 1e-15);
    }

    #[test]
    fn errors_name_file_and_line() {
        let cases = [
            ("0,1,2,3,4\n1,1,2,3\n", "t.csv:2:"),
            ("0,1,2,3,4\n0,1,2,3,4\n", "t.csv:2:"),
            ("0,1,2,3,4\n1,NaN,2,3,4\n", "t.csv:2:"),
            ("0,1,2,3,4\n1,x,2,3,4\n", "t.csv:2:"),
            ("0,1,2,3,4\n", "t.csv:0:"),
            // A first row with a typo is not a header.
            ("0,1,2x,3,4\n1,1,2,3,4\n2,1,2,3,4\n", "t.csv:1:"),
            ("d,v,a,c\n0,1,2,3,4\n1,1,2,3,4\n", "t.csv:1:"),
            // A 10 km gap in a file recorded every metre.
            (
                "0,0,0,0,0\n1,0,0,0,0\n2,0,0,0,0\n10002,0,0,0,0\n",
                "t.csv:4: a gap of 10000.000 m",
            ),
        ];
        for (text, expected) in cases {
            let err = parse_csv(text, "t.csv", &params()).unwrap_err().to_string();
            assert!(err.starts_with(expected), "{err}");
        }
        let short = MeasuredParams {
            required_length: Some(500.0),
            ..params()
        };
        let err = parse_csv("0,1,2,3,4\n1,1,2,3,4\n", "t.csv", &short).unwrap_err();
        assert!(err.to_string().contains("needs 500.000 m"));
        let long_run_in = MeasuredParams {
            run_in: 30.0,
            ..params()
        };
        let err = parse_csv("0,1,2,3,4\n1,1,2,3,4\n", "t.csv", &long_run_in).unwrap_err();
        assert!(err.to_string().contains("`run_in`"), "{err}");
        assert!(matches!(err, LocoError::InvalidParameter { .. }));
        let bad = parse_csv("0,1,2x,3,4\n1,1,2,3,4\n", "t.csv", &params()).unwrap_err();
        assert!(matches!(
            bad,
            LocoError::Parse {
                kind: FileKind::Track,
                ..
            }
        ));
        assert!(matches!(
            load_csv("/nonexistent/track.csv", &params()),
            Err(LocoError::Io { .. })
        ));
    }
}
