//! What a format is, as the registry (`formats.rs`) records it: one
//! [`FormatInfo`] per format, declared as a constant in the format's own
//! folder beside its writer, so the facts a door or a stage needs (its
//! name, extensions, MIME type, what it can carry, how large it can get,
//! how it is written) are stated once, where the writer that makes them
//! true lives.
//!
//! Everything here is data or a plain function pointer: a descriptor is a
//! `const`, the registry a table of them, and nothing needs allocating or
//! registering at run time.

use super::{ExportError, ExportMeta, ExportOptions, Provenance};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use crate::mesh::MeshLayout;
use crate::model::{Drawing, Hierarchy, Scene};
use crate::preview::Image;

/// One format: everything the CLI, the service, the schema, the cache, the
/// pipeline and the golden table read about it.
#[derive(Debug, Clone, Copy)]
pub struct FormatInfo {
    /// The request name (`"glb"`, `"stl-ascii"`, `"3mf"` …): the one
    /// spelling of requests, the CLI, the schema's enum, the cache key,
    /// metrics labels, logs and the golden table's variants. Lower case,
    /// unique across the registry.
    pub name: &'static str,
    /// File extensions without the dot, lower case. The first is the one a
    /// file of this format is named with; all of them are recognised on
    /// output file names and in `/v1/models/NAME.EXT` (by the first format
    /// of the registry that claims one, so binary STL keeps `.stl`).
    pub extensions: &'static [&'static str],
    /// The MIME type the service sends as `Content-Type`.
    pub mime: &'static str,
    /// What the format can carry; the pipeline picks a route from these.
    pub caps: Capabilities,
    /// Which of the request's format options the format reads (they are
    /// validated, keyed and accepted only for such a format).
    pub options: OptionGroup,
    /// The upper bound on a file's size, charged before writing.
    pub size: SizeBound,
    /// How the format is written.
    pub writer: Writer,
}

/// What a format can carry beyond triangles. Each flag is read by one
/// decision of the pipeline or the service, named in its comment; a format
/// sets only those its writer implements. `instancing` and `streamed`
/// choose the routes that feed the sink of [`Writer::Sink`]'s `model`,
/// which such a format must name.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Capabilities {
    /// The bytes are UTF-8 text (JSON, STL ASCII, UniGrafix), not binary:
    /// the service compresses them when the client accepts it.
    pub text: bool,
    /// Repeated meshes and object-instancing hierarchies can be written
    /// once and drawn per instance (glTF's `EXT_mesh_gpu_instancing`), so
    /// front ends are asked for a hierarchy and the pipeline takes the
    /// instanced route under `instancing: gpu`.
    pub instancing: bool,
    /// A node graph can be written: bones, their animation and a camera
    /// path (glTF nodes and animations). Without it a model shows time 0.
    pub node_graph: bool,
    /// Written from the model a chunk at a time, without a merged mesh or
    /// an expanded hierarchy (strips), when not printed or fitted.
    pub streamed: bool,
    /// Only positions are written (STL): normals and colours are dropped
    /// before the output is allocated, so a big model's peak stays low.
    pub positions_only: bool,
}

impl Capabilities {
    /// Triangles and nothing else, in binary.
    pub const NONE: Capabilities = Capabilities { text: false, instancing: false, node_graph: false, streamed: false, positions_only: false };
}

/// The group of request options a format reads besides the ones every
/// format takes (`fit`, `print`, `layout`, `detail`). At most one group
/// per format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OptionGroup {
    /// None of its own.
    None,
    /// `weld`, `quantize`, `compress` and `instancing` (glTF).
    Gltf,
    /// `position_bits`, `normal_bits` and `zstd` (strips).
    Strips,
    /// `size`, `view` and `background`: the preview stage's picture.
    Preview,
    /// `checksum` (scene: a CRC-32 after the last mesh, docs/scene-format.md).
    Scene,
}

