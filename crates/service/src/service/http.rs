//! The HTTP API (axum): JSON in, model bytes out.

use super::library::{self, GrammarInfo};
use super::request::{from_json, CheckBody, RenderBody};
use super::metrics::{wants_openmetrics, OPENMETRICS, PROMETHEUS_TEXT};
use super::access_log::{log_request, Finished};
use super::header_names as names;
use super::timing::RequestTiming;
use super::{AppState, Served, ServiceError};
use crate::cache::CacheOutcome;
use crate::core::Limits;
use crate::export::Format;
use crate::core::{Diagnostic, Severity};
use axum::body::{Body, Bytes};
use axum::extract::rejection::BytesRejection;
use axum::extract::{DefaultBodyLimit, MatchedPath, Path, RawQuery, Request, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::{Extension, Json, Router};
use futures_util::StreamExt;
use serde::Serialize;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, OnceLock};
use super::error::{ErrorBody, ErrorDetail};
use tower_http::compression::predicate::{Predicate, SizeAbove};
use tower_http::compression::CompressionLayer;
use utoipa::{OpenApi, ToSchema};
use utoipa_axum::router::OpenApiRouter;
use utoipa_axum::routes;
use std::time::Instant;
use tracing::Instrument;

/// `Cache-Control` of a model whose every input is pinned by its URL.
pub(crate) const CACHE_IMMUTABLE: &str = "public, max-age=31536000, immutable";
/// `Cache-Control` of a model whose seed is not pinned by its URL.
pub(crate) const CACHE_SHORT: &str = "public, max-age=300";

/// The HTTP router with every route, the body limit, response compression
/// and request metrics.
pub fn router(state: Arc<AppState>) -> Router {
    let (routes, _doc) = api_router().split_for_parts();
    let router = routes
        .merge(super::playground::router())
        .fallback(|| async { ServiceError::NotFound("no such route".into()) })
        .layer(DefaultBodyLimit::max(state.config.body_limit))
        .layer(middleware::from_fn_with_state(state.clone(), access))
        .layer(compression())
        .layer(middleware::from_fn(etag_per_encoding))
        .layer(middleware::from_fn_with_state(state.clone(), observe));
    // Outermost, so that preflights are answered before access control and
    // error responses (401, 429) carry the CORS headers browsers need to read them.
    let router = match cors(&state.config.cors_origins) {
        Some(layer) => router.layer(layer),
        None => router,
    };
    router.with_state(state)
}

/// The CORS policy for `origins` (`*` for any); `None` when empty (no CORS headers at all).
fn cors(origins: &[String]) -> Option<tower_http::cors::CorsLayer> {
    use tower_http::cors::{AllowOrigin, CorsLayer};
    if origins.is_empty() {
        return None;
    }
    let allow = if origins.iter().any(|o| o.trim() == "*") {
        AllowOrigin::any()
    } else {
        AllowOrigin::list(origins.iter().filter_map(|o| HeaderValue::from_str(o.trim()).ok()))
    };
    let name = header::HeaderName::from_static;
    Some(
        CorsLayer::new()
            .allow_origin(allow)
            .allow_methods([axum::http::Method::GET, axum::http::Method::POST])
            .allow_headers([header::CONTENT_TYPE, header::AUTHORIZATION, name("x-api-key"), header::CACHE_CONTROL, header::IF_NONE_MATCH])
            .expose_headers([
                header::ETAG,
                header::RETRY_AFTER,
                name("x-request-id"),
                name("server-timing"),
                name("x-rulemesh-cache"),
                name("x-rulemesh-error"),
                name("x-rulemesh-primitives"),
                name("x-rulemesh-seed"),
                name("x-rulemesh-variation"),
                name("x-rulemesh-triangles"),
                name("x-rulemesh-truncated"),
                name("x-rulemesh-truncated-limit"),
            ])
            .max_age(std::time::Duration::from_secs(600)),
    )
}

/// Who is calling: the ceiling their limits are clamped to (the server's,
/// lowered by their API key's). Inserted by [`access`] into every request.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Caller {
    /// The ceiling for this request.
    pub ceiling: Limits,
}

