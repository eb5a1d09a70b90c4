//! Swept lines (seed 000 §4.3): segment counts, continuation along a line,
//! closed loops and capped ends that admesh finds watertight.

use crate::common::{admesh, decode_stl, repo, run, signed_volume, tempdir};
use glam::DVec3;
use rulemesh::eval::{bind_params, evaluate, EvalOptions};
use rulemesh::core::{Budget, Limits};
use rulemesh::model::Scene;
use std::collections::BTreeMap;

fn scene_of(source: &str) -> Scene {
    let program = rulemesh::lang::mdg::parse(source.as_bytes()).unwrap_or_else(|e| panic!("parse: {e}"));
    let params = bind_params(&program, &BTreeMap::new()).expect("params");
    evaluate(&program, &params, &EvalOptions::default(), &mut Budget::new(Limits::default())).expect("evaluate")
}

fn segments(scene: &Scene) -> usize {
    scene.lines.iter().map(|l| l.points.len().saturating_sub(1)).sum()
}

#[test]
fn listing_5_1_draws_the_arrowhead_with_2187_segments() {
    // The listing itself, seven levels deep (grammars/arrowhead.mdg stops at
    // five and sweeps a thicker tube, to read at icon size).
    let src = "startshape YF\nselector XF, YF depth\n\
        rule XF 6 { YF{} \\ XF{rx 60} \\ YF{rx 60} }\nrule YF 6 { XF{} \\ YF{rx -60} \\ XF{rx -60} }\n\
        rule XF 7 { SLINETO{z 1} }\nrule YF 7 { SLINETO{z 1} }\n";
    let library = scene_of(&std::fs::read_to_string(repo().join("grammars/arrowhead.mdg")).expect("arrowhead.mdg"));
    assert_eq!((library.lines.len(), segments(&library)), (1, 243), "the library's five levels: 3^5 segments");
    let scene = scene_of(src);
    assert_eq!(scene.lines.len(), 1, "one continuous line");
    assert_eq!(segments(&scene), 2187);
    let pts: Vec<DVec3> = scene.lines[0].points.iter().map(|p| p.frame.translation).collect();
    // Every segment has unit length and lies in the plane x = 0.
    for w in pts.windows(2) {
        assert!(((w[1] - w[0]).length() - 1.0).abs() < 1e-9);
        assert!(w[1].x.abs() < 1e-9);
    }
    // A simple path: 2188 distinct vertices (seed notes, worked example 4).
    let mut keys: Vec<(i64, i64)> = pts.iter().map(|p| ((p.y * 1e6).round() as i64, (p.z * 1e6).round() as i64)).collect();
    keys.sort();
    keys.dedup();
    assert_eq!(keys.len(), 2188);
    // It ends 128 units from its start, at (0, 64√3, 64) or its mirror image.
    let end = *pts.last().expect("points");
    assert!((end.length() - 128.0).abs() < 1e-6, "{end}");
    assert!((end.y.abs() - 64.0 * 3f64.sqrt()).abs() < 1e-6 && (end.z - 64.0).abs() < 1e-6, "{end}");
}

#[test]
fn pen_operations_start_lift_and_reset_lines() {
    // Pen starts down at the origin: a first LINETO draws a segment.
    assert_eq!(segments(&scene_of("rule A { LINETO { z 1 } LINETO { z 2 } }")), 2);
    // MOVETO places the pen without drawing.
    let s = scene_of("rule A { MOVETO { x 5 } LINETO { x 6 } }");
    assert_eq!((s.lines.len(), segments(&s)), (1, 1));
    // NEWLINE lifts the pen: the next LINETO only puts it down (seed notes, example 6).
    let s = scene_of("rule A { LINETO { z 1 } NEWLINE {} LINETO { x 3 } LINETO { x 4 } LINETO { x 5 } }");
    assert_eq!((s.lines.len(), segments(&s)), (2, 3));
    // RESET returns to the last MOVETO and starts a new line there.
    let s = scene_of("rule A { MOVETO { y 1 } LINETO { y 2 } RESET {} LINETO { x 1 y 1 } }");
    assert_eq!(s.lines.len(), 2);
    assert!((s.lines[1].points[0].frame.translation - DVec3::Y).length() < 1e-12);
    // Continuation starts from the pen.
    let s = scene_of("rule A { LINETO { z 1 } \\ LINETO { z 1 } \\ LINETO { z 1 } }");
    let z: Vec<f64> = s.lines[0].points.iter().map(|p| p.frame.translation.z).collect();
    assert_eq!(z, [0.0, 1.0, 2.0, 3.0]);
}

