//! The scanner over preprocessed text and the C-like part of cpfg's
//! language: expressions and the statements of `{ }` blocks
//! (`lsys_input.l`, the `EXPRESSION` start condition; `lsys_input.y`,
//! `Statement`, `Expression`).
//!
//! Line ends matter as in cpfg's lexer: a newline ends a production or a
//! header line, except inside `{ }` and when the next line starts with a
//! tab (`lsys_input.l`: `\n\t` only counts the line).

use super::preprocess::Preprocessed;
use super::{BinOp, Expr, Func, Stmt, Target, UnOp};
use crate::core::{ParseError, Span};

/// Deepest expression or block nesting accepted (the parser recurses).
pub(crate) const MAX_NESTING: u32 = 200;

/// Names in scope while parsing.
#[derive(Debug, Default)]
pub struct Names {
    /// Global variables.
    pub globals: Vec<String>,
    /// Global arrays.
    pub arrays: Vec<String>,
    /// The current production's formal parameters and locals.
    pub locals: Vec<String>,
    /// In a global block every assigned name is global.
    pub global_mode: bool,
}

impl Names {
    fn lookup(&mut self, name: &str) -> Expr {
        if !self.global_mode {
            if let Some(k) = self.locals.iter().position(|n| n == name) {
                return Expr::Local(k as u32);
            }
        }
        if let Some(k) = self.globals.iter().position(|n| n == name) {
            return Expr::Global(k as u32);
        }
        if self.global_mode {
            self.globals.push(name.to_string());
            return Expr::Global(self.globals.len() as u32 - 1);
        }
        self.locals.push(name.to_string());
        Expr::Local(self.locals.len() as u32 - 1)
    }
}

/// A cursor over the preprocessed text.
pub(crate) struct Cur<'a> {
    /// The characters.
    pub c: Vec<char>,
    /// Position.
    pub i: usize,
    line_starts: Vec<usize>,
    pp: &'a Preprocessed,
    /// `{ }` depth: newlines are blanks inside.
    pub braces: u32,
    depth: u32,
    /// Names in scope.
    pub names: Names,
}

