//! The process's log and trace output: one subscriber for `rulemesh serve`,
//! logging to stderr as text or as one JSON object per line (the format log
//! shippers read without a parser of their own) and, only when an OTLP
//! endpoint is configured, exporting OpenTelemetry spans over OTLP/gRPC.
//!
//! Spans: each request's span (`http` or `grpc`, named `POST /v1/render`,
//! `Render`…, with the `language` and cache `key` as attributes) becomes a
//! server span, the child of the caller's W3C `traceparent` when it sent
//! one; each pipeline stage that ran becomes a child span of it
//! ([`stage_spans`]), timed by the pipeline's own stage clock. Without an
//! endpoint no exporter, layer or propagator is installed and the helpers
//! here return at once: tracing costs nothing when off.
//!
//! Log lines go through [`super::log_writer`]: a thread of its own writes
//! them to stderr in batches from a bounded queue, so a worker never waits
//! for a slow log reader (nor makes a system call per line); when the queue
//! is full the line is dropped and counted ([`dropped_lines`], exported as
//! `rulemesh_log_lines_dropped_total`).

use crate::core::timing::PhaseTimes;
use opentelemetry::trace::{Span as _, SpanKind, Tracer as _, TracerProvider as _};
use opentelemetry::KeyValue;
use opentelemetry_otlp::WithExportConfig as _;
use opentelemetry_sdk::trace::SdkTracerProvider;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::OnceLock;
use super::log_writer::{BatchWriter, FlushGuard};
use std::time::SystemTime;
use tracing_opentelemetry::OpenTelemetrySpanExt as _;
use tracing_subscriber::filter::LevelFilter;
use tracing_subscriber::layer::SubscriberExt as _;
use tracing_subscriber::util::SubscriberInitExt as _;
use tracing_subscriber::Layer as _;

/// How log lines are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum LogFormat {
    /// Human-readable lines (coloured on a terminal).
    #[default]
    Text,
    /// One JSON object per line: `timestamp`, `level`, `fields` (the
    /// message and the event's fields, e.g. a request's `server_timing`
    /// and `parse_ms`), `span` and `spans` (the request's id, route,
    /// language, cache key and result).
    Json,
}

/// Why telemetry could not be set up.
#[derive(Debug, thiserror::Error)]
pub enum TelemetryError {
    /// A global subscriber was already installed.
    #[error("cannot install the log subscriber: {0}")]
    Init(String),
    /// The OTLP exporter could not be built (a malformed endpoint).
    #[error("--otlp-endpoint: {0}")]
    Otlp(String),
}

/// True once spans are exported (an OTLP endpoint was configured).
static TRACING: AtomicBool = AtomicBool::new(false);

/// Whether spans are being exported.
pub(crate) fn tracing_on() -> bool {
    TRACING.load(Ordering::Relaxed)
}

/// The log writer, whose count of dropped lines [`dropped_lines`] reads, once [`init`] ran.
static WRITER: OnceLock<BatchWriter> = OnceLock::new();

/// Whether the access log may write its INFO line itself (`access_line`):
/// [`init`] made the lines plain text without colours with INFO on, so the
/// line is exactly what `tracing-subscriber`'s formatter would write. False
/// for JSON, a terminal's colours, a level above INFO, or a process that
/// never called [`init`] (tests).
static PLAIN_INFO: AtomicBool = AtomicBool::new(false);

/// The log writer [`WRITER`], when [`PLAIN_INFO`] holds.
pub(crate) fn plain_info_writer() -> Option<&'static BatchWriter> {
    WRITER.get().filter(|_| PLAIN_INFO.load(Ordering::Relaxed))
}

/// Log lines dropped because the writer's queue was full (0 before
/// [`init`], and in processes that log directly).
pub(crate) fn dropped_lines() -> u64 {
    WRITER.get().map_or(0, BatchWriter::dropped)
}

/// The default length of the log writer's queue, in lines: about ten
/// seconds of access-log lines at 6,000 requests a second, a few
/// megabytes at most, before lines are dropped rather than waited for.
pub const DEFAULT_LOG_BUFFER_LINES: usize = 65_536;

/// What [`init`] set up; [`Telemetry::shutdown`] flushes the spans not yet sent.
#[derive(Debug, Default)]
pub struct Telemetry {
    provider: Option<SdkTracerProvider>,
    /// Flushes the log writer's queue when dropped.
    log_writer: Option<FlushGuard>,
}

impl Telemetry {
    /// Sends the spans still batched, stops the exporter (a no-op without
    /// one) and writes out the log lines still queued.
    pub fn shutdown(self) {
        if let Some(p) = self.provider {
            if let Err(e) = p.shutdown() {
                tracing::warn!(error = %e, "OTLP exporter did not shut down cleanly");
            }
        }
        drop(self.log_writer);
    }
}

/// The W3C trace context a request carried (`traceparent`, `tracestate`).
struct Carrier {
    traceparent: Option<String>,
    tracestate: Option<String>,
}

