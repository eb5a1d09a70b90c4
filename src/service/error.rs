//! One error type for the service, mapped to an HTTP status with a JSON body
//! and to a gRPC status with the same JSON as details.

use crate::eval::{EvalError, Limit, LimitExceeded};
use crate::lang::ParseError;
use crate::RenderError;
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde_json::{json, Value};

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
    /// No such grammar or route.
    #[error("not found: {0}")]
    NotFound(String),
    /// The request body is larger than the server accepts.
    #[error("request body larger than {limit} bytes")]
    PayloadTooLarge {
        /// The body limit in bytes.
        limit: usize,
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
    /// The request waited for a render slot longer than its deadline.
    #[error("no render slot within the {ms} ms request deadline")]
    QueueTimeout {
        /// The deadline in milliseconds.
        ms: u64,
    },
    /// The server is shutting down.
    #[error("shutting down")]
    ShuttingDown,
    /// A failure inside the server.
    #[error("internal error: {0}")]
    Internal(String),
}

impl From<RenderError> for ServiceError {
    fn from(e: RenderError) -> Self {
        match e {
            RenderError::BadRequest(m) => ServiceError::BadRequest(m),
            RenderError::Parse(p) => ServiceError::Parse(p),
            RenderError::Limit(l) => ServiceError::Limit(l),
            RenderError::Eval(e) => ServiceError::Eval(e),
            RenderError::Export(x) => ServiceError::Internal(x.to_string()),
        }
    }
}

impl ServiceError {
    /// The HTTP status.
    pub fn http_status(&self) -> StatusCode {
        match self {
            ServiceError::BadRequest(_) | ServiceError::Parse(_) | ServiceError::Eval(_) => StatusCode::BAD_REQUEST,
            ServiceError::Limit(l) if l.limit == Limit::Deadline => StatusCode::GATEWAY_TIMEOUT,
            ServiceError::Limit(_) => StatusCode::UNPROCESSABLE_ENTITY,
            ServiceError::NotFound(_) => StatusCode::NOT_FOUND,
            ServiceError::PayloadTooLarge { .. } => StatusCode::PAYLOAD_TOO_LARGE,
            ServiceError::Overloaded { .. } | ServiceError::ShuttingDown => StatusCode::SERVICE_UNAVAILABLE,
            ServiceError::QueueTimeout { .. } => StatusCode::GATEWAY_TIMEOUT,
            ServiceError::Internal(_) => StatusCode::INTERNAL_SERVER_ERROR,
        }
    }

    /// The gRPC status code.
    pub fn grpc_code(&self) -> tonic::Code {
        match self {
            ServiceError::BadRequest(_) | ServiceError::Parse(_) | ServiceError::Eval(_) => tonic::Code::InvalidArgument,
            ServiceError::Limit(l) if l.limit == Limit::Deadline => tonic::Code::DeadlineExceeded,
            ServiceError::Limit(_) => tonic::Code::ResourceExhausted,
            ServiceError::NotFound(_) => tonic::Code::NotFound,
            ServiceError::PayloadTooLarge { .. } => tonic::Code::ResourceExhausted,
            ServiceError::Overloaded { .. } | ServiceError::ShuttingDown => tonic::Code::Unavailable,
            ServiceError::QueueTimeout { .. } => tonic::Code::DeadlineExceeded,
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
            ServiceError::NotFound(_) => "not_found",
            ServiceError::PayloadTooLarge { .. } => "payload_too_large",
            ServiceError::Overloaded { .. } => "overloaded",
            ServiceError::QueueTimeout { .. } => "queue_timeout",
            ServiceError::ShuttingDown => "shutting_down",
            ServiceError::Internal(_) => "internal",
        }
    }

    /// Seconds a client should wait before retrying, for overload errors.
    pub fn retry_after(&self) -> Option<u64> {
        match self {
            ServiceError::Overloaded { retry_after_secs, .. } => Some(*retry_after_secs),
            ServiceError::ShuttingDown => Some(1),
            _ => None,
        }
    }

    /// The JSON body `{"error": {"code", "message", "line"?, "column"?, "limit"?, "configured"?, "reached"?}}`.
    pub fn body(&self) -> Value {
        let mut e = json!({ "code": self.code(), "message": self.to_string() });
        let span = match self {
            ServiceError::Parse(p) => p.diagnostics.first().map(|d| d.span),
            ServiceError::Eval(ev) => ev.span(),
            _ => None,
        };
        if let Some(s) = span {
            e["line"] = s.line.into();
            e["column"] = s.column.into();
        }
        if let ServiceError::Parse(p) = self {
            e["diagnostics"] = serde_json::to_value(&p.diagnostics).unwrap_or(Value::Null);
        }
        if let ServiceError::Limit(l) = self {
            e["limit"] = l.limit.name().into();
            e["configured"] = l.configured.into();
            e["reached"] = l.reached.into();
        }
        if let Some(r) = self.retry_after() {
            e["retry_after"] = r.into();
        }
        json!({ "error": e })
    }

    /// The gRPC status: the message, with the JSON body as details and the
    /// limit fields as metadata.
    pub fn to_status(&self) -> tonic::Status {
        let body = self.body();
        let mut status = tonic::Status::with_details(self.grpc_code(), self.to_string(), body.to_string().into_bytes().into());
        let md = status.metadata_mut();
        md.insert("x-rulemesh-error", tonic::metadata::MetadataValue::from_static(self.code()));
        if let ServiceError::Limit(l) = self {
            md.insert("x-rulemesh-limit", tonic::metadata::MetadataValue::from_static(l.limit.name()));
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
        resp
    }
}