/// A token of the expression scanner.
#[derive(Debug, Clone, PartialEq)]
pub enum Tok {
    /// A number.
    Num(f64),
    /// A name.
    Name(String),
    /// A string literal.
    Str,
    /// An operator or punctuation.
    Op(&'static str),
    /// End of line (outside braces) or of text.
    Eol,
}

const OPS: &[&str] = &["-->", "-o>", "&&", "||", "==", "!=", "<>", "<=", ">=", "=", "+", "-", "*", "/", "%", "^", ";", ",", "?", ":", "(", ")", "[", "]", "<", ">", "!", "{", "}", "&"];

impl<'a> Cur<'a> {
    /// A cursor at the start of `pp`'s text.
    pub fn new(pp: &'a Preprocessed) -> Cur<'a> {
        let c: Vec<char> = pp.text.chars().collect();
        let mut line_starts = vec![0];
        for (k, &ch) in c.iter().enumerate() {
            if ch == '\n' {
                line_starts.push(k + 1);
            }
        }
        Cur { c, i: 0, line_starts, pp, braces: 0, depth: 0, names: Names::default() }
    }

    /// The source position of index `i`.
    pub(crate) fn span_at(&self, i: usize) -> Span {
        let line = self.line_starts.partition_point(|&s| s <= i);
        let col = i - self.line_starts[line - 1] + 1;
        self.pp.span(line as u32, col as u32)
    }

    /// The source position of the cursor.
    pub fn span(&self) -> Span {
        self.span_at(self.i)
    }

    /// An error at the cursor (naming the included file it lies in).
    pub fn err<T>(&self, msg: impl Into<String>) -> Result<T, ParseError> {
        self.err_at(self.i, msg)
    }

    /// An error at index `i`.
    pub(crate) fn err_at<T>(&self, i: usize, msg: impl Into<String>) -> Result<T, ParseError> {
        let line = self.line_starts.partition_point(|&s| s <= i) as u32;
        let msg = msg.into();
        let msg = match self.pp.included_file(line) {
            Some(f) => format!("in {f}: {msg}"),
            None => msg,
        };
        Err(ParseError::single(self.span_at(i), msg))
    }

    /// The character at the cursor.
    pub fn peek(&self) -> Option<char> {
        self.c.get(self.i).copied()
    }

    /// True at text `s`.
    pub fn at(&self, s: &str) -> bool {
        s.chars().enumerate().all(|(k, ch)| self.c.get(self.i + k) == Some(&ch))
    }

    /// Skips blanks: spaces, tabs, `\r`, a newline followed by a tab, and
    /// inside braces every newline.
    pub(crate) fn blanks(&mut self) {
        while let Some(ch) = self.peek() {
            match ch {
                ' ' | '\t' | '\r' => self.i += 1,
                '\n' if self.braces > 0 || self.c.get(self.i + 1) == Some(&'\t') => self.i += 1,
                _ => break,
            }
        }
    }

    /// At a line end (or the end of the text) after blanks.
    pub(crate) fn at_eol(&mut self) -> bool {
        self.blanks();
        matches!(self.peek(), None | Some('\n'))
    }

    /// Skips to the start of the next line.
    pub(crate) fn next_line(&mut self) {
        while let Some(ch) = self.peek() {
            self.i += 1;
            if ch == '\n' && self.c.get(self.i) != Some(&'\t') {
                break;
            }
        }
    }

    /// Reads the next expression token without consuming it (returns its end).
    fn scan(&mut self) -> Result<(Tok, usize), ParseError> {
        self.blanks();
        // A stray `\` (left by a `\\` continuation) is no token: cpfg's
        // flex lexer echoes it and reads on.
        while self.peek() == Some('\\') {
            self.i += 1;
            self.blanks();
        }
        let s = self.i;
        let Some(ch) = self.peek() else { return Ok((Tok::Eol, s)) };
        if ch == '\n' {
            return Ok((Tok::Eol, s));
        }
        if ch.is_ascii_digit() || (ch == '.' && self.c.get(s + 1).is_some_and(char::is_ascii_digit)) {
            let mut e = s;
            while e < self.c.len() && (self.c[e].is_ascii_digit() || self.c[e] == '.') {
                e += 1;
            }
            if e < self.c.len() && matches!(self.c[e], 'e' | 'E') {
                let mut k = e + 1;
                if k < self.c.len() && matches!(self.c[k], '+' | '-') {
                    k += 1;
                }
                if k < self.c.len() && self.c[k].is_ascii_digit() {
                    e = k;
                    while e < self.c.len() && self.c[e].is_ascii_digit() {
                        e += 1;
                    }
                }
            }
            let text: String = self.c[s..e].iter().collect();
            return match text.parse::<f64>() {
                Ok(v) => Ok((Tok::Num(v), e)),
                Err(_) => self.err_at(s, format!("bad number `{text}`")),
            };
        }
        if ch.is_ascii_alphabetic() || ch == '_' {
            let mut e = s;
            while e < self.c.len() && (self.c[e].is_ascii_alphanumeric() || self.c[e] == '_') {
                e += 1;
            }
            return Ok((Tok::Name(self.c[s..e].iter().collect()), e));
        }
        if ch == '"' {
            let mut e = s + 1;
            while e < self.c.len() && self.c[e] != '"' && self.c[e] != '\n' {
                e += 1;
            }
            return Ok((Tok::Str, (e + 1).min(self.c.len())));
        }
        for op in OPS {
            if self.at(op) {
                return Ok((Tok::Op(op), s + op.chars().count()));
            }
        }
        self.err(format!("unexpected `{ch}` in an expression"))
    }

    /// The next token, not consumed.
    pub(crate) fn peek_tok(&mut self) -> Result<Tok, ParseError> {
        Ok(self.scan()?.0)
    }

    /// Consumes and returns the next token.
    pub(crate) fn tok(&mut self) -> Result<Tok, ParseError> {
        let (t, e) = self.scan()?;
        self.i = e;
        Ok(t)
    }

    /// Consumes operator `op` or fails saying what was expected.
    pub fn expect(&mut self, op: &str) -> Result<(), ParseError> {
        let s = self.i;
        match self.tok()? {
            Tok::Op(o) if o == op => Ok(()),
            t => self.err_at(s.max(self.i.min(s + 1)).min(self.i), format!("expected `{op}`, found {}", describe(&t))),
        }
    }

    /// Consumes operator `op` when it comes next.
    pub(crate) fn eat(&mut self, op: &str) -> Result<bool, ParseError> {
        let (t, e) = self.scan()?;
        if t == Tok::Op(leak(op)) {
            self.i = e;
            return Ok(true);
        }
        Ok(false)
    }

    fn enter(&mut self) -> Result<(), ParseError> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            return self.err(format!("expressions or blocks nest more than {MAX_NESTING} deep"));
        }
        Ok(())
    }

