//! What was made for the directories used most recently, kept for the next
//! program that asks: the programs of a walk come folder by folder, so a
//! folder's listing and subprograms are asked for by the programs in it and
//! then no more, while the cycle directories are asked for by every one.
//! Keeping only the most recent few makes a run's memory independent of how
//! many folders and files it walks; what was dropped is made again if asked
//! for (it is read again from the disk, never wrong).

use std::collections::HashMap;
use std::hash::Hash;
use std::sync::Mutex;

/// Directories kept: as many as a run works on at once (at most 64 programs
/// in flight; they lie in a few folders unless the folders are tiny, and a
/// tiny folder is cheap to read again) and the cycle directories.
const KEPT: usize = 64;

pub(crate) struct Recent<K, V> {
    inner: Mutex<Inner<K, V>>,
}

struct Inner<K, V> {
    /// Each value with the time it was last asked for.
    entries: HashMap<K, (V, u64)>,
    clock: u64,
}

impl<K, V> Default for Recent<K, V> {
    fn default() -> Self {
        Self {
            inner: Mutex::new(Inner {
                entries: HashMap::new(),
                clock: 0,
            }),
        }
    }
}

impl<K: Hash + Eq + Clone, V: Clone> Recent<K, V> {
    /// The value for `key`, made by `make` when it is not kept. Two threads
    /// asking at once may both make it; one is kept.
    pub(crate) fn get_or_make<E>(
        &self,
        key: &K,
        make: impl FnOnce() -> Result<V, E>,
    ) -> Result<V, E> {
        if let Some(known) = self.get(key) {
            return Ok(known);
        }
        let made = make()?;
        if let Ok(mut inner) = self.inner.lock() {
            if inner.entries.len() >= KEPT {
                // The least recently asked for goes: a scan, once for each
                // directory made, not for each one asked.
                let oldest = inner
                    .entries
                    .iter()
                    .min_by_key(|(_, (_, used))| *used)
                    .map(|(key, _)| key.clone());
                if let Some(oldest) = oldest {
                    inner.entries.remove(&oldest);
                }
            }
            inner.clock += 1;
            let now = inner.clock;
            inner.entries.insert(key.clone(), (made.clone(), now));
        }
        Ok(made)
    }

    /// Keeps `value` for `key`, as [`Self::get_or_make`] keeps what it made.
    pub(crate) fn insert(&self, key: &K, value: V) {
        let _ = self.get_or_make(key, || Ok::<V, ()>(value));
    }

    pub(crate) fn get(&self, key: &K) -> Option<V> {
        let mut inner = self.inner.lock().ok()?;
        inner.clock += 1;
        let now = inner.clock;
        let (value, used) = inner.entries.get_mut(key)?;
        *used = now;
        Some(value.clone())
    }

    #[cfg(test)]
    fn len(&self) -> usize {
        self.inner.lock().map_or(0, |inner| inner.entries.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_least_recently_used_goes_and_is_made_again_when_asked() {
        let recent: Recent<usize, usize> = Recent::default();
        let made = std::cell::Cell::new(0);
        let ask = |key: usize| {
            recent
                .get_or_make(&key, || {
                    made.set(made.get() + 1);
                    Ok::<_, ()>(key * 10)
                })
                .expect("made")
        };
        // One key asked for all along (a cycle directory), many once each.
        for key in 1..=10 * KEPT {
            assert_eq!(ask(0), 0);
            assert_eq!(ask(key), key * 10);
        }
        assert_eq!(recent.len(), KEPT);
        // Key 0 was never dropped: made once, and once for each other key.
        assert_eq!(made.get(), 1 + 10 * KEPT);
        // The first of the others was dropped, and is made again.
        assert_eq!(ask(1), 10);
        assert_eq!(made.get(), 2 + 10 * KEPT);
    }

    #[test]
    fn an_error_is_not_kept() {
        let recent: Recent<&str, u8> = Recent::default();
        assert_eq!(recent.get_or_make(&"a", || Err("no")), Err("no"));
        assert_eq!(recent.get_or_make(&"a", || Ok::<_, &str>(1)), Ok(1));
    }
}
