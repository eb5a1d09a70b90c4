//! The headless service: HTTP ([`http`], axum) and gRPC ([`grpc`], tonic)
//! front doors over one [`Engine`] (content-hash cache, single-flight,
//! bounded concurrency) that calls the same [`crate::render`] as the CLI.
//!
//! Workers are stateless: any worker answers any request, and nothing but
//! the cache outlives a request.

pub mod access;
pub mod access_log;
mod access_line;
pub mod batch;
pub mod config;
pub mod conn;
pub(crate) mod direct;
pub mod engine;
pub mod error;
pub mod fast;
pub mod grpc;
pub(crate) mod header_names;
pub(crate) mod grpc_batch;
pub(crate) mod grpc_conn;
pub mod http;
pub(crate) mod http_batch;
pub(crate) mod http_schema;
pub(crate) mod inline;
pub mod library;
pub(crate) mod log_writer;
pub mod memory;
pub mod metrics;
pub mod phone;
pub mod playground;
pub mod request;
pub mod schema;
pub mod telemetry;
pub mod timing;

pub use config::{ConfigFile, ServeConfig};
pub use engine::Engine;
pub(crate) use engine::Served;
pub(crate) use error::ServiceError;
pub(crate) use metrics::Metrics;
pub use request::RenderBody;
pub(crate) use request::RenderPlan;

use crate::core::Limits;
use std::future::Future;
use std::net::SocketAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use tokio::sync::watch;
use tokio::task::JoinHandle;

/// What every handler shares.
pub struct AppState {
    /// The render engine (cache, limits, blocking pool).
    pub engine: Engine,
    /// Metrics.
    pub metrics: Arc<Metrics>,
    /// The configuration.
    pub config: ServeConfig,
    /// The server-side ceiling on client limits.
    pub ceiling: Limits,
    /// API keys, their rates, shares and ceilings (open when none are configured).
    pub access: access::Access,
    /// Responses kept for the cached-GET fast path.
    pub fast: fast::Answers,
    ready: AtomicBool,
}

impl AppState {
    /// State for `config`; fails if the disk cache directory cannot be
    /// opened or the Redis URL is invalid.
    pub fn new(config: ServeConfig) -> Result<AppState, ServeError> {
        let metrics = Arc::new(Metrics::for_worker(config.worker_id.clone()));
        let ceiling = config.ceiling();
        Ok(AppState {
            engine: Engine::new(&config, metrics.clone())?,
            metrics,
            access: access::Access::new(&config.api_keys, &ceiling),
            ceiling,
            config,
            fast: fast::Answers::default(),
            ready: AtomicBool::new(true),
        })
    }

    /// Admits a request presenting `key` (see [`access::Access::admit`]),
    /// counting refusals in `/metrics`.
    pub fn admit(&self, key: Option<&str>) -> Result<access::Admission, ServiceError> {
        self.access.admit(key, &self.ceiling).inspect_err(|e| self.metrics.access_rejected(e.code()))
    }

    /// False once shutdown has begun.
    pub fn is_ready(&self) -> bool {
        self.ready.load(Ordering::Acquire)
    }
}

