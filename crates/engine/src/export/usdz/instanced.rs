//! USDZ of an object-instancing hierarchy (L-systems, memoised MDG): each
//! (leaf shape, colour) written once as a prototype and placed once per
//! leaf with USD's scene-graph instancing (Pixar, *USD Glossary:
//! Instancing*, openusd.org): an `instanceable` `Xform` per leaf with its
//! world transform, its colour's material bound, referencing its
//! prototype. The file then grows with the leaves, not their triangles:
//! the Sierpinski bush's million triangles are 40 meshes and 35 310
//! placements.
//!
//! Each prototype is a layer of its own in the package
//! (`prototypes/P_N.usda`), referenced by asset path, not a prim of the
//! default layer referenced by prim path: three.js's `USDLoader` (r187,
//! `examples/jsm/loaders/usd/USDComposer.js`, `_getReferences`) resolves
//! only `@asset@` references, and neither it nor ARKit's rules take a
//! `PointInstancer` (usd-core's `ARKitPrimTypeChecker`). Layer references
//! inside the package are what AR Quick Look reads too (`docs/usdz.md`).

use super::layer::{self, Group};
use super::package;
use crate::core::budget::Budget;
use crate::export::{ExportError, ExportMeta, DEADLINE_EVERY};
use crate::geom::mesh::mesh_bytes;
use crate::geom::{Mesh, NamedMesh};
use crate::model::hierarchy::PlacedLeaf;
use crate::model::Hierarchy;
use glam::DMat4;
use std::collections::HashMap;
use std::fmt::Write as _;

/// Bytes of the default layer one placement takes at most: the prim
/// (about 280 bytes with its name, binding and reference), and a 4×4
/// matrix of numbers of at most 16 characters with their separators
/// (about 330), and the op order (about 60).
pub const INSTANCE_BYTES: u64 = 768;

/// The path of prototype `k`'s layer inside the package.
fn prototype_path(k: usize) -> String {
    format!("prototypes/P_{k}.usda")
}

/// A prototype's layer: stage metadata (the prototype as default prim) and
/// one `Xform` holding its mesh, unbound. Returns the layer and the memory
/// charged for it.
fn prototype_layer(k: usize, mesh: &NamedMesh, budget: &mut Budget) -> Result<(Vec<u8>, u64), ExportError> {
    let t = mesh.mesh.triangle_count() as u64;
    let bytes = super::USDZ.size.of(0, t).saturating_add(super::PRIM_BYTES);
    budget.reserve_memory(bytes)?;
    let mut out = String::new();
    let _ = writeln!(out, "#usda 1.0\n(\n    defaultPrim = \"P_{k}\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n\ndef Xform \"P_{k}\"\n{{");
    let group = Group { colour: mesh.mesh.colours.first().copied().unwrap_or([255; 4]), vertices: (0..mesh.mesh.positions.len() as u32).collect(), indices: mesh.mesh.indices.clone() };
    layer::mesh_prim(&mut out, "Mesh", mesh, &group, false, &mut layer::Pace::new(budget))?;
    layer::footer(&mut out);
    Ok((out.into_bytes(), bytes))
}

/// A leaf's world transform as USD's `matrix4d` (row vectors: the rows
/// are glam's columns, translation last).
fn matrix(out: &mut String, leaf: &PlacedLeaf) {
    let m = DMat4::from_scale_rotation_translation(glam::DVec3::splat(leaf.scale), leaf.rotation, leaf.translation);
    out.push_str("( ");
    for (r, col) in m.to_cols_array_2d().iter().enumerate() {
        out.push_str(if r == 0 { "(" } else { ", (" });
        for (c, v) in col.iter().enumerate() {
            if c > 0 {
                out.push_str(", ");
            }
            // As the glTF instanced writer places leaves: f32 values.
            layer::float(out, *v as f32);
        }
        out.push(')');
    }
    out.push_str(" )");
}

/// Writes `h` as a USDZ package of prototypes and instances (see the
/// module comment), with `meta`'s provenance; a leaf's prototype is its
/// (shape, colour).
pub(crate) fn write_usdz_hierarchy(h: &Hierarchy, detail: u32, meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let counts = h.leaf_counts();
    let mut index: HashMap<(u32, [u8; 4]), usize> = HashMap::new();
    let mut prototypes: Vec<NamedMesh> = Vec::new();
    let mut instances = 0u64;
    let mut reserved = 0u64;
    for (&(shape, colour), &n) in &counts {
        let Some(s) = h.shapes.get(shape as usize) else { continue };
        let p = s.prototype(detail);
        let mesh_size = mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3);
        budget.reserve_memory(mesh_size)?;
        reserved = reserved.saturating_add(mesh_size);
        index.insert((shape, colour), prototypes.len());
        let mesh = Mesh { colours: vec![colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        prototypes.push(NamedMesh { name: format!("P_{}", prototypes.len()), mesh });
        instances = instances.saturating_add(n);
    }
    let mut layers = Vec::with_capacity(prototypes.len());
    for (k, p) in prototypes.iter().enumerate() {
        let (bytes, charged) = prototype_layer(k, p, budget)?;
        reserved = reserved.saturating_add(charged);
        layers.push((prototype_path(k), bytes));
    }
    let mut colours: Vec<[u8; 4]> = Vec::new();
    for p in &prototypes {
        let c = p.mesh.colours.first().copied().unwrap_or([255; 4]);
        if !colours.contains(&c) {
            colours.push(c);
        }
    }
    let provenance = meta.provenance.as_ref().map_or(0, |p| p.params_json().len() as u64 + p.model_key.len() as u64);
    let text_bytes = super::USDZ.size.fixed.saturating_add(instances.saturating_mul(INSTANCE_BYTES)).saturating_add((colours.len() as u64).saturating_mul(super::MATERIAL_BYTES)).saturating_add(2 * provenance);
    // The default layer, then the package holding it and the prototypes.
    let layers_bytes: u64 = layers.iter().map(|(_, b)| b.len() as u64).sum();
    let bytes = text_bytes.saturating_mul(2).saturating_add(layers_bytes);
    budget.reserve_memory(bytes)?;
    let mut text = String::with_capacity(usize::try_from(text_bytes).unwrap_or(usize::MAX).min(1 << 30));
    layer::header(&mut text, meta);
    layer::materials(&mut text, &colours);
    let mut n = 0usize;
    let mut late = Ok(());
    h.walk_while(&mut |leaf| {
        let Some(&k) = index.get(&(leaf.shape, leaf.colour)) else { return true };
        let colour = prototypes.get(k).and_then(|p| p.mesh.colours.first().copied()).unwrap_or([255; 4]);
        let _ = write!(
            text,
            "\n    def Xform \"I_{n}\" (\n        instanceable = true\n        prepend apiSchemas = [\"MaterialBindingAPI\"]\n        prepend references = @{}@\n    )\n    {{\n        rel material:binding = </{}/Materials/{}>\n        matrix4d xformOp:transform = ",
            prototype_path(k),
            layer::ROOT,
            layer::material_name(colour)
        );
        matrix(&mut text, leaf);
        text.push_str("\n        uniform token[] xformOpOrder = [\"xformOp:transform\"]\n    }\n");
        n += 1;
        if n % DEADLINE_EVERY == 0 {
            late = budget.check_deadline();
        }
        late.is_ok()
    });
    late?;
    layer::footer(&mut text);
    drop(prototypes);
    budget.check_deadline()?;
    let out = package::package(text.as_bytes(), &layers, budget);
    budget.release_memory(reserved.saturating_add(bytes));
    out
}
