//! The MDG parser: tokens → IR. Recursive descent whose recursion is bounded
//! by [`MAX_NESTING`], so hostile input gets an error, never a stack overflow.
//!
//! One `Parser` walks the token stream once. This file holds its state, the
//! token helpers and the top-level loop; each part of the language is parsed
//! by its own file, all of them `impl Parser` blocks in child modules:
//!
//! - `params.rs`: the `@` lines (`@define`, `@param`, `@presets`);
//! - `directives.rs`: keyword directives (`maxdepth`, `angle`, `selector`,
//!   `isosurface`, `namespace`, …) and the ones skipped with a warning;
//! - `mesh_decl.rs`: `mesh NAME { … }` declarations and named solids;
//! - `rules.rs`: `rule NAME { … }` and its body of calls, blocks and iterators;
//! - `adjustments.rs`: the `{ x 1 s 0.5 R 0.1 }` lists of calls and iterators;
//! - `expressions.rs`: arguments, `@define` values and constant values;
//! - `resolve.rs`: what happens at the end of the file: names resolved to
//!   rule groups, meshes, isosurfaces and primitives, and the [`Program`] assembled.

use super::lexer::{Tok, Token};
use crate::expr::Expr;
use crate::ir::{AngleMode, Directives, Isosurface, ParamDecl, Program, RuleGroup, Selector};
use crate::core::{Diagnostic, ParseError, Span};
use std::collections::HashMap;

#[path = "adjustments.rs"]
mod adjustments;
#[path = "directives.rs"]
mod directives;
#[path = "expressions.rs"]
mod expressions;
#[path = "mesh_decl.rs"]
mod mesh_decl;
#[path = "params.rs"]
mod params;
#[path = "resolve.rs"]
mod resolve;
#[path = "rules.rs"]
mod rules;

use params::Define;

/// Maximum nesting of blocks, iterator chains, parentheses and expression trees.
pub(crate) const MAX_NESTING: u32 = crate::expr::grammar::MAX_NESTING;

/// The parameter `@presets` declares.
pub(crate) const PRESET_PARAM: &str = "preset";

/// The largest `fps` a grammar may set (frames are sampled per tick).
pub(crate) const MAX_FPS: f64 = 240.0;

/// The longest `duration` a grammar may set, in seconds.
pub(crate) const MAX_DURATION: f64 = 3600.0;

type PResult<T> = Result<T, ParseError>;

