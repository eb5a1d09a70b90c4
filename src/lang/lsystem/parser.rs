//! Parsing L-system source into an [`LSystem`].
//!
//! The source is split into statements: one per line, where an indented line
//! continues the statement above it. Comments (`//` to the end of the line,
//! `/* … */`) are blanked first, keeping every other character's line and
//! column. Each statement is a setting (`axiom: …`), a directive
//! (`#define NAME expr`, `#ignore …`) or a production (it contains `->`).

use super::{LSystem, Module, Pattern, Production, Shape, SYM_POP, SYM_PUSH};
use crate::lang::expr::{BinOp, Expr, Func};
use crate::core::PrimitiveKind;
use crate::core::{ParseError, Span};
use std::collections::HashMap;

/// Deepest expression nesting accepted (keeps evaluation recursion bounded).
const MAX_EXPR_DEPTH: u32 = 64;
/// Most iterations a grammar may ask for (the budget usually binds far earlier).
const MAX_ITERATIONS: f64 = 100_000.0;

type Chars = [(char, Span)];

fn err<T>(span: Span, msg: impl Into<String>) -> Result<T, ParseError> {
    Err(ParseError::single(span, msg))
}

/// Parses L-system source.
pub fn parse(source: &[u8]) -> Result<LSystem, ParseError> {
    let text = match std::str::from_utf8(source) {
        Ok(t) => t,
        Err(e) => {
            let good = &source[..e.valid_up_to()];
            let line = good.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
            let col = String::from_utf8_lossy(good.rsplit(|&b| b == b'\n').next().unwrap_or(&[])).chars().count() as u32 + 1;
            return err(Span::new(line, col), "the source is not valid UTF-8");
        }
    };
    let chars = blank_comments(text)?;
    let statements = split_statements(&chars)?;
    let mut p = Parser::default();
    p.sys.symbols = vec!["[".to_string(), "]".to_string()];
    for st in &statements {
        p.statement(st)?;
    }
    p.finish()
}

/// The characters of `text` with their positions, comments replaced by spaces.
fn blank_comments(text: &str) -> Result<Vec<(char, Span)>, ParseError> {
    let mut out = Vec::with_capacity(text.len());
    let (mut line, mut col) = (1u32, 1u32);
    for c in text.chars() {
        out.push((c, Span::new(line, col)));
        if c == '\n' {
            line += 1;
            col = 1;
        } else {
            col += 1;
        }
    }
    // `/` is also the roll symbol, so `//` and `/*` open a comment only at the
    // start of a line or after whitespace, and `//` only before whitespace or
    // the end of the line: `F//F` rolls twice, `F // note` is a comment.
    let mut i = 0;
    while i < out.len() {
        let next = out.get(i + 1).map(|c| c.0);
        let after_space = i == 0 || out[i - 1].0.is_whitespace();
        let before_space = !out.get(i + 2).is_some_and(|c| !c.0.is_whitespace());
        match (out[i].0, next) {
            ('/', Some('/')) if after_space && before_space => {
                while i < out.len() && out[i].0 != '\n' {
                    out[i].0 = ' ';
                    i += 1;
                }
            }
            ('/', Some('*')) if after_space => {
                let start = out[i].1;
                out[i].0 = ' ';
                out[i + 1].0 = ' ';
                i += 2;
                loop {
                    if i >= out.len() {
                        return err(start, "unterminated comment: `/*` has no closing `*/`");
                    }
                    if out[i].0 == '*' && out.get(i + 1).is_some_and(|c| c.0 == '/') {
                        out[i].0 = ' ';
                        out[i + 1].0 = ' ';
                        i += 2;
                        break;
                    }
                    if out[i].0 != '\n' {
                        out[i].0 = ' ';
                    }
                    i += 1;
                }
            }
            _ => i += 1,
        }
    }
    Ok(out)
}

/// True when a line (already trimmed at the start) starts a statement of its own.
fn starts_statement(line: &Chars) -> bool {
    let word_len = line.iter().take_while(|c| is_ident(c.0)).count();
    let word = text_of(&line[..word_len]);
    let setting = SETTINGS.contains(&word.as_str()) && trim(&line[word_len..]).first().is_some_and(|c| c.0 == ':');
    setting || line.first().is_some_and(|c| c.0 == '#') || find_top(line, "->").is_some()
}

