//! Expressions (`exp`, `exp2`, `exp3`, `expfunc`, `arglist` in `cfdg.ypp`,
//! Context Free 3.4): adjustment arguments, full expressions by precedence
//! climbing, calls and parameter lists. Split from `parser.rs` to keep it
//! small.

use super::super::Expr;
use super::{path, term_kind, Parser, Tok, REUSE};
use crate::ParseError;

impl Parser<'_> {
    pub(super) fn starts_exp(&self) -> bool {
        match self.peek() {
            Tok::Num(_) | Tok::Punct("(") | Tok::Punct("-") | Tok::Punct("+") => true,
            Tok::Word(w) => term_kind(w).is_none() && !(self.path.terms && path::is_path_term(w)),
            _ => false,
        }
    }

    /// An adjustment argument (`exp` in cfdg.ypp): numbers, parenthesised
    /// expressions, calls, variables, unary signs, `..` and `+/-`.
    pub(super) fn exp(&mut self) -> Result<Expr, ParseError> {
        self.enter()?;
        let mut left = self.exp_atom()?;
        while self.is_punct("..") || self.is_punct("+/-") {
            let op = if self.is_punct("..") { "rand." } else { "rand+/-" };
            let span = self.span();
            self.bump();
            let right = self.exp_atom()?;
            left = Expr::Call(op.into(), Box::new(Some(Expr::Cons(vec![left, right]))), span);
        }
        self.depth -= 1;
        Ok(left)
    }

    pub(super) fn exp_atom(&mut self) -> Result<Expr, ParseError> {
        self.enter()?;
        let e = match self.peek().clone() {
            Tok::Punct("-") => {
                self.bump();
                Expr::Unary('N', Box::new(self.exp_atom()?))
            }
            Tok::Punct("+") => {
                self.bump();
                Expr::Unary('P', Box::new(self.exp_atom()?))
            }
            _ => self.primary()?,
        };
        self.depth -= 1;
        Ok(e)
    }

    pub(super) fn primary(&mut self) -> Result<Expr, ParseError> {
        let span = self.span();
        match self.peek().clone() {
            Tok::Num(n) => {
                self.bump();
                let pct = n.ends_with('%');
                let v: f64 = n.trim_end_matches('%').parse().unwrap_or(0.0);
                Ok(Expr::Num(if pct { v / 100.0 } else { v }, n))
            }
            Tok::Punct("(") => {
                self.bump();
                let e = self.expr(0)?;
                self.expect(")")?;
                Ok(Expr::Paren(Box::new(e)))
            }
            // An adjustment inside an expression (`exp3`'s `modification`).
            Tok::Punct("[") if self.v3() => Ok(Expr::Adjust(Box::new(self.adjustment()?), span)),
            Tok::Word(w) if w == "let" && matches!(self.peek_at(1), Tok::Punct("(")) => {
                self.bump();
                self.let_expr(span)
            }
            Tok::Word(w) if term_kind(&w).is_none() => {
                self.bump();
                if self.index_follows(&w, span) {
                    self.index_expr(w, span)
                } else if self.is_punct("(") {
                    let args = self.call_args(&w)?;
                    if w == "rand_static" {
                        self.rand_static.push(span);
                    }
                    Ok(Expr::Call(w, Box::new(args), span))
                } else {
                    Ok(Expr::Var(w, span))
                }
            }
            _ => self.err("expected a number, a name or `(`"),
        }
    }

    /// `( a, b, … )` after a function or shape name: each argument held in
    /// parentheses and the list always a list, as cfdg's arglist builds it
    /// (its entropy shows it); `rand()` and `rand(x)` get cfdg's textless bounds.
    pub(super) fn call_args(&mut self, name: &str) -> Result<Option<Expr>, ParseError> {
        self.expect("(")?;
        // `NAME(=)`: the parent's parameters, reused (cfdg's SimpleParentArgs).
        if self.is_punct("=") && matches!(self.peek_at(1), Tok::Punct(")")) {
            self.bump();
            self.bump();
            return Ok(Some(Expr::Var(REUSE.into(), self.span())));
        }
        // `if` is a keyword whose parentheses hold a bare list (`IF '(' exp2 ')'`).
        if name == "if" {
            let e = if self.is_punct(")") { None } else { Some(self.expr(0)?) };
            self.expect(")")?;
            return Ok(e);
        }
        let mut items = Vec::new();
        while !self.is_punct(")") {
            items.push(Expr::Paren(Box::new(self.expr(1)?)));
            if !self.is_punct(",") {
                break;
            }
            self.bump();
        }
        self.expect(")")?;
        let zero = || Expr::Num(0.0, String::new());
        Ok(match (name, items.len()) {
            ("rand" | "rand_static" | "randint", 0) => Some(Expr::Cons(vec![zero(), Expr::Num(if name == "randint" { 2.0 } else { 1.0 }, String::new())])),
            // One argument may be a pair (`rand(range)` with `range = -60, 60`):
            // the evaluator supplies the lower bound 0 only to a single number.
            // The text hashed is the same either way (cfdg's wrapping list
            // is flattened: a textless 0, the argument, the list's bytes).
            (_, 0) => None,
            _ => Some(Expr::Cons(items)),
        })
    }

    /// `(number a, vector2 b, …)` after `shape NAME` or `path NAME`: the
    /// names, the types kept in `last_params` ([`super::func`]).
    pub(super) fn param_list(&mut self) -> Result<Vec<String>, ParseError> {
        let params = self.typed_params()?;
        let names = params.iter().map(|p| p.name.clone()).collect();
        self.last_params = params;
        Ok(names)
    }

    /// A full expression (`exp2`/`exp3`) by precedence climbing; `,` makes a list.
    pub(super) fn expr(&mut self, min: u8) -> Result<Expr, ParseError> {
        self.enter()?;
        let mut left = match self.peek().clone() {
            Tok::Punct("-") => {
                self.bump();
                Expr::Unary('N', Box::new(self.expr(8)?))
            }
            Tok::Punct("+") => {
                self.bump();
                Expr::Unary('P', Box::new(self.expr(8)?))
            }
            Tok::Punct("!") => {
                self.bump();
                Expr::Unary('!', Box::new(self.expr(8)?))
            }
            _ => self.primary()?,
        };
        loop {
            let (op, prec, right_assoc): (char, u8, bool) = match self.peek() {
                Tok::Punct(",") => (',', 0, true),
                Tok::Punct("^^") => ('X', 1, false),
                Tok::Punct("||") => ('|', 2, false),
                Tok::Punct("&&") => ('&', 3, false),
                Tok::Punct("==") => ('=', 4, false),
                Tok::Punct("<>") | Tok::Punct("!=") => ('n', 4, false),
                Tok::Punct("<") => ('<', 5, false),
                Tok::Punct("<=") => ('L', 5, false),
                Tok::Punct(">") => ('>', 5, false),
                Tok::Punct(">=") => ('G', 5, false),
                Tok::Punct("..") => ('.', 6, false),
                Tok::Punct("+/-") => ('~', 6, false),
                Tok::Punct("+") => ('+', 7, false),
                Tok::Punct("-") => ('-', 7, false),
                Tok::Punct("--") => ('_', 7, false),
                Tok::Punct("*") => ('*', 8, false),
                Tok::Punct("/") => ('/', 8, false),
                Tok::Punct("^") => ('^', 10, true),
                _ => break,
            };
            if prec < min {
                break;
            }
            let span = self.span();
            self.bump();
            let right = self.expr(if right_assoc { prec } else { prec + 1 })?;
            left = match op {
                ',' => match left {
                    Expr::Cons(mut v) => {
                        match right {
                            Expr::Cons(w) => v.extend(w),
                            r => v.push(r),
                        }
                        Expr::Cons(v)
                    }
                    l => match right {
                        Expr::Cons(mut w) => {
                            w.insert(0, l);
                            Expr::Cons(w)
                        }
                        r => Expr::Cons(vec![l, r]),
                    },
                },
                '.' => Expr::Call("rand.".into(), Box::new(Some(Expr::Cons(vec![left, right]))), span),
                '~' => Expr::Call("rand+/-".into(), Box::new(Some(Expr::Cons(vec![left, right]))), span),
                op => Expr::Binary(op, Box::new(left), Box::new(right)),
            };
        }
        self.depth -= 1;
        Ok(left)
    }
}

/// The value of a constant case expression: numbers, signs, arithmetic,
/// parentheses and a few pure functions (kept here, below the evaluator).
pub(super) fn const_value(e: &Expr) -> Option<f64> {
    let v = match e {
        Expr::Num(v, _) => *v,
        Expr::Paren(a) => const_value(a)?,
        Expr::Unary('N', a) => -const_value(a)?,
        Expr::Unary('P', a) => const_value(a)?,
        Expr::Binary(op, a, b) => {
            let (x, y) = (const_value(a)?, const_value(b)?);
            match op {
                '+' => x + y,
                '-' => x - y,
                '*' => x * y,
                '/' => x / y,
                '^' => x.powf(y),
                _ => return None,
            }
        }
        Expr::Call(name, args, _) => {
            let items = args.as_ref().as_ref()?.items();
            let x = match items.as_slice() {
                [a] => const_value(a)?,
                _ => return None,
            };
            match name.as_str() {
                "abs" => x.abs(),
                "floor" => x.floor(),
                "ceiling" => x.ceil(),
                "sqrt" => x.sqrt(),
                _ => return None,
            }
        }
        _ => return None,
    };
    v.is_finite().then_some(v)
}
