//! One error type for the service, mapped to an HTTP status with a JSON body
//! and to a gRPC status with the same JSON as details.

use crate::core::{Limit, LimitExceeded, ParseError};
use crate::export::ExportError;
use crate::model::EvalError;
use crate::RenderError;
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use crate::core::Diagnostic;
use serde::Serialize;
use serde_json::Value;
use utoipa::ToSchema;

/// Every error response: `{"error": {...}}`.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ErrorBody {
    /// What went wrong.
    pub error: ErrorDetail,
}

/// The fields of an error response.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ErrorDetail {
    /// A stable machine-readable code (`bad_request`, `parse_error`, `limit_exceeded`, ...).
    pub code: &'static str,
    /// A human message.
    pub message: String,
    /// 1-based line of a parse or evaluation error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<u32>,
    /// 1-based column of a parse or evaluation error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub column: Option<u32>,
    /// Every parse diagnostic.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<Vec<super::http::DiagnosticSchema>>)]
    pub diagnostics: Option<Vec<Diagnostic>>,
    /// The limit that was exceeded.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub limit: Option<&'static str>,
    /// The limit's configured value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub configured: Option<u64>,
    /// How far the render got when the limit stopped it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reached: Option<u64>,
    /// Seconds to wait before retrying (also the `Retry-After` header).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub retry_after: Option<u64>,
}

/// Why a service request failed.
#[derive(Debug, Clone, thiserror::Error)]
pub enum ServiceError {
    /// The request is malformed (bad JSON, unknown field or value).
    #[error("{0}")]
    BadRequest(String),
    /// The source does not parse.
    #[error(transparent)]
    Parse(ParseError),
    /// Evaluation failed for a reason in the source or the parameters.
    #[error(transparent)]
    Eval(EvalError),
    /// A limit ran out.
    #[error(transparent)]
    Limit(LimitExceeded),
    /// The model cannot be made as asked although the request is well formed:
    /// nothing in it can be printed, or it is larger than the output format
    /// holds (`code` says which: `unprintable`, `output_too_large`).
    #[error("{message}")]
    Unprocessable {
        /// The stable code.
        code: &'static str,
        /// What is wrong.
        message: String,
    },
    /// No such grammar or route.
    #[error("not found: {0}")]
    NotFound(String),
    /// The request body is larger than the server accepts.
    #[error("request body larger than {limit} bytes")]
    PayloadTooLarge {
        /// The body limit in bytes.
        limit: usize,
    },
    /// A batch with more members than a batch may have (its `seeds`, or
    /// the product of its `sweep`'s lists): too large to take, as a body
    /// over the byte limit is.
    #[error("a batch of {members} members is over the cap of {cap}")]
    TooManyMembers {
        /// Members asked for.
        members: usize,
        /// The cap.
        cap: usize,
    },
    /// Too many renders running and waiting; try again later.
    #[error("overloaded: {running} renders running and {waiting} waiting; retry after {retry_after_secs} s")]
    Overloaded {
        /// Renders running.
        running: usize,
        /// Renders waiting.
        waiting: usize,
        /// Suggested wait in seconds.
        retry_after_secs: u64,
    },
    /// The process is too close to its memory ceiling (`--memory-ceiling`)
    /// for one more render's memory budget, and no render in flight gave
    /// memory back while this one waited: retry, here later or on another
    /// worker. The guard behind each render's budget (`memory`), so that
    /// no sizing mistake reaches the kernel's OOM killer.
    #[error("memory_pressure: the process holds {} MiB of its {} MiB memory ceiling, too little room for a render with a {} MiB memory budget; retry after {retry_after_secs} s", mib(*resident), mib(*ceiling), mib(*budget))]
    MemoryPressure {
        /// Resident bytes when the render gave up waiting.
        resident: u64,
        /// The memory ceiling in bytes.
        ceiling: u64,
        /// The render's memory budget in bytes.
        budget: u64,
        /// Suggested wait in seconds.
        retry_after_secs: u64,
    },
    /// The request waited for a render slot (or a print slot) longer than
    /// the queue timeout; it never started. HTTP 503 with `Retry-After`,
    /// gRPC `UNAVAILABLE`.
    #[error("no render slot within the {ms} ms queue timeout; retry after 1 s")]
    QueueTimeout {
        /// The deadline in milliseconds.
        ms: u64,
    },
    /// The server is shutting down.
    #[error("shutting down")]
    ShuttingDown,
    /// API keys are configured and the request presents none that is known.
    #[error("a valid API key is required (Authorization: Bearer KEY, or X-Api-Key: KEY)")]
    Unauthorized,
    /// The caller's key is over its rate or its concurrency share.
    #[error("rate limited: {reason}; retry after {retry_after_secs} s")]
    RateLimited {
        /// Which allowance ran out.
        reason: String,
        /// Seconds until the request would be let in.
        retry_after_secs: u64,
    },
    /// The operator turned off `#javascript` EisenScript in the service.
    #[error("this server does not run #javascript EisenScript scripts (allow_javascript is off)")]
    JavaScriptDisabled,
    /// A failure inside the server.
    #[error("internal error: {0}")]
    Internal(String),
}

