//! Issue 17's hardening, end to end against the real server: bad input
//! answered with typed errors, access control (keys, rates, shares,
//! ceilings, CORS, the JavaScript switch) over HTTP and gRPC, connection
//! hygiene, verified cache tiers, cache keys that change with every input
//! that changes output (issue 33), the deadline watchdog and the OpenAPI
//! document checked by schemathesis.

mod access;
mod cache;
mod conn;
mod deadline;
mod fresh;
mod input;
mod memory;
mod prints;
mod quick;
mod schema;
mod seeds;

use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use rulemesh::service::{self, Running, ServeConfig};
use serde_json::Value;
use std::time::Duration;

/// A config on ephemeral loopback ports.
pub fn config() -> ServeConfig {
    ServeConfig {
        http: "127.0.0.1:0".parse().expect("addr"),
        grpc: "127.0.0.1:0".parse().expect("addr"),
        body_limit: 64 * 1024,
        ..ServeConfig::default()
    }
}

/// Starts a server; its HTTP base URL.
pub async fn start(config: ServeConfig) -> (Running, String) {
    let running = service::start(config).await.expect("server starts");
    let base = format!("http://{}", running.http_addr);
    (running, base)
}

/// Stops a server and checks it stopped cleanly.
pub async fn stop(srv: Running) {
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

/// An HTTP client asking for identity encoding.
pub fn client() -> reqwest::Client {
    reqwest::Client::builder().timeout(Duration::from_secs(60)).no_gzip().no_brotli().no_zstd().build().expect("client")
}

/// A gRPC client of `srv`.
pub async fn grpc(srv: &Running) -> RulemeshClient<tonic::transport::Channel> {
    RulemeshClient::connect(format!("http://{}", srv.grpc_addr)).await.expect("gRPC connects")
}

/// The `error` object of a JSON error response.
pub async fn error_of(r: reqwest::Response) -> Value {
    let v: Value = r.json().await.expect("JSON error body");
    v["error"].clone()
}

/// A header's value as text ("" when absent).
pub fn header<'a>(r: &'a reqwest::Response, name: &str) -> &'a str {
    r.headers().get(name).and_then(|v| v.to_str().ok()).unwrap_or("")
}

/// A metric sample's value from `/metrics` text (the whole sample name with labels); 0 when absent.
pub fn sample(metrics: &str, name: &str) -> f64 {
    metrics.lines().find_map(|l| l.strip_prefix(name).and_then(|rest| rest.strip_prefix(' ')).and_then(|v| v.trim().parse().ok())).unwrap_or(0.0)
}

/// `/metrics` of the server at `base`.
pub async fn metrics(base: &str) -> String {
    client().get(format!("{base}/metrics")).send().await.expect("get").text().await.expect("text")
}

/// A small grammar; `tag` makes its source (and cache key) unique.
pub fn small(tag: &str) -> String {
    format!("// {tag}\nstartshape A\nrule A {{ 5 * {{ x 1.5 }} BOX {{ R 0.5 }} SPHERE {{ y 2 }} }}\n")
}
