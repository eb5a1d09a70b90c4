//! API keys (401), rates (429 + Retry-After), concurrency shares, per-key
//! limit ceilings, CORS and the `#javascript` switch, over HTTP and gRPC.

use super::*;
use rulemesh::service::access::{ApiKeySpec, ApiKeys};
use rulemesh::service::grpc::pb;
use serde_json::json;
use tonic::metadata::MetadataValue;

/// A grammar that runs until its deadline (10^10 iterator copies, no primitives).
const SLOW: &str = "startshape A\nrule A { 100000 * { x 1 } B {} }\nrule B { 100000 * { y 1 } C {} }\nrule C { }\n";

const JS: &str = "#javascript\nBuilder.load(\"NouveauMovie.es\");\nBuilder.build();\n";
/// A movie of two pictures that loads nothing: one box, then two.
const INLINE_MOVIE: &str = "#javascript\nBuilder.append(\"box\");\nBuilder.build();\nBuilder.raytraceToFile(\"a.png\", true);\nBuilder.append(\"{ x 2 } box\");\nBuilder.build();\nBuilder.raytraceToFile(\"b.png\", true);\n";

fn key(name: &str, secret: &str) -> ApiKeySpec {
    ApiKeySpec::new(name, secret)
}

fn keyed() -> ServeConfig {
    ServeConfig {
        api_keys: ApiKeys(vec![
            // 1 request a second, 2 at once after a quiet spell.
            ApiKeySpec { rate_per_sec: Some(0.2), burst: Some(2), ..key("rated", "k-rate") },
            ApiKeySpec { ceiling_primitives: Some(3), ..key("small", "k-small") },
            ApiKeySpec { max_concurrency: Some(1), ..key("one", "k-one") },
            key("open", "k-open"),
        ]),
        cors_origins: vec!["https://app.example".into()],
        max_concurrency: 4,
        ..config()
    }
}

