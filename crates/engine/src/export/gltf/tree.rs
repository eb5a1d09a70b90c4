//! The glTF document rulemesh writes, as its own small types: exactly the
//! objects and fields its writers set, borrowing names from the meshes and
//! the model, with bounds as numbers and extensions as flags and indices.
//!
//! Why not gltf-json's `Root`: that tree is general (every field of the
//! specification, names as `String`s, bounds as `serde_json::Value`
//! arrays, extensions as `serde_json::Map`s, a `BTreeMap` per primitive),
//! and for a fresh icon render (issue 33's `gem.glb`: 25 accessors, 25
//! views, 4 meshes, 5 nodes) building, serialising and dropping it was
//! about two thirds of the instanced writer's instructions and a hundred
//! allocations. These types hold what rulemesh writes and nothing else;
//! `json_out` writes them as the bytes gltf-json gave, and gltf-json stays
//! the oracle: `json_oracle` (tests only) turns a document into
//! gltf-json's tree and holds `Root::to_vec`'s bytes equal to ours.
//!
//! Indices are `u32`, as gltf-json's `Index` is.

use crate::model::graph::Trs;

/// `EXT_meshopt_compression`: meshoptimizer's codecs on buffer views.
pub(super) const EXT_MESHOPT: &str = "EXT_meshopt_compression";
/// `KHR_mesh_quantization`: integer vertex attributes.
pub(super) const KHR_QUANT: &str = "KHR_mesh_quantization";
/// `EXT_mesh_gpu_instancing`: per-node instance transforms.
pub(super) const EXT_INSTANCING: &str = "EXT_mesh_gpu_instancing";

/// An index into one of the document's arrays.
pub(super) type Ix = u32;

/// Appends `item` to `list` and returns its index (as gltf-json's
/// `Root::push` does).
pub(super) fn push<T>(list: &mut Vec<T>, item: T) -> Ix {
    list.push(item);
    (list.len() - 1) as Ix
}

/// The whole document, its arrays in the order the JSON lists them.
#[derive(Default)]
pub(super) struct Root<'a> {
    /// `accessors`.
    pub(super) accessors: Vec<Accessor>,
    /// `animations`: at most the one `"rulemesh"` animation.
    pub(super) animations: Vec<Animation>,
    /// `asset.extras`: the model's provenance, JSON text already.
    pub(super) provenance: Option<Box<serde_json::value::RawValue>>,
    /// `buffers`.
    pub(super) buffers: Vec<Buffer>,
    /// `bufferViews`.
    pub(super) views: Vec<View>,
    /// `scene`.
    pub(super) scene: Option<Ix>,
    /// `extensionsUsed`, which rulemesh always also lists as `extensionsRequired`.
    pub(super) extensions: Vec<&'static str>,
    /// `cameras`.
    pub(super) cameras: Vec<Camera<'a>>,
    /// `materials`.
    pub(super) materials: Vec<Material<'a>>,
    /// `meshes`.
    pub(super) meshes: Vec<Mesh<'a>>,
    /// `nodes`.
    pub(super) nodes: Vec<Node<'a>>,
    /// `scenes`.
    pub(super) scenes: Vec<Scene>,
}

/// An accessor's component type (its GL enum is the JSON number).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Component {
    /// BYTE (normalised normals of quantised meshes).
    I8,
    /// UNSIGNED_BYTE (colours).
    U8,
    /// UNSIGNED_SHORT (short indices, quantised positions).
    U16,
    /// UNSIGNED_INT (long indices).
    U32,
    /// FLOAT.
    F32,
}

impl Component {
    /// The GL enum glTF names the component type by.
    pub(super) fn gl(self) -> u32 {
        match self {
            Component::I8 => 5120,
            Component::U8 => 5121,
            Component::U16 => 5123,
            Component::U32 => 5125,
            Component::F32 => 5126,
        }
    }
}

/// An accessor's element type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// One component (indices, sample times).
    Scalar,
    /// Three (positions, normals, translations, scales).
    Vec3,
    /// Four (colours, rotations).
    Vec4,
}