    /// An expression (`lsys_input.y`, `Expression`).
    pub fn expr(&mut self) -> Result<Expr, ParseError> {
        self.enter()?;
        let c = self.binary(0)?;
        let r = if self.eat("?")? {
            let a = self.expr()?;
            self.expect(":")?;
            let b = self.expr()?;
            Expr::Cond(Box::new(c), Box::new(a), Box::new(b))
        } else {
            c
        };
        self.depth -= 1;
        Ok(r)
    }

    fn binary(&mut self, level: usize) -> Result<Expr, ParseError> {
        const LEVELS: &[&[(&str, BinOp)]] = &[
            &[("||", BinOp::Or)],
            &[("&&", BinOp::And)],
            &[("==", BinOp::Eq), ("!=", BinOp::Ne), ("<>", BinOp::Ne)],
            &[("<", BinOp::Lt), ("<=", BinOp::Le), (">", BinOp::Gt), (">=", BinOp::Ge)],
            &[("+", BinOp::Add), ("-", BinOp::Sub)],
            &[("*", BinOp::Mul), ("/", BinOp::Div), ("%", BinOp::Rem)],
            &[("^", BinOp::Pow)],
        ];
        if level == LEVELS.len() {
            return self.unary();
        }
        let mut a = self.binary(level + 1)?;
        loop {
            let (t, e) = self.scan()?;
            let Tok::Op(o) = t else { break };
            let Some(&(_, op)) = LEVELS[level].iter().find(|(s, _)| *s == o) else { break };
            let span = self.span_at(e - o.len());
            self.i = e;
            let b = self.binary(level + 1)?;
            a = Expr::Binary(op, Box::new(a), Box::new(b), span);
        }
        Ok(a)
    }

    fn unary(&mut self) -> Result<Expr, ParseError> {
        self.blanks();
        let s = self.i;
        match self.tok()? {
            Tok::Op("-") => {
                self.enter()?;
                let e = self.unary()?;
                self.depth -= 1;
                Ok(match e {
                    Expr::Num(v) => Expr::Num(-v),
                    e => Expr::Unary(UnOp::Neg, Box::new(e)),
                })
            }
            Tok::Op("+") => self.unary(),
            Tok::Op("!") => {
                self.enter()?;
                let e = self.unary()?;
                self.depth -= 1;
                Ok(Expr::Unary(UnOp::Not, Box::new(e)))
            }
            Tok::Op("(") => {
                let e = self.expr()?;
                self.expect(")")?;
                Ok(e)
            }
            Tok::Op("&") => self.unary(),
            Tok::Num(v) => Ok(Expr::Num(v)),
            Tok::Str => Ok(Expr::Str),
            Tok::Name(n) => self.name(n, s),
            t => self.err_at(s, format!("expected an expression, found {}", describe(&t))),
        }
    }

    fn name(&mut self, n: String, s: usize) -> Result<Expr, ParseError> {
        let span = self.span_at(s);
        if self.peek_tok()? == Tok::Op("(") {
            let Some(f) = Func::from_name(&n) else {
                let what = match n.as_str() {
                    "curveX" | "curveY" | "curveZ" | "curveGAL" => "user-defined functions and contours (.con files) are not read yet",
                    "inblob" | "vvXmin" | "vvXmax" | "vvYmin" | "vvYmax" | "vvZmin" | "vvZmax" | "vvScale" | "GetDerivationLength" | "SetDerivationLength" => "this function of the interactive viewer has no meaning here",
                    _ => "no such function in cpfg",
                };
                return self.err_at(s, format!("{n}(): {what}"));
            };
            self.tok()?;
            let mut args = Vec::new();
            if !self.eat(")")? {
                loop {
                    args.push(self.expr()?);
                    if self.eat(")")? {
                        break;
                    }
                    self.expect(",")?;
                }
            }
            let ok = match f {
                Func::Atan => (1..=2).contains(&args.len()),
                Func::Nran | Func::Bran | Func::Biran | Func::Atan2 | Func::Func => args.len() == 2,
                Func::Ignored => true,
                _ => args.len() == 1,
            };
            if !ok {
                return self.err_at(s, format!("{n}() takes a different number of arguments than {}", args.len()));
            }
            return Ok(Expr::Call(f, args, span));
        }
        if let Some(a) = self.names.arrays.iter().position(|x| *x == n) {
            let idx = self.indices()?;
            return Ok(Expr::Elem(a as u32, idx, span));
        }
        Ok(self.names.lookup(&n))
    }

