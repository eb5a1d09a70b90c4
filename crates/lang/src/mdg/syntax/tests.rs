//! End-to-end tests of the MDG front end: source bytes → IR or positioned error.

use super::parse;
use crate::expr::{BinOp, Expr, ExprEnv};
use crate::ir::*;
use crate::core::{Severity, Span};
use std::f64::consts::{FRAC_PI_2, PI};

struct Env;
impl ExprEnv for Env {
    fn param(&self, i: u32) -> f64 {
        100.0 + f64::from(i)
    }
    fn rand(&mut self, _: u32) -> f64 {
        0.5
    }
}

fn ok(src: &str) -> Program {
    match parse(src.as_bytes()) {
        Ok(p) => p,
        Err(e) => panic!("parse failed: {e}\n{src}"),
    }
}

/// (line, column, message) of the first error.
fn fail(src: &str) -> (u32, u32, String) {
    let e = parse(src.as_bytes()).expect_err(src);
    let d = &e.diagnostics[0];
    assert_eq!(d.severity, Severity::Error);
    (d.span.line, d.span.column, d.message.clone())
}

fn body(p: &Program, group: usize, rule: usize) -> &[Item] {
    &p.groups[group].rules[rule].body
}

/// The adjustments of the first call in the start rule, evaluated.
fn ops(adj: &str) -> Vec<(String, Vec<f64>)> {
    ops_with("", adj)
}

fn ops_with(prefix: &str, adj: &str) -> Vec<(String, Vec<f64>)> {
    let p = ok(&format!("{prefix}\nrule A {{ BOX {{ {adj} }} }}"));
    let Item::Call(c) = &body(&p, 0, 0)[0] else { panic!("not a call") };
    c.adjust
        .iter()
        .map(|a| match &a.op {
            AdjustOp::Translate(v) => ("T".into(), v.iter().map(|e| e.eval(&mut Env)).collect()),
            AdjustOp::Rotate { axis, angle } => (format!("R{axis:?}"), vec![angle.eval(&mut Env)]),
            AdjustOp::Scale(k) => ("S".into(), vec![k.eval(&mut Env)]),
            AdjustOp::Reflect(v) => ("F".into(), v.iter().map(|e| e.eval(&mut Env)).collect()),
            AdjustOp::Colour { channel, delta } => (format!("C{channel}"), vec![delta.eval(&mut Env)]),
        })
        .collect()
}

fn close(a: &[(String, Vec<f64>)], b: &[(&str, &[f64])]) {
    assert_eq!(a.len(), b.len(), "{a:?} vs {b:?}");
    for ((n, v), (m, w)) in a.iter().zip(b) {
        assert_eq!(n, m, "{a:?} vs {b:?}");
        assert_eq!(v.len(), w.len(), "{a:?} vs {b:?}");
        for (x, y) in v.iter().zip(w.iter()) {
            assert!(x == y || (x - y).abs() < 1e-12, "{a:?} vs {b:?}");
        }
    }
}

#[test]
fn parses_the_basic_example_into_exact_ir() {
    let p = ok("startshape A rule A { 10 * {x 1} BOX {} }");
    let expected = Program {
        start: Target::Group(0),
        groups: vec![RuleGroup {
            name: "A".into(),
            rules: vec![Rule {
                weight: 1.0,
                transform: RuleTransform::None,
                body: vec![Item::Iterate(Iterate {
                    count: Expr::Num(10.0),
                    divisor: None,
                    step: vec![Adjust {
                        op: AdjustOp::Translate([Expr::Num(1.0), Expr::Num(0.0), Expr::Num(0.0)]),
                        span: Span::new(1, 29),
                    }],
                    body: Box::new(Item::Call(Call {
                        target: Target::Primitive(PrimitiveKind::Box),
                        adjust: vec![],
                        site: 1,
                        continues: false,
                        span: Span::new(1, 34),
                    })),
                    continues: false,
                    site: 0,
                    span: Span::new(1, 23),
                })],
                span: Span::new(1, 14),
            }],
            selector: Selector::Random,
        }],
        directives: Directives::default(),
        params: vec![],
        site_count: 2,
        warnings: vec![],
        isosurfaces: vec![],
        namespaces: Default::default(),
        meshes: vec![],
    };
    assert_eq!(p, expected);
}

