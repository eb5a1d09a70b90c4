//! Compact glTF 2.0 for phone clients: vertex welding, `KHR_mesh_quantization`
//! and `EXT_meshopt_compression`, in .glb or .gltf.
//!
//! The plain writer ([`super::gltf`]) is used when every option is off; this
//! module takes over as soon as one is on. Per mesh it
//! 1. checks the mesh (same rules as the plain writer);
//! 2. builds one record per vertex: float position, float normal and RGBA8
//!    colour (28 bytes), or with `quantize` an unsigned 16-bit position on a
//!    grid shared by all meshes, a normalised int8 normal and the colour
//!    (16 bytes, every attribute padded to 4 bytes as glTF requires);
//! 3. welds bitwise-identical records (meshoptimizer's vertex remap), drops
//!    triangles that reuse a vertex or (quantised) a grid position, orders the
//!    triangles for the post-transform vertex cache and the vertices by first
//!    use;
//! 4. writes one buffer view per attribute and one for the indices; with
//!    `compress=meshopt` each view is also encoded with meshoptimizer's
//!    vertex codec (version 0, mode `ATTRIBUTES`) or index codec (mode
//!    `TRIANGLES`) into buffer 0, while the views themselves point into a
//!    fallback buffer (buffer 1, no data, `"fallback": true`) that only
//!    gives the decoded layout; the extension is then required.
//!
//! The document is built by the one glTF builder (`document::Doc`),
//! as the plain writer's is: same asset, root node, material, camera and
//! scene `extras`; this module only lays out its buffers and views.
//!
//! Quantised positions are dequantised by the mesh node's `translation`
//! (the grid origin) and uniform `scale` (the grid step, the largest extent
//! over 65535), so the model's world coordinates are the plain export's
//! within half a grid step per axis. Normals are within 0.5/127 per
//! component, so under 0.5° off. Output is deterministic.

use super::buffer::{accessor, view};
use super::document::{Attributes, Doc};
use super::tree::{push, Bounds, Component, Ix, Kind, MeshoptView, Root, Target, EXT_MESHOPT, KHR_QUANT};
use crate::export::{ExportError, ExportMeta};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;

/// Compression of the glTF buffer.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Compression {
    /// No compression.
    #[default]
    None,
    /// `EXT_meshopt_compression` (meshoptimizer's vertex and index codecs).
    Meshopt,
}

rulemesh_core::choice!(Compression { None => "none", Meshopt => "meshopt" });

/// Compact glTF options (request options of the `glb` and `gltf` formats).
/// All off gives the plain export, byte for byte.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct GltfOptions {
    /// Weld identical vertices and drop duplicate/degenerate ones (implied by
    /// `quantize` and by compression).
    pub weld: bool,
    /// `KHR_mesh_quantization`: 16-bit positions, 8-bit normals.
    pub quantize: bool,
    /// Buffer compression.
    pub compress: Compression,
}

impl GltfOptions {
    /// Whether every option is off (the plain writer applies).
    pub(crate) fn is_plain(&self) -> bool {
        !self.weld && !self.quantize && self.compress == Compression::None
    }
}

/// Reads a compression name (`none` or `meshopt`), as the CLI and the routes spell it.
pub(crate) fn parse_compression(name: &str) -> Result<Compression, String> {
    match name.trim().to_ascii_lowercase().as_str() {
        "" | "none" => Ok(Compression::None),
        "meshopt" => Ok(Compression::Meshopt),
        other => Err(format!("unknown compression `{other}` (known: none, meshopt)")),
    }
}

const QUANT_MAX: f64 = 65535.0;

/// One attribute or index stream of one mesh, uncompressed.
struct Stream {
    bytes: Vec<u8>,
    /// Bytes per element (also the view's byteStride for attributes).
    stride: usize,
    count: usize,
    component: Component,
    type_: Kind,
    normalized: bool,
    /// POSITION bounds (glTF requires them on POSITION only).
    bounds: Option<Bounds>,
}

