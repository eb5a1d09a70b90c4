//! The GPU-instanced glTF writer: the plain document with each instanced
//! mesh's per-instance TRANSLATION (and ROTATION, SCALE and `_COLOR_0`
//! where its layout has them) appended to the buffer and
//! `EXT_mesh_gpu_instancing` on its node; meshes placed once stay plain in
//! the same document. Instances are streamed straight into the output, so
//! memory stays at the output size; this is the [`GeometrySink`] behind
//! `format=glb`/`gltf` of instancing hierarchies and of every scene with a
//! repeated mesh (fed by the pipeline's drivers, `pipeline::feed`).

use super::buffer::{
    accessor, align4, base64_len, find, invalid, place, view, write_buffer, Base64, Sink, Tracks, CHUNK_BIN, CHUNK_JSON, DATA_URI, GLB_MAGIC, MAX_BYTES,
};
use super::document::plain;
use super::tree::{push, Component, Instancing, Kind};
use crate::export::sink::{Drawn, GeometrySink, MeshId};
use crate::export::{ExportError, ExportMeta, ExportOptions};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;

pub(crate) use crate::export::sink::{InstanceData, InstanceLayout};

/// Where one instanced mesh's per-instance data lives in the buffer.
#[derive(Debug, Clone, Copy)]
struct Region {
    translation: u64,
    rotation: u64,
    scale: u64,
    colour: u64,
}

/// The instanced glTF writer as a [`GeometrySink`] (`glb`: binary, else
/// JSON with an embedded buffer): each mesh given as
/// [`Drawn::Instanced`] is written once and drawn by its placements
/// through `EXT_mesh_gpu_instancing` (listed in `extensionsUsed` and
/// `extensionsRequired`) with per-instance TRANSLATION (float VEC3) and,
/// as its layout says, ROTATION (float VEC4), SCALE (float VEC3) and
/// `_COLOR_0` (float VEC3); meshes given as [`Drawn::Plain`] stay plain.
///
/// The document is the plain one ([`write_glb`](super::write_glb)'s
/// layout) with the instance data appended to the buffer. Its layout needs
/// every mesh and count, so the output is laid out, charged and allocated
/// at the first placement (or at the end); each placement is then written
/// straight into the output at its mesh's next slot, so memory stays at
/// the output size however many there are. A placement beyond its mesh's
/// count, or fewer placements than declared, fails with
/// [`ExportError::InvalidMesh`], as does an instanced mesh with no
/// triangles or a model with meshes and no instanced one. Given no mesh
/// at all (an axiom of symbols no turtle command draws), it writes the
/// empty model as the flat writers write one: the instanced document needs
/// a buffer to point its instances into (fuzz finding).
pub(crate) struct InstancedSink {
    glb: bool,
    meta: ExportMeta,
    meshes: Vec<NamedMesh>,
    counts: Vec<u64>,
    layouts: Vec<InstanceLayout>,
    open: Option<Open>,
}

/// The output being written once laid out: the buffer (the whole `.glb`, or
/// the raw buffer of a `.gltf`), where the buffer starts in it, the JSON,
/// the buffer's length, each instanced mesh's region and placements written.
struct Open {
    out: Vec<u8>,
    bin_at: usize,
    json_bytes: Vec<u8>,
    end: u64,
    regions: Vec<Option<Region>>,
    written: Vec<u64>,
}

impl InstancedSink {
    /// An empty sink writing `.glb` when `glb`, else `.gltf`.
    pub(crate) fn new(glb: bool) -> InstancedSink {
        InstancedSink { glb, meta: ExportMeta::default(), meshes: Vec::new(), counts: Vec::new(), layouts: Vec::new(), open: None }
    }

