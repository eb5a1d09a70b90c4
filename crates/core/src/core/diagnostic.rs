//! Positions and messages about source text, shared by every parser and
//! evaluator: a [`Span`] names a place, a [`Diagnostic`] says something
//! about it, and a [`ParseError`] is a failed parse with its diagnostics.

use serde::Serialize;

/// A position in the source: 1-based line and column (columns count characters).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
pub struct Span {
    /// 1-based line.
    pub line: u32,
    /// 1-based column, in characters.
    pub column: u32,
}

impl Span {
    /// Makes a span from a line and column.
    pub fn new(line: u32, column: u32) -> Span {
        Span { line, column }
    }
}

/// How serious a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// The source cannot be evaluated.
    Error,
    /// The source runs, but something in it is ignored or suspicious.
    Warning,
}

/// A message about the source at a position, printed as `file:line:col: message`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// Where.
    #[serde(flatten)]
    pub span: Span,
    /// A human message.
    pub message: String,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { severity: Severity::Error, span, message: message.into() }
    }

    /// A warning at `span`.
    pub fn warning(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { severity: Severity::Warning, span, message: message.into() }
    }
}

impl std::fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kind = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        write!(f, "{}:{}: {}: {}", self.span.line, self.span.column, kind, self.message)
    }
}

/// A failed parse: at least one error diagnostic (warnings may follow).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}", .diagnostics.first().map(|d| d.to_string()).unwrap_or_default())]
pub struct ParseError {
    /// All diagnostics, errors first.
    pub diagnostics: Vec<Diagnostic>,
}

impl ParseError {
    /// A parse error with a single diagnostic.
    pub fn single(span: Span, message: impl Into<String>) -> ParseError {
        ParseError { diagnostics: vec![Diagnostic::error(span, message)] }
    }
}
