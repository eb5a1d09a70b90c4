//! OTLP traces: a real OTLP/gRPC collector (the OpenTelemetry protocol's
//! trace service, generated from its protobuf definitions by
//! `opentelemetry-proto`) runs in the test; `rulemesh serve
//! --otlp-endpoint` sends it one server span per request, under the
//! caller's W3C `traceparent` (HTTP header or gRPC metadata), with one child
//! span per pipeline stage. Without the flag nothing is sent.

use super::mdg;
use crate::serve_child::ServeChild;
use opentelemetry_proto::tonic::collector::trace::v1::trace_service_server::{TraceService, TraceServiceServer};
use opentelemetry_proto::tonic::collector::trace::v1::{ExportTraceServiceRequest, ExportTraceServiceResponse};
use opentelemetry_proto::tonic::common::v1::any_value::Value as AnyValue;
use opentelemetry_proto::tonic::trace::v1::span::SpanKind;
use opentelemetry_proto::tonic::trace::v1::Span;
use rulemesh::service::grpc::pb;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use serde_json::json;
use std::net::SocketAddr;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The collector: keeps every span it is sent.
#[derive(Clone, Default)]
struct Collector {
    spans: Arc<Mutex<Vec<Span>>>,
}

#[tonic::async_trait]
impl TraceService for Collector {
    async fn export(&self, request: tonic::Request<ExportTraceServiceRequest>) -> Result<tonic::Response<ExportTraceServiceResponse>, tonic::Status> {
        let mut spans = self.spans.lock().expect("lock");
        for rs in request.into_inner().resource_spans {
            for ss in rs.scope_spans {
                spans.extend(ss.spans);
            }
        }
        Ok(tonic::Response::new(ExportTraceServiceResponse { partial_success: None }))
    }
}

impl Collector {
    /// Serves OTLP/gRPC on a free loopback port; its address.
    async fn start(&self) -> SocketAddr {
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.expect("bind");
        let addr = listener.local_addr().expect("addr");
        let service = TraceServiceServer::new(self.clone());
        tokio::spawn(tonic::transport::Server::builder().add_service(service).serve_with_incoming(tonic::transport::server::TcpIncoming::from(listener)));
        addr
    }

    /// The spans of trace `trace_id` received so far.
    fn trace(&self, trace_id: &[u8]) -> Vec<Span> {
        self.spans.lock().expect("lock").iter().filter(|s| s.trace_id == trace_id).cloned().collect()
    }

