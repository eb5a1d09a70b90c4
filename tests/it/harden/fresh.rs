//! Caches are keyed by everything that changes output (issue 33): starting
//! from one request, each of source, seed, detail, limits, language and
//! files is changed alone, and each change is a fresh render (a cache
//! miss) that is then cached on its own (a hit when asked again), while
//! the first request's model stays cached. The engine version cannot
//! change inside one process; its part of the key is checked through the
//! key function the service uses, with another version named.

use super::*;
use serde_json::{json, Value};

/// Posts `body` to `/v1/render`; the response's cache result (`miss`, `hit`, …) and bytes.
async fn render(c: &reqwest::Client, base: &str, body: &Value) -> (String, Vec<u8>) {
    let r = c.post(format!("{base}/v1/render")).json(body).send().await.expect("post");
    assert_eq!(r.status(), 200, "{body}");
    let cache = header(&r, "x-rulemesh-cache").to_string();
    (cache, r.bytes().await.expect("body").to_vec())
}

/// `base` with `key` set to `value`.
fn with(base: &Value, key: &str, value: Value) -> Value {
    let mut v = base.clone();
    v[key] = value;
    v
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn each_input_that_changes_output_alone_gets_a_fresh_render() {
    let (srv, url) = start(config()).await;
    let c = client();
    // A grammar that MDG and Context Free both read (an empty rule): so the
    // language can change with nothing else. The last byte of the comment
    // is the source byte that changes.
    let source = "// fresh-a\nstartshape A\nrule A { }\n";
    let base = json!({"source": source, "language": "mdg", "format": "glb", "seed": 1});
    let (first, model) = render(&c, &url, &base).await;
    assert_eq!(first, "miss", "the first request renders");
    assert_eq!(render(&c, &url, &base).await, ("hit".to_string(), model.clone()), "the same request is served from the cache");
    let variants = [
        ("one source byte", with(&base, "source", json!(source.replace("fresh-a", "fresh-b")))),
        ("seed", with(&base, "seed", json!(2))),
        ("detail", with(&base, "detail", json!(rulemesh::geom::DEFAULT_DETAIL + 1))),
        ("limits", with(&base, "limits", json!({"max_primitives": 1000}))),
        ("language", with(&base, "language", json!("cfdg"))),
        ("files", with(&base, "files", json!({"extra.txt": "x"}))),
    ];
    for (what, body) in &variants {
        let (cache, bytes) = render(&c, &url, body).await;
        assert_eq!(cache, "miss", "changing the {what} alone renders afresh");
        assert_eq!(render(&c, &url, body).await, ("hit".to_string(), bytes), "the {what} variant is cached under its own key");
    }
    // The language changes the bytes too (each front end writes its own
    // provenance), so a shared key would have served the wrong model.
    let (_, cfdg) = render(&c, &url, &variants[4].1).await;
    assert_ne!(cfdg, model, "another language, another model");
    assert_eq!(render(&c, &url, &base).await, ("hit".to_string(), model), "the first model is still cached");
    stop(srv).await;

    // The engine version: the same request under another version has another key.
    let req = rulemesh::RenderRequest { seed: Some(1), ..Default::default() };
    let key = rulemesh::pipeline::key::cache_key(source.as_bytes(), &req);
    assert_eq!(key, rulemesh::pipeline::key::cache_key_of_engine(rulemesh::ENGINE_VERSION, source.as_bytes(), &req));
    assert_ne!(key, rulemesh::pipeline::key::cache_key_of_engine("0.0.0-other", source.as_bytes(), &req), "a new engine misses the old one's models");
}
