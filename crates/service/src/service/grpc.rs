//! The gRPC API (tonic): the same requests, models and errors as HTTP.

use super::request::{CheckBody, RenderBody};
use super::access_log::{log_request, Finished};
use crate::pipeline::{LimitsOptions, RenderOptions};
use super::{library, AppState, Served, ServiceError};
use crate::cache::CacheOutcome;
use crate::core::ParamValue;
use std::pin::Pin;
use std::sync::Arc;
use tonic::{Request, Response, Status};

/// Code generated from `proto/rulemesh/v1/rulemesh.proto`.
#[allow(missing_docs, clippy::all, clippy::pedantic)]
pub mod pb {
    tonic::include_proto!("rulemesh.v1");
}

/// The encoded protobuf descriptors of `rulemesh.v1`, served by gRPC reflection.
pub(crate) const FILE_DESCRIPTOR_SET: &[u8] = tonic::include_file_descriptor_set!("rulemesh_descriptor");

use pb::rulemesh_server::{Rulemesh, RulemeshServer};
use std::time::Instant;
use tracing::Instrument;

/// Bytes per `RenderStream` chunk.
pub(crate) const CHUNK_BYTES: usize = 64 * 1024;

/// The gRPC service over the shared engine.
pub struct GrpcService {
    state: Arc<AppState>,
}

/// The tonic server for `rulemesh.v1.Rulemesh`, with message limits from the config.
pub fn server(state: Arc<AppState>) -> RulemeshServer<GrpcService> {
    let limit = state.config.body_limit.saturating_add(64 * 1024);
    RulemeshServer::new(GrpcService { state }).max_decoding_message_size(limit).max_encoding_message_size(usize::MAX)
}

impl From<pb::RenderRequest> for RenderBody {
    /// Field by field, with no `..`: an option added to the declaration
    /// ([`RenderOptions`]) does not compile here until gRPC carries it.
    fn from(r: pb::RenderRequest) -> Self {
        let non_empty = |s: String| if s.is_empty() { None } else { Some(s) };
        let pb::RenderRequest {
            source,
            language,
            seed,
            params,
            format,
            limits,
            on_limit,
            detail,
            // Not an option of the render: how the server looks it up (`GrpcService::serve`).
            no_cache: _,
            layout,
            position_bits,
            normal_bits,
            zstd,
            weld,
            quantize,
            compress,
            fit,
            instancing,
            print,
            size_mm,
            print_report,
            min_wall_mm,
            build_volume_mm,
            triangle_ceiling,
            size,
            view,
            background,
            frame,
            files,
            checksum,
        } = r;
        let options = RenderOptions {
            language: non_empty(language),
            seed,
            params: params.into_iter().map(|(k, v)| (k, ParamValue::Text(v))).collect(),
            format: non_empty(format),
            limits: limits.map(|l| {
                let pb::Limits { max_depth, max_primitives, max_triangles, max_memory, timeout_ms, max_source_bytes, max_steps } = l;
                LimitsOptions { max_depth, max_primitives, max_triangles, max_memory, timeout_ms, max_source_bytes, max_steps }
            }),
            on_limit: non_empty(on_limit),
            detail,
            frame,
            layout: non_empty(layout),
            // Out-of-range values become 0, which validation rejects with a message.
            position_bits: position_bits.map(|b| u8::try_from(b).unwrap_or(0)),
            normal_bits: normal_bits.map(|b| u8::try_from(b).unwrap_or(0)),
            zstd,
            checksum,
            weld,
            quantize,
            compress: non_empty(compress),
            fit: non_empty(fit),
            instancing: non_empty(instancing),
            print,
            size_mm,
            print_report,
            min_wall_mm,
            // Absent and empty are the same on the wire: the default volume.
            build_volume_mm: if build_volume_mm.is_empty() { None } else { Some(build_volume_mm) },
            triangle_ceiling,
            size,
            view: non_empty(view),
            background: non_empty(background),
        };
        RenderBody { source, files: files.into_iter().map(|(k, v)| (k, file_text(v))).collect(), options }
    }
}

/// The metadata of a served model (a reply's, a stream's first chunk's, a batch item's).
pub(super) fn meta(served: &Served) -> pb::RenderMeta {
    let m = &served.model;
    pb::RenderMeta {
        content_type: m.content_type.to_string(),
        etag: m.etag.clone(),
        cache_hit: served.cache == CacheOutcome::Hit,
        primitives: m.primitives,
        triangles: m.triangles,
        truncated: m.truncated.map(|t| pb::Truncation { limit: t.limit.name().to_string(), configured: t.configured, reached: t.reached }),
        size: m.bytes.len() as u64,
        seed: m.seed,
        print: m.print.map(|p| pb::PrintSummary { volume_mm3: p.volume_mm3, surface_area_mm2: p.surface_area_mm2, bbox_mm: p.bbox_mm.to_vec(), shells: p.shells, watertight: p.watertight }),
    }
}