/// A mesh ready to be written: POSITION, NORMAL and COLOR_0, then the indices.
struct Prepared<'a> {
    name: &'a str,
    attributes: [Stream; 3],
    indices: Stream,
}

fn too_large(detail: impl Into<String>) -> ExportError {
    ExportError::TooLarge { format: "glTF", detail: detail.into() }
}


/// The quantisation grid over all meshes: origin and uniform step.
fn grid(meshes: &[NamedMesh]) -> ([f64; 3], f64) {
    let Some((lo, hi)) = crate::geom::normalize::bounds(meshes) else {
        return ([0.0; 3], 1.0);
    };
    // The origin and step are stored as f32 in the JSON; quantise against
    // those exact values so dequantisation reproduces the grid.
    let lo = lo.map(|c| f64::from(c as f32));
    let ext = (0..3).map(|a| hi[a] - lo[a]).fold(0.0f64, f64::max);
    let step = if ext > 0.0 { f64::from((ext / QUANT_MAX) as f32) } else { 1.0 };
    // Rounding the step to f32 may shrink it below ext/65535; widen by ulps until the grid covers.
    let mut step = step;
    while ext / step > QUANT_MAX {
        step = f64::from(f32::from_bits((step as f32).to_bits() + 1));
    }
    (lo, step)
}

fn snorm8(v: f32) -> u8 {
    (f64::from(v).clamp(-1.0, 1.0) * 127.0).round() as i8 as u8
}

/// Welds, drops degenerate triangles, optimises for the vertex cache and fetch.
/// `pos_len` is the number of leading bytes of a record that hold the position.
fn optimise<const N: usize>(records: &[[u8; N]], indices: &[u32], pos_len: usize) -> (Vec<[u8; N]>, Vec<u32>)
where
    [u8; N]: bytemuck::Pod,
{
    let (welded, indices) = crate::geom::strip::weld(records, indices);
    let list: Vec<u32> = indices
        .chunks_exact(3)
        .filter(|t| {
            let p = |k: usize| welded.get(t[k] as usize).map(|r| &r[..pos_len]);
            t[0] != t[1] && t[1] != t[2] && t[0] != t[2] && p(0) != p(1) && p(1) != p(2) && p(0) != p(2)
        })
        .flatten()
        .copied()
        .collect();
    if list.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let list = meshopt::optimize_vertex_cache(&list, welded.len());
    let (remap, used) = crate::geom::strip::first_use_remap(&list, welded.len());
    let mut out = vec![[0u8; N]; used];
    for (v, &r) in welded.iter().zip(&remap) {
        if let Some(slot) = out.get_mut(r as usize) {
            *slot = *v;
        }
    }
    let list = list.iter().map(|&i| remap.get(i as usize).copied().unwrap_or(0)).collect();
    (out, list)
}

/// Splits records into per-attribute byte streams at the given byte ranges.
fn column<const N: usize>(records: &[[u8; N]], from: usize, to: usize) -> Vec<u8> {
    records.iter().flat_map(|r| r[from..to].iter().copied()).collect()
}

fn int_bounds<const N: usize>(records: &[[u8; N]]) -> Bounds {
    let mut lo = [u16::MAX; 3];
    let mut hi = [0u16; 3];
    for r in records {
        for a in 0..3 {
            let q = u16::from_le_bytes([r[2 * a], r[2 * a + 1]]);
            lo[a] = lo[a].min(q);
            hi[a] = hi[a].max(q);
        }
    }
    Bounds::Grid(lo, hi)
}

fn float_bounds<const N: usize>(records: &[[u8; N]]) -> Bounds {
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for r in records {
        for a in 0..3 {
            let c = f32::from_le_bytes([r[4 * a], r[4 * a + 1], r[4 * a + 2], r[4 * a + 3]]);
            lo[a] = lo[a].min(c);
            hi[a] = hi[a].max(c);
        }
    }
    Bounds::Float(lo, hi)
}

