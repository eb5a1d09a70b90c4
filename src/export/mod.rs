//! Exporters: meshes → bytes. They read meshes and scene metadata only; they never parse.

pub mod gltf;
pub mod stl;

use crate::eval::budget::{Budget, LimitExceeded};
use crate::geom::NamedMesh;

/// Output formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Format {
    /// Binary glTF 2.0 (.glb).
    Glb,
    /// glTF 2.0 JSON with the buffer embedded as a data URI (.gltf).
    Gltf,
    /// Binary STL.
    Stl,
    /// ASCII STL.
    StlAscii,
}

impl Format {
    /// Picks a format from an output file name's extension.
    pub fn from_extension(path: &std::path::Path) -> Option<Format> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "glb" => Some(Format::Glb),
            "gltf" => Some(Format::Gltf),
            "stl" => Some(Format::Stl),
            _ => None,
        }
    }

    /// The MIME type of the format.
    pub fn content_type(self) -> &'static str {
        match self {
            Format::Glb => "model/gltf-binary",
            Format::Gltf => "model/gltf+json",
            Format::Stl | Format::StlAscii => "model/stl",
        }
    }
}

/// Scene-level facts an exporter may record besides geometry.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ExportMeta {
    /// Background colour to record (glTF `extras`).
    pub background: Option<[f32; 4]>,
    /// Whether the model was cut short by a limit (recorded in glTF `extras`).
    pub truncated: bool,
}

/// Export failures.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The output would exceed the memory budget.
    #[error(transparent)]
    Limit(#[from] LimitExceeded),
    /// The model is too large for the format (e.g. glTF's 4 GiB buffer limit).
    #[error("model too large for {format}: {detail}")]
    TooLarge {
        /// The format's name.
        format: &'static str,
        /// What overflowed.
        detail: String,
    },
    /// A mesh handed to an exporter is malformed (index out of range,
    /// attribute arrays of different lengths, non-finite positions). Meshes
    /// from [`build_meshes`](crate::geom::build_meshes) never are; this guards
    /// library callers who build meshes themselves.
    #[error("invalid mesh {name:?}: {detail}")]
    InvalidMesh {
        /// The mesh's name.
        name: String,
        /// What is wrong with it.
        detail: String,
    },
    /// JSON serialisation failed.
    #[error("serialising glTF JSON: {0}")]
    Json(#[from] serde_json::Error),
}

/// Writes `meshes` in `format`, reserving the output size in `budget` first.
pub fn export(format: Format, meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    match format {
        Format::Glb => gltf::write_glb(meshes, meta, budget),
        Format::Gltf => gltf::write_gltf(meshes, meta, budget),
        Format::Stl => stl::write_binary(meshes, budget),
        Format::StlAscii => stl::write_ascii(meshes, budget),
    }
}

/// An upper bound on the encoded size of a model with this many vertices and
/// triangles in `format`, so the budget can be checked before encoding.
/// `estimated_size(format, 0, 0)` is the fixed per-file overhead.
pub fn estimated_size(format: Format, vertices: u64, triangles: u64) -> u64 {
    let (fixed, per_vertex, per_triangle) = match format {
        Format::Glb => (64 * 1024, 28, 12),
        // base64 inflates the buffer by 4/3.
        Format::Gltf => (64 * 1024, 38, 16),
        Format::Stl => (84, 0, 50),
        Format::StlAscii => (1024, 0, 300),
    };
    vertices
        .saturating_mul(per_vertex)
        .saturating_add(triangles.saturating_mul(per_triangle))
        .saturating_add(fixed)
}
