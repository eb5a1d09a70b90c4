//! glTF 2.0 export: binary (.glb) and JSON with an embedded data URI (.gltf).
//!
//! The JSON side is built with `gltf-json`; the binary buffer is streamed
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
//! * with a [`NodeGraph`] (animated grammars, cameras): one node per bone
//!   under the root, each mesh under its bone's node, a camera node, and one
//!   animation `"rulemesh"` with LINEAR translation/rotation/scale channels
//!   per animated node, sampled at the grammar's fps; the samples follow the
//!   meshes in the buffer, in one buffer view without a target.
//!
//! Output is deterministic: every map is ordered and nothing time-dependent
//! is written.

use crate::model::graph::{NodeGraph, Trs};
use super::{ExportError, ExportMeta};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use gltf_json as json;
use json::validation::{Checked::Valid, USize64};
use std::collections::BTreeMap;

/// glTF buffers (and GLB files) address at most 2³² − 1 bytes.
const MAX_BYTES: u64 = u32::MAX as u64;
/// The largest vertex count indexed with UNSIGNED_SHORT (65535 itself is the
/// primitive-restart value and may not appear as an index).
const MAX_SHORT_VERTICES: usize = 65535;
const GLB_MAGIC: &[u8; 4] = b"glTF";
const CHUNK_JSON: u32 = 0x4E4F_534A;
const CHUNK_BIN: u32 = 0x004E_4942;
/// The URI prefix of an embedded buffer.
const DATA_URI: &str = "data:application/octet-stream;base64,";

/// Where one mesh's data lives in the binary buffer.
struct Placed {
    /// Index of the mesh in the writer's input (for the node graph).
    mesh: usize,
    vertices: usize,
    triangles: usize,
    /// Indices as u16 (else u32).
    short: bool,
    offset: u64,
    min: [f32; 3],
    max: [f32; 3],
}

impl Placed {
    fn position_offset(&self) -> u64 {
        self.offset
    }
    fn normal_offset(&self) -> u64 {
        self.offset + 12 * self.vertices as u64
    }
    fn colour_offset(&self) -> u64 {
        self.offset + 24 * self.vertices as u64
    }
    fn index_offset(&self) -> u64 {
        self.offset + 28 * self.vertices as u64
    }
    fn index_bytes(&self) -> u64 {
        3 * self.triangles as u64 * if self.short { 2 } else { 4 }
    }
    fn end(&self) -> u64 {
        self.index_offset() + self.index_bytes()
    }
}

fn align4(n: u64) -> u64 {
    n.saturating_add(3) & !3
}

fn invalid(name: &str, detail: impl Into<String>) -> ExportError {
    ExportError::InvalidMesh { name: name.to_string(), detail: detail.into() }
}

/// Rejects a mesh a glTF writer cannot describe: attribute lists of unequal
/// length, a partial triangle, an index out of range or a non-finite position.
pub(super) fn check_mesh(m: &NamedMesh) -> Result<(), ExportError> {
    let mesh = &m.mesh;
    let n = mesh.positions.len();
    if mesh.normals.len() != n || mesh.colours.len() != n {
        return Err(invalid(&m.name, "normals and colours must have one entry per position"));
    }
    if mesh.indices.len() % 3 != 0 {
        return Err(invalid(&m.name, "index count is not a multiple of 3"));
    }
    if mesh.indices.iter().any(|&i| i as usize >= n) {
        return Err(invalid(&m.name, "index out of range"));
    }
    if mesh.positions.iter().flatten().any(|c| !c.is_finite()) {
        return Err(invalid(&m.name, "non-finite position"));
    }
    Ok(())
}

/// A mesh with its place in the buffer.
type Placement<'a> = (&'a NamedMesh, Placed);

