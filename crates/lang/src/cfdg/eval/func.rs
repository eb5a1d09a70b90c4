//! User functions, `let` and vector indexing as cfdg evaluates them
//! (`astexpression.cpp`, Context Free 3.4: `ASTuserFunction::evaluate` and
//! its `StackSetup`, which binds the arguments with `StackType::evalArgs`
//! (`stacktype.cpp`) and lets the body see only the globals; `ASTlet`, a
//! user function whose arguments are its definitions and which sees its
//! caller's variables; `ASTarray::evaluate`).
//!
//! A recursive function is a user loop: every call (and every `let`) is a
//! step counted here and charged to the render's `Budget` by the renderer
//! ([`Functions::take_calls`]); the calls made before the next charge may
//! not pass the steps left, and calls nest at most [`MAX_CALL_DEPTH`] deep
//! (or the budget's depth limit, if lower), so hostile recursion ends in a
//! typed limit error, never a stack overflow.

use super::expr::{eval, Scope};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Expr, Function, ParamType};
use crate::core::budget::{Limit, LimitExceeded};
use crate::model::EvalError;
use crate::Span;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering};

/// Deepest nesting of user function calls, whatever the budget allows: each
/// level is a few Rust frames of the evaluator, and the evaluation may run
/// on a thread with a 2 MiB stack. cfdg's own bound is its parameter stack
/// ("Maximum stack size exceeded"); Ackermann's function at (3, 5), in
/// `recursiontest.cfdg`, nests about 255 deep.
pub(crate) const MAX_CALL_DEPTH: u32 = 400;

/// The user functions of a design and the meter of their calls.
#[derive(Debug, Default)]
pub struct Functions {
    /// The functions by name.
    pub defs: BTreeMap<String, Function>,
    /// Calls made and not yet charged to the budget.
    calls: AtomicU64,
    /// How many calls may be made before the next charge (the steps left).
    allowance: AtomicU64,
    /// The budget's step limit, for the error.
    max_steps: AtomicU64,
    /// The budget's steps when the allowance was set, for the error.
    base: AtomicU64,
    /// Current nesting of calls.
    depth: AtomicU32,
    /// Deepest nesting allowed.
    max_depth: AtomicU32,
}

impl Functions {
    /// The functions of a design, with no calls allowed until [`Self::allow`].
    pub fn new(defs: BTreeMap<String, Function>) -> Functions {
        Functions { defs, ..Default::default() }
    }

    /// Allows calls up to the budget's steps left; nesting up to its depth
    /// limit (at most [`MAX_CALL_DEPTH`]).
    pub fn allow(&self, steps: u64, max_steps: u64, max_depth: u32) {
        self.base.store(steps, Ordering::Relaxed);
        self.max_steps.store(max_steps, Ordering::Relaxed);
        self.allowance.store(max_steps.saturating_sub(steps), Ordering::Relaxed);
        self.max_depth.store(max_depth.min(MAX_CALL_DEPTH), Ordering::Relaxed);
    }

    /// The calls made since the last take, to be charged as steps.
    pub(crate) fn take_calls(&self) -> u64 {
        self.calls.swap(0, Ordering::Relaxed)
    }

    fn enter(&self) -> Result<(), EvalError> {
        let calls = self.calls.fetch_add(1, Ordering::Relaxed) + 1;
        if calls > self.allowance.load(Ordering::Relaxed) {
            let max = self.max_steps.load(Ordering::Relaxed);
            return Err(LimitExceeded::crossed(Limit::Steps, max, self.base.load(Ordering::Relaxed).saturating_add(calls)).into());
        }
        let depth = self.depth.fetch_add(1, Ordering::Relaxed) + 1;
        let max = self.max_depth.load(Ordering::Relaxed);
        if depth > max {
            self.depth.fetch_sub(1, Ordering::Relaxed);
            return Err(LimitExceeded::crossed(Limit::Depth, max.into(), depth.into()).into());
        }
        Ok(())
    }