/// Splits into statements: a line, plus the indented lines that follow it
/// (an indented line that is itself a setting, directive or production starts a new one).
fn split_statements(chars: &Chars) -> Result<Vec<Vec<(char, Span)>>, ParseError> {
    let mut out: Vec<Vec<(char, Span)>> = Vec::new();
    for line in chars.split(|c| c.0 == '\n') {
        let line: Vec<(char, Span)> = line.iter().copied().filter(|c| c.0 != '\r').collect();
        let Some(first) = line.iter().position(|c| !c.0.is_whitespace()) else { continue };
        if first > 0 && !starts_statement(&line[first..]) {
            if let Some(prev) = out.last_mut() {
                prev.push((' ', line[0].1));
                prev.extend_from_slice(&line[first..]);
                continue;
            }
        }
        out.push(line[first..].to_vec());
    }
    for st in &mut out {
        while st.last().is_some_and(|c| c.0.is_whitespace()) {
            st.pop();
        }
    }
    Ok(out)
}

fn trim(mut s: &Chars) -> &Chars {
    while s.first().is_some_and(|c| c.0.is_whitespace()) {
        s = &s[1..];
    }
    while s.last().is_some_and(|c| c.0.is_whitespace()) {
        s = &s[..s.len() - 1];
    }
    s
}

fn text_of(s: &Chars) -> String {
    s.iter().map(|c| c.0).collect()
}

