//! The direct model route (`service::direct`, issue 33): a model `GET` it
//! answers gets the router's answer, byte for byte on the wire (modulo the
//! request id, the durations and the date). The router's twin of each
//! request is the same request with the file name's `.` spelled `%2E`:
//! axum decodes it to the same file, and the direct route leaves every
//! `%` to the router. Each case checks that the direct route answered one
//! and the router the other, so the comparison cannot pass vacuously.

use super::wire::{get, line, raw, Wire};
use super::*;

async fn direct_answers(base: &str) -> i64 {
    let text = client().get(format!("{base}/metrics")).send().await.expect("metrics").text().await.expect("text");
    metric(&text, "rulemesh_direct_model_requests_total")
}

/// Sends `target` (whose path ends in `NAME.EXT`) the direct way and the
/// router's way (`NAME%2EEXT`) with the header lines `extra`, checks that
/// each took its way, and returns both answers.
async fn both(srv: &Running, base: &str, target: &str, extra: &str) -> (Wire, Wire) {
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    let (dir, file) = path.rsplit_once('/').expect("a path");
    let escaped = format!("{dir}/{}?{query}", file.replacen('.', "%2E", 1));
    let before = direct_answers(base).await;
    let direct = raw(srv, &get(target, extra)).await;
    assert_eq!(direct_answers(base).await, before + 1, "{target}: the direct route answered");
    let routed = raw(srv, &get(&escaped, extra)).await;
    assert_eq!(direct_answers(base).await, before + 1, "{escaped}: the router answered");
    (direct, routed)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn direct_answers_are_the_routers_on_the_wire() {
    let (srv, base) = start(config()).await;
    let fresh = "cache-control: no-cache\r\n";
    // Fresh renders, binary and text (the text one compressed for a client that takes gzip).
    for (target, extra) in [
        ("/v1/models/gem.glb?seed=5", fresh.to_string()),
        ("/v1/models/gem.gltf?seed=5&detail=8", format!("{fresh}accept-encoding: gzip\r\n")),
        ("/v1/models/gem.stl?seed=5", fresh.to_string()),
    ] {
        let (direct, routed) = both(&srv, &base, target, &extra).await;
        assert_eq!(direct.head[0], "HTTP/1.1 200 OK", "{direct:?}");
        assert_eq!(line(&direct, "x-rulemesh-cache"), "miss");
        assert_eq!(direct, routed, "{target}");
    }
    let gz = raw(&srv, &get("/v1/models/gem.gltf?seed=5&detail=8", &format!("{fresh}accept-encoding: gzip\r\n"))).await;
    assert_eq!(line(&gz, "content-encoding"), "gzip", "the text model was compressed");
    assert!(line(&gz, "etag").ends_with("-gzip\""), "{gz:?}");
    // Cache hits (each model rendered first), a 304 for a tag the client
    // holds, and a phone's glTF (its Vary and its flat default). The fast
    // path keeps nothing for a target until that target is hit, so the
    // direct route answers each first hit.
    let warm = |target: &'static str, extra: &'static str| {
        let srv = &srv;
        async move { raw(srv, &get(target, &format!("{fresh}{extra}"))).await }
    };
    let rendered = warm("/v1/models/gem.glb?seed=6", "").await;
    let (direct, routed) = both(&srv, &base, "/v1/models/gem.glb?seed=6", "").await;
    assert_eq!(line(&direct, "x-rulemesh-cache"), "hit");
    assert_eq!((&direct, &direct.body), (&routed, &rendered.body));
    let rendered = warm("/v1/models/icon-heart.glb?seed=10", "").await;
    let etag = line(&rendered, "etag").to_string();
    let (direct, routed) = both(&srv, &base, "/v1/models/icon-heart.glb?seed=10", &format!("if-none-match: \"x\", {etag}\r\n")).await;
    assert_eq!(direct.head[0], "HTTP/1.1 304 Not Modified", "{direct:?}");
    assert_eq!(direct, routed);
    let phone = "user-agent: Mozilla/5.0 (iPhone; CPU iPhone OS 17_0 like Mac OS X)\r\n";
    warm("/v1/models/gem.gltf?seed=8", phone).await;
    let (direct, routed) = both(&srv, &base, "/v1/models/gem.gltf?seed=8", phone).await;
    assert_eq!(line(&direct, "x-rulemesh-cache"), "hit");
    assert_eq!(direct, routed);
    // Errors: an unknown grammar, an unknown extension, a malformed option
    // (JSON bodies, compressed for a client that takes gzip when long enough).
    for (target, status) in [
        ("/v1/models/nosuch.glb", "HTTP/1.1 404 Not Found"),
        ("/v1/models/gem.xyz", "HTTP/1.1 404 Not Found"),
        ("/v1/models/gem.glb?seed=x", "HTTP/1.1 400 Bad Request"),
        ("/v1/models/gem.glb?max_primitives=5", "HTTP/1.1 400 Bad Request"),
    ] {
        for extra in ["", "accept-encoding: gzip\r\n"] {
            let (direct, routed) = both(&srv, &base, target, extra).await;
            assert_eq!(direct.head[0], status, "{target}: {direct:?}");
            assert_eq!(direct, routed, "{target} {extra}");
        }
    }
    // Counted like the router's answers, under the router's route name.
    let text = client().get(format!("{base}/metrics")).send().await.expect("metrics").text().await.expect("text");
    assert!(text.contains("rulemesh_requests_total{protocol=\"http\",route=\"/v1/models/{file}\",status=\"200\"}"), "{text}");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_router_keeps_what_the_direct_route_must_not_answer() {
    use rulemesh::service::access::{ApiKeySpec, ApiKeys};
    let keys = ApiKeys(vec![ApiKeySpec::new("open", "k-open")]);
    let (srv, base) = start(ServeConfig { api_keys: keys, ..config() }).await;
    // An admitted key: direct. No key or a wrong one: the router refuses and counts it.
    raw(&srv, &get("/v1/models/gem.glb?seed=9", "x-api-key: k-open\r\ncache-control: no-cache\r\n")).await;
    let (direct, routed) = both(&srv, &base, "/v1/models/gem.glb?seed=9", "x-api-key: k-open\r\n").await;
    assert_eq!(direct.head, routed.head);
    assert!(direct.body == routed.body);
    let before = direct_answers(&base).await;
    for extra in ["", "x-api-key: k-wrong\r\n"] {
        assert_eq!(raw(&srv, &get("/v1/models/gem.glb?seed=9", extra)).await.head[0], "HTTP/1.1 401 Unauthorized");
    }
    // A body, another method, a deeper path or an empty file: the router's.
    let with_body = "GET /v1/models/gem.glb HTTP/1.1\r\nhost: localhost\r\nx-api-key: k-open\r\ncontent-length: 2\r\n\r\n{}";
    raw(&srv, with_body).await;
    raw(&srv, "HEAD /v1/models/gem.glb HTTP/1.1\r\nhost: localhost\r\nx-api-key: k-open\r\n\r\n").await;
    assert_eq!(raw(&srv, &get("/v1/models/a/gem.glb", "x-api-key: k-open\r\n")).await.head[0], "HTTP/1.1 404 Not Found");
    raw(&srv, &get("/v1/models/", "x-api-key: k-open\r\n")).await;
    assert_eq!(direct_answers(&base).await, before);
    let text = client().get(format!("{base}/metrics")).send().await.expect("metrics").text().await.expect("text");
    assert!(text.contains("rulemesh_access_rejections_total{reason=\"unauthorized\"} 2"), "{text}");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
    // With a CORS policy every request is the router's.
    let (srv, base) = start(ServeConfig { cors_origins: vec!["https://app.example".into()], ..config() }).await;
    raw(&srv, &get("/v1/models/gem.glb?seed=9", "origin: https://app.example\r\n")).await;
    assert_eq!(direct_answers(&base).await, 0);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
