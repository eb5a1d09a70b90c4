//! The HTTP routes of parameter schemas: `GET /v1/grammars/{name}/schema`
//! for a library grammar and `POST /v1/schema` for a posted source (the
//! schemas themselves are built in [`super::schema`]).

use super::error::ErrorBody;
use super::http::Caller;
use super::library;
use super::request::{from_json, parse_language, CheckBody};
use super::schema::render_schema;
use super::AppState;
use super::ServiceError;
use crate::core::Limits;
use axum::body::Bytes;
use axum::extract::rejection::BytesRejection;
use axum::extract::{Path, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};
use axum::Extension;
use std::sync::Arc;

/// The media type of a JSON Schema document.
pub(crate) const SCHEMA_JSON: &str = "application/schema+json";

/// The schema of `source` as a JSON response, or the parse error (with line and column).
fn schema_response(title: &str, description: &str, source: &[u8], language: Option<crate::lang::Language>, ceiling: &Limits) -> Response {
    let limits = Limits::default().clamped_to(ceiling);
    match crate::pipeline::declared_params(source, language, &limits) {
        Ok((language, params)) => {
            let schema = render_schema(title, description, language, &params);
            ([(header::CONTENT_TYPE, SCHEMA_JSON)], schema.to_string()).into_response()
        }
        Err(e) => ServiceError::from(e).into_response(),
    }
}

/// `GET /v1/grammars/{name}/schema`.
#[utoipa::path(get, path = "/v1/grammars/{name}/schema", tag = "grammars",
    params(("name" = String, Path, description = "A built-in grammar's name (optionally with .mdg)")),
    responses(
        (status = 200, description = "A JSON Schema (2020-12) of render requests for the grammar: its parameters and the render options", content_type = "application/schema+json", body = Object),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 404, description = "No such grammar", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody)
    ))]
pub(crate) async fn grammar_schema(Extension(caller): Extension<Caller>, Path(name): Path<String>) -> Response {
    match library::find_route_name(&name) {
        Ok(b) => schema_response(b.name, &library::description(b.source), b.source.as_bytes(), Some(b.language), &caller.ceiling),
        Err(e) => e.into_response(),
    }
}

/// `POST /v1/schema`: the schema of a posted source (the body of `POST /v1/check`).
#[utoipa::path(post, path = "/v1/schema", tag = "grammars",
    request_body = CheckBody,
    responses(
        (status = 200, description = "A JSON Schema (2020-12) of render requests for the source: its parameters and the render options", content_type = "application/schema+json", body = Object),
        (status = 400, description = "Malformed request, or a source that does not parse (with line and column)", body = ErrorBody),
        (status = 401, description = "API keys are configured and none valid was presented", body = ErrorBody),
        (status = 413, description = "Request body too large", body = ErrorBody),
        (status = 422, description = "The source exceeds the source-size limit", body = ErrorBody),
        (status = 429, description = "The API key is over its rate or concurrency share (with Retry-After)", body = ErrorBody)
    ))]
pub(crate) async fn schema_post(State(st): State<Arc<AppState>>, Extension(caller): Extension<Caller>, body: Result<Bytes, BytesRejection>) -> Response {
    let body = match super::http::body_bytes(body, st.config.body_limit).and_then(|b| from_json::<CheckBody>(&b)) {
        Ok(b) => b,
        Err(e) => return e.into_response(),
    };
    let language = match parse_language(body.language.as_deref()) {
        Ok(l) => l,
        Err(e) => return e.into_response(),
    };
    let source = crate::cache::normalize_source(body.source.as_bytes());
    schema_response("posted source", "", &source, language, &caller.ceiling)
}
