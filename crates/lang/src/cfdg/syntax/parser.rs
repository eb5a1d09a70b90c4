//! The recursive-descent parser over [`lexer`](super::lexer) tokens, after
//! the productions of `cfdg.ypp` (Context Free 3.4). The version is decided
//! up front as cfdg decides it when it restarts a parse: a file with a
//! `shape` keyword, a `loop` or a `CF::` setting is 3.x, otherwise 2.x.

use super::lexer::{lex, Tok, Token};
use super::{Adjustment, Define, Element, Expr, Grammar, Loop, Param, Replacement, Rule, Term, TermKind, Value, Version};
use crate::{ParseError, Span};

mod expr;
mod func;
mod path;
mod shapeparam;
use expr::const_value;
mod namespace;
mod subpath;
mod symmetry;
pub(crate) use path::{is_path_op, path_op_arity};

/// The argument list `(=)` stands for: the parent shape's parameters.
pub(crate) const REUSE: &str = "(=)";

/// Deepest nesting of bodies and expressions the parser follows; deeper
/// input is an error, never a stack overflow.
pub(crate) const MAX_NESTING: usize = 200;

/// Reads the file an `import`/`include` names (a bare file name); `None`
/// when it cannot be read or no files may be read.
pub(crate) type Loader<'a> = &'a dyn Fn(&str) -> Option<Vec<u8>>;

/// Most files one design may import, counting repeats (an import cycle ends here).
pub(crate) const MAX_IMPORTS: usize = 64;

/// Parses CFDG `source` (UTF-8; invalid UTF-8 is an error at its position);
/// `import`/`include` are errors.
pub fn parse(source: &[u8]) -> Result<Grammar, ParseError> {
    parse_with(source, &|_| None)
}

fn tokens(source: &[u8], included: bool) -> Result<Vec<Token>, ParseError> {
    let text = std::str::from_utf8(source).map_err(|e| {
        let before = &source[..e.valid_up_to()];
        let line = before.iter().filter(|&&c| c == b'\n').count() as u32 + 1;
        let col = before.iter().rev().take_while(|&&c| c != b'\n').count() as u32 + 1;
        ParseError::single(Span::new(line, col), "invalid UTF-8")
    })?;
    let mut toks = lex(text)?;
    // The version is decided per file, as cfdg decides it when it restarts
    // a parse: a `shape`, a `loop` or a `CF::` setting makes it 3.x.
    let v3 = toks.iter().any(|t| match &t.tok {
        Tok::Word(w) => w == "shape" || w == "loop" || w.starts_with("CF::"),
        _ => false,
    });
    for t in &mut toks {
        t.v3 = v3;
        t.included = included;
    }
    Ok(toks)
}

/// Parses CFDG `source`, reading imported files through `load`.
pub(crate) fn parse_with(source: &[u8], load: Loader<'_>) -> Result<Grammar, ParseError> {
    let toks = tokens(source, false)?;
    let version = if toks.first().is_some_and(|t| t.v3) { Version::V3 } else { Version::V2 };
    let mut p = Parser { toks, pos: 0, version, depth: 0, load, imports: 0, path: path::PathState::default(), last_params: Vec::new(), start_setting: None, rand_static: Vec::new(), entropy_names: Default::default() };
    p.grammar()
}

struct Parser<'a> {
    toks: Vec<Token>,
    pos: usize,
    version: Version,
    depth: usize,
    load: Loader<'a>,
    imports: usize,
    /// Whether a path body or a path command's adjustment is being read ([`path`]).
    path: path::PathState,
    /// The typed parameters the last parameter list declared ([`func`]).
    last_params: Vec<Param>,
    /// The start shape a `CF::StartShape` setting just gave ([`func`]).
    start_setting: Option<Replacement>,
    /// `rand_static()` calls in the order they were made.
    rand_static: Vec<Span>,
    /// The written names of namespaced replacements ([`namespace`]).
    entropy_names: std::collections::BTreeMap<(u32, u32, String), String>,
}

