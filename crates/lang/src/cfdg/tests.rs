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
    let e = parse_checked(b"startshape A\nshape A {\n  B []\n}\n").unwrap_err();
    assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (3, 3));
    assert!(e.to_string().contains("`B` has no rules"), "{e}");
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