#[test]
fn weights_groups_and_start() {
    let p = ok("rule B 0.5 { A {} }\nrule A {}\nrule B 2{}\nrule C 0 {}\nstartshape A");
    assert_eq!(p.start, Target::Group(1));
    let names: Vec<&str> = p.groups.iter().map(|g| g.name.as_str()).collect();
    assert_eq!(names, ["B", "A", "C"]);
    let w: Vec<f64> = p.groups[0].rules.iter().map(|r| r.weight).collect();
    assert_eq!(w, [0.5, 2.0]);
    assert_eq!(p.groups[1].rules[0].weight, 1.0);
    assert_eq!(p.groups[2].rules[0].weight, 0.0);
    let Item::Call(c) = &body(&p, 0, 0)[0] else { panic!() };
    assert_eq!(c.target, Target::Group(1));
    // Without startshape the first rule defined starts.
    assert_eq!(ok("rule Z {} rule Y {}").start, Target::Group(0));
    // startshape may name a primitive.
    assert_eq!(ok("startshape sphere").start, Target::Primitive(PrimitiveKind::Sphere));
    assert_eq!(fail("rule A -1 {}"), (1, 8, "the weight of rule `A` must be ≥ 0, found -1".into()));
}

#[test]
fn every_adjustment_keyword() {
    let d = PI / 180.0;
    close(&ops("x 1"), &[("T", &[1.0, 0.0, 0.0])]);
    close(&ops("x 1 2"), &[("T", &[1.0, 2.0, 0.0])]);
    close(&ops("x 1 -2 3"), &[("T", &[1.0, -2.0, 3.0])]);
    close(&ops("y 2 z -.5"), &[("T", &[0.0, 2.0, 0.0]), ("T", &[0.0, 0.0, -0.5])]);
    close(&ops("r 10 20 30"), &[("RX", &[10.0 * d]), ("RY", &[20.0 * d]), ("RZ", &[30.0 * d])]);
    close(&ops("rotate 10"), &[("RX", &[10.0 * d])]);
    close(&ops("rx 1 pitch 2"), &[("RX", &[d]), ("RX", &[2.0 * d])]);
    close(&ops("ry 1 yaw 2"), &[("RY", &[d]), ("RY", &[2.0 * d])]);
    close(&ops("rz 1 roll 2"), &[("RZ", &[d]), ("RZ", &[2.0 * d])]);
    close(&ops("up"), &[("RX", &[FRAC_PI_2])]);
    close(&ops("up 30"), &[("RX", &[30.0 * d])]);
    close(&ops("down"), &[("RX", &[-FRAC_PI_2])]);
    close(&ops("down 30"), &[("RX", &[-30.0 * d])]);
    close(&ops("left"), &[("RY", &[-FRAC_PI_2])]);
    close(&ops("left 30 right"), &[("RY", &[-30.0 * d]), ("RY", &[FRAC_PI_2])]);
    close(&ops("right 30"), &[("RY", &[30.0 * d])]);
    close(&ops("rolleft 30"), &[("RZ", &[-30.0 * d])]);
    close(&ops("rollleft"), &[("RZ", &[-FRAC_PI_2])]);
    close(&ops("rollright 30 rollright"), &[("RZ", &[30.0 * d]), ("RZ", &[FRAC_PI_2])]);
    close(&ops("s 2 s 0.5"), &[("S", &[2.0]), ("S", &[0.5])]);
    close(&ops("f 1 2 3"), &[("F", &[1.0, 2.0, 3.0])]);
    close(&ops("fx fy fz"), &[("F", &[1.0, 0.0, 0.0]), ("F", &[0.0, 1.0, 0.0]), ("F", &[0.0, 0.0, 1.0])]);
    close(&ops("R 0.2 G 0.3 B -1 A -.5"), &[("C0", &[0.2]), ("C1", &[0.3]), ("C2", &[-1.0]), ("C3", &[-0.5])]);
    // The seed's example (L553–555), in order.
    close(
        &ops("rx 20 ry 30 z 10 fz R 0.2 G 0.3"),
        &[
            ("RX", &[20.0 * d]),
            ("RY", &[30.0 * d]),
            ("T", &[0.0, 0.0, 10.0]),
            ("F", &[0.0, 0.0, 1.0]),
            ("C0", &[0.2]),
            ("C1", &[0.3]),
        ],
    );
    // Weight adjustments are accepted and ignored with a warning.
    let p = ok("rule A { BOX { u 1 x 1 q 2 } }");
    let Item::Call(c) = &body(&p, 0, 0)[0] else { panic!() };
    assert_eq!(c.adjust.len(), 1);
    assert_eq!(p.warnings.len(), 2);
    assert_eq!(p.warnings[0].span, Span::new(1, 16));
    // Case matters: `r` rotates, `R` is red; unknown adjustments are errors.
    assert_eq!(fail("rule A {\n  BOX { rx 1 RZ 2 } }"), (2, 14, "unknown adjustment `RZ`".into()));
    assert_eq!(fail("rule A { BOX { x } }"), (1, 18, "expected a number after `x`, found `}`".into()));
}

