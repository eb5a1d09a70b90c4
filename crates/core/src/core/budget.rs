//! Hard limits on one evaluation, checked explicitly as work is done.
//!
//! One [`Budget`] travels through evaluation, meshing and export. Every stage
//! asks it before doing work (`charge_*`, `reserve_memory`), and it answers
//! with a typed [`LimitExceeded`] naming the limit, the configured value and
//! the value that would have been reached. Nothing is allocated first and
//! checked after, so a hostile grammar cannot run the process out of memory.

use serde::{Deserialize, Serialize};
use std::time::{Duration, Instant};

/// The limits a request runs under. Defaults suit a phone icon; each may be
/// raised by a request up to [`Limits::ceiling`].
///
/// The default primitive limit is 1,000,000, the shapes of Context Free's
/// own performance test (`tests/perftest.cfdg`, which cfdg draws with no
/// limit of its own; docs/cfdg.md). A flat 2D shape is a mark of about a
/// hundred bytes, so a million of them fit the default memory limit; for
/// the 3D languages the triangle limit (an MDG box is 12 triangles) and the
/// memory limit bind long before the primitive limit does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(default)]
pub struct Limits {
    /// Deepest rule-call nesting allowed (the start rule is depth 0).
    pub max_depth: u32,
    /// Most primitive instances in the scene.
    pub max_primitives: u64,
    /// Most triangles in the output mesh.
    pub max_triangles: u64,
    /// Most bytes of accounted memory (scene, evaluation stack, mesh and output buffers).
    pub max_memory: u64,
    /// Wall-clock limit in milliseconds for evaluation, meshing and export together.
    pub timeout_ms: u64,
    /// Largest accepted source, in bytes.
    pub max_source_bytes: u64,
    /// Most evaluation steps (rule expansions and iterator copies). Unlike the
    /// deadline this is deterministic, so runaway grammars fail the same way everywhere.
    pub max_steps: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_depth: 1_000,
            max_primitives: 1_000_000,
            max_triangles: 2_000_000,
            max_memory: 256 * 1024 * 1024,
            timeout_ms: 10_000,
            max_source_bytes: 1024 * 1024,
            max_steps: 10_000_000,
        }
    }
}

/// The default memory limit of a print (`print=true`), in bytes: 640 MiB.
///
/// Why a default of its own: a print's union and simplification hold
/// Manifold's data, about 600 bytes a triangle while it unites and 540
/// while it simplifies (issue 38, docs/print.md "Memory"), and now that the
/// print stage charges that, the library's heaviest prints need up to
/// 609 MiB (spiral-rings; the bush 572, plant-e 602). At 256 MiB, twelve
/// prints that used to succeed (while really holding up to 640 MB against
/// the 256 MiB they promised) would be refused; 640 MiB keeps every one of
/// them printing, honestly charged. A server's ceiling still clamps it
/// (`RULEMESH_CEILING_MEMORY`).
pub const PRINT_MAX_MEMORY: u64 = 640 * 1024 * 1024;

/// The default deadline of a print (`print=true`), in milliseconds: 30 s.
///
/// Why a deadline of its own, as [`PRINT_MAX_MEMORY`] is a memory limit of
/// its own: a print unites and simplifies every triangle through Manifold
/// (Cabiddu et al., *Manifold*, 2022–2026), which on two cores takes
/// seconds where the other routes take milliseconds. spiral-rings takes
/// 9.4 s alone against the ordinary 10 s, so issue 38's load run (eight
/// clients, two renders at a time) ended a third of its prints at the
/// deadline: a typed 504, but a print that succeeds alone must not fail
/// because another print shares the cores. 30 s holds the heaviest library
/// print beside another with room to spare, and a server's ceiling still
/// clamps it (`RULEMESH_CEILING_TIMEOUT_MS`, 60 s by default).
pub(crate) const PRINT_TIMEOUT_MS: u64 = 30_000;

