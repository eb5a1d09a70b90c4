//! Unit tests of the cpfg front end: exact derivations of figures of *The
//! Algorithmic Beauty of Plants* (Prusinkiewicz & Lindenmayer, 1990) as the
//! vlab course reproduces them (`AlgorithmicBotany/vlab`,
//! `oofs/ext/11-CPFG/ext/01-Introduction`), hand translations into the
//! `.ls` dialect drawing the same segments, parse errors with positions,
//! and hostile sources ending in named limits.

use super::derive::Deriver;
use super::syntax::parse_with;
use crate::core::budget::{Budget, Limit, Limits, OnLimit};
use crate::core::timing::StageClock;
use crate::model::{BuildError, BuildRequest, Downstream, EvalError, Model};
use std::collections::BTreeMap;

fn derive_text(src: &str, seed: Option<u64>) -> String {
    let sys = parse_with(src.as_bytes(), &BTreeMap::new(), &[]).expect("parses");
    let mut budget = Budget::new(Limits::default());
    let mut d = Deriver::new(&sys, seed);
    let n = sys.derivation_length.unwrap_or(0);
    d.derive(n, Some(&super::view::View::default()), OnLimit::Error, &mut budget).expect("derives").string.to_text()
}

fn build(front: &dyn crate::FrontEnd, src: &str, files: &BTreeMap<String, Vec<u8>>, limits: Limits) -> Result<Model, BuildError> {
    let params = BTreeMap::new();
    let req = BuildRequest {
        seed: None,
        params: &params,
        detail: 8,
        on_limit: OnLimit::Error,
        downstream: Downstream::default(),
        hierarchy: false,
        animated: false,
        script_dir: None,
        frame: None,
        files,
        canvas: None,
        picture_only: false,
        print: false,
    };
    front.build_model(src.as_bytes(), &req, &mut Budget::new(limits), &mut StageClock::start())
}

fn cpfg(src: &str) -> Result<Model, BuildError> {
    build(&super::Cpfg, src, &BTreeMap::new(), Limits::default())
}

/// Every tube point's position, rounded, sorted: the segments drawn.
fn points(m: &Model) -> Vec<[i64; 3]> {
    let mut v: Vec<[i64; 3]> = m.scene.lines.iter().flat_map(|l| l.points.iter()).map(|p| p.frame.translation.to_array().map(|x| (x * 1e6).round() as i64)).collect();
    v.sort_unstable();
    v
}

const KOCH: &str = "Lsystem: 1\nderivation length: 4\nAxiom: -F\nF --> F+F-F-FF+F+F-F\nendlsystem\n";
const SNOWFLAKE: &str = "Lsystem: 1\nderivation length: 4\nAxiom: -(90)F\nF --> F+F--F+F\nendlsystem\n";
const COMPOUND: &str = "Lsystem: 1\nderivation length: 4\nAxiom: A\nA --> F[+A][-A]FA\nF --> FF\nendlsystem\n";
const COMPOUND_HOMO: &str = "Lsystem: 1\nderivation length: 4\nAxiom: A\nA --> I[+A][-A]IA\nI --> II\nhomomorphism\nA --> ;F\nI --> F\nendlsystem\n";

fn count(s: &str, c: char) -> usize {
    s.chars().filter(|&x| x == c).count()
}

/// The quadratic Koch curve of vlab's `01-quadratic-Koch` (the mirrored
/// generator of ABOP Figure 1.6's island): every F becomes 8, so 8⁴
/// segments after 4 steps. The figures themselves: `figures_tests.rs`.
#[test]
fn quadratic_koch_counts() {
    let s = derive_text(KOCH, None);
    assert_eq!(count(&s, 'F'), 4096);
    assert!(s.starts_with("-F+F-F-FF+F+F-F+F+F-F-FF+F+F-F-"));
    assert_eq!(cpfg(KOCH).expect("builds").primitives, 4096);
}