    fn leave(&self) {
        self.depth.fetch_sub(1, Ordering::Relaxed);
    }
}

fn bad_call(span: Span, name: &str, message: impl std::fmt::Display) -> EvalError {
    EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: {message}", span.line, span.column) }
}

/// The scope a user function's body sees: its parameters over the globals.
fn globals_of<'a>(scope: &'a Scope<'a>) -> (&'a Scope<'a>, usize) {
    let mut s = scope;
    while let Some((up, _)) = s.up {
        s = up;
    }
    (s, s.globals.unwrap_or(s.vars.len()))
}

/// Calls user function `name` with `args` (a list of parenthesised
/// arguments), appending its value to `out` (`ASTuserFunction::evaluate`).
pub fn call(name: &str, args: Option<&Expr>, span: Span, scope: &Scope<'_>, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    let Some(f) = scope.funcs.defs.get(name) else {
        return Err(bad_call(span, name, "unknown or unsupported function"));
    };
    // The arguments are evaluated in the caller's scope, in order.
    let items = args.map(|a| a.items()).unwrap_or_default();
    let mut given = Vec::new();
    for a in &items {
        let mut v = Vec::new();
        eval(a, scope, rand, &mut v)?;
        given.push(v);
    }
    // StackType::evalArgs takes the arguments as one flat list, matched
    // against the parameters' sizes in order.
    let flat: Vec<f64> = given.into_iter().flatten().collect();
    let sizes: Vec<usize> = f.params.iter().map(|p| super::shapeval::slot_size(p.ty)).collect();
    let Some(parts) = super::shapeval::split(&sizes, &flat) else {
        return Err(bad_call(span, name, format!("takes {} parameters, given {} numbers that do not fit them", f.params.len(), flat.len())));
    };
    let mut vars = Vec::with_capacity(f.params.len());
    for (p, v) in f.params.iter().zip(parts) {
        let v = v.to_vec();
        if p.ty == ParamType::Natural && !is_natural(v[0], scope.max_natural) {
            return Err(bad_call(span, name, format!("argument `{}` is {}, not a natural number", p.name, v[0])));
        }
        vars.push((p.name.clone(), v));
    }
    scope.funcs.enter()?;
    let inner = Scope { vars, up: Some(globals_of(scope)), globals: Some(0), max_natural: scope.max_natural, funcs: scope.funcs.clone(), rand_static: scope.rand_static.clone() };
    let from = out.len();
    let r = eval(&f.body, &inner, rand, out);
    scope.funcs.leave();
    r?;
    if !super::shapeval::fits(f.ret, &out[from..]) {
        return Err(bad_call(f.span, name, format!("returns {} numbers that its type `{:?}` does not hold", out.len() - from, f.ret)));
    }
    Ok(())
}

fn is_natural(v: f64, max: f64) -> bool {
    v >= 0.0 && v <= max && v == v.floor()
}

/// `let(a = e; …; body)`: each definition evaluated in turn, seeing the
/// caller's variables and those before it, then the body (`ASTlet`).
pub(crate) fn let_in(defs: &[(String, Expr)], body: &Expr, _span: Span, scope: &Scope<'_>, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    scope.funcs.enter()?;
    let mut inner = Scope { vars: Vec::with_capacity(defs.len()), up: Some((scope, scope.vars.len())), globals: Some(0), max_natural: scope.max_natural, funcs: scope.funcs.clone(), rand_static: scope.rand_static.clone() };
    let mut r = Ok(());
    for (name, e) in defs {
        let mut v = Vec::new();
        r = eval(e, &inner, rand, &mut v);
        if r.is_err() {
            break;
        }
        inner.vars.push((name.clone(), v));
    }
    if r.is_ok() {
        r = eval(body, &inner, rand, out);
    }
    scope.funcs.leave();
    r
}