#[test]
fn angle_argument_ir_is_wrapped_to_radians() {
    let p = ok("rule A { BOX { up 30 } }");
    let Item::Call(c) = &body(&p, 0, 0)[0] else { panic!() };
    assert_eq!(c.adjust[0].span, Span::new(1, 16));
    assert_eq!(
        c.adjust[0].op,
        AdjustOp::Rotate {
            axis: Axis::X,
            angle: Expr::Binary(BinOp::Mul, Box::new(Expr::Num(30.0)), Box::new(Expr::Num(PI / 180.0))),
        }
    );
}

#[test]
fn angle_modes_and_suffixes() {
    let d = PI / 180.0;
    close(&ops("rz 1t"), &[("RZ", &[PI / 4.0])]);
    close(&ops("rz 45d"), &[("RZ", &[PI / 4.0])]);
    close(&ops_with("angle radians", "rz 1 rx 90d ry 1t"), &[("RZ", &[1.0]), ("RX", &[FRAC_PI_2]), ("RY", &[PI / 4.0])]);
    close(&ops_with("angle orbits", "rz 0.25 rx 90d ry 1t up"), &[
        ("RZ", &[FRAC_PI_2]),
        ("RX", &[FRAC_PI_2]),
        ("RY", &[PI / 4.0]),
        ("RX", &[FRAC_PI_2]),
    ]);
    // The directive applies to the whole file, wherever it is.
    let p = ok("rule A { BOX { rz 0.5 } }\nangle orbits");
    assert_eq!(p.directives.angle, AngleMode::Orbits);
    let Item::Call(c) = &body(&p, 0, 0)[0] else { panic!() };
    let AdjustOp::Rotate { angle, .. } = &c.adjust[0].op else { panic!() };
    assert!((angle.eval(&mut Env) - PI).abs() < 1e-12);
    // Outside angle arguments `d` and `t` literals are radians.
    close(&ops("x 180d 1t"), &[("T", &[PI, PI / 4.0, 0.0])]);
    // Inside parentheses of an angle argument too.
    close(&ops("rz (2 * 45d) rx (1t + 1t)"), &[("RZ", &[FRAC_PI_2]), ("RX", &[FRAC_PI_2])]);
    // Trig functions take radians and give plain numbers.
    close(&ops("x (cos(0)) rz (sin(90d) * 90)"), &[("T", &[1.0, 0.0, 0.0]), ("RZ", &[90.0 * d])]);
    // A rule named `angle` is not the directive.
    assert_eq!(ok("rule angle {}").directives.angle, AngleMode::Degrees);
    assert_eq!(fail("angle gradians rule A {}"), (1, 7, "unknown angle mode `gradians` (expected degrees, radians or orbits)".into()));
}

