//! Running the service: configuration precedence, per-request log lines,
//! the disk cache across restarts, and metrics that add up.

use super::*;

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
async fn served_from_a_config_file_and_logs_one_short_line_per_request() {
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
    let rx = common::stderr_lines(&mut child);
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
    // The access line is short (issue 33): the request, not its span's
    // cache key and language, which are on the DEBUG line.
    for part in ["method=POST", "cache=miss", "status=200", "id=", "ms=", "bytes="] {
        assert!(line.contains(part), "{part} missing from {line}");
    }
    assert!(!line.contains("key="), "{line}");
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
