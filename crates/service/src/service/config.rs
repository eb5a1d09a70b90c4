//! Server configuration: command-line flags, each also read from a
//! `RULEMESH_*` environment variable or a `--config` file (TOML or JSON),
//! with defaults that need nothing else. Precedence: flag > environment
//! variable > file > default ([`ServeConfig::resolve`]).

use super::access::ApiKeys;
use crate::core::Limits;
use clap::parser::ValueSource;
use serde::{Deserialize, Serialize};
use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Largest configuration file read, in bytes.
pub(crate) const MAX_CONFIG_BYTES: u64 = 1024 * 1024;

/// `rulemesh serve` options.
#[derive(Debug, Clone, PartialEq, Serialize, clap::Args)]
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
    /// Prints (`print=true`) running at once, within the renders above (0: one per two cores,
    /// at least one). A print unites on two threads for seconds; two beside each other on two
    /// cores each take twice as long and end at their deadline, so the others wait their turn.
    #[arg(long, env = "RULEMESH_MAX_PRINT_CONCURRENCY", default_value_t = 0)]
    pub max_print_concurrency: usize,
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
    /// Resident bytes the process keeps under: a render starts only while resident memory plus its memory budget fits (else it waits, then is refused with 503 `memory_pressure`). 0: off. Unset: 15/16 of the cgroup memory limit when there is one, else off.
    #[arg(long, env = "RULEMESH_MEMORY_CEILING")]
    pub memory_ceiling: Option<u64>,
    /// Longest a render waits for memory under the ceiling before it is refused, in milliseconds.
    #[arg(long, env = "RULEMESH_MEMORY_WAIT_MS", default_value_t = 2_000)]
    pub memory_wait_ms: u64,
    /// Directory of the disk cache tier (content-addressed files; survives restarts). None: memory only.
    #[arg(long, env = "RULEMESH_CACHE_DIR")]
    pub cache_dir: Option<PathBuf>,
    /// Byte budget of the disk cache tier; no more files are written past it.
    #[arg(long, env = "RULEMESH_CACHE_DIR_BYTES", default_value_t = 1024 * 1024 * 1024)]
    pub cache_dir_bytes: u64,
    /// Redis shared by every worker as a second cache level (`redis://host:6379/0`). None: no shared tier.
    #[arg(long, env = "RULEMESH_CACHE_REDIS")]
    #[serde(serialize_with = "redacted_url")]
    pub cache_redis: Option<String>,
    /// Lifetime of a model stored in Redis, in seconds.
    #[arg(long, env = "RULEMESH_CACHE_REDIS_TTL_SECS", default_value_t = 24 * 60 * 60)]
    pub cache_redis_ttl_secs: u64,
    /// Largest model stored in Redis, in bytes; larger ones stay local.
    #[arg(long, env = "RULEMESH_CACHE_REDIS_MAX_BYTES", default_value_t = 32 * 1024 * 1024)]
    pub cache_redis_max_bytes: u64,
    /// Longest any Redis command may take, in milliseconds, before the request goes on without it.
    #[arg(long, env = "RULEMESH_CACHE_REDIS_TIMEOUT_MS", default_value_t = 250)]
    pub cache_redis_timeout_ms: u64,
    /// Lifetime of the distributed single-flight lock in Redis, in milliseconds (0: no lock).
    #[arg(long, env = "RULEMESH_CACHE_REDIS_LOCK_MS", default_value_t = 0)]
    pub cache_redis_lock_ms: u64,
    /// This worker's name, added as a `worker` label to every metric. None: no label.
    #[arg(long, env = "RULEMESH_WORKER_ID")]
    pub worker_id: Option<String>,
    /// After SIGTERM/SIGINT, time /readyz answers 503 while requests are still served (so load balancers stop sending), in milliseconds.
    #[arg(long, env = "RULEMESH_DRAIN_MS", default_value_t = 0)]
    pub drain_ms: u64,
    /// Longest an HTTP client may take to send a request's headers, in milliseconds, counted from when the connection is ready for a request (accepted, or its previous response sent); then the connection is closed.
    #[arg(long, env = "RULEMESH_HEADER_TIMEOUT_MS", default_value_t = 10_000)]
    pub header_timeout_ms: u64,
    /// Longest an HTTP keep-alive connection may sit with no request in flight, in milliseconds (the header timeout also bounds it).
    #[arg(long, env = "RULEMESH_IDLE_TIMEOUT_MS", default_value_t = 10_000)]
    pub idle_timeout_ms: u64,
    /// Most HTTP connections open at once; further clients wait in the listen backlog until one closes.
    #[arg(long, env = "RULEMESH_MAX_CONNECTIONS", default_value_t = 1024)]
    pub max_connections: usize,
    /// API keys as a JSON array of `{"name", "key", "rate_per_sec"?, "burst"?, "max_concurrency"?, "ceiling_*"?}` (the config file takes `[[api_keys]]` tables). Empty: no keys, the service is open.
    #[arg(long, env = "RULEMESH_API_KEYS", value_parser = ApiKeys::parse, default_value = "", hide_default_value = true)]
    pub api_keys: ApiKeys,
    /// Origins browsers may call the HTTP API from (comma-separated; `*` for any). Empty: no CORS headers.
    #[arg(long, env = "RULEMESH_CORS_ORIGINS", value_delimiter = ',')]
    pub cors_origins: Vec<String>,
    /// Run `#javascript` EisenScript scripts (user JavaScript in the server process, sandboxed in QuickJS). Off by default: see docs/service.md.
    #[arg(long, env = "RULEMESH_ALLOW_JAVASCRIPT", default_value_t = false, action = clap::ArgAction::Set)]
    pub allow_javascript: bool,
}