    /// Lays out, charges and allocates the output.
    fn open(&mut self, budget: &mut Budget) -> Result<Open, ExportError> {
        let (meshes, counts, layouts, meta, glb) = (&self.meshes, &self.counts, &self.layouts, &self.meta, self.glb);
        let (placed, geometry_len) = place(meshes)?;
        let instanced = counts.iter().filter(|&&c| c > 0).count();
        if instanced == 0 || placed.iter().filter(|(_, p)| counts[p.mesh] > 0).count() != instanced {
            return Err(invalid("model", "every instanced mesh needs triangles, and at least one mesh instances"));
        }
        // Instance regions after the geometry: per instanced mesh, translations,
        // then rotations, scales and colours when written.
        let mut regions = vec![None; counts.len()];
        let mut end = align4(geometry_len);
        for ((slot, &c), layout) in regions.iter_mut().zip(counts).zip(layouts) {
            if c == 0 {
                continue;
            }
            let mut next = |bytes: u64| {
                let at = end;
                end = end.saturating_add(c.saturating_mul(bytes));
                at
            };
            let translation = next(12);
            let rotation = if layout.rotation { next(16) } else { 0 };
            let scale = if layout.scale { next(12) } else { 0 };
            let colour = if layout.colour { next(12) } else { 0 };
            *slot = Some(Region { translation, rotation, scale, colour });
        }
        if end > MAX_BYTES {
            return Err(ExportError::TooLarge { format: "glTF", detail: format!("buffer of {end} bytes exceeds the 4 GiB limit") });
        }
        let uri = (!glb).then(|| DATA_URI.to_string());
        // Up to four instance attributes per mesh, each a view and an accessor.
        let (mut doc, nodes, Some(buffer)) = plain(&placed, end, &Tracks::default(), meta, uri, 4) else {
            return Err(invalid("model", "an instanced model needs a buffer"));
        };
        for ((_, p), &node) in placed.iter().zip(&nodes) {
            let (c, layout, Some(region)) = (counts[p.mesh], layouts[p.mesh], regions[p.mesh]) else { continue };
            // Views, then accessors, in attribute order (an L-system's documents
            // keep the bytes they had before SCALE and colour existed).
            let attributes = [
                Some((region.translation, 12)),
                layout.rotation.then_some((region.rotation, 16)),
                layout.scale.then_some((region.scale, 12)),
                layout.colour.then_some((region.colour, 12)),
            ];
            let views = attributes.map(|a| a.map(|(at, size)| (push(&mut doc.root.views, view(buffer, at, size * c, None)), size)));
            let accessors = views.map(|v| {
                v.map(|(v, size)| {
                    let kind = if size == 16 { Kind::Vec4 } else { Kind::Vec3 };
                    push(&mut doc.root.accessors, accessor(v, c as usize, Component::F32, kind, false))
                })
            });
            let [Some(translation), rotation, scale, colour] = accessors else {
                return Err(invalid("model", "instance accessors missing"));
            };
            doc.instance(node, Instancing { translation, rotation, scale, colour })?;
        }
        let json_bytes = super::json_out::root_json(&doc.finish(meta)?)?;
        let bin_len = end as usize;
        let (total, bin_at) = if glb {
            let json_len = align4(json_bytes.len() as u64);
            (12 + 8 + json_len + 8 + end, (12 + 8 + json_len + 8) as usize)
        } else {
            ((json_bytes.len() as u64).saturating_add(base64_len(end)).saturating_add(end), 0)
        };
        if glb && total > MAX_BYTES {
            return Err(ExportError::TooLarge { format: super::GLB.name, detail: format!("file of {total} bytes exceeds the 4 GiB limit") });
        }
        budget.reserve_memory(total)?;
        let mut out = Vec::with_capacity(if glb { total as usize } else { bin_len });
        if glb {
            out.extend_from_slice(GLB_MAGIC);
            out.extend_from_slice(&2u32.to_le_bytes());
            // All fit: total ≤ u32::MAX was checked above.
            out.extend_from_slice(&(total as u32).to_le_bytes());
            let json_len = align4(json_bytes.len() as u64);
            out.extend_from_slice(&(json_len as u32).to_le_bytes());
            out.extend_from_slice(&CHUNK_JSON.to_le_bytes());
            out.extend_from_slice(&json_bytes);
            out.resize(20 + json_len as usize, b' ');
            out.extend_from_slice(&(end as u32).to_le_bytes());
            out.extend_from_slice(&CHUNK_BIN.to_le_bytes());
        }
        write_buffer(&mut out, &placed, &Tracks::default());
        out.resize(bin_at + bin_len, 0);
        Ok(Open { out, bin_at, json_bytes, end, written: vec![0u64; counts.len()], regions })
    }
}

