//! Applying an adjustment to a shape's state, term by term, as
//! `ASTmodTerm::evaluate` does with `shapeDest` set (`astexpression.cpp`,
//! Context Free 3.4): geometry premultiplied (so the first term written is
//! the outermost), colours moved towards 0/1 or towards the target.

use super::expr::{eval, Scope};
use super::state::{adjust, adjust_hue, Affine, State};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Adjustment, Term, TermKind};
use crate::model::EvalError;

const PI: f64 = 3.141_592_653_589_793_238_46;

/// The terms of `adj` in the order cfdg evaluates them: as written, or, for a
/// canonical adjustment, colours (and others) as written, then translate,
/// rotate, size, skew, flip and transform (`ASTmodification::makeCanonical`;
/// a repeated geometric term keeps the last one).
pub fn ordered(adj: &Adjustment) -> Vec<Term> {
    if !adj.canonical {
        return adj.terms.clone();
    }
    let slot = |k: TermKind| match k {
        TermKind::X => Some(0),
        TermKind::Y => Some(1),
        TermKind::Z => Some(2),
        TermKind::Rotate => Some(3),
        TermKind::Size => Some(4),
        TermKind::ZSize => Some(5),
        TermKind::Skew => Some(6),
        TermKind::Flip => Some(7),
        TermKind::Transform => Some(8),
        _ => None,
    };
    let mut slots: [Option<Term>; 9] = Default::default();
    let mut out = Vec::new();
    for t in &adj.terms {
        match slot(t.kind) {
            Some(i) => slots[i] = Some(t.clone()),
            None => out.push(t.clone()),
        }
    }
    out.extend(slots.into_iter().flatten());
    out
}

/// An adjustment ready to apply: its constant geometric terms folded into
/// one map, as cfdg folds them at compile time (`ASTmodification::simplify`:
/// a constant term is folded unless a non-constant term of its class came
/// before it), and the rest in evaluation order. Folding changes rounding,
/// and rounding decides ties between equal areas in the expansion order, so
/// it is done exactly as cfdg does it.
#[derive(Debug, Clone, PartialEq)]
pub struct Prepared {
    /// The folded constant geometry, applied first.
    pub folded: Option<Affine>,
    /// The terms applied after it, in order.
    pub rest: Vec<Term>,
}

pub(crate) fn is_constant(e: &crate::cfdg::syntax::Expr) -> bool {
    crate::cfdg::syntax::is_constant(e)
}

fn geometric(k: TermKind) -> bool {
    matches!(k, TermKind::X | TermKind::Y | TermKind::Size | TermKind::Rotate | TermKind::Skew | TermKind::Flip | TermKind::Transform)
}

/// Prepares `adj` for repeated application.
pub fn prepare(adj: &Adjustment) -> Prepared {
    let terms = ordered(adj);
    let mut folded: Option<State> = None;
    let mut rest = Vec::new();
    let mut blocked = false;
    let scope = Scope::default();
    let mut rand = Rand64::default();
    for t in terms {
        if geometric(t.kind) && !blocked && is_constant(&t.args) && t.kind != TermKind::X || (t.kind == TermKind::X && !blocked && is_constant(&t.args) && !matches!(&t.args, crate::cfdg::syntax::Expr::Cons(v) if v.len() == 3)) {
            let s = folded.get_or_insert_with(State::initial);
            if apply(std::slice::from_ref(&t), s, &scope, &mut rand).is_ok() {
                continue;
            }
        }
        if geometric(t.kind) {
            blocked = true;
        }
        rest.push(t);
    }
    Prepared { folded: folded.map(|s| s.transform), rest }
}

/// Applies a prepared adjustment to `s`.
pub(crate) fn apply_prepared(p: &Prepared, s: &mut State, scope: &Scope, rand: &mut Rand64) -> Result<(), EvalError> {
    if let Some(m) = &p.folded {
        s.transform.premultiply(m);
    }
    apply(&p.rest, s, scope, rand)
}

/// Applies `terms` to `s`, drawing random numbers from `rand`.
pub fn apply(terms: &[Term], s: &mut State, scope: &Scope, rand: &mut Rand64) -> Result<(), EvalError> {
    // Most replacements' terms fold into a constant map: no buffer then.
    if terms.is_empty() {
        return Ok(());
    }
    let mut a = Vec::with_capacity(6);
    for t in terms {
        // `trans NAME` with an adjustment value (eval/modval.rs).
        if t.kind == TermKind::Transform {
            if let Some(v) = super::modval::lookup(&t.args, scope) {
                super::modval::apply(v, s);
                continue;
            }
        }
        a.clear();
        eval(&t.args, scope, rand, &mut a)?;
        // `trans` of an adjustment-valued expression (eval/shapeval.rs).
        match super::shapeval::as_adjust(&a) {
            Some(v) if t.kind == TermKind::Transform => super::modval::apply(v, s),
            _ => term(t, &a, s)?,
        }
    }
    Ok(())
}