impl Limits {
    /// The defaults of a request: [`Limits::default`], with the memory
    /// limit [`PRINT_MAX_MEMORY`] and the deadline [`PRINT_TIMEOUT_MS`] for
    /// a print.
    pub fn defaults_for(print: bool) -> Limits {
        let d = Limits::default();
        if print {
            Limits { max_memory: PRINT_MAX_MEMORY, timeout_ms: PRINT_TIMEOUT_MS, ..d }
        } else {
            d
        }
    }

    /// The configured value of `limit` (the deadline in milliseconds).
    pub fn value(&self, limit: Limit) -> u64 {
        match limit {
            Limit::Depth => self.max_depth.into(),
            Limit::Primitives => self.max_primitives,
            Limit::Triangles => self.max_triangles,
            Limit::Memory => self.max_memory,
            Limit::Deadline => self.timeout_ms,
            Limit::SourceBytes => self.max_source_bytes,
            Limit::Steps => self.max_steps,
        }
    }

    /// The largest value any request may ask for.
    pub fn ceiling() -> Limits {
        Limits {
            max_depth: 100_000,
            max_primitives: 50_000_000,
            max_triangles: 1_000_000_000,
            max_memory: 16 * 1024 * 1024 * 1024,
            timeout_ms: 600_000,
            max_source_bytes: 16 * 1024 * 1024,
            max_steps: 2_000_000_000,
        }
    }

    /// Each field lowered to at most the matching field of `ceiling`.
    pub fn clamped_to(self, ceiling: &Limits) -> Limits {
        Limits {
            max_depth: self.max_depth.min(ceiling.max_depth),
            max_primitives: self.max_primitives.min(ceiling.max_primitives),
            max_triangles: self.max_triangles.min(ceiling.max_triangles),
            max_memory: self.max_memory.min(ceiling.max_memory),
            timeout_ms: self.timeout_ms.min(ceiling.timeout_ms),
            max_source_bytes: self.max_source_bytes.min(ceiling.max_source_bytes),
            max_steps: self.max_steps.min(ceiling.max_steps),
        }
    }
}

/// Which limit ran out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Limit {
    /// [`Limits::max_depth`]
    Depth,
    /// [`Limits::max_primitives`]
    Primitives,
    /// [`Limits::max_triangles`]
    Triangles,
    /// [`Limits::max_memory`]
    Memory,
    /// [`Limits::timeout_ms`]
    Deadline,
    /// [`Limits::max_source_bytes`]
    SourceBytes,
    /// [`Limits::max_steps`]
    Steps,
}

impl Limit {
    /// The limit's name as used in errors and metrics.
    pub fn name(self) -> &'static str {
        match self {
            Limit::Depth => "depth",
            Limit::Primitives => "primitives",
            Limit::Triangles => "triangles",
            Limit::Memory => "memory",
            Limit::Deadline => "deadline",
            Limit::SourceBytes => "source_bytes",
            Limit::Steps => "steps",
        }
    }
}

/// A limit was exceeded: which, what it was set to, and what would have been reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, thiserror::Error)]
#[error("limit exceeded: {} (configured {configured}, reached {reached})", limit.name())]
pub struct LimitExceeded {
    /// The limit.
    pub limit: Limit,
    /// Its configured value.
    pub configured: u64,
    /// The value the work would have reached (at least `configured + 1`).
    pub reached: u64,
}

/// What to do when a limit runs out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OnLimit {
    /// Fail with [`LimitExceeded`].
    #[default]
    Error,
    /// Stop and return what was made so far, marked truncated.
    Truncate,
}

crate::choice!(OnLimit { Error => "error", Truncate => "truncate" });

/// Running counters checked against [`Limits`].
#[derive(Debug)]
pub struct Budget {
    limits: Limits,
    started: Instant,
    deadline: Option<Instant>,
    primitives: u64,
    triangles: u64,
    memory: u64,
    /// The most accounted memory held at once so far: what the limit
    /// bounds, compared with the process's real peak in the print tests.
    memory_peak: u64,
    steps: u64,
    /// Where the current stage's share of the deadline ends, when the
    /// pipeline gave it one (under `on_limit: truncate`, so the stages after
    /// a truncated one still finish within the deadline).
    stage_deadline: Option<Instant>,
}