/// Serialises a Redis URL with its password hidden.
fn redacted_url<S: serde::Serializer>(url: &Option<String>, s: S) -> Result<S::Ok, S::Error> {
    match url {
        Some(u) => s.serialize_some(&crate::cache::redis::redact_url(u)),
        None => s.serialize_none(),
    }
}

/// Why a configuration file could not be used.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    /// The file could not be read.
    #[error("{path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is larger than [`MAX_CONFIG_BYTES`].
    #[error("{path}: larger than {MAX_CONFIG_BYTES} bytes")]
    TooLarge {
        /// The file.
        path: PathBuf,
    },
    /// The file is not valid TOML or JSON for these settings.
    #[error("{path}: {message}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// What is wrong, with the parser's position.
        message: String,
    },
}

/// A configuration file: every [`ServeConfig`] setting, by the same
/// snake_case name, each optional. Unknown keys are errors.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConfigFile {
    /// [`ServeConfig::http`]
    pub http: Option<SocketAddr>,
    /// [`ServeConfig::grpc`]
    pub grpc: Option<SocketAddr>,
    /// [`ServeConfig::cache_bytes`]
    pub cache_bytes: Option<u64>,
    /// [`ServeConfig::max_concurrency`]
    pub max_concurrency: Option<usize>,
    /// [`ServeConfig::max_print_concurrency`]
    pub max_print_concurrency: Option<usize>,
    /// [`ServeConfig::queue`]
    pub queue: Option<usize>,
    /// [`ServeConfig::body_limit`]
    pub body_limit: Option<usize>,
    /// [`ServeConfig::queue_timeout_ms`]
    pub queue_timeout_ms: Option<u64>,
    /// [`ServeConfig::grace_ms`]
    pub grace_ms: Option<u64>,
    /// [`ServeConfig::ceiling_primitives`]
    pub ceiling_primitives: Option<u64>,
    /// [`ServeConfig::ceiling_triangles`]
    pub ceiling_triangles: Option<u64>,
    /// [`ServeConfig::ceiling_memory`]
    pub ceiling_memory: Option<u64>,
    /// [`ServeConfig::ceiling_timeout_ms`]
    pub ceiling_timeout_ms: Option<u64>,
    /// [`ServeConfig::memory_ceiling`]
    pub memory_ceiling: Option<u64>,
    /// [`ServeConfig::memory_wait_ms`]
    pub memory_wait_ms: Option<u64>,
    /// [`ServeConfig::cache_dir`]
    pub cache_dir: Option<PathBuf>,
    /// [`ServeConfig::cache_dir_bytes`]
    pub cache_dir_bytes: Option<u64>,
    /// [`ServeConfig::cache_redis`]
    pub cache_redis: Option<String>,
    /// [`ServeConfig::cache_redis_ttl_secs`]
    pub cache_redis_ttl_secs: Option<u64>,
    /// [`ServeConfig::cache_redis_max_bytes`]
    pub cache_redis_max_bytes: Option<u64>,
    /// [`ServeConfig::cache_redis_timeout_ms`]
    pub cache_redis_timeout_ms: Option<u64>,
    /// [`ServeConfig::cache_redis_lock_ms`]
    pub cache_redis_lock_ms: Option<u64>,
    /// [`ServeConfig::worker_id`]
    pub worker_id: Option<String>,
    /// [`ServeConfig::drain_ms`]
    pub drain_ms: Option<u64>,
    /// [`ServeConfig::header_timeout_ms`]
    pub header_timeout_ms: Option<u64>,
    /// [`ServeConfig::idle_timeout_ms`]
    pub idle_timeout_ms: Option<u64>,
    /// [`ServeConfig::max_connections`]
    pub max_connections: Option<usize>,
    /// [`ServeConfig::api_keys`]: `[[api_keys]]` tables.
    pub api_keys: Option<ApiKeys>,
    /// [`ServeConfig::cors_origins`]
    pub cors_origins: Option<Vec<String>>,
    /// [`ServeConfig::allow_javascript`]
    pub allow_javascript: Option<bool>,
}