/// Checks each mesh and assigns buffer offsets. Meshes without triangles are
/// left out (glTF accessors may not be empty). Returns the placements (paired
/// with their mesh) and the buffer's byte length.
fn place(meshes: &[NamedMesh]) -> Result<(Vec<Placement<'_>>, u64), ExportError> {
    let mut placed = Vec::with_capacity(meshes.len());
    let mut offset = 0u64;
    for (index, m) in meshes.iter().enumerate() {
        let mesh = &m.mesh;
        let n = mesh.positions.len();
        if mesh.indices.is_empty() || n == 0 {
            continue;
        }
        check_mesh(m)?;
        let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in &mesh.positions {
            for k in 0..3 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let p = Placed { mesh: index, vertices: n, triangles: mesh.indices.len() / 3, short: n <= MAX_SHORT_VERTICES, offset, min, max };
        offset = align4(p.end());
        let end = p.end();
        placed.push((m, p));
        if end > MAX_BYTES {
            return Err(ExportError::TooLarge { format: "glTF", detail: format!("buffer of {end} bytes exceeds the 4 GiB limit") });
        }
    }
    let len = placed.last().map_or(0, |(_, p)| p.end());
    Ok((placed, len))
}

fn view(buffer: json::Index<json::Buffer>, offset: u64, length: u64, target: json::buffer::Target) -> json::buffer::View {
    json::buffer::View {
        buffer,
        byte_length: USize64(length),
        byte_offset: Some(USize64(offset)),
        byte_stride: None,
        name: None,
        target: Some(Valid(target)),
        extensions: None,
        extras: None,
    }
}

fn accessor(
    view: json::Index<json::buffer::View>,
    count: usize,
    component: json::accessor::ComponentType,
    type_: json::accessor::Type,
    normalized: bool,
) -> json::Accessor {
    json::Accessor {
        buffer_view: Some(view),
        byte_offset: None,
        count: USize64(count as u64),
        component_type: Valid(json::accessor::GenericComponentType(component)),
        extensions: None,
        extras: None,
        type_: Valid(type_),
        min: None,
        max: None,
        name: None,
        normalized,
        sparse: None,
    }
}

fn vec3_value(v: [f32; 3]) -> json::Value {
    json::Value::Array(v.iter().map(|&c| json::Value::from(f64::from(c))).collect())
}

/// The scene's `extras`: background colour and truncation, when present.
fn scene_extras(meta: &ExportMeta) -> Result<json::Extras, ExportError> {
    let mut map = BTreeMap::new();
    if let Some(bg) = meta.background {
        map.insert("background", json::Value::Array(bg.iter().map(|&c| json::Value::from(f64::from(c))).collect()));
    }
    if meta.truncated {
        map.insert("truncated", json::Value::Bool(true));
    }
    if map.is_empty() {
        return Ok(None);
    }
    Ok(Some(json::extras::RawValue::from_string(serde_json::to_string(&map)?)?))
}

/// What an animation channel moves.
#[derive(Debug, Clone, Copy)]
enum Mover {
    /// Graph node `i`.
    Node(usize),
    /// The camera node.
    Camera,
}

/// Animation samples laid out in the buffer after the meshes.
#[derive(Debug, Default)]
struct Tracks {
    /// Buffer offset of the first byte (4-byte aligned).
    offset: u64,
    /// Sample times, then each channel's outputs, all little-endian f32.
    bytes: Vec<u8>,
    /// Samples per channel.
    count: usize,
    /// The last sample time.
    end: f32,
    /// Per channel: what it moves, which property, and where its outputs start in `bytes`.
    channels: Vec<(Mover, json::animation::Property, u64)>,
}

impl Tracks {
    /// Lays out the samples of every node (and the camera) that moves;
    /// empty when nothing does. Rotations are sign-aligned sample to sample
    /// so LINEAR interpolation takes the short way.
    fn of(graph: Option<&NodeGraph>, offset: u64) -> Tracks {
        use json::animation::Property;
        let Some(g) = graph.filter(|g| g.is_animated()) else { return Tracks::default() };
        let count = g.times.len();
        let mut t = Tracks { offset, count, end: g.times.last().copied().unwrap_or(0.0), ..Tracks::default() };
        for time in &g.times {
            t.bytes.extend_from_slice(&time.to_le_bytes());
        }
        let mut movers: Vec<(Mover, &[Trs], bool)> = Vec::new();
        for (i, n) in g.nodes.iter().enumerate() {
            if n.samples.len() == count {
                movers.push((Mover::Node(i), &n.samples, true));
            }
        }
        if let Some(c) = g.camera.as_ref().filter(|c| c.samples.len() == count) {
            movers.push((Mover::Camera, &c.samples, false));
        }
        for (mover, samples, with_scale) in movers {
            t.channels.push((mover, Property::Translation, t.bytes.len() as u64));
            for s in samples {
                for c in s.translation {
                    t.bytes.extend_from_slice(&c.to_le_bytes());
                }
            }
            t.channels.push((mover, Property::Rotation, t.bytes.len() as u64));
            let mut prev = [0.0f32, 0.0, 0.0, 1.0];
            for s in samples {
                let dot: f32 = s.rotation.iter().zip(prev).map(|(a, b)| a * b).sum();
                let q = if dot < 0.0 { s.rotation.map(|c| -c) } else { s.rotation };
                for c in q {
                    t.bytes.extend_from_slice(&c.to_le_bytes());
                }
                prev = q;
            }
            if with_scale {
                t.channels.push((mover, Property::Scale, t.bytes.len() as u64));
                for s in samples {
                    for c in s.scale {
                        t.bytes.extend_from_slice(&c.to_le_bytes());
                    }
                }
            }
        }
        t
    }

    /// The buffer's length with these samples after `meshes_end` bytes of meshes.
    fn buffer_len(&self, meshes_end: u64) -> u64 {
        if self.bytes.is_empty() {
            meshes_end
        } else {
            self.offset + self.bytes.len() as u64
        }
    }
}

/// A glTF node with the transform `trs`.
fn trs_node(name: &str, trs: &Trs) -> json::Node {
    json::Node {
        name: Some(name.to_string()),
        translation: Some(trs.translation),
        rotation: Some(json::scene::UnitQuaternion(trs.rotation)),
        scale: Some(trs.scale),
        ..Default::default()
    }
}

/// Adds the graph's nodes, camera and animation to `root`. Returns, per
/// graph node, its glTF node, and the nodes that hang directly under the
/// model's root node (top-level bones and the camera).
fn add_graph(root: &mut json::Root, g: &NodeGraph, tracks: &Tracks, buffer: Option<json::Index<json::Buffer>>) -> (Vec<json::Index<json::Node>>, Vec<json::Index<json::Node>>) {
    use json::accessor::{ComponentType, Type};
    let identity = Trs { translation: [0.0; 3], rotation: [0.0, 0.0, 0.0, 1.0], scale: [1.0; 3] };
    let nodes: Vec<_> = g.nodes.iter().map(|n| root.push(trs_node(&n.name, n.samples.first().unwrap_or(&identity)))).collect();
    let mut top = Vec::new();
    for (i, n) in g.nodes.iter().enumerate() {
        match n.parent.and_then(|p| nodes.get(p as usize)) {
            Some(&p) => root.nodes[p.value()].children.get_or_insert_with(Vec::new).push(nodes[i]),
            None => top.push(nodes[i]),
        }
    }
    let camera_node = g.camera.as_ref().map(|c| {
        let camera = root.push(json::Camera {
            name: c.name.clone(),
            orthographic: None,
            perspective: Some(json::camera::Perspective { aspect_ratio: None, yfov: c.yfov, zfar: c.zfar, znear: c.znear, extensions: None, extras: None }),
            type_: Valid(json::camera::Type::Perspective),
            extensions: None,
            extras: None,
        });
        let mut node = trs_node("camera", c.samples.first().unwrap_or(&identity));
        node.scale = None;
        node.camera = Some(camera);
        let n = root.push(node);
        top.push(n);
        n
    });
    let Some(buffer) = buffer.filter(|_| !tracks.channels.is_empty()) else { return (nodes, top) };
    let view = root.push(json::buffer::View {
        buffer,
        byte_length: USize64(tracks.bytes.len() as u64),
        byte_offset: Some(USize64(tracks.offset)),
        byte_stride: None,
        name: Some("animation".to_string()),
        target: None,
        extensions: None,
        extras: None,
    });
    let mut times = accessor(view, tracks.count, ComponentType::F32, Type::Scalar, false);
    times.min = Some(json::Value::Array(vec![json::Value::from(0.0)]));
    times.max = Some(json::Value::Array(vec![json::Value::from(f64::from(tracks.end))]));
    let input = root.push(times);
    let mut samplers = Vec::new();
    let mut channels = Vec::new();
    for &(mover, property, at) in &tracks.channels {
        let type_ = if property == json::animation::Property::Rotation { Type::Vec4 } else { Type::Vec3 };
        let mut out = accessor(view, tracks.count, ComponentType::F32, type_, false);
        out.byte_offset = Some(USize64(at));
        let output = root.push(out);
        let interpolation = if g.step { json::animation::Interpolation::Step } else { json::animation::Interpolation::Linear };
        samplers.push(json::animation::Sampler { input, interpolation: Valid(interpolation), output, extensions: None, extras: None });
        let node = match mover {
            Mover::Node(i) => nodes[i],
            Mover::Camera => match camera_node {
                Some(n) => n,
                None => continue,
            },
        };
        channels.push(json::animation::Channel {
            sampler: json::Index::new((samplers.len() - 1) as u32),
            target: json::animation::Target { node, path: Valid(property), extensions: None, extras: None },
            extensions: None,
            extras: None,
        });
    }
    root.push(json::Animation { name: Some("rulemesh".to_string()), channels, samplers, extensions: None, extras: None });
    (nodes, top)
}

/// Builds the glTF JSON. `uri` is the buffer's URI (None for GLB).
fn document(placed: &[Placement<'_>], buffer_len: u64, tracks: &Tracks, meta: &ExportMeta, uri: Option<String>) -> Result<Vec<u8>, ExportError> {
    use json::accessor::{ComponentType, Type};
    use json::buffer::Target;
    let mut root = json::Root {
        asset: json::Asset {
            copyright: None,
            extensions: None,
            extras: None,
            generator: Some(format!("rulemesh {}", crate::ENGINE_VERSION)),
            min_version: None,
            version: "2.0".to_string(),
        },
        ..Default::default()
    };
    let root_node = root.push(json::Node { name: Some("rulemesh".to_string()), ..Default::default() });
    let buffer = (buffer_len > 0).then(|| root.push(json::Buffer { byte_length: USize64(buffer_len), name: None, uri, extensions: None, extras: None }));
    let (graph_nodes, mut children) = match &meta.graph {
        Some(g) => add_graph(&mut root, g, tracks, buffer),
        None => (Vec::new(), Vec::new()),
    };
    if let (false, Some(buffer)) = (placed.is_empty(), buffer) {
        let material = |name: Option<String>| json::Material {
            name,
            pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                base_color_factor: json::material::PbrBaseColorFactor([1.0, 1.0, 1.0, 1.0]),
                metallic_factor: json::material::StrengthFactor(0.0),
                roughness_factor: json::material::StrengthFactor(0.8),
                ..Default::default()
            },
            double_sided: false,
            ..Default::default()
        };
        let shared = (!meta.material_per_mesh).then(|| root.push(material(None)));
        for (m, p) in placed {
            let material = match shared {
                Some(s) => s,
                None => root.push(material(Some(m.name.clone()))),
            };
            let n = p.vertices;
            let pv = root.push(view(buffer, p.position_offset(), 12 * n as u64, Target::ArrayBuffer));
            let nv = root.push(view(buffer, p.normal_offset(), 12 * n as u64, Target::ArrayBuffer));
            let cv = root.push(view(buffer, p.colour_offset(), 4 * n as u64, Target::ArrayBuffer));
            let iv = root.push(view(buffer, p.index_offset(), p.index_bytes(), Target::ElementArrayBuffer));
            let mut pos = accessor(pv, n, ComponentType::F32, Type::Vec3, false);
            pos.min = Some(vec3_value(p.min));
            pos.max = Some(vec3_value(p.max));
            let pos = root.push(pos);
            let nrm = root.push(accessor(nv, n, ComponentType::F32, Type::Vec3, false));
            let col = root.push(accessor(cv, n, ComponentType::U8, Type::Vec4, true));
            let index_type = if p.short { ComponentType::U16 } else { ComponentType::U32 };
            let idx = root.push(accessor(iv, 3 * p.triangles, index_type, Type::Scalar, false));
            let mut attributes = BTreeMap::new();
            attributes.insert(Valid(json::mesh::Semantic::Positions), pos);
            attributes.insert(Valid(json::mesh::Semantic::Normals), nrm);
            attributes.insert(Valid(json::mesh::Semantic::Colors(0)), col);
            let mesh = root.push(json::Mesh {
                extensions: None,
                extras: None,
                name: Some(m.name.clone()),
                primitives: vec![json::mesh::Primitive {
                    attributes,
                    extensions: None,
                    extras: None,
                    indices: Some(idx),
                    material: Some(material),
                    mode: Valid(json::mesh::Mode::Triangles),
                    targets: None,
                }],
                weights: None,
            });
            let node = root.push(json::Node { mesh: Some(mesh), name: Some(m.name.clone()), ..Default::default() });
            let parent = meta.graph.as_ref().and_then(|g| g.mesh_nodes.get(p.mesh).copied().flatten()).and_then(|i| graph_nodes.get(i as usize));
            match parent {
                Some(&b) => root.nodes[b.value()].children.get_or_insert_with(Vec::new).push(node),
                None => children.push(node),
            }
        }
    }
    if !children.is_empty() {
        root.nodes[root_node.value()].children = Some(children);
    }
    let mut nodes = vec![root_node];
    if let Some(c) = &meta.camera {
        let at = c.first();
        let camera = root.push(json::Camera {
            name: c.name.clone(),
            orthographic: None,
            perspective: Some(json::camera::Perspective {
                aspect_ratio: None,
                yfov: c.yfov,
                zfar: c.zfar,
                znear: c.znear,
                extensions: None,
                extras: Default::default(),
            }),
            type_: Valid(json::camera::Type::Perspective),
            extensions: None,
            extras: Default::default(),
        });
        nodes.push(root.push(json::Node {
            camera: Some(camera),
            name: Some("camera".to_string()),
            rotation: Some(json::scene::UnitQuaternion(at.rotation)),
            translation: Some(at.translation),
            ..Default::default()
        }));
    }
    let scene = root.push(json::Scene { extensions: None, extras: scene_extras(meta)?, name: None, nodes });
    root.scene = Some(scene);
    Ok(root.to_vec()?)
}


/// A destination for the binary buffer's bytes.
trait Sink {
    fn put(&mut self, bytes: &[u8]);
}

impl Sink for Vec<u8> {
    fn put(&mut self, bytes: &[u8]) {
        self.extend_from_slice(bytes);
    }
}

/// Streams bytes as standard base64 (with `=` padding) into a vector.
struct Base64<'a> {
    out: &'a mut Vec<u8>,
    carry: [u8; 3],
    held: usize,
}