/// `response` with the request's timing as `server-timing` metadata (the
/// HTTP `Server-Timing` header's value) and the model's seed as
/// `x-rulemesh-seed` (decimal, as the HTTP header), and a Context Free
/// design's variation code as `x-rulemesh-variation`, in the response headers.
fn with_timing<T>(mut response: Response<T>, served: &Served) -> Response<T> {
    if let Ok(v) = tonic::metadata::MetadataValue::try_from(served.timing.header_value()) {
        response.metadata_mut().insert("server-timing", v);
    }
    response.metadata_mut().insert("x-rulemesh-seed", tonic::metadata::MetadataValue::from(served.model.seed));
    if let Some(code) = crate::lang::cfdg::variation_code(served.model.language, served.model.seed).and_then(|c| tonic::metadata::MetadataValue::try_from(c).ok()) {
        response.metadata_mut().insert("x-rulemesh-variation", code);
    }
    response
}

/// Admits a gRPC call by its metadata (`authorization: Bearer KEY` or `x-api-key: KEY`).
fn admit(state: &AppState, metadata: &tonic::metadata::MetadataMap) -> Result<super::access::Admission, ServiceError> {
    state.admit(super::access::presented_key(|name| metadata.get(name).and_then(|v| v.to_str().ok())))
}

impl GrpcService {
    async fn serve(&self, method: &'static str, request: Request<pb::RenderRequest>) -> Result<Served, Status> {
        let started = Instant::now();
        let admission = match admit(&self.state, request.metadata()) {
            Ok(a) => a,
            Err(e) => {
                self.count(method, &Err::<(), _>(e.clone()), started);
                return Err(e.to_status());
            }
        };
        let id = super::http::next_request_id();
        // DEBUG, as HTTP's request span (`super::http::observe` says why).
        let span = tracing::debug_span!(
            "grpc",
            id,
            method,
            otel.name = method,
            otel.kind = "server",
            language = tracing::field::Empty,
            key = tracing::field::Empty,
            cache = tracing::field::Empty
        );
        super::telemetry::adopt_parent(&span, |name| request.metadata().get(name).and_then(|v| v.to_str().ok()));
        let req = request.into_inner();
        let no_cache = req.no_cache;
        let ceiling = admission.ceiling;
        let result = async {
            let plan = RenderBody::from(req).plan(&ceiling, no_cache)?;
            let format = plan.request.format;
            plan.pipe_serve(&self.state).await.map(|s| (s, format))
        }
        .instrument(span.clone())
        .await;
        drop(admission);
        self.count(method, &result, started);
        let (code, etag, timing, bytes) = match &result {
            Ok((s, _)) => ("ok", Some(s.model.etag.as_str()), Some(&s.timing), u64::try_from(s.model.bytes.len()).ok()),
            Err(e) => (e.code(), None, None, None),
        };
        log_request(&Finished { id, method: "grpc", route: method, status: None, code: Some(code), wall: started.elapsed(), bytes, etag, timing }, &span);
        let (served, format) = result.map_err(|e| e.to_status())?;
        self.state.metrics.bytes_out("grpc", format, served.model.bytes.len());
        Ok(served)
    }

    /// Counts a finished call, by method and status code, with its latency since `started`.
    fn count<T>(&self, method: &str, result: &Result<T, ServiceError>, started: Instant) {
        let code = match result {
            Ok(_) => tonic::Code::Ok,
            Err(e) => e.grpc_code(),
        };
        self.state.metrics.request("grpc", method, code as u16, started.elapsed());
    }
}

impl super::RenderPlan {
    async fn pipe_serve(self, state: &AppState) -> Result<Served, ServiceError> {
        state.engine.serve(self).await
    }
}

type ChunkStream = Pin<Box<dyn tokio_stream::Stream<Item = Result<pb::RenderChunk, Status>> + Send>>;

#[tonic::async_trait]
impl Rulemesh for GrpcService {
    async fn render(&self, request: Request<pb::RenderRequest>) -> Result<Response<pb::RenderReply>, Status> {
        let served = self.serve("Render", request).await?;
        Ok(with_timing(Response::new(pb::RenderReply { meta: Some(meta(&served)), model: served.model.bytes.to_vec() }), &served))
    }

    type RenderStreamStream = ChunkStream;