impl ConfigFile {
    /// Reads a TOML file, or JSON when the name ends in `.json`.
    pub fn read(path: &Path) -> Result<ConfigFile, ConfigError> {
        use std::io::Read as _;
        let read_err = |source| ConfigError::Read { path: path.to_path_buf(), source };
        let file = std::fs::File::open(path).map_err(read_err)?;
        let mut text = String::new();
        file.take(MAX_CONFIG_BYTES + 1).read_to_string(&mut text).map_err(read_err)?;
        if text.len() as u64 > MAX_CONFIG_BYTES {
            return Err(ConfigError::TooLarge { path: path.to_path_buf() });
        }
        let parse_err = |message: String| ConfigError::Parse { path: path.to_path_buf(), message };
        let file: ConfigFile = if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json")) {
            serde_json::from_str(&text).map_err(|e| parse_err(e.to_string()))?
        } else {
            toml::from_str(&text).map_err(|e| parse_err(e.to_string()))?
        };
        if let Some(keys) = &file.api_keys {
            keys.validate().map_err(parse_err)?;
        }
        Ok(file)
    }
}

impl Default for ServeConfig {
    fn default() -> Self {
        ServeConfig {
            http: SocketAddr::from(([127, 0, 0, 1], 8080)),
            grpc: SocketAddr::from(([127, 0, 0, 1], 50051)),
            cache_bytes: 256 * 1024 * 1024,
            max_concurrency: 0,
            max_print_concurrency: 0,
            queue: 64,
            body_limit: 2 * 1024 * 1024,
            queue_timeout_ms: 30_000,
            grace_ms: 30_000,
            ceiling_primitives: 5_000_000,
            ceiling_triangles: 50_000_000,
            ceiling_memory: 2 * 1024 * 1024 * 1024,
            ceiling_timeout_ms: 60_000,
            memory_ceiling: None,
            memory_wait_ms: 2_000,
            cache_dir: None,
            cache_dir_bytes: 1024 * 1024 * 1024,
            cache_redis: None,
            cache_redis_ttl_secs: 24 * 60 * 60,
            cache_redis_max_bytes: 32 * 1024 * 1024,
            cache_redis_timeout_ms: 250,
            cache_redis_lock_ms: 0,
            worker_id: None,
            drain_ms: 0,
            header_timeout_ms: 10_000,
            idle_timeout_ms: 10_000,
            max_connections: 1024,
            api_keys: ApiKeys::default(),
            cors_origins: Vec::new(),
            allow_javascript: false,
        }
    }
}

