//! Designs passing shapes and adjustments as values (issue 34): exact
//! shapes, transforms and colours of small designs; parse errors with
//! positions; hostile values ending in typed errors.

use crate::cfdg::{eval, parse_checked, variation};
use crate::core::budget::{Budget, Limits};
use crate::model::EvalError;

fn render(src: &str) -> Result<eval::Picture, EvalError> {
    let g = parse_checked(src.as_bytes()).map_err(|e| EvalError::BadParam { name: "parse".into(), message: e.to_string() })?;
    let opts = eval::Options { variation: variation::from_code("ABC").unwrap_or(1), ..eval::Options::default() };
    eval::render(&g, &opts, &mut Budget::new(Limits::default()))
}

fn kinds(p: &eval::Picture) -> Vec<usize> {
    p.shapes.iter().map(|s| s.kind).collect()
}

#[test]
fn shape_parameters_draw_the_shape_bound() {
    let p = render("startshape T\nshape T { C(CIRCLE)[] C(foo(0.5))[x 4] }\nshape foo(number k) { TRIANGLE [s k] }\nshape C(shape what) {\n what[]\n what[x 2]\n}\n").unwrap();
    assert_eq!(kinds(&p), [0, 0, 2, 2]);
    assert_eq!(p.shapes[3].transform.sx, 0.5, "the bound argument travels with the shape");
    assert_eq!(p.shapes[3].transform.tx, 6.0);
}

#[test]
fn adjustment_parameters_and_functions_apply_their_adjustment() {
    let p = render("startshape T\nadjustment grow(n) = [s n]\nshape T { C([x 3 b 1])[] SQUARE [trans grow(3) y 5] }\nshape C(adjustment adj) {\n SQUARE []\n SQUARE [trans adj]\n}\n").unwrap();
    assert_eq!(p.shapes.len(), 3);
    // T's own square finishes first; C's two after C is expanded.
    assert_eq!((p.shapes[0].transform.sx, p.shapes[0].transform.ty), (3.0, 5.0));
    let white = &p.shapes[2];
    assert_eq!((white.transform.tx, white.rgba), (3.0, [1.0, 1.0, 1.0, 1.0]));
}

#[test]
fn expressions_choose_shapes_and_adjustments() {
    let src = "startshape T\nshape pick(n) = select(n, CIRCLE, SQUARE, TRIANGLE)\nshape T {\n pick(2)[]\n select(1, CIRCLE, SQUARE)[x 1]\n if(0, CIRCLE, SQUARE)[x 2]\n let(n = 2; select(n, CIRCLE, SQUARE, TRIANGLE))[x 3]\n draw = pick(0)\n draw[x 4]\n SQUARE [trans if(1, [x 5], [x 9])]\n if (1) CIRCLE [x 6]\n}\n";
    let p = render(src).unwrap();
    assert_eq!(kinds(&p), [2, 1, 1, 2, 0, 1, 0]);
    let xs: Vec<f64> = p.shapes.iter().map(|s| s.transform.tx).collect();
    assert_eq!(xs, [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
}

#[test]
fn the_start_setting_takes_arguments_and_an_adjustment() {
    let p = render("CF::StartShape = C(TRIANGLE, 2), [b 1]\nshape C(shape what, number k) { what [s k] }\n").unwrap();
    assert_eq!(kinds(&p), [2]);
    assert_eq!((p.shapes[0].transform.sx, p.shapes[0].rgba), (2.0, [1.0, 1.0, 1.0, 1.0]));
}

#[test]
fn values_of_the_wrong_type_are_errors_with_positions() {
    for (src, at) in [
        ("startshape T\nshape T { C(5)[] }\nshape C(shape what) { what[] }\n", "2:11:"),
        ("startshape T\nshape T { C(CIRCLE)[] }\nshape C(adjustment adj) { SQUARE [trans adj] }\n", "2:11:"),
        ("startshape T\nshape T {\n select(1, 2, 3)[]\n}\n", "3:2:"),
    ] {
        let e = render(src).unwrap_err();
        assert!(matches!(&e, EvalError::BadParam { message, .. } if message.starts_with(at)), "{src}: {e:?}");
    }
    for (src, at) in [("CF::StartShape = A, 5\nshape A { SQUARE [] }\n", (1, 21)), ("startshape T\nshape T {\n select(1, CIRCLE [] \n}\n", (3, 19))] {
        let e = crate::cfdg::syntax::parse(src.as_bytes()).unwrap_err();
        assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), at, "{src}: {e}");
    }
}

