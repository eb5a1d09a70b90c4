//! The process's real memory at a stage boundary, against what the budget
//! charges: how the print stage's per-element costs were calibrated
//! (issue 38, docs/print.md "Memory").
//!
//! With `RULEMESH_MEMORY_TRACE=1` in the environment, each [`mark`] writes
//! one line to standard error: the stage that just ended, the accounted
//! memory now and at its peak, the resident size now, and the highest
//! resident size since the previous mark (the kernel's `VmHWM`, reset at
//! each mark through `/proc/self/clear_refs`). Without the variable a mark
//! does nothing but read it once per process. Meant for one render per
//! process (the CLI): resident memory is the whole process's.

use super::budget::Budget;
use std::sync::OnceLock;

/// Whether tracing is on (read once).
fn enabled() -> bool {
    static ON: OnceLock<bool> = OnceLock::new();
    *ON.get_or_init(|| std::env::var_os("RULEMESH_MEMORY_TRACE").is_some_and(|v| v == "1"))
}

/// A field of `/proc/self/status` in bytes (`VmRSS`, `VmHWM`); `None` without it.
pub(crate) fn status_bytes(field: &str) -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/status").ok()?;
    parse_status(&text, field)
}

/// `field` of a `/proc/PID/status` text (given in kB there) in bytes.
pub(crate) fn parse_status(text: &str, field: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.strip_prefix(field).is_some_and(|r| r.starts_with(':')))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb.saturating_mul(1024))
}

/// Resets the kernel's resident high-water mark to the resident size now
/// (writing 5 to `/proc/self/clear_refs`); false where that is not allowed.
pub(crate) fn reset_peak() -> bool {
    std::fs::write("/proc/self/clear_refs", "5").is_ok()
}

/// Writes the trace line for the end of `stage` (when tracing is on) and
/// starts the next interval.
pub fn mark(stage: &str, budget: &Budget) {
    if !enabled() {
        return;
    }
    let mib = |b: Option<u64>| b.map_or(-1.0, |b| b as f64 / 1048576.0);
    eprintln!(
        "memory-trace stage={stage} charged_mib={:.1} charged_peak_mib={:.1} rss_mib={:.1} rss_peak_mib={:.1}",
        mib(Some(budget.memory())),
        mib(Some(budget.memory_peak())),
        mib(status_bytes("VmRSS")),
        mib(status_bytes("VmHWM"))
    );
    reset_peak();
}

/// Writes `what=value` (an element count a stage's cost is calibrated
/// by: triangles, samples) when tracing is on.
pub fn note(what: &str, value: u64) {
    if enabled() {
        eprintln!("memory-trace note {what}={value}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn status_fields_are_read_in_bytes() {
        let text = "Name:\trulemesh\nVmHWM:\t  637012 kB\nVmRSS:\t   20480 kB\n";
        assert_eq!(parse_status(text, "VmHWM"), Some(637_012 * 1024));
        assert_eq!(parse_status(text, "VmRSS"), Some(20_480 * 1024));
        assert_eq!(parse_status(text, "VmRS"), None);
        let peak = status_bytes("VmHWM").expect("linux");
        assert!(peak >= status_bytes("VmRSS").expect("linux") / 2);
    }
}
