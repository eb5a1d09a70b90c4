//! glTF 2.0 export (stub: being implemented).

use super::{ExportError, ExportMeta};
use crate::eval::budget::Budget;
use crate::geom::NamedMesh;

/// Writes a binary glTF (.glb).
pub fn write_glb(_meshes: &[NamedMesh], _meta: &ExportMeta, _budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    Ok(Vec::new())
}

/// Writes a JSON glTF with the buffer embedded as a base64 data URI.
pub fn write_gltf(_meshes: &[NamedMesh], _meta: &ExportMeta, _budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    Ok(Vec::new())
}
