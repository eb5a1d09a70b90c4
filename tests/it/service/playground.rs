//! The playground (`/playground`, issue 20): its embedded files are served
//! with their media types (open even when API keys are configured), and a
//! developer's session in headless Chromium works end to end
//! (`scripts/playground-check/check.mjs`, Playwright): the page opens on a
//! library model and names it in its URL, every library grammar is in the
//! menu under its language, a library grammar loads, a parameter from the
//! schema-driven form changes the triangle count, the PNG preview shows, a
//! parse error is marked at its line, the URL follows each change, links
//! restore their state and render what `GET /v1/models/NAME.EXT` serves
//! (checked here again, from outside the browser), bad values in a link are
//! ignored with a note, and nothing is fetched from anywhere but the server.

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
    let page_base = base.clone();
    let out = tokio::task::spawn_blocking(move || Command::new("node").arg(script).arg(&page_base).output()).await.expect("join").expect("node runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "playground-check failed ({:?}): {stderr}", out.status.code());
    let seen: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("playground-check output: {e}: {}", String::from_utf8_lossy(&out.stdout)));
    let (before, after) = (seen["triangles_before"].as_u64().expect("count"), seen["triangles_after"].as_u64().expect("count"));
    assert!(before > 0 && after > before, "{seen}");
    assert_eq!(seen["preview_width"], 256, "{seen}");
    assert_eq!(seen["marked_line"], 3, "{seen}");
    assert_eq!(seen["foreign_requests"], 0, "{seen}");
    assert_eq!(seen["sizes"].as_object().map(|s| s.len()), Some(rulemesh::export::Format::ALL.len()), "one size per registered format: {seen}");

    // Opened with no state: the default library model, named in the URL.
    let opened = &seen["default"];
    assert_eq!(opened["grammar"], "gem", "{opened}");
    assert_eq!(opened["hash"], "#grammar=gem&seed=1&format=glb", "{opened}");
    assert!(opened["triangles"].as_u64().is_some_and(|t| t > 0), "{opened}");
    // Every library grammar is in the menu, the L-systems too.
    let listed: Value = client().get(format!("{base}/v1/grammars")).send().await.expect("get").json().await.expect("json");
    assert_eq!(seen["grammars"].as_u64(), listed["grammars"].as_array().map(|g| g.len() as u64), "{seen}");
    let languages: Vec<&str> = seen["languages"].as_array().expect("languages").iter().filter_map(Value::as_str).collect();
    assert!(languages.contains(&"mdg") && languages.contains(&"lsystem"), "{seen}");
    assert_eq!(seen["hashes"]["parameter"], "#grammar=icon-coin&seed=1&format=glb&p.points=8", "{seen}");
    assert_eq!(seen["hashes"]["edited"], "#grammar=icon-coin&edited=1&seed=42&format=png&p.points=8", "{seen}");

    // Each link rendered what GET /v1/models/NAME.EXT serves, asked here
    // without the browser (and without compression, so the ETag is the
    // content hash itself).
    let links = &seen["links"];
    let tag = |v: &Value| v.as_str().map(|t| t.trim_matches('"').split('-').next().unwrap_or("").to_string()).expect("an ETag");
    for (name, path, seed_path) in [
        ("lsystem", "/v1/models/stochastic-plant.glb?seed=7", "/v1/models/stochastic-plant.glb?seed=1"),
        ("parameter", "/v1/models/icosahedron-transformations.stl?seed=5&p.phase=1.5", "/v1/models/icosahedron-transformations.stl?seed=5"),
    ] {
        let link = &links[name];
        let r = client().get(format!("{base}{path}")).send().await.expect("get");
        assert_eq!(r.status(), 200, "{path}");
        assert_eq!(tag(&link["etag"]), header(&r, "etag").trim_matches('"'), "{name}: {link}");
        assert_eq!(link["header_triangles"], header(&r, "x-rulemesh-triangles"), "{name}: {link}");
        // The seed (or the parameter) carried by the link matters: without it the model differs.
        let other = client().get(format!("{base}{seed_path}")).send().await.expect("get");
        assert_ne!(header(&other, "etag"), header(&r, "etag"), "{name}: {seed_path} gave the same model as {path}");
    }
    assert_eq!(links["lsystem"]["language"], "lsystem", "{links}");
    assert_eq!(links["lsystem"]["render_languages"], json!(["lsystem"]), "{links}");
    assert_eq!((&links["parameter"]["seed"], &links["parameter"]["format"], &links["parameter"]["params"]["phase"]), (&json!("5"), &json!("stl"), &json!("1.5")), "{links}");
    // A bad seed (and format, and parameter) is ignored with a note; the model still renders.
    let bad = &links["bad"];
    assert!(bad["note"].as_str().is_some_and(|n| n.contains("seed \"banana\"")), "{bad}");
    assert_eq!((&bad["outcome"], &bad["seed"], &bad["hash"]), (&json!("model"), &json!("1"), &json!("#grammar=gem&seed=1&format=glb")), "{bad}");
    assert!(bad["triangles"].as_u64().is_some_and(|t| t > 0), "{bad}");
    assert_eq!(links["pasted"]["grammar"], "hogeweg", "{links}");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
