//! Shared pieces of the fuzz targets: tight limits (so one input costs
//! milliseconds, and a runaway grammar is a limit error, not a libFuzzer
//! timeout) and the render driver every language's target uses.

use rulemesh::core::{Limits, OnLimit};
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::RenderRequest;

/// Limits small enough for thousands of executions a second, large enough
/// for the seed grammars to get past parsing into evaluation, meshing and export.
pub fn tight_limits() -> Limits {
    Limits {
        max_depth: 64,
        max_primitives: 2_000,
        max_triangles: 100_000,
        max_memory: 32 * 1024 * 1024,
        timeout_ms: 1_000,
        max_source_bytes: 64 * 1024,
        max_steps: 50_000,
    }
}

/// Renders `data` as `language`: the first byte picks the format (bits
/// 0-6, modulo the number of formats in the registry, so a format added by
/// docs/extending.md's steps is fuzzed with no edit here), the `on_limit`
/// mode (bit 7) and the seed (bits 3-6, so seed and format are not chosen
/// independently: enough for fuzzing, where every byte varies); the rest is
/// the source. Any outcome but a panic (or a libFuzzer timeout or
/// out-of-memory) passes.
pub fn render(language: Language, data: &[u8]) {
    let Some((&options, source)) = data.split_first() else { return };
    let req = RenderRequest {
        language: Some(language),
        format: Format::ALL[usize::from(options & 0x7f) % Format::ALL.len()],
        on_limit: if options & 0x80 != 0 { OnLimit::Truncate } else { OnLimit::Error },
        seed: Some(u64::from((options >> 3) & 0xf)),
        limits: tight_limits(),
        ..RenderRequest::default()
    };
    let _ = rulemesh::render(source, &req);
}