impl Kind {
    /// The word glTF names the type by.
    pub(super) fn word(self) -> &'static str {
        match self {
            Kind::Scalar => "SCALAR",
            Kind::Vec3 => "VEC3",
            Kind::Vec4 => "VEC4",
        }
    }
}

/// An accessor's `min` and `max`, as the writers give them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Bounds {
    /// Float positions' box, each written as the f64 of the f32.
    Float([f32; 3], [f32; 3]),
    /// Quantised positions' box on the grid.
    Grid([u16; 3], [u16; 3]),
    /// Animation sample times: `[0.0]` to `[end]` (as f64).
    Times(f32),
}

/// An accessor: `count` elements read from `view`.
pub(super) struct Accessor {
    /// `bufferView`.
    pub(super) view: Ix,
    /// `byteOffset`, when not at the view's start.
    pub(super) byte_offset: Option<u64>,
    /// `count`.
    pub(super) count: u64,
    /// `componentType`.
    pub(super) component: Component,
    /// `type`.
    pub(super) kind: Kind,
    /// `min` and `max`, when written (POSITION and sample times).
    pub(super) bounds: Option<Bounds>,
    /// `normalized`, written only when true.
    pub(super) normalized: bool,
}

/// A buffer view's `target`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Target {
    /// ARRAY_BUFFER: vertex attributes.
    Vertices,
    /// ELEMENT_ARRAY_BUFFER: indices.
    Indices,
}

impl Target {
    /// The GL enum glTF names the target by.
    pub(super) fn gl(self) -> u32 {
        match self {
            Target::Vertices => 34962,
            Target::Indices => 34963,
        }
    }
}

/// `EXT_meshopt_compression` on a buffer view: where its encoded bytes are
/// and how to decode them into the view's (fallback) layout.
#[derive(Debug, Clone, Copy)]
pub(super) struct MeshoptView {
    /// The buffer holding the encoded bytes.
    pub(super) buffer: Ix,
    /// Where the encoded bytes start.
    pub(super) byte_offset: u64,
    /// How many encoded bytes there are.
    pub(super) byte_length: u64,
    /// Bytes per decoded element.
    pub(super) byte_stride: u64,
    /// Decoded elements.
    pub(super) count: u64,
    /// The codec: `ATTRIBUTES` (vertex codec) or `TRIANGLES` (index codec).
    pub(super) mode: &'static str,
}

/// A buffer view: `byte_length` bytes at `byte_offset` of `buffer`.
pub(super) struct View {
    /// `buffer`.
    pub(super) buffer: Ix,
    /// `byteLength`.
    pub(super) byte_length: u64,
    /// `byteOffset` (always written).
    pub(super) byte_offset: u64,
    /// `byteStride`, for the compact writer's interleaved-looking streams.
    pub(super) byte_stride: Option<u64>,
    /// `name` (`"animation"` for the samples' view).
    pub(super) name: Option<&'static str>,
    /// `target`.
    pub(super) target: Option<Target>,
    /// `EXT_meshopt_compression`, when compressed.
    pub(super) meshopt: Option<MeshoptView>,
}

/// A buffer.
pub(super) struct Buffer {
    /// `byteLength`.
    pub(super) byte_length: u64,
    /// `uri` (a `.gltf`'s data URI; none for GLB's own chunk).
    pub(super) uri: Option<String>,
    /// `EXT_meshopt_compression`'s `"fallback": true`: no data of its own.
    pub(super) meshopt_fallback: bool,
}

/// The material every mesh is drawn with (white, metallic 0, roughness
/// 0.8, so vertex colours show), named when each mesh has its own.
pub(super) struct Material<'a> {
    /// `name`.
    pub(super) name: Option<&'a str>,
}

