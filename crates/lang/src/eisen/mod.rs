//! EisenScript (Structure Synth): [`build_model`] is the front end for
//! `language: "eisenscript"`: source → [`Script`](crate::eisen::syntax::Script)
//! → [`build`] (Structure Synth's breadth-first builder) → [`Model`]; a
//! `#javascript` script runs in the [`js`] sandbox and becomes a [`movie`].
//!
//! EisenScript has its own builder instead of lowering into the MDG rule IR;
//! `crate::eisen::syntax` explains why. Limits: every rule state applied and
//! every loop step counts an evaluation step (`max_steps`), pending states
//! and drawn objects are accounted in `max_memory`, and every object counts
//! as a primitive with its triangles. `max_depth` does not apply: the
//! builder never recurses, and a generation count is not a stack depth. The script's own `maxdepth`/`maxobjects`
//! end it quietly, as in Structure Synth; a budget limit fails (or truncates)
//! with the typed error naming it.

pub mod build;
mod draw;
pub mod js;
pub mod movie;
pub mod syntax;
mod view;

use crate::core::budget::Budget;
use crate::core::timing::{Phase, StageClock};
use crate::core::{ParamValue, PrimitiveKind};
use crate::geom::primitives;
use crate::eisen::syntax::{self as lang_es, ParseOptions, Script};
use crate::ir::ParamDecl;
use crate::{Diagnostic, FrontEnd, Language, ParseError, Span};
use crate::model::{BuildError, BuildRequest, EvalError, Model};
use std::collections::BTreeMap;

pub use build::{build, BuildOptions, Built};

/// The request parameter that sets the half-thickness of lines, grid edges
/// and dots (in units of the local frame; default [`build::DEFAULT_LINE_RADIUS`]).
pub const LINE_RADIUS_PARAM: &str = "line_radius";

/// Checks request parameters against the script's GUI defines and returns
/// the values to substitute, plus the line radius.
fn bind(script_params: &[lang_es::GuiParam], given: &BTreeMap<String, ParamValue>) -> Result<(BTreeMap<String, f64>, f64), EvalError> {
    let mut values = BTreeMap::new();
    let mut radius = build::DEFAULT_LINE_RADIUS;
    for (name, value) in given {
        let number = match value {
            ParamValue::Number(v) => Some(*v),
            ParamValue::Bool(_) => None,
            ParamValue::Text(t) => t.trim().parse::<f64>().ok(),
        }
        .filter(|v| v.is_finite());
        let Some(v) = number else {
            return Err(EvalError::BadParam { name: name.clone(), message: "expected a finite number".into() });
        };
        if name == LINE_RADIUS_PARAM {
            if !(v > 0.0 && v <= 0.5) {
                return Err(EvalError::BadParam { name: name.clone(), message: format!("must be in (0, 0.5], got {v}") });
            }
            radius = v;
            continue;
        }
        let Some(p) = script_params.iter().find(|p| &p.name == name) else {
            let mut declared: Vec<&str> = script_params.iter().map(|p| p.name.as_str()).collect();
            declared.push(LINE_RADIUS_PARAM);
            return Err(EvalError::UnknownParam { name: name.clone(), declared: declared.join(", ") });
        };
        if v < p.range.0 || v > p.range.1 {
            return Err(EvalError::BadParam { name: name.clone(), message: format!("must be in {}..={}, got {v}", p.range.0, p.range.1) });
        }
        if p.integer && v.fract() != 0.0 {
            return Err(EvalError::BadParam { name: name.clone(), message: format!("must be a whole number, got {v}") });
        }
        values.insert(name.clone(), v);
    }
    Ok((values, radius))
}

/// Parses `source` with the request's parameters bound to its GUI defines.
pub(crate) fn parse_bound(source: &[u8], params: &BTreeMap<String, ParamValue>, seed: u64) -> Result<(Script, f64), BuildError> {
    // The defines are only known after a first parse; request values then
    // replace their defaults in a second one.
    let first = lang_es::parse(source, &ParseOptions { params: BTreeMap::new(), seed })?;
    let (values, radius) = bind(&first.params, params)?;
    if values.is_empty() {
        return Ok((first, radius));
    }
    Ok((lang_es::parse(source, &ParseOptions { params: values, seed })?, radius))
}

/// The front end of `language: "eisenscript"`.
pub struct Eisenscript;

impl FrontEnd for Eisenscript {
    fn name(&self) -> &'static str {
        "eisenscript"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["es"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        // A JavaScript script is a program: it is only known what it builds by running it.
        if lang_es::is_javascript(source) {
            return Ok(vec![Diagnostic::warning(Span::new(1, 1), "a Structure Synth JavaScript script is run, not checked; render it to run it")]);
        }
        lang_es::parse(source, &Default::default()).map(|s| s.warnings)
    }
    /// The script's GUI defines (`#define NAME VALUE (float:LO-HI)`) as parameters.
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        Ok(lang_es::parse(source, &Default::default())?
            .params
            .into_iter()
            .map(|p| ParamDecl {
                name: p.name,
                kind: if p.integer { crate::ir::ParamKind::Int } else { crate::ir::ParamKind::Float },
                default: p.default,
                range: Some(p.range),
                choices: Vec::new(),
                span: p.span,
            })
            .collect())
    }
    fn plays_frames(&self, source: &[u8]) -> bool {
        lang_es::is_javascript(source)
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        build_model(source, req, budget, clock)
    }
}

/// Builds the model of EisenScript `source` under `budget`; a `#javascript`
/// script is run as a [`movie`].
pub fn build_model(source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    if lang_es::is_javascript(source) {
        return movie::build_model(source, req, budget, clock);
    }
    let (script, line_radius) = parse_bound(source, req.params, req.seed.unwrap_or(0))?;
    clock.lap(Phase::Parse);
    let built = build::build(&script, &build_options(req, line_radius), budget)?;
    Ok(Model {
        language: Language::Eisenscript,
        scene: built.scene,
        hierarchy: None,
        drawing: None,
        primitives: built.objects,
        warnings: script.warnings,
        promised: built.promised,
        seed: req.seed.unwrap_or(0),
    })
}

/// The builder's options for `req`, with what meshing and export will need
/// per primitive.
pub(crate) fn build_options(req: &BuildRequest<'_>, line_radius: f64) -> BuildOptions {
    let cost = req.downstream;
    BuildOptions {
        seed: req.seed.unwrap_or(0),
        detail: req.detail,
        on_limit: req.on_limit,
        line_radius,
        downstream_bytes: PrimitiveKind::ALL.map(|k| cost.bytes(primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail))),
        vertex_bytes: cost.bytes(1, 0) + cost.bytes(0, 1).div_ceil(3),
        per_instance: cost.per_instance,
    }
}
