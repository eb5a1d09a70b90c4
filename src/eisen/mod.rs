//! EisenScript (Structure Synth) rendering: [`render`] is the pipeline for
//! `language: "eisenscript"`: source → [`Script`](crate::lang::eisen::Script)
//! → [`build`] (Structure Synth's breadth-first builder) → Scene → meshes → bytes,
//! under one [`Budget`].
//!
//! EisenScript has its own builder instead of lowering into the MDG rule IR;
//! `crate::lang::eisen` explains why. Limits: every rule state applied and
//! every loop step counts an evaluation step (`max_steps`), the generation
//! (or nesting) depth is checked against `max_depth`, pending states and
//! drawn objects are accounted in `max_memory`, and every object counts as a
//! primitive with its triangles. The script's own `maxdepth`/`maxobjects`
//! end it quietly, as in Structure Synth; a budget limit fails (or truncates)
//! with the typed error naming it.

pub mod build;
pub mod movie;

use crate::eval::{Budget, EvalError, ParamValue};
use crate::export;
use crate::geom::primitives;
use crate::lang::eisen::{self as lang_es, ParseOptions, Script};
use crate::lang::ir::PrimitiveKind;
use crate::lang::Language;
use crate::pipeline::{check_detail, downstream, mesh_and_export, truncate_or_fail, RenderError, RenderOutput, RenderRequest, Stages};
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
pub fn parse_bound(source: &[u8], params: &BTreeMap<String, ParamValue>, seed: u64) -> Result<(Script, f64), RenderError> {
    // The defines are only known after a first parse; request values then
    // replace their defaults in a second one.
    let first = lang_es::parse(source, &ParseOptions { params: BTreeMap::new(), seed })?;
    let (values, radius) = bind(&first.params, params)?;
    if values.is_empty() {
        return Ok((first, radius));
    }
    Ok((lang_es::parse(source, &ParseOptions { params: values, seed })?, radius))
}

/// Renders EisenScript `source` as the request says (the request's language is taken to be EisenScript).
pub fn render(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    check_detail(req)?;
    if lang_es::js::is_javascript(source) {
        return movie::render(source, req);
    }
    let mut budget = Budget::new(req.limits);
    let mut stages = Stages::start();
    Budget::check_source(&req.limits, source.len() as u64)?;
    let (script, line_radius) = parse_bound(source, &req.params, req.seed.unwrap_or(0))?;
    stages.lap(|p| &mut p.parse);
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let opts = build_options(req, overhead, line_radius);
    let mut built = build::build(&script, &opts, &mut budget)?;
    stages.lap(|p| &mut p.eval);
    if let Err(e) = budget.check_deadline() {
        truncate_or_fail(req.on_limit, e, &mut built.scene)?;
    }
    budget.release_memory(built.promised.saturating_add(overhead));
    mesh_and_export(built.scene, req, Language::Eisenscript, built.objects, script.warnings, budget, stages)
}

/// The builder's options for `req`, with what meshing and export will need
/// per primitive (beyond `overhead`, already reserved).
pub(crate) fn build_options(req: &RenderRequest, overhead: u64, line_radius: f64) -> BuildOptions {
    let cost = downstream(req, overhead);
    BuildOptions {
        seed: req.seed.unwrap_or(0),
        detail: req.detail,
        on_limit: req.on_limit,
        line_radius,
        downstream_bytes: PrimitiveKind::ALL.map(|k| cost.bytes(primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail))),
        vertex_bytes: cost.bytes(1, 0) + cost.bytes(0, 1).div_ceil(3),
    }
}
