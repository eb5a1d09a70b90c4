//! The geometry kernel: indexed meshes, tessellation of the built-in
//! primitives, polyhedra, half-edge meshes, hulls, isosurfaces, mesh
//! modifiers, swept tubes and triangle strips. Pure functions of their
//! inputs: it knows nothing about languages, scenes or formats.

pub mod assembly;
pub mod curves;
pub mod halfedge;
pub(crate) mod hull;
pub mod isosurface;
pub mod mesh;
pub mod mitre;
pub mod modifiers;
pub mod normalize;
pub mod polyhedra;
pub mod primitives;
pub mod strip;
pub mod sweep;
pub mod testing;
pub mod weld;

pub use mesh::{Mesh, NamedMesh};

/// How many items a long loop handles between two calls of its `stop`
/// callback (the kernel's way to keep a caller's deadline without knowing
/// about budgets): often enough that a deadline is kept within
/// milliseconds, rarely enough that asking the clock costs nothing
/// measurable.
pub const STOP_EVERY: usize = 1 << 16;

/// Default tessellation detail (segments around a round primitive).
pub const DEFAULT_DETAIL: u32 = 16;
/// Smallest accepted detail.
pub const MIN_DETAIL: u32 = 3;
/// Largest accepted detail (a sphere at 256 has ~131k triangles).
pub const MAX_DETAIL: u32 = 256;
