//! `--print`: every grammar becomes one watertight solid in millimetres.
//! admesh and trimesh (installed by scripts/test) check it independently of
//! rulemesh's own report; the 3MF package opens in trimesh with the same
//! triangle count as the STL.

use crate::common::{admesh, grammar_files, repo, run, tempdir};
use std::path::Path;
use std::process::Command;

/// The Python with trimesh (scripts/test installs it into .tools/venv).
fn trimesh_python() -> String {
    std::env::var("TRIMESH_PYTHON").unwrap_or_else(|_| repo().join(".tools/venv/bin/python").display().to_string())
}

/// (is_watertight, faces, volume) as trimesh sees a file.
fn trimesh_check(file: &Path) -> (bool, u64, f64) {
    let code = "import sys, trimesh\nm = trimesh.load(sys.argv[1], force='mesh')\nprint(m.is_watertight, len(m.faces), m.volume)";
    let out = Command::new(trimesh_python()).args(["-c", code]).arg(file).output().expect("python with trimesh (run scripts/test)");
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(out.status.success(), "trimesh on {}: {text}{}", file.display(), String::from_utf8_lossy(&out.stderr));
    let mut w = text.split_whitespace();
    let watertight = w.next() == Some("True");
    let faces = w.next().and_then(|f| f.parse().ok()).expect("face count");
    let volume = w.next().and_then(|f| f.parse().ok()).expect("volume");
    (watertight, faces, volume)
}

/// The deadline a test print runs under.
#[derive(Clone, Copy, PartialEq)]
enum Deadline {
    /// The default limits (10 s): what a user gets. A union that does not
    /// finish in time is refused naming the deadline, which is issue 16's
    /// "refused with findings that name the cause".
    Default,
    /// The ceiling's 600 s: every union finishes, so every solid is checked
    /// however slow it is (the long runs: unions of thousands of parts take
    /// seconds, more on a loaded machine).
    Patient,
}

/// Renders `grammar` with `--print` under `deadline`.
fn render_within(grammar: &Path, out: &Path, extra: &[&str], deadline: Deadline) -> std::process::Output {
    let mut args = vec!["render", grammar.to_str().expect("utf-8"), "--print", "-o", out.to_str().expect("utf-8")];
    if deadline == Deadline::Patient {
        args.extend_from_slice(&["--timeout", "600000"]);
    }
    args.extend_from_slice(extra);
    run(&args, None)
}

/// Renders `grammar` with `--print` and the ceiling's deadline (these tests are about solids, not time).
fn render(grammar: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    render_within(grammar, out, extra, Deadline::Patient)
}

/// Every MDG and L-system grammar at default limits and its own size (one
/// unit a millimetre), as issue 16 asks: one watertight solid, or refused
/// with the cause. Unions that run past the 10 s deadline are refused
/// naming it; models whose pieces stay apart after fusing are refused
/// naming `separate_shells`; the same check with the ceiling's deadline is
/// the long run `every_grammar_prints_given_time` (docs/print.md).
#[test]
fn every_grammar_prints_as_one_watertight_solid_or_says_why_not() {
    let grammars: Vec<_> = grammar_files("mdg").into_iter().chain(grammar_files("ls")).filter(|g| !is_the_bush(g)).collect();
    assert!(grammars.len() >= 30, "only {} grammars", grammars.len());
    let printed = prints_as_one_watertight_solid_or_says_why_not(&grammars, Deadline::Default);
    // Refusals must not hollow the test out: most grammars print and are
    // checked in full, STL and 3MF. Of the 19 MDG grammars outside the
    // printable collection, issue 16 wants 15 to print; 15 do on a quiet
    // machine (gem, mirror, windmill and smooth-joints are pieces apart by
    // design). Several finish within seconds of the deadline (spiral-rings
    // in about 8 s, the knot in about 6 s, tree and sphereflake in about
    // 3 s), and the suite's other tests share the cores, so a refusal at
    // the deadline is accepted for any of them; a separate_shells refusal
    // only for the four apart by design.
    let collection = ["gear", "lamp-shade", "lattice-cube", "ornament", "pendant", "ring", "rook", "vase"];
    let apart = ["gem", "mirror", "windmill", "smooth-joints"];
    let is_mdg = |stem: &str, ext: &str| ext == "mdg" && !collection.contains(&stem);
    for (stem, ext, why) in &printed.refused {
        if is_mdg(stem, ext) && why.contains("separate_shells") {
            assert!(apart.contains(&stem.as_str()), "{stem} refused as separate pieces: {why}");
        }
    }
    let mdg = printed.printed.iter().filter(|(stem, ext)| is_mdg(stem, ext)).count();
    assert!(mdg >= 10, "only {mdg} of the 19 MDG grammars print: {:?}", printed.refused);
    assert!(printed.printed.len() >= 20, "only {} of {} grammars were checked in full", printed.printed.len(), grammars.len());
}