/// Bytes in whole MiB, rounded up (so a ceiling is never understated).
fn mib(bytes: u64) -> u64 {
    bytes.div_ceil(1024 * 1024)
}

impl From<RenderError> for ServiceError {
    fn from(e: RenderError) -> Self {
        match e {
            RenderError::BadRequest(m) => ServiceError::BadRequest(m),
            RenderError::Parse(p) => ServiceError::Parse(p),
            RenderError::Limit(l) => ServiceError::Limit(l),
            RenderError::Eval(e) => ServiceError::Eval(e),
            // A size or profile out of range is a bad parameter; a model with nothing to print is unprocessable.
            RenderError::Unprintable(p) if p.is_bad_option() => ServiceError::BadRequest(format!("print: {p}")),
            e @ RenderError::Unprintable(_) => ServiceError::Unprocessable { code: "unprintable", message: e.to_string() },
            e @ RenderError::TooLarge { .. } => ServiceError::Unprocessable { code: "output_too_large", message: e.to_string() },
            // Options the format cannot honour for this request (the scene
            // format for a language that makes meshes, found by the
            // `http_request` fuzz target as a 500) are the client's error.
            RenderError::Export(x @ ExportError::InvalidOptions { .. }) => ServiceError::BadRequest(x.to_string()),
            RenderError::Export(ExportError::Limit(l)) => ServiceError::Limit(l),
            RenderError::Export(x) => ServiceError::Internal(x.to_string()),
            e @ RenderError::Print(_) => ServiceError::Internal(e.to_string()),
        }
    }
}

impl ServiceError {
    /// The HTTP status.
    pub(crate) fn http_status(&self) -> StatusCode {
        match self {
            ServiceError::BadRequest(_) | ServiceError::Parse(_) | ServiceError::Eval(_) => StatusCode::BAD_REQUEST,
            ServiceError::Limit(l) if l.limit == Limit::Deadline => StatusCode::GATEWAY_TIMEOUT,
            ServiceError::Limit(_) | ServiceError::Unprocessable { .. } => StatusCode::UNPROCESSABLE_ENTITY,
            ServiceError::NotFound(_) => StatusCode::NOT_FOUND,
            ServiceError::PayloadTooLarge { .. } | ServiceError::TooManyMembers { .. } => StatusCode::PAYLOAD_TOO_LARGE,
            // A request that waited out the queue never started: like a shed
            // one, the server is busy and a retry may succeed (503 with
            // Retry-After), not a render that ran out of time (504).
            ServiceError::Overloaded { .. } | ServiceError::ShuttingDown | ServiceError::MemoryPressure { .. } | ServiceError::QueueTimeout { .. } => {
                StatusCode::SERVICE_UNAVAILABLE
            }
            ServiceError::Unauthorized => StatusCode::UNAUTHORIZED,
            ServiceError::RateLimited { .. } => StatusCode::TOO_MANY_REQUESTS,
            ServiceError::JavaScriptDisabled => StatusCode::FORBIDDEN,
            ServiceError::Internal(_) => StatusCode::INTERNAL_SERVER_ERROR,
        }
    }

