//! Productions (`label: left < pred(x) > right : condition -> successor :
//! probability`) and the module strings they are made of: axioms and
//! successors (modules with argument expressions) and predecessors and
//! contexts (patterns with formal parameter names).

use super::statements::{find_top, is_ident, is_ident_start, span_of, split_commas, text_of, trim};
use super::{err, Chars, Parser};
use crate::lsystem::syntax::{Module, Pattern, Production, SYM_POP, SYM_PUSH};
use crate::core::{ParseError, Span};

impl Parser {
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
    pub(super) fn modules(&mut self, s: &Chars, formals: &[String]) -> Result<Vec<Module>, ParseError> {
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
    pub(super) fn patterns(&mut self, s: &Chars) -> Result<Vec<Pattern>, ParseError> {
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

    pub(super) fn production(&mut self, st: &Chars) -> Result<Production, ParseError> {
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
}
