//! Instanced glTF of an object-instancing hierarchy: one mesh per (leaf
//! shape, colour), drawn once per leaf with `EXT_mesh_gpu_instancing`, so
//! the output grows with the distinct shapes and the leaf count, never with
//! the triangles of the expansion.

use super::{ExportError, ExportMeta};
use crate::core::Budget;
use crate::geom::mesh::mesh_bytes;
use crate::geom::{Mesh, NamedMesh};
use crate::model::Hierarchy;

/// Writes `h` as instanced glTF: one mesh per (leaf shape, colour), one
/// instance per leaf, transforms written as the hierarchy is walked;
/// `provenance` goes in `asset.extras`.
pub fn write_instanced(h: &Hierarchy, detail: u32, glb: bool, provenance: Option<&super::Provenance>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let counts = h.leaf_counts();
    let mut index: Vec<Vec<([u8; 4], usize)>> = vec![Vec::new(); h.shapes.len()];
    let mut meshes = Vec::with_capacity(counts.len());
    for (i, &(shape, colour)) in counts.keys().enumerate() {
        let Some(s) = h.shapes.get(shape as usize) else { continue };
        let p = s.prototype(detail);
        budget.reserve_memory(mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let mesh = Mesh { colours: vec![colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        meshes.push(NamedMesh { name: format!("segment-{i}"), mesh });
        if let Some(v) = index.get_mut(shape as usize) {
            v.push((colour, i));
        }
    }
    let counts: Vec<u64> = counts.values().copied().collect();
    let meta = ExportMeta { background: None, truncated: h.truncated.is_some(), graph: None, material_per_mesh: false, camera: None, provenance: provenance.cloned() };
    if meshes.is_empty() {
        // Nothing is drawn (an axiom of symbols no turtle command draws): an
        // empty model, written as the flat writers write one — the instanced
        // writer needs a buffer to point its instances into (fuzz finding).
        return if glb { super::gltf::write_glb(&[], &meta, budget) } else { super::gltf::write_gltf(&[], &meta, budget) };
    }
    let bytes = super::gltf::write_instanced(&meshes, &counts, &meta, glb, budget, &mut |sink| {
        h.walk(&mut |leaf| {
            let Some(&(_, mesh)) = index.get(leaf.shape as usize).and_then(|v| v.iter().find(|(c, _)| *c == leaf.colour)) else { return };
            sink(mesh, leaf.translation.as_vec3().to_array(), leaf.rotation.as_quat().normalize().to_array());
        })
    })?;
    Ok(bytes)
}
