//! Test support shared by the integration tests: locating the reference data of
//! `/work/shared/data` (see its README) without copying it into the repository.

use std::path::PathBuf;

/// The shared reference-data directory: `$LOCO_SHARED_DATA` if set, else the first `shared/data`
/// directory found next to the crate's directory or one of its ancestors (the repository sits at
/// `<root>/main` or `<root>/wt/<name>` with the data at `<root>/shared/data`). `None` when absent:
/// tests then skip with a message.
pub fn shared_data() -> Option<PathBuf> {
    if let Ok(dir) = std::env::var("LOCO_SHARED_DATA") {
        let p = PathBuf::from(dir);
        return p.is_dir().then_some(p);
    }
    let mut dir = Some(PathBuf::from(env!("CARGO_MANIFEST_DIR")));
    while let Some(d) = dir {
        let candidate = d.join("shared").join("data");
        if candidate.is_dir() {
            return Some(candidate);
        }
        dir = d.parent().map(PathBuf::from);
    }
    None
}

/// `shared_data()/relative` if it exists; otherwise prints why the calling test skips.
pub fn shared_file(relative: &str) -> Option<PathBuf> {
    match shared_data() {
        Some(d) if d.join(relative).is_file() => Some(d.join(relative)),
        _ => {
            eprintln!(
                "SKIPPED: reference data `{relative}` not found (set LOCO_SHARED_DATA or place \
                 shared/data next to the repository)"
            );
            None
        }
    }
}