/// The counters of a [`Budget`] at one moment, to [`Budget::rewind`] to.
///
/// A front end that abandons one route for another (an L-system whose
/// instancing DAG did not fit falls back to its string) refunds the work
/// it threw away; the clock is never rewound, so the deadline still holds
/// for the whole request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BudgetMark {
    primitives: u64,
    triangles: u64,
    memory: u64,
    steps: u64,
}


impl LimitExceeded {
    /// A limit crossed by a count kept outside a [`Budget`] (Context Free's
    /// user-function calls, counted on a shared scope while the budget is
    /// borrowed elsewhere): `reached` is never reported below one past
    /// `configured`, as the budget's own errors never are.
    pub fn crossed(limit: Limit, configured: u64, reached: u64) -> LimitExceeded {
        LimitExceeded { limit, configured, reached: reached.max(configured.saturating_add(1)) }
    }

    /// A limit read back from a file that records only that a limit cut the
    /// model short (the `scene` format's truncated flag), not the values.
    pub fn recorded(limit: Limit) -> LimitExceeded {
        LimitExceeded { limit, configured: 0, reached: 0 }
    }

    /// The deadline error for a render stopped from outside its budget (the
    /// service's watchdog, when the pipeline ran past its deadline without
    /// noticing): `elapsed_ms` is reported as reached, and never less than
    /// one past the deadline, so the error always says the limit was crossed.
    pub fn deadline_passed(deadline_ms: u64, elapsed_ms: u64) -> LimitExceeded {
        LimitExceeded { limit: Limit::Deadline, configured: deadline_ms, reached: elapsed_ms.max(deadline_ms.saturating_add(1)) }
    }
}

impl Budget {
    /// A fresh budget whose deadline starts counting now.
    pub fn new(limits: Limits) -> Budget {
        let started = Instant::now();
        Budget {
            limits,
            started,
            deadline: started.checked_add(Duration::from_millis(limits.timeout_ms)),
            primitives: 0,
            triangles: 0,
            memory: 0,
            memory_peak: 0,
            steps: 0,
            stage_deadline: None,
        }
    }

    /// Moves this budget out (to an engine that must own it, like the
    /// JavaScript sandbox's shared state), leaving behind a spent budget with
    /// the same limits whose deadline has already passed, so that nothing can
    /// mistake the placeholder for a fresh budget. Put the budget back with
    /// plain assignment when the engine is done.
    pub fn take(&mut self) -> Budget {
        let spent = self.spent();
        std::mem::replace(self, spent)
    }

    /// A placeholder for this budget while it is lent out (see
    /// [`Budget::take`]): the same limits and start, a deadline already passed.
    pub fn spent(&self) -> Budget {
        Budget {
            limits: self.limits,
            started: self.started,
            deadline: Some(self.started),
            primitives: 0,
            triangles: 0,
            memory: 0,
            memory_peak: 0,
            steps: 0,
            stage_deadline: None,
        }
    }

    /// Removes the deadline, for the one write that may follow it: under
    /// `on_limit: truncate`, a model that could not be written before the
    /// deadline is replaced by an empty one marked truncated, whose writing
    /// is a fixed, tiny amount of work. Nothing else calls this.
    pub fn lift_deadline(&mut self) {
        self.deadline = None;
        self.stage_deadline = None;
    }

    /// The counters now, to rewind to when a route is abandoned.
    pub fn mark(&self) -> BudgetMark {
        BudgetMark { primitives: self.primitives, triangles: self.triangles, memory: self.memory, steps: self.steps }
    }

    /// Puts the counters back to `mark` (the work since was thrown away and
    /// its memory freed). The clock and the deadline are not touched.
    pub fn rewind(&mut self, mark: BudgetMark) {
        self.primitives = mark.primitives;
        self.triangles = mark.triangles;
        self.memory = mark.memory;
        self.steps = mark.steps;
    }

    /// Fails when a total the caller computed (segments of a derivation, steps
    /// it will take, memory it will need) exceeds the configured `limit`,
    /// before the work is done. Nothing is charged.
    pub fn check_total(&self, limit: Limit, reached: u64) -> Result<(), LimitExceeded> {
        Self::check_value(limit, self.limits.value(limit), reached)
    }

