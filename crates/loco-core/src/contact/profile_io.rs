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
//! - SIMPACK: the header's `type` (0 rail, 1 wheel) must agree with the extension and with the
//!   kind asked for. The point section's coordinates are processed as SIMPACK documents in the
//!   file's own header comments, in its order: shift (`shift.y`, `shift.z`), rotation (only 0 is
//!   supported: its sign convention is not documented in the file), bounds (`bound.*`, active when
//!   min < max), mirroring (`mirror.y`, `mirror.z`), units (`units.len.f` = user units per m). SIMPACK
//!   profiles have z **down**, so z is negated at the end. `!` starts comments.

use super::profile::{Profile, ProfileKind};
use crate::error::{LocoError, Result};
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
    let text = std::fs::read_to_string(path).map_err(|e| LocoError::Io {
        path: label.clone(),
        reason: e.to_string(),
    })?;
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| label.clone());
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    let profile = match ext.as_str() {
        "prw" => parse_simpack(&text, &label, ProfileKind::Wheel, kind)?,
        "prr" => parse_simpack(&text, &label, ProfileKind::Rail, kind)?,
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
    Ok(profile.renamed(name))
}

fn parse_error(path: &str, line: usize, reason: impl Into<String>) -> LocoError {
    LocoError::Parse {
        path: path.to_string(),
        line,
        reason: reason.into(),
    }
}

/// Points with the 1-based line each came from.
struct RawPoints {
    y: Vec<f64>,
    z: Vec<f64>,
    line: Vec<usize>,
}

impl RawPoints {
    fn new() -> Self {
        Self {
            y: Vec::new(),
            z: Vec::new(),
            line: Vec::new(),
        }
    }