    /// The gRPC status code.
    pub(crate) fn grpc_code(&self) -> tonic::Code {
        match self {
            ServiceError::BadRequest(_) | ServiceError::Parse(_) | ServiceError::Eval(_) => tonic::Code::InvalidArgument,
            ServiceError::Limit(l) if l.limit == Limit::Deadline => tonic::Code::DeadlineExceeded,
            ServiceError::Limit(_) => tonic::Code::ResourceExhausted,
            ServiceError::Unprocessable { .. } => tonic::Code::FailedPrecondition,
            ServiceError::NotFound(_) => tonic::Code::NotFound,
            ServiceError::PayloadTooLarge { .. } | ServiceError::TooManyMembers { .. } | ServiceError::MemoryPressure { .. } => tonic::Code::ResourceExhausted,
            ServiceError::Overloaded { .. } | ServiceError::ShuttingDown | ServiceError::QueueTimeout { .. } => tonic::Code::Unavailable,
            ServiceError::Unauthorized => tonic::Code::Unauthenticated,
            ServiceError::RateLimited { .. } => tonic::Code::ResourceExhausted,
            ServiceError::JavaScriptDisabled => tonic::Code::PermissionDenied,
            ServiceError::Internal(_) => tonic::Code::Internal,
        }
    }

    /// A stable machine-readable code.
    pub fn code(&self) -> &'static str {
        match self {
            ServiceError::BadRequest(_) => "bad_request",
            ServiceError::Parse(_) => "parse_error",
            ServiceError::Eval(_) => "eval_error",
            ServiceError::Limit(l) if l.limit == Limit::Deadline => "deadline_exceeded",
            ServiceError::Limit(_) => "limit_exceeded",
            ServiceError::Unprocessable { code, .. } => code,
            ServiceError::NotFound(_) => "not_found",
            ServiceError::PayloadTooLarge { .. } => "payload_too_large",
            ServiceError::TooManyMembers { .. } => "too_many_members",
            ServiceError::Overloaded { .. } => "overloaded",
            ServiceError::MemoryPressure { .. } => "memory_pressure",
            ServiceError::QueueTimeout { .. } => "queue_timeout",
            ServiceError::ShuttingDown => "shutting_down",
            ServiceError::Unauthorized => "unauthorized",
            ServiceError::RateLimited { .. } => "rate_limited",
            ServiceError::JavaScriptDisabled => "javascript_disabled",
            ServiceError::Internal(_) => "internal",
        }
    }

    /// Seconds a client should wait before retrying, for overload errors.
    pub fn retry_after(&self) -> Option<u64> {
        match self {
            ServiceError::Overloaded { retry_after_secs, .. } | ServiceError::RateLimited { retry_after_secs, .. } | ServiceError::MemoryPressure { retry_after_secs, .. } => {
                Some(*retry_after_secs)
            }
            ServiceError::ShuttingDown | ServiceError::QueueTimeout { .. } => Some(1),
            _ => None,
        }
    }

    /// The typed error body.
    pub fn detail(&self) -> ErrorBody {
        let span = match self {
            ServiceError::Parse(p) => p.diagnostics.first().map(|d| d.span),
            ServiceError::Eval(ev) => ev.span(),
            _ => None,
        };
        let limit = match self {
            ServiceError::Limit(l) => Some(l),
            _ => None,
        };
        ErrorBody {
            error: ErrorDetail {
                code: self.code(),
                message: self.to_string(),
                line: span.map(|s| s.line),
                column: span.map(|s| s.column),
                diagnostics: match self {
                    ServiceError::Parse(p) => Some(p.diagnostics.clone()),
                    _ => None,
                },
                limit: match self {
                    ServiceError::MemoryPressure { .. } => Some("memory_ceiling"),
                    _ => limit.map(|l| l.limit.name()),
                },
                configured: match self {
                    ServiceError::MemoryPressure { ceiling, .. } => Some(*ceiling),
                    _ => limit.map(|l| l.configured),
                },
                reached: match self {
                    ServiceError::MemoryPressure { resident, budget, .. } => Some(resident.saturating_add(*budget)),
                    _ => limit.map(|l| l.reached),
                },
                retry_after: self.retry_after(),
            },
        }
    }

    /// The JSON body `{"error": {"code", "message", "line"?, "column"?, "limit"?, "configured"?, "reached"?}}`.
    pub fn body(&self) -> Value {
        serde_json::to_value(self.detail()).unwrap_or(Value::Null)
    }

    /// The gRPC status: the message, with the JSON body as details and the
    /// limit fields as metadata.
    pub(crate) fn to_status(&self) -> tonic::Status {
        let body = self.body();
        let mut status = tonic::Status::with_details(self.grpc_code(), self.to_string(), body.to_string().into_bytes().into());
        let md = status.metadata_mut();
        md.insert("x-rulemesh-error", tonic::metadata::MetadataValue::from_static(self.code()));
        match self {
            ServiceError::Limit(l) => {
                md.insert("x-rulemesh-limit", tonic::metadata::MetadataValue::from_static(l.limit.name()));
            }
            ServiceError::MemoryPressure { .. } => {
                md.insert("x-rulemesh-limit", tonic::metadata::MetadataValue::from_static("memory_ceiling"));
            }
            _ => {}
        }
        if let Some(r) = self.retry_after() {
            md.insert("retry-after", tonic::metadata::MetadataValue::from(r));
        }
        status
    }
}