#[test]
fn expressions() {
    close(&ops("x (2 ^ 3 ^ 2) (-2^2) (1 + 2 * 3 - 4 / 2)"), &[("T", &[512.0, -4.0, 5.0])]);
    close(&ops("s (max(1, 5, 3)) s (atan2(1, 0)) s (pow(2, 10))"), &[("S", &[5.0]), ("S", &[FRAC_PI_2]), ("S", &[1024.0])]);
    close(&ops("x (rand()) (1/0)"), &[("T", &[0.5, f64::INFINITY, 0.0])]);
    assert_eq!(fail("rule A { BOX { x (sin(1, 2)) } }"), (1, 19, "`sin` takes 1 argument(s), 2 given".into()));
    assert_eq!(fail("rule A { BOX { x (atan2(1)) } }"), (1, 19, "`atan2` takes 2 argument(s), 1 given".into()));
    assert_eq!(fail("rule A { BOX { x (height / 2) } }"), (1, 19, "unknown name `height`".into()));
    assert_eq!(fail("rule A { BOX { x (1 + ) } }"), (1, 23, "expected a number, found `)`".into()));
    assert_eq!(fail("rule A { BOX { x 1e999 } }"), (1, 18, "number `1e999` is too large".into()));
    assert_eq!(fail("rule A { BOX { s (1 2) } }"), (1, 21, "expected `)` to close `(`, found number `2`".into()));
}

#[test]
fn site_ids_are_in_source_order() {
    let p = ok("rule A { B { x (rand()) } 2 * { y (rand()) } { BOX {} } }\nrule B { BOX { z (rand()) } }");
    let Item::Call(c) = &body(&p, 0, 0)[0] else { panic!() };
    assert_eq!(c.site, 0);
    assert_eq!(c.adjust[0].op, AdjustOp::Translate([Expr::Rand(1), Expr::Num(0.0), Expr::Num(0.0)]));
    let Item::Iterate(it) = &body(&p, 0, 0)[1] else { panic!() };
    assert_eq!(it.site, 2);
    assert_eq!(it.step[0].op, AdjustOp::Translate([Expr::Num(0.0), Expr::Rand(3), Expr::Num(0.0)]));
    let Item::Block(b) = &*it.body else { panic!() };
    let Item::Call(c) = &b[0] else { panic!() };
    assert_eq!(c.site, 4);
    let Item::Call(c) = &body(&p, 1, 0)[0] else { panic!() };
    assert_eq!((c.site, p.site_count), (5, 7));
    assert_eq!(c.adjust[0].op, AdjustOp::Translate([Expr::Num(0.0), Expr::Num(0.0), Expr::Rand(6)]));
    assert_eq!(p, ok("rule A { B { x (rand()) } 2 * { y (rand()) } { BOX {} } }\nrule B { BOX { z (rand()) } }"));
}

