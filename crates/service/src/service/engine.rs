//! The render engine shared by HTTP and gRPC: cache lookup with single-flight,
//! then the pipeline on the blocking pool behind a concurrency limit with a
//! bounded wait queue, prints behind a narrower limit of their own. Renders
//! known to be quick run on the async worker instead (module `inline`).

use super::timing::{RanRender, RequestTiming};
use super::{Metrics, RenderPlan, ServeConfig, ServiceError};
use crate::cache::{CacheOutcome, DiskTier, ModelCache, RedisTier, Rendered};
use crate::core::timing::PhaseTimes;
use crate::core::LimitExceeded;
use crate::lang::Language;
use crate::RenderRequest;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime};
use tokio::sync::Semaphore;

/// A model, whether it came from the cache, and where the request's time went.
#[derive(Debug, Clone)]
pub struct Served {
    /// The model.
    pub model: Arc<Rendered>,
    /// Hit or miss.
    pub cache: CacheOutcome,
    /// The lookup, and the render if this request ran it (`Server-Timing`).
    pub timing: RequestTiming,
}

/// Renders through the cache under the concurrency limit.
pub struct Engine {
    cache: ModelCache,
    slots: Arc<Semaphore>,
    slot_count: usize,
    /// Print slots (`ServeConfig::print_concurrency`): a print takes one
    /// before its render slot, so a waiting print holds no render slot.
    print_slots: Arc<Semaphore>,
    queue_limit: usize,
    waiting: AtomicUsize,
    queue_timeout: Duration,
    allow_javascript: bool,
    metrics: Arc<Metrics>,
    memory: Arc<super::memory::MemoryGuard>,
    /// Which renders run on the async worker instead of the blocking pool.
    quick: super::inline::QuickRenders,
}

/// Decrements the waiting count even if the waiting future is dropped.
struct Waiting<'a>(&'a Engine);

impl Drop for Waiting<'_> {
    fn drop(&mut self) {
        self.0.waiting.fetch_sub(1, Ordering::AcqRel);
        self.0.metrics.queued(-1);
    }
}

impl Engine {
    /// Takes a permit of `slots` at once, or waits for one in the bounded
    /// queue (shed with 503 when the queue is full, 503 when the wait
    /// passes the queue timeout, counted from `queued_at`).
    async fn wait_for(&self, slots: &Arc<Semaphore>, queued_at: Instant) -> Result<tokio::sync::OwnedSemaphorePermit, ServiceError> {
        if let Ok(p) = slots.clone().try_acquire_owned() {
            return Ok(p);
        }
        let before = self.waiting.fetch_add(1, Ordering::AcqRel);
        self.metrics.queued(1);
        let guard = Waiting(self);
        if before >= self.queue_limit {
            drop(guard);
            self.metrics.shed();
            return Err(ServiceError::Overloaded { running: self.slot_count, waiting: before, retry_after_secs: 1 });
        }
        let left = self.queue_timeout.saturating_sub(queued_at.elapsed());
        let acquired = tokio::time::timeout(left, slots.clone().acquire_owned()).await;
        drop(guard);
        match acquired {
            Ok(Ok(p)) => Ok(p),
            Ok(Err(_)) => Err(ServiceError::ShuttingDown),
            Err(_) => Err(ServiceError::QueueTimeout { ms: u64::try_from(self.queue_timeout.as_millis()).unwrap_or(u64::MAX) }),
        }
    }

    /// An engine configured by `config`, reporting to `metrics`; fails if the
    /// disk cache directory cannot be opened or the Redis URL is invalid
    /// (Redis itself need not be up).
    pub fn new(config: &ServeConfig, metrics: Arc<Metrics>) -> Result<Engine, super::ServeError> {
        let slot_count = config.concurrency();
        let mut cache = ModelCache::new(config.cache_bytes);
        if let Some(dir) = &config.cache_dir {
            cache = cache.with_disk(DiskTier::open(dir, config.cache_dir_bytes)?);
        }
        if let Some(settings) = config.redis() {
            tracing::info!(redis = %settings.redacted(), lock = ?settings.lock, "shared Redis cache tier");
            cache = cache.with_redis(RedisTier::new(settings)?);
        }
        // The metrics read the cache's figures through a handle without the
        // observer, so that neither keeps the other alive.
        metrics.attach_cache(cache.clone());
        let cache = cache.with_observer(metrics.clone());
        let memory = Arc::new(super::memory::MemoryGuard::new(config.memory_ceiling(), Duration::from_millis(config.memory_wait_ms), Box::new(super::memory::Statm)));
        if let Some(ceiling) = memory.ceiling() {
            tracing::info!(ceiling, "memory guard on: renders start only while resident memory plus their memory budget fits");
        }
        metrics.attach_memory(memory.clone());
        Ok(Engine {
            cache,
            slots: Arc::new(Semaphore::new(slot_count)),
            slot_count,
            print_slots: Arc::new(Semaphore::new(config.print_concurrency())),
            queue_limit: config.queue,
            waiting: AtomicUsize::new(0),
            queue_timeout: config.queue_timeout(),
            allow_javascript: config.allow_javascript,
            metrics,
            memory,
            quick: super::inline::QuickRenders::default(),
        })
    }