impl opentelemetry::propagation::Extractor for Carrier {
    fn get(&self, key: &str) -> Option<&str> {
        match key {
            "traceparent" => self.traceparent.as_deref(),
            "tracestate" => self.tracestate.as_deref(),
            _ => None,
        }
    }

    fn keys(&self) -> Vec<&str> {
        vec!["traceparent", "tracestate"]
    }
}

/// Makes `span` the child of the caller's trace when the request carries a
/// `traceparent` (`header` looks a header or metadata entry up by name).
pub(crate) fn adopt_parent<'a>(span: &tracing::Span, header: impl Fn(&str) -> Option<&'a str>) {
    if !tracing_on() {
        return;
    }
    let carrier = Carrier { traceparent: header("traceparent").map(str::to_owned), tracestate: header("tracestate").map(str::to_owned) };
    if carrier.traceparent.is_none() {
        return;
    }
    let cx = opentelemetry::global::get_text_map_propagator(|p| p.extract(&carrier));
    let _ = span.set_parent(cx);
}

/// Exports one child span of the current (request) span per stage that ran
/// in a render that began at `started`, back to back as the stage clock
/// lapped them, with the stage, language and format as attributes.
pub(crate) fn stage_spans(started: SystemTime, phases: &PhaseTimes, language: &'static str, format: &'static str) {
    if !tracing_on() {
        return;
    }
    let parent = tracing::Span::current().context();
    let tracer = opentelemetry::global::tracer("rulemesh");
    let mut at = started;
    for (phase, took) in phases.ran() {
        let end = at + took;
        let mut span = tracer
            .span_builder(phase.name())
            .with_kind(SpanKind::Internal)
            .with_start_time(at)
            .with_attributes([
                KeyValue::new("rulemesh.stage", phase.name()),
                KeyValue::new("rulemesh.language", language),
                KeyValue::new("rulemesh.format", format),
            ])
            .start_with_context(&tracer, &parent);
        span.end_with_timestamp(end);
        at = end;
    }
}

/// Installs the global subscriber: `level` and above, in `format`, to
/// stderr; with `otlp` (`http://host:4317`), also rulemesh's spans exported
/// over OTLP/gRPC as service `rulemesh` (instance `worker`, if named) and
/// W3C trace context read from requests. Lines queue for stderr through a
/// batching writer holding at most `buffer_lines` lines. Call it inside
/// the Tokio runtime that will serve: the exporter's connection lives on it.
pub fn init(level: LevelFilter, format: LogFormat, otlp: Option<&str>, worker: Option<&str>, buffer_lines: usize) -> Result<Telemetry, TelemetryError> {
    use std::io::IsTerminal;
    let (writer, guard) = BatchWriter::start(std::io::stderr(), buffer_lines).map_err(|e| TelemetryError::Init(format!("cannot start the log writer thread: {e}")))?;
    let _ = WRITER.set(writer.clone());
    let ansi = std::io::stderr().is_terminal();
    PLAIN_INFO.store(format == LogFormat::Text && !ansi && level >= LevelFilter::INFO, Ordering::Relaxed);
    let fmt = tracing_subscriber::fmt::layer().with_target(false).with_writer(writer);
    let fmt = match format {
        LogFormat::Text => fmt.with_ansi(ansi).boxed(),
        LogFormat::Json => fmt.json().with_current_span(true).with_span_list(true).with_ansi(false).boxed(),
    };
    let mut telemetry = Telemetry { log_writer: Some(guard), ..Telemetry::default() };
    let otel = match otlp.map(str::trim).filter(|e| !e.is_empty()) {
        None => None,
        Some(endpoint) => {
            let exporter = opentelemetry_otlp::SpanExporter::builder()
                .with_tonic()
                .with_endpoint(endpoint)
                .build()
                .map_err(|e| TelemetryError::Otlp(e.to_string()))?;
            let mut resource = opentelemetry_sdk::Resource::builder().with_service_name("rulemesh");
            if let Some(w) = worker.filter(|w| !w.is_empty()) {
                resource = resource.with_attribute(KeyValue::new("service.instance.id", w.to_string()));
            }
            let provider = SdkTracerProvider::builder().with_batch_exporter(exporter).with_resource(resource.build()).build();
            let tracer = provider.tracer("rulemesh");
            opentelemetry::global::set_tracer_provider(provider.clone());
            opentelemetry::global::set_text_map_propagator(opentelemetry_sdk::propagation::TraceContextPropagator::new());
            telemetry.provider = Some(provider);
            TRACING.store(true, Ordering::Relaxed);
            // Only rulemesh's own spans (not hyper's, h2's or tonic's).
            let ours = tracing_subscriber::filter::filter_fn(|m| m.target().starts_with("rulemesh"));
            Some(tracing_opentelemetry::layer().with_tracer(tracer).with_filter(ours))
        }
    };
    tracing_subscriber::registry()
        .with(fmt.with_filter(level))
        .with(otel)
        .try_init()
        .map_err(|e| TelemetryError::Init(e.to_string()))?;
    Ok(telemetry)
}
