//! Hostile grammars end in a clear, typed error — never a crash, hang or OOM.
//! Each runs under `--max-memory 64000000` inside GNU time, and the process's
//! peak resident set must stay below 128 MB.

use crate::common::bin;
use std::process::{Command, Stdio};

/// Peak RSS in bytes, exit code and stderr of one `rulemesh render` run under GNU time.
fn run_measured(source: &[u8], extra: &[&str]) -> (u64, Option<i32>, String) {
    let dir = crate::common::tempdir();
    let src = dir.path().join("hostile.mdg");
    std::fs::write(&src, source).expect("write source");
    let out_file = dir.path().join("out.glb");
    let mut cmd = Command::new("/usr/bin/time");
    cmd.arg("-v")
        .arg(bin())
        .args(["render", src.to_str().expect("utf-8"), "-o", out_file.to_str().expect("utf-8"), "--max-memory", "64000000"])
        .args(extra)
        .stdin(Stdio::null());
    let out = cmd.output().expect("GNU time runs (scripts/test installs it)");
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    let rss = crate::common::max_rss_bytes(&err);
    // GNU time reports the child's status as "Exit status: N".
    let code = err
        .lines()
        .find_map(|l| l.trim().strip_prefix("Exit status:"))
        .and_then(|v| v.trim().parse().ok());
    let signalled = err.contains("Command terminated by signal");
    assert!(!signalled, "rulemesh was killed by a signal:\n{err}");
    (rss, code, err)
}

const RSS_BOUND: u64 = 128 * 1000 * 1000;

fn expect(name: &str, source: &[u8], extra: &[&str], code: i32, message: &str) {
    let (rss, got, err) = run_measured(source, extra);
    assert_eq!(got, Some(code), "{name}: exit code\n{err}");
    assert!(err.contains(message), "{name}: expected `{message}` in\n{err}");
    assert!(rss < RSS_BOUND, "{name}: peak RSS {rss} bytes exceeds {RSS_BOUND}");
}

#[test]
fn infinite_recursion_stops_at_the_depth_limit() {
    expect("recursion", b"startshape A\nrule A { A {} }", &[], 3, "limit exceeded: depth (configured 1000, reached 1001)");
    // With the depth limit raised to the ceiling, the step or memory budget still ends it.
    let (rss, code, err) = run_measured(b"startshape A\nrule A { A { x 1 } }", &["--max-depth", "100000", "--max-steps", "100000000"]);
    assert_eq!(code, Some(3), "{err}");
    assert!(err.contains("limit exceeded"), "{err}");
    assert!(rss < RSS_BOUND, "{rss}");
}

#[test]
fn a_billion_iterations_stop_at_a_limit() {
    // Flat, each box promises ~1.7 kB of mesh and output buffers, so under
    // 64 MB the memory limit binds after ~38 000 boxes, during evaluation.
    expect(
        "billion",
        b"startshape A\nrule A { 1000000000 * {x 1} BOX {} }",
        &["--instancing", "flat"],
        3,
        "limit exceeded: memory (configured 64000000,",
    );
    // Instanced (the default), a repeated box costs its stored placement
    // and 52 bytes of output, about 82 bytes accounted: under 64 MB the
    // memory limit binds after ~780 000 boxes, before the default
    // primitive limit (1 000 000).
    expect(
        "billion-instanced",
        b"startshape A\nrule A { 1000000000 * {x 1} BOX {} }",
        &[],
        3,
        "limit exceeded: memory (configured 64000000,",
    );
    expect(
        "billion-primitives",
        b"startshape A\nrule A { 1000000000 * {x 1} BOX {} }",
        &["--max-primitives", "1000"],
        3,
        "limit exceeded: primitives (configured 1000, reached 1001)",
    );
    expect(
        "billion-triangles",
        b"startshape A\nrule A { 1000000000 * {x 1} BOX {} }",
        &["--max-triangles", "12000", "--instancing", "flat"],
        3,
        "limit exceeded: triangles (configured 12000, reached 12012)",
    );
    // Instanced: the box's 12 triangles once, then one per further box.
    expect(
        "billion-triangles-instanced",
        b"startshape A\nrule A { 1000000000 * {x 1} BOX {} }",
        &["--max-triangles", "12000"],
        3,
        "limit exceeded: triangles (configured 12000, reached 12001)",
    );
}

