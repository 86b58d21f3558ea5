//! Verification records: what a case measured against its reference, written by the test that
//! measures it into `docs/verification/records/<case>.json`, from which
//! `scripts/docs/verification_docs.py` generates the Verification page.
//!
//! Each value is stored rounded to the significant digits the page shows, so a record changes
//! only when a result does. In a normal run [`Record::check`] compares what the test measured
//! with the committed record and fails, naming the case and the quantities that differ, when they
//! differ; with `LOCO_UPDATE_RECORDS=1` it rewrites the record instead. Results are bit-identical
//! for any thread count, so the comparison is stable. The test's own assertion against its
//! reference stays in the test; the record is in addition.

use std::fmt::Write as _;
use std::path::PathBuf;

/// One measured quantity: its value as the page shows it, its unit and the tolerance the test
/// asserts (if it asserts one on this quantity).
struct Quantity {
    key: String,
    value: String,
    unit: String,
    tolerance: Option<String>,
}

/// The record of one verification case, built by the test and checked (or written) at its end.
pub struct Record {
    case: String,
    test: String,
    quantities: Vec<Quantity>,
}

/// `value` rounded to `digits` significant digits, in plain notation between 1e-4 and 1e6 and in
/// exponent notation outside (both are JSON numbers and read back as the same value).
pub fn significant(value: f64, digits: usize) -> String {
    assert!(digits >= 1, "a record shows at least one digit");
    if !value.is_finite() {
        return "NaN".to_string();
    }
    if value == 0.0 {
        return "0".to_string();
    }
    let exponent = value.abs().log10().floor() as i32;
    // Rounding can carry into the next decade (9.96 at 2 digits is 10): format in exponent
    // notation first, whose mantissa rounding is exact, and read the decade back from it.
    let scientific = format!("{:.*e}", digits - 1, value);
    let decade: i32 = scientific
        .split('e')
        .nth(1)
        .and_then(|e| e.parse().ok())
        .unwrap_or(exponent);
    if (-4..6).contains(&decade) {
        let decimals = (digits as i32 - 1 - decade).max(0) as usize;
        let rounded: f64 = scientific.parse().unwrap_or(value);
        format!("{:.*}", decimals, rounded)
    } else {
        scientific
    }
}

/// A tolerance's limit with the fewest significant digits (up to 6) that give it back (0.01,
/// 1e-9), or with 3 for a limit computed from other values.
pub fn limit_text(limit: f64) -> String {
    (1..=6)
        .map(|digits| significant(limit, digits))
        .find(|text| text.parse::<f64>().ok() == Some(limit))
        .unwrap_or_else(|| significant(limit, 3))
}

