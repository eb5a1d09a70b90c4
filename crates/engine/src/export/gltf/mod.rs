//! glTF 2.0 export: binary (.glb) and JSON with an embedded data URI (.gltf).
//!
//! The JSON side is rulemesh's own small document (`tree`, which says why
//! it is not gltf-json's), written by `json_out`; the binary buffer is streamed
//! straight into the output vector (raw for GLB, base64 for .gltf), so the
//! only large allocation is the output itself, whose exact size is computed
//! and reserved in the [`Budget`] before it is allocated.
//!
//! Layout of the document:
//! * one buffer; per mesh four buffer views (POSITION, NORMAL, COLOR_0,
//!   indices), each starting at a 4-byte aligned offset;
//! * one mesh per [`NamedMesh`] with a single TRIANGLES primitive using the
//!   default material (white, metallic 0, roughness 0.8) so vertex colours show;
//! * one scene whose only root node, `"rulemesh"`, has no transform and one
//!   child node per mesh; background colour and truncation go in the scene's
//!   `extras`;
//! * with a [`NodeGraph`](crate::model::graph::NodeGraph) (animated grammars, cameras): one node per bone
//!   under the root, each mesh under its bone's node, a camera node, and one
//!   animation `"rulemesh"` with LINEAR translation/rotation/scale channels
//!   per animated node, sampled at the grammar's fps; the samples follow the
//!   meshes in the buffer, in one buffer view without a target.
//!
//! Output is deterministic: every map is ordered and nothing time-dependent
//! is written.
//!
//! This module holds the two formats' descriptors ([`GLB`], [`GLTF`]) and
//! the two container writers ([`write_glb`], [`write_gltf`]); the parts are
//! in the modules beside it: `buffer` (buffer layout, limits, sinks),
//! `tree` (the document's types), `document` (the one document builder:
//! meshes, materials, cameras, scene, extensions; also behind `compact`
//! and instancing), `json_out` (its JSON), `graph`
//! (bones, camera node, animation), `gpu_instancing` (the
//! `EXT_mesh_gpu_instancing` writer, [`InstancedSink`], a
//! [`GeometrySink`](crate::export::GeometrySink) the pipeline feeds a flat
//! scene's repeated meshes or a hierarchy), `instanced` (what an instance
//! costs) and `compact` (welded, quantised and meshopt output).

mod buffer;
pub mod compact;
mod document;
mod gpu_instancing;
mod graph;
mod json_out;
#[cfg(test)]
mod json_oracle;
mod instanced;
mod tree;

use super::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use super::{ExportError, ExportMeta, ExportOptions};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use buffer::{align4, animation_tracks, base64_len, find, invalid, place, write_buffer_until, Base64, CHUNK_BIN, CHUNK_JSON, DATA_URI, GLB_MAGIC, MAX_BYTES};
use document::document;

pub(crate) use gpu_instancing::InstanceLayout;

/// What both glTF containers carry: GPU instancing of repeated meshes and
/// hierarchies, and a node graph (bones, animation, a camera path).
const CAPS: Capabilities = Capabilities { instancing: true, node_graph: true, ..Capabilities::NONE };

/// `glb`: binary glTF 2.0.
pub const GLB: FormatInfo = FormatInfo {
    name: "glb",
    extensions: &["glb"],
    mime: "model/gltf-binary",
    caps: CAPS,
    options: OptionGroup::Gltf,
    size: SizeBound { fixed: 64 * 1024, per_vertex: 28, per_triangle: 12, per_instance: instanced::SCENE_INSTANCE_BYTES },
    writer: Writer::Sink { flat: write_glb_with, model: Some(gpu_instancing::glb_sink) },
};

/// `gltf`: glTF 2.0 JSON with the buffer as a data URI. base64 inflates
/// the buffer by 4/3; instanced, it is built raw and then encoded, so an
/// instance costs its raw and its base64 bytes.
pub(crate) const GLTF: FormatInfo = FormatInfo {
    name: "gltf",
    extensions: &["gltf"],
    mime: "model/gltf+json",
    caps: Capabilities { text: true, ..CAPS },
    options: OptionGroup::Gltf,
    size: SizeBound { fixed: 64 * 1024, per_vertex: 38, per_triangle: 16, per_instance: 3 * instanced::SCENE_INSTANCE_BYTES },
    writer: Writer::Sink { flat: write_gltf_with, model: Some(gpu_instancing::gltf_sink) },
};

