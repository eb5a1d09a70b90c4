//! Shapes named inside expressions, resolved once the whole design is
//! read: cfdg's parser cannot tell `foo(0.5)` (a shape with its arguments
//! bound, `ASTruleSpecifier`) from a user function call, nor `CIRCLE` from a
//! variable, so it decides during type check (`ASTuserFunction::compile`,
//! `Builder::MakeVariable`, `astexpression.cpp`/`builder.cpp`, Context Free
//! 3.4). This pass does the same over the finished [`Grammar`]: a call of a
//! name that is a shape and not a function, and a name that is a shape and
//! no variable, parameter or definition, become [`Expr::Shape`]. The two
//! hash differently (a shape hashes its name before its arguments, a
//! function after), so the random streams depend on it.
//!
//! A replacement whose shape is a function returning a shape
//! (`anything()[ ]`) keeps its name and gets the call as its arguments:
//! cfdg's rule specifier of kind `ShapeArgs` hashes its name, then the
//! call's text (`ASTruleSpecifier::compile`, `DynamicArgs` with a function).

use super::{Element, Expr, Grammar, ParamType, Replacement, SymmetryItem, Value};
use std::collections::{HashMap, HashSet};

/// The shape name of a replacement whose shape is chosen by an expression
/// (`select(…)[ ]`, `if(…)[ ]`, `let(…)[ ]`): the expression is its
/// arguments. Empty, as cfdg's rule specifier built from an expression has
/// no name to hash (`ASTruleSpecifier(exp_ptr, loc)`).
pub(crate) const SHAPE_EXPR: &str = "";

/// The number of each shape of `g`, as the renderer numbers them: the three
/// primitives, then each rule's shape in order of its first rule.
pub(crate) fn shape_numbers(g: &Grammar) -> HashMap<String, usize> {
    let mut index: HashMap<String, usize> = HashMap::new();
    for (i, p) in ["CIRCLE", "SQUARE", "TRIANGLE"].iter().enumerate() {
        index.insert((*p).to_string(), i);
    }
    for r in &g.rules {
        let n = index.len();
        index.entry(r.name.clone()).or_insert(n);
    }
    index
}

struct Names {
    shapes: HashMap<String, usize>,
    /// Every name a variable, parameter, loop index or definition takes.
    vars: HashSet<String>,
    /// User functions returning a shape.
    shape_funcs: HashSet<String>,
    funcs: HashSet<String>,
}

/// Rewrites the shapes named in `g`'s expressions as [`Expr::Shape`].
pub(super) fn resolve(g: &mut Grammar) {
    let mut vars: HashSet<String> = HashSet::new();
    for d in &g.defines {
        vars.insert(d.name.clone());
    }
    for r in &g.rules {
        vars.extend(r.params.iter().cloned());
        collect_vars(&r.body, &mut vars);
    }
    for f in g.functions.values() {
        vars.extend(f.params.iter().map(|p| p.name.clone()));
    }
    let names = Names {
        shapes: shape_numbers(g),
        vars,
        shape_funcs: g.functions.values().filter(|f| f.ret == ParamType::Shape).map(|f| f.name.clone()).collect(),
        funcs: g.functions.keys().cloned().collect(),
    };
    for d in &mut g.defines {
        value(&mut d.value, &names);
    }
    for r in &mut g.rules {
        body(&mut r.body, &names);
    }
    for f in g.functions.values_mut() {
        expr(&mut f.body, &names);
    }
    if let Some(s) = &mut g.start {
        replacement(s, &names);
    }
}

fn collect_vars(body: &[Element], out: &mut HashSet<String>) {
    for e in body {
        match e {
            Element::Define(d) => {
                out.insert(d.name.clone());
            }
            Element::Loop(l) => {
                if let Some(v) = &l.var {
                    out.insert(v.clone());
                }
                collect_vars(&l.body, out);
                collect_vars(&l.finally, out);
            }
            Element::If { then, otherwise, .. } => {
                collect_vars(then, out);
                collect_vars(otherwise, out);
            }
            Element::Switch { cases, otherwise, .. } => {
                cases.iter().for_each(|(_, b)| collect_vars(b, out));
                collect_vars(otherwise, out);
            }
            Element::Transform { body, .. } => collect_vars(body, out),
            Element::Replace(_) | Element::PathOp(_) | Element::PathCommand(_) => {}
        }
    }
}