/// Index of the first `pat` at parenthesis depth 0.
fn find_top(s: &Chars, pat: &str) -> Option<usize> {
    let pat: Vec<char> = pat.chars().collect();
    let mut depth = 0i32;
    for i in 0..s.len() {
        match s[i].0 {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth == 0 && s[i..].iter().map(|c| c.0).take(pat.len()).eq(pat.iter().copied()) {
            return Some(i);
        }
    }
    None
}

fn span_of(s: &Chars, fallback: Span) -> Span {
    s.first().map_or(fallback, |c| c.1)
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

const SETTINGS: [&str; 13] = [
    "iterations", "angle", "length", "width", "axiom", "ignore", "seed", "shape", "tropism", "elasticity", "terminate", "modules", "variety",
];

/// The largest `variety:` accepted: more variants than this defeat instancing.
const MAX_VARIETY: f64 = 1024.0;

#[derive(Default)]
struct Parser {
    sys: LSystem,
    defines: HashMap<String, Expr>,
    /// Multi-character module names declared with `modules:`, longest first.
    long_names: Vec<Vec<char>>,
    groups: HashMap<String, u32>,
    axiom_set: bool,
}

impl Default for LSystem {
    fn default() -> Self {
        LSystem {
            symbols: Vec::new(),
            axiom: Vec::new(),
            productions: Vec::new(),
            terminate: Vec::new(),
            iterations: 0,
            angle: 90.0,
            length: 1.0,
            width: 0.1,
            seed: None,
            ignore: Vec::new(),
            shape: Shape::Tube,
            tropism: None,
            elasticity: 0.2,
            variety: None,
            site_count: 0,
            warnings: Vec::new(),
        }
    }
}

impl Parser {
    fn finish(mut self) -> Result<LSystem, ParseError> {
        if !self.axiom_set {
            return err(Span::new(1, 1), "the L-system has no `axiom:`");
        }
        self.sys.ignore.sort_unstable();
        self.sys.ignore.dedup();
        Ok(self.sys)
    }

    fn intern(&mut self, name: &str) -> u32 {
        if let Some(i) = self.sys.symbols.iter().position(|s| s == name) {
            return i as u32;
        }
        self.sys.symbols.push(name.to_string());
        (self.sys.symbols.len() - 1) as u32
    }

    fn statement(&mut self, st: &Chars) -> Result<(), ParseError> {
        let start = st[0].1;
        if st[0].0 == '#' {
            return self.directive(st);
        }
        // A setting: a known word followed by ':'.
        let word_len = st.iter().take_while(|c| is_ident(c.0)).count();
        let word = text_of(&st[..word_len]);
        let rest = trim(&st[word_len..]);
        if SETTINGS.contains(&word.as_str()) && rest.first().is_some_and(|c| c.0 == ':') {
            return self.setting(&word, trim(&rest[1..]), start);
        }
        if find_top(st, "->").is_some() {
            let p = self.production(st)?;
            self.sys.productions.push(p);
            return Ok(());
        }
        if rest.first().is_some_and(|c| c.0 == ':') && word_len > 1 {
            return err(start, format!("unknown setting `{word}` (known: {})", SETTINGS.join(", ")));
        }
        err(start, "expected a setting such as `axiom: F` or a production `pred -> successor`")
    }

    fn directive(&mut self, st: &Chars) -> Result<(), ParseError> {
        let word_len = 1 + st[1..].iter().take_while(|c| is_ident(c.0)).count();
        let word = text_of(&st[..word_len]);
        let rest = trim(&st[word_len..]);
        match word.as_str() {
            "#define" => {
                let name_len = rest.iter().take_while(|c| is_ident(c.0)).count();
                if name_len == 0 || !is_ident_start(rest[0].0) {
                    return err(span_of(rest, st[0].1), "`#define` expects a name and an expression");
                }
                let name = text_of(&rest[..name_len]);
                let body = trim(&rest[name_len..]);
                if body.is_empty() {
                    return err(rest[0].1, format!("`#define {name}` has no value"));
                }
                let e = self.expr(body, &[], rest[0].1)?;
                self.defines.insert(name, e);
                Ok(())
            }
            "#ignore" => {
                let rest = if rest.first().is_some_and(|c| c.0 == ':') { trim(&rest[1..]) } else { rest };
                self.setting("ignore", rest, st[0].1)
            }
            _ => err(st[0].1, format!("unknown directive `{word}` (known: #define, #ignore)")),
        }
    }

    fn number(&mut self, value: &Chars, at: Span, what: &str) -> Result<f64, ParseError> {
        if value.is_empty() {
            return err(at, format!("`{what}:` needs a value"));
        }
        let e = self.expr(value, &[], at)?;
        let v = e.eval(&mut ConstEnv);
        if !v.is_finite() {
            return err(value[0].1, format!("`{what}:` is not a finite number ({v})"));
        }
        Ok(v)
    }

    fn setting(&mut self, key: &str, value: &Chars, at: Span) -> Result<(), ParseError> {
        let vspan = span_of(value, at);
        match key {
            "iterations" => {
                let v = self.number(value, at, key)?;
                if v < 0.0 || v.fract() != 0.0 || v > MAX_ITERATIONS {
                    return err(vspan, format!("`iterations:` must be a whole number in 0..={MAX_ITERATIONS}, got {v}"));
                }
                self.sys.iterations = v as u32;
            }
            "angle" => self.sys.angle = self.number(value, at, key)?,
            "length" => self.sys.length = self.number(value, at, key)?,
            "width" => self.sys.width = self.number(value, at, key)?,
            "elasticity" => self.sys.elasticity = self.number(value, at, key)?,
            "variety" => {
                let v = self.number(value, at, key)?;
                if v < 1.0 || v.fract() != 0.0 || v > MAX_VARIETY {
                    return err(vspan, format!("`variety:` must be a whole number in 1..={MAX_VARIETY}, got {v}"));
                }
                self.sys.variety = Some(v as u32);
            }
            "seed" => {
                let v = self.number(value, at, key)?;
                if v < 0.0 || v.fract() != 0.0 || v >= 1.8e19 {
                    return err(vspan, format!("`seed:` must be a whole number ≥ 0, got {v}"));
                }
                self.sys.seed = Some(v as u64);
            }
            "axiom" => {
                if self.axiom_set {
                    return err(at, "a second `axiom:`");
                }
                if value.is_empty() {
                    return err(at, "`axiom:` needs at least one module");
                }
                self.sys.axiom = self.modules(value, &[])?;
                self.axiom_set = true;
            }
            "ignore" => {
                for m in self.patterns(value)? {
                    if m.arity != 0 {
                        return err(m.span, "`ignore:` lists symbols without parameters");
                    }
                    self.sys.ignore.push(m.symbol);
                }
            }
            "modules" => {
                for w in value.split(|c| c.0.is_whitespace()).filter(|w| !w.is_empty()) {
                    if !w.iter().all(|c| is_ident(c.0)) || w.len() < 2 {
                        return err(w[0].1, format!("`modules:` declares names of two or more letters, digits or `_`, got `{}`", text_of(w)));
                    }
                    self.long_names.push(w.iter().map(|c| c.0).collect());
                }
                self.long_names.sort_by(|a, b| b.len().cmp(&a.len()).then_with(|| a.cmp(b)));
            }
            "shape" => {
                let name = text_of(value);
                self.sys.shape = if name.eq_ignore_ascii_case("tube") {
                    Shape::Tube
                } else {
                    match PrimitiveKind::ALL.iter().find(|k| format!("{k:?}").eq_ignore_ascii_case(&name)) {
                        Some(k) => Shape::Primitive(*k),
                        None => return err(vspan, format!("unknown shape `{name}` (tube or a built-in primitive such as CYLINDER)")),
                    }
                };
            }
            "tropism" => {
                let parts: Vec<&Chars> =
                    value.split(|c| c.0.is_whitespace() || c.0 == ',').filter(|w| !w.is_empty()).collect();
                if parts.len() != 3 {
                    return err(vspan, "`tropism:` needs three numbers `x y z`");
                }
                let mut t = [0.0; 3];
                for (slot, part) in t.iter_mut().zip(parts) {
                    *slot = self.number(part, at, key)?;
                }
                self.sys.tropism = Some(t);
            }
            "terminate" => {
                if find_top(value, "->").is_none() {
                    return err(vspan, "`terminate:` expects a production such as `L -> F`");
                }
                let p = self.production(value)?;
                self.sys.terminate.push(p);
            }
            _ => return err(at, format!("unknown setting `{key}`")),
        }
        Ok(())
    }

    /// Reads one symbol name at `s[i..]`; returns (name, length in chars).
    fn symbol_at(&self, s: &Chars, i: usize) -> (String, usize) {
        for name in &self.long_names {
            if s.len() - i >= name.len()
                && s[i..i + name.len()].iter().map(|c| c.0).eq(name.iter().copied())
            {
                return (name.iter().collect(), name.len());
            }
        }
        if s[i].0 == '?' && s.get(i + 1).is_some_and(|c| c.0.is_ascii_alphabetic()) {
            return (format!("?{}", s[i + 1].0), 2);
        }
        (s[i].0.to_string(), 1)
    }

    /// Splits a module string into (name, span, argument text) triples.
    fn module_parts<'s>(&self, s: &'s Chars) -> Result<Vec<(String, Span, Option<&'s Chars>)>, ParseError> {
        let mut out = Vec::new();
        let mut i = 0;
        while i < s.len() {
            let (c, at) = s[i];
            if c.is_whitespace() {
                i += 1;
                continue;
            }
            if matches!(c, '(' | ')' | ',' | ';' | ':') {
                return err(at, format!("unexpected `{c}` in a module string"));
            }
            let (name, len) = self.symbol_at(s, i);
            i += len;
            let mut args = None;
            if s.get(i).is_some_and(|c| c.0 == '(') {
                let open = i;
                let mut depth = 0;
                let mut close = None;
                for (j, c) in s.iter().enumerate().skip(open) {
                    match c.0 {
                        '(' => depth += 1,
                        ')' => {
                            depth -= 1;
                            if depth == 0 {
                                close = Some(j);
                                break;
                            }
                        }
                        _ => {}
                    }
                }
                let Some(close) = close else { return err(s[open].1, "`(` has no matching `)`") };
                args = Some(&s[open + 1..close]);
                i = close + 1;
            }
            out.push((name, at, args));
        }
        Ok(out)
    }

    /// Parses modules with argument expressions (axiom, successor).
    fn modules(&mut self, s: &Chars, formals: &[String]) -> Result<Vec<Module>, ParseError> {
        let parts = self.module_parts(s)?;
        let mut out = Vec::with_capacity(parts.len());
        for (name, span, args) in parts {
            let symbol = self.intern(&name);
            let args = match args {
                None => Vec::new(),
                Some(a) => split_commas(a)
                    .into_iter()
                    .map(|arg| {
                        if trim(arg).is_empty() {
                            err(span_of(arg, span), "empty argument")
                        } else {
                            self.expr(arg, formals, span)
                        }
                    })
                    .collect::<Result<_, _>>()?,
            };
            out.push(Module { symbol, args, span });
        }
        Ok(out)
    }

    /// Parses patterns: modules whose arguments are formal parameter names. Returns
    /// the patterns; formal names are checked by [`Parser::formals_of`].
    fn patterns(&mut self, s: &Chars) -> Result<Vec<Pattern>, ParseError> {
        Ok(self.patterns_with_names(s)?.into_iter().map(|(p, _)| p).collect())
    }

    fn patterns_with_names(&mut self, s: &Chars) -> Result<Vec<(Pattern, Vec<(String, Span)>)>, ParseError> {
        let parts = self.module_parts(s)?;
        let mut out = Vec::new();
        for (name, span, args) in parts {
            let symbol = self.intern(&name);
            let mut names = Vec::new();
            if let Some(a) = args {
                for arg in split_commas(a) {
                    let arg = trim(arg);
                    if arg.is_empty() || !is_ident_start(arg[0].0) || !arg.iter().all(|c| is_ident(c.0)) {
                        return err(span_of(arg, span), "a predecessor's parameters must be names, such as `A(x, y)`");
                    }
                    names.push((text_of(arg), arg[0].1));
                }
            }
            out.push((Pattern { symbol, arity: names.len() as u32, span }, names));
        }
        Ok(out)
    }

    fn production(&mut self, st: &Chars) -> Result<Production, ParseError> {
        let span = st[0].1;
        let mut body = st;
        let mut label = None;
        if let Some(colon) = find_top(st, ":") {
            let head = trim(&st[..colon]);
            let arrow = find_top(st, "->").unwrap_or(st.len());
            if colon < arrow && head.len() >= 2 && head.iter().all(|c| is_ident(c.0)) && is_ident_start(head[0].0) {
                let name: Vec<char> = head.iter().map(|c| c.0).collect();
                if !self.long_names.contains(&name) {
                    label = Some(text_of(head));
                    body = &st[colon + 1..];
                }
            }
        }
        let Some(arrow) = find_top(body, "->") else { return err(span, "a production needs `->`") };
        let (lhs, rhs) = (&body[..arrow], &body[arrow + 2..]);
        let (pred_part, cond_part) = match find_top(lhs, ":") {
            Some(i) => (&lhs[..i], Some(trim(&lhs[i + 1..]))),
            None => (lhs, None),
        };
        let (left_part, rest) = match find_top(pred_part, "<") {
            Some(i) => (Some(trim(&pred_part[..i])), &pred_part[i + 1..]),
            None => (None, pred_part),
        };
        let (strict, right_part) = match find_top(rest, ">") {
            Some(i) => (&rest[..i], Some(trim(&rest[i + 1..]))),
            None => (rest, None),
        };
        let context = |this: &mut Parser, part: Option<&Chars>| -> Result<Vec<(Pattern, Vec<(String, Span)>)>, ParseError> {
            match part {
                None => Ok(Vec::new()),
                Some(p) if text_of(p) == "*" => Ok(Vec::new()),
                Some(p) if p.is_empty() => err(span, "empty context: write `*` for any context, or leave out `<`/`>`"),
                Some(p) => this.patterns_with_names(p),
            }
        };
        let left = context(self, left_part)?;
        if let Some(bad) = left.iter().find(|(p, _)| p.symbol == SYM_PUSH || p.symbol == SYM_POP) {
            return err(bad.0.span, "a left context cannot contain brackets");
        }
        let mut pred = self.patterns_with_names(strict)?;
        if pred.len() != 1 {
            return err(span_of(trim(strict), span), format!("the predecessor must be exactly one module, got {}", pred.len()));
        }
        let right = context(self, right_part)?;
        // Formal parameters: left context, predecessor, right context, in order.
        let mut formals: Vec<String> = Vec::new();
        for (_, names) in left.iter().chain(pred.iter()).chain(right.iter()) {
            for (n, at) in names {
                if formals.contains(n) {
                    return err(*at, format!("parameter `{n}` is bound twice"));
                }
                if self.defines.contains_key(n) {
                    return err(*at, format!("parameter `{n}` has the name of a #define"));
                }
                formals.push(n.clone());
            }
        }
        let condition = match cond_part {
            None => None,
            Some(c) if text_of(c) == "*" => None,
            Some(c) if c.is_empty() => return err(span, "empty condition after `:`"),
            Some(c) => Some(self.expr(c, &formals, span)?),
        };
        let (succ_part, prob_part) = match find_top(rhs, ":") {
            Some(i) => (&rhs[..i], Some(trim(&rhs[i + 1..]))),
            None => (rhs, None),
        };
        let successor = self.modules(succ_part, &formals)?;
        let probability = match prob_part {
            None => None,
            Some(p) if p.is_empty() => return err(span, "empty probability after `:`"),
            Some(p) => Some(self.expr(p, &formals, span)?),
        };
        let key = format!(
            "{}|{}|{}|{}",
            text_of(trim(left_part.unwrap_or(&[]))),
            text_of(trim(strict)).split('(').next().unwrap_or(""),
            text_of(trim(right_part.unwrap_or(&[]))),
            cond_part.map(text_of).unwrap_or_default()
        );
        let next = self.groups.len() as u32;
        let group = *self.groups.entry(key).or_insert(next);
        let (pred, _) = pred.remove(0);
        Ok(Production {
            label,
            left: left.into_iter().map(|p| p.0).collect(),
            pred,
            right: right.into_iter().map(|p| p.0).collect(),
            condition,
            successor,
            probability,
            group,
            span,
        })
    }

    fn expr(&mut self, s: &Chars, formals: &[String], at: Span) -> Result<Expr, ParseError> {
        let toks = lex_expr(s)?;
        let mut ep = ExprParser { toks: &toks, pos: 0, formals, defines: &self.defines, sites: &mut self.sys.site_count, end: span_of(s, at) };
        let e = ep.or(0)?;
        if let Some(t) = toks.get(ep.pos) {
            return err(t.span, format!("unexpected `{}` in an expression", t.text));
        }
        Ok(e)
    }
}

/// Splits at commas of parenthesis depth 0.
fn split_commas(s: &Chars) -> Vec<&Chars> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in s.iter().enumerate() {
        match c.0 {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&s[start..]);
    out
}

struct ConstEnv;

impl crate::lang::expr::ExprEnv for ConstEnv {
    fn param(&self, _index: u32) -> f64 {
        f64::NAN
    }
    fn rand(&mut self, _site: u32) -> f64 {
        0.5
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Num(f64),
    Ident(String),
    Op,
}

#[derive(Debug, Clone)]
struct Tok {
    kind: Kind,
    text: String,
    span: Span,
}

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

struct ExprParser<'a> {
    toks: &'a [Tok],
    pos: usize,
    formals: &'a [String],
    defines: &'a HashMap<String, Expr>,
    sites: &'a mut u32,
    end: Span,
}

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

#[cfg(test)]
mod tests {
    use super::*;

    fn p(src: &str) -> LSystem {
        parse(src.as_bytes()).unwrap_or_else(|e| panic!("{e}"))
    }

    fn e(src: &str) -> String {
        parse(src.as_bytes()).expect_err("should fail").to_string()
    }

    #[test]
    fn parses_settings_and_a_production() {
        let s = p("iterations: 5\nangle: 25.7\naxiom: F\nF -> F[+F]F[-F]F\n");
        assert_eq!(s.iterations, 5);
        assert_eq!(s.angle, 25.7);
        assert_eq!(s.productions.len(), 1);
        assert_eq!(s.productions[0].successor.len(), 11);
    }

    #[test]
    fn parses_full_production_form() {
        let s = p("#define R 1.5\naxiom: A(1)\np1: B(a) < A(x) > C(y, z) : x < R && !(y == 2) -> A(x+1) F(x*R, rand()) : 0.5\n");
        let pr = &s.productions[0];
        assert_eq!(pr.label.as_deref(), Some("p1"));
        assert_eq!(pr.left.len(), 1);
        assert_eq!(pr.right[0].arity, 2);
        assert!(pr.condition.is_some() && pr.probability.is_some());
        assert_eq!(s.site_count, 1);
    }

    #[test]
    fn comments_and_continuation_lines() {
        let s = p("axiom: A // start\n/* block\n comment */ A -> F//F\n   [+A]\n");
        assert_eq!(s.productions[0].successor.len(), 8);
    }

    #[test]
    fn errors_have_positions() {
        assert!(e("axiom: F\nF -> F(1+)\n").starts_with("2:"), "{}", e("axiom: F\nF -> F(1+)\n"));
        assert!(e("axiom: F\nfoo: 3\n").contains("unknown setting"));
        assert!(e("F -> FF\n").contains("no `axiom:`"));
        assert!(e("axiom: F\nF(q) -> F(w)\n").contains("unknown name `w`"));
        assert!(e("axiom: F\nA(x,x) -> F\n").contains("bound twice"));
        assert!(e("axiom: F\n/* open\n").contains("unterminated comment"));
        assert!(e("axiom: F(\n").contains("no matching"));
        assert_eq!(e("axiom: F\nF -> F : \n"), "2:1: error: empty probability after `:`");
    }

    #[test]
    fn long_module_names() {
        let s = p("modules: draw rotateZ\naxiom: A(1)\nA(w) : w = 1 -> A(w+1) rotateZ(45) draw(2)\n");
        let names: Vec<&str> = s.productions[0].successor.iter().map(|m| s.symbols[m.symbol as usize].as_str()).collect();
        assert_eq!(names, ["A", "rotateZ", "draw"]);
    }
}