/// The sink of the `glb` descriptor's instanced route.
pub(crate) fn glb_sink(_: &ExportOptions) -> Box<dyn GeometrySink> {
    Box::new(InstancedSink::new(true))
}

/// The sink of the `gltf` descriptor's instanced route.
pub(crate) fn gltf_sink(_: &ExportOptions) -> Box<dyn GeometrySink> {
    Box::new(InstancedSink::new(false))
}

impl GeometrySink for InstancedSink {
    fn format(&self) -> &'static str {
        if self.glb {
            super::GLB.name
        } else {
            super::GLTF.name
        }
    }

    /// Keeps the model's metadata (background, truncation, provenance) for
    /// the document; the output is laid out once every mesh is known.
    fn begin(&mut self, meta: &ExportMeta, _budget: &mut Budget) -> Result<(), ExportError> {
        self.meta = meta.clone();
        Ok(())
    }

    fn mesh(&mut self, mesh: NamedMesh, drawn: Drawn, _budget: &mut Budget) -> Result<MeshId, ExportError> {
        if self.open.is_some() {
            return Err(invalid(&mesh.name, "a mesh given after the first placement"));
        }
        let (count, layout) = match drawn {
            Drawn::Plain => (0, InstanceLayout::default()),
            Drawn::Instanced { count, layout } => (count, layout),
        };
        self.meshes.push(mesh);
        self.counts.push(count);
        self.layouts.push(layout);
        Ok(MeshId(self.meshes.len() - 1))
    }

    fn place(&mut self, MeshId(mesh): MeshId, d: &InstanceData, budget: &mut Budget) -> Result<(), ExportError> {
        if self.open.is_none() {
            self.open = Some(self.open(budget)?);
        }
        let Some(o) = self.open.as_mut() else { return Err(invalid("model", "the output is not open")) };
        let (Some(n), Some(&c), Some(layout), Some(Some(r))) = (o.written.get_mut(mesh), self.counts.get(mesh), self.layouts.get(mesh), o.regions.get(mesh)) else {
            return Err(invalid("model", "instances fed do not match the declared counts"));
        };
        if *n >= c {
            return Err(invalid("model", "instances fed do not match the declared counts"));
        }
        let bin = &mut o.out[o.bin_at..];
        let mut put = |at: u64, values: &[f32]| {
            for (k, v) in values.iter().enumerate() {
                let i = at as usize + 4 * k;
                bin[i..i + 4].copy_from_slice(&v.to_le_bytes());
            }
        };
        put(r.translation + 12 * *n, &d.translation);
        if layout.rotation {
            put(r.rotation + 16 * *n, &d.rotation);
        }
        if layout.scale {
            put(r.scale + 12 * *n, &d.scale);
        }
        if layout.colour {
            put(r.colour + 12 * *n, &d.colour);
        }
        *n += 1;
        Ok(())
    }

    fn end(mut self: Box<Self>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
        if self.meshes.is_empty() {
            return if self.glb { super::write_glb(&[], &self.meta, budget) } else { super::write_gltf(&[], &self.meta, budget) };
        }
        let o = match self.open.take() {
            Some(o) => o,
            None => self.open(budget)?,
        };
        let Open { out, json_bytes, end, written, .. } = o;
        if written != self.counts {
            return Err(invalid("model", "instances fed do not match the declared counts"));
        }
        if self.glb {
            return Ok(out);
        }
        // JSON: splice the base64 of the buffer into the data URI.
        let needle = format!("\"uri\":\"{DATA_URI}\"");
        let at = find(&json_bytes, needle.as_bytes()).ok_or_else(|| invalid("model", "buffer URI not found in the serialised JSON"))?;
        let split = at + needle.len() - 1;
        let mut text = Vec::with_capacity(json_bytes.len() + base64_len(end) as usize);
        text.extend_from_slice(&json_bytes[..split]);
        let mut b64 = Base64 { out: &mut text, carry: [0; 3], held: 0 };
        b64.put(&out);
        b64.finish();
        text.extend_from_slice(&json_bytes[split..]);
        drop(out);
        budget.release_memory(end);
        Ok(text)
    }
}