/// Marks a response whose body is still being made when it is returned
/// (the batch route's NDJSON): [`access`] then holds the caller's
/// concurrency share until the body ends, not just until the headers.
#[derive(Debug, Clone, Copy)]
pub struct Streamed;

/// Admits `/v1/…` requests by API key (401, 429), holding the key's
/// concurrency share until the response is ready (a [`Streamed`] one: until
/// its body ends); other routes (probes, metrics, the OpenAPI document) stay open.
async fn access(State(st): State<Arc<AppState>>, mut req: Request, next: Next) -> Response {
    if !req.uri().path().starts_with("/v1/") {
        req.extensions_mut().insert(Caller { ceiling: st.ceiling });
        return next.run(req).await;
    }
    let key = super::access::presented_key(|n| req.headers().get(n).and_then(|v| v.to_str().ok()));
    let admission = match st.admit(key) {
        Ok(a) => a,
        Err(e) => return e.into_response(),
    };
    req.extensions_mut().insert(Caller { ceiling: admission.ceiling });
    let resp = next.run(req).await;
    if resp.extensions().get::<Streamed>().is_some() {
        let (parts, body) = resp.into_parts();
        let held = body.into_data_stream().map(move |chunk| {
            let _share = &admission;
            chunk
        });
        return Response::from_parts(parts, Body::from_stream(held));
    }
    drop(admission);
    resp
}

/// Every documented route: each handler registered once, for both the
/// router and the OpenAPI document, so the two cannot drift apart.
fn api_router() -> OpenApiRouter<Arc<AppState>> {
    OpenApiRouter::with_openapi(ApiDoc::openapi())
        .routes(routes!(render_post))
        .routes(routes!(super::http_batch::batch_post))
        .routes(routes!(model_get))
        .routes(routes!(grammars_list))
        .routes(routes!(grammar_source))
        .routes(routes!(super::http_schema::grammar_schema))
        .routes(routes!(super::http_schema::schema_post))
        .routes(routes!(check_post))
        .routes(routes!(healthz))
        .routes(routes!(readyz))
        .routes(routes!(metrics))
        .routes(routes!(openapi_json))
}

/// The document's title, version and shared schemas; paths come from the handlers.
#[derive(OpenApi)]
#[openapi(
    info(title = "rulemesh", description = "Shape grammars to 3D models (glTF, STL, strips) under hard limits."),
    components(schemas(ErrorBody, ErrorDetail, DiagnosticSchema))
)]
struct ApiDoc;

/// The OpenAPI 3 document of the HTTP API, generated from the handlers' types.
pub fn openapi() -> utoipa::openapi::OpenApi {
    api_router().split_for_parts().1
}

/// [`openapi`] as JSON, built once.
pub fn openapi_json_text() -> &'static str {
    static DOC: OnceLock<String> = OnceLock::new();
    DOC.get_or_init(|| {
        let mut doc = serde_json::to_value(openapi()).unwrap_or_default();
        super::schema::tighten_openapi(&mut doc);
        serde_json::to_string(&doc).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
    })
}

/// `GET /openapi.json`.
#[utoipa::path(get, path = "/openapi.json", tag = "meta",
    responses((status = 200, description = "This API's OpenAPI 3 document", content_type = "application/json", body = Object)))]
async fn openapi_json() -> Response {
    ([(header::CONTENT_TYPE, "application/json")], openapi_json_text()).into_response()
}

/// Responses smaller than this are sent as they are.
pub(crate) const COMPRESS_MIN_BYTES: u16 = 256;

/// The response compression of every route: text and JSON bodies of at
/// least [`COMPRESS_MIN_BYTES`], in the codings the request accepts. One
/// constructor for the router and the direct model route (`super::direct`),
/// so the two compress alike.
pub(super) fn compression() -> CompressionLayer<tower_http::compression::predicate::And<SizeAbove, TextBodies>> {
    CompressionLayer::new().compress_when(SizeAbove::new(COMPRESS_MIN_BYTES).and(TextBodies))
}

/// Marks a response whose body is text (glTF JSON, ASCII STL) so that it may
/// be compressed although its type is `model/*`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TextModel;

/// Compresses JSON and text bodies and models marked [`TextModel`]; binary
/// models (GLB, binary STL, strips) go out as they are.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TextBodies;

