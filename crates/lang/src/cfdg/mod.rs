//! Context Free Design Grammar (CFDG 2.x and 3.x; John Horigan, Mark
//! Lentczner and Chris Coyne, *Context Free*, 2005–2018, cfdg 3.4): the
//! front end for `language: "cfdg"`. Source → [`syntax::Grammar`] →
//! [`eval::render`] (cfdg's renderer: the same shapes, order, colours and
//! framing for the same variation code) → a [`Model`] of thin tiles, one per
//! primitive, stacked in drawing order ([`tiles`]), carrying the picture as
//! its 2D drawing ([`drawing`]) for `svg` and `png`. See `docs/cfdg.md`.
//!
//! Limits: every rule expanded and every loop iteration is a step, every
//! finished primitive a primitive (with its triangles), every shape kept
//! is memory; cfdg's own `CF::MaxShapes`/maximum shapes end the render
//! quietly, as in cfdg. `max_depth` does not apply: expansion is a heap,
//! never a recursion.

pub mod drawing;
pub mod eval;
pub mod instanced;
pub(crate) mod rand64;
pub mod solid;
pub mod syntax;
pub mod tiles;
pub mod variation;

use crate::core::budget::Budget;
use crate::core::timing::{Phase, StageClock};
use crate::core::ParamValue;
use crate::ir::ParamDecl;
use crate::model::{BuildError, BuildRequest, EvalError, Model};
use crate::{Diagnostic, FrontEnd, Language, ParseError};

/// The request parameter naming a variation code (`"ABC"`), as cfdg's `-v`.
pub(crate) const VARIATION_PARAM: &str = "variation";

/// Whether unnamed source reads as CFDG rather than MDG (which shares
/// `startshape` and `rule`): it has `startshape` and a 3.x `shape` line, a
/// `CF::` setting or one of Context Free's 2D primitives as a whole word,
/// and none of MDG's own words (`@param`, `@define`, `selector`, `linerule`).
pub(crate) fn looks_like_cfdg(text: &str) -> bool {
    let word = |w: &str| {
        text.match_indices(w).any(|(i, _)| {
            let before = text[..i].chars().next_back().is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
            let after = text[i + w.len()..].chars().next().is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
            before && after
        })
    };
    let shape_line = text.lines().any(|l| l.trim_start().starts_with("shape ") || l.trim_start().starts_with("shape\t"));
    let mdg = ["@param", "@define", "selector ", "linerule", "camerarule"].iter().any(|w| text.contains(w));
    text.contains("startshape") && !mdg && (shape_line || text.contains("CF::") || ["SQUARE", "CIRCLE", "TRIANGLE"].iter().any(|w| word(w)))
}

/// The front end of `language: "cfdg"`.
pub struct Cfdg;

/// Parses and checks `source` (every shape named has rules); `import` is an error.
pub(crate) fn parse_checked(source: &[u8]) -> Result<syntax::Grammar, ParseError> {
    parse_checked_in(source, None)
}

/// Reads an imported file `name` from `dir`: a bare file name only (no
/// folder, no `..`), so a design reads nothing but the files beside it.
pub(crate) fn read_beside(dir: &std::path::Path, name: &str) -> Option<Vec<u8>> {
    let ok = !name.is_empty() && !name.contains(['/', '\\']) && !name.starts_with('.');
    if !ok {
        return None;
    }
    std::fs::read(dir.join(name)).ok()
}

/// Parses and checks `source`, importing files from `dir` when given (the
/// CLI's folder of the design; the service gives none).
pub fn parse_checked_in(source: &[u8], dir: Option<&std::path::Path>) -> Result<syntax::Grammar, ParseError> {
    let g = match dir {
        Some(d) => syntax::parse_with(source, &|name: &str| read_beside(d, name))?,
        None => syntax::parse(source)?,
    };
    eval::check(&g)?;
    Ok(g)
}