/// Von Koch's snowflake curve (vlab `03-snowflake`; ABOP Figure 1.1, not
/// Figure 1.7b, which is its quadratic modification): 4⁴ segments.
#[test]
fn snowflake_counts() {
    assert_eq!(count(&derive_text(SNOWFLAKE, None), 'F'), 256);
    assert_eq!(cpfg(SNOWFLAKE).expect("builds").primitives, 256);
}

/// The compound leaf of the vlab course (`04-compound`, ABOP Figure 1.24e
/// with A for X, 4 steps instead of 7): A ↦ 3A, F ↦ 2F + 2 per A,
/// 130 segments after 4 steps; with the homomorphism (`05-compound-homo`)
/// the 81 apices draw too: 211.
#[test]
fn compound_leaf_counts() {
    assert_eq!(count(&derive_text(COMPOUND, None), 'F'), 130);
    assert_eq!(count(&derive_text(COMPOUND, None), 'A'), 81);
    assert_eq!(cpfg(COMPOUND).expect("builds").primitives, 130);
    assert_eq!(cpfg(COMPOUND_HOMO).expect("builds").primitives, 211);
}

/// The fractal fern of the vlab course (`07-fractal-ferns`) with D = 0, R = 2:
/// the exact string after two steps, parameters and all.
#[test]
fn fractal_fern_string() {
    let src = "#define D 0\n#define R 2\nLsystem: 1\nderivation length: 2\nAxiom: A(0)\nA(t) : t<D  --> A(t+1)\nA(t) : t==D --> I(1)[+A(0)][-A(0)]I(1)A(t)\nI(x) --> I(R*x)\nendlsystem\n";
    assert_eq!(derive_text(src, None), "I(2)[+I(1)[+A(0)][-A(0)]I(1)A(0)][-I(1)[+A(0)][-A(0)]I(1)A(0)]I(2)I(1)[+A(0)][-A(0)]I(1)A(0)");
}

/// Signal propagation with left context (ABOP §1.8): b < a → b moves the b right.
#[test]
fn context_moves_a_signal() {
    let src = "Lsystem: 1\nderivation length: 3\nAxiom: baaaa\nb < a --> b\nb --> a\nendlsystem\n";
    assert_eq!(derive_text(src, None), "aaaba");
    let src = "Lsystem: 1\nderivation length: 1\nignore: +\nAxiom: b[+a]+a\nb < a --> b\nendlsystem\n";
    assert_eq!(derive_text(src, None), "b[+b]+b");
}

/// Blocks: globals set in start:, changed in string order by productions.
#[test]
fn blocks_run_in_string_order() {
    let src = "Lsystem: 1\nStart: { n = 0; }\nderivation length: 1\nAxiom: AAA\nA : { n = n + 1; i = 0; s = 0; while (i < n) { s = s + i; i = i + 1; } } * --> B(n, s)\nendlsystem\n";
    assert_eq!(derive_text(src, None), "B(1,0)B(2,1)B(3,3)");
}

/// A stochastic model gives the same string for the same seed.
#[test]
fn stochastic_is_reproducible() {
    let src = "Lsystem: 1\nseed: 5\nderivation length: 5\nAxiom: F\nF --> F[+F]F : 1\nF --> F[-F]F : 1\nF --> F : 1\nendlsystem\n";
    let a = derive_text(src, None);
    assert_eq!(a, derive_text(src, None));
    assert_eq!(derive_text(src, Some(9)), derive_text(src, Some(9)));
    assert!(a.contains('+') || a.contains('-'));
}

/// cpfg's cut: `%` removes the rest of its branch in the next step.
#[test]
fn cut_removes_the_branch() {
    let src = "Lsystem: 1\nderivation length: 2\nAxiom: F[AFF]F\nA --> %\nendlsystem\n";
    assert_eq!(derive_text(src, None), "F[]F");
}

