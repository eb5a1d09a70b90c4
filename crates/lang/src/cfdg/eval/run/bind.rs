//! Binding shape parameters and shape variables, as cfdg binds them
//! (Context Free 3.4): a shape's arguments are one flat list of numbers
//! split by its parameters' sizes (`StackRule::evalArgs`, `stacktype.cpp`;
//! `vectorN` parameters take N); a definition whose value names a shape,
//! with or without arguments (`stem = curve(0.97, 1)`, `draw = CIRCLE`,
//! `bar = foo`), is a shape variable (`ASTruleSpecifier` of kind
//! `StackArgs`, `astexpression.cpp` `compile` and `simplify`, `builder.cpp`
//! `MakeRuleSpec`), and a replacement naming it draws that shape with those
//! arguments; a shape named but never given rules is an error only when it
//! is reached ("Shape with no rules encountered", `renderimpl.cpp`).
//!
//! A shape variable is kept among the numeric variables under its name
//! prefixed by [`SHAPE_VAR`], its value whether it is constant (1 or 0),
//! the shape's number and its arguments, so it is scoped and dropped exactly as the other locals are.

use super::super::expr::{eval, Scope};
use super::super::Rules;
use super::Renderer;
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{self, Expr, Replacement};
use crate::model::EvalError;

/// The prefix that marks a shape variable among the scope's variables (a
/// character no CFDG name can hold).
pub(super) const SHAPE_VAR: char = super::super::shapeval::SHAPE_VAR;

fn key(name: &str) -> String {
    format!("{SHAPE_VAR}{name}")
}

/// If `e` names a shape, its value: whether it is constant (1 or 0), the
/// shape's number, then its arguments. `parent` holds the enclosing
/// shape's arguments (for `NAME(=)`).
pub(super) fn shape_value(e: &Expr, rules: &Rules<'_>, scope: &Scope<'_>, rand: &mut Rand64, parent: &[f64]) -> Result<Option<Vec<f64>>, EvalError> {
    let constant = f64::from(u8::from(shape_is_constant(e, scope)));
    match e {
        Expr::Paren(a) => shape_value(a, rules, scope, rand, parent),
        Expr::Var(name, _) => {
            if let Some(v) = scope.get_marked(SHAPE_VAR, name) {
                return Ok(Some(v.to_vec()));
            }
            if scope.get(name).is_some() {
                return Ok(None);
            }
            Ok(rules.index.get(name.as_str()).map(|&i| vec![constant, i as f64]))
        }
        Expr::Shape(name, _, args, _) if args.is_none() => shape_value(&Expr::Var(name.clone(), crate::Span::new(0, 0)), rules, scope, rand, parent),
        Expr::Call(name, args, span) | Expr::Shape(name, _, args, span) if !syntax::is_builtin(name) && !scope.funcs.defs.contains_key(name) => {
            let Some(&i) = rules.index.get(name.as_str()) else { return Ok(None) };
            let mut v = vec![constant, i as f64];
            match args.as_ref() {
                Some(Expr::Var(r, _)) if r == syntax::REUSE => v.extend_from_slice(parent),
                Some(a) => eval(a, scope, rand, &mut v)?,
                None => {}
            }
            if super::super::shapeval::split(&rules.sizes[i], &v[2..]).is_none() {
                let wanted = rules.sizes[i].len();
                return Err(EvalError::BadParam { name: name.clone(), message: format!("{}:{}: shape `{name}` takes {wanted} parameters, given {} numbers that do not fit them", span.line, span.column, v.len() - 2) });
            }
            Ok(Some(v))
        }
        _ => Ok(None),
    }
}

/// Whether a shape definition is constant, so cfdg folds it at compile time
/// and never traverses it (no seed mixed in): a shape named alone or with
/// constant arguments, or a constant shape variable (`ASTparameter::constCopy`).
pub(super) fn shape_is_constant(e: &Expr, scope: &Scope<'_>) -> bool {
    match e {
        Expr::Paren(a) => shape_is_constant(a, scope),
        Expr::Var(name, _) => scope.get_marked(SHAPE_VAR, name).is_none_or(|v| v.first() == Some(&1.0)),
        Expr::Shape(name, _, args, _) if args.is_none() => shape_is_constant(&Expr::Var(name.clone(), crate::Span::new(0, 0)), scope),
        Expr::Call(_, args, _) | Expr::Shape(_, _, args, _) => match args.as_ref() {
            Some(Expr::Var(r, _)) if r == syntax::REUSE => false,
            Some(a) => syntax::is_constant(a),
            None => true,
        },
        _ => false,
    }
}

/// Pushes a shape variable `name` with value `v` ([`shape_value`]).
pub(super) fn push_shape_var(scope: &mut Scope<'_>, name: &str, v: Vec<f64>) {
    scope.vars.push((key(name), v));
}

