//! Expressions in module arguments, conditions, probabilities, settings and
//! `#define` bodies: a small lexer and a recursive-descent parser, one level
//! per precedence: `||` (or `|`), `&&` (or `&`), comparisons (`<`, `<=`, `>`,
//! `>=`, `==` or `=`, `!=`), `+ -`, `* /`, unary `- + !`, then `^`. Names are
//! the production's parameters, `#define`s (each use gets fresh `rand()`
//! sites) and `pi`; calls are `rand()`, `ran(x)` and the shared functions.
//! Nesting is bounded by [`MAX_EXPR_DEPTH`].

use super::statements::{is_ident, is_ident_start, span_of, text_of};
use super::{err, Chars, Parser};
use crate::lang::expr::{BinOp, Expr, Func};
use crate::core::{ParseError, Span};
use std::collections::HashMap;

/// Deepest expression nesting accepted (keeps evaluation recursion bounded).
const MAX_EXPR_DEPTH: u32 = 64;

impl Parser {
    /// Parses `s` as one expression whose names are `formals` (the matched
    /// production's parameters) or `#define`s; `at` locates an empty `s`.
    pub(super) fn expr(&mut self, s: &Chars, formals: &[String], at: Span) -> Result<Expr, ParseError> {
        let toks = lex_expr(s)?;
        let mut ep = ExprParser { toks: &toks, pos: 0, formals, defines: &self.defines, sites: &mut self.sys.site_count, end: span_of(s, at) };
        let e = ep.or(0)?;
        if let Some(t) = toks.get(ep.pos) {
            return err(t.span, format!("unexpected `{}` in an expression", t.text));
        }
        Ok(e)
    }
}

/// The kind of an expression token.
#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Num(f64),
    Ident(String),
    Op,
}

/// An expression token with its text and position.
#[derive(Debug, Clone)]
struct Tok {
    kind: Kind,
    text: String,
    span: Span,
}

/// Splits an expression into tokens.
fn lex_expr(s: &Chars) -> Result<Vec<Tok>, ParseError> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < s.len() {
        let (c, at) = s[i];
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c.is_ascii_digit() || (c == '.' && s.get(i + 1).is_some_and(|d| d.0.is_ascii_digit())) {
            let start = i;
            while i < s.len() && (s[i].0.is_ascii_digit() || s[i].0 == '.') {
                i += 1;
            }
            if i < s.len() && (s[i].0 == 'e' || s[i].0 == 'E') {
                let mut j = i + 1;
                if j < s.len() && (s[j].0 == '+' || s[j].0 == '-') {
                    j += 1;
                }
                if j < s.len() && s[j].0.is_ascii_digit() {
                    i = j;
                    while i < s.len() && s[i].0.is_ascii_digit() {
                        i += 1;
                    }
                }
            }
            let text = text_of(&s[start..i]);
            let v: f64 = text.parse().map_err(|_| ParseError::single(at, format!("bad number `{text}`")))?;
            out.push(Tok { kind: Kind::Num(v), text, span: at });
            continue;
        }
        if is_ident_start(c) {
            let start = i;
            while i < s.len() && is_ident(s[i].0) {
                i += 1;
            }
            let text = text_of(&s[start..i]);
            out.push(Tok { kind: Kind::Ident(text.clone()), text, span: at });
            continue;
        }
        let two: String = s[i..].iter().take(2).map(|c| c.0).collect();
        let text = if ["<=", ">=", "==", "!=", "&&", "||"].contains(&two.as_str()) {
            two
        } else if "+-*/^()<>=!&|,".contains(c) {
            c.to_string()
        } else {
            return err(at, format!("unexpected `{c}` in an expression"));
        };
        i += text.chars().count();
        out.push(Tok { kind: Kind::Op, text, span: at });
    }
    Ok(out)
}

/// A parser over one expression's tokens.
struct ExprParser<'a> {
    toks: &'a [Tok],
    pos: usize,
    formals: &'a [String],
    defines: &'a HashMap<String, Expr>,
    sites: &'a mut u32,
    end: Span,
}

/// `a op b` as an expression.
fn bin(op: BinOp, a: Expr, b: Expr) -> Expr {
    Expr::Binary(op, Box::new(a), Box::new(b))
}