fn term_kind(word: &str) -> Option<TermKind> {
    Some(match word {
        "x" => TermKind::X,
        "y" => TermKind::Y,
        "z" => TermKind::Z,
        "size" | "s" => TermKind::Size,
        "rotate" | "r" => TermKind::Rotate,
        "flip" | "f" => TermKind::Flip,
        "skew" => TermKind::Skew,
        "transform" | "trans" => TermKind::Transform,
        "hue" | "h" => TermKind::Hue,
        "saturation" | "sat" => TermKind::Sat,
        "brightness" | "b" => TermKind::Bright,
        "alpha" | "a" => TermKind::Alpha,
        "|hue" | "|h" => TermKind::TargHue,
        "|saturation" | "|sat" => TermKind::TargSat,
        "|brightness" | "|b" => TermKind::TargBright,
        "|alpha" | "|a" => TermKind::TargAlpha,
        "time" => TermKind::Time,
        "timescale" => TermKind::TimeScale,
        "blend" => TermKind::Ignored,
        _ => return None,
    })
}

impl Parser<'_> {
    fn v3(&self) -> bool {
        self.toks[self.pos.min(self.toks.len() - 1)].v3
    }
    fn peek(&self) -> &Tok {
        &self.toks[self.pos.min(self.toks.len() - 1)].tok
    }
    fn peek_at(&self, k: usize) -> &Tok {
        &self.toks[(self.pos + k).min(self.toks.len() - 1)].tok
    }
    fn span(&self) -> Span {
        self.toks[self.pos.min(self.toks.len() - 1)].span
    }
    fn bump(&mut self) -> Token {
        let t = self.toks[self.pos.min(self.toks.len() - 1)].clone();
        if self.pos < self.toks.len() - 1 {
            self.pos += 1;
        }
        t
    }
    fn is_punct(&self, p: &str) -> bool {
        matches!(self.peek(), Tok::Punct(q) if *q == p)
    }
    fn is_word(&self, w: &str) -> bool {
        matches!(self.peek(), Tok::Word(q) if q == w)
    }
    fn err<T>(&self, msg: impl Into<String>) -> Result<T, ParseError> {
        let found = match self.peek() {
            Tok::Num(n) => format!("`{n}`"),
            Tok::Word(w) => format!("`{w}`"),
            Tok::Str(s) => format!("\"{s}\""),
            Tok::Punct(p) => format!("`{p}`"),
            Tok::Eof => "end of input".into(),
        };
        Err(ParseError::single(self.span(), format!("{}, found {found}", msg.into())))
    }
    fn expect(&mut self, p: &str) -> Result<(), ParseError> {
        if self.is_punct(p) {
            self.bump();
            Ok(())
        } else {
            self.err(format!("expected `{p}`"))
        }
    }
    fn name(&mut self, what: &str) -> Result<(String, Span), ParseError> {
        let span = self.span();
        match self.peek().clone() {
            Tok::Word(w) if term_kind(&w).is_none() => {
                self.bump();
                Ok((w, span))
            }
            _ => self.err(format!("expected {what}")),
        }
    }
    fn enter(&mut self) -> Result<(), ParseError> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            return Err(ParseError::single(self.span(), format!("nesting deeper than {MAX_NESTING}")));
        }
        Ok(())
    }

    fn grammar(&mut self) -> Result<Grammar, ParseError> {
        let mut g = Grammar { version: self.version, start: None, rules: Vec::new(), defines: Vec::new(), background: None, warnings: Vec::new(), functions: Default::default(), param_types: Default::default(), rand_static: Vec::new(), entropy_names: Default::default(), start_from_setting: false };
        let mut current_shape: Option<String> = None;
        let mut current_params: Vec<String> = Vec::new();
        let mut declared: std::collections::HashMap<String, Vec<String>> = std::collections::HashMap::new();
        loop {
            let span = self.span();
            match self.peek().clone() {
                Tok::Eof => break,
                Tok::Word(w) if w == "startshape" => {
                    self.bump();
                    let (name, nspan) = self.name("a shape name after `startshape`")?;
                    let args = if self.is_punct("(") { self.call_args(&name)? } else { None };
                    let (name, args) = shapeparam::chosen_start(name, args, nspan);
                    let adjust = if self.is_punct("[") { self.adjustment()? } else { Adjustment { canonical: true, terms: Vec::new() } };
                    // The design's own startshape wins over an imported file's.
                    if !self.toks[self.pos.saturating_sub(1)].included || g.start.is_none() {
                        g.start = Some(Replacement { shape: name, adjust, args, span: nspan });
                        g.start_from_setting = false;
                    }
                }
                Tok::Word(w) if w == "include" || w == "import" => {
                    self.bump();
                    let ns = self.namespace()?;
                    let name = match self.bump().tok {
                        Tok::Word(n) | Tok::Str(n) => n,
                        _ => return Err(ParseError::single(span, "expected a file name after `import`")),
                    };
                    self.imports += 1;
                    if self.imports > MAX_IMPORTS {
                        return Err(ParseError::single(span, format!("more than {MAX_IMPORTS} imports (a cycle?)")));
                    }
                    let Some(bytes) = (self.load)(&name) else {
                        return Err(ParseError::single(span, format!("cannot import `{name}` (only files beside the design can be imported)")));
                    };
                    let mut more = tokens(&bytes, true).map_err(|e| {
                        let d = &e.diagnostics[0];
                        ParseError::single(span, format!("in `{name}` at {}:{}: {}", d.span.line, d.span.column, d.message))
                    })?;
                    more.pop(); // its end of input
                    if let Some(ns) = &ns {
                        namespace::qualify(&mut more, ns);
                    }
                    let at = self.pos;
                    self.toks.splice(at..at, more);
                }
                Tok::Word(w) if w == "path" && !matches!(self.peek_at(1), Tok::Punct("=")) => {
                    self.last_params.clear();
                    let rule = self.path_rule(span)?;
                    if !self.last_params.is_empty() {
                        g.param_types.insert(rule.name.clone(), std::mem::take(&mut self.last_params));
                    }
                    g.rules.push(rule);
                    current_shape = None;
                }
                Tok::Word(_) if self.function_header().is_some() => {
                    let f = self.function()?;
                    g.functions.insert(f.name.clone(), f);
                    current_shape = None;
                }
                Tok::Word(w) if w == "shape" => {
                    self.bump();
                    let (name, _) = self.name("a shape name after `shape`")?;
                    // A shape declared with parameters keeps them when its
                    // body comes later under `shape NAME` alone (paramtest6).
                    current_params = if self.is_punct("(") {
                        let p = self.param_list()?;
                        declared.insert(name.clone(), p.clone());
                        g.param_types.insert(name.clone(), std::mem::take(&mut self.last_params));
                        p
                    } else {
                        declared.get(&name).cloned().unwrap_or_default()
                    };
                    if self.is_punct("{") {
                        let body = self.body()?;
                        g.rules.push(Rule { name, weight: 1.0, percent: false, body, is_path: false, params: current_params.clone(), span });
                        current_shape = None;
                    } else {
                        current_shape = Some(name);
                    }
                }
                Tok::Word(w) if w == "rule" => {
                    self.bump();
                    let name = if !self.v3() {
                        self.name("a rule name after `rule`")?.0
                    } else {
                        match &current_shape {
                            Some(n) => n.clone(),
                            None => return self.err("`rule` outside a `shape`"),
                        }
                    };
                    let (weight, percent) = if let Tok::Num(n) = self.peek().clone() {
                        self.bump();
                        let pct = n.ends_with('%');
                        let v: f64 = n.trim_end_matches('%').parse().unwrap_or(1.0);
                        (if pct { v / 100.0 } else { v }, pct)
                    } else {
                        (1.0, false)
                    };
                    let body = if !self.v3() { self.body_v2()? } else { self.body()? };
                    let weight = if weight > 0.0 && weight.is_finite() { weight } else { 1.0 };
                    let params = if self.v3() { current_params.clone() } else { Vec::new() };
                    g.rules.push(Rule { name, weight, percent, body, is_path: false, params, span });
                }
                Tok::Word(w) if !self.v3() && matches!(w.as_str(), "background" | "tile" | "size") => {
                    self.bump();
                    let adj = self.adjustment()?;
                    match w.as_str() {
                        "background" => g.background = Some(adj),
                        "tile" => g.defines.push(Define { name: "CF::Tile".into(), value: Value::Adjust(adj), span }),
                        _ => g.defines.push(Define { name: "CF::Size".into(), value: Value::Adjust(adj), span }),
                    }
                }
                Tok::Word(_) if matches!(self.peek_at(1), Tok::Punct("=")) => {
                    let d = self.define()?;
                    if d.name == "CF::StartShape" {
                        if let Some(start) = self.start_setting.take() {
                            g.start = Some(start);
                            g.start_from_setting = true;
                        }
                    }
                    current_shape = None;
                    g.defines.push(d);
                }
                _ => return self.err("expected `startshape`, `shape`, `rule`, a definition or a setting"),
            }
        }
        g.rand_static = std::mem::take(&mut self.rand_static);
        g.entropy_names = std::mem::take(&mut self.entropy_names);
        super::shapes::resolve(&mut g);
        Ok(g)
    }

    fn define(&mut self) -> Result<Define, ParseError> {
        let (name, span) = match self.bump() {
            Token { tok: Tok::Word(w), span, .. } => (w, span),
            _ => return self.err("expected a name"),
        };
        self.expect("=")?;
        let value = if name == "CF::Symmetry" {
            Value::Symmetry(self.symmetry_list()?)
        } else if self.is_punct("[") {
            Value::Adjust(self.adjustment()?)
        } else if name == "CF::StartShape" {
            let start = self.start_setting()?;
            let shape = start.shape.clone();
            self.start_setting = Some(start);
            Value::Shape(shape)
        } else {
            Value::Expr(self.expr(0)?)
        };
        Ok(Define { name, value, span })
    }

    /// `{ elements }` or one element (3.x).
    fn body(&mut self) -> Result<Vec<Element>, ParseError> {
        self.enter()?;
        let mut out = Vec::new();
        if self.is_punct("{") {
            self.bump();
            while !self.is_punct("}") {
                if matches!(self.peek(), Tok::Eof) {
                    return self.err("expected `}`");
                }
                out.push(self.element()?);
            }
            self.bump();
        } else {
            out.push(self.element()?);
        }
        self.depth -= 1;
        Ok(out)
    }

    fn element(&mut self) -> Result<Element, ParseError> {
        let span = self.span();
        let word = match self.peek().clone() {
            Tok::Word(w) => w,
            _ => return self.err("expected a shape, `loop`, `if`, `switch`, `transform` or a definition"),
        };
        if let Some(r) = self.chosen_shape(span)? {
            return Ok(r);
        }
        match word.as_str() {
            "loop" => {
                self.bump();
                let var = if matches!(self.peek(), Tok::Word(_)) && matches!(self.peek_at(1), Tok::Punct("=")) {
                    let (v, _) = self.name("a loop index")?;
                    self.bump();
                    Some(v)
                } else {
                    None
                };
                let args = self.expr(0)?;
                let adjust = self.adjustment()?;
                let body = self.body()?;
                let finally = if self.is_word("finally") {
                    self.bump();
                    self.body()?
                } else {
                    Vec::new()
                };
                Ok(Element::Loop(Loop { var, args, adjust, body, finally, v2: false, span }))
            }
            "if" => {
                self.bump();
                self.expect("(")?;
                let cond = self.expr(0)?;
                self.expect(")")?;
                let then = self.body()?;
                let otherwise = if self.is_word("else") {
                    self.bump();
                    self.body()?
                } else {
                    Vec::new()
                };
                Ok(Element::If { cond, then, otherwise, span })
            }
            "switch" => {
                self.bump();
                self.expect("(")?;
                let selector = self.expr(0)?;
                self.expect(")")?;
                self.expect("{")?;
                let (mut cases, mut otherwise) = (Vec::new(), Vec::new());
                while !self.is_punct("}") {
                    if self.is_word("case") {
                        self.bump();
                        let mut ranges = Vec::new();
                        loop {
                            let lo = self.case_value()?;
                            let hi = if self.is_punct("..") {
                                self.bump();
                                self.case_value()?
                            } else {
                                lo
                            };
                            ranges.push((lo, hi));
                            if !self.is_punct(",") {
                                break;
                            }
                            self.bump();
                        }
                        self.expect(":")?;
                        cases.push((ranges, self.body()?));
                    } else if self.is_word("else") {
                        self.bump();
                        self.expect(":")?;
                        otherwise = self.body()?;
                    } else {
                        return self.err("expected `case`, `else` or `}`");
                    }
                }
                self.bump();
                Ok(Element::Switch { selector, cases, otherwise, span })
            }
            // `trans` is `transform`'s short form here too (cfdg.l: both are MODTYPE transform).
            "transform" | "trans" | "clone" if !matches!(self.peek_at(1), Tok::Punct("=")) => {
                self.bump();
                let (adjusts, symmetry) = self.transform_list()?;
                let body = self.body()?;
                Ok(Element::Transform { clone: word == "clone", adjusts, symmetry, body, span })
            }
            "finally" | "else" | "case" => self.err("unexpected keyword"),
            "path" if self.path.in_path && matches!(self.peek_at(1), Tok::Word(_)) => self.subpath(),
            w if is_path_op(w) && (self.path.in_path || !matches!(w, "FILL" | "STROKE")) && !matches!(self.peek_at(1), Tok::Punct("=")) => self.path_element(),
            _ if matches!(self.peek_at(1), Tok::Punct("=")) => Ok(Element::Define(self.define()?)),
            _ if self.path.in_path => self.err("Replacements are not allowed in paths (a subpath is `path NAME [ ]`)"),
            _ => {
                let (shape, span) = self.name("a shape name")?;
                self.note_written(&shape, span);
                let args = if self.is_punct("(") { self.call_args(&shape)? } else { None };
                let adjust = self.adjustment()?;
                Ok(Element::Replace(Replacement { shape, adjust, args, span }))
            }
        }
    }

    /// A case value: a constant expression above the range operator, floored.
    fn case_value(&mut self) -> Result<i64, ParseError> {
        let span = self.span();
        let e = self.expr(7)?;
        let v = const_value(&e).ok_or_else(|| ParseError::single(span, "a case value must be a constant number"))?;
        Ok(v.floor().clamp(-1e15, 1e15) as i64)
    }

    /// A 2.x rule body: `{ replacements }`.
    fn body_v2(&mut self) -> Result<Vec<Element>, ParseError> {
        self.enter()?;
        self.expect("{")?;
        let mut out = Vec::new();
        while !self.is_punct("}") {
            out.push(self.replacement_v2()?);
        }
        self.bump();
        self.depth -= 1;
        Ok(out)
    }

    fn replacement_v2(&mut self) -> Result<Element, ParseError> {
        let span = self.span();
        match self.peek().clone() {
            Tok::Num(n) if matches!(self.peek_at(1), Tok::Punct("*")) => {
                self.bump();
                self.bump();
                let value: f64 = n.trim_end_matches('%').parse().unwrap_or(0.0);
                let adjust = self.adjustment()?;
                let body = if self.is_punct("{") { self.body_v2()? } else { vec![self.replacement_v2()?] };
                Ok(Element::Loop(Loop { var: None, args: Expr::Num(value, n), adjust, body, finally: Vec::new(), v2: true, span }))
            }
            Tok::Word(w) if is_path_op(&w) && (self.path.in_path || !matches!(w.as_str(), "FILL" | "STROKE")) => self.path_element(),
            Tok::Word(_) if self.path.in_path => self.err("Replacements are not allowed in paths"),
            Tok::Word(_) => {
                let (shape, span) = self.name("a shape name")?;
                self.note_written(&shape, span);
                let adjust = self.adjustment()?;
                Ok(Element::Replace(Replacement { shape, adjust, args: None, span }))
            }
            _ => self.err("expected a replacement"),
        }
    }

    /// An adjustment: 3.x `[ ]` canonical, `[[ ]]` ordered; 2.x `{ }` canonical, `[ ]` ordered.
    fn adjustment(&mut self) -> Result<Adjustment, ParseError> {
        let (canonical, close): (bool, &[&str]) = if self.v3() {
            if self.is_punct("[") && matches!(self.peek_at(1), Tok::Punct("[")) {
                self.bump();
                self.bump();
                (false, &["]", "]"])
            } else if self.is_punct("[") {
                self.bump();
                (true, &["]"])
            } else {
                return self.err("expected an adjustment `[ ]`");
            }
        } else if self.is_punct("{") {
            self.bump();
            (true, &["}"])
        } else if self.is_punct("[") {
            self.bump();
            (false, &["]"])
        } else {
            return self.err("expected an adjustment `{ }` or `[ ]`");
        };
        let mut terms: Vec<Term> = Vec::new();
        while !self.is_punct(close[0]) {
            let span = self.span();
            if self.path.terms && self.path_term()? {
                continue;
            }
            let kind = match self.peek().clone() {
                Tok::Word(w) => match term_kind(&w) {
                    Some(k) => k,
                    None => return self.err("expected an adjustment (x, y, size, rotate, hue, …)"),
                },
                _ => return self.err(format!("expected an adjustment or `{}`", close[0])),
            };
            self.bump();
            let mut args = Vec::new();
            while self.starts_exp() {
                args.push(self.exp()?);
            }
            if args.is_empty() {
                return self.err("expected a number after the adjustment");
            }
            let mut kind = kind;
            if self.is_punct("|") && args.len() == 1 {
                self.bump();
                kind = match kind {
                    TermKind::Hue => TermKind::HueTarg,
                    TermKind::Sat => TermKind::SatTarg,
                    TermKind::Bright => TermKind::BrightTarg,
                    TermKind::Alpha => TermKind::AlphaTarg,
                    _ => return Err(ParseError::single(span, "only colour adjustments take a target `|`")),
                };
            }
            let args = if args.len() == 1 { args.pop().unwrap_or(Expr::Cons(Vec::new())) } else { Expr::Cons(args) };
            // `x a y b` merges into one two-argument x term (ASTmodification::compile).
            if kind == TermKind::Y {
                if let Some(prev) = terms.last_mut() {
                    if prev.kind == TermKind::X && !matches!(prev.args, Expr::Cons(_)) {
                        let x = std::mem::replace(&mut prev.args, Expr::Cons(Vec::new()));
                        prev.args = Expr::Cons(vec![x, args]);
                        continue;
                    }
                }
            }
            // `x a b c` and `size a b c` split into a z term, placed first,
            // and a two-number term (ASTmodification::compile's xyz split).
            if let (TermKind::X | TermKind::Size, Expr::Cons(v)) = (kind, &args) {
                if v.len() == 3 {
                    let mut v = v.clone();
                    let z = v.pop().unwrap_or(Expr::Cons(Vec::new()));
                    terms.push(Term { kind: if kind == TermKind::X { TermKind::Z } else { TermKind::ZSize }, args: z, span });
                    terms.push(Term { kind, args: Expr::Cons(v), span });
                    continue;
                }
            }
            terms.push(Term { kind, args, span });
        }
        for c in close {
            self.expect(c)?;
        }
        Ok(Adjustment { canonical, terms })
    }
}
