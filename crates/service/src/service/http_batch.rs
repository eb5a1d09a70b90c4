//! `POST /v1/render/batch` (issue 20): many variations of one request in one
//! call, answered as NDJSON, one line per member as it finishes, in request
//! order, the model's bytes in base64. [`super::batch`] expands and runs the
//! members; this module reads the JSON body and writes the lines.

use super::batch::{self, MemberOutcome};
use super::error::{ErrorBody, ErrorDetail};
use super::http::{body_bytes, wants_fresh, Caller, Streamed};
use super::request::{ParamValueSchema, RenderBody, SeedSchema};
use super::AppState;
use crate::cache::CacheOutcome;
use crate::core::ParamValue;
use axum::body::{Body, Bytes};
use axum::extract::rejection::BytesRejection;
use axum::extract::State;
use axum::http::{header, HeaderMap, HeaderValue};
use axum::response::{IntoResponse, Response};
use axum::Extension;
use base64::Engine as _;
use futures_util::StreamExt;
use serde::Serialize;
use std::collections::BTreeMap;
use std::convert::Infallible;
use std::sync::Arc;
use utoipa::openapi::schema::Schema;
use utoipa::openapi::RefOr;
use utoipa::{PartialSchema, ToSchema};

/// The media type of the answer: one JSON document per line.
pub const NDJSON: &str = "application/x-ndjson";

/// The request body: a [`RenderBody`] (with `source` optional) and the
/// fields below. Its schema is built from [`RenderBody`]'s, so the two
/// cannot drift apart; the server reads it with [`batch::from_json_body`].
pub struct BatchBody;

/// The fields a batch adds to a render body (for the OpenAPI document).
#[derive(ToSchema)]
#[allow(dead_code)] // Only its schema is used; the body is read as JSON by `batch::from_json_body`.
struct BatchFields {
    /// A built-in grammar's name (`GET /v1/grammars`), instead of `source`.
    grammar: Option<String>,
    /// One member per seed, in this order (each a number or a decimal
    /// string, as `seed`); not together with `seed` or `sweep`.
    #[schema(value_type = Option<Vec<SeedSchema>>, min_items = 1, max_items = 256)]
    seeds: Option<Vec<u64>>,
    /// One member per combination of these parameters' values (the
    /// cartesian product, names in sorted order, the last varying fastest),
    /// each over `params`; at most 256 members.
    #[schema(value_type = Option<BTreeMap<String, Vec<ParamValueSchema>>>)]
    sweep: Option<BTreeMap<String, Vec<ParamValue>>>,
}

impl PartialSchema for BatchBody {
    fn schema() -> RefOr<Schema> {
        let mut schema = RenderBody::schema();
        if let (RefOr::T(Schema::Object(body)), RefOr::T(Schema::Object(fields))) = (&mut schema, BatchFields::schema()) {
            body.required.retain(|f| f != "source");
            body.properties.extend(fields.properties);
            body.description = Some("A render body (`source` or `grammar`) and `seeds` or `sweep`: the members of the batch.".into());
        }
        schema
    }
}

impl ToSchema for BatchBody {
    fn schemas(schemas: &mut Vec<(String, RefOr<Schema>)>) {
        <RenderBody as ToSchema>::schemas(schemas);
        <BatchFields as ToSchema>::schemas(schemas);
    }
}

/// Where a limit cut a member's model short.
#[derive(Debug, Serialize)]
struct TruncatedLine {
    limit: &'static str,
    configured: u64,
    reached: u64,
}

/// One line of the answer.
#[derive(Debug, Serialize)]
struct Line {
    index: usize,
    /// Decimal: the seed the model was made with, or for a failed member
    /// the seed it asked for (null when it asked for none).
    seed: Option<String>,
    params: BTreeMap<String, ParamValue>,
    #[serde(flatten)]
    outcome: LineOutcome,
}

#[derive(Debug, Serialize)]
#[serde(untagged)]
enum LineOutcome {
    Model {
        etag: String,
        cache: &'static str,
        content_type: &'static str,
        primitives: u64,
        triangles: u64,
        truncated: Option<TruncatedLine>,
        size: usize,
        bytes_base64: String,
    },
    Failed {
        error: ErrorDetail,
    },
}

/// The NDJSON line of one member, newline included.
fn line(outcome: &MemberOutcome, state: &AppState) -> Bytes {
    let MemberOutcome { member, result } = outcome;
    let params = member.params.iter().map(|(k, v)| (k.clone(), v.canonical())).collect();
    let (seed, outcome) = match result {
        Ok((served, format)) => {
            let m = &served.model;
            state.metrics.bytes_out("http", *format, m.bytes.len());
            let outcome = LineOutcome::Model {
                etag: m.etag.clone(),
                cache: if served.cache == CacheOutcome::Hit { "hit" } else { "miss" },
                content_type: m.content_type,
                primitives: m.primitives,
                triangles: m.triangles,
                truncated: m.truncated.map(|t| TruncatedLine { limit: t.limit.name(), configured: t.configured, reached: t.reached }),
                size: m.bytes.len(),
                bytes_base64: base64::engine::general_purpose::STANDARD.encode(&m.bytes),
            };
            (Some(m.seed), outcome)
        }
        Err(e) => (member.seed, LineOutcome::Failed { error: e.detail().error }),
    };
    let line = Line { index: member.index, seed: seed.map(|s| s.to_string()), params, outcome };
    let mut bytes = serde_json::to_vec(&line).unwrap_or_else(|e| {
        serde_json::json!({"index": member.index, "seed": line.seed, "error": {"code": "internal", "message": format!("cannot write this member's line: {e}")}}).to_string().into_bytes()
    });
    bytes.push(b'\n');
    Bytes::from(bytes)
}

/// `POST /v1/render/batch`.
#[utoipa::path(post, path = "/v1/render/batch", tag = "render",
    request_body = BatchBody,
    params(("Cache-Control" = Option<String>, Header, description = "`no-cache` renders every member afresh")),
    responses(
        (status = 200, description = "One JSON object per line (NDJSON), one per member, in request order, each sent as soon as it and those before it are done: \
            `{\"index\", \"seed\" (decimal string), \"params\", \"etag\", \"cache\" (hit or miss), \"content_type\", \"primitives\", \"triangles\", \"truncated\", \"size\", \"bytes_base64\"}`, \
            or for a member that failed alone (a limit, an evaluation error, shed by the concurrency limit) `{\"index\", \"seed\", \"params\", \"error\": {\"code\", \"message\", ...}}`",
            content_type = "application/x-ndjson", body = String),
        (status = 400, description = "Malformed request (also: no members)", body = ErrorBody),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 404, description = "No built-in grammar of that name", body = ErrorBody),
        (status = 413, description = "Request body too large, or more than 256 members (`too_many_members`)", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody)
    ))]
pub(super) async fn batch_post(State(st): State<Arc<AppState>>, Extension(caller): Extension<Caller>, headers: HeaderMap, body: Result<Bytes, BytesRejection>) -> Response {
    let batch = match body_bytes(body, st.config.body_limit).and_then(|b| batch::from_json_body(&b, &caller.ceiling, super::phone::is_phone(&headers))) {
        Ok(b) => b,
        Err(e) => return e.into_response(),
    };
    let state = st.clone();
    let lines = batch.run(st, caller.ceiling, wants_fresh(&headers), tracing::Span::current()).map(move |o| Ok::<_, Infallible>(line(&o, &state)));
    let mut resp = Response::new(Body::from_stream(lines));
    let h = resp.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static(NDJSON));
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    resp.extensions_mut().insert(Streamed);
    resp
}
