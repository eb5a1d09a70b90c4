//! L-systems (issue 5): exact segment counts, the Hogeweg–Hesper system
//! against an independent reference derivation, the Gen and PlantMaker
//! strings of seed 004, determinism, budgets, diagnostics, and every
//! `grammars/*.ls` through the glTF validator.

use crate::common::{grammar_files, run, tempdir, validate_gltf};
use rulemesh::core::{Budget, Limit, Limits, OnLimit};
use rulemesh::export::Format;
use rulemesh::lang::lsystem::syntax::parse;
use rulemesh::lang::Language;
use rulemesh::lsystem::derive::derive_n;
use rulemesh::{render, RenderError, RenderRequest};

fn req(format: Format) -> RenderRequest {
    RenderRequest { language: Some(Language::Lsystem), format, ..RenderRequest::default() }
}

fn segments(src: &str) -> u64 {
    render(src.as_bytes(), &req(Format::Stl)).unwrap_or_else(|e| panic!("{e}")).primitives
}

/// The string after `n` derivation steps.
fn derived(src: &str, n: u32, seed: u64) -> String {
    let sys = parse(src.as_bytes()).unwrap_or_else(|e| panic!("{e}"));
    let mut budget = Budget::new(Limits::default());
    let d = derive_n(&sys, seed, n, OnLimit::Error, &mut budget).unwrap_or_else(|e| panic!("{e}"));
    d.string.to_text(&sys)
}

#[test]
fn bracketed_plant_has_five_to_the_fifth_segments() {
    assert_eq!(segments("iterations: 5\nangle: 25.7\naxiom: F\nF -> F[+F]F[-F]F\n"), 3125);
}

#[test]
fn koch_curve_has_four_to_the_sixth_segments() {
    assert_eq!(segments("iterations: 6\nangle: 60\naxiom: F\nF -> F+F--F+F\n"), 4096);
}

#[test]
fn koch_string_length_is_predicted_exactly() {
    // The derived string equals a naive text rewrite.
    let mut s = "F".to_string();
    for _ in 0..4 {
        s = s.chars().map(|c| if c == 'F' { "F+F--F+F".to_string() } else { c.to_string() }).collect();
    }
    assert_eq!(derived("axiom: F\nF -> F+F--F+F\n", 4, 0), s);
}

const HOGEWEG: &str = include_str!("../../grammars/hogeweg.ls");

/// An independent, deliberately naive derivation of ABOP fig 1.31a: chars,
/// bracket depth counted by scanning, contexts found by walking.
fn hogeweg_reference(steps: usize) -> String {
    let ignored = |c: char| c == '+' || c == '-' || c == 'F';
    let mut s: Vec<char> = "F1F1F1".chars().collect();
    for _ in 0..steps {
        let mut out = String::new();
        for i in 0..s.len() {
            let c = s[i];
            match c {
                '+' => out.push('-'),
                '-' => out.push('+'),
                '0' | '1' => {
                    // Left: walk back; a ']' skips its whole branch, a '[' is passed into the parent.
                    let mut left = None;
                    let mut j = i;
                    while j > 0 {
                        j -= 1;
                        match s[j] {
                            ']' => {
                                let mut depth = 1;
                                while depth > 0 && j > 0 {
                                    j -= 1;
                                    if s[j] == ']' {
                                        depth += 1;
                                    } else if s[j] == '[' {
                                        depth -= 1;
                                    }
                                }
                            }
                            '[' => {}
                            x if ignored(x) => {}
                            x => {
                                left = Some(x);
                                break;
                            }
                        }
                    }
                    // Right: walk forward; a '[' skips its branch, a ']' ends the search.
                    let mut right = None;
                    let mut j = i + 1;
                    while j < s.len() {
                        match s[j] {
                            '[' => {
                                let mut depth = 1;
                                while depth > 0 && j + 1 < s.len() {
                                    j += 1;
                                    if s[j] == '[' {
                                        depth += 1;
                                    } else if s[j] == ']' {
                                        depth -= 1;
                                    }
                                }
                                j += 1;
                            }
                            ']' => break,
                            x if ignored(x) => j += 1,
                            x => {
                                right = Some(x);
                                break;
                            }
                        }
                    }
                    let succ = match (left, c, right) {
                        (Some('0'), '0', Some('0')) => "0",
                        (Some('0'), '0', Some('1')) => "1[+F1F1]",
                        (Some('0'), '1', Some('0')) => "1",
                        (Some('0'), '1', Some('1')) => "1",
                        (Some('1'), '0', Some('0')) => "0",
                        (Some('1'), '0', Some('1')) => "1F1",
                        (Some('1'), '1', Some('0')) => "0",
                        (Some('1'), '1', Some('1')) => "0",
                        _ => "",
                    };
                    if succ.is_empty() {
                        out.push(c);
                    } else {
                        out.push_str(succ);
                    }
                }
                other => out.push(other),
            }
        }
        s = out.chars().collect();
    }
    s.into_iter().collect()
}

