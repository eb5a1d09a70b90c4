//! The drivers of the writers' one output shape, [`GeometrySink`]
//! (`export::sink`, after Nicolas Silva, lyon_tessellation
//! `GeometryBuilder`): each walks a model as a stage would and feeds a
//! sink, so the stage work — walking a hierarchy leaf by leaf, tessellating
//! each piece, finding a scene's repeated meshes — happens here, in the
//! pipeline, and the sinks only encode what they are given.
//!
//! * [`survey`] and [`pieces`]: the flat model as a stream of pieces (a
//!   scene and the leaves of a hierarchy, never expanded), for the streamed
//!   route.

use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::export::{ExportError, ExportMeta, GeometrySink};
use crate::mesh::pieces::for_each_piece;
use crate::mesh::MeshLayout;
use crate::model::{Hierarchy, Scene};

/// The flat model a streaming sink is fed from: a scene (and the hierarchy
/// whose leaves it stands for, not expanded), at a detail, its pieces in the
/// order of the merged meshes of `layout`.
#[derive(Debug, Clone, Copy)]
pub(super) struct ModelPieces<'a> {
    /// The flat part of the model.
    pub scene: &'a Scene,
    /// An instancing hierarchy, walked leaf by leaf after the scene.
    pub hierarchy: Option<&'a Hierarchy>,
    /// Tessellation detail.
    pub detail: u32,
    /// The mesh layout (it orders the pieces).
    pub layout: MeshLayout,
}

/// What the first pass over a model's pieces found.
#[derive(Debug, Clone)]
pub(super) struct Surveyed {
    /// Pieces walked: the second pass stops at as many.
    pieces: u64,
    /// Triangles of the flat model (what the merged mesh would hold).
    pub triangles: u64,
    /// The limit that cut the model short under `truncate` (the pass stops
    /// there, and so will the second).
    pub cut: Option<LimitExceeded>,
}

/// The first pass: walks the model's pieces (placed pieces are not
/// tessellated; their corners are mapped as the mesher maps them), counting
/// them and their triangles, and hands each to the sink's
/// [`survey`](GeometrySink::survey) when it asks for one. Under `truncate`
/// the deadline stops the walk, as it stops meshing, and the second pass
/// then stops at the same piece.
pub(super) fn survey(src: &ModelPieces<'_>, sink: &mut dyn GeometrySink, on_limit: OnLimit, budget: &mut Budget) -> Result<Surveyed, ExportError> {
    let (mut pieces, mut triangles) = (0u64, 0u64);
    let surveys = sink.surveys();
    let cut = for_each_piece::<ExportError>(src.scene, src.hierarchy, src.detail, src.layout, on_limit, budget, &mut |piece, _| {
        pieces += 1;
        triangles += piece.counts().1 as u64;
        if surveys {
            sink.survey(&piece)?;
        }
        Ok(true)
    })?;
    Ok(Surveyed { pieces, triangles, cut })
}

/// The second pass: begins the sink's output with `meta`, feeds it the
/// pieces [`survey`] walked (the same ones, in order; the deadline now
/// fails the call) and ends it.
pub(super) fn pieces(src: &ModelPieces<'_>, mut sink: Box<dyn GeometrySink>, surveyed: &Surveyed, meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    sink.begin(meta, budget)?;
    let mut fed = 0u64;
    for_each_piece::<ExportError>(src.scene, src.hierarchy, src.detail, src.layout, OnLimit::Error, budget, &mut |piece, budget| {
        if fed >= surveyed.pieces {
            return Ok(false);
        }
        fed += 1;
        sink.piece(&piece, budget)?;
        Ok(true)
    })?;
    sink.end(budget)
}
