//! Verified cache tiers: a damaged or planted entry in a real Redis or on
//! disk is a miss — re-rendered, never served — and counted in `/metrics`.

use super::*;
use crate::scaleout::{free_port, require_redis_server, Redis};
use serde_json::json;

/// Renders a grammar whose geometry (not only its source) differs by `tag`.
async fn render(c: &reqwest::Client, base: &str, tag: &str) -> (String, Vec<u8>) {
    let n = 2 + tag.len();
    let source = format!("// {tag}\nstartshape A\nrule A {{ {n} * {{ x 1.5 }} BOX {{ }} }}\n");
    let r = c.post(format!("{base}/v1/render")).json(&json!({"source": source, "format": "stl"})).send().await.expect("post");
    assert_eq!(r.status(), 200);
    let cache = header(&r, "x-rulemesh-cache").to_string();
    (cache, r.bytes().await.expect("body").to_vec())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn corrupted_or_planted_redis_entries_are_never_served() {
    require_redis_server();
    let redis = Redis::start(free_port());
    let (srv, base) = start(ServeConfig { cache_redis: Some(redis.url()), ..config() }).await;
    let c = client();
    let (first, a) = render(&c, &base, "redis-a").await;
    let (_, b) = render(&c, &base, "redis-bb").await;
    assert_eq!(first, "miss");
    assert!(a != b, "two different models");
    let mut conn = ::redis::Client::open(redis.url()).expect("url").get_multiplexed_async_connection().await.expect("connects");
    let mut keys: Vec<String> = ::redis::cmd("KEYS").arg("rulemesh:m:*").query_async(&mut conn).await.expect("KEYS");
    keys.sort();
    assert_eq!(keys.len(), 2, "{keys:?}");
    let values: Vec<Vec<u8>> = ::redis::cmd("MGET").arg(&keys).query_async(&mut conn).await.expect("MGET");
    // Which key holds model A: the value that ends (before its 32-byte hash) with A's bytes.
    let ia = values.iter().position(|v| v[..v.len() - 32].ends_with(&a)).expect("A is stored");
    let (ka, kb) = (keys[ia].clone(), keys[1 - ia].clone());

    // One byte of A's model flipped in Redis.
    let mut damaged = values[ia].clone();
    let at = damaged.len() - 32 - a.len() / 2;
    damaged[at] ^= 0x01;
    let _: () = ::redis::cmd("SET").arg(&ka).arg(&damaged).query_async(&mut conn).await.expect("SET");
    srv.state.engine.cache().clear();
    let (cache, again) = render(&c, &base, "redis-a").await;
    assert_eq!((cache.as_str(), again == a), ("miss", true), "re-rendered, the right bytes");
    // The re-render replaced the damaged value.
    let stored: Vec<u8> = ::redis::cmd("GET").arg(&ka).query_async(&mut conn).await.expect("GET");
    assert!(stored == values[ia], "the damaged value was replaced");

    // A's valid entry planted under B's key.
    let _: () = ::redis::cmd("SET").arg(&kb).arg(&values[ia]).query_async(&mut conn).await.expect("SET");
    srv.state.engine.cache().clear();
    let (cache, got) = render(&c, &base, "redis-bb").await;
    assert_eq!((cache.as_str(), got == b), ("miss", true), "B's own model, not A's");

    // An intact entry is still a hit.
    srv.state.engine.cache().clear();
    let (cache, again) = render(&c, &base, "redis-a").await;
    assert!(cache == "hit" && again == a, "an intact entry is served: {cache}");
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_cache_corrupt_total"), 2.0, "{m}");
    stop(srv).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn corrupted_disk_entries_are_never_served() {
    let dir = crate::common::tempdir();
    let (srv, base) = start(ServeConfig { cache_dir: Some(dir.path().to_path_buf()), ..config() }).await;
    let c = client();
    let (_, a) = render(&c, &base, "disk-a").await;
    let files: Vec<_> = std::fs::read_dir(dir.path()).expect("dir").flatten().map(|e| e.path()).collect();
    assert_eq!(files.len(), 1, "{files:?}");
    let good = std::fs::read(&files[0]).expect("read");
    for at in [good.len() - 32 - a.len() / 2, good.len() - 1, 14] {
        let mut damaged = good.clone();
        damaged[at] ^= 0x04;
        std::fs::write(&files[0], &damaged).expect("write");
        srv.state.engine.cache().clear();
        let (cache, got) = render(&c, &base, "disk-a").await;
        assert_eq!((cache.as_str(), got == a), ("miss", true), "byte {at} damaged: re-rendered, the right bytes");
        assert!(std::fs::read(&files[0]).expect("rewritten") == good, "the damaged file was replaced");
    }
    srv.state.engine.cache().clear();
    let (cache, again) = render(&c, &base, "disk-a").await;
    assert!(cache == "hit" && again == a, "an intact file is served: {cache}");
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_cache_corrupt_total"), 3.0, "{m}");
    stop(srv).await;
}