/// `glb` with the request's options: the plain writer when every compact
/// option is off (byte for byte the plain export), else `compact`.
fn write_glb_with(meshes: &[NamedMesh], meta: &ExportMeta, options: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    match options.gltf.is_plain() {
        true => write_glb(meshes, meta, budget),
        false => compact::write_glb(meshes, meta, &options.gltf, budget),
    }
}

/// `gltf` with the request's options, as [`write_glb_with`].
fn write_gltf_with(meshes: &[NamedMesh], meta: &ExportMeta, options: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    match options.gltf.is_plain() {
        true => write_gltf(meshes, meta, budget),
        false => compact::write_gltf(meshes, meta, &options.gltf, budget),
    }
}

/// Writes a binary glTF (.glb): 12-byte header, JSON chunk padded with spaces,
/// BIN chunk padded with zeros (omitted when there is no geometry).
///
/// Reserves the exact output size in `budget` before allocating it; fails
/// with [`ExportError::TooLarge`] beyond the format's 4 GiB limit.
pub(crate) fn write_glb(meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let (placed, meshes_end) = place(meshes)?;
    budget.check_deadline()?;
    let tracks = animation_tracks(meta, meshes_end, budget)?;
    let buffer_len = tracks.buffer_len(meshes_end);
    let json_bytes = document(&placed, buffer_len, &tracks, meta, None)?;
    let json_len = align4(json_bytes.len() as u64);
    let bin_chunk = if buffer_len == 0 { 0 } else { 8 + align4(buffer_len) };
    let total = 12 + 8 + json_len + bin_chunk;
    if total > MAX_BYTES {
        return Err(ExportError::TooLarge { format: GLB.name, detail: format!("file of {total} bytes exceeds the 4 GiB limit") });
    }
    budget.reserve_memory(total)?;
    let mut out = Vec::with_capacity(total as usize);
    out.extend_from_slice(GLB_MAGIC);
    out.extend_from_slice(&2u32.to_le_bytes());
    // All three fit: total ≤ u32::MAX was checked above.
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json_len as u32).to_le_bytes());
    out.extend_from_slice(&CHUNK_JSON.to_le_bytes());
    out.extend_from_slice(&json_bytes);
    out.resize(20 + json_len as usize, b' ');
    if buffer_len > 0 {
        out.extend_from_slice(&(align4(buffer_len) as u32).to_le_bytes());
        out.extend_from_slice(&CHUNK_BIN.to_le_bytes());
        write_buffer_until(&mut out, &placed, &tracks, &|| budget.check_deadline())?;
        out.resize(total as usize, 0);
    }
    debug_assert_eq!(out.len() as u64, total);
    Ok(out)
}

