//! The route: how a request's model becomes bytes, decided once from the
//! validated request (its format's descriptor and options) before the
//! front end runs. The stages follow it and nothing downstream tests the
//! request's flags again (issue 22: the route was re-decided from flags in
//! a dozen places, and two of them could disagree).
//!
//! The front end is told only what the route needs from it
//! ([`Route::wants_hierarchy`]: a hierarchy or not; [`Route::animated`]),
//! never the format; a hierarchy it builds is charged here, as the route
//! writes it ([`Route::charge_hierarchy`]).

use super::RenderRequest;
use crate::export::{EncodePicture, Instancing, MakeSink, WriteDrawing, WriteMeshes, WriteModel, Writer};
use crate::core::budget::{Budget, Limit, LimitExceeded};
use crate::model::Hierarchy;

/// The way a model is written, chosen by [`Route::of`].
#[derive(Debug, Clone, Copy)]
pub(crate) enum Route {
    /// The format writes the model as made: its instances and hierarchy,
    /// nothing tessellated (`scene`, docs/scene-format.md).
    Model(WriteModel),
    /// The format writes the model's 2D drawing (`svg`), which only a
    /// language that draws makes (Context Free); others are refused.
    Drawing(WriteDrawing),
    /// The model fed piece by piece into the format's streaming sink
    /// (strips, a chunk at a time): no merged mesh, a hierarchy walked, not
    /// expanded (docs/strips-format.md); `empty` writes the empty model a
    /// late answer falls back to.
    Streamed { sink: MakeSink, empty: WriteMeshes },
    /// One watertight solid from the print stage (docs/print.md), then
    /// its report as JSON when `report`, else the solid in `output`.
    Print { report: bool, output: Output },
    /// Each repeated mesh (a flat scene's, or a hierarchy's leaf shapes)
    /// fed once into the format's instancing sink and placed per placement
    /// (glTF's `EXT_mesh_gpu_instancing`); `flat` writes what is not
    /// instanced (a moving model, one without repeats).
    Instanced { sink: MakeSink, flat: WriteMeshes },
    /// A hierarchy fed into the format's hierarchy sink, each (leaf shape,
    /// colour) once and placed per leaf (usdz's scene-graph instancing,
    /// docs/usdz.md); a model without one goes to `flat`.
    InstancedHierarchy { sink: MakeSink, flat: Output },
    /// Meshes in `output`; a node graph with the model's animation and
    /// camera path when `animated`; a hierarchy the front end builds is
    /// expanded first when `hierarchy` (glTF asked for flat instancing).
    Flat { output: Output, animated: bool, hierarchy: bool },
}

/// What the meshes of the [`Route::Print`] and [`Route::Flat`] routes become.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Output {
    /// The format's writer, after the meshes are fitted into the unit box when `fit`.
    Meshes { write: WriteMeshes, fit: bool },
    /// A picture of the meshes (the preview stage, docs/preview.md), then its encoding.
    Picture(EncodePicture),
}

impl Route {
    /// The route of `req`: the format's own model writer first, then the
    /// streamed, printed, instanced and flat routes, in that order of precedence.
    pub(crate) fn of(req: &RenderRequest) -> Route {
        let info = req.format.info();
        let opts = &req.export_options;
        let print = opts.print.enabled;
        let fit = opts.fit_unit_box;
        let plain = opts.gltf.is_plain();
        let (output, meshes, model) = match info.writer {
            Writer::Model(write) => return Route::Model(write),
            Writer::Drawing(write) => return Route::Drawing(write),
            Writer::Sink { flat, model } => (Output::Meshes { write: flat, fit }, Some(flat), model),
            Writer::Instancing { meshes, hierarchy } => {
                let output = Output::Meshes { write: meshes, fit };
                if !print && !fit {
                    return Route::InstancedHierarchy { sink: hierarchy, flat: output };
                }
                (output, Some(meshes), None)
            }
            Writer::Picture(encode) => (Output::Picture(encode), None, None),
        };
        match (meshes, model) {
            (Some(empty), Some(sink)) if info.caps.streamed && !print && !fit => return Route::Streamed { sink, empty },
            (Some(flat), Some(sink)) if info.caps.instancing && opts.instancing == Instancing::Gpu && plain && !fit && !print => {
                return Route::Instanced { sink, flat }
            }
            _ => {}
        }
        if print {
            Route::Print { report: opts.print.report, output }
        } else {
            Route::Flat { output, animated: info.caps.node_graph && plain && !fit, hierarchy: info.caps.instancing }
        }
    }

