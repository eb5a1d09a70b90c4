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
//!
//! The writer is a [`GeometrySink`] ([`HierarchySink`]): the pipeline's
//! driver (`pipeline::feed::hierarchy`) walks the hierarchy, tessellates
//! each (leaf shape, colour) once and gives it as a mesh, then places it
//! per leaf, as it feeds instanced glTF; nothing here walks or tessellates.

use super::layer::{self, Group};
use super::package;
use crate::core::budget::Budget;
use crate::export::sink::not_begun;
use crate::export::{Drawn, ExportError, ExportMeta, ExportOptions, GeometrySink, InstanceData, MeshId, DEADLINE_EVERY};
use crate::geom::NamedMesh;
use glam::DMat4;
use std::fmt::Write as _;

/// Bytes of the default layer one placement takes at most: the prim
/// (about 280 bytes with its name, binding and reference), and a 4×4
/// matrix of numbers of at most 16 characters with their separators
/// (about 330), and the op order (about 60).
pub(crate) const INSTANCE_BYTES: u64 = 768;

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

/// A placement's world transform as USD's `matrix4d` (row vectors: the
/// rows are glam's columns, translation last), made in f64 from the
/// placement as the model holds it ([`InstanceData::exact`]).
fn matrix(out: &mut String, at: &InstanceData) {
    let m = DMat4::from_scale_rotation_translation(at.exact.scale, at.exact.rotation, at.exact.translation);
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

/// The default layer being written, from the first placement on.
struct Placing {
    /// The layer's text so far.
    text: String,
    /// The prototypes' layers, by path.
    layers: Vec<(String, Vec<u8>)>,
    /// Placements written.
    placed: usize,
}

/// USDZ's hierarchy sink (the descriptor's `Writer::Instancing`): takes
/// each prototype as a [`Drawn::Instanced`] mesh of one colour, then its
/// placements, and writes the package of prototypes and instances the
/// module comment describes, with `meta`'s provenance.
pub(crate) struct HierarchySink {
    meta: Option<ExportMeta>,
    /// The prototypes, named `P_k` in the order given.
    prototypes: Vec<NamedMesh>,
    /// Placements announced by the meshes' [`Drawn::Instanced`] counts.
    instances: u64,
    /// Memory this sink reserved (layers, text and package).
    reserved: u64,
    placing: Option<Placing>,
}

/// Makes USDZ's hierarchy sink (it reads no format options).
pub(crate) fn hierarchy_sink(_: &ExportOptions) -> Box<dyn GeometrySink> {
    Box::new(HierarchySink { meta: None, prototypes: Vec::new(), instances: 0, reserved: 0, placing: None })
}

impl HierarchySink {
    /// Writes the prototypes' layers and the default layer's header and
    /// materials, reserving the whole package first (once, before the
    /// first placement or at the end).
    fn start(&mut self, budget: &mut Budget) -> Result<&mut Placing, ExportError> {
        if self.placing.is_none() {
            let meta = self.meta.as_ref().ok_or_else(|| not_begun(super::USDZ.name))?;
            let mut layers = Vec::with_capacity(self.prototypes.len());
            for (k, p) in self.prototypes.iter().enumerate() {
                let (bytes, charged) = prototype_layer(k, p, budget)?;
                self.reserved = self.reserved.saturating_add(charged);
                layers.push((prototype_path(k), bytes));
            }
            let mut colours: Vec<[u8; 4]> = Vec::new();
            for p in &self.prototypes {
                let c = p.mesh.colours.first().copied().unwrap_or([255; 4]);
                if !colours.contains(&c) {
                    colours.push(c);
                }
            }
            let provenance = meta.provenance.as_ref().map_or(0, |p| p.params_json().len() as u64 + p.model_key.len() as u64);
            let text_bytes = super::USDZ.size.fixed.saturating_add(self.instances.saturating_mul(INSTANCE_BYTES)).saturating_add((colours.len() as u64).saturating_mul(super::MATERIAL_BYTES)).saturating_add(2 * provenance);
            // The default layer, then the package holding it and the prototypes.
            let layers_bytes: u64 = layers.iter().map(|(_, b)| b.len() as u64).sum();
            let bytes = text_bytes.saturating_mul(2).saturating_add(layers_bytes);
            budget.reserve_memory(bytes)?;
            self.reserved = self.reserved.saturating_add(bytes);
            let mut text = String::with_capacity(usize::try_from(text_bytes).unwrap_or(usize::MAX).min(1 << 30));
            layer::header(&mut text, meta);
            layer::materials(&mut text, &colours);
            self.placing = Some(Placing { text, layers, placed: 0 });
        }
        self.placing.as_mut().ok_or_else(|| not_begun(super::USDZ.name))
    }
}

impl GeometrySink for HierarchySink {
    fn format(&self) -> &'static str {
        super::USDZ.name
    }

    fn begin(&mut self, meta: &ExportMeta, _budget: &mut Budget) -> Result<(), ExportError> {
        self.meta = Some(meta.clone());
        Ok(())
    }

    fn mesh(&mut self, mut mesh: NamedMesh, drawn: Drawn, _budget: &mut Budget) -> Result<MeshId, ExportError> {
        let Drawn::Instanced { count, .. } = drawn else {
            return Err(ExportError::InvalidOptions { format: super::USDZ.name, detail: "a hierarchy's prototypes are placed, never drawn plain".into() });
        };
        if self.meta.is_none() || self.placing.is_some() {
            return Err(not_begun(super::USDZ.name));
        }
        mesh.name = format!("P_{}", self.prototypes.len());
        self.prototypes.push(mesh);
        self.instances = self.instances.saturating_add(count);
        Ok(MeshId(self.prototypes.len() - 1))
    }

    fn place(&mut self, mesh: MeshId, at: &InstanceData, budget: &mut Budget) -> Result<(), ExportError> {
        let colour = self.prototypes.get(mesh.0).ok_or_else(|| not_begun(super::USDZ.name))?.mesh.colours.first().copied().unwrap_or([255; 4]);
        let placing = self.start(budget)?;
        let n = placing.placed;
        let _ = write!(
            placing.text,
            "\n    def Xform \"I_{n}\" (\n        instanceable = true\n        prepend apiSchemas = [\"MaterialBindingAPI\"]\n        prepend references = @{}@\n    )\n    {{\n        rel material:binding = </{}/Materials/{}>\n        matrix4d xformOp:transform = ",
            prototype_path(mesh.0),
            layer::ROOT,
            layer::material_name(colour)
        );
        matrix(&mut placing.text, at);
        placing.text.push_str("\n        uniform token[] xformOpOrder = [\"xformOp:transform\"]\n    }\n");
        placing.placed += 1;
        if placing.placed % DEADLINE_EVERY == 0 {
            budget.check_deadline()?;
        }
        Ok(())
    }

    fn end(mut self: Box<Self>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
        self.start(budget)?;
        let Some(Placing { mut text, layers, .. }) = self.placing.take() else { return Err(not_begun(super::USDZ.name)) };
        layer::footer(&mut text);
        self.prototypes = Vec::new();
        budget.check_deadline()?;
        let out = package::package(text.as_bytes(), &layers, budget);
        budget.release_memory(self.reserved);
        out
    }
}
