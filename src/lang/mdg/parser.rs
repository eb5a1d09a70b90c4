//! The MDG parser: tokens → IR. Recursive descent whose recursion is bounded
//! by [`MAX_NESTING`], so hostile input gets an error, never a stack overflow.

use super::lexer::{Tok, Token};
use crate::lang::expr::{BinOp, Expr, ExprEnv, Func};
use crate::lang::ir::{GroupId, Isosurface, LineOp, Namespaces, RuleTransform, Selector};
use crate::lang::ir::{
    Adjust, AdjustOp, AngleMode, Axis, Call, Directives, Item, Iterate, ParamDecl, ParamKind, PrimitiveKind,
    Program, Rule, RuleGroup, Target,
};
use crate::core::{Diagnostic, ParseError, Span};
use std::collections::HashMap;
use std::f64::consts::{FRAC_PI_2, PI};

#[path = "mesh_decl.rs"]
mod mesh_decl;

/// Maximum nesting of blocks, iterator chains, parentheses and expression trees.
pub const MAX_NESTING: u32 = 256;

/// Top-level directives that are skipped (to the end of their line) with a warning.
const SKIPPED_DIRECTIVES: [&str; 5] = [
    "uniform",
    "buffer",
    "invalidateskipframes",
    "cameramode",
    "render",
];

/// The parameter `@presets` declares.
pub const PRESET_PARAM: &str = "preset";

/// The largest `fps` a grammar may set (frames are sampled per tick).
pub const MAX_FPS: f64 = 240.0;

/// The longest `duration` a grammar may set, in seconds.
pub const MAX_DURATION: f64 = 3600.0;

/// Adjustment keywords (case-sensitive); a bare name equal to one of these is never an argument.
const ADJUST_WORDS: &[&str] = &[
    "x", "y", "z", "r", "rotate", "rx", "pitch", "ry", "yaw", "rz", "roll", "up", "down", "left", "right",
    "rolleft", "rollleft", "rollright", "s", "f", "fx", "fy", "fz", "R", "G", "B", "A", "u", "v", "w", "q",
    "fps",
];

type PResult<T> = Result<T, ParseError>;

/// An expression with its tree depth.
#[derive(Clone)]
struct E {
    e: Expr,
    depth: u32,
    nodes: usize,
}

struct Define {
    expr: E,
}

/// Which angle unit literals are interpreted in.
#[derive(Clone, Copy, PartialEq)]
enum Ctx {
    /// A plain number: `d`/`t` literals become radians.
    Plain,
    /// An angle argument: literals are in the mode's unit, `d`/`t` converted into it.
    Angle,
}

/// What an argument belongs to, for error messages (formatted only on error).
#[derive(Clone, Copy)]
enum What<'s> {
    /// After an adjustment or directive keyword.
    After(&'s str),
    /// A description such as "an iteration count".
    Text(&'s str),
}

impl std::fmt::Display for What<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            What::After(w) => write!(f, "after `{w}`"),
            What::Text(t) => write!(f, "for {t}"),
        }
    }
}

struct NaNEnv;
impl ExprEnv for NaNEnv {
    fn param(&self, _: u32) -> f64 {
        f64::NAN
    }
    fn rand(&mut self, _: u32) -> f64 {
        f64::NAN
    }
}

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
    meshes: Vec<crate::lang::ir::MeshDecl>,
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

fn num(v: f64) -> E {
    E { e: Expr::Num(v), depth: 1, nodes: 1 }
}

fn is_const(e: &Expr) -> bool {
    match e {
        Expr::Num(_) => true,
        Expr::Param(_) | Expr::Rand(_) | Expr::Coord(_) => false,
        Expr::Neg(a) => is_const(a),
        Expr::Binary(_, a, b) => is_const(a) && is_const(b),
        Expr::Func(_, args) => args.iter().all(is_const),
    }
}

impl<'a> Parser<'a> {
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