/// The same models in rulemesh's `.ls` dialect draw the same segments.
#[test]
fn ls_translations_draw_the_same_segments() {
    let pairs = [
        (KOCH, "iterations: 4\nangle: 45\naxiom: - F\nF -> F + F - F - F F + F + F - F\n".replace("angle: 45", "angle: 90")),
        (SNOWFLAKE, "iterations: 4\nangle: 60\naxiom: -(90) F\nF -> F + F - - F + F\n".to_string()),
        (COMPOUND, "iterations: 4\nangle: 45\naxiom: A\nA -> F [ + A ] [ - A ] F A\nF -> F F\n".to_string()),
        (
            "#define R 2\nLsystem: 1\nderivation length: 4\nAxiom: A(0)\nA(t) --> F(1)[+A(0)][-A(0)]F(1)A(t)\nF(x) --> F(R*x)\nendlsystem\n",
            "iterations: 4\nangle: 45\naxiom: A(0)\nA(t) -> F(1) [ + A(0) ] [ - A(0) ] F(1) A(t)\nF(x) -> F(2*x)\n".to_string(),
        ),
        // `//` would start a comment for cpfg's preprocessor (vlabcpp keeps C++ comments on), so the rolls are written `/(120)`.
        ("Lsystem: 1\nderivation length: 3\nAxiom: A\nA --> [&FA]/(120)[&FA]/(120)^(10)[&FA]\nendlsystem\n", "iterations: 3\nangle: 45\naxiom: A\nA -> [ & F A ] /(120) [ & F A ] /(120) ^(10) [ & F A ]\n".to_string()),
    ];
    let views = [90.0, 60.0, 45.0, 45.0, 45.0];
    for ((c, ls), angle) in pairs.iter().zip(views) {
        let mut files = BTreeMap::new();
        files.insert("m.v".to_string(), format!("angle increment: {angle}\n").into_bytes());
        let a = build(&super::Cpfg, c, &files, Limits::default()).expect("cpfg builds");
        let b = build(&crate::lsystem::Lsystem, ls, &BTreeMap::new(), Limits::default()).expect("ls builds");
        assert_eq!(a.primitives, b.primitives, "{c}");
        assert_eq!(points(&a), points(&b), "{c}");
    }
}

/// Two more pairs: conditions with a branching delay (the fractal ferns'
/// productions with F for I and R = 1.5, exact in `f32`), and the
/// context-sensitive plant of ABOP Figure 1.31a (Hogeweg and Hesper;
/// `grammars/hogeweg.ls` with a, b for 0, 1), whose contexts skip `+ - F`
/// and whole branches in both dialects.
#[test]
fn ls_translations_with_conditions_and_context() {
    let pairs = [
        (
            "#define D 3\n#define R 1.5\nLsystem: 1\nderivation length: 12\nAxiom: A(0)\nA(t) : t<D --> A(t+1)\nA(t) : t==D --> F(1)[+A(0)][-A(0)]F(1)A(t)\nF(x) --> F(R*x)\nendlsystem\n",
            "iterations: 12\nangle: 45\naxiom: A(0)\nA(t) : t < 3 -> A(t+1)\nA(t) : t == 3 -> F(1) [ + A(0) ] [ - A(0) ] F(1) A(t)\nF(x) -> F(1.5*x)\n",
            45.0,
        ),
        (
            "Lsystem: 1\nderivation length: 30\nignore: +-F\nAxiom: FbFbFb\na < a > a --> a\na < a > b --> b[+FbFb]\na < b > a --> b\na < b > b --> b\nb < a > a --> a\nb < a > b --> bFb\nb < b > a --> a\nb < b > b --> a\n+ --> -\n- --> +\nendlsystem\n",
            "iterations: 30\nangle: 22.5\nignore: + - F\naxiom: F b F b F b\na < a > a -> a\na < a > b -> b [ + F b F b ]\na < b > a -> b\na < b > b -> b\nb < a > a -> a\nb < a > b -> b F b\nb < b > a -> a\nb < b > b -> a\n* < + > * -> -\n* < - > * -> +\n",
            22.5,
        ),
    ];
    for (c, ls, angle) in pairs {
        let mut files = BTreeMap::new();
        files.insert("m.v".to_string(), format!("angle increment: {angle}\n").into_bytes());
        let a = build(&super::Cpfg, c, &files, Limits::default()).expect("cpfg builds");
        let b = build(&crate::lsystem::Lsystem, ls, &BTreeMap::new(), Limits::default()).expect("ls builds");
        assert!(a.primitives > 50, "{c}: {}", a.primitives);
        assert_eq!(a.primitives, b.primitives, "{c}");
        assert_eq!(points(&a), points(&b), "{c}");
    }
}

