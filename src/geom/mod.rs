//! Geometry: tessellation of the built-in primitives and turning a
//! [`Scene`](crate::eval::scene::Scene) of instances into indexed meshes.

pub mod halfedge;
pub mod hull;
pub mod isosurface;
pub mod mesh;
pub mod meshing;
pub mod modifiers;
pub mod normalize;
pub mod polyhedra;
pub mod primitives;
pub mod strip;
pub mod sweep;

pub use mesh::{Mesh, NamedMesh};
pub use meshing::{build_meshes, MeshLayout};

/// Default tessellation detail (segments around a round primitive).
pub const DEFAULT_DETAIL: u32 = 16;
/// Smallest accepted detail.
pub const MIN_DETAIL: u32 = 3;
/// Largest accepted detail (a sphere at 256 has ~131k triangles).
pub const MAX_DETAIL: u32 = 256;
