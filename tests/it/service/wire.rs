//! Responses as they come off the wire, for tests that compare two ways
//! of answering one request (the cached-GET fast path, the direct model
//! route) with the router's: the status line and header lines in order,
//! with the per-request values masked, and the body.

use rulemesh::service::Running;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

/// One response as it came off the wire: the status line and header lines
/// in order (the per-request values masked), and the body.
#[derive(Debug, PartialEq)]
pub(super) struct Wire {
    pub(super) head: Vec<String>,
    pub(super) body: Vec<u8>,
}

/// Sends `request` (a whole HTTP/1.1 request) on a new connection and reads one response.
pub(super) async fn raw(srv: &Running, request: &str) -> Wire {
    let mut s = tokio::net::TcpStream::connect(srv.http_addr).await.expect("connect");
    s.write_all(request.as_bytes()).await.expect("send");
    let mut buf = Vec::new();
    let head_end = loop {
        let mut chunk = [0u8; 4096];
        let n = s.read(&mut chunk).await.expect("read");
        assert!(n > 0, "connection closed before the head: {}", String::from_utf8_lossy(&buf));
        buf.extend_from_slice(&chunk[..n]);
        if let Some(i) = buf.windows(4).position(|w| w == b"\r\n\r\n") {
            break i;
        }
    };
    let head = String::from_utf8(buf[..head_end].to_vec()).expect("ASCII head");
    let length: usize = match request.starts_with("HEAD ") {
        true => 0,
        false => head.lines().find_map(|l| l.strip_prefix("content-length: ")).map_or(0, |v| v.parse().expect("length")),
    };
    let mut body = buf[head_end + 4..].to_vec();
    while body.len() < length {
        let mut chunk = vec![0u8; length - body.len()];
        let n = s.read(&mut chunk).await.expect("read body");
        assert!(n > 0, "connection closed in the body");
        body.extend_from_slice(&chunk[..n]);
    }
    let head = head.lines().map(mask).collect();
    Wire { head, body }
}

/// Masks a header line's per-request value: the request id, the date, and
/// the lookup's duration in `Server-Timing` (its names and order stay).
pub(super) fn mask(line: &str) -> String {
    if line.starts_with("x-request-id: ") {
        return "x-request-id: N".into();
    }
    if line.starts_with("date: ") {
        return "date: D".into();
    }
    if let Some(v) = line.strip_prefix("server-timing: ") {
        let parts: Vec<String> = v.split(", ").map(|p| p.split(';').filter(|f| !f.starts_with("dur=")).collect::<Vec<_>>().join(";")).collect();
        return format!("server-timing: {}", parts.join(", "));
    }
    line.to_string()
}

/// A whole `GET target` request with the header lines `extra` (each ending in CRLF).
pub(super) fn get(target: &str, extra: &str) -> String {
    format!("GET {target} HTTP/1.1\r\nhost: localhost\r\n{extra}\r\n")
}

/// The value of header `name` in `w` ("" when absent).
pub(super) fn line<'a>(w: &'a Wire, name: &str) -> &'a str {
    w.head.iter().find_map(|l| l.strip_prefix(name)?.strip_prefix(": ")).unwrap_or("")
}
