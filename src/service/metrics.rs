//! Prometheus metrics, hand-written text exposition over atomics.

use crate::cache::ModelCache;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::atomic::{AtomicI64, AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::Duration;

/// Upper bounds (seconds) of the render latency histogram buckets.
const BUCKETS: [f64; 14] = [0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 30.0];

/// Every counter and gauge the service exports.
#[derive(Debug, Default)]
pub struct Metrics {
    requests: Mutex<BTreeMap<(String, String, u16), u64>>,
    latency_buckets: [AtomicU64; BUCKETS.len()],
    latency_sum_us: AtomicU64,
    latency_count: AtomicU64,
    renders: AtomicU64,
    cache_hits: AtomicU64,
    cache_misses: AtomicU64,
    rejections: Mutex<BTreeMap<&'static str, u64>>,
    truncations: Mutex<BTreeMap<&'static str, u64>>,
    in_flight: AtomicI64,
    queued: AtomicI64,
    shed: AtomicU64,
}

impl Metrics {
    /// Counts one finished request (`protocol` is `http` or `grpc`).
    pub fn request(&self, protocol: &str, route: &str, status: u16) {
        if let Ok(mut m) = self.requests.lock() {
            *m.entry((protocol.to_string(), route.to_string(), status)).or_default() += 1;
        }
    }

    /// Records one pipeline run and its duration.
    pub fn render_done(&self, took: Duration) {
        self.renders.fetch_add(1, Ordering::Relaxed);
        let secs = took.as_secs_f64();
        for (i, b) in BUCKETS.iter().enumerate() {
            if secs <= *b {
                self.latency_buckets[i].fetch_add(1, Ordering::Relaxed);
            }
        }
        self.latency_sum_us.fetch_add(u64::try_from(took.as_micros()).unwrap_or(u64::MAX), Ordering::Relaxed);
        self.latency_count.fetch_add(1, Ordering::Relaxed);
    }

    /// Pipeline runs so far (cache misses that rendered, and bypasses).
    pub fn renders(&self) -> u64 {
        self.renders.load(Ordering::Relaxed)
    }

    /// Counts a cache hit or miss.
    pub fn cache(&self, hit: bool) {
        if hit { &self.cache_hits } else { &self.cache_misses }.fetch_add(1, Ordering::Relaxed);
    }

    /// Counts a render rejected by a limit.
    pub fn rejected(&self, limit: &'static str) {
        if let Ok(mut m) = self.rejections.lock() {
            *m.entry(limit).or_default() += 1;
        }
    }

    /// Counts a render truncated by a limit.
    pub fn truncated(&self, limit: &'static str) {
        if let Ok(mut m) = self.truncations.lock() {
            *m.entry(limit).or_default() += 1;
        }
    }

    /// Adjusts the in-flight renders gauge.
    pub fn in_flight(&self, delta: i64) {
        self.in_flight.fetch_add(delta, Ordering::Relaxed);
    }

    /// Adjusts the queue depth gauge.
    pub fn queued(&self, delta: i64) {
        self.queued.fetch_add(delta, Ordering::Relaxed);
    }

    /// Counts a request shed for overload.
    pub fn shed(&self) {
        self.shed.fetch_add(1, Ordering::Relaxed);
    }

    /// The Prometheus text exposition.
    pub fn render_text(&self, cache: &ModelCache) -> String {
        let mut s = String::new();
        let _ = self.write_text(&mut s, cache);
        s
    }

    fn write_text(&self, s: &mut String, cache: &ModelCache) -> std::fmt::Result {
        writeln!(s, "# HELP rulemesh_requests_total Requests answered, by protocol, route and status.")?;
        writeln!(s, "# TYPE rulemesh_requests_total counter")?;
        if let Ok(m) = self.requests.lock() {
            for ((p, r, st), n) in m.iter() {
                writeln!(s, "rulemesh_requests_total{{protocol=\"{p}\",route=\"{r}\",status=\"{st}\"}} {n}")?;
            }
        }
        writeln!(s, "# HELP rulemesh_render_duration_seconds Time of each pipeline run.")?;
        writeln!(s, "# TYPE rulemesh_render_duration_seconds histogram")?;
        for (i, b) in BUCKETS.iter().enumerate() {
            writeln!(s, "rulemesh_render_duration_seconds_bucket{{le=\"{b}\"}} {}", self.latency_buckets[i].load(Ordering::Relaxed))?;
        }
        let count = self.latency_count.load(Ordering::Relaxed);
        writeln!(s, "rulemesh_render_duration_seconds_bucket{{le=\"+Inf\"}} {count}")?;
        writeln!(s, "rulemesh_render_duration_seconds_sum {}", self.latency_sum_us.load(Ordering::Relaxed) as f64 / 1e6)?;
        writeln!(s, "rulemesh_render_duration_seconds_count {count}")?;
        let counter = |s: &mut String, name: &str, help: &str, v: u64| -> std::fmt::Result {
            writeln!(s, "# HELP {name} {help}")?;
            writeln!(s, "# TYPE {name} counter")?;
            writeln!(s, "{name} {v}")
        };
        let gauge = |s: &mut String, name: &str, help: &str, v: i64| -> std::fmt::Result {
            writeln!(s, "# HELP {name} {help}")?;
            writeln!(s, "# TYPE {name} gauge")?;
            writeln!(s, "{name} {v}")
        };
        counter(s, "rulemesh_renders_total", "Pipeline runs.", self.renders())?;
        counter(s, "rulemesh_cache_hits_total", "Models served from the cache.", self.cache_hits.load(Ordering::Relaxed))?;
        counter(s, "rulemesh_cache_misses_total", "Models rendered for the request.", self.cache_misses.load(Ordering::Relaxed))?;
        counter(s, "rulemesh_cache_evictions_total", "Models evicted to keep the byte budget.", cache.evictions())?;
        gauge(s, "rulemesh_cache_bytes", "Bytes held by the cache.", i64::try_from(cache.weighted_bytes()).unwrap_or(i64::MAX))?;
        gauge(s, "rulemesh_cache_entries", "Models held by the cache.", i64::try_from(cache.entry_count()).unwrap_or(i64::MAX))?;
        writeln!(s, "# HELP rulemesh_budget_rejections_total Renders failed by a limit, by limit.")?;
        writeln!(s, "# TYPE rulemesh_budget_rejections_total counter")?;
        if let Ok(m) = self.rejections.lock() {
            for (l, n) in m.iter() {
                writeln!(s, "rulemesh_budget_rejections_total{{limit=\"{l}\"}} {n}")?;
            }
        }
        writeln!(s, "# HELP rulemesh_budget_truncations_total Renders truncated by a limit, by limit.")?;
        writeln!(s, "# TYPE rulemesh_budget_truncations_total counter")?;
        if let Ok(m) = self.truncations.lock() {
            for (l, n) in m.iter() {
                writeln!(s, "rulemesh_budget_truncations_total{{limit=\"{l}\"}} {n}")?;
            }
        }
        gauge(s, "rulemesh_renders_in_flight", "Renders running now.", self.in_flight.load(Ordering::Relaxed))?;
        gauge(s, "rulemesh_render_queue_depth", "Renders waiting for a slot.", self.queued.load(Ordering::Relaxed))?;
        counter(s, "rulemesh_shed_total", "Requests refused for overload.", self.shed.load(Ordering::Relaxed))
    }
}