    fn finish(mut self) -> PResult<Program> {
        self.declare_named_solids()?;
        let start = match self.startshape {
            Some((name, span)) => self.resolve(name, span)?,
            // Thesis listings without `startshape` (C.4) start from `START`.
            None if self.group_index.contains_key("START") => Target::Group(self.group_index["START"]),
            None if !self.groups.is_empty() => Target::Group(0),
            None => {
                let span = self.peek().span;
                return Err(err(span, "no rules: expected at least one `rule` or a `startshape`"));
            }
        };
        // Resolve call targets, in site order for a stable first error.
        let mut targets: Vec<Option<Target>> = vec![None; self.site as usize];
        for &(site, name, span, ns) in &self.call_names {
            if let Some(slot) = targets.get_mut(site as usize) {
                *slot = Some(self.resolve_in(ns, name, span)?);
            }
        }
        let mut groups = std::mem::take(&mut self.groups);
        let group_of = |ns: Option<&str>, name: &str, span: Span| match self.group_in(ns, name) {
            Some(g) => Ok(g),
            None => Err(err(span, format!("unknown rule `{name}`"))),
        };
        let mut profiles: Vec<Option<GroupId>> = vec![None; self.site as usize];
        for &(r, name, span, ns) in &self.group_refs {
            let g = group_of(ns, name, span)?;
            match r {
                GroupRef::Path { group, rule, index } => {
                    let slot = groups
                        .get_mut(group as usize)
                        .and_then(|gr| gr.rules.get_mut(rule))
                        .and_then(|ru| match &mut ru.transform {
                            RuleTransform::Convolve(v) | RuleTransform::Animate(v) => v.get_mut(index),
                            RuleTransform::None => None,
                        });
                    if let Some(slot) = slot {
                        *slot = g;
                    }
                }
                GroupRef::Profile { site } => {
                    if let Some(slot) = profiles.get_mut(site as usize) {
                        *slot = Some(g);
                    }
                }
            }
        }
        let linerule = self.linerule.map(|(name, span)| group_of(None, name, span)).transpose()?;
        let camerarule = self.camerarule.map(|(name, span)| group_of(None, name, span)).transpose()?;
        self.directives.linerule = linerule;
        self.directives.camerarule = camerarule;
        let lens = self.directives.camera;
        if lens.far <= lens.near {
            return Err(err(Span::new(1, 1), format!("camerafarplane ({}) must be beyond cameranearplane ({})", lens.far, lens.near)));
        }
        for (name, span, pending) in std::mem::take(&mut self.selectors) {
            let selector = match pending {
                PendingSelector::Ready(s) => s,
                PendingSelector::Named(f, fspan) => match self.functions.get(f) {
                    Some(e) => Selector::Function(e.clone()),
                    None => return Err(err(fspan, format!("unknown function `{f}`"))),
                },
            };
            match self.group_index.get(name).and_then(|&g| groups.get_mut(g as usize)) {
                Some(g) => g.selector = selector,
                None => return Err(err(span, format!("selector names `{name}`, which has no rules"))),
            }
        }
        for g in &mut groups {
            for r in &mut g.rules {
                set_targets(&mut r.body, &targets, &profiles);
            }
        }
        Ok(Program {
            start,
            groups,
            directives: self.directives,
            params: self.params,
            site_count: self.site,
            warnings: self.warnings,
            isosurfaces: self.isosurfaces,
            namespaces: namespace_table(self.namespace_names, &self.site_namespace, self.site),
            meshes: self.meshes,
        })
    }

    /// The group `name` names when written in namespace `ns`: `ns.name`
    /// first, then the global `name` (a qualified `a.B` is looked up as is).
    fn group_in(&self, ns: Option<&str>, name: &str) -> Option<u32> {
        if let Some(ns) = ns.filter(|_| !name.contains('.')) {
            if let Some(&g) = self.group_index.get(&format!("{ns}.{name}")) {
                return Some(g);
            }
        }
        self.group_index.get(name).copied()
    }

    /// [`Self::resolve`] for a call written in namespace `ns`.
    fn resolve_in(&self, ns: Option<&str>, name: &str, span: Span) -> PResult<Target> {
        match self.group_in(ns, name) {
            Some(g) => Ok(Target::Group(g)),
            None => self.resolve(name, span),
        }
    }

    /// The index of namespace `name` (declared or only referenced, as `X.LINETO` may).
    fn namespace_id(&mut self, name: &str, span: Span) -> PResult<u32> {
        if let Some(i) = self.namespace_names.iter().position(|n| n == name) {
            return Ok(i as u32);
        }
        let i = u32::try_from(self.namespace_names.len()).map_err(|_| err(span, "too many namespaces"))?;
        self.namespace_names.push(name.to_string());
        Ok(i)
    }

    /// Whether `w` is an adjustment keyword (under the current colour and weight names).
    fn is_adjust_word(&self, w: &str) -> bool {
        ADJUST_WORDS.contains(&w) || self.colour_names.contains(&w) || self.weight_names.contains(&w)
    }