const BASE64_ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

impl Base64<'_> {
    fn emit(&mut self, n: usize) {
        let [a, b, c] = self.carry;
        let quad = [a >> 2, ((a & 0x03) << 4) | (b >> 4), ((b & 0x0f) << 2) | (c >> 6), c & 0x3f];
        for (k, &q) in quad.iter().enumerate() {
            self.out.push(if k <= n { BASE64_ALPHABET[q as usize] } else { b'=' });
        }
    }

    fn finish(mut self) {
        if self.held > 0 {
            for k in self.held..3 {
                self.carry[k] = 0;
            }
            self.emit(self.held);
        }
    }
}

impl Sink for Base64<'_> {
    fn put(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.carry[self.held] = b;
            self.held += 1;
            if self.held == 3 {
                self.emit(3);
                self.held = 0;
            }
        }
    }
}

/// Standard base64 (with `=` padding) of `bytes`, for other glTF writers.
pub(super) fn base64(bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(base64_len(bytes.len() as u64) as usize);
    let mut b = Base64 { out: &mut out, carry: [0; 3], held: 0 };
    b.put(bytes);
    b.finish();
    out
}

/// Length of the base64 encoding of `n` bytes.
fn base64_len(n: u64) -> u64 {
    n.div_ceil(3).saturating_mul(4)
}