fn render_body(source: &str) -> Value {
    json!({"source": source})
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn http_keys_rates_shares_ceilings_and_cors() {
    let (srv, base) = start(keyed()).await;
    let c = client();
    let url = |p: &str| format!("{base}{p}");

    // No key, an unknown key, a malformed Authorization: 401 with WWW-Authenticate.
    for (name, value) in [("x-unused", "1"), ("authorization", "Bearer nope"), ("authorization", "Basic k-open"), ("x-api-key", "k-open2")] {
        let r = c.post(url("/v1/render")).header(name, value).json(&render_body(&small("401"))).send().await.expect("post");
        assert_eq!(r.status(), 401, "{name}: {value}");
        assert_eq!(header(&r, "www-authenticate"), "Bearer realm=\"rulemesh\"");
        assert_eq!(error_of(r).await["code"], "unauthorized");
    }
    assert_eq!(c.get(url("/v1/grammars")).send().await.expect("get").status(), 401);
    // Probes, metrics and the OpenAPI document need no key.
    for p in ["/healthz", "/readyz", "/metrics", "/openapi.json"] {
        assert_eq!(c.get(url(p)).send().await.expect("get").status(), 200, "{p}");
    }
    // Both header forms are accepted.
    let r = c.post(url("/v1/render")).bearer_auth("k-open").json(&render_body(&small("ok"))).send().await.expect("post");
    assert_eq!(r.status(), 200);
    let r = c.get(url("/v1/grammars")).header("x-api-key", "k-open").send().await.expect("get");
    assert_eq!(r.status(), 200);

    // The rate: a burst of 2, then 429 with the bucket's Retry-After (1 / 0.2 = 5 s).
    for _ in 0..2 {
        assert_eq!(c.get(url("/v1/grammars")).bearer_auth("k-rate").send().await.expect("get").status(), 200);
    }
    let r = c.get(url("/v1/grammars")).bearer_auth("k-rate").send().await.expect("get");
    assert_eq!(r.status(), 429);
    assert_eq!(header(&r, "retry-after"), "5");
    let e = error_of(r).await;
    assert_eq!((e["code"].as_str(), e["retry_after"].as_u64()), (Some("rate_limited"), Some(5)), "{e}");
    // Other keys are not affected.
    assert_eq!(c.get(url("/v1/grammars")).bearer_auth("k-open").send().await.expect("get").status(), 200);

    // The key's ceiling: max_primitives clamped to 3 whatever the request asks.
    let r = c
        .post(url("/v1/render"))
        .bearer_auth("k-small")
        .json(&json!({"source": small("ceiling"), "limits": {"max_primitives": 1000}}))
        .send()
        .await
        .expect("post");
    assert_eq!(r.status(), 422);
    let e = error_of(r).await;
    assert_eq!((e["limit"].as_str(), e["configured"].as_u64()), (Some("primitives"), Some(3)), "{e}");
    // The same request under a key without that ceiling renders.
    let r = c.post(url("/v1/render")).bearer_auth("k-open").json(&json!({"source": small("ceiling"), "limits": {"max_primitives": 1000}})).send().await.expect("post");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-primitives"), "6");

    // The concurrency share: one request of k-one at a time.
    let slow = json!({"source": SLOW, "limits": {"timeout_ms": 1500, "max_steps": 2_000_000_000u64}, "on_limit": "truncate"});
    let (c2, u2) = (c.clone(), url("/v1/render"));
    let hog = tokio::spawn(async move { c2.post(u2).bearer_auth("k-one").json(&slow).send().await.expect("post").status() });
    tokio::time::sleep(Duration::from_millis(400)).await;
    let r = c.get(url("/v1/grammars")).bearer_auth("k-one").send().await.expect("get");
    assert_eq!(r.status(), 429);
    assert_eq!(header(&r, "retry-after"), "1");
    assert_eq!(hog.await.expect("task"), 200);
    assert_eq!(c.get(url("/v1/grammars")).bearer_auth("k-one").send().await.expect("get").status(), 200, "the share is released");

    // CORS: a preflight from the allowed origin is answered without a key;
    // responses (errors too) carry the headers; other origins get none.
    let r = c
        .request(reqwest::Method::OPTIONS, url("/v1/render"))
        .header("origin", "https://app.example")
        .header("access-control-request-method", "POST")
        .header("access-control-request-headers", "authorization,content-type")
        .send()
        .await
        .expect("preflight");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "access-control-allow-origin"), "https://app.example");
    assert!(header(&r, "access-control-allow-methods").contains("POST"), "{:?}", r.headers());
    assert!(header(&r, "access-control-allow-headers").contains("authorization"), "{:?}", r.headers());
    let r = c.post(url("/v1/render")).header("origin", "https://app.example").json(&render_body(&small("cors"))).send().await.expect("post");
    assert_eq!((r.status().as_u16(), header(&r, "access-control-allow-origin")), (401, "https://app.example"));
    let r = c.get(url("/v1/grammars")).header("origin", "https://app.example").bearer_auth("k-open").send().await.expect("get");
    assert!(header(&r, "access-control-expose-headers").contains("etag") || header(&r, "access-control-expose-headers").contains("ETag"), "{:?}", r.headers());
    let r = c.get(url("/v1/grammars")).header("origin", "https://evil.example").bearer_auth("k-open").send().await.expect("get");
    assert_eq!((r.status().as_u16(), header(&r, "access-control-allow-origin")), (200, ""));

    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_access_rejections_total{reason=\"unauthorized\"}"), 6.0, "{m}");
    assert_eq!(sample(&m, "rulemesh_access_rejections_total{reason=\"rate_limited\"}"), 2.0, "{m}");
    stop(srv).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_keys_rates_shares_and_ceilings() {
    let (srv, _base) = start(keyed()).await;
    let mut g = grpc(&srv).await;
    let with = |k: &str, source: &str| {
        let mut r = tonic::Request::new(pb::RenderRequest { source: source.into(), ..Default::default() });
        if !k.is_empty() {
            r.metadata_mut().insert("authorization", MetadataValue::try_from(format!("Bearer {k}")).expect("ascii"));
        }
        r
    };
    for k in ["", "nope"] {
        let e = g.render(with(k, &small("g401"))).await.expect_err("401");
        assert_eq!(e.code(), tonic::Code::Unauthenticated, "{k}");
        assert_eq!(e.metadata().get("x-rulemesh-error").and_then(|v| v.to_str().ok()), Some("unauthorized"));
        let e = g.list_grammars(pb::ListGrammarsRequest {}).await.expect_err("401");
        assert_eq!(e.code(), tonic::Code::Unauthenticated);
    }
    // x-api-key works as well as authorization.
    let mut r = tonic::Request::new(pb::CheckRequest { source: small("chk"), language: String::new(), files: Default::default() });
    r.metadata_mut().insert("x-api-key", MetadataValue::from_static("k-open"));
    assert!(g.check(r).await.expect("check").into_inner().ok);
    assert_eq!(g.render(with("k-open", &small("gok"))).await.expect("renders").into_inner().meta.expect("meta").primitives, 6);

    // Rate: two, then ResourceExhausted with retry-after metadata.
    for _ in 0..2 {
        g.render(with("k-rate", &small("grate"))).await.expect("within the burst");
    }
    let e = g.render(with("k-rate", &small("grate"))).await.expect_err("429");
    assert_eq!(e.code(), tonic::Code::ResourceExhausted);
    assert_eq!(e.metadata().get("retry-after").and_then(|v| v.to_str().ok()), Some("5"));
    assert_eq!(e.metadata().get("x-rulemesh-error").and_then(|v| v.to_str().ok()), Some("rate_limited"));

    // Ceiling.
    let e = g.render(with("k-small", &small("gceil"))).await.expect_err("422");
    assert_eq!(e.code(), tonic::Code::ResourceExhausted);
    assert_eq!(e.metadata().get("x-rulemesh-limit").and_then(|v| v.to_str().ok()), Some("primitives"));
    let details: Value = serde_json::from_slice(e.details()).expect("json");
    assert_eq!(details["error"]["configured"], 3);

    // Share.
    let slow = pb::RenderRequest {
        source: SLOW.into(),
        on_limit: "truncate".into(),
        limits: Some(pb::Limits { timeout_ms: Some(1500), max_steps: Some(2_000_000_000), ..Default::default() }),
        ..Default::default()
    };
    let mut hog_req = tonic::Request::new(slow);
    hog_req.metadata_mut().insert("authorization", MetadataValue::from_static("Bearer k-one"));
    let mut g2 = g.clone();
    let hog = tokio::spawn(async move { g2.render(hog_req).await.map(|r| r.into_inner().meta.and_then(|m| m.truncated).is_some()) });
    tokio::time::sleep(Duration::from_millis(400)).await;
    let e = g.render(with("k-one", &small("gone"))).await.expect_err("over the share");
    assert_eq!((e.code(), e.metadata().get("retry-after").and_then(|v| v.to_str().ok())), (tonic::Code::ResourceExhausted, Some("1")));
    assert_eq!(hog.await.expect("task").expect("truncated model"), true);
    g.render(with("k-one", &small("gone"))).await.expect("the share is released");
    stop(srv).await;
}

