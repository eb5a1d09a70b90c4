//! Adjustment values: a definition `NAME = [ terms ]` and its use as
//! `trans NAME` (`transform NAME`), as cfdg 3.4 evaluates them
//! (`astexpression.cpp`: `ASTmodification::setVal` evaluates the terms
//! into a `Modification` with `shapeDest` false, so colour terms record
//! deltas, targets and assignment flags instead of changing a colour;
//! `ASTvariable::evaluate` applies it with `Modification::operator*=`
//! (`shape.h`): geometry and z premultiplied, colours by
//! `HSBColor::Adjust` (`HSBColor.cpp`), each channel moved plainly, towards
//! the shape's target, or towards the value's own two-value target).
//!
//! The value is kept among the numeric variables under its name prefixed
//! by [`MOD_VAR`] (a character no CFDG name holds), as 18 numbers: the
//! affine map (sx, shy, shx, sy, tx, ty), z's scale and offset, the colour
//! deltas (h, s, b, a), the target deltas and the assignment flags, so it
//! is scoped as the other locals are.

use super::adjust::{prepare, term};
use super::expr::{eval, Scope};
use super::state::{adjust, adjust_hue, Affine, State};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Adjustment, Expr, TermKind};
use crate::model::EvalError;

/// The prefix marking an adjustment value among the scope's variables.
pub(crate) const MOD_VAR: char = '\u{2}';

/// `HSBColor::Color2Value`, `ColorTarget`: a channel's assignment flags.
const TWO_VALUE: u32 = 3;
const TARGET: u32 = 1;

/// The variable name an adjustment value `name` is kept under.
pub fn key(name: &str) -> String {
    format!("{MOD_VAR}{name}")
}

/// The adjustment value `e` names, if it names one (`trans NAME`).
pub fn lookup<'s>(e: &Expr, scope: &'s Scope<'_>) -> Option<&'s [f64]> {
    match e {
        Expr::Paren(a) => lookup(a, scope),
        Expr::Var(name, _) => scope.get_marked(MOD_VAR, name),
        _ => None,
    }
}

fn refuse(t: &crate::cfdg::syntax::Term, what: &str) -> EvalError {
    EvalError::BadParam { name: "adjustment".into(), message: format!("{}:{}: {what} is not allowed", t.span.line, t.span.column) }
}

/// Evaluates `adj` into an adjustment value (`ASTmodification::setVal`);
/// `constant` as [`is_constant`] says (the definition is then folded where
/// it is used, see [`fold_seeds`]).
pub(crate) fn value_of(adj: &Adjustment, scope: &Scope<'_>, rand: &mut Rand64, constant: bool) -> Result<Vec<f64>, EvalError> {
    let p = prepare(adj);
    let mut geo = State::initial();
    if let Some(m) = p.folded {
        geo.transform = m;
    }
    let (mut color, mut target, mut assign) = ([0.0f64; 4], [0.0f64; 4], 0u32);
    let mut a = Vec::with_capacity(6);
    for t in &p.rest {
        a.clear();
        match lookup(&t.args, scope) {
            Some(v) => a.extend_from_slice(v),
            None => eval(&t.args, scope, rand, &mut a)?,
        }
        // An adjustment inside another: merged (eval/shapeval.rs).
        let nested = if a.len() + 1 == super::shapeval::ADJUST_LEN && lookup(&t.args, scope).is_some() { Some(&a[..]) } else { super::shapeval::as_adjust(&a) };
        if let Some(v) = nested {
            if t.kind != TermKind::Transform {
                return Err(refuse(t, "an adjustment as the argument of a term other than `trans`"));
            }
            // On a colour conflict cfdg merges nothing and draws on (its
            // "Conflicting color change" is not reported by the CLI).
            super::shapeval::merge(v, &mut geo, &mut color, &mut target, &mut assign);
            continue;
        }
        let clamp = |v: f64| v.clamp(-1.0, 1.0);
        let channel = |k: TermKind| match k {
            TermKind::Hue | TermKind::HueTarg | TermKind::TargHue => 0,
            TermKind::Sat | TermKind::SatTarg | TermKind::TargSat => 1,
            TermKind::Bright | TermKind::BrightTarg | TermKind::TargBright => 2,
            _ => 3,
        };
        match t.kind {
            TermKind::Hue | TermKind::Sat | TermKind::Bright | TermKind::Alpha => {
                let first = channel(t.kind);
                if a.len() == 2 {
                    color[first] = clamp(a[0]);
                    target[first] = if first == 0 { a[1] } else { clamp(a[1]) };
                    assign |= TWO_VALUE << (2 * first);
                } else {
                    for (i, &v) in a.iter().enumerate().take(4 - first.min(3)) {
                        let k = first + i;
                        if k == 0 {
                            color[0] += v;
                        } else {
                            color[k] = clamp(v);
                        }
                    }
                }
            }
            TermKind::HueTarg | TermKind::SatTarg | TermKind::BrightTarg | TermKind::AlphaTarg => {
                let k = channel(t.kind);
                color[k] = clamp(a.first().copied().unwrap_or(0.0));
                assign |= TARGET << (2 * k);
            }
            TermKind::TargHue => target[0] += a.first().copied().unwrap_or(0.0),
            TermKind::TargSat | TermKind::TargBright | TermKind::TargAlpha => target[channel(t.kind)] = clamp(a.first().copied().unwrap_or(0.0)),
            _ => term(t, &a, &mut geo)?,
        }
    }
    let m = geo.transform;
    let mut v = vec![m.sx, m.shy, m.shx, m.sy, m.tx, m.ty, geo.sz, geo.tz];
    v.extend_from_slice(&color);
    v.extend_from_slice(&target);
    v.push(f64::from(assign));
    v.push(f64::from(u8::from(constant)));
    Ok(v)
}

