//! Server configuration: command-line flags, each also read from a
//! `RULEMESH_*` environment variable, with defaults that need nothing else.

use crate::eval::Limits;
use std::net::SocketAddr;
use std::time::Duration;

/// `rulemesh serve` options.
#[derive(Debug, Clone, clap::Args)]
pub struct ServeConfig {
    /// HTTP listen address.
    #[arg(long, env = "RULEMESH_HTTP", default_value = "127.0.0.1:8080")]
    pub http: SocketAddr,
    /// gRPC listen address.
    #[arg(long, env = "RULEMESH_GRPC", default_value = "127.0.0.1:50051")]
    pub grpc: SocketAddr,
    /// Byte budget of the in-process model cache.
    #[arg(long, env = "RULEMESH_CACHE_BYTES", default_value_t = 256 * 1024 * 1024)]
    pub cache_bytes: u64,
    /// Renders running at once (0: one per core).
    #[arg(long, env = "RULEMESH_MAX_CONCURRENCY", default_value_t = 0)]
    pub max_concurrency: usize,
    /// Renders allowed to wait for a slot; more are shed with 503.
    #[arg(long, env = "RULEMESH_QUEUE", default_value_t = 64)]
    pub queue: usize,
    /// Largest accepted request body, in bytes.
    #[arg(long, env = "RULEMESH_BODY_LIMIT", default_value_t = 2 * 1024 * 1024)]
    pub body_limit: usize,
    /// Longest a request may wait for a render slot, in milliseconds.
    #[arg(long, env = "RULEMESH_QUEUE_TIMEOUT_MS", default_value_t = 30_000)]
    pub queue_timeout_ms: u64,
    /// Time in-flight requests get to finish after SIGTERM/SIGINT, in milliseconds.
    #[arg(long, env = "RULEMESH_GRACE_MS", default_value_t = 30_000)]
    pub grace_ms: u64,
    /// Server-side ceiling on every client limit: most primitives.
    #[arg(long, env = "RULEMESH_CEILING_PRIMITIVES", default_value_t = 5_000_000)]
    pub ceiling_primitives: u64,
    /// Server-side ceiling: most triangles.
    #[arg(long, env = "RULEMESH_CEILING_TRIANGLES", default_value_t = 50_000_000)]
    pub ceiling_triangles: u64,
    /// Server-side ceiling: most accounted memory per render, in bytes.
    #[arg(long, env = "RULEMESH_CEILING_MEMORY", default_value_t = 2 * 1024 * 1024 * 1024)]
    pub ceiling_memory: u64,
    /// Server-side ceiling: longest render, in milliseconds.
    #[arg(long, env = "RULEMESH_CEILING_TIMEOUT_MS", default_value_t = 60_000)]
    pub ceiling_timeout_ms: u64,
}

impl Default for ServeConfig {
    fn default() -> Self {
        ServeConfig {
            http: SocketAddr::from(([127, 0, 0, 1], 8080)),
            grpc: SocketAddr::from(([127, 0, 0, 1], 50051)),
            cache_bytes: 256 * 1024 * 1024,
            max_concurrency: 0,
            queue: 64,
            body_limit: 2 * 1024 * 1024,
            queue_timeout_ms: 30_000,
            grace_ms: 30_000,
            ceiling_primitives: 5_000_000,
            ceiling_triangles: 50_000_000,
            ceiling_memory: 2 * 1024 * 1024 * 1024,
            ceiling_timeout_ms: 60_000,
        }
    }
}

impl ServeConfig {
    /// Renders running at once, resolving 0 to the number of cores.
    pub fn concurrency(&self) -> usize {
        if self.max_concurrency > 0 {
            self.max_concurrency
        } else {
            std::thread::available_parallelism().map_or(2, |n| n.get())
        }
    }

    /// The ceiling every client-supplied limit is clamped to: these settings,
    /// never above [`Limits::ceiling`], and sources never above the body limit.
    pub fn ceiling(&self) -> Limits {
        Limits {
            max_primitives: self.ceiling_primitives,
            max_triangles: self.ceiling_triangles,
            max_memory: self.ceiling_memory,
            timeout_ms: self.ceiling_timeout_ms,
            max_source_bytes: self.body_limit as u64,
            ..Limits::ceiling()
        }
        .clamped_to(&Limits::ceiling())
    }

    /// The longest wait for a render slot.
    pub fn queue_timeout(&self) -> Duration {
        Duration::from_millis(self.queue_timeout_ms)
    }

    /// The shutdown grace period.
    pub fn grace(&self) -> Duration {
        Duration::from_millis(self.grace_ms)
    }
}
