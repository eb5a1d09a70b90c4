//! L-systems: derivation ([`derive`]) and turtle interpretation ([`turtle`])
//! of systems parsed by [`syntax`], and [`build_model`], the
//! front end for `language: "lsystem"` (ETOL's, [`crate::etol`], translates and calls it):
//! source → derived string → turtle → [`Model`].
//!
//! Context-free systems take the instancing route instead (issue 5, the
//! Calgary instancing thesis, ch. 4): source → derivation DAG ([`dag`]) → object hierarchy
//! ([`instance`]) → a model whose [`Hierarchy`] the stages write as
//! `format=scene` or `EXT_mesh_gpu_instancing` glTF, with no string in
//! between; for the flat formats the DAG is walked through the turtle.
//!
//! Limits: every module rewritten counts one evaluation step (`max_steps`),
//! every string is accounted in `max_memory` before it is allocated (so the
//! string length is bounded by both), and every segment counts as a
//! primitive (`max_primitives`) with its triangles (`max_triangles`).

pub mod dag;
pub mod syntax;
pub mod derive;
pub mod instance;
pub mod turtle;

use crate::core::budget::{Budget, Limit, LimitExceeded, OnLimit};
use crate::core::timing::{Phase, StageClock};
use crate::core::PrimitiveKind;
use crate::geom::{primitives, sweep};
use crate::ir::ParamDecl;
use crate::{Diagnostic, FrontEnd, Language, ParseError};
use syntax as lang_ls;
use crate::model::{BuildError, BuildRequest, EvalError, Hierarchy, Model};

pub use derive::derive;
pub(crate) use derive::ModuleString;

/// Builds the model of L-system `source` under `budget`.
///
/// Systems that [instance](dag::not_instanceable) are derived as a DAG of
/// distinct subtrees, never as a string. Where the request asks for a
/// hierarchy ([`BuildRequest::hierarchy`]) the model is that [`Hierarchy`]
/// (the pipeline charges its size as the route writes it); otherwise the
/// DAG is walked through the turtle. Other systems are derived in full.
///
/// Under `on_limit: truncate` a route that runs out of a limit is abandoned
/// for the string route, which stops at the limit; the work thrown away is
/// refunded ([`Budget::rewind`]) but the clock is not restarted, so the
/// deadline holds for the whole request.
pub fn build_model(source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let sys = lang_ls::parse(source)?;
    if let Some(name) = req.params.keys().next() {
        return Err(EvalError::UnknownParam { name: name.clone(), declared: String::new() }.into());
    }
    clock.lap(Phase::Parse);
    let seed = req.seed.or(sys.seed).unwrap_or(0);
    let truncating = req.on_limit == OnLimit::Truncate;
    let start = budget.mark();
    let dag = match dag::not_instanceable(&sys) {
        Some(_) => None,
        None => match dag::build(&sys, seed, budget) {
            Ok(d) => Some(d),
            // The DAG is built whole or not at all; truncation needs the string.
            Err(EvalError::Limit(_)) if truncating => {
                budget.rewind(start);
                None
            }
            Err(e) => return Err(e.into()),
        },
    };
    if req.hierarchy && dag.is_some() {
        let mark = budget.mark();
        match hierarchy(&sys, dag.as_ref(), seed, req, budget) {
            Ok(h) => {
                let primitives = h.leaves();
                return Ok(Model { language: Language::Lsystem, scene: Default::default(), hierarchy: Some(h), drawing: None, primitives, warnings: sys.warnings, promised: 0, seed });
            }
            Err(EvalError::Limit(_)) if truncating => budget.rewind(mark),
            Err(e) => return Err(e.into()),
        }
    }
    let cost = req.downstream;
    let opts = turtle::TurtleOptions {
        detail: req.detail,
        on_limit: req.on_limit,
        line_point_bytes: {
            let (v, t) = sweep::per_point_bound(sweep::profile_sides(req.detail));
            cost.bytes(v, t)
        },
        downstream_bytes: PrimitiveKind::ALL.map(|k| cost.bytes(primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail))),
    };
    let walk = match &dag {
        Some(d) if fits(d, req.on_limit, budget)? => Some(d),
        _ => None,
    };
    let drawing = match walk {
        Some(d) => turtle::interpret_stream(&sys, &opts, budget, &mut |sink| d.feed(d.root_index(), sink))?,
        None => string_drawing(&sys, seed, &opts, budget)?,
    };
    Ok(Model { language: Language::Lsystem, scene: drawing.scene, hierarchy: None, drawing: None, primitives: drawing.segments, warnings: sys.warnings, promised: drawing.promised, seed })
}

/// The front end of `language: "lsystem"`.
pub struct Lsystem;

impl FrontEnd for Lsystem {
    fn name(&self) -> &'static str {
        "lsystem"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["ls"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        syntax::parse(source).map(|s| s.warnings)
    }
    /// L-systems declare no parameters (the source is checked all the same).
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        syntax::parse(source).map(|_| Vec::new())
    }
    /// An L-system's colour is part of each mesh it instances.
    fn colours_per_instance(&self) -> bool {
        false
    }
    /// The hierarchy's segments are capped cylinders; the turtle sweeps mitred tubes.
    fn own_hierarchy_geometry(&self) -> bool {
        true
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        build_model(source, req, budget, clock)
    }
}

/// Whether walking `d` through the turtle stays within the limits: reading
/// the expansion costs a step per module, and every segment is a primitive.
/// What is known to exceed either is refused before drawing (`error`), or
/// (`truncate`) drawn from the string instead, which stops at the limit.
fn fits(d: &dag::StringDag, on_limit: OnLimit, budget: &Budget) -> Result<bool, LimitExceeded> {
    let over = budget
        .check_total(Limit::Steps, budget.steps().saturating_add(d.root().modules))
        .and_then(|()| budget.check_total(Limit::Primitives, d.root().segments));
    match (over, on_limit) {
        (Ok(()), _) => Ok(true),
        (Err(e), OnLimit::Error) => Err(e),
        (Err(_), OnLimit::Truncate) => Ok(false),
    }
}

/// Derives the string of `sys` in full under the budget and draws it.
fn string_drawing(sys: &lang_ls::LSystem, seed: u64, opts: &turtle::TurtleOptions, budget: &mut Budget) -> Result<turtle::Drawing, EvalError> {
    let derivation = derive::derive(sys, seed, opts.on_limit, budget)?;
    let mut drawing = turtle::interpret(sys, &derivation.string, opts, budget)?;
    if drawing.scene.truncated.is_none() {
        drawing.scene.truncated = derivation.truncated;
    }
    budget.release_memory(derivation.string.bytes());
    Ok(drawing)
}

/// The object hierarchy of `sys` (from its DAG when it has a balanced one,
/// else from the string derived in full), charged for what building it
/// makes; the pipeline charges its size or expansion as the route writes it.
fn hierarchy(sys: &lang_ls::LSystem, dag: Option<&dag::StringDag>, seed: u64, req: &BuildRequest<'_>, budget: &mut Budget) -> Result<Hierarchy, EvalError> {
    let h = match dag {
        Some(d) if d.balanced() => instance::build(sys, d, budget)?,
        _ => {
            let derivation = derive::derive(sys, seed, req.on_limit, budget)?;
            let flat = dag::from_string(sys, &derivation.string, budget)?;
            budget.release_memory(derivation.string.bytes());
            let mut h = instance::build(sys, &flat, budget)?;
            h.truncated = derivation.truncated;
            h
        }
    };
    Ok(h)
}