/// [`every_grammar_prints_as_one_watertight_solid_or_says_why_not`] with the
/// ceiling's deadline: minutes (the plants' flat unions take 10–70 s each,
/// three times), so a long run: `<it-binary> print --ignored` (docs/print.md).
#[test]
#[ignore = "minutes: a long run (docs/print.md)"]
fn every_grammar_prints_given_time() {
    let grammars: Vec<_> = grammar_files("mdg").into_iter().chain(grammar_files("ls")).filter(|g| !is_the_bush(g)).collect();
    let printed = prints_as_one_watertight_solid_or_says_why_not(&grammars, Deadline::Patient);
    assert!(printed.printed.len() >= 25, "only {} of {} grammars were checked in full: {:?}", printed.printed.len(), grammars.len(), printed.refused);
}

/// The Sierpinski bush (35,310 tubes) has a test of its own, below.
fn is_the_bush(g: &Path) -> bool {
    g.file_stem().and_then(|s| s.to_str()) == Some("sierpinski-bush")
}

/// The Sierpinski bush prints at default limits, STL and 3MF, as one
/// watertight shell (united once per distinct subtree, kept in Manifold's
/// double precision: `print::rigid`). Issue 16's 10 s is measured in
/// `scripts/bench` (docs/benchmarks.md), not here: the suite's other tests
/// share the cores, so a refusal at the default deadline is retried with
/// the ceiling's, and the solid is checked either way.
#[test]
fn the_sierpinski_bush_prints_as_one_watertight_solid() {
    let bush = [repo().join("grammars/sierpinski-bush.ls")];
    let mut outcome = prints_as_one_watertight_solid_or_says_why_not(&bush, Deadline::Default);
    if outcome.refused.iter().any(|(_, _, why)| why.contains("limit exceeded: deadline")) {
        outcome = prints_as_one_watertight_solid_or_says_why_not(&bush, Deadline::Patient);
    }
    assert_eq!(outcome.printed.len(), 1, "{:?}", outcome.refused);
    // The same solid on every machine: Manifold's union is deterministic.
    let dir = tempdir();
    let stl = dir.path().join("bush.stl");
    let out = render(&bush[0], &stl, &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let a = admesh(&stl);
    assert_eq!(a.facets, 1_007_446, "{}", a.raw);
    // The tubes' volume less their overlaps (Manifold 3.5.4 in Python, from
    // the same turtle: 11,677.2 mm³).
    assert!((a.volume - 11_677.0).abs() < 10.0, "{}", a.volume);
}

/// Whether a failed print was refused at a limit, a typed refusal that
/// names its cause: the deadline (only at the default limits: the long run
/// lifts it), or another limit (the steps of the Sierpinski tetrahedron's
/// sampled grid, plant-e's memory), which both runs keep.
fn refused_at_the_deadline(stem: &str, out: &std::process::Output, deadline: Deadline) -> bool {
    let err = String::from_utf8_lossy(&out.stderr);
    let at_deadline = err.contains("limit exceeded: deadline");
    let refused = err.contains("limit exceeded: ") && (deadline == Deadline::Default || !at_deadline);
    if refused {
        eprintln!("{stem}: refused at the default deadline: {}", err.trim());
    }
    refused
}

/// For each grammar: the report, the STL (checked by admesh and trimesh
/// against the report) and the 3MF (from another process: the same solid).
/// A grammar either prints as one watertight shell (admesh: 1 part, no
/// backwards edge, degenerate or disconnected facet; trimesh: watertight),
/// or is refused naming why (the deadline at default limits, nothing
/// closed, or separate pieces).
fn prints_as_one_watertight_solid_or_says_why_not(grammars: &[std::path::PathBuf], deadline: Deadline) -> Outcomes {
    let dir = tempdir();
    let mut printed = Outcomes::default();
    for g in grammars {
        let g = g.as_path();
        let stem = g.file_stem().and_then(|s| s.to_str()).expect("name").to_string();
        let ext = g.extension().and_then(|s| s.to_str()).expect("extension").to_string();
        let json = dir.path().join(format!("{stem}.json"));
        let out = render_within(&g, &json, &["--print-report"], deadline);
        if !out.status.success() {
            let err = String::from_utf8_lossy(&out.stderr).to_string();
            if refused_at_the_deadline(&stem, &out, deadline) {
                printed.refused.push((stem, ext, err));
                continue;
            }
            // Nothing closed to print (e.g. only free-vertex surfaces): the error says so.
            assert!(err.contains("nothing printable"), "{stem}: {err}");
            printed.refused.push((stem, ext, err));
            continue;
        }
        let report: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).expect("report")).expect("report is JSON");
        let stl = dir.path().join(format!("{stem}.stl"));
        let out = render_within(&g, &stl, &[], deadline);
        if !out.status.success() && refused_at_the_deadline(&stem, &out, deadline) {
            // The report's union finished in time, this one did not (a loaded machine).
            printed.refused.push((stem, ext, String::from_utf8_lossy(&out.stderr).to_string()));
            continue;
        }
        let err = String::from_utf8_lossy(&out.stderr);
        if report["shells"].as_u64() != Some(1) {
            // Pieces apart even after fusing: refused, naming the cause; the report says so too.
            assert!(!out.status.success() && err.contains("separate_shells"), "{stem}: {err}\n{report}");
            assert!(report["warnings"].to_string().contains("separate shells"), "{stem}: {report}");
            eprintln!("{stem}: refused: {}", err.trim());
            printed.refused.push((stem, ext, err.to_string()));
            continue;
        }
        assert!(out.status.success(), "{stem}: {err}");
        assert!(report["is_watertight"] == true && report["nonmanifold_edges"] == 0, "{stem}: {report}");
        let a = admesh(&stl);
        assert_eq!((a.parts, a.backwards, a.degenerate, a.disconnected, a.open_edges), (1, 0, 0, 0, 0), "{stem}: {}", a.raw);
        let volume = report["volume_mm3"].as_f64().expect("volume");
        assert!((volume - a.volume).abs() <= 1e-3 * a.volume.abs(), "{stem}: report {volume} vs admesh {}", a.volume);
        let (watertight, faces, _) = trimesh_check(&stl);
        assert!(watertight, "{stem}: trimesh says not watertight");
        assert_eq!(faces, a.facets, "{stem}");
        let mf = dir.path().join(format!("{stem}.3mf"));
        let out = render_within(&g, &mf, &[], deadline);
        if !out.status.success() && refused_at_the_deadline(&stem, &out, deadline) {
            printed.refused.push((stem, ext, String::from_utf8_lossy(&out.stderr).to_string()));
            continue;
        }
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{stem}: {err}");
        let (watertight, faces, volume3) = trimesh_check(&mf);
        assert!(watertight, "{stem}: 3MF not watertight in trimesh");
        // The 3MF comes from another process than the STL: the solid is the
        // same triangle for triangle (print output is deterministic).
        assert_eq!(faces, a.facets, "{stem}: 3MF and STL triangle counts");
        assert!((volume3 - a.volume).abs() <= 1e-3 * a.volume.abs(), "{stem}: 3MF volume {volume3}");
        printed.printed.push((stem, ext));
    }
    printed
}