fn attribute(bytes: Vec<u8>, stride: usize, count: usize, component: Component, type_: Kind, normalized: bool) -> Stream {
    Stream { bytes, stride, count, component, type_, normalized, bounds: None }
}

fn index_stream(list: &[u32], vertices: usize) -> Stream {
    let short = vertices <= 65535;
    let bytes: Vec<u8> = if short {
        // Fits: every index is below `vertices` ≤ 65535.
        list.iter().flat_map(|&i| (i as u16).to_le_bytes()).collect()
    } else {
        list.iter().flat_map(|&i| i.to_le_bytes()).collect()
    };
    Stream {
        bytes,
        stride: if short { 2 } else { 4 },
        count: list.len(),
        component: if short { Component::U16 } else { Component::U32 },
        type_: Kind::Scalar,
        normalized: false,
        bounds: None,
    }
}

fn prepare(m: &NamedMesh, quantize: Option<([f64; 3], f64)>) -> Result<Option<Prepared<'_>>, ExportError> {
    super::buffer::check_mesh(m)?;
    let mesh = &m.mesh;
    if mesh.indices.is_empty() {
        return Ok(None);
    }
    let (attributes, indices) = match quantize {
        Some((lo, step)) => {
            let records: Vec<[u8; 16]> = (0..mesh.positions.len())
                .map(|i| {
                    let mut r = [0u8; 16];
                    let p = mesh.positions[i];
                    for a in 0..3 {
                        let q = ((f64::from(p[a]) - lo[a]) / step).round().clamp(0.0, QUANT_MAX) as u16;
                        r[2 * a..2 * a + 2].copy_from_slice(&q.to_le_bytes());
                    }
                    let n = mesh.normals[i];
                    r[8..11].copy_from_slice(&n.map(snorm8));
                    r[12..16].copy_from_slice(&mesh.colours[i]);
                    r
                })
                .collect();
            let (v, list) = optimise(&records, &mesh.indices, 6);
            if list.is_empty() {
                return Ok(None);
            }
            let mut pos = attribute(column(&v, 0, 8), 8, v.len(), Component::U16, Kind::Vec3, false);
            pos.bounds = Some(int_bounds(&v));
            let nrm = attribute(column(&v, 8, 12), 4, v.len(), Component::I8, Kind::Vec3, true);
            let col = attribute(column(&v, 12, 16), 4, v.len(), Component::U8, Kind::Vec4, true);
            ([pos, nrm, col], index_stream(&list, v.len()))
        }
        None => {
            let records: Vec<[u8; 28]> = (0..mesh.positions.len())
                .map(|i| {
                    let mut r = [0u8; 28];
                    for a in 0..3 {
                        r[4 * a..4 * a + 4].copy_from_slice(&mesh.positions[i][a].to_le_bytes());
                        r[12 + 4 * a..16 + 4 * a].copy_from_slice(&mesh.normals[i][a].to_le_bytes());
                    }
                    r[24..28].copy_from_slice(&mesh.colours[i]);
                    r
                })
                .collect();
            let (v, list) = optimise(&records, &mesh.indices, 12);
            if list.is_empty() {
                return Ok(None);
            }
            let mut pos = attribute(column(&v, 0, 12), 12, v.len(), Component::F32, Kind::Vec3, false);
            pos.bounds = Some(float_bounds(&v));
            let nrm = attribute(column(&v, 12, 24), 12, v.len(), Component::F32, Kind::Vec3, false);
            let col = attribute(column(&v, 24, 28), 4, v.len(), Component::U8, Kind::Vec4, true);
            ([pos, nrm, col], index_stream(&list, v.len()))
        }
    };
    Ok(Some(Prepared { name: &m.name, attributes, indices }))
}

