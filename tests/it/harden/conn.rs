//! Connection hygiene: stalled headers are cut off at the header timeout,
//! idle keep-alive connections at the idle timeout, and the open-connection
//! cap holds, while normal requests keep being answered.

use super::*;
use serde_json::json;
use std::sync::atomic::{AtomicI64, Ordering};
use std::sync::Arc;
use std::time::Instant;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

/// Half a request head, as a slow or malicious client sends it.
const HALF: &[u8] = b"POST /v1/render HTTP/1.1\r\nHost: rulemesh\r\nContent-Le";

/// Opens `n` connections that each send [`HALF`] and then stall.
/// Each comes with the moment it was opened.
async fn stalled(addr: std::net::SocketAddr, n: usize) -> Vec<(TcpStream, Instant)> {
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        let t = Instant::now();
        let mut s = TcpStream::connect(addr).await.expect("connect");
        s.write_all(HALF).await.expect("write half a head");
        out.push((s, t));
    }
    out
}

/// Reads until the server closes `s` (EOF or reset); how long after `t0`
/// that was. Panics if it is still open `limit` after `t0`.
async fn closed_within((mut s, t0): (TcpStream, Instant), limit: Duration) -> Duration {
    let mut buf = [0u8; 1024];
    loop {
        match tokio::time::timeout(limit.saturating_sub(t0.elapsed()), s.read(&mut buf)).await {
            Ok(Ok(0)) | Ok(Err(_)) => return t0.elapsed(),
            Ok(Ok(_)) => continue,
            Err(_) => panic!("the connection was still open after {limit:?}"),
        }
    }
}

/// Waits until the server counts `n` open connections.
async fn until_open(srv: &Running, n: i64) {
    let deadline = Instant::now() + Duration::from_secs(10);
    while srv.state.metrics.connections_open() != n {
        assert!(Instant::now() < deadline, "open connections: {} (waiting for {n})", srv.state.metrics.connections_open());
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn stalled_headers_are_closed_after_the_timeout_while_requests_are_served_and_the_cap_holds() {
    let cap = 64;
    let timeout = Duration::from_millis(1000);
    let (srv, base) = start(ServeConfig { header_timeout_ms: 1000, idle_timeout_ms: 500, max_connections: cap, ..config() }).await;
    let addr = srv.http_addr;
    // The highest open-connection count seen, sampled throughout.
    let peak = Arc::new(AtomicI64::new(0));
    let sampler = {
        let (peak, state) = (peak.clone(), srv.state.clone());
        tokio::spawn(async move {
            loop {
                peak.fetch_max(state.metrics.connections_open(), Ordering::Relaxed);
                tokio::time::sleep(Duration::from_millis(2)).await;
            }
        })
    };

    // Under the cap: 40 stalled connections, and normal requests answered meanwhile.
    let held = stalled(addr, 40).await;
    until_open(&srv, 40).await;
    let c = client();
    for i in 0..5 {
        let r = c.post(format!("{base}/v1/render")).json(&json!({"source": small(&format!("during-{i}"))})).send().await.expect("post");
        assert_eq!(r.status(), 200);
    }
    let waits = futures_join(held.into_iter().map(|s| closed_within(s, Duration::from_secs(5)))).await;
    for w in &waits {
        // Closed by the timeout: not before it, and not long after.
        assert!(*w >= timeout - Duration::from_millis(20) && *w <= timeout + Duration::from_millis(1500), "closed after {w:?}");
    }
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_http_connections_closed_total{reason=\"header_timeout\"}"), 40.0, "{m}");

    // Over the cap: 100 stalled connections; the server never holds more
    // than the cap, and a normal request is still answered once the first
    // ones have timed out.
    drop(c);
    tokio::time::sleep(Duration::from_millis(1000)).await; // the clients' keep-alive connections idle out
    until_open(&srv, 0).await;
    peak.store(0, Ordering::Relaxed);
    let held = stalled(addr, 100).await;
    until_open(&srv, cap as i64).await;
    let r = client().post(format!("{base}/v1/render")).json(&json!({"source": small("over-cap")})).send().await.expect("post");
    assert_eq!(r.status(), 200, "a request behind the stalled ones is answered");
    let waits = futures_join(held.into_iter().map(|s| closed_within(s, Duration::from_secs(10)))).await;
    assert_eq!(waits.len(), 100);
    assert!(peak.load(Ordering::Relaxed) <= cap as i64, "peak {} over the cap {cap}", peak.load(Ordering::Relaxed));
    assert_eq!(peak.load(Ordering::Relaxed), cap as i64, "the cap was reached");
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_http_connections_closed_total{reason=\"header_timeout\"}"), 140.0, "{m}");
    sampler.abort();
    stop(srv).await;
}