    /// Fails when `reached` exceeds `configured` for `limit`: for limits the
    /// caller derives from the configured ones (a JavaScript script's loaded
    /// text shares the source-size limit).
    pub fn check_value(limit: Limit, configured: u64, reached: u64) -> Result<(), LimitExceeded> {
        if reached > configured {
            return Err(Self::exceeded(limit, configured, reached));
        }
        Ok(())
    }

    /// Fails when reserving `bytes` more would exceed the memory limit,
    /// without reserving them (for callers that allocate in pieces).
    pub fn check_memory(&self, bytes: u64) -> Result<(), LimitExceeded> {
        self.check_total(Limit::Memory, self.memory.saturating_add(bytes))
    }

    /// The memory limit, refused for `bytes` more whatever the limit: for
    /// allocations that cannot be made at all (more vertices than 32-bit
    /// indices address) and for an engine with its own allocator (the
    /// JavaScript sandbox) that ran out of what it was given. The value
    /// reached is what the allocation would have brought, at least one byte
    /// over the limit.
    pub fn memory_refused(&self, bytes: u64) -> LimitExceeded {
        let reached = self.memory.saturating_add(bytes).max(self.limits.max_memory.saturating_add(1));
        Self::exceeded(Limit::Memory, self.limits.max_memory, reached)
    }

    /// Gives the stage that runs next only the time until `fraction` of the
    /// deadline has passed (`None`: the whole deadline again). The pipeline
    /// does this under `on_limit: truncate`, so that evaluation cut short at
    /// its share still leaves meshing and export the time to finish.
    pub fn set_stage_share(&mut self, fraction: Option<f64>) {
        self.stage_deadline = fraction.and_then(|f| {
            let ms = (self.limits.timeout_ms as f64 * f.clamp(0.0, 1.0)) as u64;
            self.started.checked_add(Duration::from_millis(ms))
        });
    }

    /// The limits this budget enforces.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// Primitives charged so far.
    pub fn primitives(&self) -> u64 {
        self.primitives
    }

    /// Triangles charged so far.
    pub fn triangles(&self) -> u64 {
        self.triangles
    }

    /// Accounted memory in use.
    pub fn memory(&self) -> u64 {
        self.memory
    }

    /// The most accounted memory held at once since the budget was made
    /// (a rewind does not lower it: the abandoned route's memory was held).
    pub(crate) fn memory_peak(&self) -> u64 {
        self.memory_peak
    }