fn render_stl(src: &str, name: &str) -> (std::path::PathBuf, tempfile::TempDir) {
    let dir = tempdir();
    let path = dir.path().join(format!("{name}.stl"));
    let out = run(&["render", "-", "--language", "mdg", "-o", path.to_str().expect("utf-8")], Some(src.as_bytes()));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    (path, dir)
}

#[test]
fn a_lathe_closes_with_no_gap_and_open_lines_are_capped() {
    for (name, src) in [
        ("lathe", "rule A { MOVETO { x 1 } 30/30 * [ry 360] LINETO { x 1 } }"),
        ("open", "rule A { MOVETO {} 5 * { z 1 rx 20 } LINETO {} }"),
        ("mirrored", "rule A { B { fx } } rule B { MOVETO {} 5 * { z 1 rx 20 } LINETO {} }"),
        ("backwards", "rule A { MOVETO {} 5 * { z -1 ry 10 } SLINETO {} }"),
    ] {
        let (path, _dir) = render_stl(src, name);
        let r = admesh(&path);
        assert_eq!(r.open_edges, 0, "{name}: {}", r.raw);
        assert_eq!(r.parts, 1, "{name}: {}", r.raw);
        assert_eq!(r.reversed, 0, "{name}: {}", r.raw);
        assert_eq!(r.degenerate, 0, "{name}: {}", r.raw);
        let v = signed_volume(&decode_stl(&std::fs::read(&path).expect("stl")));
        assert!(v > 0.0, "{name}: volume {v}");
    }
}

#[test]
fn the_c2_knot_convolves_three_paths_into_one_closed_line() {
    let src = std::fs::read_to_string(repo().join("grammars/knot.mdg")).expect("knot.mdg");
    let scene = scene_of(&src);
    // NEWLINE lifts the pen, so the first of 4000 ALINETOs only places it.
    assert_eq!(scene.lines.len(), 1);
    assert_eq!(segments(&scene), 3999);
    // Point i sits in frame zpath_i ∘ ypath_i ∘ xpath_i (parent first), inside
    // `ring {s 2}` and moved by `z 0.2`: hand-computed with quaternions.
    let turn = std::f64::consts::TAU;
    for i in [1usize, 2, 1000, 2345, 4000] {
        let t = i as f64 / 4000.0;
        let q = glam::DQuat::from_rotation_z(9.0 * turn * t)
            * glam::DQuat::from_rotation_y(81.0 * turn * t)
            * glam::DQuat::from_rotation_x(16.0 * turn * t);
        let expected = 2.0 * (q * DVec3::new(0.0, 0.0, 0.2));
        let got = scene.lines[0].points[i - 1].frame.translation;
        assert!((got - expected).length() < 1e-9, "point {i}: {got} vs {expected}");
        assert!((scene.lines[0].points[i - 1].frame.scale - 0.6).abs() < 1e-12);
    }
    // The 12-point line rule is the profile.
    assert_eq!(scene.profiles.len(), 1);
    assert_eq!(scene.profiles[0].len(), 12);
    let (path, _dir) = render_stl(&src, "knot");
    let r = admesh(&path);
    assert_eq!((r.open_edges, r.parts, r.reversed, r.degenerate), (0, 1, 0, 0), "{}", r.raw);
}

