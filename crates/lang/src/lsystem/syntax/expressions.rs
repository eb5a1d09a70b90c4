//! Expressions in module arguments, conditions, probabilities, settings and
//! `#define` bodies. The grammar is the shared one
//! (`crate::expr::grammar`); this module is the L-system's lexer and
//! [`Host`] for it: `|` and `=` also spell `||` and `==`, `&` spells `&&`;
//! names are the production's parameters, `#define`s (each use gets fresh
//! `rand()` sites) and `pi`; `ran(x)` is `x * rand()`.

use super::statements::{is_ident, is_ident_start, span_of, text_of};
use super::{err, Chars, Parser};
use crate::core::{ParseError, Span};
use crate::expr::grammar::{self, Host, Op, Parsed, Token, MAX_NESTING};
use crate::expr::{BinOp, Expr};
use std::collections::HashMap;

impl Parser {
    /// Parses `s` as one expression whose names are `formals` (the matched
    /// production's parameters) or `#define`s; `at` locates an empty `s`.
    pub(super) fn expr(&mut self, s: &Chars, formals: &[String], at: Span) -> Result<Expr, ParseError> {
        let toks = lex_expr(s)?;
        let mut h = LsysHost { toks: &toks, pos: 0, formals, defines: &self.defines, sites: &mut self.sys.site_count, end: span_of(s, at), nesting: 0 };
        let e = grammar::expression(&mut h)?;
        if let Some(t) = toks.get(h.pos) {
            return err(t.span, format!("unexpected `{}` in an expression", t.text));
        }
        Ok(e.expr)
    }
}

/// The kind of an expression token.
#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Num(f64),
    Ident(String),
    Op(Op),
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
        let (op, text) = match operator(&two) {
            Some(op) => (op, two),
            None => match operator(&c.to_string()) {
                Some(op) => (op, c.to_string()),
                None => return err(at, format!("unexpected `{c}` in an expression")),
            },
        };
        i += text.chars().count();
        out.push(Tok { kind: Kind::Op(op), text, span: at });
    }
    Ok(out)
}

/// The operator `text` spells, if any.
fn operator(text: &str) -> Option<Op> {
    Some(match text {
        "||" | "|" => Op::Or,
        "&&" | "&" => Op::And,
        "<" => Op::Lt,
        "<=" => Op::Le,
        ">" => Op::Gt,
        ">=" => Op::Ge,
        "==" | "=" => Op::Eq,
        "!=" => Op::Ne,
        "+" => Op::Add,
        "-" => Op::Sub,
        "*" => Op::Mul,
        "/" => Op::Div,
        "^" => Op::Pow,
        "!" => Op::Not,
        "(" => Op::Open,
        ")" => Op::Close,
        "," => Op::Comma,
        _ => return None,
    })
}

/// One expression's tokens as the shared grammar's host.
struct LsysHost<'a> {
    toks: &'a [Tok],
    pos: usize,
    formals: &'a [String],
    defines: &'a HashMap<String, Expr>,
    sites: &'a mut u32,
    /// Where the expression ends (locates errors at its end).
    end: Span,
    nesting: u32,
}

impl LsysHost<'_> {
    fn new_site(&mut self) -> u32 {
        let s = *self.sites;
        *self.sites = self.sites.saturating_add(1);
        s
    }

    /// A copy of a `#define` body whose `rand()` sites are fresh, so each use draws its own numbers.
    fn renumber(&mut self, e: &Expr) -> Expr {
        // Defines are bounded in depth by MAX_NESTING (each was parsed under it).
        match e {
            Expr::Rand(_) => Expr::Rand(self.new_site()),
            Expr::Neg(a) => Expr::Neg(Box::new(self.renumber(a))),
            Expr::Binary(op, a, b) => {
                let a = self.renumber(a);
                Expr::Binary(*op, Box::new(a), Box::new(self.renumber(b)))
            }
            Expr::Func(f, args) => Expr::Func(*f, args.iter().map(|a| self.renumber(a)).collect()),
            other => other.clone(),
        }
    }
}

impl<'a> Host<'a> for LsysHost<'a> {
    fn peek(&self) -> (Token<'a>, Span) {
        let toks: &'a [Tok] = self.toks;
        match toks.get(self.pos) {
            None => (Token::Other, self.end),
            Some(t) => {
                let tok = match &t.kind {
                    Kind::Num(v) => Token::Num(*v),
                    Kind::Ident(name) => Token::Name(name.as_str()),
                    Kind::Op(op) => Token::Op(*op),
                };
                (tok, t.span)
            }
        }
    }

    fn bump(&mut self) {
        self.pos += 1;
    }

    fn describe(&self) -> String {
        self.toks.get(self.pos).map_or_else(|| "the end of the expression".to_string(), |t| format!("`{}`", t.text))
    }

    fn enter(&mut self, at: Span) -> Result<(), ParseError> {
        self.nesting += 1;
        if self.nesting > MAX_NESTING {
            return err(at, format!("nesting deeper than {MAX_NESTING}"));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.nesting = self.nesting.saturating_sub(1);
    }

    fn name(&mut self, name: &'a str, at: Span) -> Result<Parsed, ParseError> {
        if let Some(i) = self.formals.iter().position(|f| f == name) {
            return Ok(Parsed::leaf(Expr::Param(i as u32)));
        }
        if let Some(e) = self.defines.get(name) {
            let e = self.renumber(e);
            return Ok(Parsed::measure(e));
        }
        match name {
            "pi" | "PI" => Ok(Parsed::leaf(Expr::Num(std::f64::consts::PI))),
            _ => err(at, format!("unknown name `{name}` (not a parameter or #define)")),
        }
    }

    fn rand_site(&mut self, _at: Span) -> Result<u32, ParseError> {
        Ok(self.new_site())
    }

    fn own_call(&mut self, name: &str, args: &mut Vec<Parsed>, at: Span) -> Option<Result<Parsed, ParseError>> {
        if name != "ran" {
            return None;
        }
        if args.len() != 1 {
            return Some(err(at, format!("`ran` takes 1 argument(s), {} given", args.len())));
        }
        let site = self.new_site();
        let x = args.remove(0);
        Some(grammar::combine(BinOp::Mul, x, Parsed::leaf(Expr::Rand(site)), at))
    }
}