    /// Evaluation steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    fn exceeded(limit: Limit, configured: u64, reached: u64) -> LimitExceeded {
        LimitExceeded { limit, configured, reached }
    }

    /// Checks a depth before descending to it.
    pub fn check_depth(&self, depth: u32) -> Result<(), LimitExceeded> {
        if depth > self.limits.max_depth {
            return Err(Self::exceeded(Limit::Depth, self.limits.max_depth.into(), depth.into()));
        }
        Ok(())
    }

    /// Counts one evaluation step; every 1024 steps also checks the clock.
    #[inline]
    pub fn charge_step(&mut self) -> Result<(), LimitExceeded> {
        self.steps += 1;
        if self.steps > self.limits.max_steps {
            return Err(Self::exceeded(Limit::Steps, self.limits.max_steps, self.steps));
        }
        if self.steps % 1024 == 0 {
            self.check_deadline()?;
        }
        Ok(())
    }

    /// Counts `n` evaluation steps at once (work proportional to a known size,
    /// such as an isosurface grid), checking the clock once.
    pub fn charge_steps(&mut self, n: u64) -> Result<(), LimitExceeded> {
        self.steps = self.steps.saturating_add(n);
        if self.steps > self.limits.max_steps {
            return Err(Self::exceeded(Limit::Steps, self.limits.max_steps, self.steps));
        }
        self.check_deadline()
    }

    /// Counts one primitive with `triangles` triangles.
    #[inline]
    pub fn charge_primitive(&mut self, triangles: u64) -> Result<(), LimitExceeded> {
        let p = self.primitives + 1;
        if p > self.limits.max_primitives {
            return Err(Self::exceeded(Limit::Primitives, self.limits.max_primitives, p));
        }
        self.charge_triangles(triangles)?;
        self.primitives = p;
        Ok(())
    }

    /// Counts triangles (from primitives or free geometry).
    pub fn charge_triangles(&mut self, triangles: u64) -> Result<(), LimitExceeded> {
        let t = self.triangles.saturating_add(triangles);
        if t > self.limits.max_triangles {
            return Err(Self::exceeded(Limit::Triangles, self.limits.max_triangles, t));
        }
        self.triangles = t;
        Ok(())
    }

    /// Accounts `bytes` more memory before it is allocated.
    #[inline]
    pub fn reserve_memory(&mut self, bytes: u64) -> Result<(), LimitExceeded> {
        let m = self.memory.saturating_add(bytes);
        if m > self.limits.max_memory {
            return Err(Self::exceeded(Limit::Memory, self.limits.max_memory, m));
        }
        self.memory = m;
        self.memory_peak = self.memory_peak.max(m);
        Ok(())
    }

    /// Returns accounted memory that has been freed.
    pub fn release_memory(&mut self, bytes: u64) {
        self.memory = self.memory.saturating_sub(bytes);
    }

    /// Fails once the wall-clock deadline has passed.
    ///
    /// Under a stage share ([`Budget::set_stage_share`]) the share's end
    /// counts as the deadline, and the error names the share in milliseconds.
    pub fn check_deadline(&self) -> Result<(), LimitExceeded> {
        let (end, configured) = match (self.deadline, self.stage_deadline) {
            (Some(d), Some(s)) if s < d => (Some(s), s.saturating_duration_since(self.started).as_millis().try_into().unwrap_or(u64::MAX)),
            (d, _) => (d, self.limits.timeout_ms),
        };
        match end {
            Some(d) if Instant::now() >= d => Err(Self::exceeded(Limit::Deadline, configured, self.elapsed().as_millis().try_into().unwrap_or(u64::MAX))),
            _ => Ok(()),
        }
    }

    /// A stop test for the loops that ask a `stop: &dyn Fn() -> bool`
    /// whether to give up (welding, the preview's closed-solid test and
    /// projection): [`DeadlineStop::stop`] says true once the deadline has
    /// passed and records the [`LimitExceeded`] it saw, and
    /// [`DeadlineStop::error`] returns it, so that a caller returns the
    /// deadline by name instead of building a fallback error of its own for
    /// a stop it cannot tell apart.
    pub fn deadline_stop(&self) -> DeadlineStop<'_> {
        DeadlineStop { budget: self, seen: std::cell::Cell::new(None) }
    }

    /// Time left before [`Budget::check_deadline`] fails (zero once it
    /// has), or `None` without a deadline: for work that cannot check the
    /// deadline itself and must be told when to stop (a Manifold union).
    pub fn time_left(&self) -> Option<Duration> {
        let end = match (self.deadline, self.stage_deadline) {
            (Some(d), Some(s)) => Some(d.min(s)),
            (d, _) => d,
        }?;
        Some(end.saturating_duration_since(Instant::now()))
    }

    /// Time since the budget was created.
    pub fn elapsed(&self) -> Duration {
        self.started.elapsed()
    }

    /// Checks a source length against [`Limits::max_source_bytes`].
    pub fn check_source(limits: &Limits, len: u64) -> Result<(), LimitExceeded> {
        if len > limits.max_source_bytes {
            return Err(Self::exceeded(Limit::SourceBytes, limits.max_source_bytes, len));
        }
        Ok(())
    }
}

/// The deadline as a stop test that remembers why it said stop
/// ([`Budget::deadline_stop`]).
pub struct DeadlineStop<'a> {
    budget: &'a Budget,
    seen: std::cell::Cell<Option<LimitExceeded>>,
}

