//! Numbers and expressions: call and adjustment arguments, `@define`
//! values, function bodies, and the constant values directives require.
//!
//! The grammar is the shared one (`crate::expr::grammar`); this
//! module is MDG's [`Host`] for it: MDG's tokens (its lexer has `+ - * / ^`
//! but no comparison or logical operators), `d`/`t` literal suffixes and
//! angle units, `@param` and `@define` names (each substitution charged to
//! the parser's copy budget), `x`/`y`/`z` in function bodies, and `rand()`
//! call sites. An argument outside parentheses is a primary (a number, a
//! name, a function call or a parenthesised expression) after any `-`
//! signs, so `x 1 -2` reads as two arguments; inside parentheses the full
//! grammar applies.

use super::{err, PResult, Parser};
use crate::core::{ParseError, Span};
use crate::expr::grammar::{self, Host, Op, Parsed, Token};
use crate::expr::{BinOp, Expr, ExprEnv, Func};
use crate::ir::AngleMode;
use crate::mdg::syntax::lexer::Tok;
use std::f64::consts::PI;

/// An expression with its tree depth and node count.
pub(super) type E = Parsed;

/// Which angle unit literals are interpreted in.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Ctx {
    /// A plain number: `d`/`t` literals become radians.
    Plain,
    /// An angle argument: literals are in the mode's unit, `d`/`t` converted into it.
    Angle,
}

/// What an argument belongs to, for error messages (formatted only on error).
#[derive(Clone, Copy)]
pub(super) enum What<'s> {
    /// After an adjustment or directive keyword.
    After(&'s str),
    /// A description such as "an iteration count".
    Text(&'s str),
}

impl std::fmt::Display for What<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            What::After(w) => write!(f, "after `{w}`"),
            What::Text(t) => write!(f, "for {t}"),
        }
    }
}

/// The environment of [`is_const`] expressions, which read neither a
/// parameter nor a random number (either would be NaN).
struct NaNEnv;
impl ExprEnv for NaNEnv {
    fn param(&self, _: u32) -> f64 {
        f64::NAN
    }
    fn rand(&mut self, _: u32) -> f64 {
        f64::NAN
    }
}

/// A number literal as an expression tree of one node.
pub(super) fn num(v: f64) -> E {
    Parsed::leaf(Expr::Num(v))
}

/// The parser as the shared grammar's host, reading literals in `ctx`
/// (call arguments are plain numbers: trigonometry works in radians).
struct MdgHost<'p, 'a> {
    p: &'p mut Parser<'a>,
    /// The literal context, innermost last.
    ctx: Vec<Ctx>,
}

impl<'a> Host<'a> for MdgHost<'_, 'a> {
    fn peek(&self) -> (Token<'a>, Span) {
        let t = self.p.peek();
        let tok = match t.tok {
            Tok::Num { value, suffix, .. } => Token::Num(self.p.literal(value, suffix, *self.ctx.last().unwrap_or(&Ctx::Plain))),
            Tok::Ident(w) => Token::Name(w),
            Tok::Punct(c) => match c {
                '(' => Token::Op(Op::Open),
                ')' => Token::Op(Op::Close),
                ',' => Token::Op(Op::Comma),
                '+' => Token::Op(Op::Add),
                '-' => Token::Op(Op::Sub),
                '*' => Token::Op(Op::Mul),
                '/' => Token::Op(Op::Div),
                '^' => Token::Op(Op::Pow),
                _ => Token::Other,
            },
            _ => Token::Other,
        };
        (tok, t.span)
    }

    fn bump(&mut self) {
        self.p.bump();
    }

    fn describe(&self) -> String {
        self.p.peek().tok.to_string()
    }

    fn enter(&mut self, at: Span) -> Result<(), ParseError> {
        self.p.enter(at)
    }

    fn leave(&mut self) {
        self.p.leave();
    }

    fn name(&mut self, name: &'a str, at: Span) -> Result<Parsed, ParseError> {
        if self.p.coords {
            if let Some(axis) = ["x", "y", "z"].iter().position(|c| *c == name) {
                return Ok(Parsed::leaf(Expr::Coord(axis as u8)));
            }
        }
        if let Some(&i) = self.p.param_index.get(name) {
            return Ok(Parsed::leaf(Expr::Param(i)));
        }
        if let Some(d) = self.p.defines.get(name) {
            let e = d.expr.clone();
            if e.nodes > self.p.subst_budget {
                return Err(err(at, "@define substitution too large"));
            }
            self.p.subst_budget -= e.nodes;
            return Ok(e);
        }
        Err(err(at, format!("unknown name `{name}`")))
    }

    fn rand_site(&mut self, at: Span) -> Result<u32, ParseError> {
        self.p.next_site(at)
    }