fn align4(v: &mut Vec<u8>) {
    while v.len() % 4 != 0 {
        v.push(0);
    }
}

/// Where buffer views go: the uncompressed layout (the real buffer, or the
/// meshopt fallback) and, with meshopt, the compressed bytes.
struct Layout {
    /// Uncompressed bytes (only kept without compression).
    raw: Vec<u8>,
    /// Length of the uncompressed layout.
    raw_len: usize,
    /// Compressed bytes (meshopt).
    packed: Vec<u8>,
    meshopt: bool,
}

/// Buffer 0 holds the data (raw, or meshopt-encoded); with meshopt, buffer 1
/// is the fallback whose layout the views describe. Both are added last,
/// when their lengths are known.
const DATA_BUFFER: u32 = 0;
const FALLBACK_BUFFER: u32 = 1;

impl Layout {
    /// Places a stream, adds its view to `doc` and returns the view.
    fn place(&mut self, doc: &mut Doc<'_>, s: &Stream, vertex: bool) -> Result<Ix, ExportError> {
        self.raw_len = self.raw_len.next_multiple_of(4);
        let offset = self.raw_len;
        self.raw_len += s.bytes.len();
        let buffer = if self.meshopt { FALLBACK_BUFFER } else { DATA_BUFFER };
        let mut v = view(buffer, offset as u64, s.bytes.len() as u64, Some(if vertex { Target::Vertices } else { Target::Indices }));
        if vertex {
            v.byte_stride = Some(s.stride as u64);
        }
        let meshopt = if self.meshopt {
            align4(&mut self.packed);
            let encoded = if vertex {
                encode_vertices(&s.bytes, s.stride)?
            } else {
                let list: Vec<u32> = if s.stride == 2 {
                    s.bytes.chunks_exact(2).map(|c| u32::from(u16::from_le_bytes([c[0], c[1]]))).collect()
                } else {
                    s.bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
                };
                let vertex_count = list.iter().max().map_or(0, |&m| m as usize + 1);
                meshopt::encode_index_buffer(&list, vertex_count).map_err(|e| too_large(format!("meshopt index codec: {e:?}")))?
            };
            let ext = MeshoptView {
                buffer: DATA_BUFFER,
                byte_offset: self.packed.len() as u64,
                byte_length: encoded.len() as u64,
                byte_stride: s.stride as u64,
                count: s.count as u64,
                mode: if vertex { "ATTRIBUTES" } else { "TRIANGLES" },
            };
            self.packed.extend_from_slice(&encoded);
            Some(ext)
        } else {
            self.raw.resize(offset, 0);
            self.raw.extend_from_slice(&s.bytes);
            None
        };
        if self.raw_len > u32::MAX as usize || self.packed.len() > u32::MAX as usize {
            return Err(too_large("buffer exceeds the 4 GiB limit"));
        }
        Ok(doc.view(v, meshopt))
    }

    /// Places a stream and adds its view and accessor to `doc`.
    fn accessor(&mut self, doc: &mut Doc<'_>, s: &Stream, vertex: bool) -> Result<Ix, ExportError> {
        let v = self.place(doc, s, vertex)?;
        let mut a = accessor(v, s.count, s.component, s.type_, s.normalized);
        a.bounds = s.bounds;
        Ok(push(&mut doc.root.accessors, a))
    }
}

/// meshoptimizer's vertex codec, version 0 (the one `EXT_meshopt_compression` specifies).
fn encode_vertices(bytes: &[u8], stride: usize) -> Result<Vec<u8>, ExportError> {
    let err = |e: meshopt::Error| too_large(format!("meshopt vertex codec: {e:?}"));
    match stride {
        4 => meshopt::encode_vertex_buffer_level(bytemuck::cast_slice::<u8, [u8; 4]>(bytes), 2, Some(0)).map_err(err),
        8 => meshopt::encode_vertex_buffer_level(bytemuck::cast_slice::<u8, [u8; 8]>(bytes), 2, Some(0)).map_err(err),
        12 => meshopt::encode_vertex_buffer_level(bytemuck::cast_slice::<u8, [u8; 12]>(bytes), 2, Some(0)).map_err(err),
        _ => Err(too_large(format!("unsupported vertex stride {stride}"))),
    }
}

