//! The per-request access log: one short INFO line per request (method,
//! route, status, milliseconds, cache result, bytes), the request's stage
//! timings at DEBUG level (and in its trace), and a switch that samples or
//! silences the short line (`--access-log all|sampled|off`).
//!
//! Why short: issue 33 measured the old INFO line, about 800 bytes with the
//! span's fields, the cache key and `Server-Timing` twice, at a third of
//! the cached-GET throughput (81 MB of log in ten seconds of load). The
//! details are still there for whoever asks for them (`--log debug`, or the
//! OTLP spans), and never cost a request that does not.
//!
//! The lines reach stderr through a batching writer ([`super::log_writer`],
//! installed by [`super::telemetry::init`]): a slow or
//! stalled log reader costs dropped lines, counted in
//! `rulemesh_log_lines_dropped_total`, never a blocked worker.

use super::access_line::Line;
use super::timing::{ms, RequestTiming};
use crate::cache::CacheOutcome;
use crate::core::timing::Phase;
use std::sync::atomic::{AtomicU64, AtomicU8, Ordering};
use std::time::Duration;

/// Which requests get their access-log line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum AccessLog {
    /// Every request (the default).
    #[default]
    All,
    /// One request in [`SAMPLE_EVERY`] (the 100th, 200th, … of the
    /// process, counted over HTTP and gRPC together), and every request
    /// that ended in an internal error (HTTP 500, gRPC `internal`), which
    /// is always worth a line and never a flood.
    Sampled,
    /// None: the metrics and traces still count every request.
    Off,
}

/// The sampling period of [`AccessLog::Sampled`].
pub(crate) const SAMPLE_EVERY: u64 = 100;

/// The mode [`set_mode`] chose (an `AccessLog` as its index; `All` until set).
static MODE: AtomicU8 = AtomicU8::new(0);

/// Requests seen, for sampling.
static SEEN: AtomicU64 = AtomicU64::new(0);

/// Sets the process's access-log mode (`rulemesh serve --access-log`).
pub fn set_mode(mode: AccessLog) {
    MODE.store(mode as u8, Ordering::Relaxed);
}

fn mode() -> AccessLog {
    match MODE.load(Ordering::Relaxed) {
        0 => AccessLog::All,
        1 => AccessLog::Sampled,
        _ => AccessLog::Off,
    }
}

/// Whether this request gets its line, counting it for sampling.
fn wanted(internal_error: bool) -> bool {
    match mode() {
        AccessLog::All => true,
        AccessLog::Off => false,
        AccessLog::Sampled => {
            let n = SEEN.fetch_add(1, Ordering::Relaxed) + 1;
            internal_error || n % SAMPLE_EVERY == 0
        }
    }
}

/// One finished request, as the access log sees it.
#[derive(Debug, Clone, Copy)]
pub struct Finished<'a> {
    /// The process-wide request id (`x-request-id`).
    pub id: u64,
    /// The HTTP method, or `grpc`.
    pub method: &'a str,
    /// The matched route, or the gRPC method.
    pub route: &'a str,
    /// The HTTP status, when HTTP.
    pub status: Option<u16>,
    /// The gRPC outcome (`ok`, or the error's code), when gRPC.
    pub code: Option<&'a str>,
    /// Wall time from request to response.
    pub wall: Duration,
    /// The response body's length, when known.
    pub bytes: Option<u64>,
    /// The model's strong ETag, when the answer was a model.
    pub etag: Option<&'a str>,
    /// Where its time went, when the answer was a model.
    pub timing: Option<&'a RequestTiming>,
}

/// Whether the DEBUG detail line is on: it is written inside the request's
/// span, which only the router makes, so the fast path steps aside then.
pub(crate) fn detail_enabled() -> bool {
    tracing::enabled!(tracing::Level::DEBUG)
}

/// Logs `r`: the short INFO line (when the mode wants it), outside the
/// request's span so that the line carries only its own fields (in JSON,
/// `fields` alone; in text, no span prefix with the 64-digit cache key),
/// then, when DEBUG is on, the DEBUG line with the details inside `span`
/// (so that it carries the request's language, cache key and result).
pub(crate) fn log_request(r: &Finished<'_>, span: &tracing::Span) {
    let internal = r.status == Some(500) || r.code == Some("internal");
    if wanted(internal) {
        let cache = r.timing.map(|t| match (t.lookup.outcome, t.lookup.tier) {
            (CacheOutcome::Hit, Some(tier)) => tier.name(),
            (CacheOutcome::Hit, None) => "hit",
            _ => "miss",
        });
        let line = Line { id: r.id, method: r.method, route: r.route, status: r.status, code: r.code, ms: (ms(r.wall) * 1000.0).round() / 1000.0, cache, bytes: r.bytes };
        // The same line without `tracing`'s machinery when its text is the
        // formatter's (module `access_line` says when and why).
        match super::telemetry::plain_info_writer().filter(|_| !detail_enabled()) {
            Some(writer) => {
                let now = std::time::SystemTime::now();
                writer.push_with(|out| super::access_line::write(out, now, &line));
            }
            None => info_event(&line),
        }
    }
    if detail_enabled() {
        span.in_scope(|| log_detail(r));
    }
}

