//! Prometheus metrics on the official Rust client, `prometheus-client`.
//!
//! Why that crate: it is the Prometheus project's own client, its label sets
//! are typed structs (so no label can be filled from a seed, a key or a
//! parameter by accident: every label value here comes from a fixed set —
//! routes, statuses, languages, formats, stages, tiers, limits), it speaks
//! both exposition formats, and it has no global registry, so every server
//! (and every test) has its own. `metrics` + `metrics-exporter-prometheus`
//! would have added a global recorder and an exporter of its own for no gain.
//!
//! `/metrics` answers in the OpenMetrics text format when the scraper asks
//! for it (`Accept: application/openmetrics-text`, as Prometheus does) and
//! in the classic text format 0.0.4 otherwise. Every sample carries
//! `worker="<id>"` when the worker has an id. Figures that live in the cache
//! tiers (bytes held, Redis counters) are read at scrape time ([`figures`]).

mod figures;
mod kept;

use crate::cache::{CacheObserver, ModelCache, Tier};
use crate::core::timing::PhaseTimes;
use crate::export::Format;
use crate::lang::Language;
use prometheus_client::encoding::EncodeLabelSet;
use prometheus_client::metrics::counter::Counter;
use prometheus_client::metrics::family::Family;
use prometheus_client::metrics::gauge::Gauge;
use prometheus_client::metrics::histogram::Histogram;
use prometheus_client::registry::Registry;
use std::borrow::Cow;
use std::sync::{Arc, OnceLock};
use std::time::Duration;

/// Upper bounds (seconds) of the request, render, stage and queue-wait
/// histogram buckets: from 10 µs (a cached answer, or a stage of a small
/// grammar) to 30 s (a render at the ceiling's deadline).
pub(crate) const BUCKETS: [f64; 20] =
    [0.00001, 0.000025, 0.00005, 0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 30.0];

/// Upper bounds (seconds) of the cache lookup histogram buckets: memory
/// answers in microseconds, disk and Redis in fractions of a millisecond.
pub(crate) const LOOKUP_BUCKETS: [f64; 13] = [0.00001, 0.00005, 0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25];

/// The content type of the OpenMetrics text exposition.
pub(crate) const OPENMETRICS: &str = "application/openmetrics-text; version=1.0.0; charset=utf-8";
/// The content type of the classic Prometheus text exposition.
pub(crate) const PROMETHEUS_TEXT: &str = "text/plain; version=0.0.4; charset=utf-8";

type Hist = fn() -> Histogram;

/// A finished request: protocol, route (the router's matched path or the gRPC method), status.
#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct RequestLabels {
    protocol: &'static str,
    route: String,
    status: u16,
}

/// A pipeline stage of one render.
#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct StageLabels {
    stage: &'static str,
    language: &'static str,
    format: &'static str,
}

/// Model bytes sent.
#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct BytesLabels {
    protocol: &'static str,
    format: &'static str,
}

/// A quick render's outcome (`done` on the worker, `fell_back` to the pool).
#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct QuickLabels {
    outcome: &'static str,
}

/// One cache tier lookup.
#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct LookupLabels {
    tier: &'static str,
    result: &'static str,
}

#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct TierLabel {
    tier: &'static str,
}

#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct LimitLabel {
    limit: &'static str,
}

#[derive(Debug, Clone, Hash, PartialEq, Eq, EncodeLabelSet)]
struct ReasonLabel {
    reason: &'static str,
}

fn histogram() -> Histogram {
    Histogram::new(BUCKETS)
}

fn lookup_histogram() -> Histogram {
    Histogram::new(LOOKUP_BUCKETS)
}
/// Every metric the service exports, registered once in its own registry.
pub struct Metrics {
    registry: Registry,
    requests: Family<RequestLabels, Counter>,
    request_seconds: Family<RequestLabels, Histogram, Hist>,
    response_bytes: Family<BytesLabels, Counter>,
    render_seconds: Histogram,
    stage_seconds: Family<StageLabels, Histogram, Hist>,
    queue_wait_seconds: Histogram,
    renders: Counter,
    cache_hits: Counter,
    cache_misses: Counter,
    lookups: Family<LookupLabels, Counter>,
    lookup_seconds: Family<TierLabel, Histogram, Hist>,
    rejections: Family<LimitLabel, Counter>,
    truncations: Family<LimitLabel, Counter>,
    in_flight: Gauge,
    queued: Gauge,
    shed: Counter,
    connections: Gauge,
    connections_closed: Family<ReasonLabel, Counter>,
    access_rejections: Family<ReasonLabel, Counter>,
    watchdog: Counter,
    /// Renders run on the async worker (`service::inline`), and tries there sent back to the pool.
    quick: Family<QuickLabels, Counter>,
    memory_refusals: Counter,
    memory_waits: Counter,
    /// Cached GETs answered by `service::fast` before the router.
    fast_hits: Counter,
    /// Model GETs answered by the direct route (`service::direct`).
    direct_models: Counter,
    /// Handles of the request and stage series, looked up once per label set.
    kept: kept::Kept,
    cache: Arc<OnceLock<ModelCache>>,
    memory: Arc<OnceLock<Arc<crate::service::memory::MemoryGuard>>>,
}