impl Predicate for TextBodies {
    fn should_compress<B>(&self, response: &axum::http::Response<B>) -> bool
    where
        B: axum::body::HttpBody,
    {
        if response.extensions().get::<TextModel>().is_some() {
            return true;
        }
        let ctype = response.headers().get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("");
        ctype.starts_with("text/") || ctype.starts_with("application/json")
    }
}

/// Gives a compressed response its own strong ETag (`"HASH-gzip"`), as one
/// entity tag must name one byte sequence; [`etag_matches`] accepts both.
async fn etag_per_encoding(req: Request, next: Next) -> Response {
    let mut resp = next.run(req).await;
    tag_encoded_etag(&mut resp);
    resp
}

/// [`etag_per_encoding`]'s work on a finished response (also the direct model route's).
pub(super) fn tag_encoded_etag(resp: &mut Response) {
    let encoding = resp.headers().get(header::CONTENT_ENCODING).and_then(|v| v.to_str().ok()).map(str::to_string);
    if let Some(enc) = encoding {
        let tagged = resp.headers().get(header::ETAG).and_then(|v| v.to_str().ok()).and_then(|t| t.strip_suffix('"').map(|t| format!("{t}-{enc}\"")));
        if let Some(t) = tagged {
            resp.headers_mut().insert(header::ETAG, header_value(&t));
        }
    }
}

static REQUEST_ID: AtomicU64 = AtomicU64::new(1);

/// A new request id, unique in this process (shared by HTTP and gRPC).
pub(crate) fn next_request_id() -> u64 {
    REQUEST_ID.fetch_add(1, Ordering::Relaxed)
}

/// Counts every request by route and status and logs it in a span with a
/// request id, the language, the cache key and the cache result.
async fn observe(State(state): State<Arc<AppState>>, req: Request, next: Next) -> Response {
    // The matched path is shared (an `Arc<str>` inside): cloned, not copied.
    let matched = req.extensions().get::<MatchedPath>().cloned();
    let route = matched.as_ref().map_or("unmatched", MatchedPath::as_str);
    let id = next_request_id();
    let method = req.method().clone();
    // The span is at DEBUG level: at the default INFO nothing reads it (the
    // access line is written outside it), and creating it cost every request
    // the formatting of its fields into the log layer's storage, then again
    // on each `record` (about 3 % of a fresh `gem.glb`'s instructions, issue
    // 33). It exists whenever its readers do: with `--log debug` (the detail
    // line) and while spans are exported (the OTLP layer takes every
    // rulemesh span whatever its level). A warning logged inside a request
    // at the default level therefore carries no `http{id=…}` prefix.
    let span = tracing::debug_span!(
        "http",
        id,
        method = %method,
        route = %route,
        otel.name = tracing::field::Empty,
        otel.kind = "server",
        language = tracing::field::Empty,
        key = tracing::field::Empty,
        cache = tracing::field::Empty
    );
    // The span's name in a trace; only spans being exported need it, and
    // formatting it cost every request an allocation (issue 33).
    if super::telemetry::tracing_on() {
        span.record("otel.name", tracing::field::display(format_args!("{method} {route}")));
    }
    super::telemetry::adopt_parent(&span, |name| req.headers().get(name).and_then(|v| v.to_str().ok()));
    let started = Instant::now();
    let mut resp = next.run(req).instrument(span.clone()).await;
    observed(&state, id, method.as_str(), route, started.elapsed(), &mut resp, &span);
    resp
}

/// [`observe`]'s work on a finished response (also the direct model
/// route's): counts it, writes its access line and gives it its request id.
pub(super) fn observed(state: &AppState, id: u64, method: &str, route: &str, took: std::time::Duration, resp: &mut Response, span: &tracing::Span) {
    let status = resp.status().as_u16();
    state.metrics.request("http", route, status, took);
    let etag = resp.headers().get(header::ETAG).and_then(|v| v.to_str().ok());
    let timing = resp.extensions().get::<RequestTiming>();
    let bytes = axum::body::HttpBody::size_hint(resp.body()).exact();
    let finished = Finished { id, method, route, status: Some(status), code: None, wall: took, bytes, etag, timing };
    log_request(&finished, span);
    resp.headers_mut().insert(names::X_REQUEST_ID, HeaderValue::from(id));
}

