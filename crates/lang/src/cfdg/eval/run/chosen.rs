//! The shape a replacement draws when it is a value: a shape parameter
//! (`thingie[]`), a variable holding a shape (`draw = anything()`), a
//! function returning a shape (`anything()[ ]`), or an expression choosing
//! one (`select(…)[ ]`, `if(…)[ ]`, `let(…)[ ]`), as cfdg 3.4 finds it
//! (`astexpression.cpp`: `ASTruleSpecifier::evalArgs` for `StackArgs` and
//! `ShapeArgs`, evaluated in `ASTreplacement::replace` before the
//! replacement's seed is mixed in).

use super::super::expr::eval;
use super::super::shapeval::as_shape;
use super::Renderer;
use crate::cfdg::syntax::{Expr, Replacement, SHAPE_EXPR};
use crate::model::EvalError;

impl Renderer<'_> {
    /// The shape `rep` draws and, when it is a value, its bound arguments
    /// (else as [`Renderer::target`] finds them).
    pub(super) fn target_of(&mut self, rep: &Replacement) -> Result<(usize, Option<Vec<f64>>), EvalError> {
        let error = |what: &str| EvalError::BadParam { name: if rep.shape.is_empty() { "shape".into() } else { rep.shape.clone() }, message: format!("{}:{}: {what}", rep.span.line, rep.span.column) };
        let chosen = rep.shape == SHAPE_EXPR || (matches!(&rep.args, Some(Expr::Call(f, ..)) if *f == rep.shape) && !self.rules.index.contains_key(rep.shape.as_str()) && self.scope.funcs.defs.contains_key(&rep.shape));
        // Parameters and variables holding a shape (`thingie[]`) are
        // found by `target`, as a subpath finds them.
        if !chosen {
            return self.target(rep);
        }
        let Some(e) = &rep.args else { return Err(error("expected a shape")) };
        let mut v = Vec::new();
        eval(e, &self.scope, &mut self.current, &mut v)?;
        self.charge_calls()?;
        match as_shape(&v) {
            Some((shape, args)) if shape < self.rules.by_shape.len() => Ok((shape, Some(args.to_vec()))),
            _ => Err(error("the expression does not give a shape")),
        }
    }
}
