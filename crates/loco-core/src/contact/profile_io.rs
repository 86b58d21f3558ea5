//! Profile loaders: two-column text files (mm) and SIMPACK `.prw` (wheel) / `.prr` (rail) files.
//!
//! Both return a [`Profile`] in the frame of [`super::profile`] (y toward the field side, z up, m).
//!
//! - Text (`.txt`, `.dat`, `.csv`, anything not SIMPACK): one point a line, y then z in **mm**,
//!   separated by blanks, commas or semicolons (extra columns ignored); `#` and `%` start comments.
//!   The points must already be in the profile frame (EN 15302 reference files are); they may run
//!   in either y direction but must be strictly monotonic, unless `drop_backtracking` is set, in
//!   which case points that do not advance beyond the last kept y are dropped (for digitised
//!   profiles that double back on themselves at an end).
//! - SIMPACK (`.prw` wheel, `.prr` rail): see [`super::profile_simpack`].

use super::profile::{Profile, ProfileKind};
use crate::error::{FileKind, LocoError, Result};
use std::path::Path;

/// Loads a profile file. SIMPACK files are recognised by their extension (`.prw`, `.prr`); any
/// other file is read as text and then needs `kind`. If `kind` is given for a SIMPACK file it
/// must match the file's type.
pub fn load_profile(
    path: &Path,
    kind: Option<ProfileKind>,
    drop_backtracking: bool,
) -> Result<Profile> {
    let label = path.display().to_string();
    let text = crate::util::text_file::read_text(path, FileKind::Profile)?;
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| label.clone());
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    let profile = match ext.as_str() {
        "prw" => super::profile_simpack::parse_simpack(&text, &label, ProfileKind::Wheel, kind)?,
        "prr" => super::profile_simpack::parse_simpack(&text, &label, ProfileKind::Rail, kind)?,
        _ => {
            let kind = kind.ok_or_else(|| {
                LocoError::param(
                    "kind",
                    format!("{label} is a text profile: say whether it is a 'wheel' or a 'rail'"),
                )
            })?;
            parse_text(&text, &label, kind, drop_backtracking)?
        }
    };
    let profile = profile.renamed(name);
    if let Some(reason) = super::profile_plausibility::implausibility(&profile) {
        return Err(parse_error(&label, 0, reason));
    }
    Ok(profile)
}

pub(super) fn parse_error(path: &str, line: usize, reason: impl Into<String>) -> LocoError {
    LocoError::parse(FileKind::Profile, path, line, reason)
}

/// Points with the 1-based line each came from.
pub(super) struct RawPoints {
    pub(super) y: Vec<f64>,
    pub(super) z: Vec<f64>,
    pub(super) line: Vec<usize>,
}

impl RawPoints {
    pub(super) fn new() -> Self {
        Self {
            y: Vec::new(),
            z: Vec::new(),
            line: Vec::new(),
        }
    }

    /// Orders the points by increasing y (reversing a decreasing file), optionally dropping
    /// points that backtrack, checks count and monotonicity and builds the profile.
    pub(super) fn into_profile(
        mut self,
        path: &str,
        kind: ProfileKind,
        drop_backtracking: bool,
    ) -> Result<Profile> {
        let n = self.y.len();
        if n < super::profile::MIN_PROFILE_POINTS {
            return Err(parse_error(
                path,
                0,
                format!(
                    "needs at least {} points, found {n}",
                    super::profile::MIN_PROFILE_POINTS
                ),
            ));
        }
        if self.y[n - 1] < self.y[0] {
            self.y.reverse();
            self.z.reverse();
            self.line.reverse();
        }
        let (mut y, mut z) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for i in 0..n {
            if let Some(&last) = y.last() {
                if self.y[i] <= last {
                    if drop_backtracking {
                        continue;
                    }
                    return Err(parse_error(
                        path,
                        self.line[i],
                        format!(
                            "y is not strictly monotonic ({} after {} mm-equivalent point); \
                             profiles must be functions z(y)",
                            self.y[i], last
                        ),
                    ));
                }
            }
            y.push(self.y[i]);
            z.push(self.z[i]);
        }
        Profile::new(path, kind, &y, &z).map_err(|e| parse_error(path, 0, e.to_string()))
    }
}