/// A derived string without the modules that only change how the plant
/// looks (`!` and `'(r,g,b)`), which the library's hogeweg.ls adds to each
/// new branch and ignores in context matching.
fn without_looks(s: &str) -> String {
    let mut out = String::new();
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '!' => {}
            '\'' => {
                if chars.peek() == Some(&'(') {
                    for d in chars.by_ref() {
                        if d == ')' {
                            break;
                        }
                    }
                }
            }
            _ => out.push(c),
        }
    }
    out
}

#[test]
fn hogeweg_hesper_matches_reference_at_step_30() {
    let reference = hogeweg_reference(30);
    // The look modules are there, and the plant grows as the book's without them.
    assert!(derived(HOGEWEG, 30, 0).contains("!'("), "hogeweg.ls colours and thins its branches");
    let derived = |src: &str, n: u32, seed: u64| without_looks(&derived(src, n, seed));
    assert!(reference.len() > 1000, "the reference plant grows: {}", reference.len());
    for n in [1, 2, 5, 10, 30] {
        assert_eq!(derived(HOGEWEG, n, 0), hogeweg_reference(n as usize), "step {n}");
    }
    assert_eq!(derived(HOGEWEG, 30, 0), reference);
    // Early steps by hand (ABOP p.35): 1<1>1 → 0; the end modules lack a neighbour and stay.
    assert_eq!(derived(HOGEWEG, 1, 0), "F1F0F1");
    assert_eq!(derived(HOGEWEG, 2, 0), "F1F1F1F1");
}

#[test]
fn gen_example_corrected_generations() {
    // Seed 004 lines 2010–2018, with the off-by-one corrected (seed note 004 §7.1).
    let src = "modules: draw rotateZ\naxiom: A(1)\nA(w) : (w = 1) -> A(w+1) rotateZ(45) draw(2)\nA(w) : (w > 1) -> draw(1) rotateZ(45) A(w+1)\n";
    assert_eq!(derived(src, 0, 0), "A(1)");
    assert_eq!(derived(src, 1, 0), "A(2)rotateZ(45)draw(2)");
    assert_eq!(derived(src, 2, 0), "draw(1)rotateZ(45)A(3)rotateZ(45)draw(2)");
    assert_eq!(derived(src, 3, 0), "draw(1)rotateZ(45)draw(1)rotateZ(45)A(4)rotateZ(45)draw(2)");
}

