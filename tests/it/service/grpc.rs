//! The gRPC door: the same bytes as HTTP, error mapping, health and reflection.

use super::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_matches_http_and_maps_errors() {
    let (srv, base) = start(config()).await;
    let mut g = grpc_client(&srv).await;
    let source = std::fs::read_to_string(common::repo().join("grammars/tower.mdg")).expect("grammar");
    for format in ["glb", "stl", "gltf"] {
        let http = post(&base, "/v1/render", &json!({"source": source, "format": format, "seed": 2})).await.bytes().await.expect("body");
        let req = pb::RenderRequest { source: source.clone(), format: format.into(), seed: Some(2), ..Default::default() };
        let reply = g.render(req.clone()).await.expect("Render").into_inner();
        assert!(reply.model == http.as_ref(), "{format}: gRPC and HTTP bytes differ");
        let meta = reply.meta.expect("meta");
        assert!(meta.cache_hit);
        assert_eq!(meta.size, http.len() as u64);
        assert_eq!(meta.etag, blake3::hash(&http).to_hex()[..32]);

        let mut stream = g.render_stream(pb::RenderRequest { no_cache: true, ..req }).await.expect("RenderStream").into_inner();
        let mut bytes = Vec::new();
        let mut chunks = 0;
        while let Some(chunk) = stream.message().await.expect("chunk") {
            assert_eq!(chunk.meta.is_some(), chunks == 0);
            bytes.extend_from_slice(&chunk.data);
            chunks += 1;
        }
        assert!(bytes == http.as_ref(), "{format}: streamed bytes differ");
    }

    // print=true travels over gRPC too, byte-identical to HTTP.
    let http = post(&base, "/v1/render", &json!({"source": source, "format": "3mf", "print": true, "size_mm": 40})).await.bytes().await.expect("body");
    let req = pb::RenderRequest { source: source.clone(), format: "3mf".into(), print: Some(true), size_mm: Some(40.0), ..Default::default() };
    let reply = g.render(req).await.expect("Render print").into_inner();
    assert!(reply.model == http.as_ref() && http.starts_with(b"PK"), "gRPC and HTTP print bytes differ");
    // The printer profile too: a low ceiling is a finding, a bad minimum wall is INVALID_ARGUMENT.
    let boxes = "rule R { BOX {} BOX { x 0.5 } }".to_string();
    let req = pb::RenderRequest { source: boxes.clone(), print: Some(true), print_report: Some(true), triangle_ceiling: Some(4), build_volume_mm: vec![250.0, 210.0, 210.0], ..Default::default() };
    let report: Value = serde_json::from_slice(&g.render(req).await.expect("Render report").into_inner().model).expect("report");
    assert!(report["findings"].as_array().expect("findings").iter().any(|f| f["code"] == "too_many_triangles"), "{report}");
    let err = g.render(pb::RenderRequest { source: boxes, print: Some(true), min_wall_mm: Some(0.0), ..Default::default() }).await.expect_err("bad wall");
    assert_eq!(err.code(), tonic::Code::InvalidArgument);

    let err = g.render(pb::RenderRequest { source: "startshape A\nrule A { BOX { x } }".into(), ..Default::default() }).await.expect_err("parse error");
    assert_eq!(err.code(), tonic::Code::InvalidArgument);
    let details: Value = serde_json::from_slice(err.details()).expect("JSON details");
    assert_eq!(details["error"]["line"], 2);

    let limits = pb::Limits { max_primitives: Some(2), ..Default::default() };
    let err = g.render(pb::RenderRequest { source: small("grpc"), limits: Some(limits), ..Default::default() }).await.expect_err("limit");
    assert_eq!(err.code(), tonic::Code::ResourceExhausted);
    assert_eq!(err.metadata().get("x-rulemesh-limit").and_then(|v| v.to_str().ok()), Some("primitives"));

    let limits = pb::Limits { timeout_ms: Some(30), max_steps: Some(2_000_000_000), ..Default::default() };
    let err = g.render(pb::RenderRequest { source: SLOW.into(), limits: Some(limits), ..Default::default() }).await.expect_err("deadline");
    assert_eq!(err.code(), tonic::Code::DeadlineExceeded);

    let err = g.render(pb::RenderRequest { source: small("fmt"), format: "obj".into(), ..Default::default() }).await.expect_err("format");
    assert_eq!(err.code(), tonic::Code::InvalidArgument);

    let check = g.check(pb::CheckRequest { source: "startshape A\nrule A { BOX { x } }".into(), language: String::new(), files: Default::default() }).await.expect("Check").into_inner();
    assert!(!check.ok);
    assert_eq!(check.diagnostics[0].line, 2);
    // A cpfg model's #include resolves against the request's files, as in a render.
    let cpfg = "#include \"rules.h\"\nLsystem: 1\nAxiom: F\nRULE\nendlsystem\n";
    let files: std::collections::HashMap<String, Vec<u8>> = [("rules.h".to_string(), b"#define RULE F --> FF\n".to_vec())].into();
    let with = g.check(pb::CheckRequest { source: cpfg.into(), language: String::new(), files }).await.expect("Check").into_inner();
    assert!(with.ok && with.language == "cpfg", "{with:?}");
    let without = g.check(pb::CheckRequest { source: cpfg.into(), language: String::new(), files: Default::default() }).await.expect("Check").into_inner();
    assert!(!without.ok && without.diagnostics[0].message.contains("rules.h"), "{without:?}");

    let list = g.list_grammars(pb::ListGrammarsRequest {}).await.expect("ListGrammars").into_inner();
    assert!(list.grammars.iter().any(|x| x.name == "gem" && x.language == "mdg" && !x.description.is_empty()));

    let channel = tonic::transport::Endpoint::from_shared(format!("http://{}", srv.grpc_addr)).expect("uri").connect().await.expect("connect");
    let mut health = tonic_health::pb::health_client::HealthClient::new(channel);
    let status = health
        .check(tonic_health::pb::HealthCheckRequest { service: "rulemesh.v1.Rulemesh".into() })
        .await
        .expect("health")
        .into_inner();
    assert_eq!(status.status(), tonic_health::pb::health_check_response::ServingStatus::Serving);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_reflection_lists_the_services() {
    use tonic_reflection::pb::v1::server_reflection_client::ServerReflectionClient;
    use tonic_reflection::pb::v1::server_reflection_request::MessageRequest;
    use tonic_reflection::pb::v1::server_reflection_response::MessageResponse;
    use tonic_reflection::pb::v1::ServerReflectionRequest;
    let (srv, _base) = start(config()).await;
    let channel = tonic::transport::Channel::from_shared(format!("http://{}", srv.grpc_addr)).expect("uri").connect().await.expect("connects");
    let mut client = ServerReflectionClient::new(channel);
    let ask = |m: MessageRequest| ServerReflectionRequest { host: String::new(), message_request: Some(m) };
    let requests = vec![ask(MessageRequest::ListServices(String::new())), ask(MessageRequest::FileContainingSymbol("rulemesh.v1.Rulemesh".into()))];
    let mut replies = client.server_reflection_info(tokio_stream::iter(requests)).await.expect("reflection call").into_inner();
    let first = replies.message().await.expect("reply").expect("a reply");
    let Some(MessageResponse::ListServicesResponse(list)) = first.message_response else { panic!("{first:?}") };
    let names: Vec<&str> = list.service.iter().map(|s| s.name.as_str()).collect();
    for want in ["rulemesh.v1.Rulemesh", "grpc.health.v1.Health", "grpc.reflection.v1.ServerReflection"] {
        assert!(names.contains(&want), "{names:?}");
    }
    let second = replies.message().await.expect("reply").expect("a reply");
    let Some(MessageResponse::FileDescriptorResponse(files)) = second.message_response else { panic!("{second:?}") };
    assert!(files.file_descriptor_proto.iter().any(|f| f.windows(b"RenderStream".len()).any(|w| w == b"RenderStream")));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