/// Whether the request asks to bypass the cache.
pub(super) fn wants_fresh(headers: &HeaderMap) -> bool {
    headers
        .get_all(header::CACHE_CONTROL)
        .iter()
        .chain(headers.get_all(header::PRAGMA).iter())
        .filter_map(|v| v.to_str().ok())
        .any(|v| v.split(',').any(|d| d.trim().eq_ignore_ascii_case("no-cache")))
}

pub(super) fn body_bytes(body: Result<Bytes, BytesRejection>, limit: usize) -> Result<Bytes, ServiceError> {
    body.map_err(|e| {
        if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
            ServiceError::PayloadTooLarge { limit }
        } else {
            ServiceError::BadRequest(e.body_text())
        }
    })
}

fn header_value(s: &str) -> HeaderValue {
    HeaderValue::from_str(s).unwrap_or_else(|_| HeaderValue::from_static("invalid"))
}

/// Whether `format`'s bytes are text (and worth compressing): the registry's capability.
fn is_text(format: Format) -> bool {
    format.is_text()
}

/// A model response with its ETag, cache and count headers.
fn model_response(served: &Served, cache_control: Option<&'static str>, text: bool) -> Response {
    let m = &served.model;
    let mut resp = Response::new(Body::from(m.bytes.clone()));
    if text {
        resp.extensions_mut().insert(TextModel);
    }
    // The request's log line (in `observe`) reads the timing from here.
    resp.extensions_mut().insert(served.timing);
    let h = resp.headers_mut();
    // Room for every header the response gets (model_headers, Vary, the
    // request id, hyper's date and length): no regrowth on the way.
    h.reserve(16);
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static(m.content_type));
    model_headers(h, served, cache_control);
    resp
}

/// The headers of a model response (also of its 304): ETag, cache result,
/// the seed the model was made with (so a client that sent none can pin
/// it), counts, truncation, `Cache-Control` and `Server-Timing`.
fn model_headers(h: &mut HeaderMap, served: &Served, cache_control: Option<&'static str>) {
    let m = &served.model;
    h.insert(names::SERVER_TIMING, header_value(&served.timing.header_value()));
    h.insert(header::ETAG, header_value(&format!("\"{}\"", m.etag)));
    h.insert(names::X_CACHE, HeaderValue::from_static(if served.cache == CacheOutcome::Hit { "hit" } else { "miss" }));
    h.insert(names::X_SEED, HeaderValue::from(m.seed));
    // A Context Free design's variation code, the seed as Context Free names it.
    if let Some(code) = crate::lang::cfdg::variation_code(m.language, m.seed) {
        h.insert(names::X_VARIATION, header_value(&code));
    }
    h.insert(names::X_PRIMITIVES, HeaderValue::from(m.primitives));
    h.insert(names::X_TRIANGLES, HeaderValue::from(m.triangles));
    h.insert(names::X_TRUNCATED, HeaderValue::from_static(if m.truncated.is_some() { "true" } else { "false" }));
    if let Some(t) = &m.truncated {
        h.insert(names::X_TRUNCATED_LIMIT, HeaderValue::from_static(t.limit.name()));
        h.insert(names::X_TRUNCATED_CONFIGURED, HeaderValue::from(t.configured));
        h.insert(names::X_TRUNCATED_REACHED, HeaderValue::from(t.reached));
    }
    // A printed model's figures (STL and 3MF alike), as the print stage
    // measured them: kept with the bytes, never measured again here.
    if let Some(print) = &m.print {
        for (name, value) in print.headers() {
            h.insert(name, header_value(&value));
        }
    }
    match cache_control {
        Some(cc) if m.truncated.is_none() => h.insert(header::CACHE_CONTROL, HeaderValue::from_static(cc)),
        _ => h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store")),
    };
}