impl DeadlineStop<'_> {
    /// True once the deadline has passed; the error is kept for [`DeadlineStop::error`].
    pub fn stop(&self) -> bool {
        match self.budget.check_deadline() {
            Ok(()) => false,
            Err(e) => {
                self.seen.set(Some(e));
                true
            }
        }
    }

    /// Why [`DeadlineStop::stop`] said stop. The loops it serves give up
    /// only when told to, so this is the error `stop` saw; asked before any
    /// stop, it is the deadline as configured, reached now.
    pub fn error(&self) -> LimitExceeded {
        self.seen.take().unwrap_or_else(|| {
            let reached = self.budget.elapsed().as_millis().try_into().unwrap_or(u64::MAX);
            Budget::exceeded(Limit::Deadline, self.budget.limits.timeout_ms, reached)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_deadline_stop_returns_the_deadline_it_saw() {
        let b = Budget::new(Limits { timeout_ms: 1, ..Limits::default() });
        std::thread::sleep(Duration::from_millis(5));
        let watch = b.deadline_stop();
        assert!(watch.stop());
        assert_eq!(watch.error().limit, Limit::Deadline);
        let fresh = Budget::new(Limits::default());
        assert!(!fresh.deadline_stop().stop());
    }

    #[test]
    fn each_counter_names_its_limit() {
        let limits = Limits { max_primitives: 2, max_triangles: 30, max_memory: 100, max_steps: 3, ..Limits::default() };
        let mut b = Budget::new(limits);
        b.charge_primitive(12).unwrap();
        b.charge_primitive(12).unwrap();
        let e = b.charge_primitive(1).unwrap_err();
        assert_eq!((e.limit, e.configured, e.reached), (Limit::Primitives, 2, 3));
        let mut b = Budget::new(limits);
        b.charge_primitive(20).unwrap();
        let e = b.charge_primitive(20).unwrap_err();
        assert_eq!((e.limit, e.configured, e.reached), (Limit::Triangles, 30, 40));
        let mut b = Budget::new(limits);
        b.reserve_memory(60).unwrap();
        assert_eq!(b.reserve_memory(41).unwrap_err().reached, 101);
        b.release_memory(60);
        b.reserve_memory(41).unwrap();
        // The peak is the most held at once, refused reservations not counted.
        assert_eq!((b.memory(), b.memory_peak()), (41, 60));
        let mut b = Budget::new(limits);
        for _ in 0..3 {
            b.charge_step().unwrap();
        }
        assert_eq!(b.charge_step().unwrap_err().limit, Limit::Steps);
        assert_eq!(b.check_depth(1001).unwrap_err().limit, Limit::Depth);
    }

    #[test]
    fn zero_timeout_expires_immediately() {
        let b = Budget::new(Limits { timeout_ms: 0, ..Limits::default() });
        assert_eq!(b.check_deadline().unwrap_err().limit, Limit::Deadline);
    }

    #[test]
    fn a_deadline_passed_from_outside_names_the_deadline_and_a_value_past_it() {
        let e = LimitExceeded::deadline_passed(1000, 1500);
        assert_eq!((e.limit, e.configured, e.reached), (Limit::Deadline, 1000, 1500));
        // A watchdog that fires on the tick of the deadline still reports it crossed.
        assert_eq!(LimitExceeded::deadline_passed(1000, 1000).reached, 1001);
    }

    #[test]
    fn time_left_counts_down_to_the_deadline_or_the_stage_share() {
        let mut b = Budget::new(Limits { timeout_ms: 10_000, ..Limits::default() });
        let left = b.time_left().unwrap();
        assert!(left <= Duration::from_millis(10_000) && left > Duration::from_millis(9_000), "{left:?}");
        b.set_stage_share(Some(0.5));
        assert!(b.time_left().unwrap() <= Duration::from_millis(5_000));
        b.lift_deadline();
        assert_eq!(b.time_left(), None);
        let b = Budget::new(Limits { timeout_ms: 0, ..Limits::default() });
        assert_eq!(b.time_left(), Some(Duration::ZERO));
    }

    #[test]
    fn clamping_respects_the_ceiling() {
        let big = Limits { max_primitives: u64::MAX, ..Limits::default() };
        assert_eq!(big.clamped_to(&Limits::ceiling()).max_primitives, Limits::ceiling().max_primitives);
    }
}