#[test]
fn hostile_values_end_in_typed_errors() {
    // Shapes nested in their own arguments grow until the list limit.
    let e = render("startshape A(CIRCLE)\nshape A(shape what) {\n what[]\n A(A(what))[s 0.9]\n}\n").unwrap_err();
    assert!(matches!(e, EvalError::NonFinite { .. } | EvalError::Limit(_)), "{e:?}");
    // A function returning a shape that never returns ends at a limit.
    let e = render("startshape T\nshape loopy(n) = loopy(n + 1)\nshape T { loopy(0)[] }\n").unwrap_err();
    assert!(matches!(e, EvalError::Limit(_)), "{e:?}");
    // Arithmetic on a shape is never a shape, and never a panic.
    let e = render("startshape T\nshape T { C(CIRCLE)[] }\nshape C(shape what) { SQUARE [x (what + 1)] }\n").unwrap_err();
    assert!(matches!(e, EvalError::BadParam { .. } | EvalError::NonFinite { .. }), "{e:?}");
    let e = render("startshape T\nshape T { C(CIRCLE)[] }\nshape C(shape what) { D(what + 1)[] }\nshape D(shape what) { what[] }\n").unwrap_err();
    assert!(matches!(e, EvalError::BadParam { .. }), "{e:?}");
}

#[test]
fn adjustments_inside_adjustments_merge_as_cfdg_merges_them() {
    // `trans a1` inside `a2`: geometry premultiplied, colour deltas added.
    let p = render("startshape T\na1 = [x 1 b 0.5]\na2 = [trans a1 s 2]\nshape T { SQUARE [trans a2] }\n").unwrap();
    let t = &p.shapes[0];
    assert_eq!((t.transform.sx, t.transform.tx, t.rgba), (2.0, 2.0, [0.5, 0.5, 0.5, 1.0]));
    // Both change brightness: cfdg merges nothing of `a1` and draws on.
    let p = render("startshape T\na1 = [x 1 b 0.5]\na2 = [trans a1 b 0.3 s 2]\nshape T { SQUARE [trans a2] }\n").unwrap();
    let t = &p.shapes[0];
    assert_eq!((t.transform.sx, t.transform.tx), (2.0, 0.0));
    assert!((t.rgba[0] - 0.3).abs() < 1e-12, "{:?}", t.rgba);
    // An adjustment is only ever the argument of `trans`.
    let e = render("startshape T\na1 = [x 1]\na2 = [x a1]\nshape T { SQUARE [trans a2] }\n").unwrap_err();
    assert!(matches!(&e, EvalError::BadParam { message, .. } if message.starts_with("3:7:")), "{e:?}");
}

#[test]
fn a_local_adjustment_hides_a_global_number_of_its_name() {
    // subpathtest's pattern: `BLUE = [h BLUE …]` in a loop, then `select(…, BLUE, …)`.
    let p = render("BLUE = 201\nstartshape T\nshape T {\n loop i = 0, 2 [] {\n  BLUE = [b 1 x BLUE]\n  SQUARE [trans select(i, BLUE, [])]\n }\n}\n").unwrap();
    assert_eq!(p.shapes.len(), 2);
    assert_eq!((p.shapes[0].transform.tx, p.shapes[0].rgba), (201.0, [1.0, 1.0, 1.0, 1.0]));
    assert_eq!((p.shapes[1].transform.tx, p.shapes[1].rgba), (0.0, [0.0, 0.0, 0.0, 1.0]));
}

#[test]
fn a_start_shape_may_be_chosen_by_an_expression() {
    let p = render("startshape select(1, CIRCLE, C(2))[b 1]\nshape C(n) { TRIANGLE [s n] }\n").unwrap();
    assert_eq!(kinds(&p), [2]);
    assert_eq!((p.shapes[0].transform.sx, p.shapes[0].rgba), (2.0, [1.0, 1.0, 1.0, 1.0]));
    let p = render("startshape pick()\nshape pick() = if(0, CIRCLE, SQUARE)\n").unwrap();
    assert_eq!(kinds(&p), [1]);
    // cfdg's setting takes a shape specification only.
    let e = crate::cfdg::syntax::parse(b"CF::StartShape = if(1, A, B)\nshape A { SQUARE [] }\n").unwrap_err();
    assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (1, 18), "{e}");
}