/// `POST /v1/render`.
#[utoipa::path(post, path = "/v1/render", tag = "render",
    request_body = RenderBody,
    params(("Cache-Control" = Option<String>, Header, description = "`no-cache` renders afresh")),
    responses(
        (status = 200, description = "The model", content(
            (Vec<u8> = "model/gltf-binary"),
            (Vec<u8> = "model/gltf+json"),
            (Vec<u8> = "model/stl"),
            (Vec<u8> = "application/vnd.rulemesh.strips"),
            (Vec<u8> = "application/vnd.rulemesh.scene"),
            (Vec<u8> = "image/png")
        ), headers(
            ("ETag" = String, description = "Strong ETag: the BLAKE3 content hash (suffixed with the encoding when compressed)"),
            ("X-Rulemesh-Cache" = String, description = "hit or miss"),
            ("X-Rulemesh-Seed" = String, description = "The seed the model was made with, in decimal (0 to 2^64 - 1): the request's, else the grammar's own seed directive, else 0"),
            ("X-Rulemesh-Variation" = String, description = "language cfdg only: the variation code the design was drawn with (`ABC`; Context Free's -v), which the `variation` parameter takes back"),
            ("X-Rulemesh-Primitives" = u64, description = "Primitive instances"),
            ("X-Rulemesh-Triangles" = u64, description = "Triangles"),
            ("X-Rulemesh-Truncated" = bool, description = "Whether a limit cut the model short"),
            ("X-Print-Volume-Mm3" = String, description = "print=true (STL or 3MF): enclosed volume in mm³, three decimals"),
            ("X-Print-Surface-Area-Mm2" = String, description = "print=true: surface area in mm²"),
            ("X-Print-Bbox-Mm" = String, description = "print=true: bounding-box size x y z in mm"),
            ("X-Print-Shells" = u64, description = "print=true: connected shells (1 for one printable piece)"),
            ("X-Print-Watertight" = bool, description = "print=true: every edge has two oppositely wound faces"),
            ("Server-Timing" = String, description = "Where the time went: queue, each stage that ran (parse, eval, mesh, print, preview, export) and the cache lookup, in ms")
        )),
        (status = 400, description = "Malformed request, parse or evaluation error", body = ErrorBody),
        (status = 413, description = "Request body too large", body = ErrorBody),
        (status = 422, description = "A limit was exceeded", body = ErrorBody),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 403, description = "A #javascript EisenScript script, which this server does not run", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody),
        (status = 503, description = "Overloaded or shutting down (with Retry-After)", body = ErrorBody),
        (status = 504, description = "Deadline exceeded", body = ErrorBody)
    ))]
async fn render_post(State(st): State<Arc<AppState>>, Extension(caller): Extension<Caller>, headers: HeaderMap, body: Result<Bytes, BytesRejection>) -> Response {
    let result: Result<(Served, bool, Format), ServiceError> = async {
        let body = body_bytes(body, st.config.body_limit)?;
        let body = from_json::<RenderBody>(&body)?.with_phone_default(super::phone::is_phone(&headers));
        let plan = body.plan(&caller.ceiling, wants_fresh(&headers))?;
        let text = is_text(plan.request.format);
        let format = plan.request.format;
        Ok((st.engine.serve(plan).await?, text, format))
    }
    .await;
    match result {
        Ok((served, text, format)) => {
            st.metrics.bytes_out("http", format, served.model.bytes.len());
            let mut resp = model_response(&served, None, text);
            super::phone::vary(resp.headers_mut(), format);
            resp
        }
        Err(e) => e.into_response(),
    }
}

/// Whether `If-None-Match` lists `etag` (or `*`).
pub(super) fn etag_matches(headers: &HeaderMap, etag: &str) -> bool {
    headers.get_all(header::IF_NONE_MATCH).iter().filter_map(|v| v.to_str().ok()).any(|v| {
        v.split(',').map(str::trim).any(|t| {
            let t = t.trim_start_matches("W/").trim_matches('"');
            let base = ["-gzip", "-br", "-zstd"].iter().find_map(|s| t.strip_suffix(s)).unwrap_or(t);
            t == "*" || base == etag
        })
    })
}

/// The route of [`model_get`], as the router's `MatchedPath` names it.
pub(super) const MODELS_ROUTE: &str = "/v1/models/{file}";