impl std::fmt::Debug for Metrics {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Metrics").field("renders", &self.renders.get()).finish_non_exhaustive()
    }
}

impl Default for Metrics {
    fn default() -> Self {
        Metrics::for_worker(None)
    }
}

impl Metrics {
    /// Metrics whose every sample carries `worker="<id>"` (none when `None`).
    pub(crate) fn for_worker(worker: Option<String>) -> Metrics {
        let labels: Vec<(Cow<'static, str>, Cow<'static, str>)> =
            worker.filter(|w| !w.is_empty()).map(|w| (Cow::Borrowed("worker"), Cow::Owned(w))).into_iter().collect();
        let mut registry = Registry::with_prefix_and_labels("rulemesh", labels.into_iter());
        let m = Metrics {
            requests: Family::default(),
            request_seconds: Family::new_with_constructor(histogram),
            response_bytes: Family::default(),
            render_seconds: histogram(),
            stage_seconds: Family::new_with_constructor(histogram),
            queue_wait_seconds: histogram(),
            renders: Counter::default(),
            cache_hits: Counter::default(),
            cache_misses: Counter::default(),
            lookups: Family::default(),
            lookup_seconds: Family::new_with_constructor(lookup_histogram),
            rejections: Family::default(),
            truncations: Family::default(),
            in_flight: Gauge::default(),
            queued: Gauge::default(),
            shed: Counter::default(),
            connections: Gauge::default(),
            connections_closed: Family::default(),
            access_rejections: Family::default(),
            watchdog: Counter::default(),
            quick: Family::default(),
            memory_refusals: Counter::default(),
            memory_waits: Counter::default(),
            fast_hits: Counter::default(),
            direct_models: Counter::default(),
            kept: kept::Kept::default(),
            cache: Arc::new(OnceLock::new()),
            memory: Arc::new(OnceLock::new()),
            registry: Registry::default(),
        };
        let r = &mut registry;
        r.register("requests", "Requests answered, by protocol, route and status", m.requests.clone());
        r.register("request_duration_seconds", "Time from request to response, by protocol, route and status", m.request_seconds.clone());
        r.register("response_bytes", "Model bytes sent (before any HTTP content encoding), by protocol and format", m.response_bytes.clone());
        r.register("render_duration_seconds", "Time of each pipeline run (queue wait excluded)", m.render_seconds.clone());
        r.register("stage_duration_seconds", "Time of each pipeline stage that ran, by stage, language and format", m.stage_seconds.clone());
        r.register("queue_wait_seconds", "Time a render waited for a render slot (0 when one was free)", m.queue_wait_seconds.clone());
        r.register("renders", "Pipeline runs", m.renders.clone());
        r.register("cache_hits", "Models served from a cache tier", m.cache_hits.clone());
        r.register("cache_misses", "Models rendered for the request", m.cache_misses.clone());
        r.register("cache_lookups", "Cache tier lookups, by tier (memory, disk, redis) and result (hit, miss)", m.lookups.clone());
        r.register("cache_lookup_duration_seconds", "Time of each cache tier lookup, by tier", m.lookup_seconds.clone());
        r.register("budget_rejections", "Renders failed by a limit, by limit", m.rejections.clone());
        r.register("budget_truncations", "Renders truncated by a limit, by limit", m.truncations.clone());
        r.register("renders_in_flight", "Renders running now", m.in_flight.clone());
        r.register("render_queue_depth", "Renders waiting for a slot", m.queued.clone());
        r.register("shed", "Requests refused for overload", m.shed.clone());
        r.register("http_connections_open", "HTTP connections open now", m.connections.clone());
        r.register("http_connections_closed", "HTTP connections the server closed, by reason", m.connections_closed.clone());
        r.register("access_rejections", "Requests refused by access control, by reason", m.access_rejections.clone());
        r.register("deadline_watchdog", "Renders the service ended at their deadline because the pipeline ran past it", m.watchdog.clone());
        r.register("quick_renders", "Renders known to be quick, run on the async worker (outcome done) or sent back to the blocking pool at the try's deadline (outcome fell_back)", m.quick.clone());
        r.register("memory_refusals", "Renders refused because resident memory plus their memory budget would pass the memory ceiling (HTTP 503 memory_pressure)", m.memory_refusals.clone());
        r.register("memory_waits", "Renders that waited for memory under the ceiling and then started", m.memory_waits.clone());
        r.register("fast_path_hits", "Cached GETs answered before the router from a kept response (also counted in requests, cache_hits and cache_lookups)", m.fast_hits.clone());
        r.register("direct_model_requests", "Model GETs answered before the router by the direct model route (also counted in requests)", m.direct_models.clone());
        r.register_collector(Box::new(figures::CacheFigures::new(m.cache.clone())));
        r.register_collector(Box::new(figures::MemoryFigures::new(m.memory.clone())));
        r.register_collector(Box::new(figures::LogFigures));
        Metrics { registry, ..m }
    }