    /// Whether the front end is asked for an instancing hierarchy
    /// (`BuildRequest::hierarchy`). A language whose hierarchy shares its
    /// flat model's subtrees (MDG) is asked wherever the route takes one
    /// without merging it into one mesh: `scene` writes it as it is,
    /// instancing writes each leaf shape once, streamed strips tessellate
    /// leaf by leaf, printing unites once per distinct subtree. A language
    /// whose hierarchy is its own geometry (`own`: L-systems' capped
    /// segments, where the turtle sweeps mitred tubes) is asked by the
    /// formats that instance (so glTF and usdz show one geometry whatever
    /// their options) and by printing, which keeps it only where the exact
    /// flat union is not tried ([`Route::keeps_hierarchy`]); not by the flat
    /// formats, strips included.
    pub(crate) fn wants_hierarchy(&self, own: bool) -> bool {
        match self {
            Route::Model(_) | Route::Instanced { .. } | Route::InstancedHierarchy { .. } | Route::Print { .. } => true,
            Route::Streamed { .. } => !own,
            Route::Flat { hierarchy, .. } => *hierarchy && own,
            Route::Drawing(_) => false,
        }
    }

    /// Charges a hierarchy the front end built as this route writes it,
    /// before anything is written or expanded, so a limit is refused by
    /// name before the output is allocated: `scene` its entries and leaf
    /// shapes (nothing is tessellated); instancing one placement per leaf
    /// and the triangles of one mesh per (shape, colour); every other route
    /// (streamed strips, printing, whose fallback expands, the flat formats)
    /// the expansion's leaves and triangles, as flat geometry.
    pub(crate) fn charge_hierarchy(&self, h: &Hierarchy, detail: u32, budget: &Budget) -> Result<(), LimitExceeded> {
        match self {
            Route::Model(_) => budget.check_total(Limit::Primitives, h.entry_count().saturating_add(h.shapes.len() as u64)),
            Route::Instanced { .. } | Route::InstancedHierarchy { .. } => {
                budget.check_total(Limit::Primitives, h.leaves())?;
                let meshes = h.leaf_counts().keys().map(|&(s, _)| h.shapes.get(s as usize).map_or(0, |sh| sh.triangles(detail))).fold(0u64, u64::saturating_add);
                budget.check_total(Limit::Triangles, meshes)
            }
            _ => {
                budget.check_total(Limit::Primitives, h.leaves())?;
                budget.check_total(Limit::Triangles, h.triangles(detail))
            }
        }
    }

    /// Whether the route keeps a hierarchy it asked for: printing keeps an
    /// own-geometry hierarchy only when its expansion has more triangles than
    /// [`print::EXACT_MAX_TRIANGLES`](crate::print::EXACT_MAX_TRIANGLES);
    /// below, the flat model (the turtle's mitred sweeps, which meet face to
    /// face) is united exactly instead, so the model is built again flat.
    pub(crate) fn keeps_hierarchy(&self, h: &Hierarchy, detail: u32, own: bool) -> bool {
        !(own && matches!(self, Route::Print { .. }) && h.triangles(detail) <= crate::print::EXACT_MAX_TRIANGLES as u64)
    }

    /// Whether the output plays the model's animation and camera path in a
    /// node graph (plain glTF, instanced or flat); everything else shows time 0.
    pub(crate) fn animated(&self) -> bool {
        matches!(self, Route::Instanced { .. } | Route::Flat { animated: true, .. })
    }

    /// The side in pixels of the picture the route makes (`png`'s `size`),
    /// for front ends that evaluate in pixels (`BuildRequest::canvas`).
    pub(crate) fn canvas(&self, req: &RenderRequest) -> Option<u32> {
        matches!(self, Route::Flat { output: Output::Picture(_), .. }).then_some(req.export_options.preview.size)
    }

    /// Whether the output is a picture (a drawing written as SVG, or the
    /// preview), so a model's 2D drawing, when it has one, is all a stage reads.
    pub(crate) fn picture_only(&self) -> bool {
        matches!(self, Route::Drawing(_) | Route::Flat { output: Output::Picture(_), .. })
    }

    /// Whether no merged mesh is built (only the output is promised).
    pub(crate) fn streamed(&self) -> bool {
        matches!(self, Route::Streamed { .. })
    }

    /// Whether placements are written as instances, each charged at the
    /// format's per-instance bound: every one from the model (`scene`), the
    /// repeats under GPU instancing, a hierarchy's leaves written by the
    /// format's own hierarchy writer.
    pub(crate) fn writes_instances(&self) -> bool {
        matches!(self, Route::Model(_) | Route::Instanced { .. } | Route::InstancedHierarchy { .. })
    }
}
