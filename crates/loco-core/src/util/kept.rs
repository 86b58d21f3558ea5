//! Results of pure builds kept for reuse within the process, keyed by their inputs.
//!
//! Why: a campaign hands the native side one chunk of samples at a time, each on fresh native
//! objects, and a study's samples differ only in parameters that most expensive builds do not
//! read (the contact table, the exponential scheme's propagators). A build that is a function of
//! its inputs alone is kept and handed out again for the same inputs, so results stay
//! bit-identical, on local threads and on every Dask worker process alike (each keeps its own).
//!
//! Keys are the inputs' `Debug` text, compared exactly: it writes each `f64` so that it reads
//! back to the same bits (and tells −0.0 from 0.0). Each store keeps its last `capacity`
//! results, the most recently used first.

use crate::error::Result;
use std::sync::{Arc, Mutex, MutexGuard};

/// A store of at most `capacity` built values.
pub struct Kept<T> {
    capacity: usize,
    entries: Mutex<Vec<(String, Arc<T>)>>,
}

impl<T> Kept<T> {
    /// An empty store (usable in a `static`).
    pub const fn new(capacity: usize) -> Self {
        Self {
            capacity,
            entries: Mutex::new(Vec::new()),
        }
    }

    /// The value kept for `key`, or `build()`, then kept.
    pub fn get_or_build(&self, key: String, build: impl FnOnce() -> T) -> Arc<T> {
        match self.get_or_try_build(key, || Ok(build())) {
            Ok(value) => value,
            Err(_) => unreachable!("the build cannot fail"),
        }
    }

    /// The value kept for `key`, or `build()`, then kept (an error is not). Two threads asking
    /// for a new key at once may both build it; either build is the same.
    pub fn get_or_try_build(
        &self,
        key: String,
        build: impl FnOnce() -> Result<T>,
    ) -> Result<Arc<T>> {
        if let Some(hit) = self.take(&key) {
            return Ok(hit);
        }
        let built = Arc::new(build()?);
        let mut entries = self.lock();
        entries.retain(|(k, _)| *k != key);
        entries.insert(0, (key, Arc::clone(&built)));
        entries.truncate(self.capacity);
        Ok(built)
    }

    /// Number of values kept.
    pub fn len(&self) -> usize {
        self.lock().len()
    }

    /// Whether nothing is kept.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The kept value for `key`, moved to the front.
    fn take(&self, key: &str) -> Option<Arc<T>> {
        let mut entries = self.lock();
        let i = entries.iter().position(|(k, _)| k == key)?;
        let entry = entries.remove(i);
        let hit = Arc::clone(&entry.1);
        entries.insert(0, entry);
        Some(hit)
    }

    fn lock(&self) -> MutexGuard<'_, Vec<(String, Arc<T>)>> {
        // A panic elsewhere while holding the lock leaves the list itself consistent.
        self.entries
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::LocoError;

    #[test]
    fn a_key_is_built_once_and_the_least_recently_used_goes_first() {
        let kept = Kept::new(2);
        let builds = std::cell::Cell::new(0);
        let get = |key: f64| {
            *kept.get_or_build(format!("{key:?}"), || {
                builds.set(builds.get() + 1);
                2.0 * key
            })
        };
        assert_eq!(get(1.0), 2.0);
        assert_eq!(get(1.0), 2.0);
        assert_eq!(get(0.0), 0.0);
        // −0.0 is another input than 0.0.
        assert_eq!(get(-0.0).to_bits(), (-0.0f64).to_bits());
        assert_eq!(builds.get(), 3);
        // 1.0 was used least recently and went; −0.0 and 0.0 are still kept.
        get(0.0);
        get(-0.0);
        assert_eq!(builds.get(), 3);
        get(1.0);
        assert_eq!(builds.get(), 4);
    }

    #[test]
    fn a_failed_build_is_not_kept() {
        let kept: Kept<f64> = Kept::new(4);
        let failed = kept.get_or_try_build("k".into(), || Err(LocoError::param("x", "failed")));
        assert!(failed.is_err());
        assert!(kept.is_empty());
        assert_eq!(*kept.get_or_build("k".into(), || 1.0), 1.0);
        assert_eq!(kept.len(), 1);
    }
}
