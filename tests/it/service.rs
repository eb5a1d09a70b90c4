//! The service end to end: the real server on ephemeral ports, a real HTTP
//! client (reqwest) and a real gRPC client (tonic).

use crate::common;
use rulemesh::service::grpc::pb;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use rulemesh::service::{self, Running, ServeConfig};
use serde_json::{json, Value};
use std::time::Duration;

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

fn client() -> reqwest::Client {
    reqwest::Client::builder().timeout(Duration::from_secs(60)).build().expect("client")
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

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn health_grammars_metrics_and_404s() {
    let (srv, base) = start(config()).await;
    let c = client();
    assert_eq!(c.get(format!("{base}/healthz")).send().await.expect("get").status(), 200);
    assert_eq!(c.get(format!("{base}/readyz")).send().await.expect("get").status(), 200);

    let list: Value = c.get(format!("{base}/v1/grammars")).send().await.expect("get").json().await.expect("json");
    let grammars = list["grammars"].as_array().expect("array");
    let names: Vec<&str> = grammars.iter().filter_map(|g| g["name"].as_str()).collect();
    for n in ["gem", "menger", "tree", "stochastic"] {
        assert!(names.contains(&n), "{names:?}");
    }
    for g in grammars {
        assert_eq!(g["language"], "mdg");
        assert!(g["params"].is_array());
        assert!(!g["description"].as_str().unwrap_or("").is_empty(), "{g}");
        assert!(g.get("error").is_none(), "built-in grammar does not parse: {g}");
    }

    let src = c.get(format!("{base}/v1/grammars/gem")).send().await.expect("get");
    assert_eq!(src.status(), 200);
    assert_eq!(src.text().await.expect("text"), std::fs::read_to_string(common::repo().join("grammars/gem.mdg")).expect("file"));

    for path in ["/v1/grammars/nope", "/v1/models/nope.glb", "/v1/models/gem.obj", "/v1/models/gem", "/nowhere"] {
        let r = c.get(format!("{base}{path}")).send().await.expect("get");
        assert_eq!(r.status(), 404, "{path}");
        assert_eq!(error_body(r).await["code"], "not_found");
    }

    let m = c.get(format!("{base}/metrics")).send().await.expect("get");
    assert!(header(&m, "content-type").starts_with("text/plain"));
    let text = m.text().await.expect("text");
    for name in [
        "rulemesh_requests_total{protocol=\"http\",route=\"/v1/grammars\",status=\"200\"} 1",
        "rulemesh_requests_total{protocol=\"http\",route=\"unmatched\",status=\"404\"}",
        "rulemesh_render_duration_seconds_bucket",
        "rulemesh_cache_hits_total",
        "rulemesh_cache_misses_total",
        "rulemesh_cache_evictions_total",
        "rulemesh_cache_bytes",
        "rulemesh_renders_in_flight",
        "rulemesh_render_queue_depth",
    ] {
        assert!(text.contains(name), "metrics lack {name}:\n{text}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn render_formats_headers_cache_and_bypass() {
    let (srv, base) = start(config()).await;
    let source = small("formats");
    for (format, ctype) in [("glb", "model/gltf-binary"), ("gltf", "model/gltf+json"), ("stl", "model/stl"), ("stl-ascii", "model/stl")] {
        let r = post(&base, "/v1/render", &json!({"source": source, "format": format, "seed": 3})).await;
        assert_eq!(r.status(), 200, "{format}");
        assert_eq!(header(&r, "content-type"), ctype);
        assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
        assert_eq!(header(&r, "x-rulemesh-primitives"), "6");
        assert_eq!(header(&r, "x-rulemesh-truncated"), "false");
        assert!(header(&r, "x-rulemesh-triangles").parse::<u64>().expect("number") > 0);
        let etag = header(&r, "etag").to_string();
        assert!(etag.starts_with('"') && etag.ends_with('"') && etag.len() == 34, "{etag}");
        let bytes = r.bytes().await.expect("body");
        assert_eq!(etag.trim_matches('"'), &blake3::hash(&bytes).to_hex()[..32], "the ETag is the content hash");
        if format == "stl" {
            assert_eq!(common::decode_stl(&bytes).len() as u64 * 50 + 84, bytes.len() as u64);
        }
    }

    // Same request again: a hit with the same bytes and no render.
    let body = json!({"source": source, "seed": 3});
    let first = post(&base, "/v1/render", &body).await;
    assert_eq!(header(&first, "x-rulemesh-cache"), "hit");
    let renders = srv.state.metrics.renders();
    let again = post(&base, "/v1/render", &body).await;
    assert_eq!(header(&again, "x-rulemesh-cache"), "hit");
    assert_eq!(srv.state.metrics.renders(), renders);
    // CRLF line endings share the cache entry.
    let crlf = post(&base, "/v1/render", &json!({"source": source.replace('\n', "\r\n"), "seed": 3})).await;
    assert_eq!(header(&crlf, "x-rulemesh-cache"), "hit");
    let (e1, e2) = (header(&first, "etag").to_string(), header(&crlf, "etag").to_string());
    assert_eq!(e1, e2);

    // Cache-Control: no-cache renders afresh, with identical bytes.
    let fresh = client().post(format!("{base}/v1/render")).header("cache-control", "no-cache").json(&body).send().await.expect("post");
    assert_eq!(fresh.status(), 200);
    assert_eq!(header(&fresh, "x-rulemesh-cache"), "miss");
    assert_eq!(header(&fresh, "etag"), e1);
    assert_eq!(srv.state.metrics.renders(), renders + 1);
    assert_eq!(fresh.bytes().await.expect("body"), first.bytes().await.expect("body"));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn error_statuses() {
    let (srv, base) = start(config()).await;
    let c = client();
    // 400: malformed JSON, unknown field, bad value, parse error with position.
    let r = c.post(format!("{base}/v1/render")).body("{not json").send().await.expect("post");
    assert_eq!(r.status(), 400);
    assert_eq!(error_body(r).await["code"], "bad_request");
    for bad in [json!({"src": "x"}), json!({"source": small("f"), "format": "obj"}), json!({"source": small("d"), "detail": 100000})] {
        let r = post(&base, "/v1/render", &bad).await;
        assert_eq!(r.status(), 400, "{bad}");
        assert_eq!(error_body(r).await["code"], "bad_request", "{bad}");
    }
    let r = post(&base, "/v1/render", &json!({"source": "startshape A\nrule A {\n  BOX { x }\n}\n"})).await;
    assert_eq!(r.status(), 400);
    let e = error_body(r).await;
    assert_eq!(e["code"], "parse_error");
    assert_eq!((e["line"].as_u64(), e["column"].as_u64().is_some()), (Some(3), true), "{e}");

    // 413: body over the limit.
    let huge = json!({"source": format!("startshape A\nrule A {{ BOX {{}} }}\n//{}", "x".repeat(100 * 1024))});
    let r = post(&base, "/v1/render", &huge).await;
    assert_eq!(r.status(), 413);
    assert_eq!(error_body(r).await["code"], "payload_too_large");

    // 422: a limit, named with its configured and reached values.
    let r = post(&base, "/v1/render", &json!({"source": small("limit"), "limits": {"max_primitives": 3}})).await;
    assert_eq!(r.status(), 422);
    let e = error_body(r).await;
    assert_eq!((e["code"].as_str(), e["limit"].as_str(), e["configured"].as_u64(), e["reached"].as_u64()), (Some("limit_exceeded"), Some("primitives"), Some(3), Some(4)));

    // 504: the deadline.
    let r = post(&base, "/v1/render", &json!({"source": SLOW, "limits": {"timeout_ms": 50, "max_steps": 2_000_000_000u64}})).await;
    assert_eq!(r.status(), 504);
    let e = error_body(r).await;
    assert_eq!((e["code"].as_str(), e["limit"].as_str()), (Some("deadline_exceeded"), Some("deadline")));

    // Failures are not cached: the same bad request fails the same way again, and a good one after it works.
    let r = post(&base, "/v1/render", &json!({"source": small("limit"), "limits": {"max_primitives": 3}})).await;
    assert_eq!(r.status(), 422);
    let r = post(&base, "/v1/render", &json!({"source": small("limit"), "limits": {"max_primitives": 10}})).await;
    assert_eq!(r.status(), 200);

    let text = c.get(format!("{base}/metrics")).send().await.expect("get").text().await.expect("text");
    assert!(text.contains("rulemesh_budget_rejections_total{limit=\"primitives\"} 2"), "{text}");
    assert!(text.contains("rulemesh_budget_rejections_total{limit=\"deadline\"} 1"), "{text}");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn overload_sheds_with_503_and_retry_after() {
    let (srv, base) = start(ServeConfig { max_concurrency: 1, queue: 0, ..config() }).await;
    let slow = json!({"source": SLOW, "limits": {"timeout_ms": 1500, "max_steps": 2_000_000_000u64}, "on_limit": "truncate"});
    let b2 = base.clone();
    let hog = tokio::spawn(async move { post(&b2, "/v1/render", &slow).await });
    tokio::time::sleep(Duration::from_millis(300)).await;
    let r = post(&base, "/v1/render", &json!({"source": small("shed")})).await;
    assert_eq!(r.status(), 503);
    assert_eq!(header(&r, "retry-after"), "1");
    assert_eq!(error_body(r).await["code"], "overloaded");
    let hog = hog.await.expect("task");
    assert_eq!(hog.status(), 200);
    // Truncated: flagged, never stored, never marked cacheable.
    assert_eq!(header(&hog, "x-rulemesh-truncated"), "true");
    assert_eq!(header(&hog, "x-rulemesh-truncated-limit"), "deadline");
    assert_eq!(header(&hog, "cache-control"), "no-store");
    assert_eq!(srv.state.engine.cache().entry_count(), 0);
    // Once the slot is free the shed request succeeds.
    assert_eq!(post(&base, "/v1/render", &json!({"source": small("shed")})).await.status(), 200);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn truncation_is_flagged_and_not_cached() {
    let (srv, base) = start(config()).await;
    let body = json!({"source": small("trunc"), "limits": {"max_primitives": 4}, "on_limit": "truncate"});
    for _ in 0..2 {
        let r = post(&base, "/v1/render", &body).await;
        assert_eq!(r.status(), 200);
        assert_eq!(header(&r, "x-rulemesh-truncated"), "true");
        assert_eq!(header(&r, "x-rulemesh-truncated-limit"), "primitives");
        assert_eq!(header(&r, "x-rulemesh-primitives"), "4");
        assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
    }
    srv.state.engine.cache().sync().await;
    assert_eq!(srv.state.engine.cache().entry_count(), 0);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn models_etag_304_and_cache_control() {
    let (srv, base) = start(config()).await;
    let c = client();
    let r = c.get(format!("{base}/v1/models/gem.glb?seed=7")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "model/gltf-binary");
    assert_eq!(header(&r, "cache-control"), "public, max-age=31536000, immutable");
    let etag = header(&r, "etag").to_string();
    let bytes = r.bytes().await.expect("body");

    let r = c.get(format!("{base}/v1/models/gem.glb?seed=7")).header("if-none-match", &etag).send().await.expect("get");
    assert_eq!(r.status(), 304);
    assert_eq!(header(&r, "etag"), etag);
    assert!(r.bytes().await.expect("body").is_empty());
    let r = c.get(format!("{base}/v1/models/gem.glb?seed=7")).header("if-none-match", "\"other\"").send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-cache"), "hit");

    // The same model through POST /v1/render has the same bytes.
    let source = std::fs::read_to_string(common::repo().join("grammars/gem.mdg")).expect("gem");
    let p = post(&base, "/v1/render", &json!({"source": source, "seed": 7, "language": "mdg"})).await;
    assert_eq!(p.bytes().await.expect("body"), bytes);

    let r = c.get(format!("{base}/v1/models/tree.stl?detail=8")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "model/stl");
    assert_eq!(header(&r, "cache-control"), "public, max-age=300");
    let r = c.get(format!("{base}/v1/models/tower.gltf?seed=1")).send().await.expect("get");
    assert_eq!(header(&r, "content-type"), "model/gltf+json");

    for bad in ["gem.glb?seed=x", "gem.glb?colour=red", "gem.glb?p.size=3", "gem.glb?detail=1"] {
        let r = c.get(format!("{base}/v1/models/{bad}")).send().await.expect("get");
        assert_eq!(r.status(), 400, "{bad}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn check_reports_diagnostics_with_positions() {
    let (srv, base) = start(config()).await;
    let r = post(&base, "/v1/check", &json!({"source": small("check")})).await;
    assert_eq!(r.status(), 200);
    let v: Value = r.json().await.expect("json");
    assert_eq!((v["ok"].as_bool(), v["language"].as_str()), (Some(true), Some("mdg")));
    let r = post(&base, "/v1/check", &json!({"source": "startshape A\nrule A { BOX { x } }\n"})).await;
    let v: Value = r.json().await.expect("json");
    assert_eq!(v["ok"], false);
    let d = &v["diagnostics"][0];
    assert_eq!((d["severity"].as_str(), d["line"].as_u64()), (Some("error"), Some(2)), "{v}");
    assert!(d["column"].as_u64().is_some_and(|c| c > 1));
    assert_eq!(post(&base, "/v1/check", &json!({"source": "x", "language": "cfdg"})).await.status(), 400);
    assert_eq!(post(&base, "/v1/check", &json!({"text": "x"})).await.status(), 400);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn single_flight_100_concurrent_misses_render_once() {
    let (srv, base) = start(config()).await;
    // Big enough to take a while, so the requests overlap the render.
    let source = "// single flight\nstartshape A\nrule A { 40 * { x 1 } 40 * { y 1 } SPHERE {} }\n";
    let before = srv.state.metrics.renders();
    let c = client();
    let tasks: Vec<_> = (0..100)
        .map(|_| {
            let (c, base) = (c.clone(), base.clone());
            tokio::spawn(async move {
                let r = c.post(format!("{base}/v1/render")).json(&json!({"source": source, "detail": 24})).send().await.expect("post");
                assert_eq!(r.status(), 200);
                r.bytes().await.expect("body")
            })
        })
        .collect();
    let mut bodies = Vec::new();
    for t in tasks {
        bodies.push(t.await.expect("task"));
    }
    assert_eq!(srv.state.metrics.renders() - before, 1, "100 identical misses must render once");
    assert!(bodies.iter().all(|b| b == &bodies[0]));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn http_bytes_equal_cli_bytes() {
    let (srv, base) = start(config()).await;
    let source = std::fs::read_to_string(common::repo().join("grammars/stochastic.mdg")).expect("grammar");
    for (format, seed, detail) in [("glb", 5u64, 16u32), ("stl", 9, 8), ("gltf", 1, 12)] {
        let r = post(&base, "/v1/render", &json!({"source": source, "format": format, "seed": seed, "detail": detail})).await;
        assert_eq!(r.status(), 200);
        let http = r.bytes().await.expect("body");
        let cli = common::render_source(&source, &["--format", format, "--seed", &seed.to_string(), "--detail", &detail.to_string()]);
        assert!(http.as_ref() == cli.as_slice(), "{format}: HTTP and CLI bytes differ");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn graceful_shutdown_finishes_in_flight_render() {
    let (srv, base) = start(config()).await;
    let slow = json!({"source": SLOW, "limits": {"timeout_ms": 1200, "max_steps": 2_000_000_000u64}, "on_limit": "truncate"});
    let b2 = base.clone();
    let inflight = tokio::spawn(async move { post(&b2, "/v1/render", &slow).await });
    tokio::time::sleep(Duration::from_millis(300)).await;
    srv.shutdown();
    assert!(!srv.state.is_ready());
    let r = inflight.await.expect("task");
    assert_eq!(r.status(), 200, "the in-flight render finishes");
    assert_eq!(header(&r, "x-rulemesh-truncated"), "true");
    srv.wait().await.expect("clean shutdown");
    // Nothing listens any more.
    assert!(client().get(format!("{base}/healthz")).send().await.is_err());
}

async fn grpc_client(srv: &Running) -> RulemeshClient<tonic::transport::Channel> {
    RulemeshClient::connect(format!("http://{}", srv.grpc_addr)).await.expect("gRPC connects").max_decoding_message_size(usize::MAX)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_matches_http_and_maps_errors() {
    let (srv, base) = start(config()).await;
    let mut g = grpc_client(&srv).await;
    let source = std::fs::read_to_string(common::repo().join("grammars/tower.mdg")).expect("grammar");
    for format in ["glb", "stl", "gltf"] {
        let http = post(&base, "/v1/render", &json!({"source": source, "format": format, "seed": 2})).await.bytes().await.expect("body");
        let req = pb::RenderRequest { source: source.clone(), format: format.into(), seed: Some(2), ..Default::default() };
        let reply = g.render(req.clone()).await.expect("Render").into_inner();
        assert!(reply.model == http.as_ref(), "{format}: gRPC and HTTP bytes differ");
        let meta = reply.meta.expect("meta");
        assert!(meta.cache_hit);
        assert_eq!(meta.size, http.len() as u64);
        assert_eq!(meta.etag, blake3::hash(&http).to_hex()[..32]);

        let mut stream = g.render_stream(pb::RenderRequest { no_cache: true, ..req }).await.expect("RenderStream").into_inner();
        let mut bytes = Vec::new();
        let mut chunks = 0;
        while let Some(chunk) = stream.message().await.expect("chunk") {
            assert_eq!(chunk.meta.is_some(), chunks == 0);
            bytes.extend_from_slice(&chunk.data);
            chunks += 1;
        }
        assert!(bytes == http.as_ref(), "{format}: streamed bytes differ");
    }

    let err = g.render(pb::RenderRequest { source: "startshape A\nrule A { BOX { x } }".into(), ..Default::default() }).await.expect_err("parse error");
    assert_eq!(err.code(), tonic::Code::InvalidArgument);
    let details: Value = serde_json::from_slice(err.details()).expect("JSON details");
    assert_eq!(details["error"]["line"], 2);

    let limits = pb::Limits { max_primitives: Some(2), ..Default::default() };
    let err = g.render(pb::RenderRequest { source: small("grpc"), limits: Some(limits), ..Default::default() }).await.expect_err("limit");
    assert_eq!(err.code(), tonic::Code::ResourceExhausted);
    assert_eq!(err.metadata().get("x-rulemesh-limit").and_then(|v| v.to_str().ok()), Some("primitives"));

    let limits = pb::Limits { timeout_ms: Some(30), max_steps: Some(2_000_000_000), ..Default::default() };
    let err = g.render(pb::RenderRequest { source: SLOW.into(), limits: Some(limits), ..Default::default() }).await.expect_err("deadline");
    assert_eq!(err.code(), tonic::Code::DeadlineExceeded);

    let err = g.render(pb::RenderRequest { source: small("fmt"), format: "obj".into(), ..Default::default() }).await.expect_err("format");
    assert_eq!(err.code(), tonic::Code::InvalidArgument);

    let check = g.check(pb::CheckRequest { source: "startshape A\nrule A { BOX { x } }".into(), language: String::new() }).await.expect("Check").into_inner();
    assert!(!check.ok);
    assert_eq!(check.diagnostics[0].line, 2);

    let list = g.list_grammars(pb::ListGrammarsRequest {}).await.expect("ListGrammars").into_inner();
    assert!(list.grammars.iter().any(|x| x.name == "gem" && x.language == "mdg" && !x.description.is_empty()));

    let channel = tonic::transport::Endpoint::from_shared(format!("http://{}", srv.grpc_addr)).expect("uri").connect().await.expect("connect");
    let mut health = tonic_health::pb::health_client::HealthClient::new(channel);
    let status = health
        .check(tonic_health::pb::HealthCheckRequest { service: "rulemesh.v1.Rulemesh".into() })
        .await
        .expect("health")
        .into_inner();
    assert_eq!(status.status(), tonic_health::pb::health_check_response::ServingStatus::Serving);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
