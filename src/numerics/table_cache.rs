//! A process-wide cache of tables built once per value of one parameter: the journal bearing's
//! table per L/D ([`crate::journal::JournalTable`]) and the clearance's Jₙ table per flow index
//! ([`crate::clearance::PowerLawTable`]). Keyed by the parameter's bits (so −0.0 and 0.0, or
//! two NaNs of different payloads, are different keys; a bad value is refused by the builder
//! before anything is stored), bounded: emptied when full, tables in use live on through their
//! [`Arc`].

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard, OnceLock, PoisonError};

/// Tables of type `T` by the bits of their parameter, at most `max` of them (for a `static`).
#[derive(Debug)]
pub struct TableCache<T> {
    map: OnceLock<Mutex<HashMap<u64, Arc<T>>>>,
    max: usize,
}

impl<T> TableCache<T> {
    /// An empty cache that keeps at most `max` tables.
    pub const fn new(max: usize) -> Self {
        Self { map: OnceLock::new(), max }
    }

    /// The table of `key`, built by `build(key)` on first use (outside the lock, so a slow
    /// build does not hold up lookups of other keys; when two threads build the same key at
    /// once, the first stored wins and both get it). A build error is returned and nothing is
    /// stored.
    pub fn get_or_build<E>(&self, key: f64, build: impl FnOnce(f64) -> Result<T, E>) -> Result<Arc<T>, E> {
        let bits = key.to_bits();
        if let Some(t) = self.lock().get(&bits) {
            return Ok(Arc::clone(t));
        }
        let table = Arc::new(build(key)?);
        let mut map = self.lock();
        if map.len() >= self.max {
            map.clear();
        }
        Ok(Arc::clone(map.entry(bits).or_insert(table)))
    }

    /// The map, locked. A poisoned lock only means another thread panicked while holding it:
    /// the map is still a valid map, so go on with it.
    fn lock(&self) -> MutexGuard<'_, HashMap<u64, Arc<T>>> {
        self.map.get_or_init(|| Mutex::new(HashMap::new())).lock().unwrap_or_else(PoisonError::into_inner)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    #[test]
    fn builds_once_per_key_refuses_errors_and_empties_when_full() {
        let cache: TableCache<f64> = TableCache::new(2);
        let builds = Cell::new(0);
        let build = |k: f64| -> Result<f64, String> {
            builds.set(builds.get() + 1);
            if k.is_nan() { Err(format!("bad key {k}")) } else { Ok(2.0 * k) }
        };
        let a = cache.get_or_build(1.0, build).unwrap();
        let b = cache.get_or_build(1.0, build).unwrap();
        assert!(Arc::ptr_eq(&a, &b) && *a == 2.0 && builds.get() == 1);
        assert_eq!(cache.get_or_build(f64::NAN, build).unwrap_err(), "bad key NaN");
        assert_eq!(cache.lock().len(), 1, "an error stores nothing");
        // By bits: −0.0 is another key than 0.0.
        cache.get_or_build(0.0, build).unwrap();
        assert_eq!(cache.lock().len(), 2);
        let n = builds.get();
        cache.get_or_build(-0.0, build).unwrap();
        assert_eq!(builds.get(), n + 1);
        // Full (2 tables): emptied before the third is stored; the table in use lives on.
        assert_eq!(cache.lock().len(), 1);
        assert_eq!(*a, 2.0);
        let c = cache.get_or_build(1.0, build).unwrap();
        assert!(!Arc::ptr_eq(&a, &c) && *c == 2.0, "rebuilt after the cache was emptied");
    }
}
