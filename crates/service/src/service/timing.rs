//! Where one request's time went, as its `Server-Timing` header (HTTP), its
//! `server-timing` response metadata (gRPC) and the fields of its DEBUG log
//! line (`access_log`) all say it: the wait for a render slot, each pipeline stage that ran, and
//! the cache lookup. The same struct formats all three, so they agree.

use crate::cache::{CacheOutcome, Lookup};
use crate::core::timing::{Phase, PhaseTimes};
use std::time::Duration;

/// The render this request ran itself (absent on a hit, or when it shared
/// another request's render).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RanRender {
    /// The wait for a render slot.
    pub queue: Duration,
    /// The stages of the pipeline.
    pub phases: PhaseTimes,
}

/// One request's timing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RequestTiming {
    /// The cache's account of the lookup.
    pub lookup: Lookup,
    /// The render, when this request ran one.
    pub ran: Option<RanRender>,
}

/// A duration in milliseconds, as the header, the log fields and the
/// access log write them.
pub(super) fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

/// Appends `d` in milliseconds with three decimals (whole microseconds,
/// half a microsecond rounded up), in integers: `{:.3}` of a float, six
/// times per header, was a microsecond of each fresh render's CPU.
///
/// Written with `itoa` and three digits by hand, in `u64` (a `Duration`'s
/// nanoseconds are a `u128`, whose division is a library call):
/// `core::fmt` with its padding was still most of the header's cost.
fn push_ms(s: &mut String, d: Duration) {
    let ns = u64::try_from(d.as_nanos()).unwrap_or(u64::MAX);
    let us = ns.saturating_add(500) / 1000;
    s.push_str(itoa::Buffer::new().format(us / 1000));
    s.push('.');
    let frac = us % 1000;
    for digit in [frac / 100, frac / 10 % 10, frac % 10] {
        s.push(char::from(b'0' + digit as u8));
    }
}

impl RequestTiming {
    /// The timed parts, in the order they happened: `queue` (when a render
    /// ran), each stage that ran, and `cache` (the lookups). They never
    /// overlap, so they add up to at most the request's wall time.
    pub fn parts(&self) -> Vec<(&'static str, Duration)> {
        let mut parts = Vec::with_capacity(7);
        if let Some(r) = &self.ran {
            parts.push(("queue", r.queue));
            parts.extend(r.phases.ran().map(|(p, d)| (p.name(), d)));
        }
        parts.push(("cache", self.lookup.took));
        parts
    }

    /// The `Server-Timing` value (W3C Server Timing; durations in
    /// milliseconds): `queue;dur=0.004, parse;dur=0.210, eval;dur=1.020,
    /// mesh;dur=0.800, export;dur=0.310, cache;desc=miss;dur=0.015`, and on
    /// a hit `cache;desc=hit;dur=0.002, tier;desc=memory`.
    pub(crate) fn header_value(&self) -> String {
        // Room for every stage and the cache's part: one allocation.
        let mut s = String::with_capacity(192);
        for (name, d) in self.parts() {
            if !s.is_empty() {
                s.push_str(", ");
            }
            if name == "cache" {
                s.push_str(if self.lookup.outcome == CacheOutcome::Hit { "cache;desc=hit;dur=" } else { "cache;desc=miss;dur=" });
            } else {
                s.push_str(name);
                s.push_str(";dur=");
            }
            push_ms(&mut s, d);
        }
        if let Some(t) = self.lookup.tier {
            s.push_str(", tier;desc=");
            s.push_str(t.name());
        }
        s
    }

    /// A stage's time in milliseconds, when it ran (for log fields).
    pub(crate) fn stage_ms(&self, phase: Phase) -> Option<f64> {
        self.ran.filter(|r| r.phases.did_run(phase)).map(|r| ms(r.phases.get(phase)))
    }

    /// The queue wait in milliseconds, when a render ran.
    pub(crate) fn queue_ms(&self) -> Option<f64> {
        self.ran.map(|r| ms(r.queue))
    }

    /// The cache lookups' time in milliseconds.
    pub fn cache_ms(&self) -> f64 {
        ms(self.lookup.took)
    }

}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cache::Tier;
    use crate::core::timing::StageClock;

    #[test]
    fn header_lists_what_ran() {
        let mut clock = StageClock::start();
        clock.lap(Phase::Parse);
        clock.lap(Phase::Eval);
        clock.lap(Phase::Mesh);
        clock.lap(Phase::Export);
        let miss = RequestTiming {
            lookup: Lookup { outcome: CacheOutcome::Miss, tier: None, took: Duration::from_micros(15) },
            ran: Some(RanRender { queue: Duration::from_micros(4), phases: clock.phases }),
        };
        let h = miss.header_value();
        let names: Vec<&str> = h.split(", ").map(|p| p.split(';').next().unwrap_or("")).collect();
        assert_eq!(names, ["queue", "parse", "eval", "mesh", "export", "cache"], "{h}");
        assert!(h.ends_with("cache;desc=miss;dur=0.015"), "{h}");
        let hit = RequestTiming { lookup: Lookup { outcome: CacheOutcome::Hit, tier: Some(Tier::Redis), took: Duration::from_micros(800) }, ran: None };
        assert_eq!(hit.header_value(), "cache;desc=hit;dur=0.800, tier;desc=redis");
    }

    /// `push_ms` writes what `format!("{}.{:03}")` of the rounded
    /// microseconds wrote before it was done by hand.
    #[test]
    fn milliseconds_are_written_as_format_wrote_them() {
        for ns in [0u64, 1, 499, 500, 999, 1_000, 15_000, 999_499, 999_500, 1_234_567, 12_345_678_901, 86_400_000_000_000] {
            let d = Duration::from_nanos(ns);
            let us = d.as_nanos().saturating_add(500) / 1000;
            let mut s = String::new();
            push_ms(&mut s, d);
            assert_eq!(s, format!("{}.{:03}", us / 1000, us % 1000), "{ns} ns");
        }
    }
}
