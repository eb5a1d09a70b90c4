//! STL export (stub: being implemented).

use super::ExportError;
use crate::eval::budget::Budget;
use crate::geom::NamedMesh;

/// Writes binary STL.
pub fn write_binary(_meshes: &[NamedMesh], _budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    Ok(Vec::new())
}

/// Writes ASCII STL.
pub fn write_ascii(_meshes: &[NamedMesh], _budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    Ok(Vec::new())
}
