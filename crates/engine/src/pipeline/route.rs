//! The route: how a request's model becomes bytes, decided once from the
//! validated request (its format's descriptor and options) before the
//! front end runs. The stages follow it and nothing downstream tests the
//! request's flags again (issue 22: the route was re-decided from flags in
//! a dozen places, and two of them could disagree).
//!
//! The front end is told only what the route needs from it
//! ([`Route::hierarchy`], [`Route::animated`]), never the format.

use super::RenderRequest;
use crate::export::{EncodePicture, Instancing, WriteDrawing, WriteHierarchy, WriteMeshes, WriteModel, Writer};
use crate::model::HierarchyUse;

/// The way a model is written, chosen by [`Route::of`].
#[derive(Debug, Clone, Copy)]
pub(crate) enum Route {
    /// The format writes the model as made: its instances and hierarchy,
    /// nothing tessellated (`scene`, docs/scene-format.md).
    Model(WriteModel),
    /// The format writes the model's 2D drawing (`svg`), which only a
    /// language that draws makes (Context Free); others are refused.
    Drawing(WriteDrawing),
    /// Strips written from the model a chunk at a time: no merged mesh,
    /// a hierarchy walked, not expanded (docs/strips-format.md); `empty`
    /// writes the empty model a late answer falls back to.
    StreamedStrips { empty: WriteMeshes },
    /// One watertight solid from the print stage (docs/print.md), then
    /// its report as JSON when `report`, else the solid in `output`.
    Print { report: bool, output: Output },
    /// glTF writing each repeated mesh once and drawing it per placement
    /// (`EXT_mesh_gpu_instancing`), `.glb` when `binary`; `flat` writes
    /// what is not instanced (a moving model, one without repeats).
    InstancedGltf { binary: bool, flat: WriteMeshes },
    /// A hierarchy written by the format's own writer, each leaf shape once
    /// and placed per leaf (usdz's scene-graph instancing, docs/usdz.md);
    /// a model without one goes to `flat`.
    InstancedHierarchy { write: WriteHierarchy, flat: Output },
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
        let (output, meshes) = match info.writer {
            Writer::Model(write) => return Route::Model(write),
            Writer::Drawing(write) => return Route::Drawing(write),
            Writer::Meshes(write) => (Output::Meshes { write, fit }, Some(write)),
            Writer::Instancing { meshes, hierarchy } => {
                let output = Output::Meshes { write: meshes, fit };
                if !print && !fit {
                    return Route::InstancedHierarchy { write: hierarchy, flat: output };
                }
                (output, Some(meshes))
            }
            Writer::Picture(encode) => (Output::Picture(encode), None),
        };
        match meshes {
            Some(empty) if info.caps.streamed && !print && !fit => return Route::StreamedStrips { empty },
            Some(flat) if info.caps.instancing && opts.instancing == Instancing::Gpu && plain && !fit && !print => {
                return Route::InstancedGltf { binary: !info.caps.text, flat }
            }
            _ => {}
        }
        if print {
            Route::Print { report: opts.print.report, output }
        } else {
            Route::Flat { output, animated: info.caps.node_graph && plain && !fit, hierarchy: info.caps.instancing }
        }
    }

    /// Whether the front end should build an instancing hierarchy, and how
    /// the limits charge it (`HierarchyUse` documents each answer).
    pub(crate) fn hierarchy(&self) -> HierarchyUse {
        match self {
            Route::Model(_) => HierarchyUse::Required,
            Route::Print { .. } => HierarchyUse::Union,
            Route::InstancedGltf { .. } | Route::InstancedHierarchy { .. } | Route::Flat { hierarchy: true, .. } => HierarchyUse::Preferred,
            Route::StreamedStrips { .. } => HierarchyUse::Streamed,
            Route::Flat { hierarchy: false, .. } | Route::Drawing(_) => HierarchyUse::Never,
        }
    }

    /// Whether the output plays the model's animation and camera path in a
    /// node graph (plain glTF, instanced or flat); everything else shows time 0.
    pub(crate) fn animated(&self) -> bool {
        matches!(self, Route::InstancedGltf { .. } | Route::Flat { animated: true, .. })
    }

    /// The side in pixels of the picture the route makes (`png`'s `size`),
    /// for front ends that evaluate in pixels (`BuildRequest::canvas`).
    pub(crate) fn canvas(&self, req: &RenderRequest) -> Option<u32> {
        matches!(self, Route::Flat { output: Output::Picture(_), .. }).then_some(req.export_options.preview.size)
    }

    /// Whether no merged mesh is built (only the output is promised).
    pub(crate) fn streamed(&self) -> bool {
        matches!(self, Route::StreamedStrips { .. })
    }

    /// Whether placements are written as instances, each charged at the
    /// format's per-instance bound: every one from the model (`scene`), the
    /// repeats under GPU instancing, a hierarchy's leaves written by the
    /// format's own hierarchy writer.
    pub(crate) fn writes_instances(&self) -> bool {
        matches!(self, Route::Model(_) | Route::InstancedGltf { .. } | Route::InstancedHierarchy { .. })
    }
}
