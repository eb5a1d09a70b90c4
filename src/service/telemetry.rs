//! The process's log (and, when configured, trace) output: one subscriber
//! for `rulemesh serve`, logging to stderr as text or as one JSON object per
//! line, the format log shippers read without a parser of their own.

use tracing_subscriber::filter::LevelFilter;
use tracing_subscriber::layer::SubscriberExt as _;
use tracing_subscriber::util::SubscriberInitExt as _;
use tracing_subscriber::Layer as _;

/// How log lines are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum LogFormat {
    /// Human-readable lines (coloured on a terminal).
    #[default]
    Text,
    /// One JSON object per line: `timestamp`, `level`, `fields` (the
    /// message and the event's fields, e.g. a request's `server_timing`
    /// and `parse_ms`), `span` and `spans` (the request's id, route,
    /// language, cache key and result).
    Json,
}

/// Why telemetry could not be set up.
#[derive(Debug, thiserror::Error)]
pub enum TelemetryError {
    /// A global subscriber was already installed.
    #[error("cannot install the log subscriber: {0}")]
    Init(String),
}

/// Installs the global subscriber: `level` and above, in `format`, to stderr.
pub fn init(level: LevelFilter, format: LogFormat) -> Result<(), TelemetryError> {
    use std::io::IsTerminal;
    let fmt = tracing_subscriber::fmt::layer().with_target(false).with_writer(std::io::stderr);
    let fmt = match format {
        LogFormat::Text => fmt.with_ansi(std::io::stderr().is_terminal()).boxed(),
        LogFormat::Json => fmt.json().with_current_span(true).with_span_list(true).with_ansi(false).boxed(),
    };
    tracing_subscriber::registry().with(fmt.with_filter(level)).try_init().map_err(|e| TelemetryError::Init(e.to_string()))
}