/// The parser's state: the tokens and the position in them, and everything
/// recorded along the way for the IR, including the names resolved at the end.
pub(crate) struct Parser<'a> {
    toks: Vec<Token<'a>>,
    pos: usize,
    /// Tokens at or beyond this index read as end of input (used for line-bounded constructs).
    end: usize,
    mode: AngleMode,
    depth: u32,
    groups: Vec<RuleGroup>,
    group_index: HashMap<String, u32>,
    defines: HashMap<&'a str, Define>,
    params: Vec<ParamDecl>,
    param_index: HashMap<&'a str, u32>,
    site: u32,
    /// Unresolved call names with their sites and the namespace they are
    /// written in, in increasing site order.
    call_names: Vec<(u32, &'a str, Span, Option<&'a str>)>,
    directives: Directives,
    startshape: Option<(&'a str, Span)>,
    warnings: Vec<Diagnostic>,
    /// Budget of expression nodes copied by `@define` substitution.
    subst_budget: usize,
    /// `selector` directives, applied to their groups once every rule is known.
    selectors: Vec<(&'a str, Span, PendingSelector<'a>)>,
    /// `function NAME { expr }` definitions of x, y, z.
    functions: HashMap<&'a str, Expr>,
    /// True while parsing a function of position, where `x`, `y`, `z` name coordinates.
    coords: bool,
    /// Names to resolve to groups at the end: transform-rule paths and line
    /// profiles, with the namespace they are written in.
    group_refs: Vec<(GroupRef, &'a str, Span, Option<&'a str>)>,
    /// `linerule NAME`, resolved at the end.
    linerule: Option<(&'a str, Span)>,
    /// `camerarule NAME`, resolved at the end.
    camerarule: Option<(&'a str, Span)>,
    /// The namespace being parsed (`namespace NS { … }`), if any.
    namespace: Option<&'a str>,
    /// Namespace names; index 0 is the global one, "".
    namespace_names: Vec<String>,
    /// The namespace of each call site that is not the global one.
    site_namespace: Vec<(u32, u32)>,
    /// Names of the colour adjustments (`color` renames R G B A).
    colour_names: [&'a str; 4],
    /// Names of the vertex-weight adjustments (`weight` renames u v w q).
    weight_names: [&'a str; 4],
    /// `isosurface` declarations and their names.
    isosurfaces: Vec<Isosurface>,
    isosurface_index: HashMap<&'a str, u32>,
    /// `mesh` declarations and implicitly declared solids, and their names.
    meshes: Vec<crate::ir::MeshDecl>,
    mesh_index: HashMap<String, u32>,
}

/// Where a group name that must be resolved at the end belongs.
#[derive(Debug, Clone, Copy)]
enum GroupRef {
    /// Path `index` of rule `rule` of group `group`.
    Path { group: u32, rule: usize, index: usize },
    /// The profile of the line drawable at call site `site`.
    Profile { site: u32 },
}

/// A selector mode as written; a named function is looked up at the end.
#[derive(Clone)]
enum PendingSelector<'a> {
    Ready(Selector),
    Named(&'a str, Span),
}

fn err(span: Span, msg: impl Into<String>) -> ParseError {
    ParseError::single(span, msg)
}

impl<'a> Parser<'a> {
    /// A parser over `toks` (the lexer's output, ending with `Tok::Eof`);
    /// `source_len`, the source's length in bytes, sizes the `@define` substitution budget.
    pub(crate) fn new(toks: Vec<Token<'a>>, source_len: usize) -> Parser<'a> {
        let end = toks.len().saturating_sub(1);
        let mode = prescan_angle(&toks);
        Parser {
            toks,
            pos: 0,
            end,
            mode,
            depth: 0,
            groups: Vec::new(),
            group_index: HashMap::new(),
            defines: HashMap::new(),
            params: Vec::new(),
            param_index: HashMap::new(),
            site: 0,
            call_names: Vec::new(),
            directives: Directives { angle: mode, ..Directives::default() },
            startshape: None,
            warnings: Vec::new(),
            subst_budget: source_len.saturating_mul(4).saturating_add(64 * 1024),
            selectors: Vec::new(),
            functions: HashMap::new(),
            coords: false,
            group_refs: Vec::new(),
            linerule: None,
            camerarule: None,
            namespace: None,
            namespace_names: vec![String::new()],
            site_namespace: Vec::new(),
            colour_names: ["R", "G", "B", "A"],
            weight_names: ["u", "v", "w", "q"],
            isosurfaces: Vec::new(),
            isosurface_index: HashMap::new(),
            meshes: Vec::new(),
            mesh_index: HashMap::new(),
        }
    }

    // ----- token helpers -----

    fn tok_at(&self, i: usize) -> Token<'a> {
        let last = self.toks.len().saturating_sub(1);
        if i >= self.end {
            // End of a bounded region: report at the next real token (or the end).
            let t = self.toks.get(i.min(last)).or(self.toks.last()).copied();
            let span = t.map_or(Span::new(1, 1), |t| t.span);
            return Token { tok: Tok::Eof, span, line: t.map_or(0, |t| t.line) };
        }
        self.toks.get(i).copied().unwrap_or(Token { tok: Tok::Eof, span: Span::new(1, 1), line: 0 })
    }

    fn peek(&self) -> Token<'a> {
        self.tok_at(self.pos)
    }

    fn peek2(&self) -> Token<'a> {
        self.tok_at(self.pos + 1)
    }

    fn bump(&mut self) -> Token<'a> {
        let t = self.peek();
        if self.pos < self.end {
            self.pos += 1;
        }
        t
    }

    fn is_punct(&self, c: char) -> bool {
        self.peek().tok == Tok::Punct(c)
    }

    fn expect_punct(&mut self, c: char, context: impl FnOnce() -> String) -> PResult<Token<'a>> {
        let t = self.peek();
        if t.tok == Tok::Punct(c) {
            Ok(self.bump())
        } else {
            Err(err(t.span, format!("expected `{c}` {}, found {}", context(), t.tok)))
        }
    }

    fn enter(&mut self, span: Span) -> PResult<()> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    fn next_site(&mut self, span: Span) -> PResult<u32> {
        let s = self.site;
        self.site = self.site.checked_add(1).ok_or_else(|| err(span, "too many call sites"))?;
        Ok(s)
    }

    // ----- top level -----

    /// Parses the whole token stream into a program.
    pub(crate) fn parse_program(mut self) -> PResult<Program> {
        if self.peek().tok == Tok::Eof {
            return Err(err(Span::new(1, 1), "empty source: expected `startshape` or `rule`"));
        }
        loop {
            let t = self.peek();
            match t.tok {
                Tok::Eof => break,
                Tok::At(w) => self.preprocessor_line(w, t)?,
                Tok::Ident(w) => self.directive(w, t)?,
                other => {
                    return Err(err(t.span, format!("expected `rule`, `startshape` or a directive, found {other}")))
                }
            }
        }
        self.finish()
    }

    /// Index just past the last token on the same (preprocessed) line as token `from`.
    fn line_end(&self, from: usize) -> usize {
        let line = self.tok_at(from).line;
        let mut i = from;
        while i < self.end && self.toks.get(i).is_some_and(|t| t.line == line) {
            i += 1;
        }
        i
    }

    fn name_after(&mut self, what: &str) -> PResult<(&'a str, Span)> {
        let t = self.bump();
        match t.tok {
            Tok::Ident(n) => Ok((n, t.span)),
            other => Err(err(t.span, format!("expected a name after `{what}`, found {other}"))),
        }
    }
}

/// Finds the first top-level `angle MODE` so that it applies to the whole file.
fn prescan_angle(toks: &[Token]) -> AngleMode {
    let mut level = 0i64;
    let mut prev: Option<Tok> = None;
    for (i, t) in toks.iter().enumerate() {
        match t.tok {
            Tok::Punct('{' | '[' | '(') => level += 1,
            Tok::Punct('}' | ']' | ')') => level -= 1,
            Tok::Ident(w) if level == 0 && w.eq_ignore_ascii_case("angle") => {
                let after_name = matches!(prev, Some(Tok::Ident(p)) if p.eq_ignore_ascii_case("rule") || p.eq_ignore_ascii_case("startshape"));
                if !after_name {
                    if let Some(Tok::Ident(m)) = toks.get(i + 1).map(|t| t.tok) {
                        match m.to_ascii_lowercase().as_str() {
                            "radians" => return AngleMode::Radians,
                            "orbits" => return AngleMode::Orbits,
                            "degrees" => return AngleMode::Degrees,
                            _ => {}
                        }
                    }
                }
            }
            _ => {}
        }
        prev = Some(t.tok);
    }
    AngleMode::Degrees
}
