//! Replacements whose shape is chosen by an expression: `select(n, A, B)[ ]`,
//! `if(c, A, B)[ ]` and `let(n = e; select(n, A, B))[ ]`, after `cfdg.ypp`'s
//! `element_simple` (Context Free 3.4: `shapeName parameter_spec
//! modification` with the name `select`, `IF '(' exp2 ')' modification`,
//! `letHeader letBody modification`) and `Builder::MakeRuleSpec`
//! (`builder.cpp`), which makes each a rule specifier holding the
//! expression. An `if` followed by its parenthesis and then `[` is this
//! form; followed by anything else it is the `if` statement.

use super::super::{Element, Expr, Replacement, SHAPE_EXPR};
use super::{Parser, Tok};
use crate::{ParseError, Span};

impl Parser<'_> {
    /// The replacement starting here when its shape is chosen by an
    /// expression; `None` (nothing read) otherwise.
    pub(super) fn chosen_shape(&mut self, span: Span) -> Result<Option<Element>, ParseError> {
        let Tok::Word(w) = self.peek() else { return Ok(None) };
        if !self.v3() || !matches!(w.as_str(), "select" | "if" | "let") || !matches!(self.peek_at(1), Tok::Punct("(")) {
            return Ok(None);
        }
        if !self.bracket_after_parens() {
            return Ok(None);
        }
        self.enter()?;
        let e = self.primary()?;
        let adjust = self.adjustment()?;
        self.depth -= 1;
        Ok(Some(Element::Replace(Replacement { shape: SHAPE_EXPR.to_string(), adjust, args: Some(e), span })))
    }

    /// Whether the parenthesis after the current word closes right before a `[`.
    fn bracket_after_parens(&self) -> bool {
        let mut depth = 0usize;
        let mut k = 1;
        loop {
            match self.peek_at(k) {
                Tok::Punct("(") => depth += 1,
                Tok::Punct(")") => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return matches!(self.peek_at(k + 1), Tok::Punct("["));
                    }
                }
                Tok::Eof => return false,
                _ => {}
            }
            k += 1;
        }
    }
}

/// A start shape chosen by `select(…)` or `if(…)` (`startshape select(…)`,
/// `CF::StartShape = if(…)`: `Builder::MakeRuleSpec` with `makeStart`): the
/// shape name [`SHAPE_EXPR`] and the call as its arguments; any other
/// name and arguments unchanged.
pub(super) fn chosen_start(name: String, args: Option<Expr>, span: Span) -> (String, Option<Expr>) {
    if matches!(name.as_str(), "select" | "if") && args.is_some() {
        (SHAPE_EXPR.to_string(), Some(Expr::Call(name, Box::new(args), span)))
    } else {
        (name, args)
    }
}
