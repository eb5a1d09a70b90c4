//! Every committed fuzz seed (`fuzz/seeds/`), replayed through the same
//! drivers as the fuzz targets on the stable toolchain: the render targets
//! through `fuzz/src/lib.rs` itself, the decoders with the targets' checks.
//! The libFuzzer runs (nightly, sanitizers) are `scripts/fuzz`
//! (docs/reliability.md); this keeps every seed and every past finding a
//! regression test in the normal suite.

#[path = "../../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod fuzz_lib;

use crate::common::repo;
use rulemesh::lang::Language;

/// The files of `fuzz/seeds/<target>/`, sorted (at least one).
fn seeds(target: &str) -> Vec<Vec<u8>> {
    let dir = repo().join("fuzz/seeds").join(target);
    let mut files: Vec<_> = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())).map(|e| e.expect("entry").path()).collect();
    files.sort();
    assert!(!files.is_empty(), "no seeds for {target}");
    files.iter().map(|f| std::fs::read(f).expect("read seed")).collect()
}

#[test]
fn every_render_seed_replays_without_a_panic() {
    for (target, language) in [
        ("render_mdg", Language::Mdg),
        ("render_lsystem", Language::Lsystem),
        ("render_eisen", Language::Eisenscript),
        ("render_etol", Language::Etol),
        ("render_stack", Language::Stack),
        ("render_ug", Language::Ug),
    ] {
        for data in seeds(target) {
            fuzz_lib::render(language, &data);
        }
    }
}

#[test]
fn every_decoder_seed_replays_without_a_panic() {
    for data in seeds("decode_strips") {
        if let Ok(d) = rulemesh::decode::strips::decode_strips_full(&data) {
            let n = d.mesh.positions.len();
            assert!(d.mesh.indices.iter().all(|&i| (i as usize) < n), "index out of range in a decoded mesh");
        }
    }
    for data in seeds("decode_scene") {
        if let Ok(h) = rulemesh::decode::scene::decode_scene(&data) {
            let _ = h.leaves();
        }
    }
}
