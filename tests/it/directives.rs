//! The rest of MDG's directives (seed 000 §4.1.4, B.1, B.2): namespaces with
//! their own pens and continuation points, `@import` of built-in grammars,
//! `@presets`, `color`/`weight` renaming, `stacksize`, and their errors.

use crate::common::run;
use rulemesh::eval::{bind_params, evaluate, EvalOptions};
use rulemesh::core::{Budget, Limits, ParamValue};
use rulemesh::model::Scene;
use std::collections::BTreeMap;

fn scene_with(source: &str, params: &[(&str, &str)]) -> Scene {
    let program = rulemesh::lang::mdg::parse(source.as_bytes()).unwrap_or_else(|e| panic!("parse: {e}"));
    let given: BTreeMap<String, ParamValue> = params.iter().map(|(k, v)| (k.to_string(), ParamValue::Text(v.to_string()))).collect();
    let params = bind_params(&program, &given).unwrap_or_else(|e| panic!("params: {e}"));
    evaluate(&program, &params, &EvalOptions::default(), &mut Budget::new(Limits::default())).expect("evaluate")
}

fn scene_of(source: &str) -> Scene {
    scene_with(source, &[])
}

fn parse_error(source: &str) -> String {
    match rulemesh::lang::mdg::parse(source.as_bytes()) {
        Ok(_) => panic!("expected a parse error for:\n{source}"),
        Err(e) => e.to_string(),
    }
}

/// Line end points, rounded, per polyline.
fn line_points(s: &Scene) -> Vec<Vec<[i64; 3]>> {
    s.lines
        .iter()
        .map(|l| l.points.iter().map(|p| p.frame.translation.to_array().map(|c| (c * 1000.0).round() as i64)).collect())
        .collect()
}

#[test]
fn each_namespace_has_its_own_pen() {
    // Interleaved LINETOs of two namespaces draw two separate lines; the
    // global pen draws a third from the origin.
    let s = scene_of(
        "startshape START
namespace a { rule START { LINETO { x 1 } } }
namespace b { rule START { LINETO { y 1 } } }
rule START {
  a.START {} b.START {} a.LINETO { x 2 } b.LINETO { y 2 }
  LINETO { z 3 }
}",
    );
    let k = 1000;
    assert_eq!(
        line_points(&s),
        vec![vec![[0, 0, 0], [k, 0, 0], [2 * k, 0, 0]], vec![[0, 0, 0], [0, k, 0], [0, 2 * k, 0]], vec![[0, 0, 0], [0, 0, 3 * k]]]
    );
}

#[test]
fn calls_inside_a_namespace_prefer_its_own_rules() {
    // In namespace n, `LEAF` is n.LEAF (a sphere); outside, the global LEAF (a box);
    // `n.LEAF` can be called from anywhere, and a global rule is found from inside.
    let s = scene_of(
        "startshape TOP
rule LEAF { BOX {} }
rule ONLYGLOBAL { CYLINDER {} }
namespace n {
  rule LEAF { SPHERE {} }
  rule TREE { LEAF { x 1 } ONLYGLOBAL { x 2 } }
}
rule TOP { n.TREE {} LEAF { x 3 } n.LEAF { x 4 } }",
    );
    let kinds: Vec<(String, f32)> = s.instances.iter().map(|i| (i.kind.name().to_string(), i.translation.x)).collect();
    let want: Vec<(String, f32)> = [("SPHERE", 1.0), ("CYLINDER", 2.0), ("BOX", 3.0), ("SPHERE", 4.0)].iter().map(|(k, x)| (k.to_string(), *x)).collect();
    assert_eq!(kinds, want);
}

#[test]
fn continuation_reads_the_namespace_of_the_call() {
    // The global BOX at x 5 is the last terminal overall, but `\` inside
    // namespace a continues from a's last terminal (its LINETO at y 2).
    let s = scene_of(
        "startshape TOP
namespace a {
  rule DRAW { LINETO { y 2 } }
  rule NEXT { \\ SPHERE { z 1 } }
}
rule TOP { a.DRAW {} BOX { x 5 } a.NEXT {} }",
    );
    let sphere = s.instances.iter().find(|i| i.kind.name() == "SPHERE").expect("sphere");
    assert_eq!(sphere.translation.to_array(), [0.0, 2.0, 1.0]);
}