/// What became of each grammar printed: (name, extension) of those that
/// printed, and (name, extension, error) of those refused.
#[derive(Default)]
struct Outcomes {
    printed: Vec<(String, String)>,
    refused: Vec<(String, String, String)>,
}

#[test]
fn overlapping_parts_are_united() {
    // Two overlapping unit boxes: the union is 1.5 × 1 × 1 = 1.5 units³, one shell.
    let dir = tempdir();
    let src = "rule R { BOX {} BOX { x 0.5 } }";
    let stl = dir.path().join("u.stl");
    let out = run(&["render", "-", "--language", "mdg", "--print", "-o", stl.to_str().expect("utf-8")], Some(src.as_bytes()));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let a = admesh(&stl);
    assert_eq!((a.open_edges, a.degenerate, a.parts), (0, 0, 1), "{}", a.raw);
    assert!((a.volume - 1.5).abs() < 1e-4, "{}", a.raw);
    let out = run(&["render", "-", "--language", "mdg", "--print", "--print-report", "-o", "-"], Some(src.as_bytes()));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(report["parts"], 2);
    assert_eq!(report["shells"], 1);
    // Shrunk to 1 mm overall, the 0.67 mm features warn.
    let out = run(&["render", "-", "--language", "mdg", "--print", "--size-mm", "1", "--print-report", "-o", "-"], Some(src.as_bytes()));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert!(report["warnings"].to_string().contains("thinnest feature"), "{report}");
    // Deterministic bytes.
    let again = run(&["render", "-", "--language", "mdg", "--print", "--format", "3mf", "-o", "-"], Some(src.as_bytes()));
    let twice = run(&["render", "-", "--language", "mdg", "--print", "--format", "3mf", "-o", "-"], Some(src.as_bytes()));
    assert!(again.status.success() && again.stdout == twice.stdout && again.stdout.starts_with(b"PK"));
    // size_mm without --print is a usage error.
    let out = run(&["render", "-", "--language", "mdg", "--size-mm", "40", "-o", "-"], Some(src.as_bytes()));
    assert_eq!(out.status.code(), Some(2));
}