    /// The process memory guard.
    pub fn memory(&self) -> &super::memory::MemoryGuard {
        &self.memory
    }

    /// The model cache.
    pub fn cache(&self) -> &ModelCache {
        &self.cache
    }

    /// Serves `plan` from the cache, or renders it (once for all concurrent
    /// identical requests). Records the language, the cache key and the
    /// cache result on the caller's span (fields `language`, `key`, `cache`).
    ///
    /// The future is boxed: it sits inside every caller's future, and
    /// axum's layers move the handler's future several times a request.
    /// It was 8.6 KB, so a fresh `gem.glb` copied tens of kilobytes for
    /// nothing (issue 33's profile: `memcpy` under tower's `MapFuture`, 2 %
    /// of the request's instructions). The cache's fill for a miss and the
    /// render are boxed where they are made (most of the size, and a fresh
    /// render never makes the fill); the 2.7 KB left is boxed here, so each
    /// move copies a pointer, for one allocation.
    pub fn serve(&self, plan: RenderPlan) -> futures_util::future::BoxFuture<'_, Result<Served, ServiceError>> {
        Box::pin(self.serve_unboxed(plan))
    }

    /// [`Engine::serve`]'s work, unboxed.
    async fn serve_unboxed(&self, plan: RenderPlan) -> Result<Served, ServiceError> {
        let key = plan.key;
        let fresh = plan.no_cache;
        let span = tracing::Span::current();
        // The key's hex is made only for a span that keeps it (issue 33).
        if !span.is_disabled() {
            span.record("key", tracing::field::display(key.hex()));
        }
        let language = plan.request.language.or_else(|| Language::detect(&plan.source));
        span.record("language", tracing::field::display(language.map_or("unknown", Language::name)));
        if !self.allow_javascript && language == Some(Language::Eisenscript) && crate::lang::eisen::syntax::is_javascript(&plan.source) {
            self.metrics.access_rejected("javascript_disabled");
            return Err(ServiceError::JavaScriptDisabled);
        }
        // Filled by `run` only when this call is the one that renders.
        let ran: Mutex<Option<RanRender>> = Mutex::new(None);
        // The render's future boxed too: inline, it would sit in the cache's
        // fill future and in this one, whatever the cache answers.
        let (model, lookup) = self.cache.get_or_render(key, fresh, || Box::pin(self.run(plan, &ran))).await?;
        let cache = lookup.outcome;
        self.metrics.cache(cache == CacheOutcome::Hit);
        span.record("cache", tracing::field::display(if cache == CacheOutcome::Hit { "hit" } else { "miss" }));
        let ran = ran.lock().ok().and_then(|r| *r);
        Ok(Served { model, cache, timing: RequestTiming { lookup, ran } })
    }

    /// Waits for a slot (or sheds), then runs the pipeline on the blocking
    /// pool; records the wait and the stages in `ran` and the metrics.
    async fn run(&self, plan: RenderPlan, ran: &Mutex<Option<RanRender>>) -> Result<Rendered, ServiceError> {
        let queued_at = Instant::now();
        // A print waits for a print slot first (issue 38's load run: two
        // prints beside each other on two cores both ran past their
        // deadline). Its wait counts against the same queue and timeout.
        let print_permit = match plan.request.export_options.print.enabled {
            true => Some(self.wait_for(&self.print_slots, queued_at).await?),
            false => None,
        };
        let permit = self.wait_for(&self.slots, queued_at).await?;
        let permit = (permit, print_permit);
        // The second line behind the render's own budget: start only while
        // the process has room for the whole budget (waiting a little for
        // renders in flight to give memory back), never into the OOM killer.
        let budget = plan.request.limits.max_memory;
        match self.memory.admit(budget).await {
            Ok(waited) => {
                if waited {
                    self.metrics.memory_waited();
                }
            }
            Err(p) => {
                drop(permit);
                self.metrics.memory_refused();
                tracing::warn!(resident = p.resident, ceiling = p.ceiling, budget = p.budget, "render refused: memory ceiling");
                return Err(ServiceError::MemoryPressure { resident: p.resident, ceiling: p.ceiling, budget: p.budget, retry_after_secs: 1 });
            }
        }
        let queue = queued_at.elapsed();
        let metrics = self.metrics.clone();
        metrics.queue_wait(queue);
        metrics.in_flight(1);
        let started = Instant::now();
        let RenderPlan { source, mut request, .. } = plan;
        let timeout_ms = request.limits.timeout_ms;
        let format = request.format;
        // Only a request that may be tried on the worker has its source hashed for the memo.
        let memo = super::inline::may_try(timeout_ms, request.export_options.print.enabled, source.len()).then(|| self.quick.key(&source, format));
        let tried = match memo {
            Some(memo) if self.quick.is_quick(memo) => self.try_on_worker(&source, &mut request, memo),
            _ => None,
        };
        let watched = match tried {
            Some(done) => {
                drop(permit);
                Ok(Ok(done))
            }
            None => {
                let quick = &self.quick;
                let task = tokio::task::spawn_blocking(move || {
                    let started = Instant::now();
                    let result = render_blocking(&source, &request);
                    let took = started.elapsed();
                    drop(permit);
                    (result, took)
                });
                tokio::time::timeout(watchdog_after(timeout_ms), task).await.map(|joined| {
                    joined.map(|(result, took)| {
                        if let (true, Some(memo)) = (result.is_ok(), memo) {
                            quick.record(memo, took);
                        }
                        result
                    })
                })
            }
        };
        metrics.in_flight(-1);
        metrics.render_done(started.elapsed());
        let result = match watched {
            Ok(joined) => joined.map_err(|e| ServiceError::Internal(format!("render task failed: {e}")))?.map(|(r, phases, began)| {
                metrics.stages(r.language, format, &phases);
                super::telemetry::stage_spans(began, &phases, r.language.name(), format.name());
                if let Ok(mut slot) = ran.lock() {
                    *slot = Some(RanRender { queue, phases });
                }
                r
            }),
            Err(_) => {
                // The pipeline ran past its deadline without noticing. The
                // request ends now with the typed deadline error; the
                // blocking thread finishes on its own and keeps its render
                // slot until then, so overload protection still counts it.
                metrics.watchdog_fired();
                tracing::warn!(timeout_ms, "render ran past its deadline; ended by the watchdog");
                let elapsed = u64::try_from(started.elapsed().as_millis()).unwrap_or(u64::MAX);
                Err(ServiceError::Limit(LimitExceeded::deadline_passed(timeout_ms, elapsed)))
            }
        };
        match &result {
            Err(ServiceError::Limit(l)) => metrics.rejected(l.limit.name()),
            Ok(r) => {
                if let Some(t) = &r.truncated {
                    metrics.truncated(t.limit.name());
                }
            }
            Err(_) => {}
        }
        result
    }
}

