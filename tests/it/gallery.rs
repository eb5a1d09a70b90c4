//! The thesis gallery (seed 000 appendix C) renders with the counts the seed
//! notes work out, and isosurfaces are closed solids.

use crate::common::{admesh, repo, run, tempdir};
use rulemesh::eval::{bind_params, evaluate, Budget, EvalOptions, Limits, Scene};
use rulemesh::lang::{parse, Language};
use std::collections::BTreeMap;

fn scene_of_file(name: &str) -> Scene {
    let src = std::fs::read_to_string(repo().join("grammars").join(name)).expect("grammar");
    let program = parse(Language::Mdg, src.as_bytes()).unwrap_or_else(|e| panic!("parse: {e}"));
    let params = bind_params(&program, &BTreeMap::new()).expect("params");
    evaluate(&program, &params, &EvalOptions::default(), &mut Budget::new(Limits::default())).expect("evaluate")
}

#[test]
fn c5_dodecahedron_in_the_coxeter_complex() {
    let scene = scene_of_file("coxeter-dodecahedron.mdg");
    // 108 VERTEX calls: 36 triangles over the dodecahedron's 20 vertices at radius 20.
    assert_eq!(scene.vertices.len(), 108);
    let mut keys: Vec<[i64; 3]> = scene.vertices.iter().map(|v| v.position.to_array().map(|c| (c * 1e6).round() as i64)).collect();
    for v in &scene.vertices {
        assert!((v.position.length() - 20.0).abs() < 1e-6, "{}", v.position);
    }
    keys.sort();
    keys.dedup();
    assert_eq!(keys.len(), 20);
    // 30 SPHEREs, each the grammar's own isosurface, not the built-in primitive.
    assert_eq!(scene.instances.len(), 0);
    assert_eq!(scene.shape_instances.len(), 30);
    assert_eq!(scene.shapes.len(), 1);
    // 15 great circles, each 48 LINETOs closing back on its MOVETO.
    assert_eq!(scene.lines.len(), 15);
    for l in &scene.lines {
        assert_eq!(l.points.len(), 49);
        assert!((l.points[0].frame.translation - l.points[48].frame.translation).length() < 1e-9);
    }
}

#[test]
fn an_isosurface_is_a_closed_solid_and_overrides_a_primitive() {
    let dir = tempdir();
    let path = dir.path().join("iso.stl");
    let src = "isosurface SPHERE {\n  xyz -1 1 10\n  function { 0.8 - (x*x + y*y + z*z) }\n}\nrule A { SPHERE { s 3 } SPHERE { x 4 } }";
    let out = run(&["render", "-", "--language", "mdg", "-o", path.to_str().expect("utf-8")], Some(src.as_bytes()));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let r = admesh(&path);
    assert_eq!((r.open_edges, r.parts, r.reversed, r.degenerate), (0, 2, 0, 0), "{}", r.raw);
    assert!(r.volume > 0.0);
    // A huge grid is refused by the step budget before it is sampled.
    let big = "isosurface S { xyz -1 1 100000 function { 1 } }\nrule A { S {} }";
    let out = run(&["render", "-", "--language", "mdg", "-o", "-"], Some(big.as_bytes()));
    assert_eq!(out.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&out.stderr).contains("limit exceeded: steps"), "{}", String::from_utf8_lossy(&out.stderr));
}