/// Whether an adjustment definition is constant, so cfdg folds it at
/// compile time and never traverses it (no seed mixed in): every term
/// constant and none a colour term, since `ASTmodTerm::evaluate` defers
/// colours to run time and the definition keeps them as run-time terms.
/// Found against cfdg's output: a constant `b9 = [s 10]` mixes nothing in
/// (arraytest1), a constant `x5 = [alpha -.5 sat .5]` its seed (`mod exp
/// test`, where it changes the rules chosen after it).
pub(crate) fn is_constant(adj: &Adjustment) -> bool {
    adj.terms.iter().all(|t| crate::cfdg::syntax::is_constant(&t.args) && !is_colour(t.kind))
}

fn is_colour(k: TermKind) -> bool {
    matches!(k, TermKind::Hue | TermKind::Sat | TermKind::Bright | TermKind::Alpha | TermKind::HueTarg | TermKind::SatTarg | TermKind::BrightTarg | TermKind::AlphaTarg | TermKind::TargHue | TermKind::TargSat | TermKind::TargBright | TermKind::TargAlpha)
}

/// Mixes into a replacement's seed what cfdg's compile-time folding of its
/// constant, colourless adjustment values mixes in: the definition's own
/// seed (its name's, `ASTdefine::compile`), xored in by
/// `Modification::operator*=` when `ASTmodTerm::evaluate` folds the value
/// into the replacement's constant part (`ASTparameter::constCopy`). Found
/// against cfdg's output: without it `mtree mod def test` expands differently.
pub(crate) fn fold_seeds(adj: &Adjustment, scope: &Scope<'_>, seed: &mut Rand64) {
    for t in &adj.terms {
        if t.kind != TermKind::Transform {
            continue;
        }
        let mut e = &t.args;
        while let Expr::Paren(a) = e {
            e = a;
        }
        if let (Expr::Var(name, _), Some(v)) = (e, lookup(&t.args, scope)) {
            if v.get(17) == Some(&1.0) {
                seed.xor(crate::cfdg::syntax::define_seed(name));
            }
        }
    }
}

/// Applies adjustment value `v` to a shape's state (`Modification::operator*=`).
pub fn apply(v: &[f64], s: &mut State) {
    let [sx, shy, shx, sy, tx, ty, sz, tz, h, sat, b, al, th, ts, tb, ta, assign, _foldable] = v else { return };
    s.transform.premultiply(&Affine { sx: *sx, shy: *shy, shx: *shx, sy: *sy, tx: *tx, ty: *ty });
    s.tz += s.sz * tz;
    s.sz *= sz;
    let assign = *assign as u32;
    let adj = [*h, *sat, *b, *al];
    let targ = [*th, *ts, *tb, *ta];
    for k in 0..4 {
        let current = (assign >> (2 * k)) & TWO_VALUE;
        let two = current == TWO_VALUE;
        let dest_target = *s.target.get_mut(k);
        let goal = if two { targ[k] } else { dest_target };
        let c = s.color.get_mut(k);
        *c = if k == 0 { adjust_hue(*c, adj[k], current != 0, goal) } else { adjust(*c, adj[k], current != 0, goal) };
        if !two {
            let t = s.target.get_mut(k);
            *t = if k == 0 { adjust_hue(*t, targ[k], false, 0.0) } else { adjust(*t, targ[k], false, 0.0) };
        }
    }
}
