//! The stages every model goes through after its front end, one function
//! per [`Route`]: the hierarchy written as it is or expanded, then
//! printing, meshing or the preview, then the writer. The route was decided
//! before the front end ran; nothing here reads the request's flags to
//! decide it again.

use super::feed;
use super::route::{Output, Route};
use super::{RenderError, RenderOutput, RenderRequest};
use crate::core::budget::{Budget, Limit, LimitExceeded, OnLimit};
use crate::core::timing::{Phase, PhaseTimes, StageClock};
use crate::export::{self, ExportError, ExportMeta, FlatSink, GeometrySink, MakeSink, Provenance, WriteMeshes};
use crate::geom::NamedMesh;
use crate::mesh;
use crate::model::{instancing, Model};
use std::time::Duration;

/// Runs the stages of `route` on `model`.
pub(super) fn run(route: Route, mut model: Model, provenance: Provenance, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    match route {
        Route::Model(write) => {
            // Instances, hierarchy and the meshes that are not instances, as made (docs/scene-format.md).
            let h = model.hierarchy.take();
            let (bytes, triangles) = write(&model.scene, h.as_ref(), req.detail, req.layout, &req.export_options, Some(&provenance), budget)?;
            clock.lap(Phase::Export);
            let truncated = h.as_ref().map_or(model.scene.truncated, |h| h.truncated);
            Ok(summary(bytes, &model, triangles, truncated))
        }
        Route::Drawing(write) => match model.drawing.take() {
            // A 2D design as SVG, as cfdg -V writes it.
            Some(drawing) => {
                let bytes = write(&drawing, Some(&provenance), budget)?;
                clock.lap(Phase::Export);
                Ok(summary(bytes, &model, 0, model.scene.truncated))
            }
            None => Err(no_drawing(req.format, model.language).into()),
        },
        // A 2D design's picture is the drawing itself, not a view of its tiles.
        Route::Flat { output: Output::Picture(encode), .. } if model.drawing.is_some() => {
            let drawing = model.drawing.take().unwrap_or_default();
            let image = crate::preview::drawing::render(&drawing, &req.export_options.preview, budget).map_err(ExportError::from)?;
            clock.lap(Phase::Preview);
            let bytes = encode(&image, Some(&provenance), budget)?;
            clock.lap(Phase::Export);
            Ok(summary(bytes, &model, 0, model.scene.truncated))
        }
        Route::Streamed { sink, empty } => streamed(model, provenance, sink, empty, req, budget, clock),
        Route::Print { report, output } => print(model, provenance, report, output, req, budget, clock),
        Route::Instanced { sink, flat: write } => instanced(model, provenance, sink, write, req, budget, clock),
        Route::InstancedHierarchy { sink, flat: output } => match model.hierarchy.take() {
            Some(h) => {
                let meta = hierarchy_meta(&model, h.truncated.is_some(), provenance);
                // One prototype per (leaf shape, colour): usdz binds a material per prototype.
                let bytes = feed::hierarchy(&h, req.detail, false, sink(&req.export_options), &meta, budget)?;
                clock.lap(Phase::Export);
                Ok(summary(bytes, &model, h.triangles(req.detail), h.truncated))
            }
            None => flat(model, provenance, output, None, req, budget, clock),
        },
        Route::Flat { output, animated, .. } => {
            if let Some(h) = model.hierarchy.take() {
                model.scene = h.expand(req.detail, budget)?;
            }
            let graph = (animated && has_motion(&model)).then_some(Charge::AsDrawn);
            flat(model, provenance, output, graph, req, budget, clock)
        }
    }
}

/// The typed refusal of a drawing format (`svg`) for a language whose
/// models have no 2D drawing: a client error naming the capability.
pub(super) fn no_drawing(format: crate::export::Format, language: crate::lang::Language) -> ExportError {
    let name = format.name();
    ExportError::InvalidOptions { format: name, detail: export::no_drawing(name, &format!("`{}` models", language.name())) }
}

/// Whether the model moves: an animation rig or a camera path, which play
/// in a node graph (written flat) where the route has one.
fn has_motion(model: &Model) -> bool {
    model.scene.rig.is_some() || model.scene.camera.as_ref().is_some_and(|c| c.is_path())
}