/// The finished document and its binary buffer.
struct Built<'a> {
    /// The document.
    root: Root<'a>,
    /// Buffer 0's bytes (raw, or meshopt-encoded).
    bin: Vec<u8>,
}

/// Prepares every mesh and builds the document and the buffer 0 it describes.
fn build<'a>(meshes: &'a [NamedMesh], meta: &'a ExportMeta, opts: &GltfOptions) -> Result<Built<'a>, ExportError> {
    let grid = opts.quantize.then(|| grid(meshes));
    let meshopt = opts.compress == Compression::Meshopt;
    let mut prepared = Vec::new();
    for m in meshes {
        if let Some(p) = prepare(m, grid)? {
            prepared.push(p);
        }
    }
    let mut layout = Layout { raw: Vec::new(), raw_len: 0, packed: Vec::new(), meshopt };
    let mut doc = Doc::new();
    // The grid origin and step, as the node's dequantising transform.
    let placement = grid.map(|(lo, step)| (lo.map(|c| c as f32), step as f32));
    for p in &prepared {
        let [position, normal, colour] = &p.attributes;
        let attributes = Attributes {
            position: layout.accessor(&mut doc, position, true)?,
            normal: layout.accessor(&mut doc, normal, true)?,
            colour: layout.accessor(&mut doc, colour, true)?,
        };
        let indices = layout.accessor(&mut doc, &p.indices, false)?;
        doc.mesh(p.name, attributes, indices, meta, placement, None);
    }
    if !prepared.is_empty() {
        if meshopt {
            doc.require(EXT_MESHOPT);
        }
        if opts.quantize {
            doc.require(KHR_QUANT);
        }
        let data = doc.buffer(if meshopt { layout.packed.len() } else { layout.raw.len() } as u64, None);
        debug_assert_eq!(data, DATA_BUFFER);
        if meshopt {
            let fallback = doc.meshopt_fallback_buffer(layout.raw_len as u64);
            debug_assert_eq!(fallback, FALLBACK_BUFFER);
        }
    }
    let bin = if meshopt { layout.packed } else { layout.raw };
    Ok(Built { root: doc.finish(meta)?, bin })
}

/// Writes a compact binary glTF (.glb) as `opts` say. Reserves the output
/// size in `budget` before assembling it.
pub(crate) fn write_glb(meshes: &[NamedMesh], meta: &ExportMeta, opts: &GltfOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let built = build(meshes, meta, opts)?;
    // Building (welding, quantising, compressing) is the work; writing is a copy.
    budget.check_deadline()?;
    let json_bytes = super::json_out::root_json(&built.root)?;
    let json_len = json_bytes.len().next_multiple_of(4);
    let has_bin = !built.root.buffers.is_empty();
    let bin_len = built.bin.len().next_multiple_of(4);
    let total = 12 + 8 + json_len + if has_bin { 8 + bin_len } else { 0 };
    let total32 = u32::try_from(total).map_err(|_| too_large(format!("file of {total} bytes exceeds the 4 GiB limit")))?;
    budget.reserve_memory(total as u64)?;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&total32.to_le_bytes());
    // Both fit: each is below `total`.
    out.extend_from_slice(&(json_len as u32).to_le_bytes());
    out.extend_from_slice(&0x4E4F_534Au32.to_le_bytes());
    out.extend_from_slice(&json_bytes);
    out.resize(20 + json_len, b' ');
    if has_bin {
        out.extend_from_slice(&(bin_len as u32).to_le_bytes());
        out.extend_from_slice(&0x004E_4942u32.to_le_bytes());
        out.extend_from_slice(&built.bin);
        out.resize(total, 0);
    }
    Ok(out)
}

