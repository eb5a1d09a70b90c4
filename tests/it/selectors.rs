//! Rule selection modes and continuation (seed 000 §4.2.2, §4.2.4): each
//! alternative draws a different primitive, so the scene records which rule
//! ran at each call.

use glam::Vec3;
use rulemesh::eval::{bind_params, evaluate, EvalOptions};
use rulemesh::core::{Budget, Limits};
use rulemesh::model::Scene;
use rulemesh::lang::ir::PrimitiveKind;
use std::collections::BTreeMap;
use PrimitiveKind::{Box as B, Cone, Icosahedron as Ico, Octahedron as Oct, Sphere, Tetrahedron as Tet};

fn scene_of(source: &str, seed: u64) -> Scene {
    let program = rulemesh::lang::mdg::parse(source.as_bytes()).unwrap_or_else(|e| panic!("parse: {e}"));
    let params = bind_params(&program, &BTreeMap::new()).expect("params");
    let options = EvalOptions { seed: Some(seed), ..EvalOptions::default() };
    evaluate(&program, &params, &options, &mut Budget::new(Limits::default())).expect("evaluate")
}

fn kinds(scene: &Scene) -> Vec<PrimitiveKind> {
    scene.instances.iter().map(|i| i.kind).collect()
}

#[test]
fn every_selector_mode_picks_the_documented_rule() {
    let src = "
startshape Root
selector D depth
selector S scale
selector Q sequential
selector F function { x }
selector R random

rule Root { D {} S {} 5 * {x 1} Q {} F { x -1 } F { x 5 } F { x 200 } 3 * {} R {} }

// depth: the smallest weight >= the call's depth (Root is 0, D starts at 1)
rule D 2 { CONE {} D {} }
rule D 4 { BOX {} D {} }

// scale: the smallest weight >= the frame's scale
rule S 0.3 { TETRAHEDRON {} }
rule S 10 { SPHERE {} S { s 0.5 } }

// sequential: each rule `weight` times in order, then again
rule Q 2 { BOX {} }
rule Q 1 { CONE {} }

// function of position: the smallest weight >= x
rule F 0 { OCTAHEDRON {} }
rule F 100 { ICOSAHEDRON {} }

// random: weight 0 is never chosen
rule R 1 { BOX {} }
rule R 0 { SPHERE {} }
";
    let expected = vec![
        Cone, Cone, B, B, // depth 1, 2 → weight 2; depth 3, 4 → weight 4; depth 5 → none
        Sphere, Sphere, Tet, // scale 1, 0.5 → weight 10; 0.25 → weight 0.3
        B, B, Cone, B, B, // sequential 2 × BOX, 1 × CONE, repeating
        Oct, Ico, // x = -1 → weight 0; x = 5 → weight 100; x = 200 → none
        B, B, B, // random never picks weight 0
    ];
    for seed in [0, 1, 99] {
        assert_eq!(kinds(&scene_of(src, seed)), expected, "seed {seed}");
    }
}

#[test]
fn sequential_counts_per_name_in_depth_first_order() {
    // The inner calls of the first Q run before the second top-level Q.
    let src = "startshape Root\nselector Q sequential\nrule Root { P {} P {} }\nrule P { Q {} Q {} }\nrule Q 1 { BOX {} }\nrule Q 1 { SPHERE {} }\nrule Q 1 { CONE {} }";
    assert_eq!(kinds(&scene_of(src, 0)), [B, Sphere, Cone, B]);
}

#[test]
fn listing_5_1_depth_selector_recurses_to_depth_7() {
    // Seed 000 Listing 5.1 with BOX standing in for SLINETO: 3^7 terminals.
    let src = "startshape YF\nselector XF, YF depth\nrule XF 6 { YF{} XF{rx 60} YF{rx 60} }\nrule YF 6 { XF{} YF{rx -60} XF{rx -60} }\nrule XF 7 { BOX{z 1} }\nrule YF 7 { BOX{z 1} }";
    assert_eq!(scene_of(src, 0).instances.len(), 2187);
}

#[test]
fn continuation_starts_from_the_last_terminal() {
    let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-5;
    // Without `\` every call starts from the caller's frame; with it, from the last box.
    let plain = scene_of("startshape A\nrule A { BOX { x 1 } BOX { x 1 } BOX { x 1 } }", 0);
    assert!(plain.instances.iter().all(|i| close(i.translation, Vec3::X)));
    let chained = scene_of("startshape A\nrule A { BOX { x 1 } \\ BOX { x 1 } \\ BOX { x 1 } }", 0);
    let t: Vec<Vec3> = chained.instances.iter().map(|i| i.translation).collect();
    assert!(close(t[0], Vec3::X) && close(t[1], Vec3::new(2.0, 0.0, 0.0)) && close(t[2], Vec3::new(3.0, 0.0, 0.0)), "{t:?}");
    // Continuation reaches into a deeper rule's terminal, orientation included.
    let walk = scene_of("startshape Walk\nrule Walk { Step {} \\ Step {} \\ Step {} }\nrule Step { BOX { x 1 rz 90 } }", 0);
    let t: Vec<Vec3> = walk.instances.iter().map(|i| i.translation).collect();
    assert!(close(t[0], Vec3::X) && close(t[1], Vec3::new(1.0, 1.0, 0.0)) && close(t[2], Vec3::new(0.0, 1.0, 0.0)), "{t:?}");
    // Under an iterator, `\` chains every copy (seed 000 L1447).
    let iter = scene_of("startshape A\nrule A { BOX {} 3 * {} \\ BOX { x 1 } }", 0);
    let xs: Vec<f32> = iter.instances.iter().map(|i| i.translation.x).collect();
    assert_eq!(xs, [0.0, 1.0, 2.0, 3.0]);
}