    /// Lets the scrape read the cache's own figures (bytes, entries, tier
    /// counters). Pass a handle made before [`ModelCache::with_observer`],
    /// so that the cache and these metrics do not hold each other.
    pub(crate) fn attach_cache(&self, cache: ModelCache) {
        let _ = self.cache.set(cache);
    }

    /// Lets the scrape read the process's resident bytes and the memory
    /// guard's ceiling.
    pub(crate) fn attach_memory(&self, guard: Arc<crate::service::memory::MemoryGuard>) {
        let _ = self.memory.set(guard);
    }

    /// Counts a render refused by the memory guard.
    pub fn memory_refused(&self) {
        self.memory_refusals.inc();
    }

    /// Counts a cached GET answered by the fast path (`service::fast`).
    pub(crate) fn fast_path_hit(&self) {
        self.fast_hits.inc();
    }

    /// Counts a model GET answered by the direct route (`service::direct`).
    pub(crate) fn direct_model_request(&self) {
        self.direct_models.inc();
    }

    /// Counts a render that waited for memory and then started.
    pub(crate) fn memory_waited(&self) {
        self.memory_waits.inc();
    }

    /// Counts one finished request and its latency (`protocol` is `http` or `grpc`).
    pub fn request(&self, protocol: &'static str, route: &str, status: u16, took: Duration) {
        let (count, seconds) = self.kept.request(protocol, route, status, || {
            let labels = RequestLabels { protocol, route: route.to_string(), status };
            (self.requests.get_or_create(&labels).clone(), self.request_seconds.get_or_create(&labels).clone())
        });
        count.inc();
        seconds.observe(took.as_secs_f64());
    }

    /// Counts model bytes sent in `format`.
    pub(crate) fn bytes_out(&self, protocol: &'static str, format: Format, bytes: usize) {
        self.kept.bytes(protocol, format, || self.response_bytes.get_or_create(&BytesLabels { protocol, format: format.name() }).clone()).inc_by(bytes as u64);
    }

    /// Records one pipeline run and its duration.
    pub(crate) fn render_done(&self, took: Duration) {
        self.renders.inc();
        self.render_seconds.observe(took.as_secs_f64());
    }

    /// Records the time of every stage that ran in one render of `language` into `format`.
    pub fn stages(&self, language: Language, format: Format, phases: &PhaseTimes) {
        for (phase, took) in phases.ran() {
            let seconds = self.kept.stage(phase, language, format, || {
                let labels = StageLabels { stage: phase.name(), language: language.name(), format: format.name() };
                self.stage_seconds.get_or_create(&labels).clone()
            });
            seconds.observe(took.as_secs_f64());
        }
    }

    /// Records how long a render waited for its slot.
    pub(crate) fn queue_wait(&self, took: Duration) {
        self.queue_wait_seconds.observe(took.as_secs_f64());
    }

    /// Pipeline runs so far (cache misses that rendered, and bypasses).
    pub fn renders(&self) -> u64 {
        self.renders.get()
    }

    /// Counts a request's cache result.
    pub fn cache(&self, hit: bool) {
        if hit { &self.cache_hits } else { &self.cache_misses }.inc();
    }

    /// Counts a render rejected by a limit.
    pub fn rejected(&self, limit: &'static str) {
        self.rejections.get_or_create(&LimitLabel { limit }).inc();
    }

    /// Counts a render truncated by a limit.
    pub fn truncated(&self, limit: &'static str) {
        self.truncations.get_or_create(&LimitLabel { limit }).inc();
    }