/// `GET /v1/models/{name}.{glb|gltf|stl|3mf|png}?seed=N&p.<param>=V&detail=D&…`: the
/// declaration's query options (`request::query_body`); a png also `size`, `view`, `background`.
#[utoipa::path(get, path = "/v1/models/{file}", tag = "render",
    params(
        ("file" = String, Path, description = "NAME.glb, NAME.gltf, NAME.stl, NAME.3mf or NAME.png, NAME a built-in grammar"),
        // The other query options are the declaration's (`pipeline::options`), listed by `schema::tighten_openapi`.
        ("p.<param>" = Option<String>, Query, description = "A grammar parameter, e.g. p.size=3"),
        ("If-None-Match" = Option<String>, Header, description = "ETags the client holds"),
        ("Cache-Control" = Option<String>, Header, description = "`no-cache` renders afresh")
    ),
    responses(
        (status = 200, description = "The model, with Cache-Control for CDNs", content(
            (Vec<u8> = "model/gltf-binary"),
            (Vec<u8> = "model/gltf+json"),
            (Vec<u8> = "model/stl"),
            (Vec<u8> = "application/vnd.rulemesh.strips"),
            (Vec<u8> = "model/3mf"),
            (Vec<u8> = "image/png")
        ), headers(
            ("ETag" = String, description = "Strong ETag: the BLAKE3 content hash (suffixed with the encoding when compressed)"),
            ("X-Rulemesh-Cache" = String, description = "hit or miss"),
            ("X-Rulemesh-Seed" = String, description = "The seed the model was made with, in decimal (0 to 2^64 - 1): the request's, else the grammar's own seed directive, else 0"),
            ("X-Rulemesh-Variation" = String, description = "language cfdg only: the variation code the design was drawn with (`ABC`; Context Free's -v), which the `variation` parameter takes back"),
            ("X-Rulemesh-Primitives" = u64, description = "Primitive instances"),
            ("X-Rulemesh-Triangles" = u64, description = "Triangles"),
            ("X-Rulemesh-Truncated" = bool, description = "Whether a limit cut the model short"),
            ("X-Print-Volume-Mm3" = String, description = "print=true (STL or 3MF): enclosed volume in mm³, three decimals"),
            ("X-Print-Surface-Area-Mm2" = String, description = "print=true: surface area in mm²"),
            ("X-Print-Bbox-Mm" = String, description = "print=true: bounding-box size x y z in mm"),
            ("X-Print-Shells" = u64, description = "print=true: connected shells (1 for one printable piece)"),
            ("X-Print-Watertight" = bool, description = "print=true: every edge has two oppositely wound faces"),
            ("Server-Timing" = String, description = "Where the time went: queue, each stage that ran (parse, eval, mesh, print, preview, export) and the cache lookup, in ms")
        )),
        (status = 304, description = "Not modified (If-None-Match matched)"),
        (status = 404, description = "Unknown grammar or extension", body = ErrorBody),
        (status = 400, description = "Malformed request, parse or evaluation error", body = ErrorBody),
        (status = 413, description = "Request body too large", body = ErrorBody),
        (status = 422, description = "A limit was exceeded", body = ErrorBody),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody),
        (status = 503, description = "Overloaded or shutting down (with Retry-After)", body = ErrorBody),
        (status = 504, description = "Deadline exceeded", body = ErrorBody)
    ))]
async fn model_get(
    State(st): State<Arc<AppState>>,
    Extension(caller): Extension<Caller>,
    Path(file): Path<String>,
    RawQuery(query): RawQuery,
    // The request itself, not a `HeaderMap` extractor: that one clones the
    // headers of every request (issue 33's profile).
    req: Request,
) -> Response {
    model_for(&st, &caller, &file, query.as_deref(), req.headers()).await
}

