//! The cached-GET fast path (`service::fast`, issue 33): its answers are
//! the router's, byte for byte on the wire (modulo the request id, the
//! lookup's duration and the date), 304s included; anything that changes
//! the response misses it; it is counted; nothing malformed gets into it;
//! and a cleared cache ends its answers.

use super::*;
use super::wire::{get, line, raw};
use tokio::io::{AsyncReadExt, AsyncWriteExt};

async fn fast_hits(base: &str) -> i64 {
    let text = client().get(format!("{base}/metrics")).send().await.expect("metrics").text().await.expect("text");
    metric(&text, "rulemesh_fast_path_hits_total")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fast_answers_are_the_routers_byte_for_byte_with_304s() {
    let (srv, base) = start(config()).await;
    for target in ["/v1/models/gem.glb?seed=41", "/v1/models/gem.gltf?seed=41&detail=8"] {
        let req = get(target, "");
        let rendered = raw(&srv, &req).await;
        assert_eq!(line(&rendered, "x-rulemesh-cache"), "miss", "{rendered:?}");
        // The router's hit keeps its answer; the next is the fast path's.
        let before = fast_hits(&base).await;
        let routed = raw(&srv, &req).await;
        assert_eq!(fast_hits(&base).await, before, "the first hit is the router's");
        let fast = raw(&srv, &req).await;
        assert_eq!(fast_hits(&base).await, before + 1, "the second hit is the fast path's");
        assert_eq!(routed.head[0], "HTTP/1.1 200 OK");
        assert_eq!(line(&routed, "x-rulemesh-cache"), "hit");
        assert_eq!(line(&routed, "server-timing"), "cache;desc=hit, tier;desc=memory");
        assert_eq!(fast, routed, "{target}");
        assert_eq!(fast.body, rendered.body);
        // A 304 through both: the router's first, then the fast path's.
        let etag = line(&fast, "etag").to_string();
        let conditional = get(target, &format!("if-none-match: \"other\", {etag}\r\n"));
        let routed_304 = raw(&srv, &conditional).await;
        let fast_304 = raw(&srv, &conditional).await;
        assert_eq!(routed_304.head[0], "HTTP/1.1 304 Not Modified");
        assert_eq!(fast_304, routed_304, "{target}");
        assert!(fast_304.body.is_empty());
        assert_eq!(fast_hits(&base).await, before + 2);
        // A tag that names another model gets the 200, from the fast path.
        assert_eq!(raw(&srv, &get(target, "if-none-match: \"other\"\r\n")).await, routed);
        assert_eq!(fast_hits(&base).await, before + 3);
    }
    // Counted like the router's answers: every request, every hit, every memory lookup.
    let text = client().get(format!("{base}/metrics")).send().await.expect("metrics").text().await.expect("text");
    assert_eq!(metric(&text, "rulemesh_fast_path_hits_total"), 6);
    assert_eq!(metric(&text, "rulemesh_cache_hits_total"), 10);
    assert!(text.contains("rulemesh_requests_total{protocol=\"http\",route=\"/v1/models/{file}\",status=\"200\"} 8"), "{text}");
    assert!(text.contains("rulemesh_requests_total{protocol=\"http\",route=\"/v1/models/{file}\",status=\"304\"} 4"), "{text}");
    assert!(text.contains("rulemesh_cache_lookups_total{tier=\"memory\",result=\"hit\"} 10"), "{text}");
    assert_eq!(srv.state.fast.len(), 2);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_changed_query_or_header_misses_the_fast_path() {
    let (srv, base) = start(config()).await;
    let req = get("/v1/models/gem.glb?seed=7", "");
    for _ in 0..3 {
        raw(&srv, &req).await;
    }
    let warm = fast_hits(&base).await;
    assert_eq!(warm, 1);
    // Another seed, another query spelling, a phone, no-cache: the router answers each.
    let cases = [
        (get("/v1/models/gem.glb?seed=8", ""), "miss"),
        (get("/v1/models/gem.glb?seed=7&detail=9", ""), "miss"),
        (get("/v1/models/gem.glb?seed=7", "user-agent: okhttp/4.12.0\r\n"), "miss"),
        (get("/v1/models/gem.glb?seed=7", "cache-control: no-cache\r\n"), "miss"),
        (get("/v1/models/gem.glb?seed=7", "pragma: no-cache\r\n"), "miss"),
        // The same model by another spelling of the query: a hit, but the router's.
        (get("/v1/models/gem.glb?seed=7&", ""), "hit"),
        (get("/v1/models/gem.glb?seed=7", "accept-encoding: gzip\r\n"), "hit"),
    ];
    for (req, cache) in &cases {
        let w = raw(&srv, req).await;
        assert_eq!(w.head[0], "HTTP/1.1 200 OK", "{req}");
        assert_eq!(line(&w, "x-rulemesh-cache"), *cache, "{req}");
        assert_eq!(fast_hits(&base).await, warm, "{req}");
    }
    // The phone's flat model is another model.
    let phone = raw(&srv, &cases[2].0).await;
    assert_ne!(phone.body, raw(&srv, &req).await.body);
    // A HEAD is the router's too.
    let head = raw(&srv, "HEAD /v1/models/gem.glb?seed=7 HTTP/1.1\r\nhost: localhost\r\n\r\n").await;
    assert_eq!(head.head[0], "HTTP/1.1 200 OK");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn malformed_requests_never_enter_and_a_cleared_cache_ends_fast_answers() {
    let (srv, base) = start(config()).await;
    for bad in ["/v1/models/gem.glb?seed=x", "/v1/models/gem.glb?seed=%zz", "/v1/models/nope.glb", "/v1/models/gem.obj", "/v1/models/gem.glb?detail=99999"] {
        for _ in 0..3 {
            let w = raw(&srv, &get(bad, "")).await;
            assert!(w.head[0].starts_with("HTTP/1.1 4"), "{bad}: {w:?}");
        }
    }
    // A GET with a body, and a head that is not HTTP, on the model's own route.
    let with_body = "GET /v1/models/gem.glb?seed=9 HTTP/1.1\r\nhost: localhost\r\ncontent-length: 5\r\n\r\nhello";
    for _ in 0..3 {
        assert_eq!(raw(&srv, with_body).await.head[0], "HTTP/1.1 200 OK");
    }
    let mut s = tokio::net::TcpStream::connect(srv.http_addr).await.expect("connect");
    s.write_all(b"GET /v1/models/gem.glb?seed=9 HTTP/9.9\r\n\x01\x02\r\n\r\n").await.expect("send");
    let mut answer = Vec::new();
    let _ = s.read_to_end(&mut answer).await;
    assert!(answer.is_empty() || answer.starts_with(b"HTTP/1.1 400"), "{}", String::from_utf8_lossy(&answer));
    // A key past the bound (here a long Origin) is answered, never kept.
    let long = get("/v1/models/gem.glb?seed=9", &format!("origin: https://{}.example\r\n", "o".repeat(3000)));
    for _ in 0..3 {
        assert_eq!(raw(&srv, &long).await.head[0], "HTTP/1.1 200 OK");
    }
    assert_eq!(srv.state.fast.len(), 0, "nothing kept from malformed requests, bodies or long keys");
    assert_eq!(fast_hits(&base).await, 0);
    // The well-formed request is kept, answered fast, and still right.
    let req = get("/v1/models/gem.glb?seed=9", "");
    let routed = raw(&srv, &req).await;
    assert_eq!(fast_hits(&base).await, 0);
    assert_eq!(raw(&srv, &req).await, routed);
    assert_eq!(fast_hits(&base).await, 1);
    // A cleared cache: the router renders again, then keeps the new model.
    srv.state.engine.cache().clear();
    let again = raw(&srv, &req).await;
    assert_eq!(line(&again, "x-rulemesh-cache"), "miss");
    assert_eq!(again.body, routed.body);
    assert_eq!(fast_hits(&base).await, 1);
    raw(&srv, &req).await;
    assert_eq!(raw(&srv, &req).await, routed);
    assert_eq!(fast_hits(&base).await, 2);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn cors_answers_are_kept_per_origin() {
    let (srv, base) = start(ServeConfig { cors_origins: vec!["https://app.example".into()], ..config() }).await;
    // Each origin its own seed, so that its first request renders and its second is the router's hit.
    for (seed, origin) in [(12, "https://app.example"), (13, "https://other.example")] {
        let req = get(&format!("/v1/models/gem.glb?seed={seed}"), &format!("origin: {origin}\r\n"));
        raw(&srv, &req).await;
        let before = fast_hits(&base).await;
        let routed = raw(&srv, &req).await;
        let fast = raw(&srv, &req).await;
        assert_eq!(fast_hits(&base).await, before + 1, "{origin}");
        assert_eq!(fast, routed, "{origin}");
        let allowed = line(&fast, "access-control-allow-origin");
        assert_eq!(allowed, if origin == "https://app.example" { origin } else { "" }, "{fast:?}");
    }
    assert_eq!(srv.state.fast.len(), 2);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn with_api_keys_each_key_has_its_entries_and_fast_answers_are_admitted() {
    use rulemesh::service::access::{ApiKeySpec, ApiKeys};
    // Four requests a burst, next to none a second: the fifth is over the rate.
    let limited = ApiKeySpec { rate_per_sec: Some(0.001), burst: Some(4), ..ApiKeySpec::new("limited", "k-limited") };
    let keys = ApiKeys(vec![limited, ApiKeySpec::new("open", "k-open")]);
    let (srv, base) = start(ServeConfig { api_keys: keys, ..config() }).await;
    let as_key = |key: &str| get("/v1/models/gem.glb?seed=21", &format!("x-api-key: {key}\r\n"));
    let rendered = raw(&srv, &as_key("k-limited")).await;
    assert_eq!(line(&rendered, "x-rulemesh-cache"), "miss");
    let routed = raw(&srv, &as_key("k-limited")).await;
    assert_eq!(fast_hits(&base).await, 0);
    assert_eq!(raw(&srv, &as_key("k-limited")).await, routed);
    assert_eq!(raw(&srv, &as_key("k-limited")).await, routed);
    assert_eq!(fast_hits(&base).await, 2);
    // The bucket is empty: the fast path steps aside and the router refuses.
    let refused = raw(&srv, &as_key("k-limited")).await;
    assert_eq!(refused.head[0], "HTTP/1.1 429 Too Many Requests", "{refused:?}");
    assert_eq!(fast_hits(&base).await, 2);
    // Another key, a wrong key and no key never share the first key's entry.
    let other = raw(&srv, &as_key("k-open")).await;
    assert_eq!((line(&other, "x-rulemesh-cache"), fast_hits(&base).await), ("hit", 2));
    assert_eq!(raw(&srv, &as_key("k-open")).await, other);
    assert_eq!(fast_hits(&base).await, 3);
    for bad in [as_key("k-wrong"), get("/v1/models/gem.glb?seed=21", "")] {
        assert_eq!(raw(&srv, &bad).await.head[0], "HTTP/1.1 401 Unauthorized");
        assert_eq!(raw(&srv, &bad).await.head[0], "HTTP/1.1 401 Unauthorized");
    }
    assert_eq!(fast_hits(&base).await, 3);
    let text = client().get(format!("{base}/metrics")).send().await.expect("metrics").text().await.expect("text");
    assert!(text.contains("rulemesh_access_rejections_total{reason=\"rate_limited\"} 1"), "{text}");
    assert!(text.contains("rulemesh_access_rejections_total{reason=\"unauthorized\"} 4"), "{text}");
    assert_eq!(srv.state.fast.len(), 2);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
