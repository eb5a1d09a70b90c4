//! The playground (`/playground`, issue 20): its embedded files are served
//! with their media types (open even when API keys are configured), and a
//! developer's session in headless Chromium works end to end
//! (`scripts/playground-check/check.mjs`, Playwright): a library grammar
//! loads, a parameter from the schema-driven form changes the triangle
//! count, the PNG preview shows, a parse error is marked at its line, and
//! nothing is fetched from anywhere but the server.

use super::*;
use rulemesh::service::access::{ApiKeySpec, ApiKeys};
use std::process::Command;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_playground_files_are_embedded_and_served_without_a_key() {
    let keyed = ServeConfig { api_keys: ApiKeys(vec![ApiKeySpec::new("app", "k-app")]), ..config() };
    let (srv, base) = start(keyed).await;
    let c = reqwest::Client::builder().redirect(reqwest::redirect::Policy::none()).build().expect("client");
    let r = c.get(format!("{base}/playground")).send().await.expect("get");
    assert_eq!(r.status(), 308);
    assert_eq!(header(&r, "location"), "/playground/");
    for (path, media_type, contains) in [
        ("/playground/", "text/html; charset=utf-8", "<title>rulemesh playground</title>"),
        ("/playground/app.js", "text/javascript; charset=utf-8", "POST /v1/schema"),
        ("/playground/style.css", "text/css; charset=utf-8", "#gutter"),
        ("/playground/three/build/three.module.js", "text/javascript; charset=utf-8", "three.core.js"),
        ("/playground/three/examples/jsm/loaders/GLTFLoader.js", "text/javascript; charset=utf-8", "class GLTFLoader"),
    ] {
        let r = c.get(format!("{base}{path}")).send().await.expect("get");
        assert_eq!(r.status(), 200, "{path}");
        assert_eq!(header(&r, "content-type"), media_type, "{path}");
        assert!(r.text().await.expect("text").contains(contains), "{path}");
    }
    let r = c.get(format!("{base}/playground/three/../../Cargo.toml")).send().await.expect("get");
    assert_eq!(r.status(), 404);
    // The API behind it still wants the key.
    assert_eq!(c.get(format!("{base}/v1/grammars")).send().await.expect("get").status(), 401);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_developer_session_in_chromium_loads_edits_previews_and_marks_errors() {
    let (srv, base) = start(ServeConfig { body_limit: 1024 * 1024, ..config() }).await;
    let script = common::repo().join("scripts/playground-check/check.mjs");
    let out = tokio::task::spawn_blocking(move || Command::new("node").arg(script).arg(&base).output()).await.expect("join").expect("node runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "playground-check failed ({:?}): {stderr}", out.status.code());
    let seen: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("playground-check output: {e}: {}", String::from_utf8_lossy(&out.stdout)));
    let (before, after) = (seen["triangles_before"].as_u64().expect("count"), seen["triangles_after"].as_u64().expect("count"));
    assert!(before > 0 && after > before, "{seen}");
    assert_eq!(seen["preview_width"], 256, "{seen}");
    assert_eq!(seen["marked_line"], 3, "{seen}");
    assert_eq!(seen["foreign_requests"], 0, "{seen}");
    assert_eq!(seen["sizes"].as_object().map(|s| s.len()), Some(6), "{seen}");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
