//! USDZ: the package Apple's AR Quick Look, RealityKit and SceneKit open
//! natively (Pixar Animation Studios, *Universal Scene Description: usdz
//! File Format Specification*, 2018; Apple, *Creating USD files for Apple
//! devices*, 2023). See `docs/usdz.md`.
//!
//! A usdz is an uncompressed zip whose entries' data are 64-byte aligned
//! and whose first entry is the default layer ([`package`]). The layer
//! ([`layer`]) is USD text (`usda`): usd-core 26.11's validators
//! (`UsdValidation`, every registered validator, the usdz package checks
//! included) accept a usda root layer, and the ARKit rules of the older
//! `ComplianceChecker` allow `usda` as a layer format too (its root-layer
//! check that wanted `usdc` was dropped before 24.11), so no binary
//! crate-file writer is needed; `docs/usdz.md` records the check.
//!
//! The layer holds `UsdGeom.Mesh` prims with vertex normals and constant
//! display colour, one per mesh and triangle colour, each bound to a
//! `UsdPreviewSurface` material of its colour; metres (`metersPerUnit =
//! 1`), up-axis Y and a default prim; the provenance (engine, language,
//! seed, parameters, model key) in the layer's `customLayerData`.
//! Numbers are the shortest text that reads back to the same `f32`, so the
//! same meshes give the same bytes on every machine.

pub mod instanced;
pub mod layer;
pub mod package;

use crate::core::budget::Budget;
use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::{ExportError, ExportMeta, ExportOptions};
use crate::geom::NamedMesh;

/// Bytes of USD text a triangle takes at most: its three indices (up to
/// 10 digits and a separator each), its face count, and up to three vertex
/// copies (a point and a normal of three 16-character numbers each: a
/// mesh split by colour repeats a vertex shared by two colours, so a
/// triangle, not a vertex, is what bounds them).
const TRIANGLE_BYTES: u64 = 3 * 12 + 3 + 3 * 2 * (3 * 16 + 8);

/// `usdz`: USD text in a stored zip. Vertices are counted per triangle
/// (see [`TRIANGLE_BYTES`]); each mesh prim and material adds a few
/// hundred bytes, which the writer reserves beside this bound.
pub const USDZ: FormatInfo = FormatInfo {
    name: "usdz",
    extensions: &["usdz"],
    mime: "model/vnd.usdz+zip",
    caps: Capabilities::NONE,
    options: OptionGroup::None,
    size: SizeBound { fixed: 4 * 1024, per_vertex: 0, per_triangle: TRIANGLE_BYTES, per_instance: instanced::INSTANCE_BYTES },
    writer: Writer::Instancing { meshes: write_usdz_with, hierarchy: instanced::hierarchy_sink },
};

/// Bytes a mesh prim's own text (its name, extent, binding, colour and
/// the attributes' declarations) takes at most.
const PRIM_BYTES: u64 = 1024;

/// Bytes a material's text takes at most.
const MATERIAL_BYTES: u64 = 768;

/// [`write_usdz`] with the request's metadata.
fn write_usdz_with(meshes: &[NamedMesh], meta: &ExportMeta, _: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_usdz(meshes, meta, budget)
}

/// Rejects a mesh the layer cannot describe: attribute lists of unequal
/// length, a partial triangle, an index out of range or a non-finite
/// position or normal.
fn check_mesh(m: &NamedMesh) -> Result<(), ExportError> {
    let mesh = &m.mesh;
    let n = mesh.positions.len();
    if (!mesh.normals.is_empty() && mesh.normals.len() != n) || (!mesh.colours.is_empty() && mesh.colours.len() != n) {
        return Err(layer::invalid(m, "normals and colours must have one entry per position"));
    }
    if mesh.indices.len() % 3 != 0 {
        return Err(layer::invalid(m, "index count is not a multiple of 3"));
    }
    if mesh.indices.iter().any(|&i| i as usize >= n) {
        return Err(layer::invalid(m, "index out of range"));
    }
    if mesh.positions.iter().chain(&mesh.normals).flatten().any(|c| !c.is_finite()) {
        return Err(layer::invalid(m, "non-finite position or normal"));
    }
    Ok(())
}

/// Writes a USDZ package of `meshes` with `meta`'s provenance, reserving
/// its worst-case size first. Meshes without triangles are left out (an
/// empty model is a stage with its materials scope only).
pub(crate) fn write_usdz(meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    meshes.iter().try_for_each(check_mesh)?;
    let t: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    // The split by colour: each triangle's three local indices and up to
    // three vertex references, with their hash-map entries.
    let group_bytes = t.saturating_mul(3 * (4 + 4 + 16));
    budget.reserve_memory(group_bytes)?;
    let split: Result<Vec<Vec<layer::Group>>, ExportError> = {
        let mut pace = layer::Pace::new(budget);
        meshes.iter().map(|m| layer::groups(&m.mesh, &mut pace)).collect()
    };
    let split = match split {
        Ok(split) => split,
        Err(e) => {
            budget.release_memory(group_bytes);
            return Err(e);
        }
    };
    let mut colours: Vec<[u8; 4]> = Vec::new();
    for g in split.iter().flatten() {
        if !colours.contains(&g.colour) {
            colours.push(g.colour);
        }
    }
    let prims = split.iter().map(|s| s.len() as u64).sum::<u64>();
    let provenance = meta.provenance.as_ref().map_or(0, |p| p.params_json().len() as u64 + p.model_key.len() as u64);
    // The text and the package each hold about the bound; both live at once.
    let text_bytes = USDZ.size.of(0, t).saturating_add(prims.saturating_mul(PRIM_BYTES)).saturating_add((colours.len() as u64).saturating_mul(MATERIAL_BYTES)).saturating_add(2 * provenance);
    let bytes = text_bytes.saturating_mul(2);
    if let Err(e) = budget.reserve_memory(bytes) {
        budget.release_memory(group_bytes);
        return Err(e.into());
    }
    let out = write_text(meshes, meta, &split, &colours, text_bytes, budget).and_then(|text| {
        drop(split);
        budget.check_deadline()?;
        package::package(text.as_bytes(), &[], budget)
    });
    budget.release_memory(bytes.saturating_add(group_bytes));
    out
}

/// The layer's text: header, materials (`colours`), and a prim per group of
/// `split` (each mesh's colour groups), looking at the deadline as it
/// writes ([`layer::Pace`]).
fn write_text(meshes: &[NamedMesh], meta: &ExportMeta, split: &[Vec<layer::Group>], colours: &[[u8; 4]], capacity: u64, budget: &Budget) -> Result<String, ExportError> {
    let mut text = String::with_capacity(usize::try_from(capacity).unwrap_or(usize::MAX).min(1 << 30));
    layer::header(&mut text, meta);
    layer::materials(&mut text, colours);
    let mut pace = layer::Pace::new(budget);
    for (k, (mesh, groups)) in meshes.iter().zip(split).enumerate() {
        for (j, group) in groups.iter().enumerate() {
            layer::mesh_prim(&mut text, &format!("Mesh_{k}_{j}"), mesh, group, true, &mut pace)?;
        }
    }
    layer::footer(&mut text);
    Ok(text)
}

#[cfg(test)]
mod tests;