#[test]
fn import_brings_in_a_built_in_grammar_but_not_its_startshape() {
    let gem = scene_of(&String::from_utf8(std::fs::read(crate::common::repo().join("grammars/gem.mdg")).expect("gem")).expect("utf-8"));
    // Without its startshape, the importer's START runs; gem's rules are callable.
    let s = scene_of("@import gem\nrule START { Gem {} BOX { x 10 } }\n");
    assert_eq!(s.instances.len(), gem.instances.len() + 1);
    // Namespaced import: the gem's rules become g.Gem, g.Facet, …
    let s = scene_of("startshape START\nnamespace g {\n@import gem\n}\nrule START { g.Gem {} }\n");
    assert_eq!(s.instances.len(), gem.instances.len());
    // Only library names: paths and unknown names (C.5 imports the thesis's
    // shader project) are ignored with a warning at the @import; nothing is read.
    for src in ["rule A { BOX {} }\n  @import ../../etc/passwd\n", "rule A { BOX {} }\n  @import /etc/passwd\n", "rule A { BOX {} }\n  @import nosuchgrammar\n"] {
        let p = rulemesh::lang::mdg::parse(src.as_bytes()).expect("parses");
        assert_eq!(p.warnings.len(), 1, "{src}");
        assert_eq!((p.warnings[0].span.line, p.warnings[0].span.column), (2, 3));
        assert!(p.warnings[0].to_string().contains("ignored: only built-in grammars"), "{}", p.warnings[0]);
        assert_eq!(scene_of(src).instances.len(), 1);
    }
}

#[test]
fn presets_are_a_named_parameter() {
    let src = "@presets small large huge\nrule A { (1 + preset) * { x 1 } BOX {} }\n";
    assert_eq!(scene_of(src).instances.len(), 1);
    assert_eq!(scene_with(src, &[("preset", "large")]).instances.len(), 2);
    assert_eq!(scene_with(src, &[("preset", "huge")]).instances.len(), 3);
    assert_eq!(scene_with(src, &[("preset", "1")]).instances.len(), 2);
    // Preset names are constants in expressions.
    let src2 = "@presets small large\nrule A { (1 + 5 * large) * { x 1 } BOX {} }\n";
    assert_eq!(scene_of(src2).instances.len(), 6);
    let out = run(&["render", "-", "--language", "mdg", "--format", "stl", "--param", "preset=giant"], Some(src.as_bytes()));
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("not one of small, large, huge"));
    assert!(parse_error("@presets a a\nrule A { BOX {} }\n").contains("already defined"));
}

#[test]
fn color_and_weight_renaming() {
    // `color` renames R G B A; `r` then adds red instead of rotating, and `R` is unknown.
    let s = scene_of("color r g b a\nrule A { BOX { r 1 b 0.5 } }\n");
    assert_eq!(s.instances[0].colour, [1.0, 0.0, 0.5, 1.0]);
    assert_eq!(s.instances[0].rotation, glam::Quat::IDENTITY);
    assert!(parse_error("color r g b a\nrule A { BOX { R 1 } }\n").contains("renamed"));
    // `weight` renames u v w q (vertex weights are accepted and ignored with a warning).
    let p = rulemesh::lang::mdg::parse(b"weight k1 k2 k3 k4\nrule A { BOX { k1 0.5 } }\n").expect("parses");
    assert!(p.warnings.iter().any(|w| w.to_string().contains("vertex weight `k1` ignored")));
}

#[test]
fn stacksize_stops_deep_calls_quietly() {
    assert_eq!(scene_of("stacksize 3\nrule A { BOX {} A { x 1 } }\n").instances.len(), 4);
    assert_eq!(scene_of("stacksize 0\nrule A { BOX {} A { x 1 } }\n").instances.len(), 1);
}

#[test]
fn animation_directives_are_checked() {
    assert!(parse_error("fps 0\nrule A { BOX {} }\n").starts_with("1:5:"));
    assert!(parse_error("duration -1\nrule A { BOX {} }\n").contains("duration must be in"));
    assert!(parse_error("camerarule NOPE\nrule A { BOX {} }\n").contains("unknown rule `NOPE`"));
    assert!(parse_error("cameranearplane 10\ncamerafarplane 5\nrule A { BOX {} }\n").contains("beyond cameranearplane"));
    assert!(parse_error("namespace a { namespace b { } }\nrule A { BOX {} }\n").contains("do not nest"));
}

#[test]
fn debug_draws_nothing() {
    let p = rulemesh::lang::mdg::parse(b"rule A { DEBUG { x 1 } BOX {} a.DEBUG {} }\n").expect("parses");
    assert_eq!(p.warnings.iter().filter(|w| w.to_string().contains("draws nothing")).count(), 2);
    assert_eq!(scene_of("rule A { DEBUG { x 1 } BOX {} }\n").instances.len(), 1);
}