    fn resolve(&self, name: &str, span: Span) -> PResult<Target> {
        if let Some(&g) = self.group_index.get(name) {
            return Ok(Target::Group(g));
        }
        if let Some(&i) = self.isosurface_index.get(name) {
            return Ok(Target::Isosurface(i));
        }
        if let Some(&i) = self.mesh_index.get(name) {
            return Ok(Target::Mesh(i));
        }
        if let Some(k) = PrimitiveKind::from_keyword(name) {
            return Ok(Target::Primitive(k));
        }
        Err(err(span, format!("unknown rule or primitive `{name}`")))
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

    fn preprocessor_line(&mut self, word: &str, t: Token<'a>) -> PResult<()> {
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

    fn name_after(&mut self, what: &str) -> PResult<(&'a str, Span)> {
        let t = self.bump();
        match t.tok {
            Tok::Ident(n) => Ok((n, t.span)),
            other => Err(err(t.span, format!("expected a name after `{what}`, found {other}"))),
        }
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

    /// `@presets a b c`: named presets (seed 000 B.2). Declares the int
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

    fn const_value(&mut self, what: &str) -> PResult<(f64, Span)> {
        let span = self.peek().span;
        let e = self.arg(Ctx::Plain, What::Text(what))?;
        if !is_const(&e.e) {
            return Err(err(span, format!("{what} must be a constant (no @param or rand())")));
        }
        let v = e.e.eval(&mut NaNEnv);
        if !v.is_finite() {
            return Err(err(span, format!("{what} is not a finite number")));
        }
        Ok((v, span))
    }

    fn whole_value(&mut self, what: &str, max: f64) -> PResult<f64> {
        let (v, span) = self.const_value(what)?;
        if v < 0.0 || v.fract() != 0.0 || v > max {
            return Err(err(span, format!("{what} must be a whole number ≥ 0, found {v}")));
        }
        Ok(v)
    }

    fn directive(&mut self, word: &'a str, t: Token<'a>) -> PResult<()> {
        let lower = word.to_ascii_lowercase();
        match lower.as_str() {
            "rule" => {
                self.bump();
                return self.rule(t.span);
            }
            "startshape" => {
                self.bump();
                let (name, span) = self.name_after("startshape")?;
                if self.startshape.is_some() {
                    self.warnings.push(Diagnostic::warning(t.span, "second `startshape` replaces the first"));
                }
                self.startshape = Some((name, span));
                return Ok(());
            }
            _ => {}
        }
        self.bump();
        match lower.as_str() {
            "maxdepth" => {
                let v = self.whole_value("maxdepth", f64::from(u32::MAX))?;
                self.directives.maxdepth = Some(v as u32);
            }
            "maxiter" => self.directives.maxiter = Some(self.whole_value("maxiter", u64::MAX as f64)? as u64),
            "randseed" => self.directives.randseed = Some(self.whole_value("randseed", u64::MAX as f64)? as u64),
            "minsize" => {
                let (v, span) = self.const_value("minsize")?;
                if v < 0.0 {
                    return Err(err(span, format!("minsize must be ≥ 0, found {v}")));
                }
                self.directives.minsize = Some(v);
            }
            "background" => {
                let mut c = [0.0, 0.0, 0.0, 1.0];
                for v in c.iter_mut().take(3) {
                    *v = self.const_value("a background component")?.0;
                }
                if self.starts_arg() {
                    c[3] = self.const_value("a background component")?.0;
                }
                self.directives.background = Some(c);
            }
            "angle" => {
                let m = self.bump();
                let mode = match m.tok {
                    Tok::Ident(w) => match w.to_ascii_lowercase().as_str() {
                        "degrees" => AngleMode::Degrees,
                        "radians" => AngleMode::Radians,
                        "orbits" => AngleMode::Orbits,
                        "arcdegrees" | "frequency" => return Err(err(m.span, format!("not supported yet: angle mode `{w}`"))),
                        _ => return Err(err(m.span, format!("unknown angle mode `{w}` (expected degrees, radians or orbits)"))),
                    },
                    other => return Err(err(m.span, format!("expected an angle mode after `angle`, found {other}"))),
                };
                if mode != self.mode {
                    self.warnings.push(Diagnostic::warning(m.span, "conflicting `angle` directives: the first applies to the whole file"));
                }
            }
            "linerule" => {
                self.linerule = Some(self.name_after("linerule")?);
            }
            "camerarule" => {
                self.camerarule = Some(self.name_after("camerarule")?);
            }
            "stacksize" => {
                let v = self.whole_value("stacksize", f64::from(u32::MAX))?;
                self.directives.stacksize = Some(v as u32);
            }
            "fps" => {
                let (v, span) = self.const_value("fps")?;
                if !(v > 0.0 && v <= MAX_FPS) {
                    return Err(err(span, format!("fps must be in (0, {MAX_FPS}], found {v}")));
                }
                self.directives.fps = Some(v);
            }
            "duration" => {
                let (v, span) = self.const_value("duration")?;
                if !(0.0..=MAX_DURATION).contains(&v) {
                    return Err(err(span, format!("duration must be in [0, {MAX_DURATION}] seconds, found {v}")));
                }
                self.directives.duration = Some(v);
            }
            "camerafov" => {
                let (v, span) = self.const_value("camerafov")?;
                if !(v > 0.0 && v < 180.0) {
                    return Err(err(span, format!("camerafov must be in (0, 180) degrees, found {v}")));
                }
                self.directives.camera.fov_degrees = v;
            }
            "cameranearplane" | "camerafarplane" => {
                let (v, span) = self.const_value(word)?;
                if !(v > 0.0) {
                    return Err(err(span, format!("{word} must be > 0, found {v}")));
                }
                if lower == "cameranearplane" {
                    self.directives.camera.near = v;
                } else {
                    self.directives.camera.far = v;
                }
            }
            "normal" => {
                let mut n = [0.0; 3];
                for (i, c) in n.iter_mut().enumerate() {
                    *c = self.const_value(&format!("component {} of `normal`", i + 1))?.0;
                }
                self.directives.normal = Some(n);
            }
            "selector" => {
                let mut names = vec![self.name_after("selector")?];
                while self.is_punct(',') {
                    self.bump();
                    names.push(self.name_after("`,` in selector")?);
                }
                let m = self.bump();
                let mode = match m.tok {
                    Tok::Ident(w) => w.to_ascii_lowercase(),
                    other => return Err(err(m.span, format!("expected a selector mode, found {other}"))),
                };
                let pending = match mode.as_str() {
                    "random" | "frequency" => PendingSelector::Ready(Selector::Random),
                    "depth" => PendingSelector::Ready(Selector::Depth),
                    "scale" => PendingSelector::Ready(Selector::Scale),
                    "sequential" => PendingSelector::Ready(Selector::Sequential),
                    "function" if self.is_punct('{') => PendingSelector::Ready(Selector::Function(self.position_function()?)),
                    "function" => {
                        let (f, fspan) = self.name_after("selector function")?;
                        PendingSelector::Named(f, fspan)
                    }
                    _ => {
                        return Err(err(
                            m.span,
                            format!("unknown selector mode `{mode}` (random, frequency, depth, scale, sequential, function)"),
                        ))
                    }
                };
                for (name, span) in names {
                    self.selectors.push((name, span, pending.clone()));
                }
            }
            "function" => {
                let (name, _) = self.name_after("function")?;
                let e = self.position_function()?;
                self.functions.insert(name, e);
            }
            "program" => {
                self.skip_block(&format!("`{word}`"))?;
                self.warnings.push(Diagnostic::warning(t.span, format!("`{word}` ignored: not supported yet")));
            }
            "isosurface" => self.isosurface(t.span)?,
            "namespace" => self.namespace_block(t.span)?,
            "color" | "colour" | "weight" => {
                // Renames adjustments from here on (text parsed earlier, such as
                // imported rules, keeps the names it was written with).
                let mut names = [""; 4];
                for n in &mut names {
                    *n = self.name_after(word)?.0;
                }
                if lower == "weight" {
                    self.weight_names = names;
                } else {
                    self.colour_names = names;
                }
            }
            "mesh" => self.mesh_decl(t.span)?,
            w if SKIPPED_DIRECTIVES.contains(&w) => {
                let stop = self.line_end(self.pos.saturating_sub(1));
                while self.pos < stop && !self.is_punct('{') {
                    self.bump();
                }
                if self.is_punct('{') {
                    self.skip_block(&format!("`{word}`"))?;
                }
                self.warnings.push(Diagnostic::warning(t.span, format!("`{word}` ignored: not supported yet")));
            }
            _ => {
                return Err(err(t.span, format!("expected `rule`, `startshape` or a directive, found `{word}`")));
            }
        }
        Ok(())
    }

    /// `isosurface NAME { xyz|x|y|z min max cells … function { expr } | function NAME }`.
    fn isosurface(&mut self, span: Span) -> PResult<()> {
        let (name, _) = self.name_after("isosurface")?;
        self.expect_punct('{', || format!("after `isosurface {name}`"))?;
        let mut axes: [Option<(f64, f64, u32)>; 3] = [None; 3];
        let mut field: Option<Expr> = None;
        loop {
            let t = self.bump();
            let word = match t.tok {
                Tok::Punct('}') => break,
                Tok::Ident(w) => w.to_ascii_lowercase(),
                other => return Err(err(t.span, format!("expected `xyz`, `x`, `y`, `z`, `function` or `}}` in isosurface `{name}`, found {other}"))),
            };
            let which: &[usize] = match word.as_str() {
                "xyz" => &[0, 1, 2],
                "x" => &[0],
                "y" => &[1],
                "z" => &[2],
                "function" => {
                    field = Some(if self.is_punct('{') {
                        self.position_function()?
                    } else {
                        let (f, fspan) = self.name_after("isosurface function")?;
                        self.functions.get(f).cloned().ok_or_else(|| err(fspan, format!("unknown function `{f}`")))?
                    });
                    continue;
                }
                _ => return Err(err(t.span, format!("unknown isosurface setting `{word}` (xyz, x, y, z, function)"))),
            };
            let (lo, _) = self.const_value("the isosurface minimum")?;
            let (hi, hspan) = self.const_value("the isosurface maximum")?;
            if hi <= lo {
                return Err(err(hspan, format!("isosurface maximum {hi} must be above the minimum {lo}")));
            }
            let cells = self.whole_value("the isosurface resolution", 1e9)?;
            if cells < 1.0 {
                return Err(err(hspan, "isosurface resolution must be at least 1"));
            }
            for &a in which {
                axes[a] = Some((lo, hi, cells as u32));
            }
        }
        let Some(field) = field else { return Err(err(span, format!("isosurface `{name}` has no `function`"))) };
        let mut done = [(0.0, 0.0, 0); 3];
        for (i, a) in axes.iter().enumerate() {
            done[i] = a.ok_or_else(|| err(span, format!("isosurface `{name}` sets no range for {}", ["x", "y", "z"][i])))?;
        }
        if self.isosurface_index.contains_key(name) {
            return Err(err(span, format!("isosurface `{name}` is declared twice")));
        }
        let i = u32::try_from(self.isosurfaces.len()).map_err(|_| err(span, "too many isosurfaces"))?;
        self.isosurfaces.push(Isosurface { name: name.to_string(), axes: done, field, span });
        self.isosurface_index.insert(name, i);
        Ok(())
    }

    /// `{ expr }` where `x`, `y`, `z` are the current position's coordinates.
    fn position_function(&mut self) -> PResult<Expr> {
        self.expect_punct('{', || "before a function body".to_string())?;
        self.coords = true;
        let e = self.expr(Ctx::Plain);
        self.coords = false;
        let e = e?;
        self.expect_punct('}', || "to close the function body".to_string())?;
        Ok(e.e)
    }

    /// Skips `{ … }` with balanced braces (no recursion).
    fn skip_block(&mut self, what: &str) -> PResult<()> {
        let open = self.expect_punct('{', || format!("after {what}"))?;
        let mut level = 1usize;
        while level > 0 {
            let t = self.bump();
            match t.tok {
                Tok::Punct('{') => level += 1,
                Tok::Punct('}') => level -= 1,
                Tok::Eof => return Err(err(open.span, format!("`{{` of {what} is not closed"))),
                _ => {}
            }
        }
        Ok(())
    }

    /// `namespace NS { rules and directives }`: rule names get the prefix
    /// `NS.`; calls inside find `NS.NAME` before a global `NAME`.
    fn namespace_block(&mut self, span: Span) -> PResult<()> {
        if self.namespace.is_some() {
            return Err(err(span, "namespaces do not nest"));
        }
        let (ns, nspan) = self.name_after("namespace")?;
        if ns.contains('.') {
            return Err(err(nspan, format!("namespace name `{ns}` may not contain `.`")));
        }
        self.namespace_id(ns, nspan)?;
        self.expect_punct('{', || format!("after `namespace {ns}`"))?;
        self.namespace = Some(ns);
        loop {
            let t = self.peek();
            match t.tok {
                Tok::Punct('}') => {
                    self.bump();
                    break;
                }
                Tok::Eof => return Err(err(span, format!("`{{` of namespace `{ns}` is not closed"))),
                Tok::At(w) => self.preprocessor_line(w, t)?,
                Tok::Ident(w) => self.directive(w, t)?,
                other => return Err(err(t.span, format!("expected `rule` or a directive in namespace `{ns}`, found {other}"))),
            }
        }
        self.namespace = None;
        Ok(())
    }

    fn rule(&mut self, span: Span) -> PResult<()> {
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
        // `NS.LINETO` draws with namespace NS's pen (seed 000 §4.1.4).
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
        if let Expr::Num(v) = count.e {
            if v < 0.0 || v.fract() != 0.0 {
                return Err(err(start, format!("iteration count must be a whole number ≥ 0, found {v}")));
            }
        }
        let mut divisor = None;
        if self.is_punct('/') {
            self.bump();
            divisor = Some(self.arg(Ctx::Plain, What::Text("an iteration divisor"))?.e);
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
        Ok(Item::Iterate(Iterate { count: count.e, divisor, step, body: Box::new(body), site, span: start }))
    }

    // ----- adjustments -----

    fn adjustments(&mut self, close: char) -> PResult<Vec<Adjust>> {
        let mut out = Vec::new();
        loop {
            let t = self.bump();
            let word = match t.tok {
                Tok::Punct(c) if c == close => return Ok(out),
                Tok::Ident(w) => w,
                Tok::Eof => return Err(err(t.span, format!("expected `{close}` to close the adjustments, found end of input"))),
                other => return Err(err(t.span, format!("expected an adjustment or `{close}`, found {other}"))),
            };
            let span = t.span;
            // Colour and weight adjustments go by their (renamable) names first.
            if let Some(channel) = self.colour_names.iter().position(|n| *n == word) {
                let d = self.arg(Ctx::Plain, What::After(word))?;
                out.push(Adjust { op: AdjustOp::Colour { channel: channel as u8, delta: d.e }, span });
                continue;
            }
            if self.weight_names.contains(&word) {
                self.arg(Ctx::Plain, What::After(word))?;
                self.warnings.push(Diagnostic::warning(span, format!("vertex weight `{word}` ignored: weights only feed the thesis's shaders")));
                continue;
            }
            let mut push = |op: AdjustOp| out.push(Adjust { op, span });
            let rot = |axis, angle: E| AdjustOp::Rotate { axis, angle: angle.e };
            match word {
                "x" => {
                    let a = self.arg(Ctx::Plain, What::After("x"))?;
                    let (mut b, mut c) = (num(0.0), num(0.0));
                    if let Some(v) = self.opt_arg(Ctx::Plain, What::After("x"))? {
                        b = v;
                        c = self.opt_arg(Ctx::Plain, What::After("x"))?.unwrap_or_else(|| num(0.0));
                    }
                    push(AdjustOp::Translate([a.e, b.e, c.e]));
                }
                "y" => {
                    let a = self.arg(Ctx::Plain, What::After("y"))?;
                    push(AdjustOp::Translate([Expr::Num(0.0), a.e, Expr::Num(0.0)]));
                }
                "z" => {
                    let a = self.arg(Ctx::Plain, What::After("z"))?;
                    push(AdjustOp::Translate([Expr::Num(0.0), Expr::Num(0.0), a.e]));
                }
                "r" | "rotate" => {
                    push(rot(Axis::X, self.angle_arg(word)?));
                    if self.starts_arg() {
                        push(rot(Axis::Y, self.angle_arg(word)?));
                        if self.starts_arg() {
                            push(rot(Axis::Z, self.angle_arg(word)?));
                        }
                    }
                }
                "rx" | "pitch" => push(rot(Axis::X, self.angle_arg(word)?)),
                "ry" | "yaw" => push(rot(Axis::Y, self.angle_arg(word)?)),
                "rz" | "roll" => push(rot(Axis::Z, self.angle_arg(word)?)),
                "up" | "down" | "left" | "right" | "rolleft" | "rollleft" | "rollright" => {
                    let (axis, negative) = match word {
                        "up" => (Axis::X, false),
                        "down" => (Axis::X, true),
                        "left" => (Axis::Y, true),
                        "right" => (Axis::Y, false),
                        "rollright" => (Axis::Z, false),
                        _ => (Axis::Z, true),
                    };
                    let angle = if self.starts_arg() {
                        let a = self.angle_arg(word)?;
                        if negative {
                            Expr::Neg(Box::new(a.e))
                        } else {
                            a.e
                        }
                    } else {
                        Expr::Num(if negative { -FRAC_PI_2 } else { FRAC_PI_2 })
                    };
                    push(AdjustOp::Rotate { axis, angle });
                }
                "s" => {
                    let k = self.arg(Ctx::Plain, What::After("s"))?;
                    if self.starts_arg() {
                        return Err(err(self.peek().span, "not supported yet: non-uniform scale `s x y z`"));
                    }
                    push(AdjustOp::Scale(k.e));
                }
                "f" => {
                    let a = self.arg(Ctx::Plain, What::After("f"))?;
                    let b = self.arg(Ctx::Plain, What::After("f"))?;
                    let c = self.arg(Ctx::Plain, What::After("f"))?;
                    push(AdjustOp::Reflect([a.e, b.e, c.e]));
                }
                "fx" | "fy" | "fz" => {
                    let n = match word {
                        "fx" => [1.0, 0.0, 0.0],
                        "fy" => [0.0, 1.0, 0.0],
                        _ => [0.0, 0.0, 1.0],
                    };
                    push(AdjustOp::Reflect(n.map(Expr::Num)));
                }
                "R" | "G" | "B" | "A" | "u" | "v" | "w" | "q" => {
                    return Err(err(span, format!("unknown adjustment `{word}`: renamed by a `color` or `weight` directive")));
                }
                "fps" => {
                    self.arg(Ctx::Plain, What::After(word))?;
                    self.warnings.push(Diagnostic::warning(span, format!("adjustment `{word}` ignored: not supported yet")));
                }
                other => return Err(err(span, format!("unknown adjustment `{other}`"))),
            }
        }
    }

    // ----- numbers and expressions -----

    fn is_value_name(&self, name: &str) -> bool {
        self.defines.contains_key(name) || self.param_index.contains_key(name)
    }

    /// Whether the next token can start an (optional) argument.
    fn starts_arg(&self) -> bool {
        match self.peek().tok {
            Tok::Num { .. } | Tok::Punct('(') | Tok::Punct('-') => true,
            Tok::Ident(w) => {
                !self.is_adjust_word(w)
                    && (self.is_value_name(w) || (w == "rand" || Func::from_name(w).is_some()) && self.peek2().tok == Tok::Punct('('))
            }
            _ => false,
        }
    }

    fn opt_arg(&mut self, ctx: Ctx, what: What) -> PResult<Option<E>> {
        if self.starts_arg() {
            Ok(Some(self.arg(ctx, what)?))
        } else {
            Ok(None)
        }
    }

    fn angle_factor(&self) -> f64 {
        match self.mode {
            AngleMode::Degrees => PI / 180.0,
            AngleMode::Radians => 1.0,
            AngleMode::Orbits => 2.0 * PI,
        }
    }

    /// An angle argument, converted to radians.
    fn angle_arg(&mut self, word: &str) -> PResult<E> {
        let span = self.peek().span;
        let a = self.arg(Ctx::Angle, What::After(word))?;
        let f = self.angle_factor();
        if f == 1.0 {
            return Ok(a);
        }
        self.bin(BinOp::Mul, a, num(f), span)
    }

    /// An argument outside parentheses: `-`* then a primary (no binary operators).
    fn arg(&mut self, ctx: Ctx, what: What) -> PResult<E> {
        let t = self.peek();
        match t.tok {
            Tok::Punct('-') => {
                self.bump();
                self.enter(t.span)?;
                let inner = self.arg(ctx, what)?;
                self.leave();
                self.neg(inner, t.span)
            }
            Tok::Num { .. } | Tok::Punct('(') => self.primary(ctx),
            Tok::Ident(w) if !self.is_adjust_word(w) || self.is_value_name(w) => self.primary(ctx),
            other => Err(err(t.span, format!("expected a number {what}, found {other}"))),
        }
    }

    fn neg(&self, a: E, span: Span) -> PResult<E> {
        if let Expr::Num(v) = a.e {
            return Ok(num(-v));
        }
        let depth = a.depth + 1;
        if depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        Ok(E { e: Expr::Neg(Box::new(a.e)), depth, nodes: a.nodes + 1 })
    }

    fn bin(&self, op: BinOp, a: E, b: E, span: Span) -> PResult<E> {
        let depth = a.depth.max(b.depth) + 1;
        if depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        Ok(E { e: Expr::Binary(op, Box::new(a.e), Box::new(b.e)), depth, nodes: a.nodes + b.nodes + 1 })
    }

    /// A full expression (inside parentheses or a `@define` value).
    fn expr(&mut self, ctx: Ctx) -> PResult<E> {
        let mut lhs = self.term(ctx)?;
        loop {
            let t = self.peek();
            let op = match t.tok {
                Tok::Punct('+') => BinOp::Add,
                Tok::Punct('-') => BinOp::Sub,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = self.term(ctx)?;
            lhs = self.bin(op, lhs, rhs, t.span)?;
        }
    }

    fn term(&mut self, ctx: Ctx) -> PResult<E> {
        let mut lhs = self.unary(ctx)?;
        loop {
            let t = self.peek();
            let op = match t.tok {
                Tok::Punct('*') => BinOp::Mul,
                Tok::Punct('/') => BinOp::Div,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = self.unary(ctx)?;
            lhs = self.bin(op, lhs, rhs, t.span)?;
        }
    }

    fn unary(&mut self, ctx: Ctx) -> PResult<E> {
        let t = self.peek();
        if t.tok == Tok::Punct('-') {
            self.bump();
            self.enter(t.span)?;
            let inner = self.unary(ctx)?;
            self.leave();
            return self.neg(inner, t.span);
        }
        let base = self.primary(ctx)?;
        let t = self.peek();
        if t.tok == Tok::Punct('^') {
            self.bump();
            self.enter(t.span)?;
            let exp = self.unary(ctx)?;
            self.leave();
            return self.bin(BinOp::Pow, base, exp, t.span);
        }
        Ok(base)
    }

    fn literal(&self, value: f64, suffix: Option<char>, ctx: Ctx) -> f64 {
        let radians = match suffix {
            None => return value,
            Some('d') if ctx == Ctx::Angle && self.mode == AngleMode::Degrees => return value,
            Some('d') => value.to_radians(),
            Some(_) => value.atan(),
        };
        match ctx {
            Ctx::Plain => radians,
            Ctx::Angle => radians / self.angle_factor(),
        }
    }

    fn primary(&mut self, ctx: Ctx) -> PResult<E> {
        let t = self.bump();
        match t.tok {
            Tok::Num { value, suffix, .. } => Ok(num(self.literal(value, suffix, ctx))),
            Tok::Punct('(') => {
                self.enter(t.span)?;
                let e = self.expr(ctx)?;
                self.leave();
                self.expect_punct(')', || "to close `(`".to_string())?;
                Ok(e)
            }
            Tok::Ident(name) => {
                if self.is_punct('(') {
                    return self.func_call(name, t.span, ctx);
                }
                if self.coords {
                    if let Some(axis) = ["x", "y", "z"].iter().position(|c| *c == name) {
                        return Ok(E { e: Expr::Coord(axis as u8), depth: 1, nodes: 1 });
                    }
                }
                if let Some(&i) = self.param_index.get(name) {
                    return Ok(E { e: Expr::Param(i), depth: 1, nodes: 1 });
                }
                if let Some(d) = self.defines.get(name) {
                    let e = d.expr.clone();
                    if e.nodes > self.subst_budget {
                        return Err(err(t.span, "@define substitution too large"));
                    }
                    self.subst_budget -= e.nodes;
                    return Ok(e);
                }
                Err(err(t.span, format!("unknown name `{name}`")))
            }
            other => Err(err(t.span, format!("expected a number, found {other}"))),
        }
    }

    fn func_call(&mut self, name: &'a str, span: Span, ctx: Ctx) -> PResult<E> {
        self.bump(); // `(`
        self.enter(span)?;
        let mut args: Vec<E> = Vec::new();
        if !self.is_punct(')') {
            loop {
                // Function arguments are plain numbers: trig works in radians.
                let _ = ctx;
                args.push(self.expr(Ctx::Plain)?);
                if self.is_punct(',') {
                    self.bump();
                    continue;
                }
                break;
            }
        }
        self.expect_punct(')', || format!("to close the arguments of `{name}`"))?;
        self.leave();
        if name == "rand" {
            if !args.is_empty() {
                return Err(err(span, format!("`rand` takes no arguments, {} given", args.len())));
            }
            let site = self.next_site(span)?;
            return Ok(E { e: Expr::Rand(site), depth: 1, nodes: 1 });
        }
        let f = Func::from_name(name).ok_or_else(|| err(span, format!("unknown function `{name}`")))?;
        let (lo, hi) = f.arity();
        if args.len() < lo || hi.is_some_and(|h| args.len() > h) {
            let want = match hi {
                Some(h) if h == lo => format!("{lo}"),
                Some(h) => format!("{lo} to {h}"),
                None => format!("at least {lo}"),
            };
            return Err(err(span, format!("`{name}` takes {want} argument(s), {} given", args.len())));
        }
        let depth = args.iter().map(|a| a.depth).max().unwrap_or(0) + 1;
        if depth > MAX_NESTING {
            return Err(err(span, format!("nesting deeper than {MAX_NESTING}")));
        }
        let nodes = args.iter().map(|a| a.nodes).sum::<usize>() + 1;
        Ok(E { e: Expr::Func(f, args.into_iter().map(|a| a.e).collect()), depth, nodes })
    }
}

/// Marks the first call an item reaches (through iterators) as continuing.
fn mark_continuation(item: &mut Item) {
    let mut cur = item;
    loop {
        match cur {
            Item::Call(c) => {
                c.continues = true;
                return;
            }
            Item::Iterate(it) => cur = &mut it.body,
            Item::Block(b) => match b.first_mut() {
                Some(first) => cur = first,
                None => return,
            },
        }
    }
}

/// Fills in resolved call targets (recursion bounded by the nesting limit).
fn set_targets(items: &mut [Item], targets: &[Option<Target>], profiles: &[Option<GroupId>]) {
    for item in items {
        match item {
            Item::Call(c) => {
                if let Some(Some(t)) = targets.get(c.site as usize) {
                    c.target = *t;
                }
                if let (Target::Line(op, _), Some(Some(g))) = (c.target, profiles.get(c.site as usize)) {
                    c.target = Target::Line(op, Some(*g));
                }
            }
            Item::Block(b) => set_targets(b, targets, profiles),
            Item::Iterate(it) => set_targets(std::slice::from_mut(&mut *it.body), targets, profiles),
        }
    }
}

/// Finds the first top-level `angle MODE` so that it applies to the whole file.
/// The program's namespace table: names, and each call site's namespace
/// (left empty when the source declares and references no namespace).
fn namespace_table(names: Vec<String>, site_namespace: &[(u32, u32)], sites: u32) -> Namespaces {
    if names.len() <= 1 {
        return Namespaces::default();
    }
    let mut of_site = vec![0; sites as usize];
    for &(site, ns) in site_namespace {
        if let Some(slot) = of_site.get_mut(site as usize) {
            *slot = ns;
        }
    }
    Namespaces { names, of_site }
}

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
