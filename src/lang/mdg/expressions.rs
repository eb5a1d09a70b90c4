//! Numbers and expressions: call and adjustment arguments, `@define`
//! values, function bodies, and the constant values directives require.
//!
//! An argument outside parentheses is a primary (a number, a name, a
//! function call or a parenthesised expression) after any `-` signs, so
//! `x 1 -2` reads as two arguments; inside parentheses the full grammar
//! `+ - * / ^` applies. Every tree is built with its depth and node count,
//! so depth stays under [`MAX_NESTING`] and `@define` substitution under the
//! parser's copy budget.

use super::{err, PResult, Parser, MAX_NESTING};
use crate::lang::expr::{BinOp, Expr, ExprEnv, Func};
use crate::lang::ir::AngleMode;
use crate::lang::mdg::lexer::Tok;
use crate::core::Span;
use std::f64::consts::PI;

/// An expression with its tree depth and node count.
#[derive(Clone)]
pub(super) struct E {
    /// The expression.
    pub(super) e: Expr,
    depth: u32,
    nodes: usize,
}

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
    E { e: Expr::Num(v), depth: 1, nodes: 1 }
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
        if !is_const(&e.e) {
            return Err(err(span, format!("{what} must be a constant (no @param or rand())")));
        }
        let v = e.e.eval(&mut NaNEnv);
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
        self.bin(BinOp::Mul, a, num(f), span)
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
                self.neg(inner, t.span)
            }
            Tok::Num { .. } | Tok::Punct('(') => self.primary(ctx),
            Tok::Ident(w) if !self.is_adjust_word(w) || self.is_value_name(w) => self.primary(ctx),
            other => Err(err(t.span, format!("expected a number {what}, found {other}"))),
        }
    }

    fn neg(&self, a: E, span: Span) -> PResult<E> {
        if let Expr::Num(v) = a.e {
            return Ok(num(-v));
        }
        let depth = a.depth + 1;
        if depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        Ok(E { e: Expr::Neg(Box::new(a.e)), depth, nodes: a.nodes + 1 })
    }

    fn bin(&self, op: BinOp, a: E, b: E, span: Span) -> PResult<E> {
        let depth = a.depth.max(b.depth) + 1;
        if depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        Ok(E { e: Expr::Binary(op, Box::new(a.e), Box::new(b.e)), depth, nodes: a.nodes + b.nodes + 1 })
    }

    /// A full expression (inside parentheses or a `@define` value).
    pub(super) fn expr(&mut self, ctx: Ctx) -> PResult<E> {
        let mut lhs = self.term(ctx)?;
        loop {
            let t = self.peek();
            let op = match t.tok {
                Tok::Punct('+') => BinOp::Add,
                Tok::Punct('-') => BinOp::Sub,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = self.term(ctx)?;
            lhs = self.bin(op, lhs, rhs, t.span)?;
        }
    }

    fn term(&mut self, ctx: Ctx) -> PResult<E> {
        let mut lhs = self.unary(ctx)?;
        loop {
            let t = self.peek();
            let op = match t.tok {
                Tok::Punct('*') => BinOp::Mul,
                Tok::Punct('/') => BinOp::Div,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = self.unary(ctx)?;
            lhs = self.bin(op, lhs, rhs, t.span)?;
        }
    }

    fn unary(&mut self, ctx: Ctx) -> PResult<E> {
        let t = self.peek();
        if t.tok == Tok::Punct('-') {
            self.bump();
            self.enter(t.span)?;
            let inner = self.unary(ctx)?;
            self.leave();
            return self.neg(inner, t.span);
        }
        let base = self.primary(ctx)?;
        let t = self.peek();
        if t.tok == Tok::Punct('^') {
            self.bump();
            self.enter(t.span)?;
            let exp = self.unary(ctx)?;
            self.leave();
            return self.bin(BinOp::Pow, base, exp, t.span);
        }
        Ok(base)
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

    fn primary(&mut self, ctx: Ctx) -> PResult<E> {
        let t = self.bump();
        match t.tok {
            Tok::Num { value, suffix, .. } => Ok(num(self.literal(value, suffix, ctx))),
            Tok::Punct('(') => {
                self.enter(t.span)?;
                let e = self.expr(ctx)?;
                self.leave();
                self.expect_punct(')', || "to close `(`".to_string())?;
                Ok(e)
            }
            Tok::Ident(name) => {
                if self.is_punct('(') {
                    return self.func_call(name, t.span, ctx);
                }
                if self.coords {
                    if let Some(axis) = ["x", "y", "z"].iter().position(|c| *c == name) {
                        return Ok(E { e: Expr::Coord(axis as u8), depth: 1, nodes: 1 });
                    }
                }
                if let Some(&i) = self.param_index.get(name) {
                    return Ok(E { e: Expr::Param(i), depth: 1, nodes: 1 });
                }
                if let Some(d) = self.defines.get(name) {
                    let e = d.expr.clone();
                    if e.nodes > self.subst_budget {
                        return Err(err(t.span, "@define substitution too large"));
                    }
                    self.subst_budget -= e.nodes;
                    return Ok(e);
                }
                Err(err(t.span, format!("unknown name `{name}`")))
            }
            other => Err(err(t.span, format!("expected a number, found {other}"))),
        }
    }

    fn func_call(&mut self, name: &'a str, span: Span, ctx: Ctx) -> PResult<E> {
        self.bump(); // `(`
        self.enter(span)?;
        let mut args: Vec<E> = Vec::new();
        if !self.is_punct(')') {
            loop {
                // Function arguments are plain numbers: trig works in radians.
                let _ = ctx;
                args.push(self.expr(Ctx::Plain)?);
                if self.is_punct(',') {
                    self.bump();
                    continue;
                }
                break;
            }
        }
        self.expect_punct(')', || format!("to close the arguments of `{name}`"))?;
        self.leave();
        if name == "rand" {
            if !args.is_empty() {
                return Err(err(span, format!("`rand` takes no arguments, {} given", args.len())));
            }
            let site = self.next_site(span)?;
            return Ok(E { e: Expr::Rand(site), depth: 1, nodes: 1 });
        }
        let f = Func::from_name(name).ok_or_else(|| err(span, format!("unknown function `{name}`")))?;
        let (lo, hi) = f.arity();
        if args.len() < lo || hi.is_some_and(|h| args.len() > h) {
            let want = match hi {
                Some(h) if h == lo => format!("{lo}"),
                Some(h) => format!("{lo} to {h}"),
                None => format!("at least {lo}"),
            };
            return Err(err(span, format!("`{name}` takes {want} argument(s), {} given", args.len())));
        }
        let depth = args.iter().map(|a| a.depth).max().unwrap_or(0) + 1;
        if depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        let nodes = args.iter().map(|a| a.nodes).sum::<usize>() + 1;
        Ok(E { e: Expr::Func(f, args.into_iter().map(|a| a.e).collect()), depth, nodes })
    }
}
