//! L-systems: derivation ([`derive`]) and turtle interpretation ([`turtle`])
//! of systems parsed by [`crate::lang::lsystem`], and [`render`], the
//! pipeline for `language: "lsystem"`: source → derived string → Scene →
//! meshes → bytes, under one [`Budget`].
//!
//! Limits: every module rewritten counts one evaluation step (`max_steps`),
//! every string is accounted in `max_memory` before it is allocated (so the
//! string length is bounded by both), and every segment counts as a
//! primitive (`max_primitives`) with its triangles (`max_triangles`).

pub mod derive;
pub mod turtle;

use crate::eval::{Budget, EvalError};
use crate::export;
use crate::geom::{self, primitives};
use crate::lang::ir::PrimitiveKind;
use crate::lang::{lsystem as lang_ls, Language};
use crate::pipeline::{check_detail, downstream, mesh_and_export, truncate_or_fail, RenderError, RenderOutput, RenderRequest, Stages};

pub use derive::{derive, Derivation, ModuleString};

/// Renders L-system `source` as the request says (the request's language is taken to be L-system).
pub fn render(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    check_detail(req)?;
    let mut budget = Budget::new(req.limits);
    let mut stages = Stages::start();
    Budget::check_source(&req.limits, source.len() as u64)?;
    let sys = lang_ls::parse(source)?;
    if let Some(name) = req.params.keys().next() {
        return Err(EvalError::UnknownParam { name: name.clone(), declared: String::new() }.into());
    }
    stages.lap(|p| &mut p.parse);
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let seed = req.seed.or(sys.seed).unwrap_or(0);
    let derivation = derive::derive(&sys, seed, req.on_limit, &mut budget)?;
    let cost = downstream(req, overhead);
    let opts = turtle::TurtleOptions {
        detail: req.detail,
        on_limit: req.on_limit,
        line_point_bytes: {
            let (v, t) = geom::sweep::per_point_bound(geom::sweep::profile_sides(req.detail));
            cost.bytes(v, t)
        },
        downstream_bytes: PrimitiveKind::ALL.map(|k| cost.bytes(primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail))),
    };
    let mut drawing = turtle::interpret(&sys, &derivation.string, &opts, &mut budget)?;
    if drawing.scene.truncated.is_none() {
        drawing.scene.truncated = derivation.truncated;
    }
    budget.release_memory(derivation.string.bytes());
    drop(derivation);
    stages.lap(|p| &mut p.eval);
    if let Err(e) = budget.check_deadline() {
        truncate_or_fail(req.on_limit, e, &mut drawing.scene)?;
    }
    budget.release_memory(drawing.promised.saturating_add(overhead));
    mesh_and_export(drawing.scene, req, Language::Lsystem, drawing.segments, sys.warnings, budget, stages)
}