/// The short line as a `tracing` event.
fn info_event(l: &Line<'_>) {
    // Displayed, not debugged: `route=/v1/render`, not `route="/v1/render"`.
    tracing::info!(
        id = l.id,
        method = %l.method,
        route = %l.route,
        status = l.status,
        code = l.code.map(tracing::field::display),
        ms = l.ms,
        cache = l.cache.map(tracing::field::display),
        bytes = l.bytes,
        "request"
    );
}

/// The DEBUG line: the numbers of the `Server-Timing` header as fields
/// (`queue_ms`, `parse_ms`, `eval_ms`, `mesh_ms`, `print_ms`,
/// `preview_ms`, `export_ms`, `cache_ms`, `tier`) and as its text
/// (`server_timing`), and the ETag.
fn log_detail(r: &Finished<'_>) {
    let timing = r.timing;
    let stage = |p| timing.and_then(|t| t.stage_ms(p));
    tracing::debug!(
        id = r.id,
        status = r.status,
        code = r.code,
        etag = r.etag,
        ms = ms(r.wall),
        server_timing = timing.map(|t| tracing::field::display(t.header_value())),
        queue_ms = timing.and_then(RequestTiming::queue_ms),
        parse_ms = stage(Phase::Parse),
        eval_ms = stage(Phase::Eval),
        mesh_ms = stage(Phase::Mesh),
        print_ms = stage(Phase::Print),
        preview_ms = stage(Phase::Preview),
        export_ms = stage(Phase::Export),
        cache_ms = timing.map(RequestTiming::cache_ms),
        tier = timing.and_then(|t| t.lookup.tier.map(|t| t.name())),
        "request detail"
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sampling_keeps_one_in_a_hundred_and_every_internal_error() {
        // The mode and counter are process-wide; this is the only test that
        // sets them in this crate's unit tests.
        set_mode(AccessLog::Sampled);
        SEEN.store(0, Ordering::Relaxed);
        let kept = (0..1000).filter(|_| wanted(false)).count();
        assert_eq!(kept, 10);
        assert!(wanted(true), "an internal error is always logged");
        set_mode(AccessLog::Off);
        assert!(!wanted(true));
        set_mode(AccessLog::All);
        assert!(wanted(false));
    }

    /// The line written by hand (`access_line`) is the text the
    /// formatter writes for `info_event` (plain, no target, no colours, as
    /// `telemetry::init` sets it up): every field present and absent, and
    /// `ms` values whose `Debug` text differs from `Display`'s. The
    /// timestamps differ (two clocks read); each has RFC 3339's shape.
    #[test]
    fn the_line_by_hand_is_the_formatters_text() {
        let base = Line { id: 7, method: "GET", route: "/v1/models/{file}", status: Some(200), code: None, ms: 0.635, cache: Some("miss"), bytes: Some(12460) };
        let lines = [
            base,
            Line { status: None, code: Some("resource_exhausted"), method: "grpc", route: "Render", bytes: None, cache: None, ms: 12.0, ..base },
            Line { id: u64::MAX, ms: 0.0, cache: Some("memory"), ..base },
            Line { ms: 1234567.125, cache: Some("redis"), ..base },
            Line { ms: 1e-7, cache: None, ..base },
        ];
        for line in lines {
            let captured = crate::service::log_writer::Sink::default();
            let sink = captured.clone();
            let subscriber = tracing_subscriber::fmt().with_target(false).with_ansi(false).with_writer(move || sink.clone()).finish();
            tracing::subscriber::with_default(subscriber, || info_event(&line));
            let theirs = String::from_utf8(captured.0.lock().expect("buffer").clone()).expect("utf-8");
            let mut ours = Vec::new();
            crate::service::access_line::write(&mut ours, std::time::SystemTime::UNIX_EPOCH + Duration::from_micros(1_796_560_746_058_664), &line);
            let ours = String::from_utf8(ours).expect("utf-8");
            assert_eq!(ours.split_once(' ').map(|p| p.1), theirs.split_once(' ').map(|p| p.1), "{ours} against {theirs}");
            assert_eq!(ours.split_once(' ').map(|p| p.0), Some("2026-12-06T12:39:06.058664Z"));
            let stamp = theirs.split_once(' ').map_or("", |p| p.0);
            assert!(stamp.len() == 27 && stamp.ends_with('Z') && stamp.as_bytes()[19] == b'.', "{stamp}");
        }
    }
}