/// Pushes cfdg's predefined globals (`CFDGImpl::initVariables`,
/// `cfdgimpl.cpp`): `π`, and Unicode names for the primitives as constant
/// shape variables (⚫ ● ⬤ a CIRCLE; ⬛ ◼ ◾ ￭ ■ a SQUARE; ▲ ▴ a TRIANGLE).
pub(super) fn push_predefined(scope: &mut Scope<'_>) {
    scope.vars.push(("\u{3c0}".to_string(), vec![std::f64::consts::PI]));
    let prims: [(&[&str], usize); 3] = [(&["\u{26ab}", "\u{25cf}", "\u{2b24}"], 0), (&["\u{2b1b}", "\u{25fc}", "\u{25fe}", "\u{ffed}", "\u{25a0}"], 1), (&["\u{25b2}", "\u{25b4}"], 2)];
    for (names, shape) in prims {
        for name in names {
            push_shape_var(scope, name, vec![1.0, shape as f64]);
        }
    }
}

/// Whether `name` is a rule's shape name rather than a variable in scope.
pub(super) fn names_rule(e: &Expr, rules: &Rules<'_>, scope: &Scope<'_>) -> bool {
    match e {
        Expr::Paren(a) => names_rule(a, rules, scope),
        Expr::Var(name, _) => scope.get_marked(SHAPE_VAR, name).is_some() || (scope.get(name).is_none() && rules.index.contains_key(name.as_str())),
        Expr::Shape(name, _, args, _) if args.is_none() => names_rule(&Expr::Var(name.clone(), crate::Span::new(0, 0)), rules, scope),
        Expr::Call(name, _, _) | Expr::Shape(name, _, _, _) => !syntax::is_builtin(name) && !scope.funcs.defs.contains_key(name) && rules.index.contains_key(name.as_str()),
        _ => false,
    }
}

impl Renderer<'_> {
    /// Pushes shape `shape`'s parameters onto the scope, `params` split by
    /// the parameters' sizes.
    pub(super) fn bind_params(&mut self, shape: usize, params: &[f64]) {
        let names = self.rules.params[shape];
        // Typed parameters (shapes, adjustments) split by their runs.
        if let Some(parts) = super::super::shapeval::split(&self.rules.sizes[shape], params) {
            for (n, v) in names.iter().zip(parts) {
                self.scope.vars.push((n.clone(), v.to_vec()));
            }
            return;
        }
        let mut at = 0;
        for (i, n) in names.iter().enumerate() {
            let k = self.rules.sizes[shape].get(i).copied().unwrap_or(1);
            let v = params.get(at..at + k).map(<[f64]>::to_vec).unwrap_or_default();
            at += k;
            self.scope.vars.push((n.clone(), v));
        }
    }

    /// The shape a replacement draws and, for a shape variable, its bound
    /// arguments; a name with no rules and no variable is an error here,
    /// where cfdg meets it.
    pub(super) fn target(&self, rep: &Replacement) -> Result<(usize, Option<Vec<f64>>), EvalError> {
        if let Some(v) = self.scope.get_marked(SHAPE_VAR, &rep.shape) {
            if rep.args.is_some() {
                return Err(EvalError::BadParam { name: rep.shape.clone(), message: format!("{}:{}: cannot bind parameters twice (`{}` is a shape variable)", rep.span.line, rep.span.column, rep.shape) });
            }
            let shape = v.get(1).map_or(0, |&s| s as usize);
            return Ok((shape, Some(v.get(2..).map(<[f64]>::to_vec).unwrap_or_default())));
        }
        // A shape parameter or a variable holding a shape (eval/shapeval.rs).
        if let Some((shape, args)) = self.scope.get(&rep.shape).and_then(super::super::shapeval::as_shape) {
            if rep.args.is_some() || shape >= self.rules.by_shape.len() {
                return Err(EvalError::BadParam { name: rep.shape.clone(), message: format!("{}:{}: cannot bind parameters twice (`{}` is a shape parameter)", rep.span.line, rep.span.column, rep.shape) });
            }
            return Ok((shape, Some(args.to_vec())));
        }
        match self.rules.index.get(rep.shape.as_str()) {
            Some(&i) => Ok((i, None)),
            None => Err(EvalError::BadParam { name: rep.shape.clone(), message: format!("{}:{}: shape with no rules encountered: `{}`", rep.span.line, rep.span.column, rep.shape) }),
        }
    }

    /// Charges the user function calls made since the last charge as
    /// steps, and allows as many more as the budget has left.
    pub(super) fn charge_calls(&mut self) -> Result<(), EvalError> {
        let n = self.scope.funcs.take_calls();
        if n > 0 {
            self.budget.charge_steps(n)?;
        }
        let limits = self.budget.limits();
        self.scope.funcs.allow(self.budget.steps(), limits.max_steps, limits.max_depth);
        Ok(())
    }
}
