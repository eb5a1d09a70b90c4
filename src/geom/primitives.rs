//! Tessellation of the built-in primitives (stub: being implemented).

use crate::lang::ir::PrimitiveKind;

/// A primitive's tessellated prototype in its unit local space.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Prototype {
    /// Local positions.
    pub positions: Vec<[f32; 3]>,
    /// Unit normals.
    pub normals: Vec<[f32; 3]>,
    /// CCW-outward triangles.
    pub indices: Vec<u32>,
}

/// Tessellates `kind` at `detail` (already clamped to MIN_DETAIL..=MAX_DETAIL).
pub fn tessellate(_kind: PrimitiveKind, _detail: u32) -> Prototype {
    Prototype::default()
}

/// Triangle count of `tessellate(kind, detail)`, computed without allocating.
pub fn triangle_count(_kind: PrimitiveKind, _detail: u32) -> u64 {
    12
}

/// Vertex count of `tessellate(kind, detail)`, computed without allocating.
pub fn vertex_count(_kind: PrimitiveKind, _detail: u32) -> u64 {
    24
}
