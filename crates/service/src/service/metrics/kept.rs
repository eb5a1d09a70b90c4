//! Handles of the per-request series, kept by their labels.
//!
//! `prometheus-client`'s `Family::get_or_create` takes a read lock on the
//! family, hashes the whole label set with std's SipHash and, for a request
//! series, needs the route as an owned `String`. Every request did that
//! seven times (its count and duration, its bytes, four stage durations):
//! about 1 % of a fresh icon's instructions and more of a cached GET's
//! (issue 33). A series handle is a shared pointer to the family's own
//! metric (cloning a `Counter` or `Histogram` shares its value), so the
//! handles are looked up once per label set and kept here, under foldhash
//! and, for requests, without allocating the route.
//!
//! Bounded: every label comes from a fixed set (routes the router knows or
//! `unmatched`, gRPC methods, statuses, stages, languages, formats; module
//! `metrics` says so), so the maps stay as small as the families.

use crate::core::timing::Phase;
use crate::export::Format;
use crate::lang::Language;
use prometheus_client::metrics::counter::Counter;
use prometheus_client::metrics::histogram::Histogram;
use std::collections::HashMap;
use std::sync::RwLock;

type Fold = foldhash::fast::RandomState;

/// One request series: its protocol and status (the route is the map's
/// key), and the handles of its count and duration.
#[derive(Debug)]
struct RequestSeries {
    protocol: &'static str,
    status: u16,
    count: Counter,
    seconds: Histogram,
}

/// Handles kept by a small, `Copy` label key.
#[derive(Debug)]
struct ByKey<K, M>(RwLock<HashMap<K, M, Fold>>);

impl<K, M> Default for ByKey<K, M> {
    fn default() -> Self {
        ByKey(RwLock::default())
    }
}

impl<K: std::hash::Hash + Eq + Copy, M: Clone> ByKey<K, M> {
    /// The handle of `key`, made by `make` (the family's `get_or_create`)
    /// the first time. A poisoned lock (a panic while holding it) only
    /// costs the shortcut.
    fn get(&self, key: K, make: impl FnOnce() -> M) -> M {
        if let Some(m) = self.0.read().ok().and_then(|map| map.get(&key).cloned()) {
            return m;
        }
        let m = make();
        if let Ok(mut map) = self.0.write() {
            map.entry(key).or_insert_with(|| m.clone());
        }
        m
    }
}

/// Kept handles of the request, response-bytes and stage series.
#[derive(Debug, Default)]
pub(super) struct Kept {
    /// By route, then (protocol, status) in the route's short list: keyed
    /// by the borrowed route, a lookup allocates nothing.
    requests: RwLock<HashMap<String, Vec<RequestSeries>, Fold>>,
    bytes: ByKey<(&'static str, Format), Counter>,
    stages: ByKey<(Phase, Language, Format), Histogram>,
}

impl Kept {
    /// The count and duration handles of (`protocol`, `route`, `status`),
    /// made by `make` (the families' `get_or_create`) the first time.
    pub(super) fn request(&self, protocol: &'static str, route: &str, status: u16, make: impl FnOnce() -> (Counter, Histogram)) -> (Counter, Histogram) {
        let this = |s: &RequestSeries| s.protocol == protocol && s.status == status;
        // A poisoned lock (a panic while holding it) only costs the shortcut.
        if let Some(handles) = self.requests.read().ok().and_then(|m| m.get(route).and_then(|list| list.iter().find(|s| this(s)).map(|s| (s.count.clone(), s.seconds.clone())))) {
            return handles;
        }
        let (count, seconds) = make();
        if let Ok(mut m) = self.requests.write() {
            let list = m.entry(route.to_string()).or_default();
            if !list.iter().any(this) {
                list.push(RequestSeries { protocol, status, count: count.clone(), seconds: seconds.clone() });
            }
        }
        (count, seconds)
    }

    /// The response-bytes handle of (`protocol`, `format`), made by `make`
    /// the first time.
    pub(super) fn bytes(&self, protocol: &'static str, format: Format, make: impl FnOnce() -> Counter) -> Counter {
        self.bytes.get((protocol, format), make)
    }

    /// The duration handle of (`stage`, `language`, `format`), made by
    /// `make` the first time.
    pub(super) fn stage(&self, stage: Phase, language: Language, format: Format, make: impl FnOnce() -> Histogram) -> Histogram {
        self.stages.get((stage, language, format), make)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// A label set is made once; its kept handles share the first ones'
    /// values; another protocol, status or route gets series of its own.
    #[test]
    fn each_label_set_is_made_once_and_shares_its_values() {
        let kept = Kept::default();
        let made = Cell::new(0);
        let make = || {
            made.set(made.get() + 1);
            (Counter::default(), Histogram::new([1.0]))
        };
        let (first, _) = kept.request("http", "/v1/render", 200, make);
        for _ in 0..3 {
            let (c, _) = kept.request("http", "/v1/render", 200, make);
            c.inc();
        }
        assert_eq!(made.get(), 1);
        assert_eq!(first.get(), 3, "the kept handle counts into the first");
        kept.request("http", "/v1/render", 422, make);
        kept.request("grpc", "/v1/render", 200, make);
        kept.request("http", "/v1/grammars", 200, make);
        assert_eq!(made.get(), 4);
        let stage_made = Cell::new(0);
        let make_stage = || {
            stage_made.set(stage_made.get() + 1);
            Histogram::new([1.0])
        };
        kept.stage(Phase::Eval, Language::Mdg, Format::Glb, make_stage);
        kept.stage(Phase::Eval, Language::Mdg, Format::Glb, make_stage);
        kept.stage(Phase::Export, Language::Mdg, Format::Glb, make_stage);
        assert_eq!(stage_made.get(), 2);
        let bytes_made = Cell::new(0);
        let make_bytes = || {
            bytes_made.set(bytes_made.get() + 1);
            Counter::default()
        };
        kept.bytes("http", Format::Glb, make_bytes).inc_by(5);
        assert_eq!(kept.bytes("http", Format::Glb, make_bytes).get(), 5, "the kept handle counts into the first");
        kept.bytes("grpc", Format::Glb, make_bytes);
        assert_eq!(bytes_made.get(), 2);
    }
}