#[test]
fn plantmaker_generation_three_string() {
    // Seed 004 line 1776; PlantMaker's push/pop `(` `)` are our `[` `]`.
    let src = "axiom: p\ni -> S[ejL][ekL]S\np -> ir[p]de[dL]i[cL]l[p]cp\n";
    let printed = "S(ejL) (ekL) Sr(ir(p) de (dL) i (cL) l (p) cp) de (dL) S(ejL) (ekL) S(cL) l (ir(p) de (dL) i (cL) l (p) cp) cir (p) de (dL) i (cL) l (p) cp";
    let expected: String = printed.chars().filter(|c| !c.is_whitespace()).map(|c| match c {
        '(' => '[',
        ')' => ']',
        c => c,
    }).collect();
    let got = derived(src, 2, 0);
    assert_eq!(got, expected);
    assert_eq!(got.len(), 107);
    assert_eq!(got.matches('L').count(), 12);
}

#[test]
fn parametric_conditions_and_context_with_parameters() {
    // ABOP fig 1.31-style signal passing with parameters: B(x) < A(y) moves values right.
    let src = "axiom: B(5) A(0) A(0) A(0)\nB(x) < A(y) -> A(x + y)\nA(y) < A(z) : y > 0 && z == 0 -> A(y * 2)\nB(x) -> B(x - 1)\n";
    assert_eq!(derived(src, 1, 0), "B(4)A(5)A(0)A(0)");
    assert_eq!(derived(src, 2, 0), "B(3)A(9)A(10)A(0)");
}

#[test]
fn stochastic_choice_is_seeded_and_terminate_table_applies_once() {
    let src = "axiom: A\nA -> AB : 1\nA -> AC : 1\nterminate: A -> F\n";
    let a = derived(src, 12, 1);
    assert_eq!(a, derived(src, 12, 1));
    assert_ne!(a, derived(src, 12, 2));
    assert!(a.starts_with('F') && a.len() == 13 && !a.contains('A'), "{a}");
    let (b, c) = (a.matches('B').count(), a.matches('C').count());
    assert_eq!(b + c, 12);
}

#[test]
fn cut_removes_the_rest_of_the_branch() {
    assert_eq!(derived("axiom: F[F%FF[F]F]F\n", 1, 0), "F[F]F");
}

#[test]
fn same_seed_same_bytes_and_stochastic_seeds_differ() {
    let src = std::fs::read(crate::common::repo().join("grammars/stochastic-plant.ls")).expect("grammar");
    let with = |seed| render(&src, &RenderRequest { seed: Some(seed), ..req(Format::Glb) }).expect("renders").bytes;
    assert_eq!(with(3), with(3));
    assert_ne!(with(3), with(4));
    let grass = std::fs::read(crate::common::repo().join("grammars/grass.ls")).expect("grammar");
    let g = |seed| render(&grass, &RenderRequest { seed: Some(seed), ..req(Format::Stl) }).expect("renders").bytes;
    assert_eq!(g(9), g(9));
    assert_ne!(g(9), g(10));
}

#[test]
fn exponential_growth_is_refused_before_the_work() {
    let start = std::time::Instant::now();
    let e = render(b"iterations: 60\naxiom: F\nF -> FF\n", &req(Format::Stl)).expect_err("too big");
    assert!(matches!(e, RenderError::Limit(l) if l.limit == Limit::Steps || l.limit == Limit::Memory), "{e}");
    assert!(start.elapsed().as_secs_f64() < 1.0);
    // Not predictable (parametric): stopped by the budget while deriving.
    let e = render(b"iterations: 60\naxiom: A(1)\nA(x) -> A(x+1)A(x)\n", &req(Format::Stl)).expect_err("too big");
    assert!(matches!(e, RenderError::Limit(_)), "{e}");
    // Too many segments for the primitive limit.
    let limits = Limits { max_primitives: 100, ..Limits::default() };
    let e = render(b"iterations: 5\naxiom: F\nF -> F[+F]F[-F]F\n", &RenderRequest { limits, ..req(Format::Stl) }).expect_err("limit");
    assert!(matches!(e, RenderError::Limit(l) if l.limit == Limit::Primitives), "{e}");
    // Truncation on request keeps a partial model.
    let out = render(
        b"iterations: 5\naxiom: F\nF -> F[+F]F[-F]F\n",
        &RenderRequest { limits, on_limit: OnLimit::Truncate, ..req(Format::Stl) },
    )
    .expect("truncated render");
    assert_eq!(out.primitives, 100);
    assert!(out.truncated.is_some());
}