impl ExprParser<'_> {
    fn peek_op(&self) -> Option<&str> {
        match self.toks.get(self.pos) {
            Some(Tok { kind: Kind::Op, text, .. }) => Some(text.as_str()),
            _ => None,
        }
    }

    fn here(&self) -> Span {
        self.toks.get(self.pos).map_or(self.end, |t| t.span)
    }

    fn check_depth(&self, depth: u32) -> Result<(), ParseError> {
        if depth > MAX_EXPR_DEPTH {
            return err(self.here(), format!("expression nested more than {MAX_EXPR_DEPTH} deep"));
        }
        Ok(())
    }

    fn binary_level(
        &mut self,
        depth: u32,
        ops: &[(&str, BinOp)],
        next: fn(&mut Self, u32) -> Result<Expr, ParseError>,
    ) -> Result<Expr, ParseError> {
        self.check_depth(depth)?;
        let mut a = next(self, depth + 1)?;
        while let Some(op) = self.peek_op().and_then(|t| ops.iter().find(|(s, _)| *s == t).map(|o| o.1)) {
            self.pos += 1;
            let b = next(self, depth + 1)?;
            a = bin(op, a, b);
        }
        Ok(a)
    }

    fn or(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.binary_level(depth, &[("||", BinOp::Or), ("|", BinOp::Or)], Self::and)
    }

    fn and(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.binary_level(depth, &[("&&", BinOp::And), ("&", BinOp::And)], Self::cmp)
    }

    fn cmp(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.binary_level(
            depth,
            &[
                ("<", BinOp::Lt),
                ("<=", BinOp::Le),
                (">", BinOp::Gt),
                (">=", BinOp::Ge),
                ("==", BinOp::Eq),
                ("=", BinOp::Eq),
                ("!=", BinOp::Ne),
            ],
            Self::add,
        )
    }

    fn add(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.binary_level(depth, &[("+", BinOp::Add), ("-", BinOp::Sub)], Self::mul)
    }

    fn mul(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.binary_level(depth, &[("*", BinOp::Mul), ("/", BinOp::Div)], Self::unary)
    }

    fn unary(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.check_depth(depth)?;
        match self.peek_op() {
            Some("-") => {
                self.pos += 1;
                Ok(Expr::Neg(Box::new(self.unary(depth + 1)?)))
            }
            Some("+") => {
                self.pos += 1;
                self.unary(depth + 1)
            }
            Some("!") => {
                self.pos += 1;
                Ok(bin(BinOp::Eq, self.unary(depth + 1)?, Expr::Num(0.0)))
            }
            _ => self.power(depth + 1),
        }
    }

    fn power(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.check_depth(depth)?;
        let base = self.primary(depth + 1)?;
        if self.peek_op() == Some("^") {
            self.pos += 1;
            let exp = self.unary(depth + 1)?;
            return Ok(bin(BinOp::Pow, base, exp));
        }
        Ok(base)
    }

    fn expect(&mut self, op: &str) -> Result<(), ParseError> {
        if self.peek_op() == Some(op) {
            self.pos += 1;
            Ok(())
        } else {
            err(self.here(), format!("expected `{op}`"))
        }
    }

    fn new_site(&mut self) -> u32 {
        let s = *self.sites;
        *self.sites = self.sites.saturating_add(1);
        s
    }

    /// A copy of a `#define` body whose `rand()` sites are fresh, so each use draws its own numbers.
    fn renumber(&mut self, e: &Expr) -> Expr {
        // Defines are bounded in depth by MAX_EXPR_DEPTH (each was parsed under it).
        match e {
            Expr::Rand(_) => Expr::Rand(self.new_site()),
            Expr::Neg(a) => Expr::Neg(Box::new(self.renumber(a))),
            Expr::Binary(op, a, b) => {
                let a = self.renumber(a);
                bin(*op, a, self.renumber(b))
            }
            Expr::Func(f, args) => Expr::Func(*f, args.iter().map(|a| self.renumber(a)).collect()),
            other => other.clone(),
        }
    }

    fn primary(&mut self, depth: u32) -> Result<Expr, ParseError> {
        self.check_depth(depth)?;
        let Some(t) = self.toks.get(self.pos).cloned() else { return err(self.end, "expression ends too early") };
        self.pos += 1;
        match t.kind {
            Kind::Num(v) => Ok(Expr::Num(v)),
            Kind::Op if t.text == "(" => {
                let e = self.or(depth + 1)?;
                self.expect(")")?;
                Ok(e)
            }
            Kind::Op => err(t.span, format!("unexpected `{}` in an expression", t.text)),
            Kind::Ident(name) => {
                if self.peek_op() == Some("(") {
                    self.pos += 1;
                    let mut args = Vec::new();
                    if self.peek_op() != Some(")") {
                        loop {
                            args.push(self.or(depth + 1)?);
                            if self.peek_op() == Some(",") {
                                self.pos += 1;
                            } else {
                                break;
                            }
                        }
                    }
                    self.expect(")")?;
                    return self.call(&name, args, t.span);
                }
                if let Some(i) = self.formals.iter().position(|f| *f == name) {
                    return Ok(Expr::Param(i as u32));
                }
                if let Some(e) = self.defines.get(&name) {
                    let e = e.clone();
                    return Ok(self.renumber(&e));
                }
                match name.as_str() {
                    "pi" | "PI" => Ok(Expr::Num(std::f64::consts::PI)),
                    _ => err(t.span, format!("unknown name `{name}` (not a parameter or #define)")),
                }
            }
        }
    }

    fn call(&mut self, name: &str, args: Vec<Expr>, at: Span) -> Result<Expr, ParseError> {
        match name {
            "rand" if args.is_empty() => Ok(Expr::Rand(self.new_site())),
            "ran" if args.len() == 1 => {
                let site = self.new_site();
                let mut args = args;
                Ok(bin(BinOp::Mul, args.remove(0), Expr::Rand(site)))
            }
            "rand" | "ran" => err(at, format!("`{name}` takes {} argument(s)", if name == "rand" { 0 } else { 1 })),
            _ => {
                let Some(f) = Func::from_name(name) else { return err(at, format!("unknown function `{name}`")) };
                let (lo, hi) = f.arity();
                if args.len() < lo || hi.is_some_and(|h| args.len() > h) {
                    return err(at, format!("`{name}` takes {lo}{} argument(s), got {}", hi.map_or("+".to_string(), |h| if h == lo { String::new() } else { format!("..{h}") }), args.len()));
                }
                Ok(Expr::Func(f, args))
            }
        }
    }
}
