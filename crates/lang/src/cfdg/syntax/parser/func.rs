//! User functions, typed parameters, `let` and vector indexing, after
//! `cfdg.ypp` (Context Free 3.4): `function_definition_header` (`[TYPE]
//! NAME(params) =`), `function_parameter_list`/`buncha_parameters` (typed
//! and untyped parameters), `letHeader`/`letBody`/`letVariables` and
//! `expfunc`'s `USER_ARRAYNAME '[' exp2 ']'`; the types as `ast.cpp`
//! `decodeType` reads them; a name is an array name only when `[` follows
//! it at once (`cfdg.l`'s `{STRING}` rule peeks at the next character).

use super::super::{Adjustment, Expr, Function, Param, ParamType, Replacement};
use super::{Parser, Tok};
use crate::{ParseError, Span};

/// Reads a type word as `AST::decodeType` does: `number`, `natural`,
/// `shape`, `adjustment`, or `vectorN` with N in 2..=99.
pub(super) fn decode_type(w: &str) -> Option<ParamType> {
    match w {
        "number" => Some(ParamType::Number),
        "natural" => Some(ParamType::Natural),
        "shape" => Some(ParamType::Shape),
        "adjustment" => Some(ParamType::Adjustment),
        _ => {
            let n: usize = w.strip_prefix("vector")?.parse().ok()?;
            (2..=99).contains(&n).then_some(ParamType::Vector(n))
        }
    }
}

impl Parser<'_> {
    /// Whether a function definition starts here: `[TYPE] NAME ( … ) =`;
    /// the number of type words (0 or 1) when it does.
    pub(super) fn function_header(&self) -> Option<usize> {
        let typed = match (self.peek(), self.peek_at(1)) {
            (Tok::Word(_), Tok::Punct("(")) => 0,
            (Tok::Word(_), Tok::Word(_)) if matches!(self.peek_at(2), Tok::Punct("(")) => 1,
            _ => return None,
        };
        if let Tok::Word(w) = self.peek() {
            if matches!(w.as_str(), "startshape" | "include" | "import" | "path" | "rule") || (typed == 0 && w == "shape") {
                return None;
            }
        }
        // The parameter list's parentheses, then `=`.
        let mut depth = 0usize;
        let mut k = typed + 1;
        loop {
            match self.peek_at(k) {
                Tok::Punct("(") => depth += 1,
                Tok::Punct(")") => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                Tok::Eof | Tok::Punct("{") | Tok::Punct("[") => return None,
                _ => {}
            }
            k += 1;
        }
        matches!(self.peek_at(k + 1), Tok::Punct("=")).then_some(typed)
    }

    /// `[TYPE] NAME(params) = expression` at the top level.
    pub(super) fn function(&mut self) -> Result<Function, ParseError> {
        let span = self.span();
        let typed = self.function_header().unwrap_or(0);
        let ret = if typed == 1 {
            let (w, wspan) = self.name("a type")?;
            match decode_type(&w) {
                Some(t) => t,
                None => return Err(ParseError::single(wspan, format!("unknown type `{w}` (number, natural, vectorN, shape or adjustment)"))),
            }
        } else {
            ParamType::Number
        };
        let (name, _) = self.name("a function name")?;
        if name.starts_with("CF::") {
            return Err(ParseError::single(span, "configuration names are reserved"));
        }
        let params = self.typed_params()?;
        self.expect("=")?;
        let body = self.expr(0)?;
        Ok(Function { name, params, ret, body, span })
    }

    /// The value of `CF::StartShape =`: a shape, its arguments, then
    /// optionally `, [adjustment]` (`Builder::MakeConfig`, `builder.cpp`:
    /// a rule specifier, then a modification).
    pub(super) fn start_setting(&mut self) -> Result<Replacement, ParseError> {
        let (shape, span) = self.name("a shape name")?;
        let args = if self.is_punct("(") { self.call_args(&shape)? } else { None };
        // cfdg reads `select(…)`/`if(…)` here as a function, not a shape
        // specification, and refuses it (`Builder::MakeConfig`).
        if matches!(shape.as_str(), "select" | "if" | "let") {
            return Err(ParseError::single(span, "`CF::StartShape` must start with a shape specification"));
        }
        if matches!(&args, Some(Expr::Var(v, _)) if v == super::REUSE) {
            return Err(ParseError::single(span, "the start shape cannot reuse parameters"));
        }
        let adjust = if self.is_punct(",") {
            self.bump();
            if !self.is_punct("[") {
                return self.err("`CF::StartShape`'s second term must be an adjustment");
            }
            self.adjustment()?
        } else {
            Adjustment { canonical: true, terms: Vec::new() }
        };
        Ok(Replacement { shape, adjust, args, span })
    }

    /// `( [TYPE] name, … )`: typed or untyped (number) parameters.
    pub(super) fn typed_params(&mut self) -> Result<Vec<Param>, ParseError> {
        self.expect("(")?;
        let mut out: Vec<Param> = Vec::new();
        while !self.is_punct(")") {
            let span = self.span();
            let ty_word = match self.peek().clone() {
                Tok::Word(w) => w,
                _ => return self.err("expected a parameter type or name"),
            };
            // An untyped parameter is a number.
            let (name, ty) = if matches!(self.peek_at(1), Tok::Punct(",") | Tok::Punct(")")) {
                (self.name("a parameter name")?.0, ParamType::Number)
            } else {
                let Some(ty) = decode_type(&ty_word) else {
                    return Err(ParseError::single(span, format!("unknown parameter type `{ty_word}` (number, natural, vectorN, shape or adjustment)")));
                };
                self.bump();
                (self.name("a parameter name")?.0, ty)
            };
            if self.is_punct("=") {
                return self.err("parameter defaults are not supported yet");
            }
            if out.iter().any(|p| p.name == name) {
                return Err(ParseError::single(span, format!("parameter `{name}` is declared twice")));
            }
            out.push(Param { name, ty });
            if !self.is_punct(",") {
                break;
            }
            self.bump();
        }
        self.expect(")")?;
        Ok(out)
    }

    /// `let ( name = exp2 ; … ; exp2 )` after the word `let`.
    pub(super) fn let_expr(&mut self, span: Span) -> Result<Expr, ParseError> {
        self.enter()?;
        self.expect("(")?;
        let mut defs = Vec::new();
        while matches!(self.peek(), Tok::Word(_)) && matches!(self.peek_at(1), Tok::Punct("=")) {
            let (name, _) = self.name("a name")?;
            self.bump();
            let e = self.expr(0)?;
            defs.push((name, e));
            self.expect(";")?;
        }
        if defs.is_empty() {
            return self.err("expected a definition `name = expression;` in `let`");
        }
        let body = self.expr(0)?;
        self.expect(")")?;
        self.depth -= 1;
        Ok(Expr::Let(defs, Box::new(body), span))
    }

    /// Whether the token after the name just read is a `[` written right
    /// against it (`v[0]`: an array name, as `cfdg.l` decides).
    pub(super) fn index_follows(&self, name: &str, span: Span) -> bool {
        self.is_punct("[") && {
            let s = self.toks[self.pos].span;
            s.line == span.line && s.column as usize == span.column as usize + name.chars().count()
        }
    }

    /// `[ index ]` or `[ index, length, stride ]` after an array name.
    pub(super) fn index_expr(&mut self, name: String, span: Span) -> Result<Expr, ParseError> {
        self.enter()?;
        self.expect("[")?;
        let e = self.expr(0)?;
        self.expect("]")?;
        self.depth -= 1;
        Ok(Expr::Index(name, Box::new(e), span))
    }
}
