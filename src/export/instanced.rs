//! Instanced glTF (`EXT_mesh_gpu_instancing`), so the output grows with the
//! distinct meshes and the placements, never with the triangles of the
//! expansion:
//! * of an object-instancing hierarchy ([`write_instanced`], L-systems): one
//!   mesh per (leaf shape, colour), drawn once per leaf;
//! * of a flat scene ([`write_scene`], every other language): each mesh
//!   placed more than once ([`Plan`]) written once and drawn per placement
//!   with its translation, rotation, per-axis scale and colour, beside the
//!   plain meshes of everything else.

use super::gltf::{InstanceData, InstanceLayout};
use super::{ExportError, ExportMeta};
use crate::core::Budget;
use crate::geom::mesh::mesh_bytes;
use crate::geom::{Mesh, NamedMesh};
use crate::model::instancing::{self, MeshKey, Plan, Source};
use crate::model::{Hierarchy, Scene};

/// The per-instance attributes of an instanced scene: placements scale per
/// axis and each has its own colour.
pub const SCENE_LAYOUT: InstanceLayout = InstanceLayout { scale: true, colour: true };

/// Output bytes per instance of an instanced scene (what a front end
/// promises per placement after a mesh's first).
pub const SCENE_INSTANCE_BYTES: u64 = SCENE_LAYOUT.bytes();

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
/// where its key says) with white vertex colours, since every instance
/// carries its own. Charged to `budget`; call before [`Plan::residual`]
/// moves the scene's shapes out.
pub fn prototypes(plan: &Plan, scene: &Scene, detail: u32, budget: &mut Budget) -> Result<Vec<NamedMesh>, ExportError> {
    let mut out = Vec::with_capacity(plan.meshes().len());
    for (key, _) in plan.meshes() {
        let name = mesh_name(key, &scene.classes);
        let p = instancing::prototype(key, scene, detail).ok_or_else(|| ExportError::InvalidMesh { name: name.clone(), detail: "no such shape".into() })?;
        budget.reserve_memory(mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let mesh = Mesh { colours: vec![[255; 4]; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        out.push(NamedMesh { name, mesh });
    }
    Ok(out)
}

/// Writes a flat scene as instanced glTF: the `prototypes` of `plan` (from
/// [`prototypes`]), each drawn once per placement, then the `plain` meshes
/// of the rest (the meshed [`Plan::residual`]). The placements are read
/// from `scene` as `plan` walks it and written straight into the output.
pub fn write_scene(
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
    let mut meshes = prototypes;
    meshes.extend(plain);
    super::gltf::write_instanced(&meshes, &counts, SCENE_LAYOUT, meta, glb, budget, &mut |sink| {
        plan.walk(scene, &mut |slot, p| {
            let [r, g, b, _] = p.colour.map(|c| f32::from(c) / 255.0);
            sink(slot, &InstanceData { translation: p.translation.to_array(), rotation: p.rotation.to_array(), scale: p.scale.to_array(), colour: [r, g, b] });
        });
    })
}

/// Writes `h` as instanced glTF, one instance per leaf, transforms written
/// as the hierarchy is walked. With `per_instance_colour` (MDG, whose flat
/// scenes instance that way) there is one white mesh per leaf shape, named
/// by its primitive, and each instance carries its colour and scale, so the
/// file is what [`write_scene`] makes of the expanded scene; without it
/// (L-systems) one mesh per (leaf shape, colour), and a SCALE only when some
/// entry scales. `meta` carries the background, truncation and provenance.
pub fn write_instanced(h: &Hierarchy, detail: u32, glb: bool, meta: &ExportMeta, per_instance_colour: bool, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let counts = h.leaf_counts();
    // Mesh of each (shape, colour): by shape alone when colours are per instance.
    let mut index: Vec<Vec<([u8; 4], usize)>> = vec![Vec::new(); h.shapes.len()];
    let mut meshes: Vec<NamedMesh> = Vec::with_capacity(counts.len());
    let mut mesh_counts: Vec<u64> = Vec::with_capacity(counts.len());
    for (&(shape, colour), &n) in &counts {
        let Some(s) = h.shapes.get(shape as usize) else { continue };
        let Some(slot) = index.get_mut(shape as usize) else { continue };
        if per_instance_colour {
            if let Some(&(_, m)) = slot.first() {
                mesh_counts[m] = mesh_counts[m].saturating_add(n);
                continue;
            }
        }
        let p = s.prototype(detail);
        budget.reserve_memory(mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let (vertex_colour, name) = if per_instance_colour { ([255; 4], s.kind.name().to_ascii_lowercase()) } else { (colour, format!("segment-{}", meshes.len())) };
        let mesh = Mesh { colours: vec![vertex_colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        slot.push((colour, meshes.len()));
        meshes.push(NamedMesh { name, mesh });
        mesh_counts.push(n);
    }
    if meshes.is_empty() {
        // Nothing is drawn (an axiom of symbols no turtle command draws): an
        // empty model, written as the flat writers write one — the instanced
        // writer needs a buffer to point its instances into (fuzz finding).
        return if glb { super::gltf::write_glb(&[], meta, budget) } else { super::gltf::write_gltf(&[], meta, budget) };
    }
    let layout = if per_instance_colour { SCENE_LAYOUT } else { InstanceLayout { scale: h.is_scaled(), colour: false } };
    super::gltf::write_instanced(&meshes, &mesh_counts, layout, meta, glb, budget, &mut |sink| {
        h.walk(&mut |leaf| {
            let Some(slot) = index.get(leaf.shape as usize) else { return };
            let found = if per_instance_colour { slot.first() } else { slot.iter().find(|(c, _)| *c == leaf.colour) };
            let Some(&(_, mesh)) = found else { return };
            let rotation = leaf.rotation.as_quat().normalize().to_array();
            let s = leaf.scale as f32;
            let [r, g, b, _] = leaf.colour.map(|c| f32::from(c) / 255.0);
            sink(mesh, &InstanceData { translation: leaf.translation.as_vec3().to_array(), rotation, scale: [s; 3], colour: [r, g, b] });
        })
    })
}