pub(crate) fn term(t: &Term, a: &[f64], s: &mut State) -> Result<(), EvalError> {
    let n = a.len();
    let arity = |ok: &[usize]| -> Result<(), EvalError> {
        if ok.contains(&n) {
            Ok(())
        } else {
            Err(EvalError::BadParam { name: format!("{:?}", t.kind).to_lowercase(), message: format!("{}:{}: {n} arguments is not one of {ok:?}", t.span.line, t.span.column) })
        }
    };
    let clamp = |v: f64| v.clamp(-1.0, 1.0);
    let tr = &mut s.transform;
    match t.kind {
        TermKind::X => {
            arity(&[1, 2, 3])?;
            tr.premultiply(&Affine::translation(a[0], if n >= 2 { a[1] } else { 0.0 }));
            if n == 3 {
                s.tz += s.sz * a[2];
            }
        }
        TermKind::Y => {
            arity(&[1])?;
            tr.premultiply(&Affine::translation(0.0, a[0]));
        }
        TermKind::Z => {
            arity(&[1])?;
            s.tz += s.sz * a[0];
        }
        TermKind::Size => {
            arity(&[1, 2, 3])?;
            tr.premultiply(&Affine::scaling(a[0], if n >= 2 { a[1] } else { a[0] }));
            if n == 3 {
                s.sz *= a[2];
            }
        }
        TermKind::ZSize => {
            arity(&[1])?;
            s.sz *= a[0];
        }
        TermKind::Rotate => {
            arity(&[1])?;
            tr.premultiply(&Affine::rotation(a[0] * PI / 180.0));
        }
        TermKind::Skew => {
            arity(&[2])?;
            tr.premultiply(&Affine::skewing(a[0] * PI / 180.0, a[1] * PI / 180.0));
        }
        TermKind::Flip => {
            arity(&[1])?;
            tr.premultiply(&Affine::reflection(a[0] * PI / 180.0));
        }
        TermKind::Transform => {
            arity(&[1, 2, 4, 6])?;
            let m = match n {
                1 | 2 => Affine::translation(a[0], if n == 2 { a[1] } else { 0.0 }),
                4 => {
                    let (dx, dy) = (a[2] - a[0], a[3] - a[1]);
                    let mut m = Affine::scaling((dx * dx + dy * dy).sqrt(), (dx * dx + dy * dy).sqrt());
                    m.multiply(&Affine::rotation(dy.atan2(dx)));
                    m.multiply(&Affine::translation(a[0], a[1]));
                    m
                }
                _ => Affine::parallelogram(&[a[0], a[1], a[2], a[3], a[4], a[5]]),
            };
            tr.premultiply(&m);
        }
        TermKind::Hue | TermKind::Sat | TermKind::Bright | TermKind::Alpha => {
            let first = match t.kind {
                TermKind::Hue => 0,
                TermKind::Sat => 1,
                TermKind::Bright => 2,
                _ => 3,
            };
            if n == 2 {
                // The two-value form: towards the given target.
                let c = s.color.get_mut(first);
                *c = if first == 0 { adjust_hue(*c, clamp(a[0]), true, a[1]) } else { adjust(*c, clamp(a[0]), true, clamp(a[1])) };
            } else {
                for (i, &v) in a.iter().enumerate().take(4 - first.min(3)) {
                    let k = first + i;
                    let c = s.color.get_mut(k);
                    *c = if k == 0 { adjust_hue(*c, v, false, 0.0) } else { adjust(*c, clamp(v), false, 0.0) };
                }
            }
        }
        TermKind::HueTarg | TermKind::SatTarg | TermKind::BrightTarg | TermKind::AlphaTarg => {
            arity(&[1])?;
            let k = match t.kind {
                TermKind::HueTarg => 0,
                TermKind::SatTarg => 1,
                TermKind::BrightTarg => 2,
                _ => 3,
            };
            let target = *s.target.get_mut(k);
            let c = s.color.get_mut(k);
            *c = if k == 0 { adjust_hue(*c, clamp(a[0]), true, target) } else { adjust(*c, clamp(a[0]), true, target) };
        }
        TermKind::TargHue => {
            arity(&[1])?;
            s.target.h += a[0];
        }
        TermKind::TargSat | TermKind::TargBright | TermKind::TargAlpha => {
            arity(&[1])?;
            let k = match t.kind {
                TermKind::TargSat => 1,
                TermKind::TargBright => 2,
                _ => 3,
            };
            let c = s.target.get_mut(k);
            *c = adjust(*c, clamp(a[0]), false, 0.0);
        }
        TermKind::Time => {
            arity(&[2])?;
            super::anim::shift(&mut s.time, a[0], a[1]);
        }
        TermKind::TimeScale => {
            arity(&[1])?;
            s.time[0] *= a[0];
        }
        TermKind::Ignored => {}
    }
    Ok(())
}