/// The level-3 Menger sponge (8,000 unit cubes, `grammars/menger.mdg`)
/// prints as one watertight shell of the sponge's volume, (20/27)³ of its
/// cube. Issue 16: Manifold 3.0.0's pairwise unions left it 1,473 pieces;
/// with 3.5.4 pairwise it was still 1,506 (faces a few f32 ulps apart) and,
/// snapped to a grid, four seams of four faces each; snapped and united in
/// one batch it is whole (src/print/union.rs).
#[test]
fn menger_prints_as_one_watertight_shell() {
    let dir = tempdir();
    let stl = dir.path().join("menger.stl");
    let out = run(&["render", repo().join("grammars/menger.mdg").to_str().expect("utf-8"), "--print", "-o", stl.to_str().expect("utf-8")], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let a = admesh(&stl);
    assert_eq!((a.parts, a.backwards, a.degenerate, a.disconnected), (1, 0, 0, 0), "{}", a.raw);
    let (watertight, faces, volume) = trimesh_check(&stl);
    assert!(watertight, "trimesh: not watertight");
    assert_eq!(faces, a.facets);
    // One model unit is one millimetre: the sponge's cube is 1 mm wide.
    let sponge = (20.0f64 / 27.0).powi(3);
    assert!((volume - sponge).abs() <= 0.01 * sponge, "volume {volume} vs {sponge}");
}

/// The findings of a report, as (code, value to a micrometre) pairs.
fn findings(report: &serde_json::Value) -> Vec<(String, Option<f64>)> {
    let um = |v: f64| (v * 1000.0).round() / 1000.0;
    report["findings"].as_array().expect("findings").iter().map(|f| (f["code"].as_str().expect("code").to_string(), f["value"].as_f64().map(um))).collect()
}

/// The printer profile through the CLI, on `tests/data/print/thin-plate.mdg`
/// (20 × 20 × 0.5 mm at `--size-mm 20`): the measured thinnest wall is the
/// plate's 0.5 mm and is flagged against the default 0.8 mm minimum, not
/// against 0.4 mm; too big for a small build volume; too many triangles
/// under a low ceiling; a bad profile value is a usage error.
#[test]
fn printer_profile_findings_through_the_cli() {
    let plate = repo().join("tests/data/print/thin-plate.mdg");
    let report = |size: &str, extra: &[&str]| {
        let mut args = vec!["render", plate.to_str().expect("utf-8"), "--print", "--print-report", "--size-mm", size, "-o", "-"];
        args.extend_from_slice(extra);
        let out = run(&args, None);
        assert!(out.status.success(), "{extra:?}: {}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice::<serde_json::Value>(&out.stdout).expect("report is JSON")
    };
    let r = report("20", &[]);
    let bbox: Vec<f64> = r["bbox_mm"].as_array().expect("bbox").iter().map(|v| v.as_f64().expect("mm")).collect();
    assert!((bbox[0] - 20.0).abs() < 1e-3 && (bbox[1] - 20.0).abs() < 1e-3 && (bbox[2] - 0.5).abs() < 1e-3, "{r}");
    let thinnest = r["thinnest_wall_mm"].as_f64().expect("measured");
    assert!((thinnest - 0.5).abs() < 0.1, "{r}");
    let thin = &r["findings"][0];
    assert_eq!(thin["code"], "thin_wall", "{r}");
    assert!((thin["value"].as_f64().expect("value") - 0.5).abs() < 0.1, "{r}");
    // The place is on the plate's top or bottom face (z 0.5 or 0).
    let z = thin["position_mm"][2].as_f64().expect("position");
    assert!(z.abs() < 1e-3 || (z - 0.5).abs() < 1e-3, "{r}");
    assert_eq!(findings(&r), vec![("thin_wall".to_string(), Some(0.5))]);
    assert_eq!(r["profile"], serde_json::json!({ "min_wall_mm": 0.8, "build_volume_mm": [250.0, 210.0, 210.0], "triangle_ceiling": 1_000_000 }));
    assert!(r["warnings"][0].as_str().expect("warning").contains("thinnest feature"), "{r}");
    // A printer that makes 0.4 mm walls: nothing to say.
    let r = report("20", &["--min-wall-mm", "0.4"]);
    assert_eq!(findings(&r), vec![], "{r}");
    assert_eq!(r["profile"]["min_wall_mm"], 0.4);
    // Over a low triangle ceiling (the plate is 12 triangles).
    let r = report("20", &["--min-wall-mm", "0.4", "--triangle-ceiling", "4"]);
    assert_eq!(findings(&r), vec![("too_many_triangles".to_string(), Some(12.0))], "{r}");
    // 300 mm across does not fit the default 250 × 210 × 210 mm: 90 mm over along y.
    let r = report("300", &[]);
    assert_eq!(findings(&r), vec![("too_big".to_string(), Some(90.0))], "{r}");
    // A given build volume it fits: nothing to say (the plate is 7.5 mm thick).
    let r = report("300", &["--build-volume-mm", "300x300x10"]);
    assert_eq!(findings(&r), vec![], "{r}");
    // Out of range: usage errors.
    for bad in [["--min-wall-mm", "0"], ["--build-volume-mm", "1x2"], ["--triangle-ceiling", "0"]] {
        let mut args = vec!["render", plate.to_str().expect("utf-8"), "--print", "--print-report", "-o", "-"];
        args.extend_from_slice(&bad);
        assert_eq!(run(&args, None).status.code(), Some(2), "{bad:?}");
    }
}

#[test]
fn every_example_in_docs_print_prints_watertight() {
    let doc = std::fs::read_to_string(repo().join("docs/print.md")).expect("docs/print.md");
    let examples = crate::docs::fenced_examples(&doc, "mdg");
    assert!(examples.len() >= 2, "only {} examples", examples.len());
    let dir = tempdir();
    for (i, src) in examples.iter().enumerate() {
        let stl = dir.path().join(format!("example-{i}.stl"));
        let out = run(&["render", "-", "--language", "mdg", "--print", "--size-mm", "30", "-o", stl.to_str().expect("utf-8")], Some(src.as_bytes()));
        assert!(out.status.success(), "example {i}:\n{src}\n{}", String::from_utf8_lossy(&out.stderr));
        let a = admesh(&stl);
        assert_eq!((a.open_edges, a.degenerate, a.parts), (0, 0, 1), "example {i}: {}", a.raw);
    }
}

/// Renders `grammar` with `--print` twice: `None` when it has nothing to
/// print, else whether the two STL files agree byte for byte.
fn print_is_deterministic(grammar: &Path, dir: &Path) -> Option<bool> {
    let mut outs = Vec::new();
    for i in 0..2 {
        let p = dir.join(format!("determinism-{i}.stl"));
        if !render(grammar, &p, &["--size-mm", "40"]).status.success() {
            return None;
        }
        outs.push(std::fs::read(&p).expect("stl"));
    }
    Some(outs[0] == outs[1])
}

/// `print=true` gives the same bytes in every process. It did not while
/// Manifold 3.0.0's CreateFaces read uninitialised memory (patched then;
/// 3.5.4 has no such read, vendor/manifold-rs/PATCHES.md): plant-b, grass
/// and hogeweg came out a few triangles apart from run to run.
#[test]
fn print_output_is_deterministic() {
    // One of the three exact unions that differed (grass, the second, is
    // now refused as separate pieces), a large union of other shapes, and a
    // fused one (contacts become connections); every other grammar's STL and
    // 3MF come from separate processes in the every-grammar test and must
    // agree triangle for triangle.
    prints_the_same_twice(&["hogeweg.ls", "menger.mdg", "tower.mdg"]);
}

/// [`print_output_is_deterministic`] for the slow ones: plant-b (the third
/// that differed) and spiral-rings, each a union of tens of seconds run
/// twice, so a long run: `<it-binary> print --ignored` (docs/print.md).
#[test]
#[ignore = "a minute or more: a long run (docs/print.md)"]
fn slow_prints_are_deterministic() {
    prints_the_same_twice(&["plant-b.ls", "spiral-rings.mdg"]);
}

fn prints_the_same_twice(stems: &[&str]) {
    let dir = tempdir();
    for stem in stems {
        let g = repo().join("grammars").join(stem);
        assert_eq!(print_is_deterministic(&g, dir.path()), Some(true), "{stem}: two runs differ or it does not print");
    }
}

/// In one process (a service worker), the same print request gives the same
/// bytes however many unions ran before it, including one on another thread
/// at the same time: Manifold numbers every mesh from a process-wide counter,
/// and the union must not depend on those numbers.
#[test]
fn print_output_does_not_depend_on_earlier_unions_in_the_process() {
    use rulemesh::export::Format;
    use rulemesh::pipeline::{render, RenderRequest};
    // The exact union (hogeweg) and the fused route (tower) alike.
    for name in ["hogeweg.ls", "tower.mdg"] {
        let source = std::fs::read(repo().join("grammars").join(name)).expect("grammar");
        // A print's default limits (the CLI's and the service's: 640 MiB of accounted memory).
        let mut req = RenderRequest { format: Format::Stl, limits: rulemesh::core::Limits::defaults_for(true), ..RenderRequest::default() };
        req.export_options.print.enabled = true;
        let first = render(&source, &req).expect("print").bytes;
        let other = std::thread::spawn(|| {
            let mut r = RenderRequest { format: Format::Stl, limits: rulemesh::core::Limits::defaults_for(true), ..RenderRequest::default() };
            r.export_options.print.enabled = true;
            render(b"rule R { 5 * { x 0.7 rz 20 } BOX {} }", &r).expect("print boxes").bytes
        });
        let second = render(&source, &req).expect("print again").bytes;
        assert!(!other.join().expect("thread").is_empty());
        let third = render(&source, &req).expect("print a third time").bytes;
        assert!(first == second && second == third, "{name} printed differently within one process");
    }
}

/// A model of surfaces only is printed as walls: at phase 1 the twenty
/// triangles of the icosahedron transformations meet only at their corners
/// (an icosidodecahedron missing its pentagons), so each becomes a prism of
/// its own, 0.8 mm thick at 40 mm, and the prisms fuse at the corners into
/// one shell; a surface that touches itself is refused with the reason.
#[test]
fn surface_only_models_print_as_walls() {
    let g = repo().join("grammars/icosahedron-transformations.mdg");
    let out = run(&["render", g.to_str().expect("utf-8"), "--print", "--print-report", "--size-mm", "40", "--param", "phase=1", "-o", "-"], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert!(report["thickened_parts"].as_u64() >= Some(1), "{report}");
    assert_eq!(report["parts"], 20, "{report}");
    assert_eq!(report["shells"], 1, "{report}");
    assert_eq!(report["skipped_parts"], 0, "{report}");
    assert_eq!(report["is_watertight"], true, "{report}");
    // At least the printable 0.8 mm once scaled (the walls add to the size they are scaled by).
    let wall = report["wall_mm"].as_f64().expect("wall_mm");
    assert!((0.8..0.81).contains(&wall), "{report}");
    assert!(report["warnings"].to_string().contains("thickened into walls"), "{report}");
    assert!(!report["warnings"].to_string().contains("thinnest feature"), "{report}");
    // The same surfaces next to a solid are left out, not thickened.
    let src = "rule R { BOX {} VERTEX { x 3 } VERTEX { x 4 } VERTEX { x 3 y 1 } }";
    let out = run(&["render", "-", "--language", "mdg", "--print", "--print-report", "-o", "-"], Some(src.as_bytes()));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!((report["parts"].as_u64(), report["skipped_parts"].as_u64(), report["thickened_parts"].as_u64()), (Some(1), Some(1), Some(0)), "{report}");
}

/// The Koch curve's mitred tube touches itself at 116 points: it is cut into
/// runs that do not, and they unite into one part with no open, degenerate
/// or backwards facet (admesh). Where two runs' tubes coincide exactly at a
/// touching point the union leaves edges of four faces (the contacts item of
/// issue 16, like the Menger sponge's): until then the report says so and
/// trimesh agrees.
#[test]
fn a_line_that_meets_itself_prints_as_one_part() {
    let dir = tempdir();
    let koch = repo().join("grammars/koch.ls");
    let stl = dir.path().join("koch.stl");
    let out = render(&koch, &stl, &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let a = admesh(&stl);
    assert_eq!((a.parts, a.open_edges, a.degenerate, a.reversed), (1, 0, 0, 0), "{}", a.raw);
    assert!(a.raw.contains("Backwards edges       :     0"), "{}", a.raw);
    let (watertight, faces, volume) = trimesh_check(&stl);
    assert_eq!(faces, a.facets);
    assert!((volume - a.volume).abs() <= 1e-3 * a.volume, "{volume} vs {}", a.volume);
    let json = dir.path().join("koch.json");
    assert!(render(&koch, &json, &["--print-report"]).status.success());
    let report: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).expect("report")).expect("JSON");
    assert_eq!(report["is_watertight"].as_bool(), Some(watertight), "{report}");
    if !watertight {
        assert!(report["nonmanifold_edges"].as_u64() > Some(0) && report["warnings"].to_string().contains("not watertight"), "{report}");
    }
}

/// Each triangle of a 3MF file as lib3mf (the 3MF Consortium's reader;
/// trimesh ignores 3MF colours) reads it: its centroid and its base
/// material's sRGB display colour.
fn lib3mf_triangle_colours(file: &Path) -> Vec<([f64; 3], [u8; 4])> {
    let code = r#"import sys, lib3mf
w = lib3mf.get_wrapper()
model = w.CreateModel()
model.QueryReader("3mf").ReadFromFile(sys.argv[1])
groups = {}
it = model.GetBaseMaterialGroups()
while it.MoveNext():
    g = it.GetCurrentBaseMaterialGroup()
    groups[g.GetResourceID()] = {i: g.GetDisplayColor(i) for i in g.GetAllPropertyIDs()}
objs = model.GetMeshObjects()
while objs.MoveNext():
    o = objs.GetCurrentMeshObject()
    vs = o.GetVertices()
    for t, p in zip(o.GetTriangleIndices(), o.GetAllTriangleProperties()):
        c = groups[p.ResourceID][p.PropertyIDs[0]]
        x = [sum(vs[i].Coordinates[k] for i in t.Indices) / 3 for k in range(3)]
        print(x[0], x[1], x[2], c.Red, c.Green, c.Blue, c.Alpha)
"#;
    let out = Command::new(trimesh_python()).args(["-c", code]).arg(file).output().expect("python with lib3mf (run scripts/test)");
    assert!(out.status.success(), "lib3mf on {}: {}", file.display(), String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|f| f.parse().expect("number")).collect();
            ([v[0], v[1], v[2]], [v[3] as u8, v[4] as u8, v[5] as u8, v[6] as u8])
        })
        .collect()
}