fn json_string(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

impl Record {
    /// A record of `case` (its file name), measured by the test in `test` (pass `file!()`).
    pub fn new(case: &str, test: &str) -> Self {
        assert!(
            !case.is_empty()
                && case
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_'),
            "a case id is lower-case letters, digits and underscores: {case:?}"
        );
        Self {
            case: case.to_string(),
            test: test.replace('\\', "/"),
            quantities: Vec::new(),
        }
    }

    fn push(mut self, key: &str, value: String, unit: &str, tolerance: Option<String>) -> Self {
        assert!(
            self.quantities.iter().all(|q| q.key != key),
            "{}: quantity {key} recorded twice",
            self.case
        );
        self.quantities.push(Quantity {
            key: key.to_string(),
            value,
            unit: unit.to_string(),
            tolerance,
        });
        self
    }

    /// A measured value (in `unit`, "" for a ratio) shown with `digits` significant digits.
    pub fn value(self, key: &str, value: f64, unit: &str, digits: usize) -> Self {
        self.push(key, significant(value, digits), unit, None)
    }

    /// A measured value with the tolerance the test asserts on it (`relation` as the page reads
    /// it, such as "≤" or "≥", and the limit in the value's unit).
    pub fn within(
        self,
        key: &str,
        value: f64,
        unit: &str,
        digits: usize,
        relation: &str,
        limit: f64,
    ) -> Self {
        let tolerance = format!("{relation} {}", limit_text(limit));
        self.push(key, significant(value, digits), unit, Some(tolerance))
    }

    /// A value expected at round-off level (a residual, an error against an exact closed form):
    /// recorded as "< floor" when smaller than `floor`, so that the last bits of a library's
    /// arithmetic do not change the record, and with one significant digit above it.
    pub fn below(
        self,
        key: &str,
        value: f64,
        unit: &str,
        floor: f64,
        relation: &str,
        limit: f64,
    ) -> Self {
        let shown = if value.abs() < floor {
            format!("< {}", significant(floor, 1))
        } else {
            significant(value, 1)
        };
        let tolerance = format!("{relation} {}", limit_text(limit));
        self.push(key, shown, unit, Some(tolerance))
    }

    /// A count (of samples, points, bins, bits that differ ...).
    pub fn count(self, key: &str, n: usize) -> Self {
        self.push(key, n.to_string(), "", None)
    }

    /// A value that is a name (a status, a mode), recorded as it reads.
    pub fn label(self, key: &str, value: &str) -> Self {
        self.push(key, value.to_string(), "", None)
    }

    /// The record as its file holds it.
    fn render(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "{{");
        let _ = writeln!(out, "  \"case\": {},", json_string(&self.case));
        let _ = writeln!(out, "  \"test\": {},", json_string(&self.test));
        let _ = writeln!(out, "  \"quantities\": [");
        for (i, q) in self.quantities.iter().enumerate() {
            let tolerance = q
                .tolerance
                .as_deref()
                .map_or("null".to_string(), json_string);
            let comma = if i + 1 < self.quantities.len() {
                ","
            } else {
                ""
            };
            let _ = writeln!(
                out,
                "    {{\"key\": {}, \"value\": {}, \"unit\": {}, \"tolerance\": {}}}{comma}",
                json_string(&q.key),
                json_string(&q.value),
                json_string(&q.unit),
                tolerance
            );
        }
        let _ = writeln!(out, "  ]");
        let _ = writeln!(out, "}}");
        out
    }

    fn path(&self) -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../docs/verification/records")
            .join(format!("{}.json", self.case))
    }

    /// Compares the record with the committed one and fails when they differ, or writes it when
    /// `LOCO_UPDATE_RECORDS=1`.
    pub fn check(self) {
        let path = self.path();
        let update = std::env::var("LOCO_UPDATE_RECORDS").as_deref() == Ok("1");
        self.check_at(&path, update);
    }

    /// [`Record::check`] against the record at `path`, rewriting it when `update`.
    fn check_at(self, path: &std::path::Path, update: bool) {
        let text = self.render();
        let committed = std::fs::read_to_string(path).unwrap_or_default();
        if update {
            if committed != text {
                std::fs::write(path, &text)
                    .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
            }
            return;
        }
        if committed != text {
            let changed: Vec<String> = self
                .quantities
                .iter()
                .filter(|q| {
                    !committed.contains(&format!(
                        "\"key\": {}, \"value\": {}",
                        json_string(&q.key),
                        json_string(&q.value)
                    ))
                })
                .map(|q| format!("{} = {}", q.key, q.value))
                .collect();
            panic!(
                "verification record {} is stale ({}; now {}): rerun the test with \
                 LOCO_UPDATE_RECORDS=1 and commit the record, then python \
                 scripts/docs/verification_docs.py --write",
                self.case,
                path.display(),
                if changed.is_empty() {
                    "its layout changed".to_string()
                } else {
                    changed.join(", ")
                }
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same cases as `tests/api/test_verification_page.py` checks for the Python writer, so the
    /// two write the same text for the same value.
    #[test]
    fn values_are_rounded_to_their_significant_digits() {
        for (value, digits, text) in [
            (0.0062, 2, "0.0062"),
            (9.96, 2, "10"),
            (34.2, 3, "34.2"),
            (6123.0, 2, "6100"),
            (1234567.0, 3, "1.23e6"),
            (-0.000123, 2, "-0.00012"),
            (1.234e-5, 3, "1.23e-5"),
            (0.0, 3, "0"),
        ] {
            assert_eq!(significant(value, digits), text, "{value} at {digits}");
        }
        assert_eq!(limit_text(0.01), "0.01");
        assert_eq!(limit_text(1e-9), "1e-9");
        assert_eq!(limit_text(1.1 * 0.0093503), "0.0103");
    }

    #[test]
    fn a_stale_record_fails_naming_the_case_and_an_update_rewrites_it() {
        let dir = std::env::temp_dir().join(format!("loco-record-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("example.json");
        let _ = std::fs::remove_file(&path);
        let measured =
            |value: f64| Record::new("example", "tests/x.rs").value("error", value, "", 2);
        let stale = |value: f64| {
            let p = path.clone();
            std::panic::catch_unwind(move || measured(value).check_at(&p, false))
                .err()
                .and_then(|e| e.downcast_ref::<String>().cloned())
        };
        let missing = stale(0.0042).expect("a missing record is stale");
        assert!(
            missing.contains("verification record example is stale"),
            "{missing}"
        );
        measured(0.0042).check_at(&path, true);
        assert!(std::fs::read_to_string(&path)
            .unwrap()
            .contains("\"value\": \"0.0042\""));
        assert_eq!(
            stale(0.0042),
            None,
            "the same measurement matches its record"
        );
        assert_eq!(stale(0.00421), None, "so does one that rounds the same");
        let changed = stale(0.0043).expect("another value is stale");
        assert!(changed.contains("error = 0.0043"), "{changed}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_record_reads_as_json_with_its_quantities_in_order() {
        let text = Record::new("example", "tests/x.rs")
            .value("a", 0.5, "m", 2)
            .within("b", 0.004, "", 1, "<", 0.01)
            .below("c", 1e-17, "", 1e-12, "<", 1e-9)
            .count("n", 3)
            .render();
        assert!(text.contains("\"case\": \"example\""), "{text}");
        assert!(
            text.contains(
                "{\"key\": \"b\", \"value\": \"0.004\", \"unit\": \"\", \"tolerance\": \"< 0.01\"}"
            ),
            "{text}"
        );
        assert!(text.contains("\"value\": \"< 1e-12\""), "{text}");
        let keys: Vec<usize> = ["\"a\"", "\"b\"", "\"c\"", "\"n\""]
            .iter()
            .map(|k| text.find(k).unwrap())
            .collect();
        assert!(keys.windows(2).all(|w| w[0] < w[1]));
    }
}
