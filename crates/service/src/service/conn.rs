//! The HTTP accept loop, with connection hygiene that `axum::serve` does not
//! offer: a header-read timeout, an idle keep-alive timeout and a cap on
//! open connections (issue 17: 3,000 half-sent requests were all still open
//! after 35 s).
//!
//! - **Header timeout** ([`ServeConfig::header_timeout`]): hyper's own. It
//!   runs from the moment a connection is ready for a request head (just
//!   accepted, or its previous response sent) until the head is complete; a
//!   client that stalls in its headers is disconnected when it expires.
//! - **Idle timeout** ([`ServeConfig::idle_timeout`]): a keep-alive
//!   connection with no request in flight for this long is closed
//!   gracefully. Since hyper's header timer also runs while a connection
//!   waits for its next request, the idle time a connection actually gets is
//!   the smaller of the two.
//! - **Connection cap** ([`ServeConfig::max_connections`]): past it the loop
//!   stops accepting, so further clients wait in the kernel's listen backlog
//!   (no file descriptor, no memory here) until a connection closes.
//!
//! [`ServeConfig::header_timeout`]: super::ServeConfig::header_timeout
//! [`ServeConfig::idle_timeout`]: super::ServeConfig::idle_timeout
//! [`ServeConfig::max_connections`]: super::ServeConfig::max_connections

use super::{AppState, ServeError};
use axum::Router;
use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::service::TowerToHyperService;
use std::future::Future;
use std::pin::Pin;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{watch, OwnedSemaphorePermit, Semaphore};

/// Serves `app` on `listener` until `stop` turns true, then stops accepting,
/// lets every open connection finish its request and waits for all to close.
pub(crate) async fn serve_http(listener: TcpListener, app: Router, state: Arc<AppState>, mut stop: watch::Receiver<bool>) -> Result<(), ServeError> {
    let max = state.config.max_connections.clamp(1, u32::MAX as usize);
    let slots = Arc::new(Semaphore::new(max));
    loop {
        let permit = tokio::select! {
            p = slots.clone().acquire_owned() => match p {
                Ok(p) => p,
                Err(_) => break,
            },
            () = stopped(&mut stop) => break,
        };
        let stream = tokio::select! {
            r = accept_or_back_off(&listener) => match r {
                Some(s) => s,
                None => continue,
            },
            () = stopped(&mut stop) => break,
        };
        tokio::spawn(connection(stream, app.clone(), state.clone(), stop.clone(), permit));
    }
    drop(listener);
    // Every connection holds a permit until it closes.
    let _ = slots.acquire_many(u32::try_from(max).unwrap_or(u32::MAX)).await;
    Ok(())
}

/// The next connection, or `None` after a short pause when accepting
/// failed (out of file descriptors and the like: back off instead of
/// spinning). Shared by the HTTP and gRPC accept loops.
pub(super) async fn accept_or_back_off(listener: &TcpListener) -> Option<TcpStream> {
    match listener.accept().await {
        Ok((s, _)) => Some(s),
        Err(e) => {
            tracing::warn!(error = %e, "accept failed");
            tokio::time::sleep(Duration::from_millis(50)).await;
            None
        }
    }
}

/// Resolves once `stop` is true (or its sender is gone). Returns `()` so that
/// no watch guard is held across an await (it is not `Send`).
async fn stopped(stop: &mut watch::Receiver<bool>) {
    let _ = stop.wait_for(|v| *v).await.is_ok();
}

/// When a connection last finished a request, and how many it has in flight.
#[derive(Debug)]
struct Activity {
    base: Instant,
    last_ms: AtomicU64,
    in_flight: AtomicUsize,
}

impl Activity {
    fn new() -> Activity {
        Activity { base: Instant::now(), last_ms: AtomicU64::new(0), in_flight: AtomicUsize::new(0) }
    }

    fn now_ms(&self) -> u64 {
        u64::try_from(self.base.elapsed().as_millis()).unwrap_or(u64::MAX)
    }