#[test]
fn iterators_divisors_chains_and_brackets() {
    let p = ok("rule X{ 12/12*{rz 1}A{} 100 / 100 * [ry 360] { A{} A{} } 5/5*{rx 1} 2/2*{ry 1} 1*{} A{} (2+1) * {} A{} }\nrule A {}");
    let b = body(&p, 0, 0);
    assert_eq!(b.len(), 4);
    let Item::Iterate(it) = &b[0] else { panic!() };
    assert_eq!((it.count.clone(), it.divisor.clone()), (Expr::Num(12.0), Some(Expr::Num(12.0))));
    assert!(matches!(&*it.body, Item::Call(c) if c.target == Target::Group(1)));
    let Item::Iterate(it) = &b[1] else { panic!() };
    assert_eq!(it.divisor, Some(Expr::Num(100.0)));
    assert!(matches!(&*it.body, Item::Block(v) if v.len() == 2));
    // Chains nest.
    let Item::Iterate(a) = &b[2] else { panic!() };
    let Item::Iterate(bb) = &*a.body else { panic!() };
    let Item::Iterate(c) = &*bb.body else { panic!() };
    assert!(c.step.is_empty());
    assert!(matches!(&*c.body, Item::Call(_)));
    let Item::Iterate(it) = &b[3] else { panic!() };
    assert_eq!(it.count.eval(&mut Env), 3.0);
    assert_eq!(fail("rule A { 2.5 * {} BOX {} }"), (1, 10, "iteration count must be a whole number ≥ 0, found 2.5".into()));
    assert_eq!(fail("rule A { 2 {} }"), (1, 12, "expected `*` after the iteration count, found `{`".into()));
    assert_eq!(fail("rule A { BOX [x 1] }"), (1, 14, "expected `{` after rule name `BOX`, found `[`".into()));
}

#[test]
fn directives() {
    let p = ok("maxdepth 10 minsize 0.01 maxiter 1000 randseed 42 background 1 0.5 0 selector A frequency\nrule A {}");
    assert_eq!(p.directives.maxdepth, Some(10));
    assert_eq!(p.directives.minsize, Some(0.01));
    assert_eq!(p.directives.maxiter, Some(1000));
    assert_eq!(p.directives.randseed, Some(42));
    assert_eq!(p.directives.background, Some([1.0, 0.5, 0.0, 1.0]));
    assert_eq!(ok("background 1 1 1 0.5 rule A {}").directives.background, Some([1.0, 1.0, 1.0, 0.5]));
    // Skipped directives warn.
    let p = ok("program { vertexshader a render }\nuniform light 1 2 3\ncamerafov 50\nrule A {}");
    assert_eq!(p.warnings.len(), 2);
    assert_eq!(p.directives.camera.fov_degrees, 50.0);
    assert_eq!(p.warnings[1].span, Span::new(2, 1));
    // Directive words are rule names inside rules.
    let p = ok("rule A { maxdepth {} }\nrule maxdepth {}");
    assert!(matches!(&body(&p, 0, 0)[0], Item::Call(c) if c.target == Target::Group(1)));
    assert_eq!(fail("maxdepth 1.5"), (1, 10, "maxdepth must be a whole number ≥ 0, found 1.5".into()));
    assert_eq!(fail("rule A {}\nfoo 1"), (2, 1, "expected `rule`, `startshape` or a directive, found `foo`".into()));
    assert_eq!(fail("selector A pattern rule A {}"), (1, 12, "unknown selector mode `pattern` (random, frequency, depth, scale, sequential, function)".into()));
    assert_eq!(fail("selector B depth rule A {}"), (1, 10, "selector names `B`, which has no rules".into()));
    assert_eq!(fail("selector A function f rule A {}"), (1, 21, "unknown function `f`".into()));
}

