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
    connections: AtomicI64,
    connections_closed: Mutex<BTreeMap<&'static str, u64>>,
    access_rejections: Mutex<BTreeMap<&'static str, u64>>,
    watchdog: AtomicU64,
    worker: Option<String>,
}

impl Metrics {
    /// Metrics whose every sample carries `worker="<id>"` (none when `None`).
    pub fn for_worker(worker: Option<String>) -> Metrics {
        Metrics { worker: worker.filter(|w| !w.is_empty()), ..Metrics::default() }
    }

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

    /// Adjusts the open HTTP connections gauge.
    pub fn connection(&self, delta: i64) {
        self.connections.fetch_add(delta, Ordering::Relaxed);
    }

    /// Open HTTP connections now.
    pub fn connections_open(&self) -> i64 {
        self.connections.load(Ordering::Relaxed)
    }

    /// Counts an HTTP connection the server closed, by reason (`header_timeout`, `idle`).
    pub fn connection_closed(&self, reason: &'static str) {
        if let Ok(mut m) = self.connections_closed.lock() {
            *m.entry(reason).or_default() += 1;
        }
    }

    /// Counts a request refused by access control, by reason (`unauthorized`, `rate_limited`, `javascript_disabled`).
    pub fn access_rejected(&self, reason: &'static str) {
        if let Ok(mut m) = self.access_rejections.lock() {
            *m.entry(reason).or_default() += 1;
        }
    }

    /// Counts a render the deadline watchdog ended (the pipeline ran past its deadline).
    pub fn watchdog_fired(&self) {
        self.watchdog.fetch_add(1, Ordering::Relaxed);
    }

    /// The Prometheus text exposition.
    pub fn render_text(&self, cache: &ModelCache) -> String {
        let mut s = String::new();
        let _ = self.write_text(&mut s, cache);
        match &self.worker {
            Some(w) => with_label(&s, "worker", w),
            None => s,
        }
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
        counter(s, "rulemesh_shed_total", "Requests refused for overload.", self.shed.load(Ordering::Relaxed))?;
        gauge(s, "rulemesh_http_connections_open", "HTTP connections open now.", self.connections_open())?;
        let labelled = |s: &mut String, name: &str, help: &str, label: &str, m: &Mutex<BTreeMap<&'static str, u64>>| -> std::fmt::Result {
            writeln!(s, "# HELP {name} {help}")?;
            writeln!(s, "# TYPE {name} counter")?;
            if let Ok(m) = m.lock() {
                for (l, n) in m.iter() {
                    writeln!(s, "{name}{{{label}=\"{l}\"}} {n}")?;
                }
            }
            Ok(())
        };
        labelled(s, "rulemesh_http_connections_closed_total", "HTTP connections the server closed, by reason.", "reason", &self.connections_closed)?;
        labelled(s, "rulemesh_access_rejections_total", "Requests refused by access control, by reason.", "reason", &self.access_rejections)?;
        counter(s, "rulemesh_deadline_watchdog_total", "Renders the service ended at their deadline because the pipeline ran past it.", self.watchdog.load(Ordering::Relaxed))?;
        counter(s, "rulemesh_cache_corrupt_total", "Disk or Redis cache entries whose content hash did not match (treated as misses, never served).", cache.corrupt())?;
        if let Some(r) = cache.redis() {
            counter(s, "rulemesh_redis_hits_total", "Models read from the shared Redis tier.", r.hits())?;
            counter(s, "rulemesh_redis_misses_total", "Redis lookups without a model.", r.misses())?;
            counter(s, "rulemesh_redis_writes_total", "Models written to Redis.", r.writes())?;
            counter(s, "rulemesh_redis_skipped_total", "Models not written to Redis (too large, or Redis failing).", r.skipped())?;
            counter(s, "rulemesh_redis_errors_total", "Redis commands that failed or timed out (served from local caching instead).", r.errors())?;
            counter(s, "rulemesh_redis_lock_waits_total", "Renders that waited for another worker's lock.", r.lock_waits())?;
            gauge(s, "rulemesh_redis_up", "1 while Redis answers, 0 while it is skipped after a failure.", i64::from(!r.is_degraded()))?;
        }
        Ok(())
    }
}

/// Adds `name="value"` to every sample line of a text exposition.
fn with_label(text: &str, name: &str, value: &str) -> String {
    let escaped = value.replace('\\', "\\\\").replace('"', "\\\"").replace('\n', "\\n");
    let label = format!("{name}=\"{escaped}\"");
    let mut out = String::with_capacity(text.len() + text.lines().count() * (label.len() + 2));
    for line in text.lines() {
        if line.starts_with('#') || line.is_empty() {
            out.push_str(line);
        } else if let Some(brace) = line.find('{') {
            let (head, tail) = line.split_at(brace + 1);
            out.push_str(head);
            out.push_str(&label);
            out.push(',');
            out.push_str(tail);
        } else if let Some((metric, value)) = line.split_once(' ') {
            let _ = write!(out, "{metric}{{{label}}} {value}");
        } else {
            out.push_str(line);
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn worker_label_on_every_sample() {
        let text = "# HELP a A.\n# TYPE a counter\na 1\nb{le=\"0.1\"} 2\n";
        assert_eq!(super::with_label(text, "worker", "w\"1"), "# HELP a A.\n# TYPE a counter\na{worker=\"w\\\"1\"} 1\nb{worker=\"w\\\"1\",le=\"0.1\"} 2\n");
    }
}
