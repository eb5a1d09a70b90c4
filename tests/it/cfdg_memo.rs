//! Memoised CFDG expansion (issue 34, the bush benchmark): a design whose
//! expansion is provably context-free (`cfdg/eval/run/memo.rs`) is expanded
//! by its compiled bodies, and its SVG is byte for byte the general
//! evaluator's, for every such design among `grammars/`, Context Free's
//! own examples (Debian's `contextfree`, installed by `scripts/test`) and
//! the bush benchmark at several cuts; the bush's scene is 18 objects, as
//! the MDG bush's is.

use crate::common::repo;
use rulemesh::core::{Budget, Limits, OnLimit};
use rulemesh::decode::scene::decode_scene;
use rulemesh::export::Format;
use rulemesh::lang::cfdg::{drawing, eval, parse_checked_in};
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderRequest};
use std::path::{Path, PathBuf};

const EXAMPLES: &str = "/usr/share/doc/contextfree/examples";

/// The SVG (or the error) of `file` rendered with `opts` under `limits`,
/// and whether the run was memoised.
fn svg(file: &Path, opts: &eval::Options, limits: Limits) -> (bool, Result<Vec<u8>, String>) {
    let src = std::fs::read(file).expect("readable");
    let g = match parse_checked_in(&src, file.parent()) {
        Ok(g) => g,
        Err(e) => return (false, Err(e.to_string())),
    };
    let mut budget = Budget::new(limits);
    match eval::render(&g, opts, &mut budget) {
        Ok(p) => {
            let memo = p.memo.is_some();
            let svg = drawing::of(&p, &mut budget).map_err(|e| e.to_string()).and_then(|d| rulemesh::export::svg::write_svg(&d, &mut budget).map_err(|e| e.to_string()));
            (memo, svg)
        }
        Err(e) => (false, Err(e.to_string())),
    }
}

/// Whether `file` is memoised: a run cut after a few steps says so.
fn memoised(file: &Path) -> bool {
    let opts = eval::Options { record: true, on_limit: OnLimit::Truncate, ..eval::Options::default() };
    svg(file, &opts, Limits { max_steps: 4, ..Limits::default() }).0
}

/// Asserts the memoised and the general evaluator draw `file` alike (as
/// a picture is drawn: without recording the nodes, whose memory is
/// charged and so may move a memory cut).
fn same(file: &Path, opts: eval::Options, limits: Limits) {
    let (_, a) = svg(file, &eval::Options { memo: true, record: false, ..opts }, limits);
    let (_, b) = svg(file, &eval::Options { memo: false, ..opts }, limits);
    assert!(a == b, "{} at {limits:?}: the memoised SVG differs from the general evaluator's", file.display());
}

fn cfdg_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap_or_else(|_| panic!("{} missing: scripts/test installs Debian's contextfree", dir.display())).flatten() {
        let p = e.path();
        if p.is_dir() && p.file_name().is_some_and(|n| n != "failing") {
            out.extend(cfdg_files(&p));
        } else if p.extension().is_some_and(|x| x == "cfdg") {
            out.push(p);
        }
    }
    out.sort();
    out
}

#[test]
fn memoised_svg_is_the_general_evaluators_for_every_context_free_design() {
    let mut files = cfdg_files(Path::new(EXAMPLES));
    files.extend(cfdg_files(&repo().join("grammars")));
    let qualifying: Vec<PathBuf> = files.into_iter().filter(|f| memoised(f)).collect();
    let names: Vec<String> = qualifying.iter().filter_map(|f| f.file_name()).map(|n| n.to_string_lossy().into_owned()).collect();
    let expected = [
        "aliastest.cfdg", "chanukah.cfdg", "demo2.cfdg", "demo2_v2.cfdg", "i_curves.cfdg", "i_curves_v2.cfdg", "lesson2.cfdg", "lesson2_v2.cfdg", "octopi.cfdg", "octopi_v2.cfdg", "rendering-tests.cfdg", "sierpinski.cfdg", "sierpinski_v2.cfdg",
        "arraytest2.cfdg", "boundstest.cfdg", "mergexytest1.cfdg", "polytest7.cfdg", "randtest.cfdg", "sattargtest.cfdg", "symmtest1.cfdg", "thingy.cfdg", "thorns.cfdg", "welcome.cfdg", "welcome_v2.cfdg", "xmas.cfdg", "cfdg-spiral.cfdg",
    ];
    assert_eq!(names, expected, "the context-free designs");
    for f in &qualifying {
        for size in [200, 500] {
            same(f, eval::Options { width: size, height: size, ..eval::Options::default() }, Limits::default());
        }
    }
}