#[test]
fn preprocessor_define_param_ifdef_macro() {
    let p = ok("@define H 4\n@define HALF (H / 2)\nrule A { BOX { s HALF x (H*2) } H * {} BOX {} }");
    close(&ops_with("@define H 4\n@define HALF (H / 2)", "s HALF x (H*2)"), &[("S", &[2.0]), ("T", &[8.0, 0.0, 0.0])]);
    let Item::Iterate(it) = &body(&p, 0, 0)[1] else { panic!() };
    assert_eq!(it.count, Expr::Num(4.0));

    let p = ok("@param int n 3 1 10\n@param float size 0.5\n@param bool flag true\nrule A { n * {x size} BOX {} }");
    assert_eq!(
        p.params,
        vec![
            ParamDecl { name: "n".into(), kind: ParamKind::Int, default: 3.0, range: Some((1.0, 10.0)), span: Span::new(1, 1), choices: vec![] },
            ParamDecl { name: "size".into(), kind: ParamKind::Float, default: 0.5, range: None, span: Span::new(2, 1), choices: vec![] },
            ParamDecl { name: "flag".into(), kind: ParamKind::Bool, default: 1.0, range: None, span: Span::new(3, 1), choices: vec![] },
        ]
    );
    let Item::Iterate(it) = &body(&p, 0, 0)[0] else { panic!() };
    assert_eq!(it.count, Expr::Param(0));
    assert_eq!(it.step[0].op, AdjustOp::Translate([Expr::Param(1), Expr::Num(0.0), Expr::Num(0.0)]));
    assert_eq!(fail("@param int n 2.5\nrule A {}"), (1, 14, "default of int `n` must be a whole number, found 2.5".into()));
    assert_eq!(fail("@param float f 5 0 1\nrule A {}"), (1, 16, "default 5 of `f` is outside [0, 1]".into()));
    assert_eq!(fail("@param bool b 2\nrule A {}"), (1, 15, "expected `true`, `false`, 0 or 1 for bool `b`, found number `2`".into()));

    let src = "@define BIG 1\n@ifdef BIG\nrule A { SPHERE {} }\n@else\nrule A { BOX {} }\n@endif\n@ifdef SMALL\nrule B {}\n@endif";
    let p = ok(src);
    assert_eq!(p.groups.len(), 1);
    assert!(matches!(&body(&p, 0, 0)[0], Item::Call(c) if c.target == Target::Primitive(PrimitiveKind::Sphere)));

    let src = "@macro ROW(n, dx)\nn * {x dx} BOX {}\n@endmacro\nrule A {\n  @expand ROW(3, 1.5)\n  @expand ROW(2, (0.5 * 2))\n}";
    let p = ok(src);
    let b = body(&p, 0, 0);
    assert_eq!(b.len(), 2);
    let Item::Iterate(it) = &b[1] else { panic!() };
    assert_eq!(it.count, Expr::Num(2.0));
    assert_eq!(it.span, Span::new(6, 3));
    // Errors inside an expansion point at the `@expand`.
    assert_eq!(fail("@macro M()\nBOX { zz 1 }\n@endmacro\nrule A {\n @expand M()\n}"), (5, 2, "unknown adjustment `zz`".into()));
    assert_eq!(fail("@frobnicate\nrule A {}"), (1, 1, "unknown preprocessor directive `@frobnicate`".into()));
    let p = ok("@fragmentshader s\nvoid main() { }\n@endshader\nrule A {}");
    assert_eq!(p.warnings.len(), 1);
    let p = ok("@import other\nrule A {}");
    assert_eq!(p.warnings[0].span, Span::new(1, 1));
    assert!(p.warnings[0].message.contains("`@import other` ignored: only built-in grammars"));
}