/// The print route: a hierarchy united once per distinct subtree, or (a
/// leaf that is no solid, a union with bad edges) expanded and united flat;
/// then the report, or the solid in the route's output.
fn print(mut model: Model, provenance: Provenance, report: bool, output: Output, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    let opts = &req.export_options.print;
    let mut printed = None;
    if let Some(h) = model.hierarchy.take() {
        printed = crate::print::make_printable_hierarchy(&h, req.detail, opts, budget)?;
        match printed {
            Some(_) => model.scene.truncated = h.truncated,
            None => model.scene = h.expand(req.detail, budget)?,
        }
    }
    let (solid, measured) = match printed {
        Some(done) => done,
        None => {
            // Printing unites closed parts, so it needs them apart (and shows time 0).
            let parts = mesh::build_parts(&model.scene, req.detail, budget)?;
            clock.lap(Phase::Mesh);
            crate::print::make_printable(&parts, opts, budget)?
        }
    };
    clock.lap(Phase::Print);
    crate::core::memprobe::mark("print", budget);
    if report {
        let bytes = serde_json::to_vec_pretty(&measured).map_err(|e| RenderError::Export(e.into()))?;
        clock.lap(Phase::Export);
        return Ok(summary(bytes, &model, measured.triangles, model.scene.truncated));
    }
    let truncated = model.scene.truncated;
    let out = write_meshes(solid, flat_meta(&model, provenance, truncated, None), truncated, output, req, budget, clock)?;
    Ok(RenderOutput { print: Some(measured.summary()), ..summary(out.bytes, &model, out.triangles, out.truncated) })
}

/// The GPU-instanced glTF route: a hierarchy written as instances; a flat
/// scene with repeated meshes written once per mesh; a moving model (a node
/// graph is written flat) or one with no repeats, flat.
fn instanced(mut model: Model, provenance: Provenance, make: MakeSink, write: WriteMeshes, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    if let Some(h) = model.hierarchy.take() {
        let meta = hierarchy_meta(&model, h.truncated.is_some(), provenance);
        // MDG's instances carry their colours, as its flat scenes' do; L-systems' meshes do.
        let per_instance_colour = model.language.front_end().colours_per_instance();
        let bytes = feed::hierarchy(&h, req.detail, per_instance_colour, make(&req.export_options), &meta, budget)?;
        clock.lap(Phase::Export);
        return Ok(summary(bytes, &model, h.triangles(req.detail), h.truncated));
    }
    let output = Output::Meshes { write, fit: false };
    if has_motion(&model) {
        // The front end charged repeats as instances, but a node graph is
        // written flat: its triangles meet the limit when meshed.
        return flat(model, provenance, output, Some(Charge::Triangles), req, budget, clock);
    }
    let plan = instancing::Plan::new(&model.scene);
    if plan.is_empty() {
        // No mesh repeats: the plain writer makes the bytes a flat request would.
        return flat(model, provenance, output, None, req, budget, clock);
    }
    let prototypes = feed::prototypes(&plan, &model.scene, req.detail, budget)?;
    let residual = plan.residual(&mut model.scene, budget)?;
    let (meshes, cut) = mesh::build_meshes_until(&residual, req.detail, req.layout, req.on_limit, budget)?;
    budget.release_memory(instancing::residual_bytes(instancing::residual_counts(&residual)));
    drop(residual);
    clock.lap(Phase::Mesh);
    budget.set_stage_share(None);
    let truncated = model.scene.truncated.or(cut);
    let instanced = plan.meshes().iter().zip(&prototypes).map(|((_, n), p)| n.saturating_mul(p.mesh.triangle_count() as u64));
    let drawn = meshes.iter().map(|m| m.mesh.triangle_count() as u64).chain(instanced).fold(0u64, u64::saturating_add);
    let meta = flat_meta(&model, provenance, truncated, None);
    let scene = &model.scene;
    let written = budget.check_deadline().map_err(ExportError::from).and_then(|()| {
        feed::scene(scene, &plan, prototypes, meshes, make(&req.export_options), &meta, budget)
    });
    let empty = |meta: &ExportMeta, budget: &mut Budget| feed::meshes(Vec::new(), flat_sink(write, req), meta, budget);
    let (bytes, triangles, truncated) = empty_if_late(written, drawn, truncated, meta, req.on_limit, budget, empty)?;
    clock.lap(Phase::Export);
    Ok(summary(bytes, &model, triangles, truncated))
}