impl Engine {
    /// Renders `request` on this async worker under a deadline of
    /// [`super::inline::TRY_DEADLINE_MS`] (module `inline` says why). `None`
    /// when the try ran into that deadline: the caller renders again on the
    /// blocking pool, with `request`'s own deadline, restored here.
    fn try_on_worker(&self, source: &[u8], request: &mut RenderRequest, memo: u64) -> Option<Result<(Rendered, PhaseTimes, SystemTime), ServiceError>> {
        let own = request.limits.timeout_ms;
        request.limits.timeout_ms = super::inline::TRY_DEADLINE_MS;
        let result = render_blocking(source, request);
        request.limits.timeout_ms = own;
        let error = match &result {
            Err(ServiceError::Limit(l)) => Some(l),
            _ => None,
        };
        let truncated = result.as_ref().ok().and_then(|(r, _, _)| r.truncated.as_ref());
        if super::inline::hit_try_deadline(error, truncated) {
            self.quick.forget(memo);
            self.metrics.quick_fell_back();
            return None;
        }
        self.metrics.quick_rendered();
        Some(result)
    }
}

/// When the watchdog ends a render whose deadline is `timeout_ms`: a little
/// after the deadline (a tenth of it, 10 ms to 1 s), so that a pipeline that
/// does check its deadline answers first, with its own error or, under
/// `on_limit=truncate`, its truncated model. Either way the request ends
/// within 1.1× its deadline plus the time to send the answer.
pub(crate) fn watchdog_after(timeout_ms: u64) -> Duration {
    let deadline = Duration::from_millis(timeout_ms);
    deadline.saturating_add((deadline / 10).clamp(Duration::from_millis(10), Duration::from_secs(1)))
}

/// The pipeline itself, exactly as the CLI runs it, its stage times and
/// when it began (for the stages' trace spans).
fn render_blocking(source: &[u8], request: &RenderRequest) -> Result<(Rendered, PhaseTimes, SystemTime), ServiceError> {
    let began = SystemTime::now();
    let out = crate::render(source, request)?;
    let phases = out.phases;
    // A print report is JSON whatever the format asked for.
    let content_type = if request.export_options.print.report { "application/json" } else { request.format.content_type() };
    Ok((Rendered::from_output(out, content_type), phases, began))
}
