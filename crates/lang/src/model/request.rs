//! What a front end is asked for: the parts of a render request that shape
//! the model (seed, parameters, detail, what to do at a limit), what the
//! stages after it will need, and nothing about output formats.

use crate::core::{OnLimit, ParamValue};
use std::collections::BTreeMap;
use std::path::Path;

/// The cost of one output vertex and one output triangle in later stages
/// (mesh buffers and encoded output). Front ends charge it to the memory
/// budget as geometry is made, so the memory limit binds (or truncates)
/// during evaluation instead of after a model too big to mesh is built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Downstream {
    /// Bytes per vertex.
    pub per_vertex: u64,
    /// Bytes per triangle.
    pub per_triangle: u64,
    /// Bytes per GPU instance when the output writes a mesh placed more
    /// than once only once (instanced glTF), so the placements after a
    /// mesh's first are charged as instances, not as triangles
    /// ([`Tally`](crate::model::instancing::Tally)); `None` when every
    /// placement is tessellated.
    pub per_instance: Option<u64>,
}

impl Downstream {
    /// Bytes for `v` vertices and `t` triangles.
    pub fn bytes(&self, v: u64, t: u64) -> u64 {
        v.saturating_mul(self.per_vertex).saturating_add(t.saturating_mul(self.per_triangle))
    }
}

/// One front end call: everything besides the source that decides the model.
#[derive(Debug, Clone, Copy)]
pub struct BuildRequest<'a> {
    /// The request's seed; `None` lets the language choose (its own seed
    /// directive, else 0).
    pub seed: Option<u64>,
    /// Values for the source's parameters.
    pub params: &'a BTreeMap<String, ParamValue>,
    /// Tessellation detail, for counting triangles against the budget.
    pub detail: u32,
    /// Fail or truncate at a limit.
    pub on_limit: OnLimit,
    /// What later stages need per vertex and triangle (see [`Downstream`]).
    pub downstream: Downstream,
    /// Whether to build an instancing [`Hierarchy`](crate::model::Hierarchy)
    /// where the language can (else flat geometry). This is all a front end
    /// learns of the route: the pipeline, which knows it, decides this from
    /// the route and [`FrontEnd::own_hierarchy_geometry`](crate::FrontEnd::own_hierarchy_geometry),
    /// and charges a hierarchy's size or expansion as the route writes it
    /// (the front end charges only what it makes while building it).
    pub hierarchy: bool,
    /// Whether the output plays animation (plain glTF): a Structure Synth
    /// movie then keeps every frame instead of showing the first.
    pub animated: bool,
    /// The folder a Structure Synth JavaScript script's `Builder.load` reads
    /// from; `None` (the service) loads built-in library grammars only.
    pub script_dir: Option<&'a Path>,
    /// Build only this picture of a JavaScript movie (see
    /// `RenderRequest::frame`); `None` builds every picture.
    pub frame: Option<u32>,
    /// Named files sent beside the source (a vlab object's view, animation,
    /// colour map and `#include`d files, for `language: "cpfg"`): a front
    /// end resolves the names a source gives only against these, never the disk.
    pub files: &'a std::collections::BTreeMap<String, Vec<u8>>,
    /// The side in pixels of the picture the output is (`png`'s `size`),
    /// `None` for every other output. Only a language whose evaluation
    /// stops at a size in pixels reads it (Context Free ends recursion
    /// below a minimum size in pixels and frames its border in pixels, so
    /// its picture at 300 px is not its picture at 500 px scaled), as
    /// `detail` is read by those that tessellate; it names no format.
    pub canvas: Option<u32>,
    /// Whether the output is a picture of the model (`png`, `svg`): a
    /// language that makes a 2D [`Drawing`](crate::model::drawing::Drawing)
    /// then need not build its 3D geometry, which no stage reads (Context
    /// Free's tiles would cost a tenth of its picture's time). Like
    /// `canvas`, it names no format.
    pub picture_only: bool,
    /// Whether the model is for a print (`print=true`). A front end whose
    /// hierarchy draws the model differently from its flat geometry
    /// (Context Free's reliefs, where each tile's thickness follows its
    /// size and children stand on their parents) keeps its flat model for
    /// a print, which must unite into one shell. Like `canvas`, it names no format.
    pub print: bool,
}
