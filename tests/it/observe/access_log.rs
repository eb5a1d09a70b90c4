//! The access log's switch and its writer (issue 33), against the real
//! server process: `--access-log off` writes no request line while the
//! metrics still count every request, `sampled` writes exactly one line in
//! a hundred, and a log reader that never reads does not stall the service:
//! the writer drops lines and counts them instead. Cached GETs answered by
//! the fast path write the same line as the router's answers.

use super::sample;
use crate::serve_child::ServeChild;
use std::net::SocketAddr;
use std::sync::mpsc::Receiver;
use std::time::Duration;

/// `rulemesh serve` with JSON log lines at INFO and `extra` flags, its stderr piped.
fn serve(extra: &[&str]) -> ServeChild {
    let mut args = vec!["--log-format", "json", "--log", "info"];
    args.extend_from_slice(extra);
    ServeChild::piped(&args, &[])
}

/// `count` sequential `GET /healthz` (each a logged request), then the
/// metrics text; every request must answer within the client's timeout.
fn requests_then_metrics(http: SocketAddr, count: usize) -> String {
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("runtime");
    runtime.block_on(async {
        let c = reqwest::Client::builder().timeout(Duration::from_secs(5)).build().expect("client");
        for i in 0..count {
            let r = c.get(format!("http://{http}/healthz")).send().await.unwrap_or_else(|e| panic!("request {i} did not answer: {e}"));
            assert_eq!(r.status(), 200, "request {i}");
        }
        c.get(format!("http://{http}/metrics")).send().await.expect("metrics").text().await.expect("text")
    })
}

/// The request lines among what arrives on `rx` within a second of quiet.
fn request_lines(rx: &Receiver<String>) -> usize {
    let mut n = 0;
    while let Ok(line) = rx.recv_timeout(Duration::from_secs(1)) {
        n += usize::from(line.contains(r#""message":"request""#));
    }
    n
}

#[test]
fn access_log_off_writes_no_request_line_and_the_metrics_still_count() {
    let mut child = serve(&["--access-log", "off"]);
    let rx = child.stderr_lines();
    let m = requests_then_metrics(child.http, 50);
    assert_eq!(request_lines(&rx), 0);
    assert_eq!(sample(&m, r#"rulemesh_requests_total{protocol="http",route="/healthz",status="200"}"#), Some(50.0), "{m}");
    drop(child);
}

#[test]
fn access_log_sampled_writes_one_line_in_a_hundred() {
    let mut child = serve(&["--access-log", "sampled"]);
    let rx = child.stderr_lines();
    // 250 probes and the metrics scrape: requests 100 and 200 are logged.
    let _ = requests_then_metrics(child.http, 250);
    assert_eq!(request_lines(&rx), 2);
    drop(child);
}

/// A log reader that never reads: stderr is a pipe nobody drains, so it
/// fills after a few hundred lines. Every request still answers (within
/// the client's 5 s), and the dropped lines are counted.
#[test]
fn a_stalled_log_reader_costs_dropped_lines_not_a_stalled_service() {
    let child = serve(&["--log-buffer-lines", "16"]);
    let m = requests_then_metrics(child.http, 3000);
    let dropped = sample(&m, "rulemesh_log_lines_dropped_total").expect("the dropped-lines counter is exported");
    assert!(dropped > 0.0, "3,000 lines into a full pipe with a 16-line queue must drop some: {dropped}");
    drop(child);
}

/// `count` sequential GETs of `path`, then the metrics text.
fn gets_then_metrics(http: SocketAddr, path: &str, count: usize) -> String {
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("runtime");
    runtime.block_on(async {
        let c = reqwest::Client::builder().timeout(Duration::from_secs(30)).build().expect("client");
        for i in 0..count {
            let r = c.get(format!("http://{http}{path}")).send().await.unwrap_or_else(|e| panic!("request {i} did not answer: {e}"));
            assert_eq!(r.status(), 200, "request {i}");
            let _ = r.bytes().await.expect("body");
        }
        c.get(format!("http://{http}/metrics")).send().await.expect("metrics").text().await.expect("text")
    })
}

/// The cached-GET fast path (`service::fast`) writes the router's line: a
/// render, the router's hit, then two fast answers, each one JSON line with
/// the same fields but its own id and milliseconds; with the log off, none.
#[test]
fn fast_path_answers_write_the_routers_access_line_under_the_switch() {
    let mut child = serve(&[]);
    let rx = child.stderr_lines();
    let m = gets_then_metrics(child.http, "/v1/models/gem.glb?seed=5", 4);
    assert_eq!(sample(&m, "rulemesh_fast_path_hits_total"), Some(2.0), "{m}");
    let mut fields = Vec::new();
    while let Ok(line) = rx.recv_timeout(Duration::from_secs(1)) {
        let v: serde_json::Value = serde_json::from_str(&line).unwrap_or_default();
        if v["fields"]["message"] == "request" && v["fields"]["route"] == "/v1/models/{file}" {
            let mut f = v["fields"].clone();
            assert!(f["ms"].as_f64().is_some_and(|ms| ms >= 0.0), "{line}");
            f.as_object_mut().map(|o| (o.remove("id"), o.remove("ms")));
            fields.push((f, v["target"].clone(), v["level"].clone()));
        }
    }
    let caches: Vec<&str> = fields.iter().map(|(f, _, _)| f["cache"].as_str().unwrap_or("")).collect();
    assert_eq!(caches, ["miss", "memory", "memory", "memory"], "{fields:?}");
    assert_eq!(fields[3], fields[1], "a fast answer's line is the router's, but for its id and ms");
    assert_eq!(fields[2], fields[1]);
    assert_eq!(fields[1].0["bytes"], 12460);
    drop(child);
    let mut child = serve(&["--access-log", "off"]);
    let rx = child.stderr_lines();
    let m = gets_then_metrics(child.http, "/v1/models/gem.glb?seed=5", 4);
    assert_eq!(sample(&m, "rulemesh_fast_path_hits_total"), Some(2.0), "{m}");
    assert_eq!(request_lines(&rx), 0);
    drop(child);
}
