//! Issue 21's observability, end to end against the real server: `/metrics`
//! on prometheus-client after a mix of requests (per-stage histograms by
//! language and format, per-tier cache figures with a real Redis), the
//! `Server-Timing` header and gRPC metadata, the JSON log line, the
//! dashboards and alerts checked by `promtool`, and OTLP traces received by a
//! real OTLP/gRPC collector the test runs.

mod access_log;
mod deploy;
mod metrics;
mod timing;
mod traces;

use rulemesh::service::ServeConfig;
use serde_json::Value;

/// A config on ephemeral loopback ports, labelled `worker`.
pub fn config(worker: &str) -> ServeConfig {
    ServeConfig {
        http: "127.0.0.1:0".parse().expect("addr"),
        grpc: "127.0.0.1:0".parse().expect("addr"),
        body_limit: 64 * 1024,
        worker_id: Some(worker.to_string()),
        ..ServeConfig::default()
    }
}

// The server and client helpers are harden's (one copy for the suite).
pub use crate::harden::{client, header, metrics, start, stop};

/// `POST /v1/render` with `body`.
pub async fn render(base: &str, body: &Value) -> reqwest::Response {
    client().post(format!("{base}/v1/render")).json(body).send().await.expect("request")
}

/// The value of the sample named exactly `name` (with its labels); `None` when absent.
pub fn sample(metrics: &str, name: &str) -> Option<f64> {
    metrics.lines().find_map(|l| l.strip_prefix(name).and_then(|rest| rest.strip_prefix(' ')).and_then(|v| v.trim().parse().ok()))
}

/// A small MDG grammar; `tag` makes its source (and cache key) unique.
pub fn mdg(tag: &str) -> String {
    format!("// {tag}\nstartshape A\nrule A {{ 5 * {{ x 1.5 }} BOX {{ R 0.5 }} SPHERE {{ y 2 }} }}\n")
}

/// A small MDG source that prints as one solid (overlapping boxes, a ball
/// on each), tagged like [`mdg`]: printing refuses pieces that do not touch.
pub fn mdg_printable(tag: &str) -> String {
    format!("// {tag}\nstartshape A\nrule A {{ 5 * {{ x 0.8 }} BOX {{ R 0.5 }} SPHERE {{ y 0.6 }} }}\n")
}

/// A small EisenScript.
pub const EISEN: &str = "set maxdepth 20\n10 * { x 1 } r\nrule r { box }\n";

/// The parts of a `Server-Timing` value: (name, dur in ms if any, desc if any).
pub fn server_timing(value: &str) -> Vec<(String, Option<f64>, Option<String>)> {
    value
        .split(',')
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .map(|p| {
            let mut fields = p.split(';');
            let name = fields.next().unwrap_or("").trim().to_string();
            let (mut dur, mut desc) = (None, None);
            for f in fields {
                match f.trim().split_once('=') {
                    Some(("dur", v)) => dur = v.parse().ok(),
                    Some(("desc", v)) => desc = Some(v.trim_matches('"').to_string()),
                    _ => {}
                }
            }
            (name, dur, desc)
        })
        .collect()
}
