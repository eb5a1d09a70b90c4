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

/// A client that asks for identity encoding (so the bytes and ETags seen are the model's own).
fn client() -> reqwest::Client {
    reqwest::Client::builder().timeout(Duration::from_secs(60)).no_gzip().no_brotli().no_zstd().build().expect("client")
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
async fn lsystems_render_as_scenes_and_instanced_or_flat_gltf() {
    let (srv, base) = start(config()).await;
    let source = std::fs::read_to_string(common::repo().join("grammars/sierpinski-tetrahedron.ls")).expect("grammar");
    let r = post(&base, "/v1/render", &json!({"source": source, "format": "scene"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/vnd.rulemesh.scene");
    assert_eq!(header(&r, "x-rulemesh-primitives"), "4096");
    let scene = r.bytes().await.expect("body");
    assert_eq!(rulemesh::export::scene::decode_scene(&scene).expect("decodes").leaves(), 4096);
    let gpu = post(&base, "/v1/render", &json!({"source": source, "format": "glb"})).await.bytes().await.expect("body");
    let flat = post(&base, "/v1/render", &json!({"source": source, "format": "glb", "instancing": "flat"})).await;
    assert_eq!(flat.status(), 200);
    let flat = flat.bytes().await.expect("body");
    let has_ext = |b: &[u8]| String::from_utf8_lossy(&b[..b.len().min(4096)]).contains("EXT_mesh_gpu_instancing");
    assert!(has_ext(&gpu) && !has_ext(&flat));
    assert!(gpu.len() * 20 < flat.len());
    let bad = post(&base, "/v1/render", &json!({"source": source, "instancing": "sometimes"})).await;
    assert_eq!(bad.status(), 400);
    let mdg = post(&base, "/v1/render", &json!({"source": small("scene"), "format": "scene"})).await;
    assert_eq!(mdg.status(), 400);
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
    // A Structure Synth JavaScript script is refused unless the operator allows
    // it (harden::access::javascript_switch_over_http_and_grpc has both cases).
    let js = json!({"source": "#javascript\nBuilder.load(\"NouveauMovie.es\");\nBuilder.build();\n", "language": "eisenscript"});
    let r = post(&base, "/v1/render", &js).await;
    assert_eq!(r.status(), 403);
    assert_eq!(error_body(r).await["code"], "javascript_disabled");
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

    // print=true travels over gRPC too, byte-identical to HTTP.
    let http = post(&base, "/v1/render", &json!({"source": source, "format": "3mf", "print": true, "size_mm": 40})).await.bytes().await.expect("body");
    let req = pb::RenderRequest { source: source.clone(), format: "3mf".into(), print: Some(true), size_mm: Some(40.0), ..Default::default() };
    let reply = g.render(req).await.expect("Render print").into_inner();
    assert!(reply.model == http.as_ref() && http.starts_with(b"PK"), "gRPC and HTTP print bytes differ");

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

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn openapi_document_lists_every_route_with_methods_and_errors() {
    let (srv, base) = start(config()).await;
    let c = client();
    let r = c.get(format!("{base}/openapi.json")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert!(header(&r, "content-type").starts_with("application/json"));
    let text = r.text().await.expect("text");
    // It parses as an OpenAPI 3 document (utoipa's own model of the spec).
    let parsed: utoipa::openapi::OpenApi = serde_json::from_str(&text).expect("an OpenAPI document");
    assert!(matches!(parsed.openapi, utoipa::openapi::OpenApiVersion::Version31));
    let doc: Value = serde_json::from_str(&text).expect("JSON");
    assert!(doc["openapi"].as_str().unwrap_or("").starts_with("3."), "{}", doc["openapi"]);
    assert_eq!(&doc, &serde_json::to_value(service::http::openapi()).expect("value"), "served = generated");

    // Every $ref points at a schema that exists.
    fn refs(v: &Value, out: &mut Vec<String>) {
        match v {
            Value::Object(m) => {
                for (k, x) in m {
                    match (k.as_str(), x) {
                        ("$ref", Value::String(r)) => out.push(r.clone()),
                        _ => refs(x, out),
                    }
                }
            }
            Value::Array(a) => a.iter().for_each(|x| refs(x, out)),
            _ => {}
        }
    }
    let mut all = Vec::new();
    refs(&doc, &mut all);
    assert!(!all.is_empty());
    for r in &all {
        let name = r.strip_prefix("#/components/schemas/").unwrap_or_else(|| panic!("unexpected $ref {r}"));
        assert!(doc["components"]["schemas"].get(name).is_some(), "dangling $ref {r}");
    }

    // The routes the issue asks for, with their methods and error statuses.
    let expected: &[(&str, &str, &[u16])] = &[
        ("/v1/render", "post", &[200, 400, 413, 422, 503, 504]),
        ("/v1/models/{file}", "get", &[200, 304, 400, 404, 422, 503, 504]),
        ("/v1/grammars", "get", &[200]),
        ("/v1/grammars/{name}", "get", &[200, 404]),
        ("/v1/check", "post", &[200, 400, 413]),
        ("/healthz", "get", &[200]),
        ("/readyz", "get", &[200, 503]),
        ("/metrics", "get", &[200]),
        ("/openapi.json", "get", &[200]),
    ];
    let paths = doc["paths"].as_object().expect("paths");
    let mut documented: Vec<&str> = paths.keys().map(String::as_str).collect();
    documented.sort_unstable();
    let mut wanted: Vec<&str> = expected.iter().map(|e| e.0).collect();
    wanted.sort_unstable();
    assert_eq!(documented, wanted, "documented paths");
    for (path, method, statuses) in expected {
        let op = &paths[*path];
        let methods: Vec<&str> = op.as_object().expect("operations").keys().map(String::as_str).collect();
        assert_eq!(methods, vec![*method], "{path}");
        for st in *statuses {
            let resp = &op[*method]["responses"][st.to_string()];
            assert!(resp.is_object(), "{method} {path} does not document {st}");
            if *st >= 400 {
                assert_eq!(resp["content"]["application/json"]["schema"]["$ref"], "#/components/schemas/ErrorBody", "{method} {path} {st}");
            }
        }
    }
    for schema in ["RenderBody", "LimitsBody", "CheckBody", "CheckReport", "GrammarList", "GrammarInfo", "ParamInfo", "ErrorBody", "ErrorDetail", "Diagnostic"] {
        assert!(doc["components"]["schemas"].get(schema).is_some(), "schema {schema}");
    }
    assert!(doc["components"]["schemas"]["RenderBody"]["properties"]["on_limit"].is_object());

    // Each documented path and method is served by the router (not the 404
    // fallback), and other methods on it answer 405.
    for (path, method, _) in expected {
        let url = format!("{base}{}", path.replace("{file}", "gem.glb").replace("{name}", "gem"));
        let r = match *method {
            "get" => c.get(&url).send().await,
            _ => c.post(&url).header("content-type", "application/json").body("{\"source\":\"\"}").send().await,
        }
        .expect("request");
        assert_ne!(header(&r, "x-rulemesh-error"), "not_found", "{method} {path} is documented but not routed");
        assert!(r.status().as_u16() < 500, "{method} {path}: {}", r.status());
        let other = if *method == "get" { c.delete(&url) } else { c.get(&url) };
        assert_eq!(other.send().await.expect("request").status(), 405, "{path}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn compression_is_negotiated_for_text_and_decodes() {
    let (srv, base) = start(config()).await;
    let plain = client();
    let source = small("compression");
    // Reference bodies in identity encoding.
    let gltf_url = format!("{base}/v1/models/tower.gltf?seed=2");
    let reference_gltf = plain.get(&gltf_url).send().await.expect("get");
    let gltf_etag = header(&reference_gltf, "etag").to_string();
    let reference_gltf = reference_gltf.bytes().await.expect("body");
    let ascii = json!({"source": source, "format": "stl-ascii", "seed": 1});
    let reference_ascii = post(&base, "/v1/render", &ascii).await.bytes().await.expect("body");
    let reference_list = plain.get(format!("{base}/v1/grammars")).send().await.expect("get").bytes().await.expect("body");
    assert!(reference_gltf.len() > 1000 && reference_ascii.len() > 1000 && reference_list.len() > 1000);

    for enc in ["gzip", "br", "zstd"] {
        // The raw response: encoded, with its own ETag and Vary.
        let r = plain.get(&gltf_url).header("accept-encoding", enc).send().await.expect("get");
        assert_eq!(header(&r, "content-encoding"), enc);
        assert!(header(&r, "vary").to_ascii_lowercase().contains("accept-encoding"), "{enc}");
        let tagged = header(&r, "etag").to_string();
        assert_eq!(tagged, format!("{}-{enc}\"", gltf_etag.trim_end_matches('"')));
        let raw = r.bytes().await.expect("body");
        assert!(raw.len() < reference_gltf.len() / 2, "{enc}: {} of {} bytes", raw.len(), reference_gltf.len());
        // A client holding the encoded variant's ETag gets 304.
        let r = plain.get(&gltf_url).header("if-none-match", &tagged).send().await.expect("get");
        assert_eq!(r.status(), 304, "{enc}");

        // A real client that decodes only this encoding gets the same bytes back.
        let decoding = reqwest::Client::builder()
            .gzip(enc == "gzip")
            .brotli(enc == "br")
            .zstd(enc == "zstd")
            .build()
            .expect("client");
        let r = decoding.get(&gltf_url).send().await.expect("get");
        assert!(header(&r, "etag").ends_with(&format!("-{enc}\"")), "{enc}: compressed on the wire");
        assert_eq!(r.bytes().await.expect("body"), reference_gltf, "{enc}: glTF");
        let r = decoding.post(format!("{base}/v1/render")).json(&ascii).send().await.expect("post");
        assert!(header(&r, "etag").ends_with(&format!("-{enc}\"")), "{enc}: ASCII STL compressed");
        assert_eq!(r.bytes().await.expect("body"), reference_ascii, "{enc}: ASCII STL");
        let r = decoding.get(format!("{base}/v1/grammars")).send().await.expect("get");
        assert_eq!(r.bytes().await.expect("body"), reference_list, "{enc}: JSON");
    }

    // Binary models go out as they are, whatever the client accepts.
    for url in [format!("{base}/v1/models/gem.glb?seed=1"), format!("{base}/v1/models/gem.stl?seed=1")] {
        let r = plain.get(&url).header("accept-encoding", "gzip, br, zstd").send().await.expect("get");
        assert_eq!(r.status(), 200);
        assert_eq!(header(&r, "content-encoding"), "", "{url}");
    }
    let r = plain.post(format!("{base}/v1/render")).header("accept-encoding", "gzip").json(&json!({"source": source})).send().await.expect("post");
    assert_eq!(header(&r, "content-type"), "model/gltf-binary");
    assert_eq!(header(&r, "content-encoding"), "");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_reflection_lists_the_services() {
    use tonic_reflection::pb::v1::server_reflection_client::ServerReflectionClient;
    use tonic_reflection::pb::v1::server_reflection_request::MessageRequest;
    use tonic_reflection::pb::v1::server_reflection_response::MessageResponse;
    use tonic_reflection::pb::v1::ServerReflectionRequest;
    let (srv, _base) = start(config()).await;
    let channel = tonic::transport::Channel::from_shared(format!("http://{}", srv.grpc_addr)).expect("uri").connect().await.expect("connects");
    let mut client = ServerReflectionClient::new(channel);
    let ask = |m: MessageRequest| ServerReflectionRequest { host: String::new(), message_request: Some(m) };
    let requests = vec![ask(MessageRequest::ListServices(String::new())), ask(MessageRequest::FileContainingSymbol("rulemesh.v1.Rulemesh".into()))];
    let mut replies = client.server_reflection_info(tokio_stream::iter(requests)).await.expect("reflection call").into_inner();
    let first = replies.message().await.expect("reply").expect("a reply");
    let Some(MessageResponse::ListServicesResponse(list)) = first.message_response else { panic!("{first:?}") };
    let names: Vec<&str> = list.service.iter().map(|s| s.name.as_str()).collect();
    for want in ["rulemesh.v1.Rulemesh", "grpc.health.v1.Health", "grpc.reflection.v1.ServerReflection"] {
        assert!(names.contains(&want), "{names:?}");
    }
    let second = replies.message().await.expect("reply").expect("a reply");
    let Some(MessageResponse::FileDescriptorResponse(files)) = second.message_response else { panic!("{second:?}") };
    assert!(files.file_descriptor_proto.iter().any(|f| f.windows(b"RenderStream".len()).any(|w| w == b"RenderStream")));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[test]
fn serve_config_precedence_flag_env_file_default() {
    let dir = common::tempdir();
    let toml_file = dir.path().join("rulemesh.toml");
    std::fs::write(&toml_file, "http = \"127.0.0.1:9101\"\nqueue = 7\nbody_limit = 1000\ngrace_ms = 1234\ncache_dir = \"/tmp/rm-cache\"\n").expect("write");
    let json_file = dir.path().join("rulemesh.json");
    std::fs::write(&json_file, r#"{"queue": 7, "cache_bytes": 4096}"#).expect("write");
    let run = |file: &std::path::Path, flags: &[&str], env: &[(&str, &str)]| -> Value {
        let mut cmd = std::process::Command::new(common::bin());
        cmd.arg("serve").arg("--config").arg(file).args(flags).arg("--print-config");
        for (k, _) in std::env::vars() {
            if k.starts_with("RULEMESH_") {
                cmd.env_remove(k);
            }
        }
        cmd.envs(env.iter().copied());
        let out = cmd.output().expect("runs");
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice(&out.stdout).expect("JSON config")
    };
    // File over default.
    let c = run(&toml_file, &[], &[]);
    assert_eq!((c["http"].as_str(), c["queue"].as_u64(), c["body_limit"].as_u64(), c["grace_ms"].as_u64()), (Some("127.0.0.1:9101"), Some(7), Some(1000), Some(1234)));
    assert_eq!(c["cache_dir"], "/tmp/rm-cache");
    assert_eq!(c["grpc"], "127.0.0.1:50051", "default where nothing sets it");
    // Environment over file; flag over environment.
    let c = run(&toml_file, &["--body-limit", "2000"], &[("RULEMESH_QUEUE", "9"), ("RULEMESH_BODY_LIMIT", "3000")]);
    assert_eq!((c["queue"].as_u64(), c["body_limit"].as_u64(), c["grace_ms"].as_u64()), (Some(9), Some(2000), Some(1234)));
    // A flag equal to the default still wins over the file.
    let c = run(&toml_file, &["--queue", "64"], &[]);
    assert_eq!(c["queue"], 64);
    // JSON files, and the file named by RULEMESH_CONFIG.
    let c = run(&json_file, &[], &[]);
    assert_eq!((c["queue"].as_u64(), c["cache_bytes"].as_u64()), (Some(7), Some(4096)));

    // The example in docs/service.md is a valid settings file.
    let doc = std::fs::read_to_string(common::repo().join("docs/service.md")).expect("docs/service.md");
    let example = doc.split("```toml\n").nth(1).and_then(|s| s.split("```").next()).expect("a TOML example");
    let doc_file = dir.path().join("doc.toml");
    std::fs::write(&doc_file, example).expect("write");
    let c = run(&doc_file, &[], &[]);
    assert_eq!((c["http"].as_str(), c["cache_dir"].as_str()), (Some("0.0.0.0:8080"), Some("/var/cache/rulemesh")));

    // Bad files are usage errors naming the file.
    let bad = dir.path().join("bad.toml");
    for text in ["queue = \"many\"\n", "colour = 1\n", "queue = \n"] {
        std::fs::write(&bad, text).expect("write");
        let out = std::process::Command::new(common::bin()).args(["serve", "--print-config", "--config"]).arg(&bad).output().expect("runs");
        assert_eq!(out.status.code(), Some(2), "{text}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("bad.toml"), "{text}");
    }
    let out = std::process::Command::new(common::bin()).args(["serve", "--print-config"]).env("RULEMESH_CONFIG", &json_file).output().expect("runs");
    assert!(out.status.success());
    let c: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(c["cache_bytes"], 4096);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn served_from_a_config_file_and_logs_language_and_key_per_request() {
    use std::io::BufRead;
    let dir = common::tempdir();
    let file = dir.path().join("serve.toml");
    std::fs::write(&file, "http = \"127.0.0.1:0\"\ngrpc = \"127.0.0.1:0\"\n").expect("write");
    let mut child = std::process::Command::new(common::bin())
        .arg("serve")
        .arg("--config")
        .arg(&file)
        .env_remove("RULEMESH_HTTP")
        .env_remove("RULEMESH_GRPC")
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("starts");
    let stderr = child.stderr.take().expect("stderr");
    let (tx, rx) = std::sync::mpsc::channel::<String>();
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stderr).lines().map_while(Result::ok) {
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    let next_matching = |want: &dyn Fn(&str) -> bool| -> String {
        loop {
            let line = rx.recv_timeout(Duration::from_secs(30)).expect("a log line");
            if want(&line) {
                return line;
            }
        }
    };
    let serving = next_matching(&|l| l.contains("rulemesh serving"));
    let addr = serving.split("http_addr=").nth(1).and_then(|s| s.split_whitespace().next()).expect("http_addr in the log");
    let base = format!("http://{addr}");
    let r = post(&base, "/v1/render", &json!({"source": small("log line")})).await;
    assert_eq!(r.status(), 200);
    let line = next_matching(&|l| l.contains("route=/v1/render") && l.contains("request"));
    let key = line.split("key=").nth(1).map(|s| s.chars().take_while(char::is_ascii_hexdigit).count());
    assert_eq!(key, Some(64), "{line}");
    for part in ["language=mdg", "cache=miss", "status=200", "id=", "ms="] {
        assert!(line.contains(part), "{part} missing from {line}");
    }
    let _ = child.kill();
    let _ = child.wait();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn disk_cache_survives_a_restart() {
    let dir = common::tempdir();
    let cache_dir = dir.path().join("cache");
    let disk_config = || ServeConfig { cache_dir: Some(cache_dir.clone()), ..config() };
    let key_files = || -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(&cache_dir)
            .expect("cache dir")
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .collect();
        names.sort();
        names
    };
    let request = json!({"source": small("disk tier"), "seed": 4, "format": "stl"});
    let (srv, base) = start(disk_config()).await;
    let r = post(&base, "/v1/render", &request).await;
    assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
    let etag = header(&r, "etag").to_string();
    let bytes = r.bytes().await.expect("body");
    let files = key_files();
    assert_eq!(files.len(), 1, "{files:?}");
    assert!(files[0].len() == 64 && files[0].chars().all(|c| c.is_ascii_hexdigit()), "named by the hex key: {files:?}");
    // A truncated render is not written.
    let r = post(&base, "/v1/render", &json!({"source": small("disk truncated"), "limits": {"max_primitives": 2}, "on_limit": "truncate"})).await;
    assert_eq!(header(&r, "x-rulemesh-truncated"), "true");
    assert_eq!(key_files().len(), 1);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");

    // A new server with an empty memory tier reads it back without rendering.
    let (srv, base) = start(disk_config()).await;
    let r = post(&base, "/v1/render", &request).await;
    assert_eq!(header(&r, "x-rulemesh-cache"), "hit");
    assert_eq!(header(&r, "etag"), etag);
    assert_eq!(r.bytes().await.expect("body"), bytes);
    assert_eq!(srv.state.metrics.renders(), 0, "served from disk");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");

    // A damaged file is dropped and the model rendered again.
    std::fs::write(cache_dir.join(&files[0]), b"RMCACHE1 garbage").expect("write");
    let (srv, base) = start(disk_config()).await;
    let r = post(&base, "/v1/render", &request).await;
    assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
    assert_eq!(r.bytes().await.expect("body"), bytes);
    assert_eq!(srv.state.metrics.renders(), 1);
    let r = post(&base, "/v1/render", &request).await;
    assert_eq!(header(&r, "x-rulemesh-cache"), "hit");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
    assert_eq!(key_files(), files, "rewritten after the damaged copy was dropped");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn metrics_add_up_to_the_requests_sent() {
    let (srv, base) = start(ServeConfig { max_concurrency: 1, queue: 4, ..config() }).await;
    let c = client();
    let mut sent = 0u64;
    let mut cacheable = 0u64;
    let mut misses = 0u64;
    // 5 GETs of one model: 1 miss, 4 hits.
    let url = format!("{base}/v1/models/gem.glb?seed=11");
    let mut etag = String::new();
    for _ in 0..5 {
        let r = c.get(&url).send().await.expect("get");
        assert_eq!(r.status(), 200);
        etag = header(&r, "etag").to_string();
        sent += 1;
        cacheable += 1;
    }
    misses += 1;
    // A 304 still looks the model up.
    assert_eq!(c.get(&url).header("if-none-match", &etag).send().await.expect("get").status(), 304);
    sent += 1;
    cacheable += 1;
    // 3 distinct renders and a bypass.
    for seed in 0..3 {
        assert_eq!(post(&base, "/v1/render", &json!({"source": small("sum"), "seed": seed})).await.status(), 200);
    }
    let r = c.post(format!("{base}/v1/render")).header("cache-control", "no-cache").json(&json!({"source": small("sum"), "seed": 0})).send().await.expect("post");
    assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
    sent += 4;
    cacheable += 4;
    misses += 4;
    // Bad requests and unknown routes, which never reach the cache.
    assert_eq!(c.post(format!("{base}/v1/render")).body("{").send().await.expect("post").status(), 400);
    assert_eq!(c.get(format!("{base}/nowhere")).send().await.expect("get").status(), 404);
    assert_eq!(c.get(format!("{base}/healthz")).send().await.expect("get").status(), 200);
    sent += 3;

    let text = c.get(format!("{base}/metrics")).send().await.expect("get").text().await.expect("text");
    assert_eq!(requests_total(&text, "http"), sent, "requests by route and status add up:\n{text}");
    let (hits, miss) = (metric(&text, "rulemesh_cache_hits_total"), metric(&text, "rulemesh_cache_misses_total"));
    assert_eq!((hits + miss) as u64, cacheable, "hits + misses = cacheable requests");
    assert_eq!(miss as u64, misses);
    assert_eq!(metric(&text, "rulemesh_renders_total") as u64, misses);
    assert_eq!(metric(&text, "rulemesh_renders_in_flight"), 0);
    assert_eq!(metric(&text, "rulemesh_render_queue_depth"), 0);

    // With one slot: one slow render runs and a second waits.
    let slow = |tag: &str| json!({"source": format!("// {tag}\n{SLOW}"), "limits": {"timeout_ms": 1500, "max_steps": 2_000_000_000u64}});
    let (b1, b2) = (base.clone(), base.clone());
    let (s1, s2) = (slow("one"), slow("two"));
    let first = tokio::spawn(async move { post(&b1, "/v1/render", &s1).await.status() });
    tokio::time::sleep(Duration::from_millis(200)).await;
    let second = tokio::spawn(async move { post(&b2, "/v1/render", &s2).await.status() });
    let mut seen = false;
    for _ in 0..50 {
        let text = c.get(format!("{base}/metrics")).send().await.expect("get").text().await.expect("text");
        if metric(&text, "rulemesh_renders_in_flight") == 1 && metric(&text, "rulemesh_render_queue_depth") == 1 {
            seen = true;
            break;
        }
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    assert!(seen, "/metrics shows one render in flight and one queued");
    assert_eq!(first.await.expect("task"), 504);
    assert_eq!(second.await.expect("task"), 504);
    let text = c.get(format!("{base}/metrics")).send().await.expect("get").text().await.expect("text");
    assert_eq!(metric(&text, "rulemesh_renders_in_flight"), 0);
    assert_eq!(metric(&text, "rulemesh_render_queue_depth"), 0);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn print_3mf_ug_stack_and_report_over_http() {
    let (srv, base) = start(config()).await;
    let source = "rule R { BOX {} BOX { x 0.5 } }";
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": 30, "format": "3mf"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "model/3mf");
    assert!(r.bytes().await.expect("body").starts_with(b"PK"));
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": 30, "print_report": true})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/json");
    let report: Value = r.json().await.expect("report");
    assert_eq!(report["is_watertight"], true);
    assert_eq!(report["shells"], 1);
    assert!((report["bbox_mm"][0].as_f64().expect("mm") - 30.0).abs() < 1e-3, "{report}");
    // STL responses carry the report as headers.
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "format": "stl"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-print-watertight"), "true");
    assert_eq!(header(&r, "x-print-shells"), "1");
    assert_eq!(header(&r, "x-print-volume-mm3"), "1.500");
    assert_eq!(header(&r, "x-print-bbox-mm"), "1.500 1.000 1.000");
    // size_mm without print is a 400, as is a nonsense size.
    let r = post(&base, "/v1/render", &json!({"source": source, "size_mm": 30})).await;
    assert_eq!(r.status(), 400);
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": -1})).await;
    assert_eq!(r.status(), 400);
    // The other new languages and format.
    let r = post(&base, "/v1/render", &json!({"source": "b1.5s1.4w0.1", "language": "stack", "format": "stl"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(common::decode_stl(&r.bytes().await.expect("body")).len(), 144);
    let r = post(&base, "/v1/render", &json!({"source": source, "format": "ug"})).await;
    assert_eq!(r.status(), 200);
    let ug = r.text().await.expect("text");
    let r = post(&base, "/v1/render", &json!({"source": ug, "language": "ug", "format": "stl"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(common::decode_stl(&r.bytes().await.expect("body")).len(), 24);
    // Built-in grammars print through the models route too.
    let r = client().get(format!("{base}/v1/models/tower.stl?print=true&size_mm=40")).send().await.expect("request");
    assert_eq!(r.status(), 200);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
