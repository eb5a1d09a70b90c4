//! Keyword directives: everything at the top level (or in a `namespace`
//! block) that is not a rule, from `startshape`, `maxdepth` and `angle` to the
//! camera lens, `selector`, `function`, `isosurface`, `namespace` and the
//! `color`/`weight` renamings. Directives of the thesis's viewer that draw
//! nothing here are skipped with a warning.

use super::expressions::Ctx;
use super::{err, PResult, Parser, PendingSelector, MAX_DURATION, MAX_FPS};
use crate::expr::Expr;
use crate::ir::{AngleMode, Isosurface, Selector};
use crate::mdg::syntax::lexer::{Tok, Token};
use crate::core::{Diagnostic, Span};

/// Top-level directives that are skipped (to the end of their line) with a warning.
const SKIPPED_DIRECTIVES: [&str; 5] = [
    "uniform",
    "buffer",
    "invalidateskipframes",
    "cameramode",
    "render",
];

impl<'a> Parser<'a> {
    /// One statement that starts with the name `word` (token `t`): `rule`,
    /// `startshape` or a directive.
    pub(super) fn directive(&mut self, word: &'a str, t: Token<'a>) -> PResult<()> {
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
        Ok(e.expr)
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
}