/// The environmental query `?P` receives the turtle's position (manual §6.9).
#[test]
fn queries_receive_the_position() {
    let src = "Lsystem: 1\nderivation length: 1\nAxiom: F(2)?P(0,0)A\nA --> +(90)F(3)?P(0,0)\nendlsystem\n";
    assert_eq!(derive_text(src, None), "F(2)?P(0,2)+(90)F(3)?P(-3,2)");
}

/// Roll symbols in successors stay symbols; a lone `\\` in an expression is skipped.
#[test]
fn backslashes() {
    assert_eq!(derive_text("Lsystem: 1\nderivation length: 1\nAxiom: A\nA --> \\(30)F\\F(1 \\ + 1)\nendlsystem\n", None), "\\(30)F\\F(2)");
}

#[test]
fn parse_errors_have_positions() {
    let e = parse_with(b"Lsystem: 1\nAxiom: F\nF --> F(1\nendlsystem\n", &BTreeMap::new(), &[]).expect_err("fails");
    assert_eq!(e.diagnostics[0].span.line, 3);
    let e = parse_with(b"Lsystem: 1\nAxiom: F\nF : x > --> F\n", &BTreeMap::new(), &[]).expect_err("fails");
    assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (3, 9));
    let e = parse_with(b"Lsystem: 1\nAxiom: F\nF --> F(curveX(1,0.5))\n", &BTreeMap::new(), &[]).expect_err("fails");
    assert!(e.diagnostics[0].message.contains("curveX"), "{e:?}");
}

#[test]
fn includes_resolve_against_the_files_only() {
    let mut files = BTreeMap::new();
    files.insert("rules.h".to_string(), b"#define RULE F --> FF\n".to_vec());
    let sys = parse_with(b"#include \"rules.h\"\nLsystem: 1\nderivation length: 1\nAxiom: F\nRULE\nendlsystem\n", &files, &[]).expect("parses");
    assert_eq!(sys.productions.len(), 1);
    // `check_with` reads the same files (what `/check` sends); `check` alone cannot.
    use crate::FrontEnd;
    let src = b"#include \"rules.h\"\nLsystem: 1\nderivation length: 1\nAxiom: F\nRULE\nendlsystem\n";
    assert!(super::Cpfg.check_with(src, &files).is_ok());
    let e = super::Cpfg.check(src).expect_err("no rules.h");
    assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].message.contains("rules.h")), (1, true), "{e:?}");
    let e = parse_with(b"#include \"/etc/passwd\"\nLsystem: 1\nAxiom: F\n", &files, &[]).expect_err("refused");
    assert!(e.diagnostics[0].message.contains("no file"), "{e:?}");
    files.insert("a.h".to_string(), b"#include \"b.h\"\n".to_vec());
    files.insert("b.h".to_string(), b"#include \"a.h\"\n".to_vec());
    let e = parse_with(b"#include \"a.h\"\nLsystem: 1\nAxiom: F\n", &files, &[]).expect_err("cycle");
    assert!(e.diagnostics[0].message.contains("cycle"), "{e:?}");
    // A chain deeper than the bound: f0.h includes f1.h includes … f39.h.
    let mut chain = BTreeMap::new();
    for k in 0..40 {
        chain.insert(format!("f{k}.h"), format!("#include \"f{}.h\"\n", k + 1).into_bytes());
    }
    chain.insert("f40.h".to_string(), Vec::new());
    let e = parse_with(b"#include \"f0.h\"\nLsystem: 1\nAxiom: F\n", &chain, &[]).expect_err("too deep");
    assert!(e.diagnostics[0].message.contains("nest more than 16"), "{e:?}");
}