/// A mesh of one TRIANGLES primitive.
pub(super) struct Mesh<'a> {
    /// `name`.
    pub(super) name: &'a str,
    /// The primitive's POSITION accessor.
    pub(super) position: Ix,
    /// NORMAL.
    pub(super) normal: Ix,
    /// COLOR_0.
    pub(super) colour: Ix,
    /// `indices`.
    pub(super) indices: Ix,
    /// `material`.
    pub(super) material: Ix,
}

/// `EXT_mesh_gpu_instancing` on a node: the accessors of its instances'
/// attributes. Rigid L-system segments have no SCALE and carry their colour
/// in their mesh; placed primitives have ROTATION, SCALE and `_COLOR_0`
/// (float RGB, which three.js reads into `InstancedMesh.instanceColor`)
/// where they differ between instances.
#[derive(Debug, Clone, Copy)]
pub(super) struct Instancing {
    /// TRANSLATION.
    pub(super) translation: Ix,
    /// ROTATION, when written.
    pub(super) rotation: Option<Ix>,
    /// SCALE, when written.
    pub(super) scale: Option<Ix>,
    /// `_COLOR_0`, when written.
    pub(super) colour: Option<Ix>,
}

/// A node.
#[derive(Default)]
pub(super) struct Node<'a> {
    /// `camera`.
    pub(super) camera: Option<Ix>,
    /// `children`, written when there are any.
    pub(super) children: Vec<Ix>,
    /// `EXT_mesh_gpu_instancing`, when its mesh is instanced.
    pub(super) instancing: Option<Instancing>,
    /// `mesh`.
    pub(super) mesh: Option<Ix>,
    /// `name` (every node rulemesh writes has one).
    pub(super) name: &'a str,
    /// `rotation` (a unit quaternion, x y z w).
    pub(super) rotation: Option<[f32; 4]>,
    /// `scale`.
    pub(super) scale: Option<[f32; 3]>,
    /// `translation`.
    pub(super) translation: Option<[f32; 3]>,
}

impl<'a> Node<'a> {
    /// A node named `name` with the transform `trs`.
    pub(super) fn trs(name: &'a str, trs: &Trs) -> Node<'a> {
        Node { name, translation: Some(trs.translation), rotation: Some(trs.rotation), scale: Some(trs.scale), ..Default::default() }
    }
}

/// A perspective camera (the aspect ratio is left to the viewer).
pub(super) struct Camera<'a> {
    /// `name`.
    pub(super) name: Option<&'a str>,
    /// `perspective.yfov`.
    pub(super) yfov: f32,
    /// `perspective.zfar`.
    pub(super) zfar: Option<f32>,
    /// `perspective.znear`.
    pub(super) znear: f32,
}

/// What an animation channel moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Path {
    /// `translation`.
    Translation,
    /// `rotation`.
    Rotation,
    /// `scale`.
    Scale,
}

impl Path {
    /// The word glTF names the path by.
    pub(super) fn word(self) -> &'static str {
        match self {
            Path::Translation => "translation",
            Path::Rotation => "rotation",
            Path::Scale => "scale",
        }
    }
}

/// An animation sampler: times `input`, values `output`.
pub(super) struct Sampler {
    /// `input`.
    pub(super) input: Ix,
    /// STEP interpolation, else LINEAR.
    pub(super) step: bool,
    /// `output`.
    pub(super) output: Ix,
}

/// An animation channel: sampler `sampler` moves `path` of `node`.
pub(super) struct Channel {
    /// `sampler`.
    pub(super) sampler: Ix,
    /// `target.node`.
    pub(super) node: Ix,
    /// `target.path`.
    pub(super) path: Path,
}

/// The `"rulemesh"` animation.
pub(super) struct Animation {
    /// `channels`.
    pub(super) channels: Vec<Channel>,
    /// `samplers`.
    pub(super) samplers: Vec<Sampler>,
}

/// The one scene: its root nodes and its `extras`.
pub(super) struct Scene {
    /// `extras.background`, when the model has one.
    pub(super) background: Option<[f32; 4]>,
    /// `extras.truncated`, written when true.
    pub(super) truncated: bool,
    /// `nodes`.
    pub(super) nodes: Vec<Ix>,
}
