//! Unit tests of the CFDG front end: parse errors with positions, exact
//! counts of what small designs make, limits named when exceeded.

use super::*;
use crate::core::budget::{Budget, Limits};

fn render(src: &str, var: &str) -> Result<eval::Picture, EvalError> {
    let g = parse_checked(src.as_bytes()).map_err(|e| EvalError::BadParam { name: "parse".into(), message: e.to_string() })?;
    let opts = eval::Options { variation: variation::from_code(var).unwrap_or(1), ..eval::Options::default() };
    eval::render(&g, &opts, &mut Budget::new(Limits::default()))
}

#[test]
fn parse_error_has_position() {
    let e = syntax::parse(b"startshape A\nshape A {\n  SQUARE [x 1 ]]\n}\n").unwrap_err();
    let d = &e.diagnostics[0];
    assert_eq!((d.span.line, d.span.column), (3, 16), "{d}");
    let e = syntax::parse(b"startshape A\nshape A {\n  SQUARE [x 1 @]\n}\n").unwrap_err();
    assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (3, 15));
    // A shape with no rules stops the render where it is reached (cfdg's
    // "Shape with no rules encountered"), with its position.
    let e = render("startshape A\nshape A {\n  B []\n}\n", "A").unwrap_err();
    assert!(matches!(&e, EvalError::BadParam { message, .. } if message.starts_with("3:3:") && message.contains("no rules")), "{e:?}");
    let e = syntax::parse(b"startshape A\nrule A {\n  SQUARE {\n").unwrap_err();
    assert_eq!(e.diagnostics[0].span.line, 4);
    assert!(syntax::parse(&[b's', 0xff, b'\n']).is_err());
}

#[test]
fn loop_counts_exactly() {
    let p = render("startshape A\nshape A {\n loop 10 [r 36] SQUARE [x 2]\n}\n", "A").unwrap();
    assert_eq!(p.shapes.len(), 10);
    let p = render("startshape A\nrule A {\n 7 * {r 10} { CIRCLE {x 1} TRIANGLE {} }\n}\n", "A").unwrap();
    assert_eq!(p.shapes.len(), 14);
}

#[test]
fn recursion_ends_at_minimum_size() {
    let p = render("startshape A\nshape A {\n SQUARE []\n A [x 1 s 0.5]\n}\n", "A").unwrap();
    assert!(p.shapes.len() > 5 && p.shapes.len() < 40, "{}", p.shapes.len());
    let again = render("startshape A\nshape A {\n SQUARE []\n A [x 1 s 0.5]\n}\n", "A").unwrap();
    assert_eq!(p, again);
}

#[test]
fn hostile_inputs_end_in_typed_errors() {
    // Never draws, so never has bounds to stop by: ends at the step limit.
    let e = render("startshape A\nshape A {\n A [x 1]\n A [x -1]\n}\n", "A").unwrap_err();
    assert!(matches!(e, EvalError::Limit(_)), "{e:?}");
    let e = render("startshape A\nshape A {\n loop 1e15 [] SQUARE []\n}\n", "A").unwrap_err();
    assert!(matches!(e, EvalError::Limit(_)), "{e:?}");
    let e = render("startshape A\nshape A {\n loop (0/0) [] SQUARE []\n}\n", "A").unwrap_err();
    assert!(matches!(e, EvalError::BadIteration { .. }), "{e:?}");
    let e = render("startshape A\nshape A {\n SQUARE [x (1/0)]\n}\n", "A").unwrap_err();
    assert!(matches!(e, EvalError::NonFinite { .. }), "{e:?}");
    let deep = format!("startshape A\nshape A {{ SQUARE [x {}1{}] }}\n", "(".repeat(5000), ")".repeat(5000));
    assert!(syntax::parse(deep.as_bytes()).is_err());
}

/// Regression: a name with multi-byte characters made the lexer slice
/// inside a character (found by scripts/cfdg-compat on `unicodetest.cfdg`).
#[test]
fn unicode_names_do_not_panic() {
    let g = syntax::parse("startshape ⬛\nshape ⬛ { SQUARE [x 1…2] }\n".as_bytes()).unwrap();
    assert_eq!(g.rules[0].name, "⬛");
    for src in ["é…", "…é", "x±é", "⬛∞", "a\u{2026}\u{2026}b"] {
        let _ = syntax::parse(src.as_bytes());
    }
}

/// User functions, `let`, vectors and indexing compute what cfdg computes
/// (the values read back from the shape's transform).
#[test]
fn functions_let_and_vectors_evaluate() {
    let x = |src: &str| render(src, "A").unwrap().shapes[0].transform.tx;
    let y = |src: &str| render(src, "A").unwrap().shapes[0].transform.ty;
    assert_eq!(x("double(v) = v * 2\nstartshape A\nshape A { SQUARE [x double(3)] }\n"), 6.0);
    assert_eq!(x("natural fib(natural n) = if(n <= 1, n, fib(n -- 1) + fib(n -- 2))\nstartshape A\nshape A { SQUARE [x fib(10)] }\n"), 55.0);
    assert_eq!(x("startshape A\nshape A { SQUARE [x let(p = 2; q = p * 3; p + q)] }\n"), 8.0);
    // A vector function, element-wise sums, a scalar product and indexing with length and stride.
    let src = "vector2 add(vector2 u, vector2 w) = u + w\nv = 1, 2, 3, 4, 5, 6\nstartshape A\nshape A { SQUARE [x (add((1, 2), v[2, 2, 2]) * 2)] }\n";
    assert_eq!((x(src), y(src)), (8.0, 14.0));
    // A vector2 shape parameter.
    let src = "startshape A\nshape A { B((3, 4)) [] }\nshape B(vector2 p) { SQUARE [x p] }\n";
    assert_eq!((x(src), y(src)), (3.0, 4.0));
    // A shape variable with arguments, drawn by its name.
    let src = "startshape A\nshape A { bv = B(5) \n bv [] }\nshape B(number n) { SQUARE [x n] }\n";
    assert_eq!(x(src), 5.0);
    // An adjustment value applied with trans.
    let src = "m = [x 2 y 3]\nstartshape A\nshape A { SQUARE [trans m] }\n";
    assert_eq!((x(src), y(src)), (2.0, 3.0));
}

/// Endless recursion in a user function is a depth limit; a wide one the
/// step limit (each call is a step).
#[test]
fn recursive_functions_end_at_limits() {
    let e = render("up(n) = up(n + 1)\nstartshape A\nshape A { SQUARE [x up(1)] }\n", "A").unwrap_err();
    assert!(matches!(&e, EvalError::Limit(l) if l.limit == crate::core::budget::Limit::Depth), "{e:?}");
    let e = render("fib(n) = if(n < 2, n, fib(n - 1) + fib(n - 2))\nstartshape A\nshape A { SQUARE [x fib(90)] }\n", "A").unwrap_err();
    assert!(matches!(&e, EvalError::Limit(l) if l.limit == crate::core::budget::Limit::Steps), "{e:?}");
}