/// 3MF carries the model's colours as base materials, per triangle, through
/// the union of `print=true` as well; lib3mf reads them back. STL stays plain.
#[test]
fn colours_round_trip_through_3mf() {
    let dir = tempdir();
    // A red box and a blue one overlapping by half: printed (one unit is a
    // millimetre, centred in x), the red end is at x < -0.25, the blue at x > 0.25.
    let src = "rule R { BOX { R 1 } BOX { x 0.5 B 1 } }";
    let mf = dir.path().join("two.3mf");
    let out = run(&["render", "-", "--language", "mdg", "--print", "-o", mf.to_str().expect("utf-8")], Some(src.as_bytes()));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let tris = lib3mf_triangle_colours(&mf);
    let colour_where = |keep: &dyn Fn(f64) -> bool| -> Vec<[u8; 4]> {
        let mut c: Vec<[u8; 4]> = tris.iter().filter(|(p, _)| keep(p[0])).map(|(_, c)| *c).collect();
        c.sort();
        c.dedup();
        c
    };
    let red = colour_where(&|x| x < -0.26);
    let blue = colour_where(&|x| x > 0.26);
    assert_eq!((red.len(), blue.len()), (1, 1), "one colour at each end: {red:?} {blue:?}");
    let (red, blue) = (red[0], blue[0]);
    assert!(red[0] > red[2] && blue[2] > blue[0] && red[3] == 255, "red end {red:?}, blue end {blue:?}");
    // The faces where the two boxes overlap take one of the two colours.
    assert!(tris.iter().all(|(_, c)| *c == red || *c == blue), "{tris:?}");
    // The gem's three colours (a crown, facets and a halo of spheres) in a
    // plain 3MF, one object per mesh.
    let gem = dir.path().join("gem.3mf");
    assert!(run(&["render", repo().join("grammars/gem.mdg").to_str().expect("utf-8"), "-o", gem.to_str().expect("utf-8")], None).status.success());
    let mut colours: Vec<[u8; 4]> = lib3mf_triangle_colours(&gem).into_iter().map(|(_, c)| c).collect();
    colours.sort();
    colours.dedup();
    assert_eq!(colours.len(), 3, "{colours:?}");
    // STL has no colour: every triangle's attribute word is zero.
    let stl = dir.path().join("two.stl");
    assert!(run(&["render", "-", "--language", "mdg", "--print", "-o", stl.to_str().expect("utf-8")], Some(src.as_bytes())).status.success());
    let bytes = std::fs::read(&stl).expect("stl");
    assert!(bytes[84..].chunks_exact(50).all(|t| t[48..50] == [0, 0]), "an STL attribute word is not zero");
}

