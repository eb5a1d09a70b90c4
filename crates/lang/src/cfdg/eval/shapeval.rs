//! Shapes and adjustments as values: `shape` and `adjustment` parameters of
//! shapes and functions, functions returning them, `select`/`if`/`let`
//! choosing one, and adjustments written inside expressions, as cfdg 3.4
//! evaluates them (`astexpression.cpp`: `ASTruleSpecifier::evalArgs`,
//! `ASTselect::evaluate`, `ASTmodification::setVal`; `stacktype.cpp`:
//! `StackType::evalArgs` puts a bound shape and a `Modification` on the
//! same stack as the numbers, `StackRule`'s and the modification's words in
//! line with them).
//!
//! rulemesh does the same: a value is a run of numbers, and a shape or an
//! adjustment is a tagged run within it. The tag is a NaN with a payload no
//! arithmetic makes from numbers (a NaN from arithmetic carries the
//! default payload), so a typed run is told from numbers wherever it is
//! passed, and every read of one checks its bounds:
//! - a shape: `[SHAPE, n, shape number, its arguments…]`, n numbers in all;
//! - an adjustment: `[ADJUST, the 18 numbers of an adjustment value]`
//!   ([`super::modval`]'s layout).

use super::expr::{eval, Scope};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Adjustment, Expr, ParamType};
use crate::model::EvalError;
use crate::Span;

const SHAPE_BITS: u64 = 0x7FF8_5348_4150_4531;
const ADJUST_BITS: u64 = 0x7FF8_4144_4A55_5354;

/// Numbers in an adjustment's run: its tag and [`super::modval`]'s 18.
pub(crate) const ADJUST_LEN: usize = 19;

/// The slot size standing for an adjustment parameter (above any
/// `vectorN`'s 99, so the two are never confused).
pub(crate) const ADJUST_SLOT: usize = 1000;

/// The slot a parameter of type `ty` takes in a shape's argument list:
/// its count of numbers, 0 for a shape (a run of its own length),
/// [`ADJUST_SLOT`] for an adjustment.
pub(crate) fn slot_size(ty: ParamType) -> usize {
    match ty {
        ParamType::Number | ParamType::Natural => 1,
        ParamType::Vector(n) => n,
        ParamType::Shape => 0,
        ParamType::Adjustment => ADJUST_SLOT,
    }
}

fn is(v: Option<&f64>, bits: u64) -> bool {
    v.is_some_and(|x| x.to_bits() == bits)
}

/// The shape number and arguments of a shape run, if `v` is exactly one.
pub(crate) fn as_shape(v: &[f64]) -> Option<(usize, &[f64])> {
    if !is(v.first(), SHAPE_BITS) || v.get(1).copied() != Some(v.len() as f64) {
        return None;
    }
    let shape = *v.get(2)?;
    (shape >= 0.0 && shape < 1e9).then(|| (shape as usize, &v[3..]))
}

/// The 18 numbers of an adjustment run, if `v` is exactly one.
pub(crate) fn as_adjust(v: &[f64]) -> Option<&[f64]> {
    (v.len() == ADJUST_LEN && is(v.first(), ADJUST_BITS)).then(|| &v[1..])
}

/// Splits a flat argument list by slot sizes ([`slot_size`]); `None` when
/// it does not fit them (too few or too many numbers, a shape or an
/// adjustment where the parameter wants another type).
pub fn split<'v>(sizes: &[usize], flat: &'v [f64]) -> Option<Vec<&'v [f64]>> {
    let mut out = Vec::with_capacity(sizes.len());
    let mut at = 0;
    for &k in sizes {
        let n = if k == 0 {
            if !is(flat.get(at), SHAPE_BITS) {
                return None;
            }
            let n = *flat.get(at + 1)?;
            if !(3.0..=flat.len() as f64).contains(&n) {
                return None;
            }
            n as usize
        } else if k == ADJUST_SLOT {
            if !is(flat.get(at), ADJUST_BITS) {
                return None;
            }
            ADJUST_LEN
        } else {
            if is(flat.get(at), ADJUST_BITS) || is(flat.get(at), SHAPE_BITS) {
                return None;
            }
            k
        };
        let part = flat.get(at..at.checked_add(n)?)?;
        if k == 0 && as_shape(part).is_none() {
            return None;
        }
        out.push(part);
        at += n;
    }
    (at == flat.len()).then_some(out)
}

