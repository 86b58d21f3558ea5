//! SIMPACK profile files: `.prw` (wheel) and `.prr` (rail).
//!
//! The header's `type` (0 rail, 1 wheel) must agree with the extension and with the kind asked
//! for. The point section's coordinates are processed as SIMPACK documents in the file's own
//! header comments, in its order: shift (`shift.y`, `shift.z`), rotation (only 0 is supported:
//! its sign convention is not documented in the file), bounds (`bound.*`, active when min < max),
//! mirroring (`mirror.y`, `mirror.z`), units (`units.len.f` = user units per m). SIMPACK profiles
//! have z **down**, so z is negated at the end. `!` starts comments.

use super::profile::{Profile, ProfileKind};
use super::profile_io::{parse_error, parse_number, RawPoints};
use crate::error::Result;

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
    use crate::error::LocoError;

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
}