impl ServeConfig {
    /// Fills every setting that neither a flag nor an environment variable
    /// gave (its value in `self` is clap's default, as `matches` tells) from
    /// `file`. `matches` are the `serve` subcommand's.
    pub fn resolve(mut self, matches: &clap::ArgMatches, file: ConfigFile) -> ServeConfig {
        let unset = |id: &str| !matches!(matches.value_source(id), Some(ValueSource::CommandLine | ValueSource::EnvVariable));
        macro_rules! layer {
            ($($field:ident),*) => {$(
                if let Some(v) = file.$field {
                    if unset(stringify!($field)) {
                        self.$field = v.into();
                    }
                }
            )*};
        }
        layer!(
            http,
            grpc,
            cache_bytes,
            max_concurrency,
            max_print_concurrency,
            queue,
            body_limit,
            queue_timeout_ms,
            grace_ms,
            ceiling_primitives,
            ceiling_triangles,
            ceiling_memory,
            ceiling_timeout_ms,
            memory_ceiling,
            memory_wait_ms,
            cache_dir,
            cache_dir_bytes,
            cache_redis,
            cache_redis_ttl_secs,
            cache_redis_max_bytes,
            cache_redis_timeout_ms,
            cache_redis_lock_ms,
            worker_id,
            drain_ms,
            header_timeout_ms,
            idle_timeout_ms,
            max_connections,
            api_keys,
            cors_origins,
            allow_javascript
        );
        self
    }

    /// Renders running at once, resolving 0 to the number of cores.
    pub fn concurrency(&self) -> usize {
        if self.max_concurrency > 0 {
            self.max_concurrency
        } else {
            std::thread::available_parallelism().map_or(2, |n| n.get())
        }
    }

    /// Prints running at once: the setting, or one per two cores (at least
    /// one); never more than [`ServeConfig::concurrency`].
    pub(crate) fn print_concurrency(&self) -> usize {
        let n = if self.max_print_concurrency > 0 {
            self.max_print_concurrency
        } else {
            (std::thread::available_parallelism().map_or(2, |n| n.get()) / 2).max(1)
        };
        n.min(self.concurrency())
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

    /// The memory guard's ceiling in bytes (`None`: off), from the setting
    /// or the cgroup's limit ([`super::memory::effective_ceiling`]).
    pub fn memory_ceiling(&self) -> Option<u64> {
        super::memory::effective_ceiling(self.memory_ceiling, super::memory::cgroup_limit())
    }

    /// The longest wait for a render slot.
    pub fn queue_timeout(&self) -> Duration {
        Duration::from_millis(self.queue_timeout_ms)
    }

    /// The Redis tier's settings, if a Redis URL is configured.
    pub fn redis(&self) -> Option<crate::cache::RedisSettings> {
        let url = self.cache_redis.as_ref().filter(|u| !u.is_empty())?;
        Some(crate::cache::RedisSettings {
            url: url.clone(),
            ttl: Duration::from_secs(self.cache_redis_ttl_secs.max(1)),
            max_value_bytes: self.cache_redis_max_bytes,
            timeout: Duration::from_millis(self.cache_redis_timeout_ms.max(1)),
            lock: (self.cache_redis_lock_ms > 0).then(|| Duration::from_millis(self.cache_redis_lock_ms)),
        })
    }

    /// How long readiness is false before the listeners close on shutdown.
    pub fn drain(&self) -> Duration {
        Duration::from_millis(self.drain_ms)
    }

    /// The HTTP header-read timeout (at least 1 ms).
    pub fn header_timeout(&self) -> Duration {
        Duration::from_millis(self.header_timeout_ms.max(1))
    }

    /// The HTTP keep-alive idle timeout (at least 1 ms).
    pub(crate) fn idle_timeout(&self) -> Duration {
        Duration::from_millis(self.idle_timeout_ms.max(1))
    }

    /// The shutdown grace period.
    pub fn grace(&self) -> Duration {
        Duration::from_millis(self.grace_ms)
    }
}
