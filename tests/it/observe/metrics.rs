//! `/metrics` after a mix of requests: the per-stage histograms count each
//! render once per stage that ran, by language and format; the cache figures
//! are per tier (memory, disk, and a real Redis shared by two workers).

use super::{client, config, metrics, mdg, mdg_printable, render, sample, start, stop, EISEN};
use crate::common;
use crate::scaleout::{free_port, require_redis_server, Redis};
use rulemesh::service::grpc::pb;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use serde_json::json;

/// `name{worker="w",labels}`.
fn series(name: &str, worker: &str, labels: &str) -> String {
    if labels.is_empty() {
        format!("{name}{{worker=\"{worker}\"}}")
    } else {
        format!("{name}{{worker=\"{worker}\",{labels}}}")
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_mix_of_requests_shows_per_stage_and_per_tier_figures() {
    require_redis_server();
    let redis = Redis::start(free_port());
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a_config = config("a");
    a_config.cache_dir = Some(dir.path().to_path_buf());
    a_config.cache_redis = Some(redis.url());
    let (a, base_a) = start(a_config).await;
    let lsystem = std::fs::read_to_string(common::repo().join("grammars/sierpinski-tetrahedron.ls")).expect("grammar");

    // Four distinct renders on worker a, one of them asked for twice.
    let glb = json!({"source": mdg("glb"), "format": "glb"});
    let mut glb_bytes = 0;
    for want in ["miss", "hit"] {
        let r = render(&base_a, &glb).await;
        assert_eq!((r.status().as_u16(), super::header(&r, "x-rulemesh-cache")), (200, want));
        glb_bytes += r.bytes().await.expect("body").len();
    }
    for body in [
        json!({"source": lsystem, "format": "scene"}),
        json!({"source": EISEN, "language": "eisenscript", "format": "stl"}),
        json!({"source": mdg_printable("print"), "format": "stl", "print": true, "size_mm": 30}),
    ] {
        let r = render(&base_a, &body).await;
        assert_eq!(r.status(), 200, "{body}");
    }
    // A rejection by a limit, and one render over gRPC.
    let r = render(&base_a, &json!({"source": mdg("big"), "limits": {"max_primitives": 3}})).await;
    assert_eq!(r.status(), 422);
    let mut grpc = RulemeshClient::connect(format!("http://{}", a.grpc_addr)).await.expect("gRPC connects");
    grpc.render(pb::RenderRequest { source: mdg("grpc"), format: "gltf".into(), ..Default::default() }).await.expect("render");
    // Out of memory: read back from disk.
    a.state.engine.cache().clear();
    let r = render(&base_a, &glb).await;
    assert_eq!(super::header(&r, "x-rulemesh-cache"), "hit");

    let m = metrics(&base_a).await;
    let count = |labels: &str| sample(&m, &series("rulemesh_stage_duration_seconds_count", "a", labels));
    for stage in ["parse", "eval", "mesh", "export"] {
        assert_eq!(count(&format!("stage=\"{stage}\",language=\"mdg\",format=\"glb\"")), Some(1.0), "{stage} glb\n{m}");
        assert_eq!(count(&format!("stage=\"{stage}\",language=\"eisenscript\",format=\"stl\"")), Some(1.0), "{stage} eisen\n{m}");
        assert_eq!(count(&format!("stage=\"{stage}\",language=\"mdg\",format=\"gltf\"")), Some(1.0), "{stage} grpc\n{m}");
    }
    for stage in ["parse", "eval", "mesh", "print", "export"] {
        assert_eq!(count(&format!("stage=\"{stage}\",language=\"mdg\",format=\"stl\"")), Some(1.0), "{stage} print\n{m}");
    }
    // A scene is written straight from the hierarchy: no meshing stage.
    for stage in ["parse", "eval", "export"] {
        assert_eq!(count(&format!("stage=\"{stage}\",language=\"lsystem\",format=\"scene\"")), Some(1.0), "{stage} scene\n{m}");
    }
    assert_eq!(count("stage=\"mesh\",language=\"lsystem\",format=\"scene\""), None, "{m}");
    assert_eq!(count("stage=\"print\",language=\"mdg\",format=\"glb\""), None, "{m}");
    // Six renders ran (the rejected one too), each after its wait for a slot.
    assert_eq!(sample(&m, &series("rulemesh_renders_total", "a", "")), Some(6.0), "{m}");
    assert_eq!(sample(&m, &series("rulemesh_queue_wait_seconds_count", "a", "")), Some(6.0), "{m}");
    assert_eq!(sample(&m, &series("rulemesh_budget_rejections_total", "a", "limit=\"primitives\"")), Some(1.0), "{m}");

    // Requests by route and status, with latency, and bytes out.
    let req = |labels: &str| sample(&m, &series("rulemesh_request_duration_seconds_count", "a", labels));
    assert_eq!(req("protocol=\"http\",route=\"/v1/render\",status=\"200\""), Some(6.0), "{m}");
    assert_eq!(req("protocol=\"http\",route=\"/v1/render\",status=\"422\""), Some(1.0), "{m}");
    assert_eq!(req("protocol=\"grpc\",route=\"Render\",status=\"0\""), Some(1.0), "{m}");
    assert_eq!(sample(&m, &series("rulemesh_response_bytes_total", "a", "protocol=\"http\",format=\"glb\"")), Some((glb_bytes * 3 / 2) as f64), "{m}");

    // Per tier: 8 lookups in memory (1 hit), 7 on disk (1 hit), 6 in Redis (none).
    let tier = |t: &str, result: &str| sample(&m, &series("rulemesh_cache_lookups_total", "a", &format!("tier=\"{t}\",result=\"{result}\"")));
    assert_eq!((tier("memory", "hit"), tier("memory", "miss")), (Some(1.0), Some(7.0)), "{m}");
    assert_eq!((tier("disk", "hit"), tier("disk", "miss")), (Some(1.0), Some(6.0)), "{m}");
    assert_eq!((tier("redis", "hit"), tier("redis", "miss")), (None, Some(6.0)), "{m}");
    for t in ["memory", "disk", "redis"] {
        let n = sample(&m, &series("rulemesh_cache_lookup_duration_seconds_count", "a", &format!("tier=\"{t}\"")));
        assert_eq!(n, Some(tier(t, "hit").unwrap_or(0.0) + tier(t, "miss").unwrap_or(0.0)), "{t}\n{m}");
    }
    assert_eq!(sample(&m, &series("rulemesh_redis_up", "a", "")), Some(1.0), "{m}");
    assert_eq!(sample(&m, &series("rulemesh_redis_errors_total", "a", "")), Some(0.0), "{m}");
    assert_eq!(sample(&m, &series("rulemesh_redis_timeouts_total", "a", "")), Some(0.0), "{m}");
    assert!(sample(&m, &series("rulemesh_cache_disk_bytes", "a", "")).is_some_and(|b| b > 0.0), "{m}");

    // A second worker sharing Redis finds worker a's model there.
    let mut b_config = config("b");
    b_config.cache_redis = Some(redis.url());
    let (b, base_b) = start(b_config).await;
    let r = render(&base_b, &glb).await;
    assert_eq!(super::header(&r, "x-rulemesh-cache"), "hit");
    assert!(super::header(&r, "server-timing").ends_with("tier;desc=redis"), "{:?}", r.headers());
    let m = metrics(&base_b).await;
    let tier = |t: &str, result: &str| sample(&m, &series("rulemesh_cache_lookups_total", "b", &format!("tier=\"{t}\",result=\"{result}\"")));
    assert_eq!((tier("memory", "miss"), tier("redis", "hit")), (Some(1.0), Some(1.0)), "{m}");
    assert_eq!(sample(&m, &series("rulemesh_renders_total", "b", "")), Some(0.0), "{m}");

    // OpenMetrics when the scraper asks for it, as Prometheus does.
    let om = client().get(format!("{base_b}/metrics")).header("accept", "application/openmetrics-text;version=1.0.0,text/plain;q=0.5").send().await.expect("get");
    assert!(super::header(&om, "content-type").starts_with("application/openmetrics-text"));
    let om = om.text().await.expect("text");
    assert!(om.ends_with("# EOF\n") && om.contains("# TYPE rulemesh_cache_lookups counter"), "{om}");
    stop(a).await;
    stop(b).await;
}
