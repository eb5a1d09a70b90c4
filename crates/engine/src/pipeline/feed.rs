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
//! * [`scene`] (with [`prototypes`]) and [`hierarchy`]: a flat scene's
//!   repeated meshes, or a hierarchy's leaf shapes, given once as meshes and
//!   then placed, for the instanced route (glTF's `EXT_mesh_gpu_instancing`)
//!   and, a hierarchy only, usdz's scene-graph instancing.
//!   Where a mesh is laid out before its placements, as glTF's buffer needs,
//!   the placements are streamed into the output as the model is walked.
//! * [`meshes`]: meshes made by the mesher or the print stage, fed plain,
//!   for the flat formats (every route that meshes, and the empty model of
//!   a late answer).

use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::export::{Drawn, ExactPlacement, ExportError, ExportMeta, GeometrySink, InstanceData, InstanceLayout, MeshId};
use crate::geom::mesh::mesh_bytes;
use crate::geom::{Mesh, NamedMesh};
use crate::mesh::pieces::for_each_piece;
use crate::mesh::MeshLayout;
use crate::model::hierarchy::PlacedLeaf;
use crate::model::instancing::{self, MeshKey, Plan, Source, Varying};
use crate::model::{Hierarchy, Scene};
use glam::{DVec3, Quat, Vec3};

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

/// The attributes a mesh's placements carry: those that vary between them.
fn layout(v: &Varying) -> InstanceLayout {
    InstanceLayout { rotation: v.rotation, scale: v.scale, colour: v.colour }
}

/// The name of an instanced scene's mesh (and of its material, when each
/// mesh has its own): the class for a non-default EisenScript class (as its
/// plain mesh is named), else the primitive's keyword or `shape-N`.
fn mesh_name(key: &MeshKey, classes: &[String]) -> String {
    match (classes.get(key.class as usize).filter(|c| key.class > 0 && !c.is_empty()), key.source) {
        (Some(class), _) => class.clone(),
        (None, Source::Primitive(kind)) => kind.name().to_ascii_lowercase(),
        (None, Source::Shape(s)) => format!("shape-{s}"),
    }
}