/// Writes 4-byte words little-endian. On little-endian machines memory
/// already has that layout, so the whole slice goes out in one copy.
fn put_words<T: bytemuck::Pod>(sink: &mut impl Sink, values: &[T], to_le: fn(T) -> [u8; 4]) {
    if cfg!(target_endian = "little") {
        sink.put(bytemuck::cast_slice(values));
    } else {
        for &v in values {
            sink.put(&to_le(v));
        }
    }
}

/// Writes the binary buffer (exactly `buffer_len` bytes, zero padding between
/// meshes), then the animation samples.
fn write_buffer(sink: &mut impl Sink, placed: &[Placement<'_>], tracks: &Tracks) {
    let mut at = 0u64;
    for (m, p) in placed {
        while at < p.offset {
            sink.put(&[0]);
            at += 1;
        }
        put_words::<f32>(sink, bytemuck::cast_slice(&m.mesh.positions), f32::to_le_bytes);
        put_words::<f32>(sink, bytemuck::cast_slice(&m.mesh.normals), f32::to_le_bytes);
        sink.put(bytemuck::cast_slice(&m.mesh.colours));
        if !p.short {
            put_words(sink, &m.mesh.indices, u32::to_le_bytes);
            at = p.end();
            continue;
        }
        for &i in &m.mesh.indices {
            // Fits: `short` means every index is below 65535.
            sink.put(&(i as u16).to_le_bytes());
        }
        at = p.end();
    }
    if !tracks.bytes.is_empty() {
        while at < tracks.offset {
            sink.put(&[0]);
            at += 1;
        }
        sink.put(&tracks.bytes);
    }
}

/// Writes a binary glTF (.glb): 12-byte header, JSON chunk padded with spaces,
/// BIN chunk padded with zeros (omitted when there is no geometry).
///
/// Reserves the exact output size in `budget` before allocating it; fails
/// with [`ExportError::TooLarge`] beyond the format's 4 GiB limit.
pub fn write_glb(meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let (placed, meshes_end) = place(meshes)?;
    let tracks = animation_tracks(meta, meshes_end, budget)?;
    let buffer_len = tracks.buffer_len(meshes_end);
    let json_bytes = document(&placed, buffer_len, &tracks, meta, None)?;
    let json_len = align4(json_bytes.len() as u64);
    let bin_chunk = if buffer_len == 0 { 0 } else { 8 + align4(buffer_len) };
    let total = 12 + 8 + json_len + bin_chunk;
    if total > MAX_BYTES {
        return Err(ExportError::TooLarge { format: "GLB", detail: format!("file of {total} bytes exceeds the 4 GiB limit") });
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
        write_buffer(&mut out, &placed, &tracks);
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
pub fn write_gltf(meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let (placed, meshes_end) = place(meshes)?;
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
        write_buffer(&mut b64, &placed, &tracks);
        b64.finish();
    }
    out.extend_from_slice(&json_bytes[split..]);
    debug_assert_eq!(out.len() as u64, total);
    Ok(out)
}

/// The animation samples of `meta`'s graph, placed after `meshes_end` bytes of
/// meshes and charged to `budget` (they are held until written).
fn animation_tracks(meta: &ExportMeta, meshes_end: u64, budget: &mut Budget) -> Result<Tracks, ExportError> {
    let tracks = Tracks::of(meta.graph.as_ref(), align4(meshes_end));
    budget.reserve_memory(tracks.bytes.len() as u64)?;
    if tracks.buffer_len(meshes_end) > MAX_BYTES {
        return Err(ExportError::TooLarge { format: "glTF", detail: "animation samples exceed the 4 GiB buffer limit".to_string() });
    }
    Ok(tracks)
}

/// The glTF extension instanced models require.
pub const EXT_INSTANCING: &str = "EXT_mesh_gpu_instancing";

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
    let mut doc: serde_json::Value = serde_json::from_slice(&document(&placed, end, &Tracks::default(), meta, uri)?)?;
    let push = |doc: &mut serde_json::Value, key: &str, v: serde_json::Value| -> usize {
        match doc[key].as_array_mut() {
            Some(a) => {
                a.push(v);
                a.len() - 1
            }
            None => 0,
        }
    };
    for (i, (&c, &(t, r))) in counts.iter().zip(&regions).enumerate() {
        let tv = push(&mut doc, "bufferViews", serde_json::json!({"buffer": 0, "byteOffset": t, "byteLength": 12 * c}));
        let rv = push(&mut doc, "bufferViews", serde_json::json!({"buffer": 0, "byteOffset": r, "byteLength": 16 * c}));
        let ta = push(&mut doc, "accessors", serde_json::json!({"bufferView": tv, "componentType": 5126, "count": c, "type": "VEC3"}));
        let ra = push(&mut doc, "accessors", serde_json::json!({"bufferView": rv, "componentType": 5126, "count": c, "type": "VEC4"}));
        // document() pushes the root node first, then one node per mesh in order.
        let Some(node) = doc.get_mut("nodes").and_then(|n| n.get_mut(i + 1)).and_then(|n| n.as_object_mut()) else {
            return Err(invalid("model", "the document lacks a node for an instanced mesh"));
        };
        node.insert("extensions".into(), serde_json::json!({ EXT_INSTANCING: {"attributes": {"TRANSLATION": ta, "ROTATION": ra}} }));
    }
    doc["extensionsUsed"] = serde_json::json!([EXT_INSTANCING]);
    doc["extensionsRequired"] = serde_json::json!([EXT_INSTANCING]);
    let json_bytes = serde_json::to_vec(&doc)?;
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

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
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
        let meta = ExportMeta { background: Some([0.25, 0.5, 1.0, 1.0]), truncated: true, graph: None, material_per_mesh: false, camera: None };
        let (j, _) = parse_glb(&write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap());
        assert_eq!(j["scenes"][0]["extras"], serde_json::json!({"background": [0.25, 0.5, 1.0, 1.0], "truncated": true}));
        let meta = ExportMeta { background: None, truncated: true, graph: None, material_per_mesh: false, camera: None };
        let (j, _) = parse_glb(&write_glb(&meshes, &meta, &mut Budget::new(Limits::default())).unwrap());
        assert_eq!(j["scenes"][0]["extras"], serde_json::json!({"truncated": true}));
    }

    #[test]
    fn gltf_embeds_the_same_buffer_as_glb() {
        let meshes = meshes_of(&all_nine(), 7, MeshLayout::Merged);
        let meta = ExportMeta { background: Some([0.0, 0.0, 0.0, 1.0]), truncated: false, graph: None, material_per_mesh: false, camera: None };
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
    fn base64_matches_reference_vectors() {
        for (raw, enc) in [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foob", "Zm9vYg=="), ("fooba", "Zm9vYmE="), ("foobar", "Zm9vYmFy")] {
            let mut out = Vec::new();
            let mut b = Base64 { out: &mut out, carry: [0; 3], held: 0 };
            b.put(raw.as_bytes());
            b.finish();
            assert_eq!(out, enc.as_bytes());
            assert_eq!(base64_len(raw.len() as u64) as usize, enc.len());
        }
    }

    #[test]
    fn deterministic_bytes() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::PerKind);
        let meta = ExportMeta { background: Some([0.1, 0.2, 0.3, 1.0]), truncated: true, graph: None, material_per_mesh: false, camera: None };
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
    fn malformed_meshes_are_rejected() {
        let mut meshes = meshes_of(&scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 1.0, false)]), 16, MeshLayout::Merged);
        meshes[0].mesh.indices[0] = 1000;
        assert!(matches!(write_glb(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())), Err(ExportError::InvalidMesh { .. })));
        meshes[0].mesh.indices[0] = 0;
        meshes[0].mesh.positions[0][0] = f32::NAN;
        assert!(matches!(write_gltf(&meshes, &ExportMeta::default(), &mut Budget::new(Limits::default())), Err(ExportError::InvalidMesh { .. })));
    }
}
