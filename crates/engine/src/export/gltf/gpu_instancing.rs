//! The GPU-instanced glTF writer: the plain document with each instanced
//! mesh's per-instance TRANSLATION (and ROTATION, SCALE and `_COLOR_0`
//! where its layout has them) appended to the buffer and
//! `EXT_mesh_gpu_instancing` on its node; meshes placed once stay plain in
//! the same document. Instances are streamed straight into the output, so
//! memory stays at the output size; this is the writer behind
//! `format=glb`/`gltf` of instancing L-systems and of every scene with a
//! repeated mesh (`super::instanced`).

use super::buffer::{
    accessor, align4, base64_len, find, invalid, place, view, write_buffer, Base64, Sink, Tracks, CHUNK_BIN, CHUNK_JSON, DATA_URI, GLB_MAGIC, MAX_BYTES,
};
use super::document::{plain, InstanceAccessors};
use crate::export::{ExportError, ExportMeta};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use gltf_json as json;
use json::accessor::{ComponentType, Type};

/// Which per-instance attributes an instanced mesh carries besides
/// TRANSLATION: ROTATION (unit quaternion), SCALE (per-axis, positive) and
/// `_COLOR_0` (float RGB, the attribute three.js's GLTFLoader reads into
/// `InstancedMesh.instanceColor`). An attribute left out is the identity for
/// every instance (the extension's default), so a mesh whose instances are
/// only moved carries 12 bytes per instance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct InstanceLayout {
    /// Write ROTATION.
    pub rotation: bool,
    /// Write SCALE.
    pub scale: bool,
    /// Write `_COLOR_0`.
    pub colour: bool,
}

impl InstanceLayout {
    /// Bytes one instance takes in the buffer.
    pub const fn bytes(self) -> u64 {
        12 + if self.rotation { 16 } else { 0 } + if self.scale { 12 } else { 0 } + if self.colour { 12 } else { 0 }
    }
}

/// One instance as written (rotation, scale and colour only where its mesh's layout has them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct InstanceData {
    /// Translation.
    pub translation: [f32; 3],
    /// Unit rotation (x, y, z, w).
    pub rotation: [f32; 4],
    /// Per-axis scale.
    pub scale: [f32; 3],
    /// Linear RGB.
    pub colour: [f32; 3],
}

/// Receives one instance: the index of its mesh and its data.
pub(crate) type InstanceSink<'s> = dyn FnMut(usize, &InstanceData) + 's;

/// Where one instanced mesh's per-instance data lives in the buffer.
#[derive(Debug, Clone, Copy)]
struct Region {
    translation: u64,
    rotation: u64,
    scale: u64,
    colour: u64,
}

/// Writes an instanced glTF (`glb`: binary, else JSON with an embedded
/// buffer): each of `meshes` with `counts[i] > 0` once, drawn `counts[i]`
/// times through `EXT_mesh_gpu_instancing` (listed in `extensionsUsed` and
/// `extensionsRequired`) with per-instance TRANSLATION (float VEC3) and, as
/// `layouts[i]` says, ROTATION (float VEC4), SCALE (float VEC3) and
/// `_COLOR_0` (float VEC3); the meshes with `counts[i] == 0` are plain.
///
/// The document is the plain one ([`write_glb`]'s layout) with the instance
/// data appended to the buffer. `feed` hands every instance to its sink, in
/// any order; each one is written straight into the output at its mesh's
/// next slot, so memory stays at the output size however many there are.
/// Fails with [`ExportError::InvalidMesh`] if `feed` gives other counts or
/// an instanced mesh has no triangles.
pub(crate) fn write_instanced(
    meshes: &[NamedMesh],
    counts: &[u64],
    layouts: &[InstanceLayout],
    meta: &ExportMeta,
    glb: bool,
    budget: &mut Budget,
    feed: &mut dyn FnMut(&mut InstanceSink<'_>),
) -> Result<Vec<u8>, ExportError> {
    let (placed, geometry_len) = place(meshes)?;
    let instanced = counts.iter().filter(|&&c| c > 0).count();
    if counts.len() != meshes.len() || layouts.len() != meshes.len() || instanced == 0 || placed.iter().filter(|(_, p)| counts[p.mesh] > 0).count() != instanced {
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
    let (mut doc, nodes, Some(buffer)) = plain(&placed, end, &Tracks::default(), meta, uri) else {
        return Err(invalid("model", "an instanced model needs a buffer"));
    };
    for ((_, p), &node) in placed.iter().zip(&nodes) {
        let (c, layout, Some(region)) = (counts[p.mesh], layouts[p.mesh], regions[p.mesh]) else { continue };
        // Views, then accessors, in attribute order (an L-system's documents
        // keep the bytes they had before SCALE and colour existed).
        let attributes: Vec<(u64, u64)> = [
            Some((region.translation, 12)),
            layout.rotation.then_some((region.rotation, 16)),
            layout.scale.then_some((region.scale, 12)),
            layout.colour.then_some((region.colour, 12)),
        ]
                .into_iter()
                .flatten()
                .collect();
        let views: Vec<_> = attributes.iter().map(|&(at, size)| doc.root.push(view(buffer, at, size * c, None))).collect();
        let mut accessors = views.iter().zip(&attributes).map(|(&v, &(_, size))| {
            let kind = if size == 16 { Type::Vec4 } else { Type::Vec3 };
            doc.root.push(accessor(v, c as usize, ComponentType::F32, kind, false))
        }).collect::<Vec<_>>().into_iter();
        let Some(translation) = accessors.next() else {
            return Err(invalid("model", "instance accessors missing"));
        };
        let rotation = if layout.rotation { accessors.next() } else { None };
        let scale = if layout.scale { accessors.next() } else { None };
        let colour = if layout.colour { accessors.next() } else { None };
        doc.instance(node, InstanceAccessors { translation, rotation, scale, colour })?;
    }
    let json_bytes = doc.finish(meta)?.to_vec()?;
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
    let mut written = vec![0u64; counts.len()];
    let mut overflow = false;
    {
        let bin = &mut out[bin_at..];
        let mut put = |at: u64, values: &[f32]| {
            for (k, v) in values.iter().enumerate() {
                let i = at as usize + 4 * k;
                bin[i..i + 4].copy_from_slice(&v.to_le_bytes());
            }
        };
        feed(&mut |mesh, d| {
            let (Some(n), Some(&c), Some(layout), Some(Some(r))) = (written.get_mut(mesh), counts.get(mesh), layouts.get(mesh), regions.get(mesh)) else {
                overflow = true;
                return;
            };
            if *n >= c {
                overflow = true;
                return;
            }
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
        });
    }
    if overflow || written != counts {
        return Err(invalid("model", "instances fed do not match the declared counts"));
    }
    if glb {
        debug_assert_eq!(out.len() as u64, total);
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
