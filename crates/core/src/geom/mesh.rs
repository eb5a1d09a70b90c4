//! Indexed triangle meshes, the common input of every exporter.

/// An indexed triangle mesh. Triangles are counter-clockwise seen from
/// outside (right-handed), so the winding-derived normal points outward.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<[f32; 3]>,
    /// Unit vertex normals, one per position.
    pub normals: Vec<[f32; 3]>,
    /// Linear RGBA8 colours, one per position.
    pub colours: Vec<[u8; 4]>,
    /// Three indices per triangle.
    pub indices: Vec<u32>,
}

impl Mesh {
    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// The colour of triangle `k`: its first corner's (`None` past the end
    /// or without colours). A 3MF base material colours a triangle evenly,
    /// and a primitive's corners agree anyway; a swept line's gradient
    /// changes from ring to ring.
    pub fn triangle_colour(&self, k: usize) -> Option<[u8; 4]> {
        self.indices.get(3 * k).and_then(|&i| self.colours.get(i as usize)).copied()
    }

    /// Bytes this mesh's buffers occupy (for the memory budget).
    pub fn byte_size(&self) -> u64 {
        (self.positions.len() * 12 + self.normals.len() * 12 + self.colours.len() * 4 + self.indices.len() * 4) as u64
    }
}

/// A mesh with a name (the primitive kind, or "model" for a merged mesh).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct NamedMesh {
    /// The name written to the output (glTF mesh/node name, STL solid name).
    pub name: String,
    /// The geometry.
    pub mesh: Mesh,
}

/// Bytes of mesh buffers for `vertices` vertices and `triangles` triangles
/// (position 12 + normal 12 + colour 4 per vertex, 12 per triangle).
pub fn mesh_bytes(vertices: u64, triangles: u64) -> u64 {
    vertices.saturating_mul(28).saturating_add(triangles.saturating_mul(12))
}