#[test]
fn exponential_branching_is_bounded() {
    expect("branching", b"startshape A\nmaxdepth 60\nrule A { A {} A {} }", &[], 3, "limit exceeded: steps");
    // Flat, every sphere is made: memory binds first.
    expect(
        "branching-drawing",
        b"startshape A\nmaxdepth 40\nrule A { SPHERE {} A { s 0.9 } A { s 0.9 } }",
        &["--detail", "64", "--max-primitives", "50000000", "--max-triangles", "1000000000", "--instancing", "flat"],
        3,
        "limit exceeded: memory",
    );
    // Instanced, the grammar is memoised into 41 objects (docs/mdg.md §9):
    // the hierarchy knows its 2^41 - 1 leaves before writing one, and the
    // glb would draw one instance per leaf, so the primitive limit refuses it at once.
    expect(
        "branching-drawing-memoised",
        b"startshape A\nmaxdepth 40\nrule A { SPHERE {} A { s 0.9 } A { s 0.9 } }",
        &["--detail", "64", "--max-primitives", "50000000", "--max-triangles", "1000000000"],
        3,
        "limit exceeded: primitives (configured 50000000, reached 2199023255551)",
    );
}

#[test]
fn truncation_returns_a_marked_partial_model_within_memory() {
    let (rss, code, err) = run_measured(
        b"startshape A\nrule A { 1000000000 * {x 1} SPHERE {} }",
        &["--on-limit", "truncate", "--detail", "64", "--max-primitives", "50000000", "--max-triangles", "1000000000"],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("TRUNCATED at memory limit"), "{err}");
    assert!(rss < RSS_BOUND, "{rss}");
}

#[test]
fn deeply_nested_braces_are_a_parse_error() {
    let mut src = b"startshape A\nrule A ".to_vec();
    src.extend(std::iter::repeat(b'{').take(100_000));
    expect("braces", &src, &[], 2, "hostile.mdg:2:");
    let mut src = b"startshape A\nrule A { BOX { s ".to_vec();
    src.extend(std::iter::repeat(b'(').take(100_000));
    expect("parens", &src, &[], 2, "hostile.mdg:2:");
}

#[test]
fn non_finite_numbers_are_errors_with_positions() {
    expect("div0", b"startshape A\nrule A {\n  BOX { s (1/0) }\n}", &[], 2, "hostile.mdg:3:");
    expect("nan", b"startshape A\nrule A {\n  BOX { x (0/0) }\n}", &[], 2, "hostile.mdg:3:");
    expect("inf-literal", b"startshape A\nrule A {\n  BOX { x 1e999 }\n}", &[], 2, "hostile.mdg:3:");
    expect("log0", b"startshape A\nrule A {\n  3 * { rz (log(0)) } BOX { }\n}", &[], 2, "hostile.mdg:3:");
}

#[test]
fn invalid_utf8_is_a_parse_error_with_position() {
    expect("utf8", b"startshape A\nrule A { BOX \xff\xfe { } }", &[], 2, "hostile.mdg:2:");
}

#[test]
fn a_ten_megabyte_source_is_refused() {
    let mut src = b"startshape A\nrule A { BOX {} }\n".to_vec();
    src.extend(std::iter::repeat(b"// padding padding padding padding\n".as_slice()).take(300_000).flatten());
    assert!(src.len() > 10_000_000);
    expect("10MB", &src, &[], 3, "limit exceeded: source_bytes (configured 1048576");
}

#[test]
fn the_wall_clock_deadline_stops_a_long_evaluation() {
    expect(
        "deadline",
        b"startshape A\nmaxdepth 60\nrule A { A {} A {} }",
        &["--max-steps", "2000000000", "--timeout", "50"],
        3,
        "limit exceeded: deadline (configured 50,",
    );
}
