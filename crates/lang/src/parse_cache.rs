//! Parsed programs kept by source, so that a library grammar or a source
//! sent again is parsed once per process (issue 33).
//!
//! A fresh icon render of the library's `gem` spent as much time parsing its
//! 1 KB of source as evaluating it: parsing is a pure function of the source
//! bytes (a request's seed and parameters are bound afterwards), so its
//! result can be shared by every render of the same source. The cache is
//! bounded by entries and by the bytes of the sources it holds (a parsed
//! program's size grows with its source's), and a source over
//! [`MAX_SOURCE`] is never kept. When full, the entry used longest ago is
//! dropped. A hit compares the whole source, not only its hash, so two
//! sources never share a program.
//!
//! What is kept is process memory outside any request's budget, as the
//! service's model cache is: at most [`MAX_BYTES`] of source and what
//! their programs hold. Failures are not kept (a bad source is parsed again
//! and gives the same error).

use std::collections::HashMap;
use std::hash::BuildHasher as _;
use std::sync::{Arc, Mutex};

/// The most programs kept.
pub(crate) const MAX_ENTRIES: usize = 512;

/// The most source bytes kept, over all entries.
pub const MAX_BYTES: usize = 16 << 20;

/// The largest source kept.
pub const MAX_SOURCE: usize = 1 << 20;

/// A bounded cache of values parsed from source bytes.
#[derive(Debug)]
pub(crate) struct ParseCache<T> {
    inner: Mutex<Inner<T>>,
    /// Hashes sources to their keys: foldhash under a seed of the
    /// process's own, not std's SipHash, which hashed every render's whole
    /// source (about 1 % of a fresh icon's instructions, issue 33). The
    /// seed keeps a colliding source from being made in advance (it would
    /// only evict the other's entry: a hit compares the whole source).
    hasher: foldhash::fast::RandomState,
}

#[derive(Debug)]
struct Inner<T> {
    entries: HashMap<u64, Entry<T>>,
    bytes: usize,
    clock: u64,
}

#[derive(Debug)]
struct Entry<T> {
    source: Arc<[u8]>,
    value: Arc<T>,
    used: u64,
}

impl<T> Default for ParseCache<T> {
    fn default() -> Self {
        ParseCache { inner: Mutex::new(Inner { entries: HashMap::new(), bytes: 0, clock: 0 }), hasher: foldhash::fast::RandomState::default() }
    }
}

impl<T> ParseCache<T> {
    /// The value parsed from `source`: kept from an earlier call, or made by
    /// `parse` now (and kept when it succeeds and the source is small enough).
    pub(crate) fn get_or_parse<E>(&self, source: &[u8], parse: impl FnOnce(&[u8]) -> Result<T, E>) -> Result<Arc<T>, E> {
        // A source too big to keep is never found either: no hash, no lock.
        if source.len() > MAX_SOURCE {
            return parse(source).map(Arc::new);
        }
        let key = self.hasher.hash_one(source);
        if let Some(v) = self.lookup(key, source) {
            return Ok(v);
        }
        let value = Arc::new(parse(source)?);
        self.keep(key, source, value.clone());
        Ok(value)
    }

    fn lookup(&self, key: u64, source: &[u8]) -> Option<Arc<T>> {
        let mut inner = self.inner.lock().ok()?;
        inner.clock += 1;
        let now = inner.clock;
        let e = inner.entries.get_mut(&key)?;
        if &*e.source != source {
            return None;
        }
        e.used = now;
        Some(e.value.clone())
    }

    fn keep(&self, key: u64, source: &[u8], value: Arc<T>) {
        let Ok(mut inner) = self.inner.lock() else { return };
        if let Some(old) = inner.entries.remove(&key) {
            inner.bytes -= old.source.len();
        }
        while !inner.entries.is_empty() && (inner.entries.len() >= MAX_ENTRIES || inner.bytes + source.len() > MAX_BYTES) {
            let Some(oldest) = inner.entries.iter().min_by_key(|(_, e)| e.used).map(|(k, _)| *k) else { break };
            if let Some(e) = inner.entries.remove(&oldest) {
                inner.bytes -= e.source.len();
            }
        }
        inner.clock += 1;
        let used = inner.clock;
        inner.bytes += source.len();
        inner.entries.insert(key, Entry { source: Arc::from(source), value, used });
    }

    /// How many programs are kept (for tests).
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.inner.lock().map_or(0, |i| i.entries.len())
    }

    /// Whether nothing is kept.
    #[cfg(test)]
    pub(crate) fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    #[test]
    fn a_source_is_parsed_once_and_a_failure_again() {
        let cache = ParseCache::<String>::default();
        let calls = Cell::new(0);
        let parse = |s: &[u8]| -> Result<String, ()> {
            calls.set(calls.get() + 1);
            if s == b"bad" {
                Err(())
            } else {
                Ok(String::from_utf8_lossy(s).into_owned())
            }
        };
        assert_eq!(*cache.get_or_parse(b"rule A {}", parse).unwrap(), "rule A {}");
        assert_eq!(*cache.get_or_parse(b"rule A {}", parse).unwrap(), "rule A {}");
        assert_eq!(calls.get(), 1, "the second call is a hit");
        assert!(cache.get_or_parse(b"bad", parse).is_err());
        assert!(cache.get_or_parse(b"bad", parse).is_err());
        assert_eq!(calls.get(), 3, "failures are not kept");
        assert_eq!(cache.len(), 1);
    }

    #[test]
    fn the_cache_stays_within_its_entries_and_drops_the_oldest() {
        let cache = ParseCache::<usize>::default();
        for i in 0..MAX_ENTRIES + 5 {
            let s = format!("source {i}");
            cache.get_or_parse(s.as_bytes(), |b| Ok::<_, ()>(b.len())).unwrap();
            if i >= 1 {
                // Source 0 is used after each insertion, so it is never the oldest.
                cache.get_or_parse(b"source 0", |_| Err::<usize, ()>(())).unwrap();
            }
        }
        assert_eq!(cache.len(), MAX_ENTRIES);
        assert!(cache.get_or_parse(b"source 0", |_| Err::<usize, ()>(())).is_ok(), "the source used last is kept");
        assert!(cache.get_or_parse(b"source 1", |_| Err::<usize, ()>(())).is_err(), "the oldest was dropped");
    }

    #[test]
    fn big_sources_are_not_kept() {
        let cache = ParseCache::<usize>::default();
        let big = vec![b'x'; MAX_SOURCE + 1];
        cache.get_or_parse(&big, |b| Ok::<_, ()>(b.len())).unwrap();
        assert!(cache.is_empty());
    }
}