    /// Waits (at most 15 s) until trace `trace_id` has `n` spans.
    async fn wait_for(&self, trace_id: &[u8], n: usize) -> Vec<Span> {
        let deadline = Instant::now() + Duration::from_secs(15);
        loop {
            let spans = self.trace(trace_id);
            if spans.len() >= n || Instant::now() > deadline {
                return spans;
            }
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    }
}

fn unhex(s: &str) -> Vec<u8> {
    (0..s.len()).step_by(2).map(|i| u8::from_str_radix(&s[i..i + 2], 16).expect("hex")).collect()
}

fn attribute(span: &Span, key: &str) -> Option<String> {
    span.attributes.iter().find(|a| a.key == key).and_then(|a| match a.value.as_ref()?.value.as_ref()? {
        AnyValue::StringValue(s) => Some(s.clone()),
        AnyValue::IntValue(i) => Some(i.to_string()),
        _ => None,
    })
}

/// A `rulemesh serve` logging warnings only, exporting a batch of spans every 100 ms.
fn serve(extra: &[&str], env: &[(&str, String)]) -> ServeChild {
    let mut args = vec!["--log", "warn"];
    args.extend_from_slice(extra);
    let mut env = env.to_vec();
    env.push(("OTEL_BSP_SCHEDULE_DELAY", "100".to_string()));
    ServeChild::start(&args, &env)
}

/// Checks a trace: one server span named `name` under `parent`, with the
/// language and cache key, and one child span per stage inside it.
fn check_trace(spans: &[Span], name: &str, parent: &[u8], stages: &[&str]) {
    let server: Vec<&Span> = spans.iter().filter(|s| s.kind == SpanKind::Server as i32).collect();
    assert_eq!(server.len(), 1, "one server span: {spans:#?}");
    let request = server[0];
    assert_eq!(request.name, name);
    assert_eq!(request.parent_span_id, parent, "the request span is the caller's child");
    assert_eq!(attribute(request, "language").as_deref(), Some("mdg"));
    assert!(attribute(request, "key").is_some_and(|k| k.len() == 64 && k.bytes().all(|b| b.is_ascii_hexdigit())), "{request:#?}");
    let mut children: Vec<&Span> = spans.iter().filter(|s| s.parent_span_id == request.span_id).collect();
    children.sort_by_key(|s| s.start_time_unix_nano);
    let names: Vec<&str> = children.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, stages, "one child span per stage, in order");
    for c in &children {
        assert!(c.start_time_unix_nano >= request.start_time_unix_nano && c.end_time_unix_nano <= request.end_time_unix_nano, "{c:#?} outside {request:#?}");
        assert!(c.end_time_unix_nano >= c.start_time_unix_nano);
        assert_eq!(attribute(c, "rulemesh.stage").as_deref(), Some(c.name.as_str()));
        assert_eq!(attribute(c, "rulemesh.language").as_deref(), Some("mdg"));
    }
    assert_eq!(spans.len(), 1 + stages.len(), "nothing else in the trace: {spans:#?}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_traced_request_has_a_span_per_stage_under_the_callers_traceparent() {
    let collector = Collector::default();
    let addr = collector.start().await;
    let child = serve(&["--otlp-endpoint", &format!("http://{addr}")], &[]);
    let (http, grpc) = (child.http, child.grpc);
    let stages = ["parse", "eval", "mesh", "export"];

    let (trace, parent) = ("0af7651916cd43dd8448eb211c80319c", "b7ad6b7169203331");
    let r = super::client()
        .post(format!("http://{http}/v1/render"))
        .header("traceparent", format!("00-{trace}-{parent}-01"))
        .json(&json!({"source": mdg("traced"), "format": "glb"}))
        .send()
        .await
        .expect("request");
    assert_eq!(r.status(), 200);

    let (grpc_trace, grpc_parent) = ("4bf92f3577b34da6a3ce929d0e0e4736", "00f067aa0ba902b7");
    let mut client = RulemeshClient::connect(format!("http://{grpc}")).await.expect("gRPC connects");
    let mut request = tonic::Request::new(pb::RenderRequest { source: mdg("traced-grpc"), format: "stl".into(), ..Default::default() });
    request.metadata_mut().insert("traceparent", format!("00-{grpc_trace}-{grpc_parent}-01").parse().expect("metadata"));
    client.render(request).await.expect("render");

    let http_spans = collector.wait_for(&unhex(trace), 5).await;
    let grpc_spans = collector.wait_for(&unhex(grpc_trace), 5).await;
    child.terminate();
    check_trace(&http_spans, "POST /v1/render", &unhex(parent), &stages);
    check_trace(&grpc_spans, "Render", &unhex(grpc_parent), &stages);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn without_an_endpoint_nothing_is_exported() {
    let collector = Collector::default();
    let addr = collector.start().await;
    // The standard variable alone does not turn exporting on: only --otlp-endpoint does.
    let child = serve(&[], &[("OTEL_EXPORTER_OTLP_ENDPOINT", format!("http://{addr}"))]);
    let http = child.http;
    let r = super::client()
        .post(format!("http://{http}/v1/render"))
        .header("traceparent", "00-11111111111111111111111111111111-2222222222222222-01")
        .json(&json!({"source": mdg("untraced")}))
        .send()
        .await
        .expect("request");
    assert_eq!(r.status(), 200);
    child.terminate();
    tokio::time::sleep(Duration::from_millis(300)).await;
    assert!(collector.spans.lock().expect("lock").is_empty(), "spans were exported without an endpoint");
}