#[test]
fn error_positions() {
    assert_eq!(fail("rule A }"), (1, 8, "expected `{` after rule name `A`, found `}`".into()));
    assert_eq!(fail("rule A {\n  BOX {}\n"), (3, 1, "expected `}` to close rule `A`, found end of input".into()));
    assert_eq!(fail("rule A {\n\tFOO {}\n}"), (2, 2, "unknown rule or primitive `FOO`".into()));
    assert_eq!(fail("startshape Q\nrule A {}"), (1, 12, "unknown rule or primitive `Q`".into()));
    assert_eq!(fail("rule A { é {} # }"), (1, 15, "unexpected character `#`".into()));
    assert_eq!(fail("rule A { LINETO P {} }"), (1, 17, "unknown rule `P`".into()));
    assert_eq!(fail("rule A * B { }"), (1, 10, "unknown rule `B`".into()));
    assert_eq!(fail("linerule L\nrule A { }"), (1, 10, "unknown rule `L`".into()));
    assert_eq!(fail("rule A { B {} \\ \\ B {} }\nrule B {}"), (1, 17, "expected a call after `\\`, found another `\\`".into()));
    assert_eq!(fail(""), (1, 1, "empty source: expected `startshape` or `rule`".into()));
    assert_eq!(fail("  // only a comment\n"), (1, 1, "empty source: expected `startshape` or `rule`".into()));
    assert_eq!(fail("maxdepth 3\n"), (2, 1, "no rules: expected at least one `rule` or a `startshape`".into()));
    assert_eq!(fail("rule A : B : C {}\nrule B {}"), (1, 14, "unknown rule `C`".into()));
}

#[test]
fn invalid_utf8_position() {
    let e = parse(b"rule A {\n  B\xffOX {} }").unwrap_err();
    assert_eq!(e.diagnostics[0].span, Span::new(2, 4));
    assert_eq!(e.diagnostics[0].message, "invalid UTF-8");
    let e = parse("rule é\u{e9}".as_bytes().iter().copied().chain([0xc3]).collect::<Vec<u8>>().as_slice()).unwrap_err();
    assert_eq!(e.diagnostics[0].span, Span::new(1, 8));
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    let src = format!("rule A {}", "{".repeat(100_000));
    let (l, c, m) = fail(&src);
    assert_eq!((l, m.as_str()), (1, "nesting deeper than 256"));
    assert!(c > 200 && c < 300, "{c}");
    let src = format!("rule A {{ BOX {{ x {} }} }}", "(".repeat(100_000));
    assert_eq!(fail(&src).2, "nesting deeper than 256");
    let src = format!("rule A {{ BOX {{ x {}1 }} }}", "-(".repeat(100_000));
    assert_eq!(fail(&src).2, "nesting deeper than 256");
    let src = format!("rule A {{ {} BOX {{}} }}", "1 * {} ".repeat(100_000));
    assert_eq!(fail(&src).2, "nesting deeper than 256");
    // Long left-associative chains are deep trees too.
    let src = format!("rule A {{ BOX {{ x (1{}) }} }}", "+1".repeat(100_000));
    assert_eq!(fail(&src).2, "nesting deeper than 256");
    // Just under the limit is fine.
    let src = format!("rule A {}BOX{{}}{}", "{".repeat(255), "}".repeat(255));
    ok(&src);
}

#[test]
fn primitives_are_case_insensitive_and_overridable() {
    let p = ok("rule A { box {} Sphere {} CYLINDER {} cone {} torus {} tetrahedron {} Octahedron {} icosahedron {} DODECAHEDRON {} }");
    let kinds: Vec<Target> = body(&p, 0, 0)
        .iter()
        .map(|i| match i {
            Item::Call(c) => c.target,
            _ => panic!(),
        })
        .collect();
    assert_eq!(kinds, PrimitiveKind::ALL.map(Target::Primitive).to_vec());
    let p = ok("rule A { BOX {} box {} }\nrule BOX { SPHERE {} }");
    let b = body(&p, 0, 0);
    assert!(matches!(&b[0], Item::Call(c) if c.target == Target::Group(1)));
    assert!(matches!(&b[1], Item::Call(c) if c.target == Target::Primitive(PrimitiveKind::Box)));
}