fn limit_of(r: Result<Model, BuildError>) -> Limit {
    match r {
        Err(BuildError::Eval(EvalError::Limit(l))) => l.limit,
        other => panic!("expected a limit, got {other:?}"),
    }
}

#[test]
fn hostile_sources_end_in_named_errors() {
    let small = Limits { max_steps: 100_000, ..Limits::default() };
    let spin = "Lsystem: 1\nStart: { i = 1; while (i > 0) { i = i + 1; } }\nderivation length: 1\nAxiom: F\nendlsystem\n";
    assert_eq!(limit_of(build(&super::Cpfg, spin, &BTreeMap::new(), small)), Limit::Steps);
    let spin = "Lsystem: 1\nderivation length: 1\nAxiom: F\nF : { do { x = 1; } while (1) } * --> F\nendlsystem\n";
    assert_eq!(limit_of(build(&super::Cpfg, spin, &BTreeMap::new(), small)), Limit::Steps);
    let huge = "Lsystem: 1\nderivation length: 4000000000\nAxiom: F\nF --> FF\nendlsystem\n";
    let l = limit_of(build(&super::Cpfg, huge, &BTreeMap::new(), small));
    assert!(matches!(l, Limit::Steps | Limit::Memory), "{l:?}");
    let div = "Lsystem: 1\nderivation length: 1\nAxiom: A(0)\nA(x) --> A(1/x)\nendlsystem\n";
    match cpfg(div) {
        Err(BuildError::Eval(EvalError::NonFinite { span, what, .. })) => assert_eq!((span.line, what.as_str()), (4, "divisor")),
        other => panic!("expected a division error, got {other:?}"),
    }
    // Inside a block (before and after the condition): the statement's own position.
    let div = "Lsystem: 1\nderivation length: 1\nAxiom: A(0)\nA(x) : { y = 2; y = y / x; } * --> A(y)\nendlsystem\n";
    match cpfg(div) {
        Err(BuildError::Eval(EvalError::NonFinite { span, what, .. })) => assert_eq!((span.line, what.as_str()), (4, "divisor")),
        other => panic!("expected a division error, got {other:?}"),
    }
    let rem = "Lsystem: 1\nStart: { n = 0; }\nderivation length: 1\nAxiom: A(3)\nA(x) : 1 { z = x % n; } --> A(z)\nendlsystem\n";
    match cpfg(rem) {
        Err(BuildError::Eval(EvalError::NonFinite { span, what, .. })) => assert_eq!((span.line, what.as_str()), (5, "divisor of %")),
        other => panic!("expected a division error, got {other:?}"),
    }
    // A derivation length from the animation file, and a recursive
    // homomorphism as deep as it may be, end at a limit too.
    let mut files = BTreeMap::new();
    files.insert("m.a".to_string(), b"last frame: 4000000000\n".to_vec());
    let l = limit_of(build(&super::Cpfg, "Lsystem: 1\nAxiom: F\nF --> FF\nendlsystem\n", &files, small));
    assert!(matches!(l, Limit::Steps | Limit::Memory), "{l:?}");
    let deep = "Lsystem: 1\nderivation length: 1\nAxiom: A\nhomomorphism\nmaximum depth: 4000000000\nA --> AA\nendlsystem\n";
    let l = limit_of(build(&super::Cpfg, deep, &BTreeMap::new(), small));
    assert!(matches!(l, Limit::Steps | Limit::Memory | Limit::Depth), "{l:?}");
    // A header that includes itself is a cycle.
    let mut own = BTreeMap::new();
    own.insert("self.h".to_string(), b"#include \"self.h\"\n".to_vec());
    let e = parse_with(b"#include \"self.h\"\nLsystem: 1\nAxiom: F\n", &own, &[]).expect_err("cycle");
    assert!(e.diagnostics[0].message.contains("cycle"), "{e:?}");
    let bomb = "#define A B B\n#define B C C\n#define C D D\n#define D E E\n#define E F F\n#define F G G\n#define G H H\n#define H I I\n#define I J J\n#define J K K\n#define K L L\n#define L M M\n#define M N N\n#define N O O\n#define O P P\n#define P Q Q\n#define Q R R\n#define R S S\n#define S T T\n#define T U U\n#define U V V\n#define V W W\n#define W X X\n#define X Y Y\nLsystem: 1\nAxiom: A\n";
    assert!(parse_with(bomb.as_bytes(), &BTreeMap::new(), &[]).is_err());
}