/// An upper bound on a file's size, linear in what it holds, so the budget
/// can be charged before the writer allocates anything:
/// `fixed + per_vertex·v + per_triangle·t` (saturating), and per instance
/// where the format writes instances rather than their triangles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SizeBound {
    /// The fixed per-file overhead (headers, the document's JSON).
    pub fixed: u64,
    /// Bytes per vertex.
    pub per_vertex: u64,
    /// Bytes per triangle.
    pub per_triangle: u64,
    /// Bytes per placed instance, for the routes that write instances
    /// (instanced glTF, scene); 0 where the format has none.
    pub per_instance: u64,
}

impl SizeBound {
    /// The bound for `vertices` and `triangles`.
    pub const fn of(&self, vertices: u64, triangles: u64) -> u64 {
        vertices.saturating_mul(self.per_vertex).saturating_add(triangles.saturating_mul(self.per_triangle)).saturating_add(self.fixed)
    }
}

/// Writes meshes (after meshing or printing) with the request's options.
pub(crate) type WriteMeshes = fn(&[NamedMesh], &ExportMeta, &ExportOptions, &mut Budget) -> Result<Vec<u8>, ExportError>;

/// Encodes the preview stage's picture, with the model's provenance where
/// the format has metadata.
pub(crate) type EncodePicture = fn(&Image, Option<&Provenance>, &mut Budget) -> Result<Vec<u8>, ExportError>;

/// Writes the model as it was made — its flat scene, or its hierarchy when
/// it has one — at a tessellation detail and mesh layout the reader
/// applies, with the request's export options (its format's group);
/// returns the bytes and the triangles a reader tessellates.
pub(crate) type WriteModel = fn(&Scene, Option<&Hierarchy>, u32, MeshLayout, &ExportOptions, Option<&Provenance>, &mut Budget) -> Result<(Vec<u8>, u64), ExportError>;

/// Writes the model's 2D drawing (a Context Free design's marks), with the
/// model's provenance where the format has metadata.
pub(crate) type WriteDrawing = fn(&Drawing, Option<&Provenance>, &mut Budget) -> Result<Vec<u8>, ExportError>;

/// How a format is written: from what, by which function.
#[derive(Debug, Clone, Copy)]
pub enum Writer {
    /// From geometry: merged meshes by `flat` (the flat and print routes,
    /// and the empty model of a late answer), and, where the format has
    /// one, the model fed into the [`GeometrySink`](super::GeometrySink)
    /// `model` makes: piece by piece for a streamed format
    /// ([`Capabilities::streamed`], strips), meshes and their placements for
    /// an instancing one ([`Capabilities::instancing`], glTF).
    Sink {
        /// The writer of merged meshes.
        flat: WriteMeshes,
        /// The sink of the streamed or instanced route.
        model: Option<super::MakeSink>,
    },
    /// From a picture of the meshes: the preview stage runs first
    /// (`docs/preview.md`), then this encoder.
    Picture(EncodePicture),
    /// From the model itself, instances and hierarchy as made, with no
    /// meshing (`docs/scene-format.md`).
    Model(WriteModel),
    /// From meshes as [`Writer::Sink`]'s `flat` does, and from an object-instancing
    /// hierarchy, when the model has one, into the sink `hierarchy` makes
    /// (unfitted and unprinted requests; the front ends are asked for a
    /// hierarchy): each (leaf shape, colour) given once as a mesh and placed
    /// per leaf by the pipeline's driver (USDZ's scene-graph instancing,
    /// `docs/usdz.md`). A flat scene's repeats are written flat.
    Instancing {
        /// The flat route's writer.
        meshes: WriteMeshes,
        /// The hierarchy's sink.
        hierarchy: super::MakeSink,
    },
    /// From the model's 2D [`Drawing`], for a model that carries one (a
    /// Context Free design); the pipeline refuses the format for a model
    /// without, naming the capability (`svg`).
    Drawing(WriteDrawing),
}
