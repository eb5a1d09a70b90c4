//! Scene → meshes (stub: being implemented).

use super::NamedMesh;
use crate::eval::budget::{Budget, LimitExceeded};
use crate::eval::scene::Scene;

/// How instances are grouped into meshes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum MeshLayout {
    /// One mesh holding every instance.
    #[default]
    Merged,
    /// One mesh per primitive kind present.
    PerKind,
}

/// Transforms every instance's prototype into world space and merges them,
/// reserving the buffers' bytes in `budget` before allocating.
pub fn build_meshes(_scene: &Scene, _detail: u32, _layout: MeshLayout, _budget: &mut Budget) -> Result<Vec<NamedMesh>, LimitExceeded> {
    Ok(Vec::new())
}

/// Bytes of mesh buffers for `vertices` vertices and `triangles` triangles
/// (position 12 + normal 12 + colour 4 per vertex, 12 per triangle).
pub fn mesh_bytes(vertices: u64, triangles: u64) -> u64 {
    vertices.saturating_mul(28).saturating_add(triangles.saturating_mul(12))
}