/// How the triangles of a node graph's meshes are charged.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Charge {
    /// As the front end charged them (primitive by primitive).
    AsDrawn,
    /// Against the triangle limit once meshed: the front end charged
    /// repeated meshes as instances, which a node graph is not.
    Triangles,
}

/// The flat route: the scene meshed (in a node graph, charged as `graph`
/// says, when there is one), then written by `output`.
fn flat(model: Model, provenance: Provenance, output: Output, graph: Option<Charge>, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    let scene = &model.scene;
    let (meshes, graph, cut) = if let Some(charge) = graph {
        let (meshes, graph) = mesh::build_with_graph(scene, req.detail, req.layout, budget)?;
        if charge == Charge::Triangles {
            let drawn: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
            budget.check_total(Limit::Triangles, drawn)?;
        }
        (meshes, Some(graph), None)
    } else {
        let (meshes, cut) = mesh::build_meshes_until(scene, req.detail, req.layout, req.on_limit, budget)?;
        (meshes, None, cut)
    };
    clock.lap(Phase::Mesh);
    let truncated = scene.truncated.or(cut);
    let meta = flat_meta(&model, provenance, truncated, graph);
    let out = write_meshes(meshes, meta, truncated, output, req, budget, clock)?;
    Ok(summary(out.bytes, &model, out.triangles, out.truncated))
}

/// The scene-level metadata of a model written from its instances or its
/// hierarchy (instanced glTF, usdz, streamed strips): the background and
/// provenance only, no node graph, no camera, no material per mesh.
fn hierarchy_meta(model: &Model, truncated: bool, provenance: Provenance) -> ExportMeta {
    ExportMeta {
        background: model.scene.background,
        truncated,
        graph: None,
        material_per_mesh: false,
        camera: None,
        provenance: Some(provenance),
    }
}

/// The scene-level metadata of meshes written flat: a camera path plays in
/// the node graph when there is one, otherwise the camera is shown at time 0.
fn flat_meta(model: &Model, provenance: Provenance, truncated: Option<LimitExceeded>, graph: Option<crate::model::graph::NodeGraph>) -> ExportMeta {
    let scene = &model.scene;
    let in_graph = graph.is_some();
    ExportMeta {
        background: scene.background,
        truncated: truncated.is_some(),
        graph,
        material_per_mesh: !scene.classes.is_empty(),
        camera: scene.camera.clone().filter(|c| !(c.is_path() && in_graph)),
        provenance: Some(provenance),
    }
}

/// What [`write_meshes`] wrote.
struct Written {
    bytes: Vec<u8>,
    triangles: u64,
    truncated: Option<LimitExceeded>,
}

