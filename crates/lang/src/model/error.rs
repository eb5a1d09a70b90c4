//! Why building a model failed: the one error type every evaluator (MDG
//! rules, the Structure Synth builder and its JavaScript sandbox, the
//! L-system derivation and turtle) reports, so the pipeline maps one type.

use crate::core::budget::LimitExceeded;
use crate::core::diagnostic::Span;

/// Why an evaluation failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EvalError {
    /// A budget limit ran out (and the request asked for an error, not truncation).
    #[error(transparent)]
    Limit(#[from] LimitExceeded),
    /// An argument evaluated to NaN or an infinity (e.g. division by zero).
    #[error("{}:{}: {what} is not a finite number ({value})", span.line, span.column)]
    NonFinite {
        /// Where the argument is written.
        span: Span,
        /// Which argument.
        what: String,
        /// The value computed.
        value: String,
    },
    /// An iterator count or divisor that is not a usable number.
    #[error("{}:{}: iteration count must be a whole number ≥ 0 and divisor > 0, got {value}", span.line, span.column)]
    BadIteration {
        /// Where the iterator is written.
        span: Span,
        /// The value computed.
        value: String,
    },
    /// A request parameter the grammar does not declare.
    #[error("unknown parameter `{name}` (declared: {declared})")]
    UnknownParam {
        /// The name given.
        name: String,
        /// The names the grammar declares, comma-separated.
        declared: String,
    },
    /// A request parameter with a bad value.
    #[error("parameter `{name}`: {message}")]
    BadParam {
        /// The parameter.
        name: String,
        /// What is wrong.
        message: String,
    },
    /// A path, profile or camera rule is needed inside its own evaluation
    /// (it animates or sweeps with itself, directly or through other path
    /// rules), or such rules nest deeper than the evaluator allows. Found by
    /// the `render_mdg` fuzz target (docs/reliability.md).
    #[error("path rule `{name}` is used inside its own evaluation (a cycle of path, profile or camera rules), or path rules nest more than {nesting} deep")]
    PathCycle {
        /// The rule whose evaluation would recurse.
        name: String,
        /// The nesting bound.
        nesting: usize,
    },
    /// A Structure Synth JavaScript script failed: a syntax error or an
    /// uncaught exception (with its line when QuickJS reports one).
    #[error("JavaScript: {message}")]
    Script {
        /// QuickJS's message.
        message: String,
    },
    /// The request's `frame` does not name a picture: the source is not a
    /// JavaScript movie, or the movie saves fewer pictures.
    #[error("frame: {message}")]
    Frame {
        /// What is wrong, with the number of pictures the script saves.
        message: String,
    },
    /// `Builder.load` could not load the file it names (refused path, missing
    /// file, or no such library grammar in the service).
    #[error("Builder.load(\"{name}\"): {reason}")]
    Load {
        /// The name the script gave.
        name: String,
        /// Why it was refused.
        reason: String,
    },
    /// A `mesh` declaration's modifiers could not be applied.
    #[error("{}:{}: mesh `{name}`: {message}", span.line, span.column)]
    Mesh {
        /// Where the mesh is declared.
        span: Span,
        /// The mesh's name.
        name: String,
        /// What went wrong.
        message: String,
    },
}

impl EvalError {
    /// The source position, when the error comes from a place in the source.
    pub fn span(&self) -> Option<Span> {
        match self {
            EvalError::NonFinite { span, .. } | EvalError::BadIteration { span, .. } | EvalError::Mesh { span, .. } => Some(*span),
            _ => None,
        }
    }
}