pub(super) fn parse_number(path: &str, line: usize, field: &str) -> Result<f64> {
    let v: f64 = field
        .parse()
        .map_err(|_| parse_error(path, line, format!("cannot read a number from '{field}'")))?;
    if !v.is_finite() {
        return Err(parse_error(path, line, format!("'{field}' is not finite")));
    }
    Ok(v)
}

/// Parses a two-column text profile (y, z in mm) of kind `kind`; `path` labels errors.
pub fn parse_text(
    text: &str,
    path: &str,
    kind: ProfileKind,
    drop_backtracking: bool,
) -> Result<Profile> {
    let mut pts = RawPoints::new();
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let content = raw.split(['#', '%']).next().unwrap_or("");
        let fields: Vec<&str> = content
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|f| !f.is_empty())
            .collect();
        if fields.is_empty() {
            continue;
        }
        if fields.len() < 2 {
            return Err(parse_error(
                path,
                line_no,
                format!("expected two columns y z (mm), got '{}'", content.trim()),
            ));
        }
        pts.y.push(parse_number(path, line_no, fields[0])? * 1e-3);
        pts.z.push(parse_number(path, line_no, fields[1])? * 1e-3);
        pts.line.push(line_no);
    }
    pts.into_profile(path, kind, drop_backtracking)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_profile_in_mm_with_comments() {
        let text = "# wheel\n% also a comment\n-2 0.5\n-1, 0.25\n0;0\n1 -0.25 # tail\n2 -0.5 7\n";
        let p = parse_text(text, "t.txt", ProfileKind::Wheel, false).unwrap();
        assert_eq!(p.y().len(), 5);
        assert!((p.y()[0] + 2e-3).abs() < 1e-15 && (p.z()[0] - 0.5e-3).abs() < 1e-15);
        // A file running toward -y is reversed.
        let p = parse_text("2 0\n1 0\n0 0\n-1 0\n-2 0\n", "r", ProfileKind::Rail, false).unwrap();
        assert!(p.y()[0] < p.y()[4]);
    }

    #[test]
    fn malformed_text_names_the_line() {
        let bad = "0 0\n1 1\nabc 2\n3 3\n4 4\n";
        match parse_text(bad, "bad.txt", ProfileKind::Wheel, false) {
            Err(LocoError::Parse { line, path, .. }) => {
                assert_eq!(line, 3);
                assert_eq!(path, "bad.txt");
            }
            other => panic!("{other:?}"),
        }
        let nan = "0 0\n1 nan\n2 2\n3 3\n4 4\n";
        assert!(matches!(
            parse_text(nan, "n", ProfileKind::Wheel, false),
            Err(LocoError::Parse { line: 2, .. })
        ));
        let one_column = "0 0\n1\n2 2\n3 3\n4 4\n";
        assert!(parse_text(one_column, "c", ProfileKind::Wheel, false).is_err());
        let few = "0 0\n1 1\n";
        assert!(parse_text(few, "f", ProfileKind::Wheel, false).is_err());
        let backtrack = "0 0\n1 1\n2 2\n1.5 2\n3 3\n4 4\n";
        assert!(matches!(
            parse_text(backtrack, "b", ProfileKind::Wheel, false),
            Err(LocoError::Parse { line: 4, .. })
        ));
        let p = parse_text(backtrack, "b", ProfileKind::Wheel, true).unwrap();
        assert_eq!(p.y().len(), 5);
    }

    #[test]
    fn missing_file_is_an_io_error_and_text_needs_a_kind() {
        let e = load_profile(
            Path::new("/no/such/file.txt"),
            Some(ProfileKind::Rail),
            false,
        );
        assert!(matches!(e, Err(LocoError::Io { .. })));
        let e = load_profile(Path::new("/no/such/file.prw"), None, false);
        assert!(matches!(e, Err(LocoError::Io { .. })));
    }
}
