//! The deadline as a property of the service: for every language and both
//! `on_limit` modes, over HTTP and gRPC, a render that would run long ends
//! within 1.2× its deadline — by the pipeline's own checks, or by the
//! service's watchdog where a stage forgets to check.

use super::*;
use rulemesh::service::grpc::pb;
use serde_json::json;
use std::time::Instant;

/// The deadline every case runs under, in milliseconds.
const DEADLINE_MS: u64 = 1000;

/// One source per language that runs far past [`DEADLINE_MS`] unless
/// stopped, and what `on_limit=error` must answer: the deadline, except for
/// ETOL, whose primitive count is known before anything is built (so it
/// fails at once on the primitive limit, well within the deadline).
fn slow_sources() -> Vec<(&'static str, String, &'static str)> {
    let mut ug = String::from("def c0;\n  v a 0 0 0; v b 1 0 0; v c 1 1 0; v d 0 1 0;\n  f (a b c); f (a c d);\nend;\n");
    for k in 1..14 {
        ug.push_str(&format!("def c{k};\n  i (c{p});\n  i (c{p} -tx 1);\n  i (c{p} -ty 1);\nend;\n", p = k - 1));
    }
    ug.push_str("i (c13);\n");
    let deadline = "deadline_exceeded";
    vec![
        ("mdg", "startshape A\nrule A { 100000 * { x 1 } B {} }\nrule B { 100000 * { y 1 } C {} }\nrule C { }\n".to_string(), deadline),
        // The stochastic L-system (ABOP fig 1.27, 14 generations).
        ("lsystem", "iterations: 14\nangle: 25.7\naxiom: F\nF -> F[+F]F[-F]F : 0.33\nF -> F[+F]F : 0.33\nF -> F[-F]F : 0.34\n".to_string(), deadline),
        ("eisenscript", "set maxobjects 100000000\nR1\nrule R1 { 1000 * { x 1 } R2 }\nrule R2 { 1000 * { y 1 } R3 }\nrule R3 { 1000 * { z 1 } sphere }\n".to_string(), deadline),
        ("etol", "0.2 0.3 40 25 L 1 L LF&F&FL 1 L F".to_string(), "limit_exceeded"),
        ("stack", "o x7 r0.3 s s s s s s s s s s s s w0.05".to_string(), deadline),
        ("ug", ug, deadline),
    ]
}

fn server() -> ServeConfig {
    // Ceilings high enough that the deadline is what stops these sources,
    // low enough that a render the watchdog gave up on cannot take the machine.
    ServeConfig {
        body_limit: 1024 * 1024,
        ceiling_memory: 512 * 1024 * 1024,
        ceiling_primitives: 3_000_000,
        ceiling_triangles: 40_000_000,
        max_concurrency: 4,
        ..config()
    }
}

fn limits() -> Value {
    json!({"timeout_ms": DEADLINE_MS, "max_steps": 2_000_000_000u64, "max_memory": 512 * 1024 * 1024u64, "max_primitives": 3_000_000, "max_triangles": 40_000_000, "max_depth": 100_000})
}

/// How a slow render ended: within the bound, as the deadline error, or
/// (truncate mode) as a model truncated by a limit.
fn check(what: &str, took: Duration, truncate: bool, outcome: &str, on_error: &str) {
    let bound = Duration::from_millis(DEADLINE_MS * 12 / 10);
    assert!(took <= bound, "{what}: ended after {took:?}, more than 1.2 × {DEADLINE_MS} ms ({outcome})");
    if truncate {
        assert!(outcome == "deadline_exceeded" || outcome.starts_with("truncated:"), "{what}: {outcome}");
    } else {
        // Which limit ends a render first depends on how fast the machine
        // is (EisenScript may reach its primitive limit just before the
        // deadline): a limit error either way, never a model.
        assert!(outcome == on_error || outcome == "limit_exceeded", "{what}: {outcome}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn slow_renders_end_within_1_2x_their_deadline_over_http_and_grpc() {
    let (srv, base) = start(server()).await;
    let c = client();
    let mut g = grpc(&srv).await;
    for (language, source, on_error) in slow_sources() {
        for on_limit in ["error", "truncate"] {
            let truncate = on_limit == "truncate";
            let what = format!("HTTP {language} on_limit={on_limit}");
            let body = json!({"source": source, "language": language, "limits": limits(), "on_limit": on_limit, "format": "glb"});
            let t0 = Instant::now();
            let r = c.post(format!("{base}/v1/render")).header("cache-control", "no-cache").json(&body).send().await.expect("post");
            let status = r.status().as_u16();
            let outcome = if status == 200 {
                format!("truncated:{}", header(&r, "x-rulemesh-truncated-limit"))
            } else {
                error_of(r).await["code"].as_str().unwrap_or("?").to_string()
            };
            check(&what, t0.elapsed(), truncate, &outcome, on_error);

            let what = format!("gRPC {language} on_limit={on_limit}");
            let req = pb::RenderRequest {
                source: source.clone(),
                language: language.into(),
                on_limit: on_limit.into(),
                no_cache: true,
                limits: Some(pb::Limits {
                    timeout_ms: Some(DEADLINE_MS),
                    max_steps: Some(2_000_000_000),
                    max_memory: Some(512 * 1024 * 1024),
                    max_primitives: Some(3_000_000),
                    max_triangles: Some(40_000_000),
                    max_depth: Some(100_000),
                    ..Default::default()
                }),
                ..Default::default()
            };
            let t0 = Instant::now();
            let outcome = match g.render(req).await {
                Ok(r) => format!("truncated:{}", r.into_inner().meta.and_then(|m| m.truncated).map_or(String::new(), |t| t.limit)),
                Err(e) => e.metadata().get("x-rulemesh-error").and_then(|v| v.to_str().ok()).unwrap_or("?").to_string(),
            };
            check(&what, t0.elapsed(), truncate, &outcome, on_error);
        }
    }
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_requests_total{protocol=\"http\",route=\"/v1/render\",status=\"500\"}"), 0.0, "{m}");
    // Renders the watchdog gave up on may still hold their threads; shutdown
    // waits for requests, not for those, so it is clean.
    stop(srv).await;
}