/// Writes a JSON glTF with the buffer embedded as a base64 data URI
/// (`data:application/octet-stream;base64,…`), so the model is one file.
///
/// The JSON is serialised with an empty data URI and the base64 text is
/// streamed into the output at that point, so the buffer is never held twice.
/// Reserves the exact output size in `budget` before allocating it.
pub(crate) fn write_gltf(meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let (placed, meshes_end) = place(meshes)?;
    budget.check_deadline()?;
    let tracks = animation_tracks(meta, meshes_end, budget)?;
    let buffer_len = tracks.buffer_len(meshes_end);
    let json_bytes = document(&placed, buffer_len, &tracks, meta, (buffer_len > 0).then(|| DATA_URI.to_string()))?;
    // Compact JSON: `"uri":"` can only occur as a key (quotes inside strings are
    // escaped), and only the one buffer has a URI.
    let split = if buffer_len == 0 {
        json_bytes.len()
    } else {
        let needle = format!("\"uri\":\"{DATA_URI}\"");
        let at = find(&json_bytes, needle.as_bytes()).ok_or_else(|| invalid("model", "buffer URI not found in the serialised JSON"))?;
        at + needle.len() - 1
    };
    let encoded = if buffer_len == 0 { 0 } else { base64_len(buffer_len) };
    let total = (json_bytes.len() as u64).saturating_add(encoded);
    budget.reserve_memory(total)?;
    let mut out = Vec::with_capacity(total as usize);
    out.extend_from_slice(&json_bytes[..split]);
    if buffer_len > 0 {
        let mut b64 = Base64 { out: &mut out, carry: [0; 3], held: 0 };
        write_buffer_until(&mut b64, &placed, &tracks, &|| budget.check_deadline())?;
        b64.finish();
    }
    out.extend_from_slice(&json_bytes[split..]);
    debug_assert_eq!(out.len() as u64, total);
    Ok(out)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::export::gltf::buffer::BASE64_ALPHABET;
    use crate::core::budget::{Limit, Limits};
    use crate::model::scene::Scene;
    use crate::export::{estimated_size, Format};
    use crate::mesh::tests::{inst, scene};
    use crate::mesh::{build_meshes, MeshLayout};
    use crate::core::PrimitiveKind;

    pub(crate) fn meshes_of(s: &Scene, detail: u32, layout: MeshLayout) -> Vec<NamedMesh> {
        build_meshes(s, detail, layout, &mut Budget::new(Limits::default())).unwrap()
    }

    pub(crate) fn all_nine() -> Scene {
        scene(PrimitiveKind::ALL.iter().enumerate().map(|(k, &kind)| inst(kind, [k as f32 * 1.5, 0.0, 0.0], 1.0, k % 2 == 1)).collect())
    }

    fn u32_at(b: &[u8], at: usize) -> u32 {
        u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
    }

    /// Splits a GLB into (json, bin), checking the container structure.
    fn parse_glb(b: &[u8]) -> (serde_json::Value, Option<&[u8]>) {
        assert_eq!(&b[0..4], b"glTF");
        assert_eq!(u32_at(b, 4), 2);
        assert_eq!(u32_at(b, 8) as usize, b.len());
        let jl = u32_at(b, 12) as usize;
        assert_eq!(jl % 4, 0);
        assert_eq!(u32_at(b, 16), CHUNK_JSON);
        let json: serde_json::Value = serde_json::from_slice(&b[20..20 + jl]).unwrap();
        let rest = &b[20 + jl..];
        if rest.is_empty() {
            return (json, None);
        }
        let bl = u32_at(rest, 0) as usize;
        assert_eq!(bl % 4, 0);
        assert_eq!(u32_at(rest, 4), CHUNK_BIN);
        assert_eq!(rest.len(), 8 + bl);
        (json, Some(&rest[8..]))
    }

    fn total_counts(meshes: &[NamedMesh]) -> (u64, u64) {
        meshes.iter().fold((0, 0), |(v, t), m| (v + m.mesh.positions.len() as u64, t + m.mesh.triangle_count() as u64))
    }

    #[test]
    fn glb_structure_accessors_and_bounds() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::PerKind);
        let out = write_glb(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap();
        let (j, bin) = parse_glb(&out);
        let bin = bin.unwrap();
        assert_eq!(j["asset"]["version"], "2.0");
        assert_eq!(j["asset"]["generator"], format!("rulemesh {}", crate::ENGINE_VERSION));
        assert_eq!(j["scene"], 0);
        assert_eq!(j["scenes"][0]["nodes"], serde_json::json!([0]));
        assert!(j["scenes"][0].get("extras").is_none());
        let root = &j["nodes"][0];
        assert_eq!(root["name"], "rulemesh");
        assert!(root.get("matrix").is_none() && root.get("translation").is_none());
        assert_eq!(root["children"].as_array().unwrap().len(), 9);
        assert_eq!(j["meshes"].as_array().unwrap().len(), 9);
        assert!(j["buffers"][0]["byteLength"].as_u64().unwrap() as usize <= bin.len());
        for (k, m) in meshes.iter().enumerate() {
            let prim = &j["meshes"][k]["primitives"][0];
            assert_eq!(j["meshes"][k]["name"], m.name.as_str());
            let pos = &j["accessors"][prim["attributes"]["POSITION"].as_u64().unwrap() as usize];
            assert_eq!(pos["count"].as_u64().unwrap() as usize, m.mesh.positions.len());
            let idx = &j["accessors"][prim["indices"].as_u64().unwrap() as usize];
            assert_eq!(idx["count"].as_u64().unwrap() as usize, m.mesh.indices.len());
            assert_eq!(idx["componentType"], 5123); // UNSIGNED_SHORT
            let col = &j["accessors"][prim["attributes"]["COLOR_0"].as_u64().unwrap() as usize];
            assert_eq!((col["componentType"].as_u64(), col["normalized"].as_bool(), col["type"].as_str()), (Some(5121), Some(true), Some("VEC4")));
            for c in 0..3 {
                let lo = m.mesh.positions.iter().map(|p| p[c]).fold(f32::INFINITY, f32::min);
                let hi = m.mesh.positions.iter().map(|p| p[c]).fold(f32::NEG_INFINITY, f32::max);
                // serde_json's default float parser may be off by an f64 ulp; compare in f32.
                assert_eq!(pos["min"][c].as_f64().unwrap() as f32, lo);
                assert_eq!(pos["max"][c].as_f64().unwrap() as f32, hi);
            }
            // The POSITION bytes in the buffer are the mesh's positions.
            let view = &j["bufferViews"][pos["bufferView"].as_u64().unwrap() as usize];
            let off = view["byteOffset"].as_u64().unwrap() as usize;
            assert_eq!(off % 4, 0);
            let first = [0, 4, 8].map(|o| f32::from_le_bytes(bin[off + o..off + o + 4].try_into().unwrap()));
            assert_eq!(first, m.mesh.positions[0]);
        }
        for v in j["bufferViews"].as_array().unwrap() {
            assert_eq!(v["byteOffset"].as_u64().unwrap() % 4, 0);
            assert!(v["target"] == 34962 || v["target"] == 34963);
        }
        let (v, t) = total_counts(&meshes);
        assert!(out.len() as u64 <= estimated_size(Format::Glb, v, t));
    }

    #[test]
    fn wide_indices_above_65535_vertices() {
        let s = scene((0..3).map(|k| inst(PrimitiveKind::Sphere, [k as f32, 0.0, 0.0], 1.0, false)).collect());
        let meshes = meshes_of(&s, 256, MeshLayout::Merged);
        assert!(meshes[0].mesh.positions.len() > 65535);
        let out = write_glb(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap();
        let (j, _) = parse_glb(&out);
        assert_eq!(j["accessors"][3]["componentType"], 5125); // UNSIGNED_INT
        let (v, t) = total_counts(&meshes);
        assert!(out.len() as u64 <= estimated_size(Format::Glb, v, t));
    }

    #[test]
    fn empty_model_is_scene_and_root_only() {
        let out = write_glb(&[], &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap();
        let (j, bin) = parse_glb(&out);
        assert!(bin.is_none());
        assert!(j.get("buffers").is_none() && j.get("meshes").is_none() && j.get("materials").is_none());
        assert_eq!(j["nodes"].as_array().unwrap().len(), 1);
        assert!(out.len() as u64 <= estimated_size(Format::Glb, 0, 0));
        let out = write_gltf(&[], &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap();
        let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(j["nodes"][0]["name"], "rulemesh");
    }

    #[test]
    fn extras_record_background_and_truncation() {
        let meshes = meshes_of(&scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 1.0, false)]), 16, MeshLayout::Merged);
        let meta = ExportMeta { background: Some([0.25, 0.5, 1.0, 1.0]), truncated: true, graph: None, material_per_mesh: false, camera: None, provenance: None };
        let (j, _) = parse_glb(&write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap());
        assert_eq!(j["scenes"][0]["extras"], serde_json::json!({"background": [0.25, 0.5, 1.0, 1.0], "truncated": true}));
        let meta = ExportMeta { background: None, truncated: true, graph: None, material_per_mesh: false, camera: None, provenance: None };
        let (j, _) = parse_glb(&write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap());
        assert_eq!(j["scenes"][0]["extras"], serde_json::json!({"truncated": true}));
    }

    #[test]
    fn gltf_embeds_the_same_buffer_as_glb() {
        let meshes = meshes_of(&all_nine(), 7, MeshLayout::Merged);
        let meta = ExportMeta { background: Some([0.0, 0.0, 0.0, 1.0]), truncated: false, graph: None, material_per_mesh: false, camera: None, provenance: None };
        let glb = write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap();
        let gltf = write_gltf(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap();
        let (jb, bin) = parse_glb(&glb);
        let jt: serde_json::Value = serde_json::from_slice(&gltf).unwrap();
        let uri = jt["buffers"][0]["uri"].as_str().unwrap();
        let data = uri.strip_prefix(DATA_URI).unwrap();
        let len = jt["buffers"][0]["byteLength"].as_u64().unwrap() as usize;
        assert_eq!(data.len() as u64, base64_len(len as u64));
        assert_eq!(decode_base64(data), bin.unwrap()[..len]);
        // Apart from the URI the documents agree.
        let mut jt2 = jt.clone();
        jt2["buffers"][0].as_object_mut().unwrap().remove("uri");
        assert_eq!(jt2, jb);
        let (v, t) = total_counts(&meshes);
        assert!(gltf.len() as u64 <= estimated_size(Format::Gltf, v, t));
    }

    fn decode_base64(s: &str) -> Vec<u8> {
        let val = |c: u8| BASE64_ALPHABET.iter().position(|&a| a == c).map(|p| p as u32);
        let mut out = Vec::new();
        for chunk in s.as_bytes().chunks(4) {
            let pads = chunk.iter().filter(|&&c| c == b'=').count();
            let n = chunk.iter().fold(0u32, |acc, &c| (acc << 6) | val(c).unwrap_or(0));
            let bytes = [(n >> 16) as u8, (n >> 8) as u8, n as u8];
            out.extend_from_slice(&bytes[..3 - pads]);
        }
        out
    }

    #[test]
    fn deterministic_bytes() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::PerKind);
        let meta = ExportMeta { background: Some([0.1, 0.2, 0.3, 1.0]), truncated: true, graph: None, material_per_mesh: false, camera: None, provenance: None };
        let a = write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap();
        let b = write_glb(&meshes_of(&all_nine(), 16, MeshLayout::PerKind), &meta, &mut Budget::new(Limits::default())).unwrap();
        assert_eq!(a, b);
        let a = write_gltf(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap();
        let b = write_gltf(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap();
        assert_eq!(a, b);
    }

    #[test]
    fn budget_refusal() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::Merged);
        for f in [write_glb, write_gltf] {
            let mut b = Budget::new(Limits { max_memory: 1024, ..Limits::default() });
            match f(&meshes, &ExportMeta::default(), &mut b) {
                Err(ExportError::Limit(e)) => assert_eq!(e.limit, Limit::Memory),
                other => panic!("expected a memory limit, got {other:?}"),
            }
            assert_eq!(b.memory(), 0);
        }
        // The reservation is the exact output size.
        let mut b = Budget::new(Limits::default());
        let out = write_glb(&meshes, &ExportMeta::default(), &mut b).unwrap();
        assert_eq!(b.memory(), out.len() as u64);
    }

    #[test]
    fn a_passed_deadline_stops_the_write_and_lifting_it_lets_it_finish() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::Merged);
        for f in [write_glb, write_gltf] {
            let mut b = Budget::new(Limits { timeout_ms: 0, ..Limits::default() });
            match f(&meshes, &ExportMeta::default(), &mut b) {
                Err(ExportError::Limit(e)) => assert_eq!(e.limit, Limit::Deadline),
                other => panic!("expected the deadline, got {other:?}"),
            }
            b.lift_deadline();
            let out = f(&meshes, &ExportMeta::default(), &mut b).expect("no deadline left");
            assert_eq!(out, f(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap());
        }
    }

    #[test]
    fn the_buffer_write_gives_up_between_runs_when_asked() {
        // 70,000 boxes' worth of vertices: more than one run per stream.
        let s = scene((0..3000).map(|k| inst(PrimitiveKind::Box, [k as f32, 0.0, 0.0], 1.0, false)).collect());
        let meshes = meshes_of(&s, 16, MeshLayout::Merged);
        assert!(meshes[0].mesh.positions.len() > crate::geom::STOP_EVERY);
        let (placed, _) = place(&meshes).unwrap();
        let asked = std::cell::Cell::new(0);
        let mut out = Vec::new();
        let whole = write_buffer_until(&mut out, &placed, &Default::default(), &|| {
            asked.set(asked.get() + 1);
            if asked.get() == 2 { Err("stop") } else { Ok(()) }
        });
        assert_eq!(whole, Err("stop"));
        // The first run of positions only: 65,536 × 12 bytes.
        assert_eq!((asked.get(), out.len()), (2, crate::geom::STOP_EVERY * 12));
    }

    #[test]
    fn malformed_meshes_are_rejected() {
        let mut meshes = meshes_of(&scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 1.0, false)]), 16, MeshLayout::Merged);
        meshes[0].mesh.indices[0] = 1000;
        assert!(matches!(write_glb(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())), Err(ExportError::InvalidMesh { .. })));
        meshes[0].mesh.indices[0] = 0;
        meshes[0].mesh.positions[0][0] = f32::NAN;
        assert!(matches!(write_gltf(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())), Err(ExportError::InvalidMesh { .. })));
    }
}
