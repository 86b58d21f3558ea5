//! Comma-separated tables of a header row of column names and rows of cells, as the curve-section
//! files (`track::design_input`) and the batch binary's samples files are read: blank lines and
//! `#` comments skipped, cells trimmed, every row as long as the header, and every error naming
//! the file and the 1-based line (0: the file as a whole).
//!
//! Measured irregularity files (`track::measured`) are not tables of this kind: their header is
//! optional and their columns fixed by position.

use crate::error::{FileKind, LocoError, Result};

/// A table split into cells (no cell interpreted yet).
#[derive(Debug, Clone, PartialEq)]
pub struct CsvTable<'a> {
    path: &'a str,
    kind: FileKind,
    /// Column names, trimmed.
    pub names: Vec<&'a str>,
    /// 1-based line of the header.
    pub header_line: usize,
    /// Data rows: 1-based line and one trimmed cell per column.
    pub rows: Vec<(usize, Vec<&'a str>)>,
}

impl<'a> CsvTable<'a> {
    /// Splits `text`, the content of the file `path` (a file of `kind`). Errors: no header row, an empty column
    /// name, a row with more or fewer cells than the header has names.
    pub fn parse(text: &'a str, path: &'a str, kind: FileKind) -> Result<Self> {
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let error = |line: usize, reason: String| parse_error(kind, path, line, reason);
        let (header_line, header) = lines.next().ok_or_else(|| {
            error(
                0,
                "empty file: expected a header row of column names".into(),
            )
        })?;
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        if names.iter().any(|n| n.is_empty()) {
            return Err(error(header_line, "empty column name in the header".into()));
        }
        let mut rows = Vec::new();
        for (line, text) in lines {
            let cells: Vec<&str> = text.split(',').map(str::trim).collect();
            if cells.len() != names.len() {
                return Err(error(
                    line,
                    format!("{} cells for {} columns", cells.len(), names.len()),
                ));
            }
            rows.push((line, cells));
        }
        Ok(Self {
            path,
            kind,
            names,
            header_line,
            rows,
        })
    }

    /// A parse error at `line` of the table's file.
    pub fn error(&self, line: usize, reason: impl Into<String>) -> LocoError {
        parse_error(self.kind, self.path, line, reason)
    }
}

fn parse_error(kind: FileKind, path: &str, line: usize, reason: impl Into<String>) -> LocoError {
    LocoError::parse(kind, path, line, reason)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_counted_in_the_file_with_comments_and_blanks() {
        let text = "# a comment\n\n a , b \n1, 2\n\n# more\n3,4\n";
        let t = CsvTable::parse(text, "f.csv", FileKind::Study).unwrap();
        assert_eq!(t.names, ["a", "b"]);
        assert_eq!(t.header_line, 3);
        assert_eq!(t.rows, [(4, vec!["1", "2"]), (7, vec!["3", "4"])]);
    }

    #[test]
    fn bad_tables_name_file_and_line() {
        let e = CsvTable::parse("# only a comment\n", "f.csv", FileKind::Study).unwrap_err();
        assert!(e.to_string().contains("f.csv:0: empty file"), "{e}");
        let e = CsvTable::parse("# c\na,,b\n", "f.csv", FileKind::Study).unwrap_err();
        assert!(e.to_string().contains("f.csv:2: empty column name"), "{e}");
        let e = CsvTable::parse("a,b\n1,2\n1,2,3\n", "f.csv", FileKind::Study).unwrap_err();
        assert!(
            e.to_string().contains("f.csv:3: 3 cells for 2 columns"),
            "{e}"
        );
    }
}
