//! The `@` lines: `@define NAME expr` (a named constant expression,
//! substituted where the name is used), `@param int|float|bool NAME default
//! [min max]` (a value a request may set) and `@presets a b c` (named choices
//! of the `preset` parameter). Each takes exactly one preprocessed line.

use super::expressions::{num, Ctx, E};
use super::{err, PResult, Parser, PRESET_PARAM};
use crate::ir::{ParamDecl, ParamKind};
use crate::mdg::syntax::lexer::{Tok, Token};
use crate::core::{Diagnostic, Span};

/// The value of an `@define`, substituted (copied) wherever its name is read.
pub(super) struct Define {
    /// The defined expression, with its size for the substitution budget.
    pub(super) expr: E,
}

impl<'a> Parser<'a> {
    /// One `@` line (`t` is its `@WORD` token), read only up to the end of its line.
    pub(super) fn preprocessor_line(&mut self, word: &str, t: Token<'a>) -> PResult<()> {
        let stop = self.line_end(self.pos);
        let saved_end = self.end;
        self.end = stop;
        self.bump();
        let r = match word.to_ascii_lowercase().as_str() {
            "define" => self.define(t.span),
            "param" => self.param(t.span),
            "presets" => self.presets(t.span),
            _ => Err(err(t.span, format!("unexpected `@{word}`"))),
        };
        r?;
        if self.pos < stop {
            let u = self.peek();
            return Err(err(u.span, format!("unexpected {} at the end of `@{word}`", u.tok)));
        }
        self.end = saved_end;
        Ok(())
    }

    fn define(&mut self, span: Span) -> PResult<()> {
        let (name, nspan) = self.name_after("@define")?;
        if self.param_index.contains_key(name) {
            return Err(err(nspan, format!("`{name}` is already a @param")));
        }
        if self.peek().tok == Tok::Eof {
            return Err(err(self.peek().span, format!("expected a value after `@define {name}`")));
        }
        let e = self.expr(Ctx::Plain)?;
        if self.defines.contains_key(name) {
            self.warnings.push(Diagnostic::warning(span, format!("`@define {name}` redefines `{name}`")));
        }
        self.defines.insert(name, Define { expr: e });
        Ok(())
    }

    fn signed_literal(&mut self, what: &str) -> PResult<(f64, Span)> {
        let t = self.peek();
        let neg = t.tok == Tok::Punct('-');
        if neg {
            self.bump();
        }
        let u = self.bump();
        match u.tok {
            Tok::Num { value, suffix: None, .. } => Ok((if neg { -value } else { value }, t.span)),
            other => Err(err(u.span, format!("expected a number for {what}, found {other}"))),
        }
    }

    /// `@presets a b c`: named presets (Andersson 2015, Table B.2). Declares the int
    /// parameter `preset` (0 ..= n − 1, default 0, the first) and each name
    /// as the constant of its index, so a grammar reads e.g. `preset == b`
    /// or `preset * { … }`, and a request picks `preset=b` by name.
    fn presets(&mut self, span: Span) -> PResult<()> {
        if self.param_index.contains_key(PRESET_PARAM) || self.defines.contains_key(PRESET_PARAM) {
            return Err(err(span, format!("`{PRESET_PARAM}` is already defined (one `@presets` per grammar)")));
        }
        let mut names: Vec<&'a str> = Vec::new();
        while self.peek().tok != Tok::Eof {
            let (n, nspan) = self.name_after("@presets")?;
            if names.contains(&n) || self.defines.contains_key(n) || self.param_index.contains_key(n) {
                return Err(err(nspan, format!("preset name `{n}` is already defined")));
            }
            names.push(n);
        }
        if names.is_empty() {
            return Err(err(span, "expected preset names after `@presets`"));
        }
        for (i, n) in names.iter().enumerate() {
            self.defines.insert(n, Define { expr: num(i as f64) });
        }
        let index = u32::try_from(self.params.len()).map_err(|_| err(span, "too many @params"))?;
        self.params.push(ParamDecl {
            name: PRESET_PARAM.to_string(),
            kind: ParamKind::Int,
            default: 0.0,
            range: Some((0.0, (names.len() - 1) as f64)),
            span,
            choices: names.iter().map(|n| n.to_string()).collect(),
        });
        self.param_index.insert(PRESET_PARAM, index);
        Ok(())
    }

    fn param(&mut self, span: Span) -> PResult<()> {
        let kt = self.bump();
        let kind = match kt.tok {
            Tok::Ident("int") => ParamKind::Int,
            Tok::Ident("float") => ParamKind::Float,
            Tok::Ident("bool") => ParamKind::Bool,
            other => return Err(err(kt.span, format!("expected `int`, `float` or `bool` after `@param`, found {other}"))),
        };
        let (name, nspan) = self.name_after("@param type")?;
        if self.param_index.contains_key(name) || self.defines.contains_key(name) {
            return Err(err(nspan, format!("`{name}` is already defined")));
        }
        let (default, dspan) = if kind == ParamKind::Bool {
            let t = self.bump();
            let v = match t.tok {
                Tok::Ident("true") => 1.0,
                Tok::Ident("false") => 0.0,
                Tok::Num { value, suffix: None, .. } if value == 0.0 || value == 1.0 => value,
                other => return Err(err(t.span, format!("expected `true`, `false`, 0 or 1 for bool `{name}`, found {other}"))),
            };
            (v, t.span)
        } else {
            self.signed_literal(&format!("the default of `{name}`"))?
        };
        let whole = |v: f64| v.fract() == 0.0;
        if kind == ParamKind::Int && !whole(default) {
            return Err(err(dspan, format!("default of int `{name}` must be a whole number, found {default}")));
        }
        let mut range = None;
        if self.peek().tok != Tok::Eof {
            let (lo, lspan) = self.signed_literal(&format!("the minimum of `{name}`"))?;
            let (hi, hspan) = self.signed_literal(&format!("the maximum of `{name}`"))?;
            if kind == ParamKind::Int && !whole(lo) {
                return Err(err(lspan, format!("minimum of int `{name}` must be a whole number")));
            }
            if kind == ParamKind::Int && !whole(hi) {
                return Err(err(hspan, format!("maximum of int `{name}` must be a whole number")));
            }
            if !(lo <= default && default <= hi) {
                return Err(err(dspan, format!("default {default} of `{name}` is outside [{lo}, {hi}]")));
            }
            range = Some((lo, hi));
        }
        let index = u32::try_from(self.params.len()).map_err(|_| err(span, "too many @params"))?;
        self.params.push(ParamDecl { name: name.to_string(), kind, default, range, span, choices: Vec::new() });
        self.param_index.insert(name, index);
        Ok(())
    }
}
