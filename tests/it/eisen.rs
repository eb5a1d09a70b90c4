//! EisenScript (issue 8): exact counts for loops, retirement, `maxobjects`
//! and breadth-first order, `set seed` reproducibility, colour pools, GUI
//! parameters, affine frames, and every example script Debian's
//! `structure-synth` package ships through the renderer (instanced glb),
//! the Khronos glTF Validator and three.js.

use crate::common::{admesh, decode_stl, signed_volume, tempdir, three_check, validate_gltf};
use rulemesh::eisen::{build, BuildOptions};
use rulemesh::core::{Limit, Limits, OnLimit, ParamValue};
use rulemesh::export::Format;
use rulemesh::lang::eisen::syntax::{parse, ParseOptions};
use rulemesh::core::PrimitiveKind;
use rulemesh::lang::Language;
use rulemesh::{render, RenderError, RenderRequest};
use std::path::{Path, PathBuf};

fn req(format: Format) -> RenderRequest {
    RenderRequest { language: Some(Language::Eisenscript), format, ..RenderRequest::default() }
}

/// The scene `src` builds with seed `seed`.
fn scene(src: &str, seed: u64) -> rulemesh::model::Scene {
    let script = parse(src.as_bytes(), &ParseOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let opts = BuildOptions {
        seed,
        detail: 8,
        on_limit: OnLimit::Error,
        line_radius: 0.01,
        downstream_bytes: [0; 9],
        vertex_bytes: 0,
        per_instance: None,
    };
    let mut budget = rulemesh::core::Budget::new(Limits::default());
    build(&script, &opts, &mut budget).unwrap_or_else(|e| panic!("{e}")).scene
}

fn count(src: &str, kind: PrimitiveKind) -> usize {
    scene(src, 0).affine.iter().filter(|a| a.kind == kind).count()
}

fn objects(src: &str) -> u64 {
    render(src.as_bytes(), &req(Format::Stl)).unwrap_or_else(|e| panic!("{e}")).primitives
}

#[test]
fn loops_make_n_copies_at_the_first_to_nth_power() {
    assert_eq!(objects("3 * { x 2 } box"), 3);
    assert_eq!(objects("2 * { y 1 } 3 * { x 1 } box"), 6);
    // A zero count still makes one copy, as in Structure Synth (Action.cpp:33-65; see ssfidelity.rs).
    assert_eq!(objects("4 * { x 1 } 0 * { y 1 } box"), 1);
    // Structure Synth's Action::apply runs each loop's counter from 1 to N:
    // the copies sit at T¹…Tᴺ (the box's centre is at 0.5 in its frame).
    let s = scene("3 * { x 2 } box", 0);
    let xs: Vec<f32> = s.affine.iter().map(|a| a.translation.x).collect();
    assert_eq!(xs, [2.5, 4.5, 6.5]);
    // Nested loops: the first loop's counter runs fastest.
    let s = scene("2 * { y 10 } 2 * { x 1 } box", 0);
    let p: Vec<(f32, f32)> = s.affine.iter().map(|a| (a.translation.x, a.translation.y)).collect();
    assert_eq!(p, [(1.5, 10.5), (1.5, 20.5), (2.5, 10.5), (2.5, 20.5)]);
    // Copies are made incrementally: 50 000 copies cost 50 000 steps, not 1.25 billion.
    let out = render(b"set maxobjects 60000\n50000 * { x 1 } box", &req(Format::Stl)).unwrap();
    assert_eq!(out.primitives, 50_000);
    // A loop's step repeats colour changes too: hue 120 per copy.
    let s = scene("3 * { x 1 hue 120 } box", 0);
    let c: Vec<[f32; 4]> = s.affine.iter().map(|a| a.colour).collect();
    assert_eq!(c, [[0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0], [1.0, 0.0, 0.0, 1.0]]);
}

#[test]
fn maxdepth_retirement_runs_the_substitute_once_per_branch() {
    let with = "r\nrule r md 3 > e { { x 1 } r box }\nrule e { sphere }\n";
    assert_eq!(count(with, PrimitiveKind::Box), 3);
    assert_eq!(count(with, PrimitiveKind::Sphere), 1);
    let without = "r\nrule r maxdepth 3 { { x 1 } r box }\n";
    assert_eq!(count(without, PrimitiveKind::Box), 3);
    assert_eq!(count(without, PrimitiveKind::Sphere), 0);
    // Retirement counters are per branch: two branches of 3 each, and the
    // substitute restarts the count (md 2 > r2 alternating never ends before maxdepth).
    assert_eq!(count("2 * { y 2 } r\nrule r md 3 { { x 1 } r box }\n", PrimitiveKind::Box), 6);
    assert_eq!(count("set maxdepth 12\nr\nrule r md 2 > r { { x 1 } r box }\n", PrimitiveKind::Box), 10);
}

#[test]
fn global_maxdepth_counts_generations() {
    // Generation 1 runs the top level, generation k + 1 draws the box queued in generation k.
    assert_eq!(objects("set maxdepth 1\nbox"), 0);
    assert_eq!(objects("set maxdepth 2\nbox"), 1);
    assert_eq!(objects("set maxdepth 10\nr\nrule r { box { x 1 } r }\n"), 8);
}

#[test]
fn maxobjects_stops_at_a_generation_boundary_in_breadth_first_order() {
    // One box per generation: exactly the limit.
    assert_eq!(objects("set maxobjects 10\nr\nrule r { box { x 1 } r }\n"), 10);
    // Four per generation: the generation that crosses the limit completes.
    assert_eq!(objects("set maxobjects 10\nr\nrule r { 4 * { y 1 } box { x 1 } r }\n"), 12);
    // Pending rule states count too: 36 queued boxes ≥ 10 stop before drawing.
    assert_eq!(objects("set maxobjects 10\n36 * { x 1 } box\n"), 0);
    // A binary tree: breadth-first keeps whole levels (the root box, then both
    // children), where depth-first would follow one branch down.
    let tree = "set maxobjects 7\nt\nrule t { box { x 1 s 0.5 } t { y 1 s 0.5 } t }\n";
    let s = scene(tree, 0);
    let mut sizes: Vec<f32> = s.affine.iter().map(|a| a.linear.x_axis.x).collect();
    sizes.sort_by(f32::total_cmp);
    assert_eq!(sizes, [0.5, 0.5, 1.0]);
    // Depth-first (`set recursion depth`) follows the first branch instead.
    let s = scene(&format!("set recursion depth\n{tree}"), 0);
    let sizes: Vec<f32> = s.affine.iter().take(3).map(|a| a.linear.x_axis.x).collect();
    assert_eq!(sizes, [1.0, 0.5, 0.25]);
}

#[test]
fn minsize_and_maxsize_prune_branches() {
    // Diagonal √3 · 0.5ᵏ: minsize 0.2 keeps k = 0..3.
    assert_eq!(objects("set minsize 0.2\nr\nrule r { box { s 0.5 } r }\n"), 4);
    assert_eq!(objects("set maxsize 4\nr\nrule r { box { s 1.5 } r }\n"), 3);
    // The size check applies to the start rule too: maxsize below √3 prunes everything, as in Structure Synth.
    assert_eq!(objects("set maxsize 1\nbox\n"), 0);
}

const RANDOM: &str = "set maxdepth 30\n40 * { x 1 } r\nrule r { { color random } box }\nrule r w 2 { { y 1 color random } sphere }\n";

#[test]
fn set_seed_reproduces_and_request_seed_varies() {
    let bytes = |src: &str, seed: u64| {
        let r = RenderRequest { seed: Some(seed), ..req(Format::Glb) };
        render(src.as_bytes(), &r).unwrap_or_else(|e| panic!("{e}")).bytes
    };
    assert_eq!(bytes(RANDOM, 1), bytes(RANDOM, 1));
    assert_ne!(bytes(RANDOM, 1), bytes(RANDOM, 2));
    // `set seed` in the script wins over the request's seed, as it does over
    // Structure Synth's GUI seed: the same geometry (strips carry no
    // provenance; a glb records the request's seed, so its bytes differ).
    let seeded = format!("set seed 7\n{RANDOM}");
    let strips = |src: &str, seed: u64| render(src.as_bytes(), &RenderRequest { seed: Some(seed), ..req(Format::Strips) }).unwrap_or_else(|e| panic!("{e}")).bytes;
    assert_eq!(strips(&seeded, 1), strips(&seeded, 2));
    assert_ne!(bytes(&seeded, 1), bytes(&format!("set seed 8\n{RANDOM}"), 1));
    // Weights: about twice as many spheres as boxes.
    let s = scene(RANDOM, 3);
    let spheres = s.affine.iter().filter(|a| a.kind == PrimitiveKind::Sphere).count();
    assert_eq!(s.affine.len(), 40);
    assert!((18..=36).contains(&spheres), "{spheres}");
    // `set seed initial` gives every branch the same random choices.
    let initial = "5 * { x 2 } r\nrule r { set seed initial 10 * { y 1 } q }\nrule q { box }\nrule q { sphere }\n";
    let s = scene(initial, 9);
    let kinds: Vec<Vec<PrimitiveKind>> = s.affine.chunks(10).map(|c| c.iter().map(|a| a.kind).collect()).collect();
    assert!(kinds.windows(2).all(|w| w[0] == w[1]), "{kinds:?}");
}

#[test]
fn colour_pools() {
    let colours = |pool: &str| -> Vec<[f32; 4]> {
        scene(&format!("set colorpool {pool}\n300 * {{ x 1 color random }} box\n"), 4).affine.iter().map(|a| a.colour).collect()
    };
    let list = colours("list:red,blue");
    assert!(list.iter().all(|c| *c == [1.0, 0.0, 0.0, 1.0] || *c == [0.0, 0.0, 1.0, 1.0]), "{list:?}");
    assert!(list.contains(&[1.0, 0.0, 0.0, 1.0]) && list.contains(&[0.0, 0.0, 1.0, 1.0]));
    let grey = colours("greyscale");
    assert!(grey.iter().all(|c| c[0] == c[1] && c[1] == c[2]));
    assert!(grey.iter().any(|c| c[0] != grey[0][0]));
    for c in colours("randomhue") {
        let max = c[0].max(c[1]).max(c[2]);
        let min = c[0].min(c[1]).min(c[2]);
        assert_eq!((max, min), (1.0, 0.0), "{c:?}");
    }
    let rgb = colours("randomrgb");
    assert!(rgb.iter().any(|c| c[0] != c[1]));
    // The default state colour is red (hue 0, full saturation and value); `hue` adds, `b` multiplies.
    let s = scene("box\n{ hue 120 } box\n{ color white } box\n{ b 0.5 color white } box\n", 0);
    assert_eq!(s.affine[0].colour, [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(s.affine[1].colour, [0.0, 1.0, 0.0, 1.0]);
    assert_eq!(s.affine[2].colour, [1.0, 1.0, 1.0, 1.0]);
    // Structure Synth composes a list's colour changes before applying them,
    // so `b 0.5` scales the absolute white that follows it: 50 % grey (sRGB).
    assert!((s.affine[3].colour[0] - 0.214_041_14).abs() < 1e-6, "{:?}", s.affine[3].colour);
    let e = render(b"set colorpool image:x.png\nbox", &req(Format::Glb)).unwrap_err();
    assert!(e.to_string().contains("image"), "{e}");
}

#[test]
fn gui_defines_bind_to_request_parameters() {
    let src = "#define n 3 (int:1-10)\n#define d 1 (float:0.5-2)\nn * { x d } box\n";
    assert_eq!(objects(src), 3);
    let with = |name: &str, v: f64| {
        let mut r = req(Format::Stl);
        r.params.insert(name.into(), ParamValue::Number(v));
        render(src.as_bytes(), &r)
    };
    assert_eq!(with("n", 5.0).unwrap().primitives, 5);
    assert!(matches!(with("n", 11.0), Err(RenderError::Eval(_))));
    assert!(matches!(with("n", 2.5), Err(RenderError::Eval(_))));
    assert!(matches!(with("nope", 1.0), Err(RenderError::Eval(_))));
    assert!(with("line_radius", 0.05).is_ok());
}

#[test]
fn budget_limits_name_the_limit() {
    // Generations are not a stack depth: `set maxdepth 5000` ends at the step limit, if any.
    let deep = "set maxdepth 5000\nr\nrule r { { x 1 } r box }\n";
    let steps = RenderRequest { limits: Limits { max_steps: 2_000, ..Limits::default() }, ..req(Format::Glb) };
    match render(deep.as_bytes(), &steps) {
        Err(RenderError::Limit(l)) => assert_eq!(l.limit, Limit::Steps),
        other => panic!("{other:?}"),
    }
    let many = "set maxobjects 1000000\nr\nrule r { 10 * { y 1 } box { x 1 } r }\n";
    let small = RenderRequest { limits: Limits { max_primitives: 100, ..Limits::default() }, ..req(Format::Glb) };
    match render(many.as_bytes(), &small) {
        Err(RenderError::Limit(l)) => assert_eq!(l.limit, Limit::Primitives),
        other => panic!("{other:?}"),
    }
    // A rule that retires into itself forever ends at the step limit, not in a stack overflow.
    let forever = "r\nrule r md 0 > r { r }\n";
    let few = RenderRequest { limits: Limits { max_steps: 100_000, ..Limits::default() }, ..req(Format::Glb) };
    match render(forever.as_bytes(), &few) {
        Err(RenderError::Limit(l)) => assert_eq!(l.limit, Limit::Steps),
        other => panic!("{other:?}"),
    }
    let out = render(many.as_bytes(), &RenderRequest { on_limit: OnLimit::Truncate, ..small }).unwrap();
    assert_eq!(out.truncated.map(|t| t.limit), Some(Limit::Primitives));
}

#[test]
fn affine_frames_keep_solids_closed_and_outward() {
    // Non-uniform scale, a shear matrix and mirrors: every solid keeps positive volume.
    let src = "{ s 1 2 0.5 } box\n{ x 3 fx } box\n{ x 6 m 1 0.5 0 0 1 0 0 0 1 } box\n{ y 4 s 2 1 1 } sphere\n{ z 4 fy s 1 0.3 2 } cylinder\n";
    let out = render(src.as_bytes(), &req(Format::Stl)).unwrap();
    let tris = decode_stl(&out.bytes);
    assert!(signed_volume(&tris) > 0.0);
    let s = scene("{ s 1 2 0.5 } box\n", 0);
    assert!((s.affine[0].linear.determinant() - 1.0).abs() < 1e-6);
    // A single mirrored box alone has the same volume as the plain one.
    let v = |src: &str| signed_volume(&decode_stl(&render(src.as_bytes(), &req(Format::Stl)).unwrap().bytes));
    assert!((v("{ fx s 2 1 1 } box") - 2.0).abs() < 1e-4);
    assert!((v("{ s 2 1 1 } box") - 2.0).abs() < 1e-4);
}

#[test]
fn lines_grids_dots_and_meshes_are_closed_solids() {
    // Printable: every part closed, no open edges, all facing outward.
    let src = "{ s 2 1 0.5 } grid\n{ x 3 rz 30 } line\n{ x 5 } dot\n{ y 3 s 1 2 1 } cylinder\n{ y 6 } sphere\n3 * { z 1.5 rx 10 s 0.9 } mesh\n";
    let out = render(src.as_bytes(), &req(Format::Stl)).unwrap();
    let dir = tempdir();
    let path = dir.path().join("solids.stl");
    std::fs::write(&path, &out.bytes).expect("write stl");
    let r = admesh(&path);
    assert_eq!((r.open_edges, r.degenerate, r.reversed), (0, 0, 0), "{}", r.raw);
    assert!(r.volume > 0.0, "{}", r.raw);
    // A thicker line_radius makes thicker bars.
    let mut thick = req(Format::Stl);
    thick.params.insert("line_radius".into(), ParamValue::Number(0.1));
    let v = |r: &RenderRequest| signed_volume(&decode_stl(&render(b"line", r).unwrap().bytes));
    assert!((v(&req(Format::Stl)) - 0.02 * 0.02).abs() < 1e-6);
    assert!((v(&thick) - 0.2 * 0.2).abs() < 1e-5);
}

#[test]
fn classes_become_mesh_names_and_detection_works() {
    let src = "box\n{ x 2 } box::glass\n{ x 4 } sphere::glass\n{ x 6 } box::metal\n";
    let out = render(src.as_bytes(), &req(Format::Gltf)).unwrap();
    let j: serde_json::Value = serde_json::from_slice(&out.bytes).unwrap();
    let names: Vec<&str> = j["meshes"].as_array().unwrap().iter().map(|m| m["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["model", "glass", "metal"]);
    let mats: Vec<&str> = j["materials"].as_array().unwrap().iter().filter_map(|m| m["name"].as_str()).collect();
    assert_eq!(mats, ["model", "glass", "metal"]);
    assert_eq!(Language::detect(b"set maxdepth 10\nr\nrule r { box }"), Some(Language::Eisenscript));
    assert_eq!(Language::from_extension(Path::new("x.es")), Some(Language::Eisenscript));
    // No MDG grammar or L-system (which use `#define` too) is taken for EisenScript.
    for ext in ["mdg", "ls"] {
        for f in crate::common::grammar_files(ext) {
            let src = std::fs::read(&f).expect("read grammar");
            assert_ne!(Language::detect(&src), Some(Language::Eisenscript), "{}", f.display());
        }
    }
}

#[test]
fn viewer_settings_become_a_gltf_camera() {
    let camera = |settings: &str| -> serde_json::Value {
        let src = format!("{settings}\nbox\n");
        for format in [Format::Gltf, Format::Glb] {
            let out = render(src.as_bytes(), &req(format)).unwrap();
            let dir = tempdir();
            let path = dir.path().join(format!("camera.{}", format.extension()));
            std::fs::write(&path, &out.bytes).expect("write");
            let (errors, _, report) = validate_gltf(&[path]).remove(0);
            assert_eq!(errors, 0, "{report}");
        }
        let out = render(src.as_bytes(), &req(Format::Gltf)).unwrap();
        let j: serde_json::Value = serde_json::from_slice(&out.bytes).unwrap();
        let scene_nodes = j["scenes"][0]["nodes"].as_array().unwrap().clone();
        let node = scene_nodes.iter().map(|n| &j["nodes"][n.as_u64().unwrap() as usize]).find(|n| n.get("camera").is_some());
        node.cloned().unwrap_or(serde_json::Value::Null)
    };
    // No viewer settings: no camera.
    assert!(camera("").is_null());
    // Structure Synth's default view puts the eye 20 units in front of the model on +Z.
    let c = camera("set scale 1");
    assert_eq!(c["translation"], serde_json::json!([0.0, 0.0, 20.0]));
    assert_eq!(c["rotation"], serde_json::json!([0.0, 0.0, 0.0, 1.0]));
    // Zoom brings it closer; the pivot moves it; a rotation turns it.
    assert_eq!(camera("set scale 2")["translation"], serde_json::json!([0.0, 0.0, 10.0]));
    assert_eq!(camera("set pivot [1 2 3]")["translation"], serde_json::json!([1.0, 2.0, 23.0]));
    let turned = camera("set rotation [0 0 1 0 1 0 -1 0 0]");
    let t: Vec<f64> = turned["translation"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    assert!((t[0] + 20.0).abs() < 1e-4 && t[1].abs() < 1e-4 && t[2].abs() < 1e-4, "{t:?}");
    assert!(render(b"set rotation [1 0 0]\nbox", &req(Format::Glb)).is_err());
    // Fitting the model into the unit box moves the camera with it: Structure
    // Synth's box spans 0..1, so the fit moves everything by −0.5 (scale 1).
    let mut fit = req(Format::Gltf);
    fit.export_options.fit_unit_box = true;
    let j: serde_json::Value = serde_json::from_slice(&render(b"set scale 2\nbox", &fit).unwrap().bytes).unwrap();
    assert_eq!(j["cameras"].as_array().map(Vec::len), Some(1));
    let node = j["nodes"].as_array().unwrap().iter().find(|n| n.get("camera").is_some()).unwrap();
    assert_eq!(node["translation"], serde_json::json!([-0.5, -0.5, 9.5]));
}

/// Every `.es` under `dir`, sorted.
fn scripts_under(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let Ok(rd) = std::fs::read_dir(dir) else { return out };
    for e in rd.flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(scripts_under(&p));
        } else if p.extension().is_some_and(|x| x == "es") {
            out.push(p);
        }
    }
    out.sort();
    out
}

/// The Debian examples that end at a budget limit with default limits, and
/// which. City of Glass (2.99 M triangles flat in 53 651 objects),
/// NineWorthies (2.92 M in 52 218) and Nouveau3 (4.41 M in 19 700 at detail
/// 16) stopped at memory or triangles when every object was tessellated;
/// as instanced glb they render (a box or sphere mesh and at most 52 bytes
/// per object, docs/service.md *GPU instancing*). The movie asked for whole
/// builds 1 001 pictures (about 24 M objects) under one budget, written flat
/// (it is animated), so it ends at the primitive count; Structure Synth
/// builds and renders each picture alone, which `frame` does, and every
/// picture renders at default limits
/// (`debian_movie_renders_every_picture_alone_at_default_limits`).
const LIMITED: [(&str, Limit); 1] = [("Tutorials/JavaScript - Movie.es", Limit::Primitives)];

#[test]
fn debian_examples_render_and_validate() {
    let dir = Path::new("/usr/share/structure-synth/Examples");
    // Required, never skipped: without the examples this test would check nothing.
    assert!(dir.is_dir(), "{} is missing: install Debian's structure-synth package (scripts/test does)", dir.display());
    let files = scripts_under(dir);
    assert!(files.len() >= 30, "expected the package's ~38 examples, found {}", files.len());
    let tmp = tempdir();
    let mut written = Vec::new();
    let mut failures = Vec::new();
    let mut stopped = Vec::new();
    for f in &files {
        let source = std::fs::read(f).expect("read example");
        let name = f.strip_prefix(dir).unwrap_or(f).display().to_string();
        let r = RenderRequest { format: Format::Glb, ..RenderRequest::default() };
        // JavaScript scripts load their EisenScript beside them, as on the CLI.
        let script_dir = f.parent().map(Path::to_path_buf);
        match render(&source, &RenderRequest { language: Language::from_extension(f), script_dir, ..r }) {
            Ok(out) => {
                let path = tmp.path().join(format!("{}.glb", written.len()));
                std::fs::write(&path, &out.bytes).expect("write glb");
                written.push((name, path, out.triangles));
            }
            Err(RenderError::Limit(l)) => {
                assert!(l.to_string().contains(l.limit.name()), "{name}: {l}");
                let expected = LIMITED.iter().find(|(n, _)| *n == name).map(|&(_, l)| l);
                assert_eq!(Some(l.limit), expected, "{name} stopped at a limit: {l}");
                stopped.push(name);
            }
            Err(e) => failures.push(format!("{name}: {e}")),
        }
    }
    assert!(failures.is_empty(), "examples that failed:\n{}", failures.join("\n"));
    assert_eq!(stopped, LIMITED.map(|(n, _)| n), "the examples that end at a limit");
    assert!(written.len() >= 25, "only {} examples rendered", written.len());
    let paths: Vec<PathBuf> = written.iter().map(|(_, p, _)| p.clone()).collect();
    for ((name, ..), (errors, _, report)) in written.iter().zip(validate_gltf(&paths)) {
        assert_eq!(errors, 0, "{name}: {report}");
    }
    // three.js draws every instanced file with its flat triangle count (the
    // count a render reports is the expansion's, instanced or not).
    for ((name, _, triangles), r) in written.iter().zip(three_check(&paths)) {
        assert_eq!(r["ok"], true, "{name} does not load in three.js: {r}");
        assert_eq!(r["triangles"].as_u64(), Some(*triangles), "{name}: {r}");
    }
}

/// A three-frame movie: `frame.es` drawn with 1, 2 and 3 boxes.
const MOVIE: &str = "#javascript\nBuilder.load(\"frame.es\");\nfor (var i = 1; i <= 3; i++) {\n  Builder.reset();\n  Builder.define(\"n\", i);\n  Builder.build();\n  Builder.raytraceToFile(\"f\" + i + \".png\", true);\n}\n";

/// Renders JavaScript `js` with `frame.es` (`n * { x 2 } box`) beside it.
fn movie(js: &str, r: RenderRequest) -> (Result<rulemesh::RenderOutput, RenderError>, tempfile::TempDir) {
    let dir = tempdir();
    std::fs::write(dir.path().join("frame.es"), "#define n 1\nn * { x 2 } box\n").expect("write frame.es");
    let r = RenderRequest { script_dir: Some(dir.path().to_path_buf()), ..r };
    (render(js.as_bytes(), &r), dir)
}

#[test]
fn javascript_movie_frames_play_as_a_step_animation() {
    let (out, dir) = movie(MOVIE, req(Format::Gltf));
    let out = out.unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(out.primitives, 6);
    let j: serde_json::Value = serde_json::from_slice(&out.bytes).unwrap();
    let nodes = j["nodes"].as_array().unwrap();
    let frames: Vec<&serde_json::Value> = nodes.iter().filter(|n| n["name"].as_str().is_some_and(|s| s.starts_with("frame "))).collect();
    assert_eq!(frames.len(), 3);
    // Only frame 0 shows before the animation plays.
    let scales: Vec<&serde_json::Value> = frames.iter().map(|n| &n["scale"]).collect();
    assert_eq!(scales, [&serde_json::json!([1.0, 1.0, 1.0]), &serde_json::json!([0.0, 0.0, 0.0]), &serde_json::json!([0.0, 0.0, 0.0])]);
    let samplers = j["animations"][0]["samplers"].as_array().unwrap();
    assert!(!samplers.is_empty());
    assert!(samplers.iter().all(|s| s["interpolation"] == "STEP"), "{samplers:?}");
    let input = samplers[0]["input"].as_u64().unwrap() as usize;
    assert_eq!(j["accessors"][input]["count"], 3);
    assert_eq!(j["accessors"][input]["max"], serde_json::json!([2.0 / 30.0_f32]));
    // glb: the Khronos validator finds no errors, and a re-run is byte-identical.
    let (glb, _d) = movie(MOVIE, req(Format::Glb));
    let glb = glb.unwrap().bytes;
    let path = dir.path().join("movie.glb");
    std::fs::write(&path, &glb).expect("write glb");
    let (errors, _, report) = validate_gltf(&[path]).remove(0);
    assert_eq!(errors, 0, "{report}");
    assert_eq!(movie(MOVIE, req(Format::Glb)).0.unwrap().bytes, glb);
    // Outputs without animation show frame 0: one box.
    assert_eq!(movie(MOVIE, req(Format::Stl)).0.unwrap().primitives, 1);
    // A script that builds but pictures nothing shows its last build.
    let built = "#javascript\nBuilder.load(\"frame.es\");\nBuilder.define(\"n\", 4);\nBuilder.build();\n";
    assert_eq!(movie(built, req(Format::Glb)).0.unwrap().primitives, 4);
}

/// `frame: k` builds the k-th saved picture alone; a frame the script does
/// not save, or a source that is no movie, is a typed error saying why.
#[test]
fn javascript_movie_frame_builds_one_picture() {
    let one = |k: u32| movie(MOVIE, RenderRequest { frame: Some(k), ..req(Format::Glb) }).0;
    let outs: Vec<rulemesh::RenderOutput> = (0..3).map(|k| one(k).unwrap_or_else(|e| panic!("frame {k}: {e}"))).collect();
    // frame.es with n = k + 1: k + 1 boxes, unanimated.
    assert_eq!(outs.iter().map(|o| o.primitives).collect::<Vec<_>>(), [1, 2, 3]);
    let j: serde_json::Value = serde_json::from_slice(&movie(MOVIE, RenderRequest { frame: Some(2), ..req(Format::Gltf) }).0.unwrap().bytes).expect("glTF JSON");
    assert!(j["animations"].is_null(), "one picture plays no animation");
    assert_eq!(one(1).unwrap().bytes, outs[1].bytes, "same frame, same bytes");
    assert_ne!(outs[1].bytes, outs[2].bytes);
    let frame_error = |r: Result<rulemesh::RenderOutput, RenderError>| match r {
        Err(RenderError::Eval(e @ rulemesh::model::EvalError::Frame { .. })) => e.to_string(),
        other => panic!("expected a frame error, got {other:?}"),
    };
    assert_eq!(frame_error(one(3)), "frame: the script saves 3 pictures (frames 0 to 2); there is no frame 3");
    let built = "#javascript\nBuilder.load(\"frame.es\");\nBuilder.build();\n";
    assert!(frame_error(movie(built, RenderRequest { frame: Some(0), ..req(Format::Glb) }).0).contains("saves no picture"));
    let plain = render(b"box\n", &RenderRequest { frame: Some(0), ..req(Format::Glb) });
    assert!(frame_error(plain).contains("this source is eisenscript, not a movie"));
    let mdg = render(b"startshape A\nrule A { BOX {} }\n", &RenderRequest { language: Some(Language::Mdg), frame: Some(0), ..req(Format::Glb) });
    assert!(frame_error(mdg).contains("this source is mdg"));
}

/// Debian's movie, one picture at a time as Structure Synth renders it: the
/// first, the middle and the last (the largest: `maxdepth` rises with the
/// frame, so every other picture is smaller) render at default limits,
/// validator-clean, with the objects of NouveauMovie.es built with that
/// picture's `#define`s (`_rz` = 360 c, `_md` = 20 + 3000 c, c = k / 1000).
#[test]
fn debian_movie_renders_every_picture_alone_at_default_limits() {
    let dir = Path::new("/usr/share/structure-synth/Examples/Tutorials");
    assert!(dir.is_dir(), "{} is missing: install Debian's structure-synth package (scripts/test does)", dir.display());
    let js = std::fs::read(dir.join("JavaScript - Movie.es")).expect("the movie");
    let nouveau = std::fs::read_to_string(dir.join("NouveauMovie.es")).expect("NouveauMovie.es");
    let tmp = tempdir();
    let mut paths = Vec::new();
    for (k, objects) in [(0u32, 240u64), (500, 23_984), (1000, 47_712)] {
        let r = RenderRequest { language: Some(Language::Eisenscript), script_dir: Some(dir.to_path_buf()), frame: Some(k), ..req(Format::Glb) };
        let out = render(&js, &r).unwrap_or_else(|e| panic!("frame {k}: {e}"));
        assert_eq!(out.primitives, objects, "frame {k}");
        let c = f64::from(k) / 1000.0;
        let text = nouveau.replace("#define _rz 0", &format!("#define _rz {}", c * 360.0)).replace("#define _md 1000", &format!("#define _md {}", 20.0 + c * 3000.0));
        let direct = render(text.as_bytes(), &RenderRequest { language: Some(Language::Eisenscript), ..req(Format::Glb) }).expect("NouveauMovie.es");
        assert_eq!((direct.primitives, direct.triangles), (out.primitives, out.triangles), "frame {k}");
        let path = tmp.path().join(format!("frame-{k}.glb"));
        std::fs::write(&path, &out.bytes).expect("write");
        paths.push(path);
    }
    for (path, (errors, _, report)) in paths.iter().zip(validate_gltf(&paths)) {
        assert_eq!(errors, 0, "{}: {report}", path.display());
    }
}

#[test]
fn javascript_math_random_follows_the_request_seed() {
    let js = "#javascript\nBuilder.load(\"frame.es\");\nBuilder.define(\"n\", 1 + Math.floor(Math.random() * 50));\nBuilder.renderToFile(\"x.png\", true);\nBuilder.define(\"n\", 1 + Math.floor(Math.random() * 50));\n";
    let run = |seed: u64| movie(js, RenderRequest { seed: Some(seed), ..req(Format::Glb) }).0.unwrap_or_else(|e| panic!("{e}")).bytes;
    assert_eq!(run(1), run(1));
    let distinct: std::collections::BTreeSet<Vec<u8>> = (1..=4).map(run).collect();
    assert!(distinct.len() > 1, "Math.random ignores the seed");
    // `Date` is gone: no output can depend on the clock.
    let e = movie("#javascript\nnew Date();\n", req(Format::Glb)).0.unwrap_err();
    assert!(e.to_string().contains("Date is not defined"), "{e}");
}

#[test]
fn javascript_sandbox_limits_are_typed() {
    let limit = |js: &str, limits: Limits| match movie(js, RenderRequest { limits, ..req(Format::Glb) }).0 {
        Err(RenderError::Limit(l)) => l.limit,
        other => panic!("{other:?}"),
    };
    // An endless loop ends at the step limit (QuickJS polls the budget), not in a hang.
    assert_eq!(limit("#javascript\nwhile (true) {}\n", Limits { max_steps: 1_000_000, ..Limits::default() }), Limit::Steps);
    // Catching does not help: the interruption is uncatchable.
    assert_eq!(limit("#javascript\nwhile (true) { try { while (true) {} } catch (e) {} }\n", Limits { max_steps: 1_000_000, ..Limits::default() }), Limit::Steps);
    assert_eq!(limit("#javascript\nwhile (true) {}\n", Limits { timeout_ms: 0, ..Limits::default() }), Limit::Deadline);
    // A huge allocation hits the memory limit.
    let small = Limits { max_memory: 16 << 20, ..Limits::default() };
    assert_eq!(limit("#javascript\nvar s = \"x\".repeat(1 << 26);\n", small), Limit::Memory);
    assert_eq!(limit("#javascript\nvar a = []; while (true) a.push(new Float64Array(1 << 16));\n", small), Limit::Memory);
    // Frames are charged together: three frames of 1 + 2 + 3 boxes exceed 5 primitives.
    assert_eq!(limit(MOVIE, Limits { max_primitives: 5, ..Limits::default() }), Limit::Primitives);
    let few = RenderRequest { limits: Limits { max_primitives: 5, ..Limits::default() }, on_limit: OnLimit::Truncate, ..req(Format::Glb) };
    let out = movie(MOVIE, few).0.unwrap();
    assert_eq!((out.primitives, out.truncated.map(|t| t.limit)), (3, Some(Limit::Primitives)));
}

#[test]
fn javascript_builder_never_runs_programs_or_leaves_its_folder() {
    let dir = tempdir();
    let marker = dir.path().join("ran");
    let js = format!("#javascript\nBuilder.execute(\"touch\", \"{}\", true);\nBuilder.load(\"frame.es\");\nBuilder.build();\n", marker.display());
    let (out, _d) = movie(&js, req(Format::Glb));
    let out = out.unwrap();
    assert!(!marker.exists());
    assert!(out.warnings.iter().any(|w| w.message.contains("execute")), "{:?}", out.warnings);
    for bad in ["../frame.es", "/etc/hostname", "sub/../../frame.es"] {
        match movie(&format!("#javascript\nBuilder.load(\"{bad}\");\n"), req(Format::Glb)).0 {
            Err(RenderError::Eval(rulemesh::model::EvalError::Load { name, .. })) => assert_eq!(name, bad),
            other => panic!("{bad}: {other:?}"),
        }
    }
    // Without a script directory (the service) only library grammars load.
    match render(b"#javascript\nBuilder.load(\"frame.es\");\n", &req(Format::Glb)) {
        Err(RenderError::Eval(rulemesh::model::EvalError::Load { reason, .. })) => assert!(reason.contains("reads no files"), "{reason}"),
        other => panic!("{other:?}"),
    }
    // Script errors carry the line.
    let e = movie("#javascript\n\nfoo(;\n", req(Format::Glb)).0.unwrap_err();
    assert!(matches!(&e, RenderError::Eval(rulemesh::model::EvalError::Script { message }) if message.contains("line 3")), "{e}");
}

/// The examples that needed instancing to fit the default limits also
/// render as `scene`, whose placements are charged as records, not
/// triangles (issue 15: budgets count what a format makes); decoded, each
/// is the glb's flat triangle count.
#[test]
fn big_debian_examples_render_as_scenes_at_default_limits() {
    let dir = Path::new("/usr/share/structure-synth/Examples");
    for (name, objects, triangles) in [("City of Glass.es", 53_651, 2_992_752), ("NineWorthies.es", 52_218, 2_924_208), ("Nouveau3.es", 19_700, 4_412_800)] {
        let source = std::fs::read(dir.join(name)).expect("Debian's structure-synth examples (scripts/test installs them)");
        let r = RenderRequest { format: Format::Scene, language: Some(Language::Eisenscript), ..RenderRequest::default() };
        let out = render(&source, &r).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!((out.primitives, out.triangles), (objects, triangles), "{name}");
        let d = rulemesh::decode::scene::decode_scene_meshes(&out.bytes, 16, u64::MAX).expect("decodes");
        let decoded: u64 = d.meshes.iter().map(|m| m.mesh.indices.len() as u64 / 3).sum();
        assert_eq!(decoded, triangles, "{name}: decoded scene");
    }
}