/// `name[i]` or `name[i, length, stride]`: `length` elements from index `i`,
/// `stride` apart (`ASTarray::evaluate`; the index truncated toward zero).
pub fn index(name: &str, args: &Expr, span: Span, scope: &Scope<'_>, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    let Some(v) = scope.get(name) else {
        return Err(bad_call(span, name, "cannot find this vector"));
    };
    let items = args.items();
    let mut i = Vec::new();
    eval(items[0], scope, rand, &mut i)?;
    let [i] = i.as_slice() else {
        return Err(bad_call(span, name, "a vector index must be one number"));
    };
    // Length and stride are constants (ASTarray::compile): the last two items.
    let mut consts = Vec::new();
    for e in &items[1..] {
        let mut c = Vec::new();
        eval(e, scope, rand, &mut c)?;
        consts.extend(c);
    }
    let (length, stride) = match consts.as_slice() {
        [] => (1, 1),
        [l] => (*l as i64, 1),
        [l, s] => (*l as i64, *s as i64),
        _ => return Err(bad_call(span, name, "a vector index takes an index, a length and a stride")),
    };
    let index = *i as i64;
    let count = v.len() as i64;
    if length < 0 || stride < 0 || index < 0 || (length - 1).saturating_mul(stride).saturating_add(index) >= count {
        return Err(bad_call(span, name, "vector index exceeds bounds"));
    }
    for k in 0..length {
        out.push(v[(k * stride + index) as usize]);
    }
    Ok(())
}

/// The built-ins on vectors (`ASTfunction::evaluate`): `dot(u, v)`,
/// `cross(u, v)` of two vector3s, and `hsb2rgb(h, s, b)` / `rgb2hsb(r, g, b)`
/// through `HSBColor` (its hextant formula and its inverse, `HSBColor.cpp`).
pub(crate) fn vector_builtin(name: &str, args: Option<&Expr>, span: Span, scope: &Scope<'_>, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    let items = args.map(|a| a.items()).unwrap_or_default();
    let mut vals = Vec::with_capacity(items.len());
    for a in &items {
        let mut v = Vec::new();
        eval(a, scope, rand, &mut v)?;
        vals.push(v);
    }
    match name {
        "vec" => super::builtins::vec(&vals, span, out)?,
        "dot" | "cross" => {
            let [l, r] = vals.as_slice() else { return Err(bad_call(span, name, "takes two vectors")) };
            if name == "dot" {
                if l.len() != r.len() || l.len() < 2 {
                    return Err(bad_call(span, name, "takes two vectors of the same length"));
                }
                out.push(l.iter().zip(r).map(|(a, b)| a * b).sum());
            } else {
                let ([l0, l1, l2], [r0, r1, r2]) = (l.as_slice(), r.as_slice()) else { return Err(bad_call(span, name, "takes two vector3s")) };
                out.extend_from_slice(&[l1 * r2 - l2 * r1, l2 * r0 - l0 * r2, l0 * r1 - l1 * r0]);
            }
        }
        _ => {
            let flat: Vec<f64> = vals.into_iter().flatten().collect();
            let [x, y, z] = flat.as_slice() else { return Err(bad_call(span, name, "takes 3 numbers")) };
            if name == "hsb2rgb" {
                let rgb = super::state::Hsba { h: *x, s: *y, b: *z, a: 1.0 }.rgba();
                out.extend_from_slice(&rgb[..3]);
            } else {
                out.extend_from_slice(&rgb_to_hsb(*x, *y, *z));
            }
        }
    }
    Ok(())
}

/// `HSBColor::HSBColor(const agg::rgba&)`.
fn rgb_to_hsb(r: f64, g: f64, b: f64) -> [f64; 3] {
    let min = r.min(g.min(b));
    let max = r.max(g.max(b));
    let delta = max - min;
    if delta < 0.00001 {
        return [0.0, 0.0, max];
    }
    let s = delta / max;
    let t = if r == max {
        (g - b) / delta
    } else if g == max {
        2.0 + (b - r) / delta
    } else {
        4.0 + (r - g) / delta
    } * 60.0;
    let h = if t < 0.0 { (t + 360.0) % 360.0 } else { t % 360.0 };
    [h, s, max]
}
