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
//! written here straight into the log writer's queue. It is used only when
//! it is the same text the formatter would write
//! ([`super::telemetry::plain_info_writer`]: plain text, no colours, INFO
//! on) and no span would prefix it (DEBUG off: the request span is a DEBUG
//! span); otherwise the line goes through `tracing` as before. The unit
//! test below holds the two texts equal.

use super::access_log::Finished;
use std::io::Write as _;
use std::time::SystemTime;

/// Appends `r`'s line, stamped `now`, with its cache result `cache`: the
/// fields of `access_log::log_request`'s `tracing::info!` in its order,
/// absent ones left out, as `tracing-subscriber` writes them (`ms` with
/// `Debug`, as its visitor records an `f64`).
pub(crate) fn write(
    out: &mut Vec<u8>,
    now: SystemTime,
    r: &Finished<'_>,
    ms: f64,
    cache: Option<&str>,
) {
    // Writing to a Vec cannot fail.
    let _ = write!(
        out,
        "{}  INFO request id={} method={} route={}",
        humantime::format_rfc3339_micros(now),
        r.id,
        r.method,
        r.route
    );
    if let Some(status) = r.status {
        let _ = write!(out, " status={status}");
    }
    if let Some(code) = r.code {
        let _ = write!(out, " code={code}");
    }
    let _ = write!(out, " ms={ms:?}");
    if let Some(cache) = cache {
        let _ = write!(out, " cache={cache}");
    }
    if let Some(bytes) = r.bytes {
        let _ = write!(out, " bytes={bytes}");
    }
    out.push(b'\n');
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};
    use std::time::Duration;

    /// What `tracing-subscriber` writes, captured.
    #[derive(Clone, Default)]
    struct Captured(Arc<Mutex<Vec<u8>>>);

    impl std::io::Write for Captured {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            self.0.lock().expect("buffer").extend_from_slice(buf);
            Ok(buf.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    /// The same `tracing::info!` as `access_log::log_request`'s.
    fn through_tracing(r: &Finished<'_>, ms: f64, cache: Option<&str>) -> String {
        let captured = Captured::default();
        let sink = captured.clone();
        let subscriber = tracing_subscriber::fmt()
            .with_target(false)
            .with_ansi(false)
            .with_writer(move || sink.clone())
            .finish();
        tracing::subscriber::with_default(subscriber, || {
            tracing::info!(
                id = r.id,
                method = %r.method,
                route = %r.route,
                status = r.status,
                code = r.code.map(tracing::field::display),
                ms = ms,
                cache = cache.map(tracing::field::display),
                bytes = r.bytes,
                "request"
            );
        });
        let bytes = captured.0.lock().expect("buffer").clone();
        String::from_utf8(bytes).expect("utf-8")
    }

    /// Every field present and absent, and `ms` values whose `Debug` text
    /// differs from `Display`'s: the text after the timestamp is the
    /// formatter's, and the timestamp has its shape (RFC 3339, microseconds).
    #[test]
    fn the_direct_line_is_the_formatters_text() {
        let base = Finished {
            id: 7,
            method: "GET",
            route: "/v1/models/{file}",
            status: Some(200),
            code: None,
            wall: Duration::ZERO,
            bytes: Some(12460),
            etag: None,
            timing: None,
        };
        let cases = [
            (base, 0.635, Some("miss")),
            (
                Finished {
                    status: None,
                    code: Some("resource_exhausted"),
                    method: "grpc",
                    route: "Render",
                    bytes: None,
                    ..base
                },
                12.0,
                None,
            ),
            (
                Finished {
                    id: u64::MAX,
                    ..base
                },
                0.0,
                Some("memory"),
            ),
            (base, 1234567.125, Some("redis")),
            (base, 1e-7, None),
        ];
        for (r, ms, cache) in cases {
            let theirs = through_tracing(&r, ms, cache);
            let mut ours = Vec::new();
            write(
                &mut ours,
                SystemTime::UNIX_EPOCH + Duration::from_micros(1_796_560_746_058_664),
                &r,
                ms,
                cache,
            );
            let ours = String::from_utf8(ours).expect("utf-8");
            assert_eq!(
                ours.split_once(' ').map(|p| p.1),
                theirs.split_once(' ').map(|p| p.1),
                "{ours} against {theirs}"
            );
            assert_eq!(
                ours.split_once(' ').map(|p| p.0),
                Some("2026-12-06T12:39:06.058664Z")
            );
            let stamp = theirs.split_once(' ').map_or("", |p| p.0);
            assert!(
                stamp.len() == 27 && stamp.ends_with('Z') && stamp.as_bytes()[19] == b'.',
                "{stamp}"
            );
        }
    }
}