#[test]
fn hostile_inputs_never_panic_and_big_inputs_are_linear() {
    for src in [
        &b"rule"[..],
        b"rule A",
        b"rule A {",
        b"rule A { 5",
        b"rule A { 5 /",
        b"rule A { 5 * {",
        b"rule A { 5 * {} ",
        b"rule A { B { x",
        b"rule A { B { x (",
        b"@define",
        b"@param",
        b"@param int",
        b"@macro",
        b"@expand",
        b"@expand M(",
        b"@",
        b"}}}}",
        b"rule A { (((",
        b"background",
        b"selector",
        b"\xc3",
        b"/*",
        b"rule A { BOX { x 1t2 } }",
    ] {
        let _ = parse(src);
    }
    let mut src = String::from("rule A {\n");
    while src.len() < 10_000_000 {
        src.push_str("  12/12 * {rz 30 x 1.5 s 0.99} B { R 0.1 y (2 * 3) }\n");
    }
    src.push_str("}\nrule B {}\n");
    let t = std::time::Instant::now();
    let p = ok(&src);
    assert!(p.site_count > 300_000);
    let elapsed = t.elapsed();
    // Generous: debug builds of dependencies are optimised, ours is not.
    assert!(elapsed.as_secs_f64() < 10.0, "{elapsed:?}");
}

#[test]
fn every_example_in_the_docs_parses() {
    let doc = include_str!("../../../../../docs/mdg.md");
    let mut count = 0;
    let mut rest = doc;
    while let Some(start) = rest.find("```mdg\n") {
        let after = &rest[start + 7..];
        let end = after.find("```").expect("unclosed example");
        let src = &after[..end];
        let p = ok(src);
        assert!(!p.groups.is_empty() || matches!(p.start, Target::Primitive(_)));
        count += 1;
        rest = &after[end + 3..];
    }
    assert!(count >= 12, "{count}");
}

#[test]
fn thesis_listing_4_1_with_the_missing_brace_restored() {
    let p = ok("selector A frequency\nrule A 0.01 {}\nrule A 0.1 {\n  A{z 1}\n  A{rz 0.3 rx 0.35}\n}\nrule A 0.9 {\n  SPHERE{}\n  A{z 1 ry 0.01}\n}");
    assert_eq!(p.groups.len(), 1);
    let w: Vec<f64> = p.groups[0].rules.iter().map(|r| r.weight).collect();
    assert_eq!(w, [0.01, 0.1, 0.9]);
    assert_eq!(p.site_count, 4);
    // As printed (the `}` missing), the error points at the nested `rule`.
    let (l, c, m) = fail("rule A 0.1 {\n  A{z 1}\nrule A 0.9 {\n  SPHERE{}\n}");
    assert_eq!((l, c, m.as_str()), (3, 6, "expected `{` after rule name `rule`, found `A`"));
}

#[test]
fn selectors_and_continuation() {
    let p = ok("selector A, B depth\nselector C function { x + 2*y }\nfunction f { z }\nselector D function f\nselector E sequential\nrule A {} rule B {} rule C {} rule D {} rule E {}");
    let modes: Vec<&Selector> = p.groups.iter().map(|g| &g.selector).collect();
    assert_eq!(modes[0], &Selector::Depth);
    assert_eq!(modes[1], &Selector::Depth);
    assert!(matches!(modes[2], Selector::Function(Expr::Binary(BinOp::Add, _, _))));
    assert_eq!(modes[3], &Selector::Function(Expr::Coord(2)));
    assert_eq!(modes[4], &Selector::Sequential);
    // `x` outside a function is not a coordinate.
    assert_eq!(fail("rule A { BOX { s (x) } }").2, "unknown name `x`");
    // `\` marks the next call (through iterators) as continuing; a trailing one is a no-op.
    let p = ok("rule A { BOX {} \\ BOX {} 2 * {} \\ BOX {} \\ }");
    let body = &p.groups[0].rules[0].body;
    assert_eq!(body.len(), 3);
    let continues = |i: &Item| match i {
        Item::Call(c) => c.continues,
        Item::Iterate(it) => it.continues || matches!(&*it.body, Item::Call(c) if c.continues),
        Item::Block(_) => false,
    };
    assert_eq!(body.iter().map(continues).collect::<Vec<_>>(), [false, true, true]);
}