/// `func(id, x)` reads the view's `.func` files as cpfg's `SplineFunction`:
/// control points on the line y = x give y = x (to cpfg's 0.001), and a
/// gallery's names are predefined as their ids.
#[test]
fn functions_from_the_view() {
    let line = "fver 1 1\nname: ramp\nsamples: 0\nflip: off\npoints: 4\n0 0\n0.333333 0.333333\n0.666667 0.666667\n1 1\n";
    let f = super::func::read_function(line, 0).expect("reads");
    assert!((f.value(0.25) - 0.25).abs() < 0.002, "{}", f.value(0.25));
    assert!((f.value(2.0) - 1.0).abs() < 0.002);
    let mut files = BTreeMap::new();
    files.insert("m.v".to_string(), b"function set: g.fset\n".to_vec());
    files.insert("g.fset".to_string(), format!("funcgalleryver 1 1\nitems: 1\n{line}").into_bytes());
    let src = "Lsystem: 1\nderivation length: 1\nAxiom: A\nA --> F(10*func(ramp, 0.5))\nendlsystem\n";
    let m = build(&super::Cpfg, src, &files, Limits::default()).expect("builds");
    let top = m.scene.lines.iter().flat_map(|l| l.points.iter()).map(|p| p.frame.translation.y).fold(0.0f64, f64::max);
    assert!((top - 5.0).abs() < 0.02, "{top}");
    assert!(m.warnings.iter().all(|w| !w.message.contains("has no function")), "{:?}", m.warnings);
    // Without the function set, func(1, …) gives 0 as cpfg's does, and the
    // render says so once, at the first call's place.
    let src = "Lsystem: 1\nderivation length: 2\nAxiom: A\nA --> F(10*func(1, 0.5))A\nendlsystem\n";
    let m = cpfg(src).expect("builds");
    let missing: Vec<_> = m.warnings.iter().filter(|w| w.message.contains("has no function")).collect();
    assert_eq!(missing.len(), 1, "{:?}", m.warnings);
    assert!(missing[0].message.starts_with("func(1, …)"), "{}", missing[0].message);
    assert_eq!((missing[0].span.line, missing[0].span.column), (4, 12), "{:?}", missing[0].span);
}

/// Found over the vlab models: a continued production line starting with
/// `#(w)` is text, not a directive (ArticulatedLamp), and an expression
/// statement in a block is run and dropped (04-paintbrush).
#[test]
fn vlab_regressions() {
    let src = "Lsystem: 1\nderivation length: 1\nAxiom: A\nA --> F\n\t#(0.5)F\nendlsystem\n";
    assert_eq!(derive_text(src, None), "F#(0.5)F");
    let src = "Lsystem: 1\nderivation length: 1\nAxiom: A(2)\nA(x) : { y = x; y - 1; } * --> B(y)\nendlsystem\n";
    assert_eq!(derive_text(src, None), "B(2)");
}

/// A source with an `Lsystem:` line is detected as cpfg, before every other language.
#[test]
fn detected_from_lsystem_line() {
    use crate::Language;
    assert_eq!(Language::detect(b"#define N 3\nLsystem: 1\nAxiom: F\nendlsystem\n"), Some(Language::Cpfg));
    assert_eq!(Language::detect(b"axiom: F\niterations: 2\nF -> FF\n"), Some(Language::Lsystem));
    assert_eq!(Language::from_extension(std::path::Path::new("plant.l")), Some(Language::Cpfg));
}