    async fn render_stream(&self, request: Request<pb::RenderRequest>) -> Result<Response<ChunkStream>, Status> {
        let served = self.serve("RenderStream", request).await?;
        let bytes = served.model.bytes.clone();
        let mut first = Some(meta(&served));
        let served_timing = served;
        let count = bytes.len().div_ceil(CHUNK_BYTES).max(1);
        let chunks = (0..count).map(move |i| {
            let end = ((i + 1) * CHUNK_BYTES).min(bytes.len());
            let data = bytes.get(i * CHUNK_BYTES..end).map(<[u8]>::to_vec).unwrap_or_default();
            Ok(pb::RenderChunk { meta: first.take(), data })
        });
        Ok(with_timing(Response::new(Box::pin(tokio_stream::iter(chunks))), &served_timing))
    }

    type RenderBatchStream = super::grpc_batch::ItemStream;

    async fn render_batch(&self, request: Request<pb::RenderBatchRequest>) -> Result<Response<Self::RenderBatchStream>, Status> {
        let started = Instant::now();
        // DEBUG, as HTTP's request span (`super::http::observe` says why).
        let span = tracing::debug_span!(
            "grpc",
            id = super::http::next_request_id(),
            method = "RenderBatch",
            otel.name = "RenderBatch",
            otel.kind = "server",
            language = tracing::field::Empty,
            key = tracing::field::Empty,
            cache = tracing::field::Empty
        );
        super::telemetry::adopt_parent(&span, |name| request.metadata().get(name).and_then(|v| v.to_str().ok()));
        let admitted = admit(&self.state, request.metadata())
            .and_then(|a| super::grpc_batch::batch_of(request.into_inner(), &a.ceiling).map(|(batch, no_cache)| (a, batch, no_cache)));
        self.count("RenderBatch", &admitted, started);
        let (admission, batch, no_cache) = admitted.map_err(|e| e.to_status())?;
        let ceiling = admission.ceiling;
        // The admission travels with the stream: the key's share is held until the last item.
        Ok(Response::new(super::grpc_batch::items(batch, self.state.clone(), ceiling, no_cache, span, admission)))
    }

    async fn check(&self, request: Request<pb::CheckRequest>) -> Result<Response<pb::CheckReply>, Status> {
        let started = Instant::now();
        let admission = admit(&self.state, request.metadata());
        let r = request.into_inner();
        let files = r.files.into_iter().map(|(k, v)| (k, file_text(v))).collect();
        let body = CheckBody { source: r.source, language: if r.language.is_empty() { None } else { Some(r.language) }, files };
        let result = admission.and_then(|a| super::http::check(body, &a.ceiling));
        self.count("Check", &result, started);
        let report = result.map_err(|e| e.to_status())?;
        Ok(Response::new(pb::CheckReply {
            ok: report.ok,
            language: report.language.unwrap_or_default().to_string(),
            diagnostics: report
                .diagnostics
                .into_iter()
                .map(|d| pb::Diagnostic {
                    severity: match d.severity {
                        crate::core::Severity::Error => "error".into(),
                        crate::core::Severity::Warning => "warning".into(),
                    },
                    line: d.span.line,
                    column: d.span.column,
                    message: d.message,
                })
                .collect(),
        }))
    }

    async fn list_grammars(&self, request: Request<pb::ListGrammarsRequest>) -> Result<Response<pb::ListGrammarsReply>, Status> {
        let started = Instant::now();
        let admitted = admit(&self.state, request.metadata()).map(|_| ());
        self.count("ListGrammars", &admitted, started);
        admitted.map_err(|e| e.to_status())?;
        let grammars = library::all()
            .map(|b| {
                let info = b.info();
                pb::Grammar {
                    name: info.name.to_string(),
                    language: info.language.to_string(),
                    description: info.description,
                    params: info
                        .params
                        .into_iter()
                        .map(|p| pb::Param { name: p.name, kind: p.kind.to_string(), default: p.default, min: p.min, max: p.max })
                        .collect(),
                }
            })
            .collect();
        Ok(Response::new(pb::ListGrammarsReply { grammars }))
    }
}

/// A gRPC file's bytes in the HTTP body's spelling: text as itself, other
/// bytes (and text that would read as base64) as `base64:` and the bytes.
fn file_text(bytes: Vec<u8>) -> String {
    use base64::Engine as _;
    match String::from_utf8(bytes) {
        Ok(t) if !t.starts_with("base64:") => t,
        Ok(t) => format!("base64:{}", base64::engine::general_purpose::STANDARD.encode(t.as_bytes())),
        Err(e) => format!("base64:{}", base64::engine::general_purpose::STANDARD.encode(e.as_bytes())),
    }
}