    /// Orders the points by increasing y (reversing a decreasing file), optionally dropping
    /// points that backtrack, checks count and monotonicity and builds the profile.
    fn into_profile(
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

fn parse_number(path: &str, line: usize, field: &str) -> Result<f64> {
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

/// Processing settings read from a SIMPACK `spline` section.
struct SimpackSettings {
    shift_y: f64,
    shift_z: f64,
    bound_y: (f64, f64),
    bound_z: (f64, f64),
    mirror_y: bool,
    mirror_z: bool,
    units_per_m: f64,
}

/// Parses a SIMPACK profile; `file_kind` comes from the extension, `expected` from the caller.
pub fn parse_simpack(
    text: &str,
    path: &str,
    file_kind: ProfileKind,
    expected: Option<ProfileKind>,
) -> Result<Profile> {
    let mut header_type: Option<(ProfileKind, usize)> = None;
    let mut settings = SimpackSettings {
        shift_y: 0.0,
        shift_z: 0.0,
        bound_y: (1.0, 0.0),
        bound_z: (1.0, 0.0),
        mirror_y: false,
        mirror_z: false,
        units_per_m: 1.0,
    };
    #[derive(PartialEq)]
    enum Section {
        Outside,
        Header,
        Spline,
        Points,
    }
    let mut section = Section::Outside;
    let mut pts = RawPoints::new();
    let mut saw_points_end = false;
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let content = raw.split('!').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        match content {
            "header.begin" => section = Section::Header,
            "spline.begin" => section = Section::Spline,
            "point.begin" => section = Section::Points,
            "point.end" => {
                section = Section::Spline;
                saw_points_end = true;
            }
            "header.end" | "spline.end" => section = Section::Outside,
            _ if section == Section::Points => {
                let fields: Vec<&str> = content.split_whitespace().collect();
                if fields.len() < 2 {
                    return Err(parse_error(
                        path,
                        line_no,
                        "expected a point 'y z [weight]'",
                    ));
                }
                pts.y.push(parse_number(path, line_no, fields[0])?);
                pts.z.push(parse_number(path, line_no, fields[1])?);
                pts.line.push(line_no);
            }
            _ => {
                let Some((key, value)) = content.split_once('=') else {
                    return Err(parse_error(
                        path,
                        line_no,
                        format!("expected 'key = value', got '{content}'"),
                    ));
                };
                let (key, value) = (key.trim(), value.trim());
                let number = || parse_number(path, line_no, value);
                match (&section, key) {
                    (Section::Header, "type") => {
                        let kind = match number()? as i64 {
                            0 => ProfileKind::Rail,
                            1 => ProfileKind::Wheel,
                            t => {
                                return Err(parse_error(
                                    path,
                                    line_no,
                                    format!("type must be 0 (rail) or 1 (wheel), got {t}"),
                                ))
                            }
                        };
                        header_type = Some((kind, line_no));
                    }
                    (Section::Spline, "shift.y") => settings.shift_y = number()?,
                    (Section::Spline, "shift.z") => settings.shift_z = number()?,
                    (Section::Spline, "rotate") if number()? != 0.0 => {
                        return Err(parse_error(
                            path,
                            line_no,
                            "a non-zero 'rotate' is not supported; rotate the points instead",
                        ));
                    }
                    (Section::Spline, "bound.y.min") => settings.bound_y.0 = number()?,
                    (Section::Spline, "bound.y.max") => settings.bound_y.1 = number()?,
                    (Section::Spline, "bound.z.min") => settings.bound_z.0 = number()?,
                    (Section::Spline, "bound.z.max") => settings.bound_z.1 = number()?,
                    (Section::Spline, "mirror.y") => settings.mirror_y = number()? != 0.0,
                    (Section::Spline, "mirror.z") => settings.mirror_z = number()? != 0.0,
                    (Section::Spline, "units.len.f") => {
                        let f = number()?;
                        if f <= 0.0 {
                            return Err(parse_error(path, line_no, "units.len.f must be > 0"));
                        }
                        settings.units_per_m = f;
                    }
                    // Other keys (version, comment, smoothing, ...) do not change the points.
                    _ => {}
                }
            }
        }
    }
    let Some((kind, type_line)) = header_type else {
        return Err(parse_error(
            path,
            0,
            "no 'type' in a header.begin section: not a SIMPACK profile",
        ));
    };
    if kind != file_kind {
        return Err(parse_error(
            path,
            type_line,
            format!(
                "the file is a {} profile but its extension says {}",
                kind.as_str(),
                file_kind.as_str()
            ),
        ));
    }
    if let Some(expected) = expected {
        if expected != kind {
            return Err(parse_error(
                path,
                type_line,
                format!(
                    "a {} profile was passed where a {} profile is needed",
                    kind.as_str(),
                    expected.as_str()
                ),
            ));
        }
    }
    if !saw_points_end {
        return Err(parse_error(path, 0, "no point.begin ... point.end section"));
    }
    let s = &settings;
    let mut out = RawPoints::new();
    for i in 0..pts.y.len() {
        let (mut y, mut z) = (pts.y[i] + s.shift_y, pts.z[i] + s.shift_z);
        let inside = |v: f64, (lo, hi): (f64, f64)| lo >= hi || (v >= lo && v <= hi);
        if !inside(y, s.bound_y) || !inside(z, s.bound_z) {
            continue;
        }
        if s.mirror_y {
            y = -y;
        }
        if s.mirror_z {
            z = -z;
        }
        out.y.push(y / s.units_per_m);
        // SIMPACK z points down; the profile frame's z points up.
        out.z.push(-z / s.units_per_m);
        out.line.push(pts.line[i]);
    }
    out.into_profile(path, kind, false)
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

    const SIMPACK_WHEEL: &str = "\
  header.begin
    version = 1
    type    = 1   ! 0=rail profile, 1=wheel profile
  header.end
  spline.begin
    shift.y = +0.0
    mirror.y = 1
    units.len.f = +1.0e+03
    point.begin
    ! y z
!7.0 9.0
   3.0  1.0
   2.0  0.5
   1.0  0.2
   0.0  0.0
  -1.0 -0.1
    point.end
  spline.end
";

    #[test]
    fn simpack_wheel_is_mirrored_scaled_and_z_flipped() {
        let p = parse_simpack(SIMPACK_WHEEL, "w.prw", ProfileKind::Wheel, None).unwrap();
        assert_eq!(p.y().len(), 5);
        // mirror.y: the file's y = 3 mm becomes -3 mm; z down 1 mm becomes z = -1 mm (up frame).
        assert!((p.y()[0] + 3e-3).abs() < 1e-15);
        assert!((p.z()[0] + 1e-3).abs() < 1e-15);
        // The file is a wheel: asking for a rail, or naming it .prr, fails on the type line.
        let e = parse_simpack(
            SIMPACK_WHEEL,
            "w.prw",
            ProfileKind::Wheel,
            Some(ProfileKind::Rail),
        );
        assert!(matches!(e, Err(LocoError::Parse { line: 3, .. })));
        let e = parse_simpack(SIMPACK_WHEEL, "w.prr", ProfileKind::Rail, None);
        assert!(matches!(e, Err(LocoError::Parse { line: 3, .. })));
        let broken = SIMPACK_WHEEL.replace("   2.0  0.5", "   2.0  x");
        assert!(matches!(
            parse_simpack(&broken, "w.prw", ProfileKind::Wheel, None),
            Err(LocoError::Parse { line: 13, .. })
        ));
        let no_header = SIMPACK_WHEEL.replace("type    = 1", "version = 2");
        assert!(parse_simpack(&no_header, "w.prw", ProfileKind::Wheel, None).is_err());
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
