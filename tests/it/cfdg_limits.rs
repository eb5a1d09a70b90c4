//! A CFDG design at a budget limit (issue 34): under `on_limit: truncate`
//! the render keeps the shapes finished before the limit, which are the
//! ones `cfdg -m N+1` draws (both expand the largest unfinished shape
//! first, and cfdg stops when its finished or unfinished shapes reach N+1),
//! and says so; under `error` it is the typed error naming the limit.

use crate::common::tempdir;
use rulemesh::core::{Limit, Limits, OnLimit};
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderError, RenderRequest};
use std::process::Command;

/// The bush benchmark's design (bench/bush-262k.cfdg): a square and two
/// smaller copies of itself, without end but for the minimum size.
fn bush() -> Vec<u8> {
    std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/bench/bush-262k.cfdg")).expect("bench design")
}

fn request(max_primitives: u64, on_limit: OnLimit) -> RenderRequest {
    RenderRequest { language: Some(Language::Cfdg), format: Format::Svg, limits: Limits { max_primitives, ..Limits::default() }, on_limit, ..RenderRequest::default() }
}

#[test]
fn truncation_keeps_the_shapes_cfdg_m_draws() {
    // 4 095 squares are the bush's first 12 generations, whole.
    let out = render(&bush(), &request(4095, OnLimit::Truncate)).expect("a partial result");
    let t = out.truncated.expect("the result says it was cut");
    assert_eq!((t.limit, t.configured, t.reached), (Limit::Primitives, 4095, 4096));
    assert_eq!(out.primitives, 4095);
    let dir = tempdir();
    let svg = dir.path().join("c.svg");
    let status = Command::new("cfdg")
        .args(["-q", "-s", "500", "-m", "4096", "-V"])
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/bench/bush-262k.cfdg"))
        .arg(&svg)
        .status()
        .expect("cfdg runs (scripts/test installs Debian's contextfree)");
    assert!(status.success());
    let compare = Command::new("python3")
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/cfdg-compare.py"))
        .arg(&svg)
        .arg({
            let p = dir.path().join("r.svg");
            std::fs::write(&p, &out.bytes).expect("write");
            p
        })
        .output()
        .expect("python3 runs");
    let verdict = String::from_utf8_lossy(&compare.stdout);
    assert!(verdict.starts_with("SAME shapes=4095 "), "{verdict}");
}

#[test]
fn the_limit_is_a_typed_error_without_truncation() {
    match render(&bush(), &request(4095, OnLimit::Error)) {
        Err(RenderError::Limit(e)) => assert_eq!((e.limit, e.configured, e.reached), (Limit::Primitives, 4095, 4096)),
        other => panic!("expected the primitives limit, got {:?}", other.map(|o| o.primitives)),
    }
}
