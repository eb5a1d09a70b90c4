//! A closed, outward solid with a colour per triangle: what a hierarchy's
//! leaves and objects are while they are united (`subtree`, `rigid`).

use crate::geom::halfedge::HalfEdgeMesh;
use glam::DVec3;

/// A closed, outward solid in an object's frame, with each triangle's colour.
#[derive(Debug, Clone, Default)]
pub(super) struct Solid {
    /// Shared positions.
    pub positions: Vec<DVec3>,
    /// CCW (outward) triangles.
    pub tris: Vec<[u32; 3]>,
    /// Linear RGBA8 of each triangle.
    pub colours: Vec<[u8; 4]>,
}

impl Solid {
    /// Bytes it holds while it waits to be placed by its parents.
    pub(super) fn bytes(&self) -> u64 {
        (self.positions.len() * 24 + self.tris.len() * 16) as u64
    }
}

/// A leaf shape's prototype as one closed, outward solid (welded by exact
/// position), or `None` when it is open or pinched.
pub(super) fn leaf_solid(p: &crate::geom::primitives::Prototype) -> Option<Solid> {
    let (distinct, remap) = crate::geom::weld::weld_by(p.positions.iter().copied(), crate::geom::weld::f32_key);
    let positions: Vec<DVec3> = distinct.iter().map(|q| glam::Vec3::from_array(*q).as_dvec3()).collect();
    let tris: Vec<[u32; 3]> = crate::geom::weld::welded_triangles(&p.indices, &remap).map(|(_, t)| t).collect();
    let m = HalfEdgeMesh::new(positions, tris).ok().filter(|m| m.is_closed() && m.nonmanifold_vertices().is_empty())?;
    let outward = m.signed_volume() > 0.0;
    let (positions, tris) = m.into_parts();
    let tris = if outward { tris } else { tris.into_iter().map(|t| [t[0], t[2], t[1]]).collect() };
    Some(Solid { colours: vec![super::PLAIN; tris.len()], positions, tris })
}
