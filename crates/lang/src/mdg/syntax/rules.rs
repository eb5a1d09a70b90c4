//! `rule NAME [weight | * path : … | : path : …] { body }` and the body it
//! contains: rule calls (including the line drawables `MOVETO`, `LINETO`, …
//! and the specials `VERTEX`, `FACENORMALS`, `FRAME`), `{ … }` blocks,
//! `\` continuations and `count * { step } body` iterators. Call targets are
//! recorded by name here and filled in at the end (see `resolve.rs`).

use super::expressions::{Ctx, What};
use super::{err, GroupRef, PResult, Parser};
use crate::expr::Expr;
use crate::ir::{Call, Item, Iterate, LineOp, PrimitiveKind, Rule, RuleGroup, RuleTransform, Selector, Target};
use crate::mdg::syntax::lexer::Tok;
use crate::core::{Diagnostic, Span};

impl<'a> Parser<'a> {
    /// `rule NAME …` (the keyword, at `span`, is already consumed).
    pub(super) fn rule(&mut self, span: Span) -> PResult<()> {
        let (short, _) = self.name_after("rule")?;
        let qualified = self.namespace.map(|ns| format!("{ns}.{short}"));
        let name: &str = qualified.as_deref().unwrap_or(short);
        let mut weight = 1.0;
        let mut paths: Vec<(&'a str, Span)> = Vec::new();
        let mut convolve = false;
        let t = self.peek();
        match t.tok {
            Tok::Punct(':') | Tok::Punct('*') => {
                // `* path : t1 : t2` (convolve) or `: x1 : x2` (animate).
                convolve = t.tok == Tok::Punct('*');
                self.bump();
                paths.push(self.name_after("a transform rule")?);
                while self.is_punct(':') {
                    self.bump();
                    paths.push(self.name_after("`:` in a transform rule")?);
                }
            }
            Tok::Punct('{') => {}
            _ if self.starts_arg() => {
                let (w, wspan) = self.const_value(&format!("the weight of rule `{name}`"))?;
                if w < 0.0 {
                    return Err(err(wspan, format!("the weight of rule `{name}` must be ≥ 0, found {w}")));
                }
                weight = w;
            }
            _ => {}
        }
        self.expect_punct('{', || format!("after rule name `{name}`"))?;
        self.enter(span)?;
        let body = self.items(&format!("rule `{name}`"))?;
        self.leave();
        let id = match self.group_index.get(name) {
            Some(&g) => g,
            None => {
                let g = u32::try_from(self.groups.len()).map_err(|_| err(span, "too many rules"))?;
                self.groups.push(RuleGroup { name: name.to_string(), rules: Vec::new(), selector: Selector::Random });
                self.group_index.insert(name.to_string(), g);
                g
            }
        };
        let transform = match (paths.is_empty(), convolve) {
            (true, _) => RuleTransform::None,
            (false, true) => RuleTransform::Convolve(vec![0; paths.len()]),
            (false, false) => RuleTransform::Animate(vec![0; paths.len()]),
        };
        if let Some(g) = self.groups.get_mut(id as usize) {
            let rule = g.rules.len();
            for (index, (p, pspan)) in paths.into_iter().enumerate() {
                self.group_refs.push((GroupRef::Path { group: id, rule, index }, p, pspan, self.namespace));
            }
            g.rules.push(Rule { weight, transform, body, span });
        }
        Ok(())
    }

    // ----- bodies -----

    /// Items up to and including the closing `}`.
    fn items(&mut self, what: &str) -> PResult<Vec<Item>> {
        let mut items = Vec::new();
        loop {
            let t = self.peek();
            match t.tok {
                Tok::Punct('}') => {
                    self.bump();
                    return Ok(items);
                }
                Tok::Eof => return Err(err(t.span, format!("expected `}}` to close {what}, found end of input"))),
                // A trailing `\\` has nothing to continue: it is a no-op.
                Tok::Punct('\\') if self.peek2().tok == Tok::Punct('}') => {
                    self.bump();
                }
                _ => items.push(self.item()?),
            }
        }
    }

    fn item(&mut self) -> PResult<Item> {
        let t = self.peek();
        match t.tok {
            Tok::Punct('{') => {
                self.bump();
                self.enter(t.span)?;
                let items = self.items("block")?;
                self.leave();
                Ok(Item::Block(items))
            }
            Tok::Punct('\\') => {
                // `\ item`: the next call continues from the last terminal's frame.
                self.bump();
                if self.is_punct('\\') {
                    return Err(err(self.peek().span, "expected a call after `\\`, found another `\\`"));
                }
                let mut item = self.item()?;
                mark_continuation(&mut item);
                Ok(item)
            }
            Tok::Num { .. } | Tok::Punct('(') | Tok::Punct('-') => self.iterator(),
            Tok::Ident(name) => {
                let next = self.peek2().tok;
                if (next == Tok::Punct('*') || next == Tok::Punct('/')) && self.is_value_name(name) {
                    return self.iterator();
                }
                self.call()
            }
            other => Err(err(t.span, format!("expected a rule call, block or iterator, found {other}"))),
        }
    }

    fn call(&mut self) -> PResult<Item> {
        let t = self.bump();
        let Tok::Ident(name) = t.tok else {
            return Err(err(t.span, format!("expected a rule call, found {}", t.tok)));
        };
        // `NS.LINETO` draws with namespace NS's pen (Andersson 2015 §4.1.4).
        let (prefix, base) = match name.rsplit_once('.') {
            Some((p, b)) => (Some(p), b),
            None => (None, name),
        };
        let line_op = match base.to_ascii_uppercase().as_str() {
            "MOVETO" => Some(LineOp::MoveTo),
            "LINETO" | "ALINETO" => Some(LineOp::LineTo),
            "SLINETO" => Some(LineOp::SLineTo),
            "BLENDTO" => Some(LineOp::BlendTo),
            "NEWLINE" => Some(LineOp::NewLine),
            "RESET" => Some(LineOp::Reset),
            _ => None,
        };
        if line_op.is_none() && base.eq_ignore_ascii_case("DEBUG") {
            // Debug output of the thesis's viewer: no geometry.
            self.expect_punct('{', || format!("after `{name}`"))?;
            self.adjustments('}')?;
            self.warnings.push(Diagnostic::warning(t.span, format!("`{name}` ignored: debug output draws nothing")));
            return Ok(Item::Block(Vec::new()));
        }
        let namespace = match (line_op, prefix) {
            (Some(_), Some(p)) => Some(p),
            _ => self.namespace,
        };
        let mut profile = None;
        if line_op.is_some() {
            if let Tok::Ident(p) = self.peek().tok {
                profile = Some((p, self.bump().span));
            }
        }
        self.expect_punct('{', || format!("after rule name `{name}`"))?;
        let site = self.next_site(t.span)?;
        if let Some(ns) = namespace {
            let id = self.namespace_id(ns, t.span)?;
            self.site_namespace.push((site, id));
        }
        let adjust = self.adjustments('}')?;
        let special = match name.to_ascii_uppercase().as_str() {
            "VERTEX" => Some(Target::Vertex),
            "FACENORMALS" => Some(Target::FaceNormals),
            "FRAME" => Some(Target::Frame),
            _ => None,
        };
        let target = match (line_op, special) {
            (Some(op), _) => {
                if let Some((p, pspan)) = profile {
                    self.group_refs.push((GroupRef::Profile { site }, p, pspan, self.namespace));
                }
                Target::Line(op, None)
            }
            (None, Some(t)) => t,
            (None, None) => {
                self.call_names.push((site, name, t.span, self.namespace));
                Target::Primitive(PrimitiveKind::Box)
            }
        };
        Ok(Item::Call(Call { target, adjust, site, continues: false, span: t.span }))
    }

    fn iterator(&mut self) -> PResult<Item> {
        let start = self.peek().span;
        self.enter(start)?;
        let count = self.arg(Ctx::Plain, What::Text("an iteration count"))?;
        if let Expr::Num(v) = count.expr {
            if v < 0.0 || v.fract() != 0.0 {
                return Err(err(start, format!("iteration count must be a whole number ≥ 0, found {v}")));
            }
        }
        let mut divisor = None;
        if self.is_punct('/') {
            self.bump();
            divisor = Some(self.arg(Ctx::Plain, What::Text("an iteration divisor"))?.expr);
        }
        self.expect_punct('*', || "after the iteration count".to_string())?;
        let site = self.next_site(start)?;
        let t = self.peek();
        let close = match t.tok {
            Tok::Punct('{') => '}',
            Tok::Punct('[') => ']',
            other => return Err(err(t.span, format!("expected `{{` or `[` after `*`, found {other}"))),
        };
        self.bump();
        let step = self.adjustments(close)?;
        let body = match self.peek().tok {
            Tok::Punct('\\') => self.item()?,
            Tok::Punct('{') | Tok::Num { .. } | Tok::Punct('(') | Tok::Punct('-') | Tok::Ident(_) => self.item()?,
            other => {
                return Err(err(self.peek().span, format!("expected a rule call, block or iterator after the iterator step, found {other}")))
            }
        };
        self.leave();
        Ok(Item::Iterate(Iterate { count: count.expr, divisor, step, body: Box::new(body), continues: false, site, span: start }))
    }
}

/// Marks the item after `\\` as continuing: a call, an iterator (whose
/// copies are then placed from the last terminal's frame, so
/// SMOOTH_TRIANGLE's `\\ 10/10 * {rx 120} LINETO{}` turns the pen), or the
/// first of a block's items.
fn mark_continuation(item: &mut Item) {
    let mut cur = item;
    loop {
        match cur {
            Item::Call(c) => {
                c.continues = true;
                return;
            }
            Item::Iterate(it) => {
                it.continues = true;
                return;
            }
            Item::Block(b) => match b.first_mut() {
                Some(first) => cur = first,
                None => return,
            },
        }
    }
}
