//! Spikeify (Haglund 2009 §4.2): every face becomes a spike.

use crate::geom::halfedge::HalfEdgeMesh;
use glam::DVec3;

/// Replaces each triangle by the three sides of a tetrahedron standing on it,
/// apex `height` above the centroid along the face normal. The base is left
/// out so the result stays a closed manifold (Haglund's "substitute every
/// face with a tetrahedron" read as three sides, not four): F′ = 3F, V′ = V + F.
pub(super) fn spikeify(m: &HalfEdgeMesh, height: f64) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut positions = m.positions.clone();
    positions.reserve(m.face_count());
    let mut tris = Vec::with_capacity(m.face_count() * 3);
    for (f, t) in m.triangles().iter().enumerate() {
        let [a, b, c] = m.corners(f);
        let apex = (a + b + c) / 3.0 + m.face_normal(f) * height;
        let s = positions.len() as u32;
        positions.push(apex);
        tris.push([t[0], t[1], s]);
        tris.push([t[1], t[2], s]);
        tris.push([t[2], t[0], s]);
    }
    (positions, tris)
}
