//! The one output shape of the mesh writers: a [`GeometrySink`] is given a
//! model's geometry a piece, a mesh or a placement at a time, and may refuse
//! each against the budget, after Nicolas Silva, lyon_tessellation
//! `GeometryBuilder` (lyon_tessellation 1.0, `geometry_builder`:
//! `begin_geometry`, `add_fill_vertex` returning a `VertexId` or a
//! `GeometryBuilderError`, `add_triangle`, `end_geometry`; where lyon calls
//! `abort_geometry` after an error, a sink is simply dropped, since its
//! output is only returned by `end`). Streamed strips, instanced glTF and the flat
//! formats are implementations; the pipeline's drivers
//! (`pipeline::feed`) walk the model and feed whichever sink the route
//! names, so the stage work (walking a hierarchy, tessellating a piece,
//! finding repeated meshes) is done there once and never inside a writer.
//!
//! Why a trait rather than five function shapes: the walk that streams a
//! model into strips and the walk that instances it into glTF were two
//! drivers written beside their writers, each with its own budget charges;
//! with one shape the charges sit where the bytes are made (the sink), and
//! a new mesh format is one more implementation, not one more route.

use super::{ExportError, ExportMeta, ExportOptions, WriteMeshes};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use crate::mesh::pieces::Piece;

/// A mesh given to a sink by [`GeometrySink::mesh`]: its number in the
/// order the meshes were given, as lyon's `VertexId` numbers vertices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MeshId(pub usize);

/// Which per-instance attributes an instanced mesh's placements carry
/// besides their translation: rotation (unit quaternion), per-axis scale
/// and colour. An attribute left out is the identity for every placement,
/// so a mesh whose placements are only moved costs 12 bytes a placement in
/// glTF (`EXT_mesh_gpu_instancing`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct InstanceLayout {
    /// Carry the rotation.
    pub rotation: bool,
    /// Carry the per-axis scale.
    pub scale: bool,
    /// Carry the colour.
    pub colour: bool,
}

impl InstanceLayout {
    /// Bytes one placement takes in glTF's buffer (f32 translation, and
    /// rotation, scale and colour where the layout has them).
    pub const fn bytes(self) -> u64 {
        12 + if self.rotation { 16 } else { 0 } + if self.scale { 12 } else { 0 } + if self.colour { 12 } else { 0 }
    }
}

/// One placement of a mesh given earlier ([`GeometrySink::place`]), in the
/// f32 values the mesher uses; rotation, scale and colour are written only
/// where the mesh's [`InstanceLayout`] has them. [`exact`](InstanceData::exact)
/// is the same placement as the model holds it, for a format that makes a
/// matrix of it in f64 before rounding (usdz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InstanceData {
    /// Translation.
    pub translation: [f32; 3],
    /// Unit rotation (x, y, z, w).
    pub rotation: [f32; 4],
    /// Per-axis scale.
    pub scale: [f32; 3],
    /// Linear RGB.
    pub colour: [f32; 3],
    /// The placement before rounding to f32: a hierarchy leaf's f64 world
    /// frame, or a flat scene's f32 placement widened.
    pub exact: ExactPlacement,
}

/// A placement in f64, as an object-instancing hierarchy computes its
/// leaves' world frames (`model::hierarchy::PlacedLeaf`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactPlacement {
    /// Translation.
    pub translation: glam::DVec3,
    /// Unit rotation.
    pub rotation: glam::DQuat,
    /// Per-axis scale.
    pub scale: glam::DVec3,
}

/// How a mesh given to [`GeometrySink::mesh`] is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Drawn {
    /// Once, as it is (a flat format's mesh, instanced glTF's residual).
    Plain,
    /// `count` times, by as many [`GeometrySink::place`] calls, each
    /// carrying what `layout` says.
    Instanced {
        /// Placements that will follow.
        count: u64,
        /// What each placement carries.
        layout: InstanceLayout,
    },
}

/// Receives a model's geometry and makes the format's bytes. The driver
/// calls, in this order:
///
/// 1. [`survey`](GeometrySink::survey) with every piece of the model, when
///    [`surveys`](GeometrySink::surveys) says the sink codes relative to the
///    whole model (strips' bounding box and palette);
/// 2. [`begin`](GeometrySink::begin), once: where the sink refuses by limit
///    name before allocating its output;
/// 3. [`piece`](GeometrySink::piece) with the pieces again (the same ones,
///    in the same order), or [`mesh`](GeometrySink::mesh) with every mesh
///    and then [`place`](GeometrySink::place) with every placement of the
///    instanced ones; a sink refuses what it cannot take, naming its format;
/// 4. [`end`](GeometrySink::end), which returns the bytes.
///
/// Each call may fail: with the budget's typed [`LimitExceeded`](crate::core::budget::LimitExceeded)
/// (memory, the deadline) or the format's own error. The bytes depend only
/// on what was fed, in order.
pub trait GeometrySink {
    /// The format's name, for refusals.
    fn format(&self) -> &'static str;