#[test]
fn memoised_bush_is_the_general_evaluators_at_every_cut() {
    let bush = repo().join("bench/bush-262k.cfdg");
    assert!(memoised(&bush));
    for (size, cut) in [(400, 1), (400, 2), (400, 100), (500, 4095), (400, 5000), (300, 65_535)] {
        let opts = eval::Options { width: size, height: size, on_limit: OnLimit::Truncate, ..eval::Options::default() };
        same(&bush, opts, Limits { max_primitives: cut, ..Limits::default() });
    }
    // Cut by memory and by steps too, and failing at the limit under `error`.
    let opts = eval::Options { on_limit: OnLimit::Truncate, ..eval::Options::default() };
    same(&bush, opts, Limits { max_steps: 3000, ..Limits::default() });
    same(&bush, opts, Limits { max_memory: 2_000_000, ..Limits::default() });
    same(&bush, eval::Options::default(), Limits { max_primitives: 5000, ..Limits::default() });
    // The minimum size ends a small bush before any limit: `CF::MinimumSize`.
    let dir = crate::common::tempdir();
    let small = dir.path().join("small.cfdg");
    std::fs::write(&small, "CF::MinimumSize = 2\nstartshape B\nshape B { SQUARE [] B [y 1 r 25 s 0.8] B [y 1 r -25 s 0.8 b 0.02] CIRCLE [s 0.5 hue 40 sat 1 b 1] }\n").expect("writes");
    assert!(memoised(&small));
    same(&small, eval::Options::default(), Limits::default());
}

fn scene(src: &[u8], max_primitives: u64) -> rulemesh::model::hierarchy::Hierarchy {
    let req = RenderRequest { language: Some(Language::Cfdg), format: Format::Scene, limits: Limits { max_primitives, ..Limits::default() }, on_limit: OnLimit::Truncate, ..RenderRequest::default() };
    let out = render(src, &req).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(render(src, &req).expect("again").bytes, out.bytes, "byte-identical reruns");
    decode_scene(&out.bytes).expect("decodes")
}

#[test]
fn the_262k_square_bush_is_a_scene_of_18_objects() {
    let src = std::fs::read(repo().join("bench/bush-262k.cfdg")).expect("bench design");
    // The bush's first 18 generations, whole: one object per generation,
    // a square and two children each (the last a square alone).
    let h = scene(&src, 262_143);
    assert_eq!((h.objects.len(), h.entry_count(), h.leaves()), (18, 3 * 17 + 1, 262_143));
    // A cut inside a generation (4 095 + 1 000 squares): the kept and the
    // cut subtrees of the last generations are distinct objects, and the
    // hierarchy still expands to exactly the shapes drawn.
    let h = scene(&src, 5095);
    assert_eq!(h.leaves(), 5095);
    let mut walked = 0u64;
    h.walk(&mut |_| walked += 1);
    assert_eq!(walked, 5095);
    // The instanced glb is written from the hierarchy and validates.
    let req = RenderRequest { language: Some(Language::Cfdg), format: Format::Glb, limits: Limits { max_primitives: 5095, ..Limits::default() }, on_limit: OnLimit::Truncate, ..RenderRequest::default() };
    let out = render(&src, &req).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(out.primitives, 5095);
    let dir = crate::common::tempdir();
    let glb = dir.path().join("bush.glb");
    std::fs::write(&glb, &out.bytes).expect("writes");
    for (errors, _, report) in crate::common::validate_gltf(&[glb]) {
        assert_eq!(errors, 0, "{report}");
    }
}

#[test]
fn designs_that_are_not_context_free_take_the_general_path() {
    let dir = crate::common::tempdir();
    let cases = [
        // Rule choice by weight draws on the shape's stream.
        ("two_rules", "startshape B\nshape B\nrule { SQUARE [] B [y 1 s 0.8] }\nrule { CIRCLE [] B [y 1 s 0.8] }\n"),
        // A random adjustment.
        ("random", "startshape B\nshape B { SQUARE [] B [y 1 r rand(-9, 9) s 0.8] }\n"),
        // A variable in an adjustment.
        ("variable", "k = 0.8\nstartshape B\nshape B { SQUARE [] B [y 1 s k] }\n"),
        // Parameters.
        ("params", "startshape B(1)\nshape B(number n) { SQUARE [] B(n + 1) [y 1 s 0.8] }\n"),
        // A loop.
        ("loop", "startshape B\nshape B { loop 2 [r 90] SQUARE [] B [y 1 s 0.5] }\n"),
        // A tiled design.
        ("tiled", "CF::Tile = [s 3]\nstartshape B\nshape B { SQUARE [] B [y 1 s 0.8] }\n"),
        // Symmetry.
        ("symmetric", "CF::Symmetry = CF::Cyclic, 3\nstartshape B\nshape B { SQUARE [] B [y 1 s 0.8] }\n"),
    ];
    for (name, src) in cases {
        let f = dir.path().join(format!("{name}.cfdg"));
        std::fs::write(&f, src).expect("writes");
        assert!(!memoised(&f), "{name} must not be memoised");
        let (_, svg) = svg(&f, &eval::Options::default(), Limits { max_primitives: 2000, ..Limits::default() });
        assert!(svg.is_ok() || svg.as_ref().is_err_and(|e| e.contains("primitives")), "{name}: {svg:?}");
    }
    // The same bush without any of these is.
    let f = dir.path().join("plain.cfdg");
    std::fs::write(&f, "startshape B\nshape B { SQUARE [] B [y 1 s 0.8 b 0.1] }\n").expect("writes");
    assert!(memoised(&f));
}