/// Evaluates a shape named in an expression (`foo(0.5)`, `CIRCLE`) into a
/// shape run (`ASTruleSpecifier::evalArgs`): its arguments now, in the
/// caller's scope and stream. A variable of that name, if any, wins.
pub(crate) fn shape_value(name: &str, shape: usize, args: Option<&Expr>, span: Span, scope: &Scope<'_>, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    if args.is_none() {
        if let Some(v) = scope.get(name) {
            out.extend_from_slice(v);
            return Ok(());
        }
        if var_fallback(name, scope, out) {
            return Ok(());
        }
    }
    let from = out.len();
    out.extend_from_slice(&[f64::from_bits(SHAPE_BITS), 0.0, shape as f64]);
    match args {
        Some(Expr::Var(r, _)) if r == crate::cfdg::syntax::REUSE => {
            return Err(EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: `{name}(=)` is only allowed as a replacement", span.line, span.column) });
        }
        Some(a) => eval(a, scope, rand, out)?,
        None => {}
    }
    out[from + 1] = (out.len() - from) as f64;
    Ok(())
}

/// Evaluates an adjustment written in an expression into an adjustment run
/// (`ASTmodification::setVal`: colours as deltas and targets, not applied).
pub(crate) fn adjust_value(adj: &Adjustment, scope: &Scope<'_>, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    let v = super::modval::value_of(adj, scope, rand, false)?;
    out.push(f64::from_bits(ADJUST_BITS));
    out.extend_from_slice(&v);
    Ok(())
}

/// Merges adjustment value `v` ([`super::modval`]'s 18 numbers) into one
/// being built, as `Modification::merge` does (`shape.cpp`): geometry and
/// z premultiplied, colour deltas, targets and assignment flags added.
/// Whether the two conflict (both change one colour channel, or one assigns
/// a hue the other changes): then nothing is merged, and cfdg reports
/// "Conflicting color change".
pub fn merge(v: &[f64], geo: &mut super::state::State, color: &mut [f64; 4], target: &mut [f64; 4], assign: &mut u32) -> bool {
    let [sx, shy, shx, sy, tx, ty, sz, tz, h, s, b, a, th, ts, tb, ta, m_assign, _] = v else { return true };
    let m_assign = *m_assign as u32;
    const HUE_MASK: u32 = 3;
    let conflict = (*assign & m_assign) != 0 || (m_assign & HUE_MASK != 0 && color[0] != 0.0) || (*assign & HUE_MASK != 0 && *h != 0.0) || (color[2] != 0.0 && *b != 0.0) || (color[1] != 0.0 && *s != 0.0) || (color[3] != 0.0 && *a != 0.0);
    if conflict {
        return true;
    }
    geo.transform.premultiply(&super::state::Affine { sx: *sx, shy: *shy, shx: *shx, sy: *sy, tx: *tx, ty: *ty });
    geo.tz += geo.sz * tz;
    geo.sz *= sz;
    for (c, d) in color.iter_mut().zip([h, s, b, a]) {
        *c += d;
    }
    for (c, d) in target.iter_mut().zip([th, ts, tb, ta]) {
        *c += d;
    }
    *assign |= m_assign;
    false
}

/// Pushes the run of a shape variable or an adjustment value kept under its
/// own key (`draw = CIRCLE`, `next = [s 0.9]`) when `name` names one, so
/// it can be passed on as an argument; whether it did.
pub(crate) fn var_fallback(name: &str, scope: &Scope<'_>, out: &mut Vec<f64>) -> bool {
    if let Some(v) = scope.get(&format!("{SHAPE_VAR}{name}")) {
        if let Some((_, rest)) = v.split_first() {
            out.extend_from_slice(&[f64::from_bits(SHAPE_BITS), (rest.len() + 2) as f64]);
            out.extend_from_slice(rest);
            return true;
        }
    }
    if let Some(v) = scope.get_marked(super::modval::MOD_VAR, name) {
        if v.len() + 1 == ADJUST_LEN {
            out.push(f64::from_bits(ADJUST_BITS));
            out.extend_from_slice(v);
            return true;
        }
    }
    false
}