#[test]
fn animated_rules_render_their_first_frame_and_recursive_paths_stop() {
    // `transform` recurses forever; only its first frame is needed for static output.
    let src = "startshape S\nrule S : T { BOX {} }\nrule T { FRAME { x 3 } T { ry 1 } }";
    let scene = scene_of(src);
    assert_eq!(scene.instances.len(), 1);
    assert!((scene.instances[0].translation.x - 3.0).abs() < 1e-6);
}

#[test]
fn free_vertices_make_triangles_and_facenormals_sets_their_normals() {
    let src = "rule A { VERTEX {} VERTEX { x 1 } VERTEX { y 1 } FACENORMALS {} VERTEX { z 1 } }";
    let scene = scene_of(src);
    assert_eq!(scene.vertices.len(), 4);
    for v in &scene.vertices[..3] {
        assert!((v.normal - DVec3::Z).length() < 1e-12);
    }
    let out = run(&["render", "-", "--language", "mdg", "--format", "stl"], Some(src.as_bytes()));
    assert!(out.status.success());
    let tris = decode_stl(&out.stdout);
    assert_eq!(tris.len(), 1, "the fourth vertex makes no triangle");
}

#[test]
fn smooth_triangle_is_a_closed_triangle_because_a_continued_iterator_turns_the_pen() {
    // Seed 000's SMOOTH_TRIANGLE listing (L749–756), verbatim: `\` before
    // `10/10 * {rx 120} LINETO{}` places the copies from the last terminal's
    // frame, so the pen turns 120° on the spot after each unit side and the
    // path closes into an equilateral triangle in the plane x = 0. (Before,
    // each copy continued on its own and dropped the turn: a 3-unit rod.)
    let s = scene_of(
        "startshape T\nrule T { MOVETO {} SMOOTH_TRIANGLE {} }\nrule SMOOTH_TRIANGLE {\n  LINETO{z 1} \\\n  10/10 * {rx 120} LINETO{} \\\n  LINETO{z 1} \\\n  10/10 * {rx 120} LINETO{} \\\n  LINETO{z 1} \\\n  10/10 * {rx 120} LINETO{} \\\n}\n",
    );
    assert_eq!(s.lines.len(), 1);
    let mut corners: Vec<DVec3> = s.lines[0].points.iter().map(|p| p.frame.translation).collect();
    corners.dedup_by(|a, b| (*a - *b).length() < 1e-9);
    let want = [DVec3::ZERO, DVec3::new(0.0, 0.0, 1.0), DVec3::new(0.0, -(3f64.sqrt()) / 2.0, 0.5), DVec3::ZERO];
    assert_eq!(corners.len(), want.len(), "{corners:?}");
    for (got, want) in corners.iter().zip(want) {
        assert!((*got - want).length() < 1e-9, "{corners:?}");
    }
}

#[test]
fn a_continuation_inside_an_iterator_continues_each_copy() {
    // `3 * {x 5} \ BOX{z 1}` (C.4's LAYERS form): each copy's call starts
    // from the last terminal (the box before it), so the boxes chain along
    // z and the step is not applied; `\ 3 * {x 5} BOX{}` starts the iterator there instead.
    let inside = scene_of("rule A { MOVETO { y 2 } 3 * {x 5} \\ BOX { z 1 } }");
    let z: Vec<[f32; 3]> = inside.instances.iter().map(|i| i.translation.to_array()).collect();
    assert_eq!(z, [[0.0, 2.0, 1.0], [0.0, 2.0, 2.0], [0.0, 2.0, 3.0]]);
    let before = scene_of("rule A { MOVETO { y 2 } \\ 3 * {x 5} BOX {} }");
    let x: Vec<[f32; 3]> = before.instances.iter().map(|i| i.translation.to_array()).collect();
    assert_eq!(x, [[5.0, 2.0, 0.0], [10.0, 2.0, 0.0], [15.0, 2.0, 0.0]]);
}
