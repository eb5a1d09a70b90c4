//! Instanced glTF (`EXT_mesh_gpu_instancing`), so the output grows with the
//! distinct meshes and the placements, never with the triangles of the
//! expansion:
//! * of an object-instancing hierarchy ([`write_instanced`], L-systems and
//!   MDG): one mesh per (leaf shape, colour) (MDG: per leaf shape, its
//!   colour per instance), drawn once per leaf;
//! * of a flat scene ([`write_scene`], every other language): each mesh
//!   placed more than once ([`Plan`]) written once and drawn per placement
//!   with its translation and, where they differ between its placements,
//!   rotation, per-axis scale and colour, beside the plain meshes of
//!   everything else.

use super::{InstanceData, InstanceLayout};
use crate::export::{ExportError, ExportMeta};
use crate::core::Budget;
use crate::geom::mesh::mesh_bytes;
use crate::geom::{Mesh, NamedMesh};
use crate::model::instancing::{self, MeshKey, Plan, Source, Varying};
use crate::model::hierarchy::PlacedLeaf;
use crate::model::{Hierarchy, Scene};
use glam::{Quat, Vec3};

/// The most per-instance attributes an instanced scene's mesh carries:
/// placements rotate, scale per axis and each has its own colour.
pub(crate) const SCENE_LAYOUT: InstanceLayout = InstanceLayout { rotation: true, scale: true, colour: true };

/// Output bytes per instance of an instanced scene at most (what a front
/// end promises per placement after a mesh's first, before it knows which
/// attributes vary).
pub(crate) const SCENE_INSTANCE_BYTES: u64 = SCENE_LAYOUT.bytes();

/// The attributes a mesh's instances carry: those that vary between them.
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

/// The meshes `plan` writes once, in its order: each prototype (mirrored
/// where its key says) with white vertex colours where every instance
/// carries its own colour, else with the one colour all its instances share.
/// Charged to `budget`; call before [`Plan::residual`] moves the scene's
/// shapes out.
pub fn prototypes(plan: &Plan, scene: &Scene, detail: u32, budget: &mut Budget) -> Result<Vec<NamedMesh>, ExportError> {
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

/// Writes a flat scene as instanced glTF: the `prototypes` of `plan` (from
/// [`prototypes`]), each drawn once per placement, then the `plain` meshes
/// of the rest (the meshed [`Plan::residual`]). The placements are read
/// from `scene` as `plan` walks it and written straight into the output.
pub(crate) fn write_scene(
    scene: &Scene,
    plan: &Plan,
    prototypes: Vec<NamedMesh>,
    plain: Vec<NamedMesh>,
    meta: &ExportMeta,
    glb: bool,
    budget: &mut Budget,
) -> Result<Vec<u8>, ExportError> {
    let mut counts: Vec<u64> = plan.meshes().iter().map(|m| m.1).collect();
    counts.resize(counts.len() + plain.len(), 0);
    let mut layouts: Vec<InstanceLayout> = plan.varying().iter().map(layout).collect();
    layouts.resize(counts.len(), InstanceLayout::default());
    let mut meshes = prototypes;
    meshes.extend(plain);
    super::write_instanced(&meshes, &counts, &layouts, meta, glb, budget, &mut |sink| {
        plan.walk(scene, &mut |slot, p| {
            let [r, g, b, _] = p.colour.map(|c| f32::from(c) / 255.0);
            sink(slot, &InstanceData { translation: p.translation.to_array(), rotation: p.rotation.to_array(), scale: p.scale.to_array(), colour: [r, g, b] });
        });
    })
}

/// Writes `h` as instanced glTF, one instance per leaf, transforms written
/// as the hierarchy is walked. With `per_instance_colour` (MDG, whose flat
/// scenes instance that way) there is one mesh per leaf shape, named by its
/// primitive, whose instances carry rotation, scale and colour where they
/// vary (a first walk finds out), so the file is the one [`write_scene`]
/// makes of the expanded scene; without it (L-systems) one mesh per (leaf
/// shape, colour) with TRANSLATION and ROTATION, and SCALE only when some
/// entry scales. `meta` carries the background, truncation and provenance.
pub(crate) fn write_instanced(h: &Hierarchy, detail: u32, glb: bool, meta: &ExportMeta, per_instance_colour: bool, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
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
    let layouts: Vec<InstanceLayout> = if per_instance_colour { varying.iter().map(|v| v.as_ref().map_or(rigid, layout)).collect() } else { vec![rigid; shapes.len()] };
    let mut meshes = Vec::with_capacity(shapes.len());
    for (m, &shape) in shapes.iter().enumerate() {
        let Some(s) = h.shapes.get(shape as usize) else { continue };
        let p = s.prototype(detail);
        budget.reserve_memory(mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let (colour, name) = match varying.get(m).copied().flatten() {
            Some(v) => (if v.colour { [255; 4] } else { v.first_colour }, s.kind.name().to_ascii_lowercase()),
            None => (index.get(shape as usize).and_then(|v| v.iter().find(|(_, i)| *i == m)).map_or([255; 4], |e| e.0), format!("segment-{m}")),
        };
        let mesh = Mesh { colours: vec![colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        meshes.push(NamedMesh { name, mesh });
    }
    if meshes.is_empty() {
        // Nothing is drawn (an axiom of symbols no turtle command draws): an
        // empty model, written as the flat writers write one — the instanced
        // writer needs a buffer to point its instances into (fuzz finding).
        return if glb { super::write_glb(&[], meta, budget) } else { super::write_gltf(&[], meta, budget) };
    }
    super::write_instanced(&meshes, &mesh_counts, &layouts, meta, glb, budget, &mut |sink| {
        h.walk(&mut |leaf| {
            if let Some(mesh) = mesh_of(leaf) {
                sink(mesh, &placement(leaf));
            }
        })
    })
}