/// [`model_get`]'s work, given what its extractors took (also the direct
/// model route's, `super::direct`): `file` is the path's last segment,
/// percent-decoded, and `query` the raw query string.
pub(super) async fn model_for(st: &AppState, caller: &Caller, file: &str, query: Option<&str>, headers: &HeaderMap) -> Response {
    let result = async {
        // Every extension of the registry's formats (the first format that claims one).
        let known = || Format::extensions().join(", ");
        let Some((name, ext)) = file.rsplit_once('.') else {
            return Err(ServiceError::NotFound(format!("`{file}`: expected NAME.EXT, EXT one of {}", known())));
        };
        // Exactly as the published pattern spells them (lower case).
        let Some(format) = Format::from_extension_name(ext).filter(|f| f.info().extensions.contains(&ext)) else {
            return Err(ServiceError::NotFound(format!("`{file}`: unknown extension ({})", known())));
        };
        let builtin = library::find(name).ok_or_else(|| ServiceError::NotFound(format!("no built-in grammar `{name}`")))?;
        let pairs = query_pairs(query.unwrap_or(""));
        let body = super::request::query_body(builtin.source, builtin.language, ext, &pairs)?.with_phone_default(super::phone::is_phone(headers));
        let pinned = body.options.seed.is_some();
        let text = is_text(format);
        let print = body.options.print == Some(true);
        let plan = body.plan(&Limits::defaults_for(print).clamped_to(&caller.ceiling), wants_fresh(headers))?;
        let format = plan.request.format;
        let key = plan.key;
        let served = st.engine.serve(plan).await?;
        Ok((served, pinned, text, format, key))
    }
    .await;
    match result {
        Ok((served, pinned, text, format, key)) => {
            let cc = if pinned { CACHE_IMMUTABLE } else { CACHE_SHORT };
            // What the fast path (`service::fast`) needs to answer this again.
            let fill = super::fast::Fillable { key, model: served.model.clone(), format, route: MODELS_ROUTE };
            if etag_matches(headers, &served.model.etag) {
                let mut resp = StatusCode::NOT_MODIFIED.into_response();
                model_headers(resp.headers_mut(), &served, Some(cc));
                super::phone::vary(resp.headers_mut(), format);
                resp.extensions_mut().insert(served.timing);
                resp.extensions_mut().insert(fill);
                return resp;
            }
            st.metrics.bytes_out("http", format, served.model.bytes.len());
            let mut resp = model_response(&served, Some(cc), text);
            super::phone::vary(resp.headers_mut(), format);
            resp.extensions_mut().insert(fill);
            resp
        }
        Err(e) => e.into_response(),
    }
}

/// Decodes `a=b&c=d` (percent-encoding and `+`) into pairs, as axum's
/// `Query` extractor would (serde_urlencoded reads with the same
/// `form_urlencoded::parse`), without its detour through a new `Uri` and
/// serde: this runs on every model GET. Decoding cannot fail: bytes that
/// are not UTF-8 after percent-decoding become U+FFFD, as with `Query`.
fn query_pairs(query: &str) -> Vec<(String, String)> {
    form_urlencoded::parse(query.as_bytes()).map(|(k, v)| (k.into_owned(), v.into_owned())).collect()
}

/// `GET /v1/grammars`.
#[utoipa::path(get, path = "/v1/grammars", tag = "grammars",
    responses(
        (status = 200, description = "Every built-in grammar", body = GrammarList),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody)
    ))]
async fn grammars_list() -> Json<GrammarList> {
    Json(GrammarList { grammars: library::all().map(|b| b.info()).collect() })
}

/// The body of `GET /v1/grammars`.
#[derive(Debug, Serialize, ToSchema)]
pub struct GrammarList {
    /// Every built-in grammar.
    pub grammars: Vec<GrammarInfo>,
}

/// `GET /v1/grammars/{name}`: the source as text.
#[utoipa::path(get, path = "/v1/grammars/{name}", tag = "grammars",
    params(("name" = String, Path, description = "A built-in grammar's name (optionally with .mdg)")),
    responses(
        (status = 200, description = "The grammar's source", content_type = "text/plain", body = String),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 404, description = "No such grammar", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody)
    ))]
async fn grammar_source(Path(name): Path<String>) -> Response {
    match library::find_route_name(&name) {
        Ok(b) => ([(header::CONTENT_TYPE, "text/plain; charset=utf-8")], b.source).into_response(),
        Err(e) => e.into_response(),
    }
}

/// The body of `POST /v1/check`.
#[derive(Debug, Serialize, ToSchema)]
pub struct CheckReport {
    /// True when the source parses.
    pub ok: bool,
    /// The language it was read as, when known.
    #[schema(value_type = Option<String>)]
    pub language: Option<&'static str>,
    /// Errors and warnings with line and column.
    #[schema(value_type = Vec<DiagnosticSchema>)]
    pub diagnostics: Vec<Diagnostic>,
}

