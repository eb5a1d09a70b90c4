//! `Server-Timing` on every model response (HTTP), the same value in the
//! gRPC response metadata and in the request's JSON log line; its numbers
//! never add up to more than the request's wall time.

use super::{client, config, header, mdg, mdg_printable, render, server_timing, start, stop, EISEN};
use crate::common;
use crate::serve_child::ServeChild;
use rulemesh::service::grpc::pb;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use serde_json::{json, Value};
use std::time::{Duration, Instant};

/// Checks one `Server-Timing` value against what the request did: on a
/// miss the wait and the `stages` (in order) then the cache; on a hit the
/// cache (with its tier) only. Its durations add up to at most `wall`.
fn check(value: &str, stages: &[&str], hit: Option<&str>, wall: Duration) {
    let parts = server_timing(value);
    let names: Vec<&str> = parts.iter().map(|(n, _, _)| n.as_str()).collect();
    let mut want: Vec<&str> = Vec::new();
    match hit {
        None => {
            want.push("queue");
            want.extend(stages);
            want.push("cache");
        }
        Some(_) => want.extend(["cache", "tier"]),
    }
    assert_eq!(names, want, "{value}");
    let cache = parts.iter().find(|(n, _, _)| n == "cache").and_then(|(_, _, d)| d.as_deref());
    assert_eq!(cache, Some(if hit.is_some() { "hit" } else { "miss" }), "{value}");
    if let Some(tier) = hit {
        assert_eq!(parts.last().and_then(|(_, _, d)| d.as_deref()), Some(tier), "{value}");
    }
    let sum: f64 = parts.iter().filter_map(|(_, d, _)| *d).sum();
    let wall_ms = wall.as_secs_f64() * 1000.0;
    assert!(sum <= wall_ms, "Server-Timing adds up to {sum} ms, more than the {wall_ms} ms the request took: {value}");
    for (name, dur, _) in &parts {
        if name != "tier" {
            assert!(dur.is_some_and(|d| d >= 0.0), "{name} has no duration: {value}");
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_model_response_says_where_its_time_went() {
    let (srv, base) = start(config("t")).await;
    let lsystem = std::fs::read_to_string(common::repo().join("grammars/sierpinski-tetrahedron.ls")).expect("grammar");
    let mesh = ["parse", "eval", "mesh", "export"];
    let cases: Vec<(Value, &[&str])> = vec![
        (json!({"source": mdg("t1"), "format": "glb"}), &mesh),
        (json!({"source": EISEN, "language": "eisenscript", "format": "gltf"}), &mesh),
        (json!({"source": mdg_printable("t2"), "format": "stl", "print": true, "size_mm": 30}), &["parse", "eval", "mesh", "print", "export"]),
        (json!({"source": lsystem, "format": "scene"}), &["parse", "eval", "export"]),
        (json!({"source": mdg("t3"), "format": "strips"}), &mesh),
    ];
    for (body, stages) in &cases {
        for hit in [None, Some("memory")] {
            let started = Instant::now();
            let r = render(&base, body).await;
            let wall = started.elapsed();
            assert_eq!(r.status(), 200, "{body}");
            check(header(&r, "server-timing"), stages, hit, wall);
        }
    }
    // The GET route, its 304, and a bypass of the cache.
    let c = client();
    let url = format!("{base}/v1/models/gem.glb?seed=3");
    let started = Instant::now();
    let r = c.get(&url).send().await.expect("get");
    check(header(&r, "server-timing"), &mesh, None, started.elapsed());
    let etag = header(&r, "etag").to_string();
    let started = Instant::now();
    let r = c.get(&url).header("if-none-match", &etag).send().await.expect("get");
    assert_eq!(r.status(), 304);
    check(header(&r, "server-timing"), &mesh, Some("memory"), started.elapsed());
    let started = Instant::now();
    let r = c.post(format!("{base}/v1/render")).header("cache-control", "no-cache").json(&cases[0].0).send().await.expect("post");
    let parts = server_timing(header(&r, "server-timing"));
    assert!(parts.iter().any(|(n, _, _)| n == "parse") && parts.iter().all(|(n, _, _)| n != "tier"), "{parts:?}");
    assert!(parts.iter().filter_map(|(_, d, _)| *d).sum::<f64>() <= started.elapsed().as_secs_f64() * 1000.0);
    // Errors carry no model, and no Server-Timing.
    let r = render(&base, &json!({"source": "rule A {"})).await;
    assert_eq!((r.status().as_u16(), header(&r, "server-timing")), (400, ""));

    // gRPC: the same value as response metadata, on Render and RenderStream.
    let mut grpc = RulemeshClient::connect(format!("http://{}", srv.grpc_addr)).await.expect("gRPC connects");
    let request = || pb::RenderRequest { source: mdg("grpc"), format: "glb".into(), ..Default::default() };
    for hit in [None, Some("memory")] {
        let started = Instant::now();
        let reply = grpc.render(request()).await.expect("render");
        let wall = started.elapsed();
        let value = reply.metadata().get("server-timing").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
        check(&value, &mesh, hit, wall);
    }
    let started = Instant::now();
    let stream = grpc.render_stream(pb::RenderRequest { source: mdg("stream"), format: "stl".into(), ..Default::default() }).await.expect("stream");
    let value = stream.metadata().get("server-timing").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
    check(&value, &mesh, None, started.elapsed());
    stop(srv).await;
}

/// The access log (issue 33): at INFO, one short JSON line per request with
/// exactly method, route, status, milliseconds, cache result and bytes (no
/// span, no key, no timings); at DEBUG, a second line in the request's span
/// with the `Server-Timing` numbers as fields, equal to the header's.
#[test]
fn the_json_log_lines_of_a_request_are_short_at_info_with_the_numbers_at_debug() {
    let mut child = ServeChild::piped(&["--log-format", "json", "--log", "debug"], &[]);
    let rx = child.stderr_lines();
    let http = child.http;
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("runtime");
    let (value, length) = runtime.block_on(async {
        let r = render(&format!("http://{http}"), &json!({"source": mdg("log"), "format": "glb"})).await;
        assert_eq!(r.status(), 200);
        let value = header(&r, "server-timing").to_string();
        (value, r.bytes().await.expect("body").len())
    });
    let (mut short, mut detail) = (None, None);
    while short.is_none() || detail.is_none() {
        let line = rx.recv_timeout(Duration::from_secs(10)).expect("the request's log lines");
        let Ok(v) = serde_json::from_str::<Value>(&line) else { panic!("not a JSON log line: {line}") };
        if v["fields"]["message"] == "request" && v["fields"]["route"] == "/v1/render" {
            short = Some((v, line.len()));
        } else if v["fields"]["message"] == "request detail" && v["span"]["route"] == "/v1/render" {
            detail = Some(v);
        }
    }
    drop(child);
    let (Some((short, short_len)), Some(line)) = (short, detail) else { unreachable!("both lines were seen") };
    let mut names: Vec<&str> = short["fields"].as_object().expect("fields").keys().map(String::as_str).collect();
    names.sort_unstable();
    assert_eq!(names, ["bytes", "cache", "id", "message", "method", "ms", "route", "status"], "{short}");
    assert!(short.get("span").is_none() && short.get("spans").is_none(), "the short line carries no span: {short}");
    assert_eq!(short["fields"]["method"], "POST");
    assert_eq!(short["fields"]["status"], 200);
    assert_eq!(short["fields"]["cache"], "miss");
    assert_eq!(short["fields"]["bytes"].as_u64(), u64::try_from(length).ok(), "{short}");
    assert!(short_len < 240, "{short_len} bytes: {short}");
    let f = &line["fields"];
    assert_eq!(f["server_timing"], value.as_str(), "{line}");
    assert_eq!(f["status"], 200, "{line}");
    assert_eq!(f["id"], short["fields"]["id"], "the two lines share the request id");
    let parts = server_timing(&value);
    for (name, dur, _) in parts.iter().filter(|(n, _, _)| n != "cache") {
        let logged = f[format!("{name}_ms")].as_f64().unwrap_or_else(|| panic!("{name}_ms missing: {line}"));
        assert!((logged - dur.unwrap_or(-1.0)).abs() < 0.001, "{name}: {logged} logged, {dur:?} in the header");
    }
    assert!(f["cache_ms"].is_number() && f["ms"].as_f64().is_some_and(|ms| ms >= f["parse_ms"].as_f64().unwrap_or(f64::MAX)), "{line}");
    assert!(line["span"]["key"].is_string() && line["span"]["language"] == "mdg", "{line}");
}