impl IntoResponse for ServiceError {
    fn into_response(self) -> Response {
        let mut resp = (self.http_status(), axum::Json(self.body())).into_response();
        if let Some(r) = self.retry_after() {
            resp.headers_mut().insert(header::RETRY_AFTER, HeaderValue::from(r));
        }
        resp.headers_mut().insert("x-rulemesh-error", HeaderValue::from_static(self.code()));
        if matches!(self, ServiceError::Unauthorized) {
            resp.headers_mut().insert(header::WWW_AUTHENTICATE, HeaderValue::from_static("Bearer realm=\"rulemesh\""));
        }
        resp
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::print::PrintError;
    use serde_json::json;

    #[test]
    fn request_faults_are_typed_and_never_500() {
        let too_large: ServiceError = RenderError::TooLarge { format: "glb", detail: "buffer over 4 GiB".into() }.into();
        assert_eq!((too_large.http_status(), too_large.code(), too_large.grpc_code()), (StatusCode::UNPROCESSABLE_ENTITY, "output_too_large", tonic::Code::FailedPrecondition));
        assert!(too_large.to_string().contains("buffer over 4 GiB"), "{too_large}");
        let unprintable: ServiceError = RenderError::Unprintable(PrintError::NothingPrintable("only open surfaces".into())).into();
        assert_eq!((unprintable.http_status(), unprintable.code()), (StatusCode::UNPROCESSABLE_ENTITY, "unprintable"));
        assert!(unprintable.to_string().starts_with("print: "), "{unprintable}");
        // Pieces that do not touch are the model's fault, named by their finding's code.
        let apart: ServiceError = RenderError::from(PrintError::SeparatePieces { shells: 3, gap_mm: 0.4 }).into();
        assert_eq!((apart.http_status(), apart.code()), (StatusCode::UNPROCESSABLE_ENTITY, "unprintable"));
        assert!(apart.to_string().contains("separate_shells") && apart.to_string().contains("3 separate pieces"), "{apart}");
        let size: ServiceError = RenderError::Unprintable(PrintError::BadSize(0.0)).into();
        assert_eq!((size.http_status(), size.code()), (StatusCode::BAD_REQUEST, "bad_request"));
        let pressure = ServiceError::MemoryPressure { resident: 1000 << 20, ceiling: 1536 << 20, budget: 1 << 29, retry_after_secs: 1 };
        assert_eq!((pressure.http_status(), pressure.code(), pressure.grpc_code()), (StatusCode::SERVICE_UNAVAILABLE, "memory_pressure", tonic::Code::ResourceExhausted));
        assert_eq!(pressure.to_string(), "memory_pressure: the process holds 1000 MiB of its 1536 MiB memory ceiling, too little room for a render with a 512 MiB memory budget; retry after 1 s");
        let body = pressure.body();
        assert_eq!((&body["error"]["limit"], &body["error"]["configured"], &body["error"]["reached"], &body["error"]["retry_after"]), (&json!("memory_ceiling"), &json!(1536u64 << 20), &json!(1512u64 << 20), &json!(1)));
        let wall: ServiceError = RenderError::Unprintable(PrintError::BadMinWall(0.0)).into();
        assert_eq!((wall.http_status(), wall.code(), wall.grpc_code()), (StatusCode::BAD_REQUEST, "bad_request", tonic::Code::InvalidArgument));
    }
}