/// Meshes to bytes by `output`: the preview stage and its encoding, or the
/// unit-box fit (a stage, not the writer's work) and the format's writer.
fn write_meshes(mut meshes: Vec<NamedMesh>, meta: ExportMeta, truncated: Option<LimitExceeded>, output: Output, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<Written, RenderError> {
    if req.format.info().caps.positions_only {
        // Before the output is allocated, so a big model's peak stays under 2× the file.
        export::keep_positions_only(&mut meshes);
    }
    budget.set_stage_share(None);
    let drawn: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    let (bytes, triangles, truncated) = match output {
        Output::Picture(encode) => {
            // A picture needs no fitting or scene metadata beyond its
            // provenance. Too late to draw under `truncate`: the background
            // alone, saying why, as a late mesh writer answers an empty model.
            let drawn_picture = crate::preview::render(&meshes, &req.export_options.preview, budget).map_err(ExportError::from).and_then(|image| {
                clock.lap(Phase::Preview);
                encode(&image, meta.provenance.as_ref(), budget)
            });
            let background = |meta: &ExportMeta, budget: &mut Budget| {
                let image = crate::preview::render(&[], &req.export_options.preview, budget).map_err(ExportError::from)?;
                encode(&image, meta.provenance.as_ref(), budget)
            };
            empty_if_late(drawn_picture, drawn, truncated, meta, req.on_limit, budget, background)?
        }
        Output::Meshes { write, fit } => {
            // Writing a large model takes a share of the deadline; a model that arrives here late is not started.
            let written = budget.check_deadline().map_err(ExportError::from).and_then(|()| match fit {
                true => fit_unit_box(&meshes, &meta, budget).and_then(|(fitted, meta)| feed::meshes(fitted, flat_sink(write, req), &meta, budget)),
                false => feed::meshes(meshes, flat_sink(write, req), &meta, budget),
            });
            let empty = |meta: &ExportMeta, budget: &mut Budget| feed::meshes(Vec::new(), flat_sink(write, req), meta, budget);
            empty_if_late(written, drawn, truncated, meta, req.on_limit, budget, empty)?
        }
    };
    clock.lap(Phase::Export);
    Ok(Written { bytes, triangles, truncated })
}

/// The format's flat sink: its merged-mesh writer with the request's options.
fn flat_sink(write: WriteMeshes, req: &RenderRequest) -> Box<dyn GeometrySink> {
    Box::new(FlatSink::new(req.format.name(), write, req.export_options))
}

/// The unit-box fit (icons, docs/icons.md): the meshes scaled and centred
/// into the unit box, and the camera moved with them, so the fitted model
/// is seen as the original was.
fn fit_unit_box(meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<(Vec<NamedMesh>, ExportMeta), ExportError> {
    let (fitted, map) = crate::geom::normalize::fit_unit_box(meshes, budget)?;
    let camera = meta.camera.as_ref().map(|c| map.map_or_else(|| c.clone(), |(centre, scale)| c.fitted(centre, scale)));
    Ok((fitted, ExportMeta { camera, ..meta.clone() }))
}

/// The written model with its triangles and truncation, or — when writing
/// failed at the deadline under `truncate` — too late to write what was
/// made: the answer is then an empty model written by `empty` that says
/// why, still (nearly) within the deadline.
fn empty_if_late(
    written: Result<Vec<u8>, ExportError>,
    drawn: u64,
    truncated: Option<LimitExceeded>,
    meta: ExportMeta,
    on_limit: OnLimit,
    budget: &mut Budget,
    empty: impl FnOnce(&ExportMeta, &mut Budget) -> Result<Vec<u8>, ExportError>,
) -> Result<(Vec<u8>, u64, Option<LimitExceeded>), RenderError> {
    match written {
        Ok(bytes) => Ok((bytes, drawn, truncated)),
        Err(ExportError::Limit(e)) if e.limit == Limit::Deadline && on_limit == OnLimit::Truncate => {
            budget.lift_deadline();
            let meta = ExportMeta { truncated: true, graph: None, ..meta };
            Ok((empty(&meta, budget)?, 0, truncated.or(Some(e))))
        }
        Err(e) => Err(e.into()),
    }
}

/// The model streamed into the format's sink (strips, docs/strips-format.md):
/// a first pass for what the sink codes against (strips' bounds and
/// palette; timed as meshing, and cut at the meshing deadline under
/// `truncate`), then the pieces, each tessellated and handed over in turn.
/// No merged mesh is built and a hierarchy is walked, not expanded.
fn streamed(mut model: Model, provenance: Provenance, make: MakeSink, empty: WriteMeshes, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    let h = model.hierarchy.take();
    let src = feed::ModelPieces { scene: &model.scene, hierarchy: h.as_ref(), detail: req.detail, layout: req.layout };
    let mut sink = make(&req.export_options);
    let surveyed = feed::survey(&src, sink.as_mut(), req.on_limit, budget)?;
    clock.lap(Phase::Mesh);
    budget.set_stage_share(None);
    let truncated = h.as_ref().and_then(|h| h.truncated).or(model.scene.truncated).or(surveyed.cut);
    let meta = hierarchy_meta(&model, truncated.is_some(), provenance);
    let written = feed::pieces(&src, sink, &surveyed, &meta, budget);
    let empty = |meta: &ExportMeta, budget: &mut Budget| feed::meshes(Vec::new(), flat_sink(empty, req), meta, budget);
    let (bytes, triangles, truncated) = empty_if_late(written, surveyed.triangles, truncated, meta, req.on_limit, budget, empty)?;
    clock.lap(Phase::Export);
    Ok(summary(bytes, &model, triangles, truncated))
}

/// The output of a render whose bytes are written (times are filled in by [`super::render`]).
fn summary(bytes: Vec<u8>, model: &Model, triangles: u64, truncated: Option<LimitExceeded>) -> RenderOutput {
    RenderOutput {
        bytes,
        language: model.language,
        seed: model.seed,
        primitives: model.primitives,
        triangles,
        truncated,
        print: None,
        warnings: model.warnings.clone(),
        elapsed: Duration::ZERO,
        phases: PhaseTimes::default(),
    }
}
