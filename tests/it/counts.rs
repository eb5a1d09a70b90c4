//! Exact-count tests through the library pipeline (parse → bind → evaluate).

use crate::common::{decode_stl, render_source, repo, signed_volume};
use glam::Vec3;
use rulemesh::eval::{bind_params, evaluate, EvalOptions};
use rulemesh::core::{Budget, Limits};
use rulemesh::model::Scene;
use rulemesh::lang::ir::PrimitiveKind;
use std::collections::BTreeMap;

fn scene_of(source: &str) -> Scene {
    let program = rulemesh::lang::mdg::parse(source.as_bytes()).unwrap_or_else(|e| panic!("parse: {e}"));
    let params = bind_params(&program, &BTreeMap::new()).expect("params");
    evaluate(&program, &params, &EvalOptions::default(), &mut Budget::new(Limits::default())).expect("evaluate")
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-5
}

#[test]
fn ten_boxes_along_x() {
    let scene = scene_of("startshape A\nrule A { 10 * {x 1} BOX {} }");
    assert_eq!(scene.instances.len(), 10);
    for (k, inst) in scene.instances.iter().enumerate() {
        assert_eq!(inst.kind, PrimitiveKind::Box);
        // Copy k (1-based) gets the step k times: the first copy already moved.
        assert!(close(inst.translation, Vec3::new(k as f32 + 1.0, 0.0, 0.0)), "copy {k}: {:?}", inst.translation);
        assert_eq!(inst.scale, 1.0);
        assert!(!inst.parity);
    }
}

#[test]
fn menger_sponge_has_8000_boxes_in_a_unit_cube() {
    let src = std::fs::read_to_string(repo().join("grammars/menger.mdg")).expect("menger.mdg");
    let scene = scene_of(&src);
    assert_eq!(scene.instances.len(), 8000);
    assert!(scene.instances.iter().all(|i| i.kind == PrimitiveKind::Box));
    // Every box has edge 1/27 and lies inside the unit cube; no two coincide.
    let mut keys: Vec<[i64; 3]> = scene
        .instances
        .iter()
        .map(|i| {
            assert!((i.scale - 1.0 / 27.0).abs() < 1e-6);
            assert!(i.translation.abs().max_element() < 0.5);
            i.translation.to_array().map(|c| (c * 27.0 * 2.0).round() as i64)
        })
        .collect();
    keys.sort();
    keys.dedup();
    assert_eq!(keys.len(), 8000);
}

#[test]
fn divided_iterator_copies_match_the_seed() {
    // Seed 000 decision 4: `m/n * {T}` steps by T/n, so `2/2 * {rz 180}` gives
    // copies at 90° and 180°, and `12/12 * {ry 360}` ends on a full turn.
    let scene = scene_of("startshape A\nrule A { 2/2 * {rz 180} BOX {x 1} }");
    let t: Vec<Vec3> = scene.instances.iter().map(|i| i.translation).collect();
    assert_eq!(t.len(), 2);
    assert!(close(t[0], Vec3::Y), "{t:?}");
    assert!(close(t[1], -Vec3::X), "{t:?}");
    let scene = scene_of("startshape A\nrule A { 12/12 * {ry 360} BOX {x 1} }");
    assert_eq!(scene.instances.len(), 12);
    assert!(close(scene.instances[11].translation, Vec3::X));
    assert!(close(scene.instances[2].translation, Vec3::new(0.0, 0.0, -1.0)), "ry 90 maps x to -z");
}

#[test]
fn mirrored_geometry_still_faces_outward() {
    // An off-centre cone and its `fx` mirror image: both must enclose positive volume.
    for src in ["startshape A\nrule A { CONE { x 2 rz 30 } }", "startshape A\nrule A { CONE { fx x 2 rz 30 } }"] {
        let tris = decode_stl(&render_source(src, &["--format", "stl"]));
        let v = signed_volume(&tris);
        // Cone volume: π r² h / 3 with r = 0.5, h = 1, within tessellation error.
        assert!(v > 0.0, "{src}: signed volume {v}");
        assert!((v - std::f64::consts::PI * 0.25 / 3.0).abs() < 0.03, "{src}: volume {v}");
    }
    let scene = scene_of("startshape A\nrule A { CONE { fx x 2 } }");
    assert!(scene.instances[0].parity);
    assert!(close(scene.instances[0].translation, Vec3::new(-2.0, 0.0, 0.0)));
}

#[test]
fn colours_add_and_clamp() {
    let scene = scene_of("startshape A\nrule A { 3 * {R 0.5} BOX { G 0.25 A -0.5 } }");
    let c: Vec<[f32; 4]> = scene.instances.iter().map(|i| i.colour).collect();
    assert_eq!(c, vec![[0.5, 0.25, 0.0, 0.5], [1.0, 0.25, 0.0, 0.5], [1.0, 0.25, 0.0, 0.5]]);
}