/// `#javascript` is refused by default (403 / PermissionDenied) and runs when
/// the operator allows it (where `Builder.load` of a file is the script's own error).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn javascript_switch_over_http_and_grpc() {
    for allow in [false, true] {
        let (srv, base) = start(ServeConfig { allow_javascript: allow, ..config() }).await;
        let r = client().post(format!("{base}/v1/render")).json(&json!({"source": JS, "language": "eisenscript"})).send().await.expect("post");
        // Detected as EisenScript without a language too.
        let r2 = client().post(format!("{base}/v1/render")).json(&json!({"source": JS})).send().await.expect("post");
        let e = g_render(&srv, JS).await;
        if allow {
            assert_eq!(r.status(), 400);
            let err = error_of(r).await;
            assert_eq!(err["code"], "eval_error", "{err}");
            assert!(err["message"].as_str().is_some_and(|m| m.contains("reads no files")), "{err}");
            assert_eq!(r2.status(), 400);
            assert_eq!(e.code(), tonic::Code::InvalidArgument);
            // `frame` builds one picture of a movie, over both doors.
            let post = |body: serde_json::Value| client().post(format!("{base}/v1/render")).json(&body).send();
            let r = post(json!({"source": INLINE_MOVIE, "frame": 1})).await.expect("post");
            assert_eq!((r.status().as_u16(), r.headers().get("x-rulemesh-primitives").and_then(|v| v.to_str().ok())), (200, Some("2")));
            let r = post(json!({"source": INLINE_MOVIE, "frame": 0})).await.expect("post");
            assert_eq!((r.status().as_u16(), r.headers().get("x-rulemesh-primitives").and_then(|v| v.to_str().ok())), (200, Some("1")));
            for body in [json!({"source": INLINE_MOVIE, "frame": 2}), json!({"source": "box\n", "language": "eisenscript", "frame": 0})] {
                let r = post(body).await.expect("post");
                assert_eq!(r.status(), 400);
                let err = error_of(r).await;
                assert_eq!(err["code"], "eval_error", "{err}");
                assert!(err["message"].as_str().is_some_and(|m| m.starts_with("frame: ")), "{err}");
            }
            let mut g = grpc(&srv).await;
            let one = g.render(pb::RenderRequest { source: INLINE_MOVIE.into(), frame: Some(1), ..Default::default() }).await.expect("frame 1");
            assert_eq!(one.into_inner().meta.map(|m| m.primitives), Some(2));
            let e = g.render(pb::RenderRequest { source: INLINE_MOVIE.into(), frame: Some(7), ..Default::default() }).await.expect_err("no frame 7");
            assert_eq!(e.code(), tonic::Code::InvalidArgument);
        } else {
            for r in [r, r2] {
                assert_eq!(r.status(), 403);
                let err = error_of(r).await;
                assert_eq!(err["code"], "javascript_disabled", "{err}");
            }
            assert_eq!(e.code(), tonic::Code::PermissionDenied);
            assert_eq!(e.metadata().get("x-rulemesh-error").and_then(|v| v.to_str().ok()), Some("javascript_disabled"));
            // Plain EisenScript still renders.
            let ok = client().post(format!("{base}/v1/render")).json(&json!({"source": "box\n", "language": "eisenscript"})).send().await.expect("post");
            assert_eq!(ok.status(), 200);
            let m = metrics(&base).await;
            assert_eq!(sample(&m, "rulemesh_access_rejections_total{reason=\"javascript_disabled\"}"), 3.0, "{m}");
        }
        stop(srv).await;
    }
}

async fn g_render(srv: &Running, source: &str) -> tonic::Status {
    grpc(srv).await.render(pb::RenderRequest { source: source.into(), language: "eisenscript".into(), ..Default::default() }).await.expect_err("an error")
}
