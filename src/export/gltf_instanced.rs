//! The GPU-instanced glTF writer: the plain document with each mesh's
//! per-instance TRANSLATION and ROTATION data appended to the buffer and
//! `EXT_mesh_gpu_instancing` on its node. Instances are streamed straight
//! into the output, so memory stays at the output size; this is the writer
//! behind `format=glb`/`gltf` of instancing L-systems (`super::instanced`).

use super::gltf_buffer::{
    accessor, align4, base64_len, find, invalid, place, view, write_buffer, Base64, Sink, Tracks, CHUNK_BIN, CHUNK_JSON, DATA_URI, GLB_MAGIC, MAX_BYTES,
};
use super::gltf_document::plain;
pub use super::gltf_document::EXT_INSTANCING;
use super::{ExportError, ExportMeta};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use gltf_json as json;
use json::accessor::{ComponentType, Type};

/// Receives one instance: the index of its mesh, its translation and its unit rotation (x, y, z, w).
pub type InstanceSink<'s> = dyn FnMut(usize, [f32; 3], [f32; 4]) + 's;

/// Writes an instanced glTF (`glb`: binary, else JSON with an embedded
/// buffer): each of `meshes` once, drawn `counts[i]` times through
/// `EXT_mesh_gpu_instancing` (listed in `extensionsUsed` and
/// `extensionsRequired`) with per-instance TRANSLATION (float VEC3) and
/// ROTATION (float VEC4) accessors. Instances are rigid, so there is no SCALE.
///
/// The document is the plain one ([`write_glb`]'s layout) with the instance
/// data appended to the buffer. `feed` hands every instance to its sink, in
/// any order; each one is written straight into the output at its mesh's
/// next slot, so memory stays at the output size however many there are.
/// Fails with [`ExportError::InvalidMesh`] if `feed` gives other counts.
pub fn write_instanced(
    meshes: &[NamedMesh],
    counts: &[u64],
    meta: &ExportMeta,
    glb: bool,
    budget: &mut Budget,
    feed: &mut dyn FnMut(&mut InstanceSink<'_>),
) -> Result<Vec<u8>, ExportError> {
    let (placed, geometry_len) = place(meshes)?;
    if placed.len() != meshes.len() || counts.len() != meshes.len() || counts.iter().any(|&c| c == 0) {
        return Err(invalid("model", "every instanced mesh needs triangles and at least one instance"));
    }
    // Instance regions: translations then rotations per mesh, after the geometry.
    let mut regions = Vec::with_capacity(counts.len());
    let mut end = align4(geometry_len);
    for &c in counts {
        let t = end;
        let r = t.saturating_add(c.saturating_mul(12));
        end = r.saturating_add(c.saturating_mul(16));
        regions.push((t, r));
    }
    if end > MAX_BYTES {
        return Err(ExportError::TooLarge { format: "glTF", detail: format!("buffer of {end} bytes exceeds the 4 GiB limit") });
    }
    let uri = (!glb).then(|| DATA_URI.to_string());
    let (mut doc, nodes, Some(buffer)) = plain(&placed, end, &Tracks::default(), meta, uri) else {
        return Err(invalid("model", "an instanced model needs a buffer"));
    };
    for ((&c, &(t, r)), &node) in counts.iter().zip(&regions).zip(&nodes) {
        let tv = doc.root.push(view(buffer, t, 12 * c, None));
        let rv = doc.root.push(view(buffer, r, 16 * c, None));
        let ta = doc.root.push(accessor(tv, c as usize, ComponentType::F32, Type::Vec3, false));
        let ra = doc.root.push(accessor(rv, c as usize, ComponentType::F32, Type::Vec4, false));
        doc.instance(node, ta, ra)?;
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
        return Err(ExportError::TooLarge { format: "GLB", detail: format!("file of {total} bytes exceeds the 4 GiB limit") });
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
        feed(&mut |mesh, t, r| {
            let (Some(n), Some(&c), Some(&(to, ro))) = (written.get_mut(mesh), counts.get(mesh), regions.get(mesh)) else {
                overflow = true;
                return;
            };
            if *n >= c {
                overflow = true;
                return;
            }
            let (ta, ra) = ((to + 12 * *n) as usize, (ro + 16 * *n) as usize);
            for (k, v) in t.iter().enumerate() {
                bin[ta + 4 * k..ta + 4 * k + 4].copy_from_slice(&v.to_le_bytes());
            }
            for (k, v) in r.iter().enumerate() {
                bin[ra + 4 * k..ra + 4 * k + 4].copy_from_slice(&v.to_le_bytes());
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