    /// `[i][j]…` or `[i, j]` after an array name.
    fn indices(&mut self) -> Result<Vec<Expr>, ParseError> {
        let mut idx = Vec::new();
        while self.eat("[")? {
            loop {
                idx.push(self.expr()?);
                if !self.eat(",")? {
                    break;
                }
            }
            self.expect("]")?;
        }
        if idx.is_empty() {
            return self.err("an array needs an index `[i]`");
        }
        Ok(idx)
    }

    /// A `{ statements }` block; the cursor is at `{`.
    pub fn block(&mut self) -> Result<Vec<Stmt>, ParseError> {
        self.enter()?;
        self.expect("{")?;
        self.braces += 1;
        let mut out = Vec::new();
        loop {
            if self.eat("}")? {
                break;
            }
            if self.eat(";")? {
                continue;
            }
            if self.peek().is_none() {
                return self.err("a `{` block is not closed with `}`");
            }
            out.push(self.statement()?);
        }
        self.braces -= 1;
        self.depth -= 1;
        Ok(out)
    }

    fn statement(&mut self) -> Result<Stmt, ParseError> {
        let s = self.i;
        match self.peek_tok()? {
            Tok::Name(n) if n == "if" => {
                self.tok()?;
                self.expect("(")?;
                let c = self.expr()?;
                self.expect(")")?;
                let a = self.block()?;
                let save = self.i;
                let b = match self.tok()? {
                    Tok::Name(e) if e == "else" => {
                        if matches!(self.peek_tok()?, Tok::Name(ref i) if i == "if") {
                            vec![self.statement()?]
                        } else {
                            self.block()?
                        }
                    }
                    _ => {
                        self.i = save;
                        Vec::new()
                    }
                };
                Ok(Stmt::If(c, a, b))
            }
            Tok::Name(n) if n == "while" => {
                self.tok()?;
                self.expect("(")?;
                let c = self.expr()?;
                self.expect(")")?;
                Ok(Stmt::While(c, self.block()?))
            }
            Tok::Name(n) if n == "do" => {
                self.tok()?;
                let body = self.block()?;
                match self.tok()? {
                    Tok::Name(w) if w == "while" => {}
                    _ => return self.err_at(s, "`do { … }` needs `while (condition)`"),
                }
                self.expect("(")?;
                let c = self.expr()?;
                self.expect(")")?;
                Ok(Stmt::Do(body, c))
            }
            Tok::Name(n) => {
                self.tok()?;
                let is_call = self.peek_tok()? == Tok::Op("(");
                if is_call {
                    let e = self.name(n, s)?;
                    self.expect(";")?;
                    return Ok(Stmt::Expr(e));
                }
                let assigns = self.peek_tok()? == Tok::Op("=") || (self.peek_tok()? == Tok::Op("[") && self.names.arrays.contains(&n));
                if !assigns {
                    // An expression for nothing (`roll - roll/L0;`): cpfg's
                    // grammar recovers from it; here it is evaluated and dropped.
                    self.i = s;
                    let e = self.expr()?;
                    self.expect(";")?;
                    return Ok(Stmt::Expr(e));
                }
                let target = match self.names.arrays.iter().position(|x| *x == n) {
                    Some(a) => {
                        let span = self.span_at(s);
                        Target::Elem(a as u32, self.indices()?, span)
                    }
                    None => match self.names.lookup(&n) {
                        Expr::Global(g) => Target::Global(g),
                        Expr::Local(l) => Target::Local(l),
                        _ => return self.err_at(s, "not a variable"),
                    },
                };
                self.expect("=")?;
                let e = self.expr()?;
                self.expect(";")?;
                Ok(Stmt::Assign(target, e))
            }
            t => self.err_at(s, format!("expected a statement, found {}", describe(&t))),
        }
    }
}

fn leak(op: &str) -> &'static str {
    OPS.iter().find(|o| **o == op).copied().unwrap_or("")
}

/// How a token is named in messages.
pub fn describe(t: &Tok) -> String {
    match t {
        Tok::Num(v) => format!("the number {v}"),
        Tok::Name(n) => format!("`{n}`"),
        Tok::Str => "a string".into(),
        Tok::Op(o) => format!("`{o}`"),
        Tok::Eol => "the end of the line".into(),
    }
}
