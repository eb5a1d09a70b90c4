//! The access log's INFO line written directly, in the exact text
//! `tracing-subscriber`'s default formatter gives it (`Full`, no target,
//! no colours):
//!
//! ```text
//! 2026-12-06T12:39:06.058664Z  INFO request id=1 method=GET route=/v1/models/{file} status=200 ms=0.635 cache=miss bytes=12460
//! ```
//!
//! Why by hand: through `tracing`, the line cost about 3 % of a fresh
//! icon's CPU and more of a cached one's (issue 33's profiles): the event's
//! dispatch, its value set, a visitor per field, `Debug` of each value and
//! the formatter's own buffer. The text is simple and fixed, so it is
//! written here straight into the log writer's queue. `access_log` uses it
//! only when it is the same text the formatter would write
//! ([`super::telemetry::plain_info_writer`]: plain text, no colours, INFO
//! on) and no span would prefix it (DEBUG off: the request span is a DEBUG
//! span); otherwise the line goes through `tracing`. `access_log`'s unit
//! test holds the two texts equal.

use std::io::Write as _;
use std::time::SystemTime;

/// The fields of one access line, in the line's order; absent ones are
/// left out of it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Line<'a> {
    /// The process-wide request id.
    pub(crate) id: u64,
    /// The HTTP method, or `grpc`.
    pub(crate) method: &'a str,
    /// The matched route, or the gRPC method.
    pub(crate) route: &'a str,
    /// The HTTP status, when HTTP.
    pub(crate) status: Option<u16>,
    /// The gRPC outcome, when gRPC.
    pub(crate) code: Option<&'a str>,
    /// Wall time in milliseconds, rounded to the microsecond.
    pub(crate) ms: f64,
    /// The cache result, when the answer was a model.
    pub(crate) cache: Option<&'a str>,
    /// The body's length, when known.
    pub(crate) bytes: Option<u64>,
}

/// Appends `l`, stamped `now`, as `tracing-subscriber` writes the same
/// event: RFC 3339 time to the microsecond, the level right-aligned, the
/// message, then `name=value` with each value's `Display`, except `ms`,
/// an `f64`, which its visitor writes with `Debug`.
pub(crate) fn write(out: &mut Vec<u8>, now: SystemTime, l: &Line<'_>) {
    // Writing to a Vec cannot fail.
    let _ = write!(out, "{}  INFO request id={} method={} route={}", humantime::format_rfc3339_micros(now), l.id, l.method, l.route);
    if let Some(status) = l.status {
        let _ = write!(out, " status={status}");
    }
    if let Some(code) = l.code {
        let _ = write!(out, " code={code}");
    }
    let _ = write!(out, " ms={:?}", l.ms);
    if let Some(cache) = l.cache {
        let _ = write!(out, " cache={cache}");
    }
    if let Some(bytes) = l.bytes {
        let _ = write!(out, " bytes={bytes}");
    }
    out.push(b'\n');
}