    fn begin_args(&mut self) {
        self.ctx.push(Ctx::Plain);
    }

    fn end_args(&mut self) {
        self.ctx.pop();
    }
}

fn is_const(e: &Expr) -> bool {
    match e {
        Expr::Num(_) => true,
        Expr::Param(_) | Expr::Rand(_) | Expr::Coord(_) => false,
        Expr::Neg(a) => is_const(a),
        Expr::Binary(_, a, b) => is_const(a) && is_const(b),
        Expr::Func(_, args) => args.iter().all(is_const),
    }
}

impl<'a> Parser<'a> {
    /// A constant argument (no `@param` or `rand()`) for `what`, evaluated.
    pub(super) fn const_value(&mut self, what: &str) -> PResult<(f64, Span)> {
        let span = self.peek().span;
        let e = self.arg(Ctx::Plain, What::Text(what))?;
        if !is_const(&e.expr) {
            return Err(err(span, format!("{what} must be a constant (no @param or rand())")));
        }
        let v = e.expr.eval(&mut NaNEnv);
        if !v.is_finite() {
            return Err(err(span, format!("{what} is not a finite number")));
        }
        Ok((v, span))
    }

    /// A constant whole number in `0..=max` for `what`.
    pub(super) fn whole_value(&mut self, what: &str, max: f64) -> PResult<f64> {
        let (v, span) = self.const_value(what)?;
        if v < 0.0 || v.fract() != 0.0 || v > max {
            return Err(err(span, format!("{what} must be a whole number ≥ 0, found {v}")));
        }
        Ok(v)
    }

    /// Whether `name` is a `@define` or a `@param`.
    pub(super) fn is_value_name(&self, name: &str) -> bool {
        self.defines.contains_key(name) || self.param_index.contains_key(name)
    }

    /// Whether the next token can start an (optional) argument.
    pub(super) fn starts_arg(&self) -> bool {
        match self.peek().tok {
            Tok::Num { .. } | Tok::Punct('(') | Tok::Punct('-') => true,
            Tok::Ident(w) => {
                !self.is_adjust_word(w)
                    && (self.is_value_name(w) || (w == "rand" || Func::from_name(w).is_some()) && self.peek2().tok == Tok::Punct('('))
            }
            _ => false,
        }
    }

    /// An argument, if one follows.
    pub(super) fn opt_arg(&mut self, ctx: Ctx, what: What) -> PResult<Option<E>> {
        if self.starts_arg() {
            Ok(Some(self.arg(ctx, what)?))
        } else {
            Ok(None)
        }
    }

    fn angle_factor(&self) -> f64 {
        match self.mode {
            AngleMode::Degrees => PI / 180.0,
            AngleMode::Radians => 1.0,
            AngleMode::Orbits => 2.0 * PI,
        }
    }

    /// An angle argument, converted to radians.
    pub(super) fn angle_arg(&mut self, word: &str) -> PResult<E> {
        let span = self.peek().span;
        let a = self.arg(Ctx::Angle, What::After(word))?;
        let f = self.angle_factor();
        if f == 1.0 {
            return Ok(a);
        }
        grammar::combine(BinOp::Mul, a, num(f), span)
    }

    /// An argument outside parentheses: `-`* then a primary (no binary operators).
    pub(super) fn arg(&mut self, ctx: Ctx, what: What) -> PResult<E> {
        let t = self.peek();
        match t.tok {
            Tok::Punct('-') => {
                self.bump();
                self.enter(t.span)?;
                let inner = self.arg(ctx, what)?;
                self.leave();
                grammar::negate(inner, t.span)
            }
            Tok::Num { .. } | Tok::Punct('(') => self.primary(ctx),
            Tok::Ident(w) if !self.is_adjust_word(w) || self.is_value_name(w) => self.primary(ctx),
            other => Err(err(t.span, format!("expected a number {what}, found {other}"))),
        }
    }

    /// A full expression (inside parentheses or a `@define` value).
    pub(super) fn expr(&mut self, ctx: Ctx) -> PResult<E> {
        grammar::expression(&mut MdgHost { p: self, ctx: vec![ctx] })
    }

    fn primary(&mut self, ctx: Ctx) -> PResult<E> {
        grammar::primary(&mut MdgHost { p: self, ctx: vec![ctx] })
    }

    fn literal(&self, value: f64, suffix: Option<char>, ctx: Ctx) -> f64 {
        let radians = match suffix {
            None => return value,
            Some('d') if ctx == Ctx::Angle && self.mode == AngleMode::Degrees => return value,
            Some('d') => value.to_radians(),
            Some(_) => value.atan(),
        };
        match ctx {
            Ctx::Plain => radians,
            Ctx::Angle => radians / self.angle_factor(),
        }
    }
}