    /// How long the connection has had nothing in flight (zero while it has).
    fn idle_for(&self) -> Duration {
        if self.in_flight.load(Ordering::Acquire) > 0 {
            return Duration::ZERO;
        }
        Duration::from_millis(self.now_ms().saturating_sub(self.last_ms.load(Ordering::Acquire)))
    }
}

/// Marks a request in flight on its connection until dropped.
struct InFlight(Arc<Activity>);

impl Drop for InFlight {
    fn drop(&mut self) {
        self.0.last_ms.store(self.0.now_ms(), Ordering::Release);
        self.0.in_flight.fetch_sub(1, Ordering::AcqRel);
    }
}

/// The router as a hyper service that keeps its connection's [`Activity`],
/// with the cached-GET fast path ([`super::fast`]) and the direct model
/// route ([`super::direct`]) in front of it.
#[derive(Clone)]
struct Tracked {
    inner: TowerToHyperService<Router>,
    activity: Arc<Activity>,
    state: Arc<AppState>,
}

type BoxFuture<T> = Pin<Box<dyn Future<Output = T> + Send>>;

impl hyper::service::Service<hyper::Request<hyper::body::Incoming>> for Tracked {
    type Response = axum::response::Response;
    type Error = std::convert::Infallible;
    type Future = BoxFuture<Result<Self::Response, Self::Error>>;

    fn call(&self, req: hyper::Request<hyper::body::Incoming>) -> Self::Future {
        self.activity.in_flight.fetch_add(1, Ordering::AcqRel);
        let guard = InFlight(self.activity.clone());
        let (state, inner) = (self.state.clone(), self.inner.clone());
        Box::pin(async move {
            let fast = &state.fast;
            let target = match fast.probe(&state, &req) {
                Some(probe) => match fast.answer(&state, &probe, req.headers()).await {
                    Some(resp) => {
                        drop(guard);
                        return Ok(resp);
                    }
                    None => Some(probe.to_target()),
                },
                None => None,
            };
            let r = match super::direct::answer(&state, req).await {
                Ok(resp) => Ok(resp),
                Err(req) => inner.call(req).await,
            };
            if let (Some(target), Ok(resp)) = (target, &r) {
                fast.offer(target, resp);
            }
            drop(guard);
            r
        })
    }
}

/// Serves one connection under the header and idle timeouts.
async fn connection(stream: TcpStream, app: Router, state: Arc<AppState>, mut stop: watch::Receiver<bool>, _slot: OwnedSemaphorePermit) {
    let metrics = state.metrics.clone();
    metrics.connection(1);
    let _ = stream.set_nodelay(true);
    let activity = Arc::new(Activity::new());
    let service = Tracked { inner: TowerToHyperService::new(app), activity: activity.clone(), state: state.clone() };
    let idle = state.config.idle_timeout();
    let mut builder = hyper::server::conn::http1::Builder::new();
    builder.timer(TokioTimer::new()).header_read_timeout(state.config.header_timeout()).keep_alive(true);
    let conn = builder.serve_connection(TokioIo::new(stream), service);
    tokio::pin!(conn);
    let mut tick = tokio::time::interval((idle / 4).clamp(Duration::from_millis(5), Duration::from_secs(1)));
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let mut closing = false;
    let mut idle_close = false;
    let result = loop {
        tokio::select! {
            r = conn.as_mut() => break r,
            () = stopped(&mut stop), if !closing => {
                closing = true;
                conn.as_mut().graceful_shutdown();
            }
            _ = tick.tick(), if !closing => {
                if activity.idle_for() >= idle {
                    closing = true;
                    idle_close = true;
                    conn.as_mut().graceful_shutdown();
                }
            }
        }
    };
    match result {
        Err(e) if e.is_timeout() => metrics.connection_closed("header_timeout"),
        Err(e) => tracing::debug!(error = %e, "HTTP connection ended with an error"),
        // A stalled head outlives the idle shutdown and is counted above.
        Ok(()) if idle_close => metrics.connection_closed("idle"),
        Ok(()) => {}
    }
    metrics.connection(-1);
}
