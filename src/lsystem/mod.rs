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
use crate::export::{self, ExportMeta};
use crate::geom::{self, primitives};
use crate::lang::ir::PrimitiveKind;
use crate::lang::{lsystem as lang_ls, Language};
use crate::pipeline::{PhaseTimes, RenderError, RenderOutput, RenderRequest};
use std::time::{Duration, Instant};

pub use derive::{derive, Derivation, ModuleString};

/// Renders L-system `source` as the request says (the request's language is taken to be L-system).
pub fn render(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    if !(geom::MIN_DETAIL..=geom::MAX_DETAIL).contains(&req.detail) {
        return Err(RenderError::BadRequest(format!(
            "detail must be in {}..={}, got {}",
            geom::MIN_DETAIL,
            geom::MAX_DETAIL,
            req.detail
        )));
    }
    let mut budget = Budget::new(req.limits);
    let mut phases = PhaseTimes::default();
    let mut mark = Instant::now();
    let mut lap = |slot: &mut Duration| {
        *slot = mark.elapsed();
        mark = Instant::now();
    };
    Budget::check_source(&req.limits, source.len() as u64)?;
    let sys = lang_ls::parse(source)?;
    if let Some(name) = req.params.keys().next() {
        return Err(EvalError::UnknownParam { name: name.clone(), declared: String::new() }.into());
    }
    lap(&mut phases.parse);
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let seed = req.seed.or(sys.seed).unwrap_or(0);
    let derivation = derive::derive(&sys, seed, req.on_limit, &mut budget)?;
    let opts = turtle::TurtleOptions {
        detail: req.detail,
        on_limit: req.on_limit,
        line_point_bytes: {
            let (v, t) = geom::sweep::per_point_bound(geom::sweep::profile_sides(req.detail));
            geom::meshing::mesh_bytes(v, t).saturating_add(export::estimated_size(req.format, v, t) - overhead)
        },
        downstream_bytes: PrimitiveKind::ALL.map(|k| {
            let (v, t) = (primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail));
            geom::meshing::mesh_bytes(v, t).saturating_add(export::estimated_size(req.format, v, t) - overhead)
        }),
    };
    let mut drawing = turtle::interpret(&sys, &derivation.string, &opts, &mut budget)?;
    if drawing.scene.truncated.is_none() {
        drawing.scene.truncated = derivation.truncated;
    }
    budget.release_memory(derivation.string.bytes());
    drop(derivation);
    lap(&mut phases.eval);
    if let Err(e) = budget.check_deadline() {
        match req.on_limit {
            crate::eval::OnLimit::Error => return Err(e.into()),
            crate::eval::OnLimit::Truncate => {
                drawing.scene.truncated.get_or_insert(e);
            }
        }
    }
    budget.release_memory(drawing.promised.saturating_add(overhead));
    let scene = drawing.scene;
    let meshes = geom::build_meshes(&scene, req.detail, req.layout, &mut budget)?;
    lap(&mut phases.mesh);
    let meta = ExportMeta { background: scene.background, truncated: scene.truncated.is_some() };
    let bytes = export::export_with(req.format, &meshes, &meta, &req.export_options, &mut budget)?;
    lap(&mut phases.export);
    let triangles = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    Ok(RenderOutput {
        bytes,
        language: Language::Lsystem,
        primitives: drawing.segments,
        triangles,
        truncated: scene.truncated,
        warnings: sys.warnings,
        elapsed: budget.elapsed(),
        phases,
    })
}