/// Why the server could not start or stopped with an error.
#[derive(Debug, thiserror::Error)]
pub enum ServeError {
    /// A listener could not be bound.
    #[error("cannot listen on {addr}: {source}")]
    Bind {
        /// The address.
        addr: SocketAddr,
        /// The cause.
        source: std::io::Error,
    },
    /// The HTTP server failed.
    #[error("HTTP server: {0}")]
    Http(std::io::Error),
    /// The disk cache directory could not be opened.
    #[error(transparent)]
    Cache(#[from] crate::cache::DiskError),
    /// The Redis URL is invalid.
    #[error(transparent)]
    Redis(#[from] crate::cache::RedisError),
    /// The gRPC reflection service could not be built.
    #[error("gRPC reflection: {0}")]
    Reflection(#[from] tonic_reflection::server::Error),
    /// The gRPC server failed.
    #[error("gRPC server: {0}")]
    Grpc(#[from] tonic::transport::Error),
    /// In-flight requests did not finish within the grace period.
    #[error("in-flight requests did not finish within {0:?}; stopped anyway")]
    GraceExpired(std::time::Duration),
    /// A server task panicked.
    #[error("server task failed: {0}")]
    Join(#[from] tokio::task::JoinError),
}

/// A running server: its addresses, its state, and a handle to stop it.
pub struct Running {
    /// Where HTTP listens.
    pub http_addr: SocketAddr,
    /// Where gRPC listens.
    pub grpc_addr: SocketAddr,
    /// The shared state (metrics, cache).
    pub state: Arc<AppState>,
    stop: watch::Sender<bool>,
    http: JoinHandle<Result<(), ServeError>>,
    grpc: JoinHandle<Result<(), ServeError>>,
}

impl Running {
    /// Marks the worker not ready (`/readyz` answers 503) while it still
    /// serves, so load balancers stop sending it work.
    pub fn drain(&self) {
        self.state.ready.store(false, Ordering::Release);
    }

    /// Begins a graceful shutdown: stop accepting, let in-flight requests finish.
    pub fn shutdown(&self) {
        self.state.ready.store(false, Ordering::Release);
        let _ = self.stop.send(true);
    }

    /// Waits for both servers to stop, at most the configured grace period after [`Running::shutdown`].
    pub async fn wait(self) -> Result<(), ServeError> {
        let grace = self.state.config.grace();
        let mut stop = self.stop.subscribe();
        let _ = stop.wait_for(|v| *v).await;
        let both = async {
            let (h, g) = tokio::join!(self.http, self.grpc);
            h??;
            g??;
            Ok(())
        };
        match tokio::time::timeout(grace, both).await {
            Ok(r) => r,
            Err(_) => Err(ServeError::GraceExpired(grace)),
        }
    }
}

async fn bind(addr: SocketAddr) -> Result<tokio::net::TcpListener, ServeError> {
    tokio::net::TcpListener::bind(addr).await.map_err(|source| ServeError::Bind { addr, source })
}

/// Binds both listeners (port 0 picks a free port) and starts serving.
pub async fn start(config: ServeConfig) -> Result<Running, ServeError> {
    let http_listener = bind(config.http).await?;
    let grpc_listener = bind(config.grpc).await?;
    let http_addr = http_listener.local_addr().map_err(|source| ServeError::Bind { addr: config.http, source })?;
    let grpc_addr = grpc_listener.local_addr().map_err(|source| ServeError::Bind { addr: config.grpc, source })?;
    let state = Arc::new(AppState::new(config)?);
    let (stop, _) = watch::channel(false);

    let stopped = |mut rx: watch::Receiver<bool>| async move {
        let _ = rx.wait_for(|v| *v).await;
    };

    let app = http::router(state.clone());
    let http = tokio::spawn(conn::serve_http(http_listener, app, state.clone(), stop.subscribe()));

    let (health, health_service) = tonic_health::server::health_reporter();
    health.set_serving::<grpc::pb::rulemesh_server::RulemeshServer<grpc::GrpcService>>().await;
    let grpc_service = grpc::server(state.clone());
    // Server reflection, in the current (v1) and the older (v1alpha) protocol that some tools still ask first.
    let reflection = || {
        tonic_reflection::server::Builder::configure()
            .register_encoded_file_descriptor_set(grpc::FILE_DESCRIPTOR_SET)
            .register_encoded_file_descriptor_set(tonic_health::pb::FILE_DESCRIPTOR_SET)
    };
    let reflection_alpha = reflection().build_v1alpha()?;
    let reflection = reflection().build_v1()?;
    let grpc_stop = stopped(stop.subscribe());
    let incoming = grpc_conn::capped_incoming(grpc_listener, state.config.max_connections, state.config.header_timeout());
    // Pings find peers that went away or stopped answering; a connection
    // that never sent its preface is closed by `grpc_conn` instead.
    let (ping_every, ping_answer) = (state.config.idle_timeout(), state.config.header_timeout());
    let grpc = tokio::spawn(async move {
        tonic::transport::Server::builder()
            .http2_keepalive_interval(Some(ping_every))
            .http2_keepalive_timeout(Some(ping_answer))
            .add_service(health_service)
            .add_service(reflection)
            .add_service(reflection_alpha)
            .add_service(grpc_service)
            // `grpc_conn` sets TCP_NODELAY on every connection it accepts.
            .serve_with_incoming_shutdown(incoming, grpc_stop)
            .await
            .map_err(ServeError::Grpc)
    });
    tracing::info!(%http_addr, %grpc_addr, "rulemesh serving");
    Ok(Running { http_addr, grpc_addr, state, stop, http, grpc })
}

/// Serves until `signal` resolves, then shuts down gracefully.
pub async fn serve(config: ServeConfig, signal: impl Future<Output = ()>) -> Result<(), ServeError> {
    let running = start(config).await?;
    signal.await;
    let drain = running.state.config.drain();
    if !drain.is_zero() {
        tracing::info!(?drain, "draining: not ready, still serving");
        running.drain();
        tokio::time::sleep(drain).await;
    }
    tracing::info!("shutting down: finishing in-flight requests");
    running.shutdown();
    running.wait().await
}

/// Resolves on SIGINT (Ctrl-C) or, on Unix, SIGTERM.
pub async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        () = ctrl_c => {},
        () = term => {},
    }
}