/// Writes a compact JSON glTF with buffer 0 embedded as a base64 data URI.
pub(crate) fn write_gltf(meshes: &[NamedMesh], meta: &ExportMeta, opts: &GltfOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let mut built = build(meshes, meta, opts)?;
    budget.check_deadline()?;
    if let Some(b0) = built.root.buffers.get_mut(DATA_BUFFER as usize) {
        let mut uri = super::buffer::DATA_URI.as_bytes().to_vec();
        uri.extend_from_slice(&super::buffer::base64(&built.bin));
        // Base64 text is ASCII.
        b0.uri = Some(String::from_utf8_lossy(&uri).into_owned());
    }
    let out = super::json_out::root_json(&built.root)?;
    budget.reserve_memory(out.len() as u64)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;
    use crate::export::gltf::tests::{all_nine, meshes_of};
    use crate::mesh::MeshLayout;
    use serde_json::Value;

    fn glb_json(b: &[u8]) -> Value {
        let jl = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
        serde_json::from_slice(&b[20..20 + jl]).expect("json chunk")
    }

    #[test]
    fn quantised_and_compressed_are_smaller_deterministic_and_declared() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::PerKind);
        let meta = ExportMeta::default();
        let plain = crate::export::gltf::write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).expect("plain");
        let mut last = plain.len();
        for opts in [
            GltfOptions { weld: true, ..Default::default() },
            GltfOptions { quantize: true, ..Default::default() },
            GltfOptions { quantize: true, compress: Compression::Meshopt, weld: false },
        ] {
            let a = write_glb(&meshes, &meta, &opts, &mut Budget::new(Limits::default())).expect("a");
            let b = write_glb(&meshes, &meta, &opts, &mut Budget::new(Limits::default())).expect("b");
            assert_eq!(a, b, "{opts:?}");
            // Welding meshes that share no identical vertices saves nothing
            // and the JSON is a little longer; the others must shrink.
            let slack = if opts.quantize { 0 } else { 1024 };
            assert!(a.len() < last + slack, "{opts:?}: {} !< {last}", a.len());
            last = a.len();
            let j = glb_json(&a);
            let used = j["extensionsUsed"].as_array().cloned().unwrap_or_default();
            assert_eq!(used.contains(&Value::from(KHR_QUANT)), opts.quantize);
            assert_eq!(used.contains(&Value::from(EXT_MESHOPT)), opts.compress == Compression::Meshopt);
            assert_eq!(j["extensionsRequired"], j["extensionsUsed"]);
        }
    }

    #[test]
    fn quantised_positions_dequantise_within_half_a_step() {
        let meshes = meshes_of(&all_nine(), 8, MeshLayout::Merged);
        let (lo, step) = grid(&meshes);
        let p = prepare(&meshes[0], Some((lo, step))).expect("ok").expect("mesh");
        let pos = &p.attributes[0].bytes;
        let q: Vec<[f64; 3]> = pos
            .chunks_exact(8)
            .map(|c| [0, 1, 2].map(|a| lo[a] + f64::from(u16::from_le_bytes([c[2 * a], c[2 * a + 1]])) * step))
            .collect();
        // Every original position is within half a step (plus f32 slack) of some dequantised one.
        for orig in &meshes[0].mesh.positions {
            let best = q.iter().map(|d| (0..3).map(|a| (d[a] - f64::from(orig[a])).abs()).fold(0.0, f64::max)).fold(f64::INFINITY, f64::min);
            assert!(best <= step * 0.5 + 1e-6, "{best} > {}", step * 0.5);
        }
    }

    #[test]
    fn compression_names() {
        assert_eq!(parse_compression("meshopt"), Ok(Compression::Meshopt));
        assert_eq!(parse_compression("none"), Ok(Compression::None));
        assert!(parse_compression("draco").is_err());
    }
}