/// The shape of a [`Diagnostic`] in JSON (for the OpenAPI document).
#[derive(Debug, Serialize, ToSchema)]
#[schema(as = Diagnostic)]
pub(crate) struct DiagnosticSchema {
    /// `error` or `warning`.
    pub severity: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column, in characters.
    pub column: u32,
    /// A human message.
    pub message: String,
}

/// Parses without evaluating; shared with gRPC.
pub fn check(body: CheckBody, ceiling: &Limits) -> Result<CheckReport, ServiceError> {
    let language = super::request::parse_language(body.language.as_deref())?;
    let source = crate::cache::normalize_source(body.source.as_bytes());
    let limits = Limits::default().clamped_to(ceiling);
    let files = super::request::decode_files(body.files)?;
    match crate::pipeline::check_source_with(&source, &files, language, &limits) {
        Ok((lang, warnings)) => Ok(CheckReport { ok: true, language: Some(lang.name()), diagnostics: warnings }),
        Err(crate::RenderError::Parse(p)) => {
            let lang = language.or_else(|| crate::lang::Language::detect(&source)).map(|l| l.name());
            let ok = !p.diagnostics.iter().any(|d| d.severity == Severity::Error);
            Ok(CheckReport { ok, language: lang, diagnostics: p.diagnostics })
        }
        Err(e) => Err(e.into()),
    }
}

/// `POST /v1/check`.
#[utoipa::path(post, path = "/v1/check", tag = "grammars",
    request_body = CheckBody,
    responses(
        (status = 200, description = "Diagnostics with line and column (no evaluation)", body = CheckReport),
        (status = 400, description = "Malformed request", body = ErrorBody),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 413, description = "Request body too large", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody)
    ))]
async fn check_post(State(st): State<Arc<AppState>>, Extension(caller): Extension<Caller>, body: Result<Bytes, BytesRejection>) -> Response {
    let result = body_bytes(body, st.config.body_limit).and_then(|b| from_json::<CheckBody>(&b)).and_then(|b| check(b, &caller.ceiling));
    match result {
        Ok(report) => Json(report).into_response(),
        Err(e) => e.into_response(),
    }
}

/// `GET /healthz`: 200 while the process runs.
#[utoipa::path(get, path = "/healthz", tag = "meta",
    responses((status = 200, description = "Alive", content_type = "text/plain", body = String)))]
async fn healthz() -> &'static str {
    "ok\n"
}

/// `GET /readyz`: 200 while accepting work, 503 once shutting down.
#[utoipa::path(get, path = "/readyz", tag = "meta",
    responses(
        (status = 200, description = "Accepting work", content_type = "text/plain", body = String),
        (status = 503, description = "Shutting down", body = ErrorBody)
    ))]
async fn readyz(State(st): State<Arc<AppState>>) -> Response {
    if st.is_ready() {
        "ready\n".into_response()
    } else {
        ServiceError::ShuttingDown.into_response()
    }
}

/// `GET /metrics`.
#[utoipa::path(get, path = "/metrics", tag = "meta",
    responses((status = 200, description = "Prometheus text exposition", content_type = "text/plain", body = String)))]
async fn metrics(State(st): State<Arc<AppState>>, headers: HeaderMap) -> Response {
    let om = wants_openmetrics(headers.get(header::ACCEPT).and_then(|v| v.to_str().ok()));
    ([(header::CONTENT_TYPE, if om { OPENMETRICS } else { PROMETHEUS_TEXT })], st.metrics.render_text(om)).into_response()
}

#[cfg(test)]
mod tests {
    /// `query_pairs` reads what axum's `Query` extractor read before it
    /// (the oracle here): percent-escapes, `+`, empty and repeated keys,
    /// and bytes that are not UTF-8.
    #[test]
    fn query_pairs_read_as_axum_query_does() {
        for query in ["", "seed=7", "seed=7&detail=4&seed=8", "p.name=a+b%20c", "a&=b&c=&&d=%FF%FE", "x=%zz%4", "%E2%9C%93=%e2%9c%93"] {
            let uri: axum::http::Uri = format!("/?{query}").parse().expect("a valid URI");
            let axum::extract::Query(oracle) = axum::extract::Query::<Vec<(String, String)>>::try_from_uri(&uri).expect("axum reads it");
            assert_eq!(super::query_pairs(query), oracle, "{query}");
        }
    }
}
