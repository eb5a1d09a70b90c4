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

/// Whether the stages can use an instancing [`Hierarchy`](crate::model::Hierarchy).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HierarchyUse {
    /// Flat geometry only (STL, strips, printing, …).
    Never,
    /// A hierarchy where the language builds one cheaply (glTF: instanced or
    /// expanded), else flat geometry.
    Preferred,
    /// The output walks a hierarchy leaf by leaf and tessellates each leaf as
    /// it writes (flat `strips`, written in chunks), so it never needs the
    /// expanded scene: MDG's memoised derivations come as a hierarchy, charged
    /// as the flat geometry they stand for (every leaf a primitive, every
    /// triangle); other languages give flat geometry, as for [`HierarchyUse::Never`].
    Streamed,
    /// The output writes a hierarchy as it is (`format=scene`), so its size,
    /// not its expansion's, is what the limits charge; where the language
    /// builds none cheaply, flat geometry, as for [`HierarchyUse::Preferred`]
    /// (so a scene holds the same model as the flat formats).
    Required,
    /// A hierarchy where the language builds one, for printing, whose union
    /// works once per distinct subtree (`print::make_printable_hierarchy`)
    /// and falls back to the expansion; else flat geometry. The limits
    /// charge the expansion's leaves and triangles, as flat geometry.
    /// L-systems give theirs only when its expansion has more than
    /// [`EXACT_UNION_MAX_TRIANGLES`]: below, the flat route unites the
    /// turtle's mitred sweeps exactly, and the print is what it always was.
    Union,
}

/// Most triangles whose flat union the print stage tries exactly
/// (`print::EXACT_MAX_TRIANGLES` is this). Above it a flat model is fused
/// (sampled), so an L-system's hierarchy, whose capped segments are united
/// exactly once per distinct subtree, is offered instead (the Sierpinski
/// bush: one exact shell in about 5 s, where fusing cannot resolve its
/// tubes within the limits).
pub const EXACT_UNION_MAX_TRIANGLES: u64 = 64_000;

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
    /// Whether a hierarchy is wanted.
    pub hierarchy: HierarchyUse,
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
}