/// A keep-alive connection with nothing in flight is closed at the idle
/// timeout (here shorter than the header timeout), after its response.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn idle_keep_alive_connections_are_closed() {
    let (srv, base) = start(ServeConfig { header_timeout_ms: 20_000, idle_timeout_ms: 300, ..config() }).await;
    let mut s = TcpStream::connect(srv.http_addr).await.expect("connect");
    let opened = Instant::now();
    s.write_all(b"GET /healthz HTTP/1.1\r\nHost: rulemesh\r\n\r\n").await.expect("write");
    let mut got = Vec::new();
    let mut buf = [0u8; 512];
    while !got.ends_with(b"ok\n") {
        let n = tokio::time::timeout(Duration::from_secs(5), s.read(&mut buf)).await.expect("a response").expect("read");
        assert!(n > 0, "closed before the response");
        got.extend_from_slice(&buf[..n]);
    }
    assert!(got.starts_with(b"HTTP/1.1 200"), "{}", String::from_utf8_lossy(&got));
    let answered = opened.elapsed();
    let waited = closed_within((s, Instant::now()), Duration::from_secs(5)).await;
    assert!(waited + answered >= Duration::from_millis(300) && waited <= Duration::from_millis(2000), "closed {waited:?} after the response");
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_http_connections_closed_total{reason=\"idle\"}"), 1.0, "{m}");
    stop(srv).await;
}

/// Awaits every future concurrently, results in order.
async fn futures_join<F: std::future::Future + Send + 'static>(futs: impl Iterator<Item = F>) -> Vec<F::Output>
where
    F::Output: Send + 'static,
{
    let handles: Vec<_> = futs.map(tokio::spawn).collect();
    let mut out = Vec::with_capacity(handles.len());
    for h in handles {
        out.push(h.await.expect("task"));
    }
    out
}

/// Waits up to `limit` for the server to send anything on `s` (its HTTP/2
/// SETTINGS, sent as soon as a connection is accepted); the bytes read.
async fn first_bytes(s: &mut TcpStream, limit: Duration) -> usize {
    let mut buf = [0u8; 256];
    match tokio::time::timeout(limit, s.read(&mut buf)).await {
        Ok(Ok(n)) => n,
        Ok(Err(_)) | Err(_) => 0,
    }
}

/// The gRPC port has the same hygiene: a connection that sends no HTTP/2
/// preface is closed at the header timeout, the open-connection cap holds
/// (the connection past it is not even accepted until one closes), and a
/// real gRPC call is answered afterwards.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_connections_without_a_preface_are_closed_and_the_cap_holds() {
    let cap = 8;
    let timeout = Duration::from_millis(1000);
    let (srv, _base) = start(ServeConfig { header_timeout_ms: 1000, idle_timeout_ms: 5000, max_connections: cap, ..config() }).await;
    let addr = srv.grpc_addr;
    let mut held = Vec::new();
    for _ in 0..cap {
        let t = Instant::now();
        let mut s = TcpStream::connect(addr).await.expect("connect");
        assert!(first_bytes(&mut s, Duration::from_secs(2)).await > 0, "an accepted connection gets the server's SETTINGS");
        held.push((s, t));
    }
    // One past the cap: connected by the kernel, not accepted by the server.
    let t_extra = Instant::now();
    let mut extra = TcpStream::connect(addr).await.expect("connect");
    assert_eq!(first_bytes(&mut extra, Duration::from_millis(400)).await, 0, "the connection past the cap was accepted");
    let waits = futures_join(held.into_iter().map(|s| closed_within(s, Duration::from_secs(5)))).await;
    for w in &waits {
        assert!(*w >= timeout - Duration::from_millis(20) && *w <= timeout + Duration::from_millis(1500), "closed after {w:?}");
    }
    // Now a slot is free: the waiting connection is accepted, and it too is
    // closed for saying nothing, a timeout after its acceptance.
    assert!(first_bytes(&mut extra, Duration::from_secs(2)).await > 0, "accepted once a slot was free");
    let w = closed_within((extra, t_extra), Duration::from_secs(6)).await;
    assert!(w >= timeout, "closed after {w:?}");
    let mut g = grpc(&srv).await;
    let r = g.render(rulemesh::service::grpc::pb::RenderRequest { source: small("grpc-after-stall"), ..Default::default() }).await;
    assert!(r.is_ok(), "{r:?}");
    stop(srv).await;
}