fn value(v: &mut Value, n: &Names) {
    match v {
        Value::Expr(e) => expr(e, n),
        Value::Adjust(a) => adjustment(a, n),
        Value::Shape(_) => {}
        Value::Symmetry(items) => items.iter_mut().for_each(|i| match i {
            SymmetryItem::Adjust(a) => adjustment(a, n),
            SymmetryItem::Expr(e, _) => expr(e, n),
        }),
    }
}

fn adjustment(a: &mut super::Adjustment, n: &Names) {
    for t in &mut a.terms {
        expr(&mut t.args, n);
    }
}

fn replacement(r: &mut Replacement, n: &Names) {
    adjustment(&mut r.adjust, n);
    if let Some(a) = &mut r.args {
        expr(a, n);
    }
    if n.shape_funcs.contains(&r.shape) && !n.shapes.contains_key(&r.shape) && !matches!(&r.args, Some(Expr::Call(f, ..)) if *f == r.shape) {
        let args = r.args.take();
        r.args = Some(Expr::Call(r.shape.clone(), Box::new(args), r.span));
    }
}

fn body(b: &mut [Element], n: &Names) {
    for e in b {
        match e {
            Element::Replace(r) => replacement(r, n),
            Element::Loop(l) => {
                expr(&mut l.args, n);
                adjustment(&mut l.adjust, n);
                body(&mut l.body, n);
                body(&mut l.finally, n);
            }
            Element::If { cond, then, otherwise, .. } => {
                expr(cond, n);
                body(then, n);
                body(otherwise, n);
            }
            Element::Switch { selector, cases, otherwise, .. } => {
                expr(selector, n);
                cases.iter_mut().for_each(|(_, b)| body(b, n));
                body(otherwise, n);
            }
            Element::Transform { adjusts, symmetry, body: b, .. } => {
                adjusts.iter_mut().for_each(|a| adjustment(a, n));
                symmetry.iter_mut().for_each(|i| match i {
                    SymmetryItem::Adjust(a) => adjustment(a, n),
                    SymmetryItem::Expr(e, _) => expr(e, n),
                });
                body(b, n);
            }
            Element::Define(d) => value(&mut d.value, n),
            Element::PathOp(p) => p.args.iter_mut().for_each(|a| expr(a, n)),
            Element::PathCommand(c) => {
                adjustment(&mut c.adjust, n);
                if let Some(w) = &mut c.width {
                    expr(w, n);
                }
            }
        }
    }
}

fn expr(e: &mut Expr, n: &Names) {
    match e {
        Expr::Num(..) | Expr::Shape(..) => {}
        Expr::Var(name, span) => {
            if let Some(&i) = n.shapes.get(name.as_str()) {
                if !n.vars.contains(name.as_str()) {
                    *e = Expr::Shape(std::mem::take(name), i, Box::new(None), *span);
                }
            }
        }
        Expr::Unary(_, a) | Expr::Paren(a) => expr(a, n),
        Expr::Binary(_, a, b) => {
            expr(a, n);
            expr(b, n);
        }
        Expr::Cons(v) => v.iter_mut().for_each(|a| expr(a, n)),
        Expr::Call(name, args, span) => {
            if let Some(a) = args.as_mut() {
                expr(a, n);
            }
            if !super::is_builtin(name) && !n.funcs.contains(name.as_str()) && !matches!(name.as_str(), "if" | "select" | "let") {
                if let Some(&i) = n.shapes.get(name.as_str()) {
                    let args = std::mem::replace(args, Box::new(None));
                    *e = Expr::Shape(std::mem::take(name), i, args, *span);
                }
            }
        }
        Expr::Let(defs, b, _) => {
            defs.iter_mut().for_each(|(_, d)| expr(d, n));
            expr(b, n);
        }
        Expr::Index(_, a, _) => expr(a, n),
        Expr::Adjust(a, _) => adjustment(a, n),
    }
}

/// The text a start shape's seed hashes after its adjustment: its name,
/// and for the `CF::StartShape = NAME(args)` form its arguments too
/// (`ASTstartSpecifier::compile` keeps the name alone, "StartShape only
/// uses name for entropy"; the setting's rule specifier was compiled as an
/// expression first, its arguments' text appended, and `MakeConfig` copies
/// it: `astexpression.cpp`, `builder.cpp`).
pub(crate) fn start_name_entropy(start: &Replacement, from_setting: bool) -> Vec<u8> {
    let mut out = start.shape.as_bytes().to_vec();
    if from_setting {
        if let Some(a) = &start.args {
            super::entropy::expr_entropy(a, &mut out);
        }
    }
    out
}