    /// Whether the sink needs a first pass over the pieces
    /// ([`survey`](GeometrySink::survey)) before [`begin`](GeometrySink::begin).
    fn surveys(&self) -> bool {
        false
    }

    /// Takes in one piece of the first pass (positions and colours only;
    /// nothing is written).
    fn survey(&mut self, _piece: &Piece<'_>) -> Result<(), ExportError> {
        Ok(())
    }

    /// Starts the output with the model's metadata: charges what it will
    /// need and refuses, by limit name, before allocating it.
    fn begin(&mut self, meta: &ExportMeta, budget: &mut Budget) -> Result<(), ExportError>;

    /// Takes one piece of the flat model (a prototype placed by a map, or a
    /// whole mesh), in the order of the merged meshes.
    fn piece(&mut self, _piece: &Piece<'_>, _budget: &mut Budget) -> Result<(), ExportError> {
        Err(refused(self.format(), "pieces of a model streamed"))
    }

    /// Takes one mesh, drawn as `drawn` says, and numbers it.
    fn mesh(&mut self, _mesh: NamedMesh, _drawn: Drawn, _budget: &mut Budget) -> Result<MeshId, ExportError> {
        Err(refused(self.format(), "meshes"))
    }

    /// Places mesh `mesh` (given as [`Drawn::Instanced`]) once more.
    fn place(&mut self, _mesh: MeshId, _at: &InstanceData, _budget: &mut Budget) -> Result<(), ExportError> {
        Err(refused(self.format(), "placed instances"))
    }

    /// Finishes the output and returns its bytes.
    fn end(self: Box<Self>, budget: &mut Budget) -> Result<Vec<u8>, ExportError>;
}

/// Makes a format's sink for one request, with the request's format
/// options (the descriptor's [`Writer::Sink`](super::Writer::Sink)).
pub type MakeSink = fn(&ExportOptions) -> Box<dyn GeometrySink>;

/// The refusal of a sink fed geometry before [`GeometrySink::begin`] (a
/// driver's bug, not the request's).
pub(crate) fn not_begun(format: &'static str) -> ExportError {
    ExportError::InvalidOptions { format, detail: "geometry fed before the output began".into() }
}

/// The refusal of a sink fed what its format does not take: a server
/// error (the route and the sink disagree), named by format.
fn refused(format: &'static str, what: &str) -> ExportError {
    ExportError::InvalidOptions { format, detail: format!("this writer takes no {what}") }
}

/// A flat format's sink: collects plain meshes and writes them all in
/// [`end`](GeometrySink::end) with the format's [`WriteMeshes`] writer
/// (STL, 3MF, UniGrafix, usdz, plain and compact glTF, strips of meshes).
/// Those formats write whole-file structures (a vertex table, a zip
/// directory) from every mesh at once, so this sink holds the meshes; the
/// streaming formats implement the trait themselves.
pub(crate) struct FlatSink {
    format: &'static str,
    write: WriteMeshes,
    meta: ExportMeta,
    options: ExportOptions,
    meshes: Vec<NamedMesh>,
}

impl FlatSink {
    /// A sink writing with `write` (the writer of the format `format`) and
    /// the request's format options.
    pub fn new(format: &'static str, write: WriteMeshes, options: ExportOptions) -> FlatSink {
        FlatSink { format, write, meta: ExportMeta::default(), options, meshes: Vec::new() }
    }
}

impl GeometrySink for FlatSink {
    fn format(&self) -> &'static str {
        self.format
    }

    fn begin(&mut self, meta: &ExportMeta, _budget: &mut Budget) -> Result<(), ExportError> {
        self.meta = meta.clone();
        Ok(())
    }

    fn mesh(&mut self, mesh: NamedMesh, drawn: Drawn, _budget: &mut Budget) -> Result<MeshId, ExportError> {
        if drawn != Drawn::Plain {
            return Err(refused(self.format, "instanced meshes"));
        }
        self.meshes.push(mesh);
        Ok(MeshId(self.meshes.len() - 1))
    }

    fn end(self: Box<Self>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
        (self.write)(&self.meshes, &self.meta, &self.options, budget)
    }
}