#[test]
fn hostile_sources_fail_cleanly() {
    let r = |s: &str| render(s.as_bytes(), &req(Format::Glb));
    let eval_error = |s: &str| match r(s) {
        Err(RenderError::Eval(e)) => (e.span().map(|p| (p.line, p.column)), e.to_string()),
        other => panic!("{s:?}: expected an evaluation error, got {other:?}"),
    };
    // Division by zero: a non-finite argument, reported where it is written.
    let (at, msg) = eval_error("axiom: F(1/0)\n");
    assert_eq!(at, Some((1, 8)), "{msg}");
    assert!(msg.contains("axiom argument is not a finite number (inf)"), "{msg}");
    // Overflow to infinity in a later generation: the rule's argument.
    let (at, msg) = eval_error("iterations: 3\naxiom: A(1)\nA(x) -> A(x*1e300)F(x)\n");
    assert_eq!(at, Some((3, 9)), "{msg}");
    assert!(msg.contains("argument of A is not a finite number (inf)"), "{msg}");
    // Unbalanced brackets: the stray pops are ignored and the segment is drawn.
    let out = r("axiom: ]]][[[F\n").expect("renders");
    assert_eq!((out.primitives, out.truncated), (1, None));
    // A rule with an empty successor erases A: an empty model, not an error.
    let out = r("iterations: 2\naxiom: A\nA -> : 0\n").expect("renders");
    assert_eq!((out.primitives, out.triangles, out.truncated), (0, 0, None));
    // Nesting past the shared expression grammar's bound (256) is a parse
    // error at the 257th parenthesis inside the argument list, not a stack overflow.
    let deep = format!("axiom: F{}1{}\n", "(".repeat(300), ")".repeat(300));
    match r(&deep) {
        Err(RenderError::Parse(p)) => {
            assert_eq!((p.diagnostics[0].span.line, p.diagnostics[0].span.column), (1, 9 + 257), "{p}");
            assert_eq!(p.diagnostics[0].message, "nesting deeper than 256", "{p}");
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
}

#[test]
fn cli_detects_the_language_and_reports_positions() {
    let out = run(&["check", "-", "--language", "lsystem"], Some(b"axiom: F\nF -> F[+F\nG -> F(2*)\n"));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.starts_with("-:3:"), "{err}");
    // Detected from content.
    let out = run(&["render", "-", "--format", "stl"], Some(b"axiom: F\n"));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for g in grammar_files("ls") {
        let out = run(&["check", g.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "{}: {}", g.display(), String::from_utf8_lossy(&out.stderr));
    }
}

#[test]
fn there_are_at_least_ten_lsystems_and_each_renders_valid_gltf() {
    let files = grammar_files("ls");
    assert!(files.len() >= 10, "{files:?}");
    let dir = tempdir();
    let mut out_files = Vec::new();
    for g in files {
        let stem = g.file_stem().and_then(|s| s.to_str()).expect("name").to_string();
        for ext in ["glb", "gltf"] {
            let path = dir.path().join(format!("{stem}.{ext}"));
            let out = run(&["render", g.to_str().expect("utf-8"), "-o", path.to_str().expect("utf-8")], None);
            assert!(out.status.success(), "{stem}: {}", String::from_utf8_lossy(&out.stderr));
            out_files.push(path);
        }
    }
    for (file, (errors, _warnings, report)) in out_files.iter().zip(validate_gltf(&out_files)) {
        assert_eq!(errors, 0, "{}: {report}", file.display());
    }
}

#[test]
fn primitive_shape_places_one_primitive_per_segment() {
    let out = render(b"iterations: 2\nshape: CYLINDER\naxiom: F\nF -> F[+F]F\n", &req(Format::Glb)).expect("renders");
    assert_eq!(out.primitives, 9);
    assert!(out.triangles > 0);
}

#[test]
fn every_lsystem_example_in_the_docs_renders() {
    let doc = std::fs::read_to_string(crate::common::repo().join("docs/lsystem.md")).expect("docs/lsystem.md");
    let mut examples = Vec::new();
    let mut current: Option<String> = None;
    for line in doc.lines() {
        match (&mut current, line.trim_end()) {
            (None, "```ls") => current = Some(String::new()),
            (Some(_), "```") => examples.extend(current.take()),
            (Some(buf), l) => {
                buf.push_str(l);
                buf.push('\n');
            }
            (None, _) => {}
        }
    }
    assert!(examples.len() >= 12, "only {} examples", examples.len());
    let dir = tempdir();
    let mut files = Vec::new();
    for (i, src) in examples.iter().enumerate() {
        let path = dir.path().join(format!("example-{i}.glb"));
        let out = run(&["render", "-", "--language", "lsystem", "-o", path.to_str().expect("utf-8")], Some(src.as_bytes()));
        assert!(out.status.success(), "example {i}:\n{src}\n{}", String::from_utf8_lossy(&out.stderr));
        let summary = String::from_utf8_lossy(&out.stderr);
        assert!(!summary.contains(" 0 primitives"), "example {i} draws something: {summary}");
        files.push(path);
    }
    for (i, (errors, _, report)) in validate_gltf(&files).into_iter().enumerate() {
        assert_eq!(errors, 0, "example {i}: {report}");
    }
}

#[test]
fn position_queries_see_the_turtle_after_every_step() {
    // Growth stops once the apex is above y = 4.5: the query carries the height.
    let src = "iterations: 10\naxiom: A ?P(0,0,0)\nA > ?P(x,y,z) : y < 4.5 -> F A\n";
    assert_eq!(segments(src), 5);
    assert_eq!(derived(src, 2, 0), "FFA?P(0,2,0)");
    // Turned: the heading vector and a position off the axis.
    let turned = derived("axiom: +F ?H(0,0,0) ?P(9)\n", 0, 0);
    assert!(turned.starts_with("+F?H(-1,") && turned.ends_with(",0)?P(-1)"), "{turned}");
    // Queries cost steps: a query system over the step budget fails cleanly.
    let limits = Limits { max_steps: 50, ..Limits::default() };
    let e = render(src.as_bytes(), &RenderRequest { limits, ..req(Format::Stl) }).expect_err("steps");
    assert!(matches!(e, RenderError::Limit(l) if l.limit == Limit::Steps), "{e}");
}

#[test]
fn polygons_fill_two_sided_fans() {
    // A unit square: 2 fan triangles, written in both windings.
    let src = "axiom: F {. f . +f . +f . }\nangle: 90\n";
    let out = render(src.as_bytes(), &req(Format::Stl)).expect("renders");
    let tris = crate::common::decode_stl(&out.bytes);
    let tube = render(b"axiom: F\n", &req(Format::Stl)).expect("renders").triangles;
    assert_eq!(out.triangles, tube + 4);
    let area: f64 = tris
        .iter()
        .rev()
        .take(4)
        .map(|[a, b, c]| {
            let (u, v) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
            let cr = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
            f64::from((cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]).sqrt()) / 2.0
        })
        .sum();
    assert!((area - 2.0).abs() < 1e-5, "both sides of a unit square: {area}");
    // Fewer than three vertices draw nothing; an unclosed polygon draws nothing.
    assert_eq!(render(b"axiom: F {. f .}\n", &req(Format::Stl)).expect("renders").triangles, tube);
    assert_eq!(render(b"axiom: F {. f . f . f .\n", &req(Format::Stl)).expect("renders").triangles, tube);
}