/// The meshes `plan` instances, in its order, tessellated at `detail`: each
/// prototype (mirrored where its key says) with white vertex colours where
/// every placement carries its own colour, else with the one colour all its
/// placements share. Charged to `budget`; call before [`Plan::residual`]
/// moves the scene's shapes out.
pub(super) fn prototypes(plan: &Plan, scene: &Scene, detail: u32, budget: &mut Budget) -> Result<Vec<NamedMesh>, ExportError> {
    let mut out = Vec::with_capacity(plan.meshes().len());
    for ((key, _), varying) in plan.meshes().iter().zip(plan.varying()) {
        let name = mesh_name(key, &scene.classes);
        let p = instancing::prototype(key, scene, detail).ok_or_else(|| ExportError::InvalidMesh { name: name.clone(), detail: "no such shape".into() })?;
        budget.reserve_memory(mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let colour = if varying.colour { [255; 4] } else { varying.first_colour };
        let mesh = Mesh { colours: vec![colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        out.push(NamedMesh { name, mesh });
    }
    Ok(out)
}

/// Feeds a flat scene's repeated meshes into `sink`: the `prototypes` of
/// `plan` (from [`prototypes`]), each to be drawn once per placement, then
/// the `plain` meshes of the rest (the meshed [`Plan::residual`]), then
/// every placement, read from `scene` as `plan` walks it.
pub(super) fn scene(scene: &Scene, plan: &Plan, prototypes: Vec<NamedMesh>, plain: Vec<NamedMesh>, mut sink: Box<dyn GeometrySink>, meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    sink.begin(meta, budget)?;
    for ((mesh, (_, count)), varying) in prototypes.into_iter().zip(plan.meshes()).zip(plan.varying()) {
        sink.mesh(mesh, Drawn::Instanced { count: *count, layout: layout(varying) }, budget)?;
    }
    for mesh in plain {
        sink.mesh(mesh, Drawn::Plain, budget)?;
    }
    let mut failed = Ok(());
    plan.walk(scene, &mut |slot, p| {
        if failed.is_ok() {
            let [r, g, b, _] = p.colour.map(|c| f32::from(c) / 255.0);
            let exact = ExactPlacement { translation: p.translation.as_dvec3(), rotation: p.rotation.as_dquat(), scale: p.scale.as_dvec3() };
            let at = InstanceData { translation: p.translation.to_array(), rotation: p.rotation.to_array(), scale: p.scale.to_array(), colour: [r, g, b], exact };
            failed = sink.place(MeshId(slot), &at, budget);
        }
    });
    failed?;
    sink.end(budget)
}

/// Feeds an object-instancing hierarchy into `sink`, one placement per
/// leaf, transforms handed over as the hierarchy is walked. With
/// `per_instance_colour` (MDG, whose flat scenes instance that way) there is
/// one mesh per leaf shape, named by its primitive, whose placements carry
/// rotation, scale and colour where they vary (a first walk finds out), so
/// the file is the one [`scene`] makes of the expanded scene; without it
/// (L-systems) one mesh per (leaf shape, colour) with translation and
/// rotation, and scale only when some entry scales (usdz too, whatever the
/// language: it binds one material per prototype). Each placement carries
/// the leaf's f64 frame as well ([`InstanceData::exact`]). The leaf shapes
/// are tessellated here, at `detail`, and charged to `budget`; the walk
/// stops at the sink's first refusal.
pub(super) fn hierarchy(h: &Hierarchy, detail: u32, per_instance_colour: bool, mut sink: Box<dyn GeometrySink>, meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    sink.begin(meta, budget)?;
    let counts = h.leaf_counts();
    // Mesh of each (shape, colour): by shape alone when colours are per instance.
    let mut index: Vec<Vec<([u8; 4], usize)>> = vec![Vec::new(); h.shapes.len()];
    let mut shapes: Vec<u32> = Vec::with_capacity(counts.len());
    let mut mesh_counts: Vec<u64> = Vec::with_capacity(counts.len());
    for (&(shape, colour), &n) in &counts {
        let Some(slot) = index.get_mut(shape as usize) else { continue };
        match slot.first() {
            Some(&(_, m)) if per_instance_colour => mesh_counts[m] = mesh_counts[m].saturating_add(n),
            _ => {
                slot.push((colour, shapes.len()));
                shapes.push(shape);
                mesh_counts.push(n);
            }
        }
    }
    let mesh_of = |leaf: &PlacedLeaf| {
        let slot = index.get(leaf.shape as usize)?;
        let found = if per_instance_colour { slot.first() } else { slot.iter().find(|(c, _)| *c == leaf.colour) };
        found.map(|&(_, mesh)| mesh)
    };
    // As `Placement::of_instance` of the leaf's `Instance` (the f32 values the mesher uses).
    let placement = |leaf: &PlacedLeaf| {
        let [r, g, b, _] = leaf.colour.map(|c| f32::from(c) / 255.0);
        InstanceData {
            translation: leaf.translation.as_vec3().to_array(),
            rotation: leaf.rotation.as_quat().normalize().to_array(),
            scale: [leaf.scale as f32; 3],
            colour: [r, g, b],
            exact: ExactPlacement { translation: leaf.translation, rotation: leaf.rotation, scale: DVec3::splat(leaf.scale) },
        }
    };
    // What varies per mesh, as `Plan` records it of the flat scene (MDG
    // only; exact comparisons): colours from the leaf counts (a leaf's colour
    // is its entry's), rotation and scale by a walk that stops once every
    // mesh has both.
    let mut varying: Vec<Option<Varying>> = vec![None; if per_instance_colour { shapes.len() } else { 0 }];
    for (&(shape, colour), _) in counts.iter().filter(|_| per_instance_colour) {
        let Some(v) = index.get(shape as usize).and_then(|v| v.first()).and_then(|e| varying.get_mut(e.1)) else { continue };
        let first = v.is_none();
        v.get_or_insert(Varying::NONE).note(Quat::IDENTITY, Vec3::ONE, colour, first);
    }
    let mut open = varying.len();
    if open > 0 {
        h.walk_while(&mut |leaf| {
            let Some(Some(v)) = mesh_of(leaf).and_then(|m| varying.get_mut(m)) else { return true };
            if !(v.rotation && v.scale) {
                let d = placement(leaf);
                // The colour was noted from the leaf counts: note the first again.
                v.note(Quat::from_array(d.rotation), Vec3::from_array(d.scale), v.first_colour, false);
                open -= usize::from(v.rotation && v.scale);
            }
            open > 0
        });
    }
    let rigid = InstanceLayout { rotation: true, scale: h.is_scaled(), colour: false };
    for (m, &shape) in shapes.iter().enumerate() {
        let Some(s) = h.shapes.get(shape as usize) else { continue };
        let p = s.prototype(detail);
        budget.reserve_memory(mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let (colour, name, carried) = match varying.get(m).copied().flatten() {
            Some(v) => (if v.colour { [255; 4] } else { v.first_colour }, s.kind.name().to_ascii_lowercase(), layout(&v)),
            None => (index.get(shape as usize).and_then(|v| v.iter().find(|(_, i)| *i == m)).map_or([255; 4], |e| e.0), format!("segment-{m}"), rigid),
        };
        let mesh = Mesh { colours: vec![colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        sink.mesh(NamedMesh { name, mesh }, Drawn::Instanced { count: mesh_counts[m], layout: carried }, budget)?;
    }
    // The walk stops at the first refusal (the deadline, a limit).
    let mut failed = Ok(());
    h.walk_while(&mut |leaf| {
        if let Some(mesh) = mesh_of(leaf) {
            failed = sink.place(MeshId(mesh), &placement(leaf), budget);
        }
        failed.is_ok()
    });
    failed?;
    sink.end(budget)
}

/// Feeds meshes made by the mesher or the print stage (merged, per kind,
/// one printable solid) into `sink` as plain meshes, in order: the flat
/// formats' route, through [`FlatSink`](crate::export::FlatSink).
pub(super) fn meshes(meshes: Vec<NamedMesh>, mut sink: Box<dyn GeometrySink>, meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    sink.begin(meta, budget)?;
    for mesh in meshes {
        sink.mesh(mesh, Drawn::Plain, budget)?;
    }
    sink.end(budget)
}
