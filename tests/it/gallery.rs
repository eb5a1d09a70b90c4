//! The thesis gallery (seed 000 appendix C) renders with the counts the seed
//! notes work out, and isosurfaces are closed solids.

use crate::common::{admesh, repo, run, tempdir};
use rulemesh::eval::{bind_params, evaluate, EvalOptions};
use rulemesh::core::{Budget, Limits};
use rulemesh::model::Scene;
use std::collections::BTreeMap;

fn scene_of_file(name: &str) -> Scene {
    let src = std::fs::read_to_string(repo().join("grammars").join(name)).expect("grammar");
    let program = rulemesh::lang::mdg::parse(src.as_bytes()).unwrap_or_else(|e| panic!("parse: {e}"));
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

#[test]
fn c4_silicon_carbide_lattice() {
    let scene = scene_of_file("sic-lattice.mdg");
    // 96 SiC units, each 1 silicon and 3 carbons, and 4 bonds of length 1.
    assert_eq!(scene.instances.len(), 384);
    let big = scene.instances.iter().filter(|i| (i.scale - 0.2 * 1.17).abs() < 1e-6).count();
    assert_eq!(big, 96, "silicon spheres");
    assert_eq!(scene.lines.len(), 384);
    for l in &scene.lines {
        assert_eq!(l.points.len(), 2);
        assert!(((l.points[1].frame.translation - l.points[0].frame.translation).length() - 1.0).abs() < 1e-9);
    }
}

#[test]
fn truncated_icosahedron_skeleton() {
    let scene = scene_of_file("truncated-icosahedron.mdg");
    // 20 hexagon frames × (NEWLINE, then 6 LINETOs of which the first places the pen).
    assert_eq!(scene.lines.len(), 20);
    assert!(scene.lines.iter().all(|l| l.points.len() == 6));
    let mut keys: Vec<[i64; 3]> = Vec::new();
    for p in scene.lines.iter().flat_map(|l| &l.points) {
        assert!((p.frame.translation.length() - 10.0).abs() < 1e-6);
        keys.push(p.frame.translation.to_array().map(|c| (c * 1e4).round() as i64));
    }
    keys.sort();
    keys.dedup();
    assert_eq!(keys.len(), 60, "60 distinct vertices at radius 10");
}

#[test]
fn listing_4_1_stops_at_depth_30_and_the_listing_itself_grows_otherwise() {
    // The library version ends every walk at depth 30; its seed forks into a spray.
    let scene = scene_of_file("listing-4-1.mdg");
    assert_eq!(scene.instances.len(), 270);
    let src = repo().join("grammars/listing-4-1.mdg");
    let out = run(&["render", src.to_str().expect("utf-8"), "--seed", "0", "-o", "-"], None);
    assert!(out.status.success(), "any seed draws: {}", String::from_utf8_lossy(&out.stderr));
    // Without `maxdepth` (the listing as printed), seed 0 grows until a limit.
    let dir = tempdir();
    let listing = dir.path().join("listing.mdg");
    let text = std::fs::read_to_string(&src).expect("listing-4-1.mdg").replace("maxdepth 30\n", "");
    std::fs::write(&listing, text).expect("write");
    let out = run(&["render", listing.to_str().expect("utf-8"), "--seed", "0", "-o", "-"], None);
    assert_eq!(out.status.code(), Some(3), "seed 0 grows until a limit");
    let out = run(&["render", listing.to_str().expect("utf-8"), "--seed", "0", "--on-limit", "truncate", "-o", "-"], None);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("TRUNCATED"));
}

#[test]
fn sphereflake_switches_detail_by_scale() {
    let scene = scene_of_file("sphereflake.mdg");
    use rulemesh::core::PrimitiveKind;
    let spheres = scene.instances.iter().filter(|i| i.kind == PrimitiveKind::Sphere).count();
    let octas = scene.instances.iter().filter(|i| i.kind == PrimitiveKind::Octahedron).count();
    // Scales 1, 0.42, 0.176 draw spheres (1 + 8 + 64); 0.074 and 0.031 draw octahedra (512 + 4096)…
    // …but below 0.02 nothing: 0.42^4 = 0.031 ≥ 0.02 draws, 0.42^5 = 0.013 stops.
    assert_eq!(spheres, 1 + 8 + 64);
    assert!(scene.instances.iter().filter(|i| i.kind == PrimitiveKind::Sphere).all(|i| i.scale > 0.12));
    assert!(scene.instances.iter().filter(|i| i.kind == PrimitiveKind::Octahedron).all(|i| i.scale <= 0.12));
    assert_eq!(spheres + octas, scene.instances.len());
}

#[test]
fn blendto_inserts_smooth_sub_segments() {
    let src = "rule A { MOVETO {} BLENDTO { x 4 ry 90 s 2 } }";
    let program = rulemesh::lang::mdg::parse(src.as_bytes()).expect("parse");
    let scene = evaluate(&program, &[], &EvalOptions::default(), &mut Budget::new(Limits::default())).expect("evaluate");
    let pts = &scene.lines[0].points;
    assert_eq!(pts.len(), 1 + 8, "start, 7 blended points, end");
    // It starts along the start frame's +Z and ends at the target with its scale.
    assert!((pts[8].frame.translation - glam::DVec3::new(4.0, 0.0, 0.0)).length() < 1e-9);
    assert!((pts[8].frame.scale - 2.0).abs() < 1e-12);
    assert!(pts[1].frame.translation.z > 0.0, "leaves along +z");
    // Scales blend monotonically.
    assert!(pts.windows(2).all(|w| w[1].frame.scale >= w[0].frame.scale));
}
