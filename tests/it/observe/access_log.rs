//! The access log's switch and its writer (issue 33), against the real
//! server process: `--access-log off` writes no request line while the
//! metrics still count every request, `sampled` writes exactly one line in
//! a hundred, and a log reader that never reads does not stall the service:
//! the writer drops lines and counts them instead.

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