/// The variation code (`"ABC"`) of a CFDG model, whose seed is its
/// variation number ([`Model::seed`]): what the service sends as
/// `X-Rulemesh-Variation`, so a client can pin a design by its code, as
/// Context Free shows and takes it. `None` for another language.
pub fn variation_code(language: Language, seed: u64) -> Option<String> {
    if language != Language::Cfdg {
        return None;
    }
    i32::try_from(seed).ok().and_then(variation::to_code)
}

/// The variation a request asks for: its `variation` parameter (a code or
/// number), else its seed folded into cfdg's range (seed `s` → variation
/// `s mod (2³¹−1) + 1`), else 1 (`A`).
pub(crate) fn variation_of(req: &BuildRequest<'_>) -> Result<i32, EvalError> {
    if let Some(v) = req.params.get(VARIATION_PARAM) {
        let code = match v {
            ParamValue::Text(t) => t.clone(),
            ParamValue::Number(n) => format!("{n}"),
            ParamValue::Bool(_) => String::new(),
        };
        return variation::from_code(&code).ok_or_else(|| EvalError::BadParam { name: VARIATION_PARAM.into(), message: format!("`{code}` is not a variation code (letters A–Z, or a number ≥ 1)") });
    }
    if let Some((name, _)) = req.params.iter().next() {
        return Err(EvalError::UnknownParam { name: name.clone(), declared: VARIATION_PARAM.into() });
    }
    Ok(match req.seed {
        Some(s) => (s % (i32::MAX as u64)) as i32 + 1,
        None => 1,
    })
}

impl FrontEnd for Cfdg {
    fn name(&self) -> &'static str {
        "cfdg"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["cfdg"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        parse_checked(source).map(|g| g.warnings)
    }
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        parse_checked(source).map(|_| Vec::new())
    }
    fn draws(&self) -> bool {
        true
    }
    /// A memoised design's hierarchy lifts children onto their parents and
    /// scales each tile's thickness with it (instanced.rs), where the flat
    /// tiles share one thickness: its own geometry, shown by every format
    /// that instances, `instancing=flat` included.
    fn own_hierarchy_geometry(&self) -> bool {
        true
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        let g = parse_checked_in(source, req.script_dir)?;
        clock.lap(Phase::Parse);
        let var = variation_of(req)?;
        let mut opts = eval::Options { variation: var, on_limit: req.on_limit, ..eval::Options::default() };
        if let Some(side) = req.canvas {
            // A picture is drawn for its size, as `cfdg -s` draws it.
            (opts.width, opts.height) = (side, side);
        }
        // Where the pipeline asks for a hierarchy (`scene`, and glTF and
        // usdz with or without instancing, since this hierarchy is geometry
        // of its own: `own_hierarchy_geometry`), a memoised run records its
        // nodes and becomes a hierarchy of its distinct subtrees
        // (instanced.rs), so every one of those formats shows the same
        // model. A print, strips and the other flat formats keep the flat
        // tiles, whose one thickness and drawing-order lift a relief needs.
        opts.record = req.hierarchy && !req.picture_only && !req.print;
        let picture = eval::render(&g, &opts, budget)?;
        let hierarchy = if opts.record { instanced::hierarchy(&picture, budget)? } else { None };
        // A picture of the design is drawn from its drawing alone.
        let mut scene = match (&hierarchy, req.picture_only) {
            (_, true) => crate::model::Scene::default(),
            (Some(_), false) => crate::model::Scene { background: tiles::background(&picture), ..Default::default() },
            (None, false) => tiles::scene(&picture, req, budget)?,
        };
        scene.truncated = picture.truncated;
        let primitives = picture.shapes.len() as u64;
        // A hierarchy is asked for only by 3D outputs, which never read the drawing.
        let drawing = if hierarchy.is_some() { None } else { Some(drawing::into_drawing(picture, budget)?) };
        Ok(Model {
            language: Language::Cfdg,
            primitives,
            scene,
            hierarchy,
            drawing,
            warnings: g.warnings,
            promised: 0,
            seed: var as u64,
        })
    }
}

#[cfg(test)]
mod tests;