/// The printable collection (`core::library::PRINTABLE`, marked `printable`
/// in `GET /v1/grammars`): each grammar, printed at its default size (one
/// unit is a millimetre), is one shell that admesh finds closed and
/// consistently wound with no degenerate or disconnected facet, and that
/// trimesh calls watertight. One trimesh process checks them all.
#[test]
fn the_printable_collection_prints_as_single_watertight_shells() {
    let dir = tempdir();
    let names = rulemesh::core::library::PRINTABLE;
    assert!(names.len() >= 8, "{names:?}");
    let mut files = Vec::new();
    for name in names {
        let g = repo().join("grammars").join(format!("{name}.mdg"));
        let stl = dir.path().join(format!("{name}.stl"));
        let out = render(&g, &stl, &[]);
        assert!(out.status.success(), "{name}: {}", String::from_utf8_lossy(&out.stderr));
        let a = admesh(&stl);
        assert_eq!((a.parts, a.backwards, a.degenerate, a.disconnected, a.open_edges), (1, 0, 0, 0, 0), "{name}: {}", a.raw);
        files.push((name, stl, a.facets));
    }
    let code = "import sys, trimesh\nfor f in sys.argv[1:]:\n    m = trimesh.load(f, force='mesh')\n    print(m.is_watertight, len(m.faces), len(m.split(only_watertight=False)))";
    let out = Command::new(trimesh_python()).args(["-c", code]).args(files.iter().map(|f| &f.1)).output().expect("python with trimesh (run scripts/test)");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), files.len(), "{text}");
    for ((name, _, facets), line) in files.iter().zip(lines) {
        assert_eq!(line, format!("True {facets} 1"), "{name}: trimesh (watertight, faces, bodies)");
    }
}

