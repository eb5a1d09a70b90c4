//! The service end to end: the real server on ephemeral ports, a real HTTP
//! client (reqwest) and a real gRPC client (tonic).

use crate::common;
use rulemesh::service::grpc::pb;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use rulemesh::service::{self, Running, ServeConfig};
use serde_json::{json, Value};
use std::time::Duration;

mod grpc;
mod http;
mod ops;
mod schema;
mod icons;
mod playground;
mod variations;
mod library;
mod print_report;
mod options;
mod phone;
mod fast;
mod direct;
mod wire;


/// A grammar that runs until its deadline (10^10 iterator copies, no primitives).
const SLOW: &str = "startshape A\nrule A { 100000 * { x 1 } B {} }\nrule B { 100000 * { y 1 } C {} }\nrule C { }\n";

/// A small grammar; `tag` makes its source (and so its cache key) unique.
fn small(tag: &str) -> String {
    format!("// {tag}\nstartshape A\nrule A {{ 5 * {{ x 1.5 }} BOX {{ R 0.5 }} SPHERE {{ y 2 }} }}\n")
}

fn config() -> ServeConfig {
    ServeConfig {
        http: "127.0.0.1:0".parse().expect("addr"),
        grpc: "127.0.0.1:0".parse().expect("addr"),
        body_limit: 64 * 1024,
        ..ServeConfig::default()
    }
}

async fn start(config: ServeConfig) -> (Running, String) {
    let running = service::start(config).await.expect("server starts");
    let base = format!("http://{}", running.http_addr);
    (running, base)
}

/// A client that asks for identity encoding (so the bytes and ETags seen are the model's own).
fn client() -> reqwest::Client {
    reqwest::Client::builder().timeout(Duration::from_secs(60)).no_gzip().no_brotli().no_zstd().build().expect("client")
}

/// A gRPC client of `srv`, taking replies of any size.
async fn grpc_client(srv: &Running) -> RulemeshClient<tonic::transport::Channel> {
    RulemeshClient::connect(format!("http://{}", srv.grpc_addr)).await.expect("gRPC connects").max_decoding_message_size(usize::MAX)
}

async fn post(base: &str, path: &str, body: &Value) -> reqwest::Response {
    client().post(format!("{base}{path}")).json(body).send().await.expect("request")
}

fn header<'a>(r: &'a reqwest::Response, name: &str) -> &'a str {
    r.headers().get(name).and_then(|v| v.to_str().ok()).unwrap_or("")
}

async fn error_body(r: reqwest::Response) -> Value {
    let v: Value = r.json().await.expect("JSON error body");
    assert!(v["error"]["code"].is_string() && v["error"]["message"].is_string(), "{v}");
    v["error"].clone()
}

/// `rulemesh_requests_total` lines for `protocol`, summed.
fn requests_total(metrics: &str, protocol: &str) -> u64 {
    metrics
        .lines()
        .filter(|l| l.starts_with(&format!("rulemesh_requests_total{{protocol=\"{protocol}\"")))
        .filter_map(|l| l.rsplit(' ').next()?.parse::<u64>().ok())
        .sum()
}

/// The value of an unlabelled metric.
fn metric(metrics: &str, name: &str) -> i64 {
    metrics
        .lines()
        .find_map(|l| l.strip_prefix(name)?.strip_prefix(' ')?.parse().ok())
        .unwrap_or_else(|| panic!("no {name} in\n{metrics}"))
}
