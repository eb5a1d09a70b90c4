//! The gRPC request conversion: arbitrary protobuf bytes decoded as a
//! `RenderRequest` (as tonic would), converted and validated into a render
//! plan exactly as the service does. Never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;
use prost::Message as _;
use rulemesh::service::grpc::pb;
use rulemesh::service::RenderBody;

fuzz_target!(|data: &[u8]| {
    if let Ok(req) = pb::RenderRequest::decode(data) {
        let no_cache = req.no_cache;
        let _ = RenderBody::from(req).plan(&rulemesh_fuzz::tight_limits(), no_cache);
    }
    if let Ok(req) = pb::CheckRequest::decode(data) {
        let body = rulemesh::service::request::CheckBody { source: req.source, language: (!req.language.is_empty()).then_some(req.language), ..Default::default() };
        let _ = rulemesh::service::http::check(body, &rulemesh_fuzz::tight_limits());
    }
});