/// A level-2 sponge (400 boxes, memoised into a hierarchy by MDG) prints
/// through the union per distinct subtree (src/print/subtree.rs): one
/// watertight shell of the sponge's volume, the same bytes from two
/// processes, in STL and in 3MF.
#[test]
fn a_hierarchy_prints_once_per_subtree_as_one_watertight_shell_byte_for_byte() {
    let src = "startshape S\n@macro SPONGE(N)\n  N { s (1/3) x -1 -1 -1 } N { s (1/3) x -1 -1 0 } N { s (1/3) x -1 -1 1 } N { s (1/3) x -1 0 -1 }\n  N { s (1/3) x -1 0 1 } N { s (1/3) x -1 1 -1 } N { s (1/3) x -1 1 0 } N { s (1/3) x -1 1 1 }\n  N { s (1/3) x 0 -1 -1 } N { s (1/3) x 0 -1 1 } N { s (1/3) x 0 1 -1 } N { s (1/3) x 0 1 1 }\n  N { s (1/3) x 1 -1 -1 } N { s (1/3) x 1 -1 0 } N { s (1/3) x 1 -1 1 } N { s (1/3) x 1 0 -1 }\n  N { s (1/3) x 1 0 1 } N { s (1/3) x 1 1 -1 } N { s (1/3) x 1 1 0 } N { s (1/3) x 1 1 1 }\n@endmacro\nrule S { L1 { s 30 } }\nrule L1 { @expand SPONGE(L0) }\nrule L0 { @expand SPONGE(BOX) }\n";
    let dir = tempdir();
    let print = |format: &str| {
        let out = run(&["render", "-", "--language", "mdg", "--print", "--format", format, "-o", "-"], Some(src.as_bytes()));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{err}");
        // The summary's phases: the union ran on the hierarchy, nothing was meshed flat.
        assert!(err.contains("print ") && !err.contains("mesh "), "{err}");
        out.stdout
    };
    for format in ["stl", "3mf"] {
        assert_eq!(print(format), print(format), "{format}: two processes, two unions");
    }
    let stl = dir.path().join("sponge.stl");
    std::fs::write(&stl, print("stl")).expect("write");
    let a = admesh(&stl);
    assert_eq!((a.parts, a.backwards, a.degenerate, a.disconnected), (1, 0, 0, 0), "{}", a.raw);
    let (watertight, faces, volume) = trimesh_check(&stl);
    assert!(watertight && faces == a.facets, "trimesh: watertight {watertight}, {faces} faces");
    let sponge = 30.0f64.powi(3) * (20.0f64 / 27.0).powi(2);
    assert!((volume - sponge).abs() <= 1e-4 * sponge, "volume {volume} vs {sponge}");
}

