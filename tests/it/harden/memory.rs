//! The process-level memory guard (issue 38): a render starts only while
//! the process's resident memory plus the render's memory budget fits under
//! the memory ceiling; otherwise it is refused with a typed 503
//! `memory_pressure` (gRPC RESOURCE_EXHAUSTED) naming the ceiling, counted
//! in `/metrics`.

use super::*;
use rulemesh::service::grpc::pb;
use crate::serve_child::ServeChild;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use serde_json::json;

const MIB: u64 = 1024 * 1024;

/// The server runs as a process of its own, so the resident memory the
/// guard reads is the server's (a few tens of MiB when fresh), not this test
/// binary's, which other tests running beside it can grow by a gigabyte: a
/// 1 GiB ceiling has room for a 16 MiB budget and never for a 2 GiB one.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_render_whose_budget_does_not_fit_under_the_ceiling_is_refused_by_name() {
    let ceiling = 1024 * MIB;
    let srv = ServeChild::start(&["--log", "warn", "--memory-ceiling", &ceiling.to_string(), "--memory-wait-ms", "100"], &[]);
    let base = srv.base();
    let r = client().post(format!("{base}/v1/render")).json(&json!({"source": small("mem-big"), "limits": {"max_memory": 2048 * MIB}})).send().await.expect("request");
    assert_eq!((r.status().as_u16(), header(&r, "retry-after"), header(&r, "x-rulemesh-error")), (503, "1", "memory_pressure"));
    let e = error_of(r).await;
    assert_eq!((e["code"].as_str(), e["limit"].as_str(), e["configured"].as_u64()), (Some("memory_pressure"), Some("memory_ceiling"), Some(ceiling)));
    assert!(e["reached"].as_u64().is_some_and(|r| r > ceiling), "{e}");
    assert!(e["message"].as_str().is_some_and(|m| m.contains("memory ceiling") && m.contains("2048 MiB memory budget")), "{e}");
    let ok = client().post(format!("{base}/v1/render")).json(&json!({"source": small("mem-small"), "limits": {"max_memory": 16 * MIB}})).send().await.expect("request");
    assert_eq!(ok.status().as_u16(), 200);

    let mut g = RulemeshClient::connect(format!("http://{}", srv.grpc)).await.expect("gRPC connects");
    let big = pb::RenderRequest { source: small("mem-grpc"), limits: Some(pb::Limits { max_memory: Some(2048 * MIB), ..Default::default() }), ..Default::default() };
    let e = g.render(big).await.expect_err("refused");
    let md = |k: &str| e.metadata().get(k).and_then(|v| v.to_str().ok()).map(str::to_string);
    assert_eq!((e.code(), md("x-rulemesh-error"), md("x-rulemesh-limit"), md("retry-after")), (tonic::Code::ResourceExhausted, Some("memory_pressure".into()), Some("memory_ceiling".into()), Some("1".into())));

    let text = metrics(&base).await;
    srv.terminate();
    assert_eq!(sample(&text, "rulemesh_memory_refusals_total"), 2.0, "{text}");
    assert_eq!(sample(&text, "rulemesh_memory_ceiling_bytes"), ceiling as f64, "{text}");
    let resident = sample(&text, "rulemesh_process_resident_bytes");
    assert!(resident > MIB as f64 && resident < ceiling as f64, "the server's own resident size: {text}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_ceiling_of_zero_turns_the_guard_off() {
    let (srv, base) = start(ServeConfig { memory_ceiling: Some(0), ..config() }).await;
    let r = client().post(format!("{base}/v1/render")).json(&json!({"source": small("mem-off"), "limits": {"max_memory": 2048 * MIB}})).send().await.expect("request");
    assert_eq!(r.status().as_u16(), 200);
    let text = metrics(&base).await;
    stop(srv).await;
    assert_eq!(sample(&text, "rulemesh_memory_ceiling_bytes"), 0.0, "{text}");
    assert_eq!(sample(&text, "rulemesh_memory_refusals_total"), 0.0, "{text}");
}