/// Pushes adjustment value `v` ([`super::modval`]'s 18 numbers) defined as
/// `name`: under its own key, for `trans name`, and as an adjustment run
/// under the name itself, so it shadows an outer variable of that name
/// wherever it is named (`BLUE = [b .73 h BLUE]` inside a loop hides a
/// global number `BLUE` from `select(i, BLUE, RED)`, as in cfdg's scopes).
pub(crate) fn push_adjust(scope: &mut Scope<'_>, name: &str, v: Vec<f64>) {
    let mut run = Vec::with_capacity(ADJUST_LEN);
    run.push(f64::from_bits(ADJUST_BITS));
    run.extend_from_slice(&v);
    scope.vars.push((super::modval::key(name), v));
    scope.vars.push((name.to_string(), run));
}

/// The prefix of a shape variable's key among the scope's variables (the
/// renderer's `bind::SHAPE_VAR`): its value is `[constant, shape, args…]`.
pub(crate) const SHAPE_VAR: char = '\u{1}';

/// Whether `v` is a value of type `ty` (a function's result).
pub fn fits(ty: ParamType, v: &[f64]) -> bool {
    match ty {
        ParamType::Shape => as_shape(v).is_some(),
        ParamType::Adjustment => as_adjust(v).is_some(),
        t => v.len() == slot_size(t) && !is(v.first(), SHAPE_BITS) && !is(v.first(), ADJUST_BITS),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape_run(shape: usize, args: &[f64]) -> Vec<f64> {
        let mut v = vec![f64::from_bits(SHAPE_BITS), (args.len() + 3) as f64, shape as f64];
        v.extend_from_slice(args);
        v
    }

    #[test]
    fn a_flat_list_splits_by_the_parameters_types() {
        let mut flat = vec![0.97, 3.0];
        flat.extend(shape_run(4, &[0.5]));
        let mut adj = vec![f64::from_bits(ADJUST_BITS)];
        adj.extend([1.0; 18]);
        flat.extend(&adj);
        let parts = split(&[1, 1, 0, ADJUST_SLOT], &flat).expect("fits");
        assert_eq!(parts.len(), 4);
        assert_eq!(as_shape(parts[2]), Some((4, &[0.5][..])));
        assert_eq!(as_adjust(parts[3]).map(<[f64]>::len), Some(18));
    }

    #[test]
    fn a_list_of_the_wrong_types_or_length_does_not_split() {
        let run = shape_run(1, &[]);
        assert!(split(&[1], &run).is_none(), "a shape is not a number");
        assert!(split(&[0], &[1.0, 2.0, 3.0]).is_none(), "numbers are not a shape");
        assert!(split(&[0, 1], &run).is_none(), "too few");
        let mut long = run.clone();
        long.push(1.0);
        assert!(split(&[0], &long).is_none(), "too many");
        // A forged length never reads out of bounds.
        let forged = [f64::from_bits(SHAPE_BITS), 1e300, 0.0];
        assert!(split(&[0], &forged).is_none());
        assert!(as_shape(&forged).is_none());
        assert!(split(&[ADJUST_SLOT], &[f64::NAN; ADJUST_LEN]).is_none());
        assert!(split(&[ADJUST_LEN], &[1.0; ADJUST_LEN]).is_some(), "a vector19 is numbers");
    }

    #[test]
    fn arithmetic_on_numbers_never_makes_a_tag() {
        let zero = std::hint::black_box(0.0f64);
        for v in [zero / zero, f64::INFINITY - f64::INFINITY, (zero - 1.0).sqrt()] {
            assert_ne!(v.to_bits(), SHAPE_BITS);
            assert_ne!(v.to_bits(), ADJUST_BITS);
        }
        assert!(fits(ParamType::Number, &[1.0]));
        assert!(!fits(ParamType::Number, &shape_run(0, &[])));
        assert!(fits(ParamType::Shape, &shape_run(0, &[])));
    }
}

#[cfg(test)]
#[path = "shapeval_tests.rs"]
mod render_tests;