/// Context Free designs print (issue 34): every CFDG grammar in `grammars/`,
/// its shapes made thin tiles at their z order (`cfdg/tiles.rs`), is one
/// shell that admesh finds closed and consistently wound and trimesh calls
/// watertight, in STL and 3MF. Before, the print stage's parts left out
/// affine instances (every CFDG tile is one), so a design printed nothing.
/// The 3MF carries the design's colours: as many as its SVG has fills, each
/// within one 8-bit step of one of them (3MF stores sRGB from the model's
/// linear colours, the SVG cfdg's 8-bit ones).
#[test]
fn every_cfdg_grammar_prints_as_one_watertight_shell_with_its_colours() {
    let grammars = grammar_files("cfdg");
    assert!(!grammars.is_empty(), "no CFDG grammar in grammars/");
    let printed = prints_as_one_watertight_solid_or_says_why_not(&grammars, Deadline::Default);
    assert!(printed.refused.is_empty(), "refused: {:?}", printed.refused);
    assert_eq!(printed.printed.len(), grammars.len());
    let dir = tempdir();
    for g in &grammars {
        let stem = g.file_stem().and_then(|s| s.to_str()).expect("name");
        let (mf, svg) = (dir.path().join(format!("{stem}.3mf")), dir.path().join(format!("{stem}.svg")));
        for (out, extra) in [(&mf, &["--print"][..]), (&svg, &[][..])] {
            let mut args = vec!["render", g.to_str().expect("utf-8"), "-o", out.to_str().expect("utf-8")];
            args.extend_from_slice(extra);
            let run = run(&args, None);
            assert!(run.status.success(), "{stem}: {}", String::from_utf8_lossy(&run.stderr));
        }
        let text = std::fs::read_to_string(&svg).expect("svg");
        let mut fills: Vec<[u8; 3]> = text
            .split("fill=\"#")
            .skip(1)
            .filter_map(|rest| rest.get(..6))
            .filter_map(|h| Some([u8::from_str_radix(h.get(0..2)?, 16).ok()?, u8::from_str_radix(h.get(2..4)?, 16).ok()?, u8::from_str_radix(h.get(4..6)?, 16).ok()?]))
            .collect();
        fills.sort();
        fills.dedup();
        let mut colours: Vec<[u8; 3]> = lib3mf_triangle_colours(&mf).into_iter().map(|(_, c)| [c[0], c[1], c[2]]).collect();
        colours.sort();
        colours.dedup();
        assert!(fills.len() > 1, "{stem}: a design of one colour tests nothing");
        assert_eq!(colours.len(), fills.len(), "{stem}: the 3MF's colours against the SVG's fills");
        for c in &colours {
            let near = fills.iter().any(|f| f.iter().zip(c).all(|(a, b)| a.abs_diff(*b) <= 1));
            assert!(near, "{stem}: 3MF colour {c:?} is no fill of the design's SVG");
        }
    }
}