    /// Adjusts the in-flight renders gauge.
    pub(crate) fn in_flight(&self, delta: i64) {
        self.in_flight.inc_by(delta);
    }

    /// Adjusts the queue depth gauge.
    pub fn queued(&self, delta: i64) {
        self.queued.inc_by(delta);
    }

    /// Counts a request shed for overload.
    pub fn shed(&self) {
        self.shed.inc();
    }

    /// Adjusts the open HTTP connections gauge.
    pub fn connection(&self, delta: i64) {
        self.connections.inc_by(delta);
    }

    /// Open HTTP connections now.
    pub fn connections_open(&self) -> i64 {
        self.connections.get()
    }

    /// Counts an HTTP connection the server closed, by reason (`header_timeout`, `idle`).
    pub(crate) fn connection_closed(&self, reason: &'static str) {
        self.connections_closed.get_or_create(&ReasonLabel { reason }).inc();
    }

    /// Counts a request refused by access control, by reason (`unauthorized`, `rate_limited`, `javascript_disabled`).
    pub(crate) fn access_rejected(&self, reason: &'static str) {
        self.access_rejections.get_or_create(&ReasonLabel { reason }).inc();
    }

    /// Counts a render the deadline watchdog ended (the pipeline ran past its deadline).
    pub(crate) fn watchdog_fired(&self) {
        self.watchdog.inc();
    }

    /// Counts a render run on the async worker (`service::inline`).
    pub(crate) fn quick_rendered(&self) {
        self.quick.get_or_create(&QuickLabels { outcome: "done" }).inc();
    }

    /// Counts a try on the async worker that ran into its deadline and was
    /// rendered again on the blocking pool.
    pub(crate) fn quick_fell_back(&self) {
        self.quick.get_or_create(&QuickLabels { outcome: "fell_back" }).inc();
    }

    /// The exposition: OpenMetrics text when `openmetrics`, else the classic text format.
    pub(crate) fn render_text(&self, openmetrics: bool) -> String {
        let mut s = String::new();
        let encoded = if openmetrics {
            prometheus_client::encoding::text::encode(&mut s, &self.registry)
        } else {
            prometheus_client::encoding::prometheus_text::encode(&mut s, &self.registry)
        };
        if let Err(e) = encoded {
            tracing::warn!(error = %e, "metrics could not be encoded");
        }
        s
    }
}

/// Whether an `Accept` header asks for OpenMetrics (as Prometheus's scraper does).
pub(crate) fn wants_openmetrics(accept: Option<&str>) -> bool {
    accept.is_some_and(|a| a.split(',').any(|t| t.trim().starts_with("application/openmetrics-text")))
}

impl CacheObserver for Metrics {
    fn lookup(&self, tier: Tier, hit: bool, took: Duration) {
        self.lookups.get_or_create(&LookupLabels { tier: tier.name(), result: if hit { "hit" } else { "miss" } }).inc();
        self.lookup_seconds.get_or_create(&TierLabel { tier: tier.name() }).observe(took.as_secs_f64());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn worker_label_on_every_sample_in_both_formats() {
        let m = Metrics::for_worker(Some("w\"1".into()));
        m.request("http", "/v1/render", 200, Duration::from_millis(3));
        for om in [false, true] {
            let text = m.render_text(om);
            let samples: Vec<&str> = text.lines().filter(|l| !l.starts_with('#') && !l.is_empty()).collect();
            assert!(!samples.is_empty());
            for s in samples {
                assert!(s.contains("{worker=\"w\\\"1\""), "{s}");
            }
            assert!(text.contains("rulemesh_requests_total{worker=\"w\\\"1\",protocol=\"http\",route=\"/v1/render\",status=\"200\"} 1"), "{text}");
            assert_eq!(text.trim_end().ends_with("# EOF"), om, "{text}");
        }
    }

    #[test]
    fn stages_that_did_not_run_are_not_observed() {
        let m = Metrics::default();
        let mut clock = crate::core::timing::StageClock::start();
        clock.lap(crate::core::timing::Phase::Parse);
        clock.lap(crate::core::timing::Phase::Export);
        m.stages(Language::Lsystem, Format::Scene, &clock.phases);
        let text = m.render_text(false);
        assert!(text.contains("rulemesh_stage_duration_seconds_count{stage=\"parse\",language=\"lsystem\",format=\"scene\"} 1"), "{text}");
        assert!(!text.contains("stage=\"mesh\""), "{text}");
        assert!(wants_openmetrics(Some("application/openmetrics-text;version=1.0.0,text/plain;q=0.5")));
        assert!(!wants_openmetrics(Some("text/plain")));
    }
}
