//! A half-edge mesh of triangles: the one connectivity structure every
//! modifier works on (Haglund 2009 §2.1.1).
//!
//! Haglund stores `next`, `face`, `vert` and `pair` per half-edge. For a
//! mesh of triangles three of those are implicit, which halves the memory
//! and removes a class of dangling-index bugs: half-edge `h` belongs to face
//! `h / 3`, its `next` is the following corner of that face, and it runs from
//! corner `h % 3` to the next corner. Only `pair` is stored. It is found in
//! O(n) through a hash of directed edges (the thesis's "direct" pairing,
//! L415), not the O(n²) "sloppy" search.
//!
//! Input that no half-edge structure can hold is rejected with a typed
//! [`HalfEdgeError`]: a directed edge used twice (three or more faces on an
//! edge, or two faces wound inconsistently), a triangle with a repeated
//! corner, or an index out of range. Open edges (boundaries) are allowed and
//! reported by [`HalfEdgeMesh::boundary_edges`]; vertices whose fan is not a
//! single disc (a "bow tie") are reported by [`HalfEdgeMesh::nonmanifold_vertices`].

use super::STOP_EVERY;
use glam::DVec3;
use std::collections::HashMap;

/// Marks a half-edge without an opposite (a boundary edge).
pub const NO_PAIR: u32 = u32::MAX;

/// Why indexed triangles cannot become a half-edge mesh.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HalfEdgeError {
    /// A triangle names a vertex that does not exist.
    #[error("triangle {triangle} names vertex {index}, but there are only {vertices}")]
    IndexOutOfRange {
        /// The triangle.
        triangle: usize,
        /// The bad index.
        index: u32,
        /// Number of vertices.
        vertices: usize,
    },
    /// A triangle repeats a corner, so it has no area and no orientation.
    #[error("triangle {triangle} is degenerate (repeated vertex {vertex})")]
    Degenerate {
        /// The triangle.
        triangle: usize,
        /// The repeated vertex.
        vertex: u32,
    },
    /// A directed edge occurs twice: more than two faces meet at the edge, or
    /// two neighbours are wound in opposite directions.
    #[error("non-manifold or inconsistently oriented edge {from}->{to}")]
    NonManifoldEdge {
        /// Start vertex.
        from: u32,
        /// End vertex.
        to: u32,
    },
    /// The caller's `stop` callback asked to give up (its deadline passed).
    #[error("stopped before the mesh was built")]
    Stopped,
    /// The mesh is larger than 32-bit half-edge indices can address.
    #[error("mesh too large for a half-edge structure ({triangles} triangles)")]
    TooLarge {
        /// Triangle count.
        triangles: usize,
    },
}

/// A triangle mesh with half-edge connectivity. Triangles are counter-clockwise
/// seen from outside, like every [`Prototype`](super::primitives::Prototype).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HalfEdgeMesh {
    /// Vertex positions (f64, so stacked modifiers do not accumulate f32 error).
    pub positions: Vec<DVec3>,
    /// Triangle corners; half-edge `3f + k` runs from `tris[f][k]` to `tris[f][(k + 1) % 3]`.
    tris: Vec<[u32; 3]>,
    /// The opposite half-edge of each half-edge, or [`NO_PAIR`] on a boundary.
    pair: Vec<u32>,
    /// One outgoing half-edge per vertex (a boundary one if the vertex has any), or [`NO_PAIR`] if unused.
    out: Vec<u32>,
}

/// Bytes a half-edge mesh of `v` vertices and `f` triangles holds (for the memory budget).
pub(crate) fn halfedge_bytes(v: u64, f: u64) -> u64 {
    v.saturating_mul(24 + 4).saturating_add(f.saturating_mul(12 + 12))
}

impl HalfEdgeMesh {
    /// Builds the structure from positions and CCW triangles in O(n).
    pub fn new(positions: Vec<DVec3>, tris: Vec<[u32; 3]>) -> Result<HalfEdgeMesh, HalfEdgeError> {
        Self::new_until(positions, tris, &|| false)
    }

    /// [`HalfEdgeMesh::new`] that asks `stop` every [`STOP_EVERY`] triangles
    /// whether to give up ([`HalfEdgeError::Stopped`]): building the edge map
    /// of a mesh of millions of triangles takes seconds, longer than a
    /// request's deadline may allow.
    pub(crate) fn new_until(positions: Vec<DVec3>, tris: Vec<[u32; 3]>, stop: &dyn Fn() -> bool) -> Result<HalfEdgeMesh, HalfEdgeError> {
        if tris.len() >= (u32::MAX / 3) as usize || positions.len() >= u32::MAX as usize {
            return Err(HalfEdgeError::TooLarge { triangles: tris.len() });
        }
        // foldhash: only inserted and looked up, never iterated.
        let mut edges: HashMap<(u32, u32), u32, foldhash::fast::FixedState> = HashMap::with_capacity_and_hasher(tris.len() * 3, foldhash::fast::FixedState::default());
        for (f, t) in tris.iter().enumerate() {
            if f % STOP_EVERY == STOP_EVERY - 1 && stop() {
                return Err(HalfEdgeError::Stopped);
            }
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                if a as usize >= positions.len() {
                    return Err(HalfEdgeError::IndexOutOfRange { triangle: f, index: a, vertices: positions.len() });
                }
                if a == b {
                    return Err(HalfEdgeError::Degenerate { triangle: f, vertex: a });
                }
                if edges.insert((a, b), (3 * f + k) as u32).is_some() {
                    return Err(HalfEdgeError::NonManifoldEdge { from: a, to: b });
                }
            }
        }
        let mut pair = vec![NO_PAIR; tris.len() * 3];
        let mut out = vec![NO_PAIR; positions.len()];
        for (f, t) in tris.iter().enumerate() {
            if f % STOP_EVERY == STOP_EVERY - 1 && stop() {
                return Err(HalfEdgeError::Stopped);
            }
            for k in 0..3 {
                let h = 3 * f + k;
                let (a, b) = (t[k], t[(k + 1) % 3]);
                pair[h] = edges.get(&(b, a)).copied().unwrap_or(NO_PAIR);
                // Prefer a boundary half-edge as the vertex's start, so fan walks cover open fans.
                let slot = &mut out[a as usize];
                if *slot == NO_PAIR || pair[h] == NO_PAIR {
                    *slot = h as u32;
                }
            }
        }
        Ok(HalfEdgeMesh { positions, tris, pair, out })
    }

    /// Builds from f32 positions and indices (a prototype or mesh), welding
    /// vertices at bit-identical positions first: flat-shaded prototypes repeat
    /// each corner once per face, and the connectivity lives in the shared positions.
    pub fn from_indexed(positions: &[[f32; 3]], indices: &[u32]) -> Result<HalfEdgeMesh, HalfEdgeError> {
        let (distinct, remap) = super::weld::weld_by(positions.iter().copied(), super::weld::f32_key);
        let welded: Vec<DVec3> = distinct.iter().map(|p| DVec3::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]))).collect();
        let mut tris = Vec::with_capacity(indices.len() / 3);
        for (f, t) in indices.chunks_exact(3).enumerate() {
            let mut c = [0u32; 3];
            for k in 0..3 {
                c[k] = *remap.get(t[k] as usize).ok_or(HalfEdgeError::IndexOutOfRange {
                    triangle: f,
                    index: t[k],
                    vertices: positions.len(),
                })?;
            }
            tris.push(c);
        }
        HalfEdgeMesh::new(welded, tris)
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub fn face_count(&self) -> usize {
        self.tris.len()
    }

    /// Number of half-edges (three per triangle).
    pub(crate) fn halfedge_count(&self) -> usize {
        self.pair.len()
    }

    /// Number of undirected edges (paired half-edges count once).
    pub(crate) fn edge_count(&self) -> usize {
        self.pair.iter().enumerate().filter(|&(h, &p)| p == NO_PAIR || (h as u32) < p).count()
    }

    /// V − E + F: 2 for a closed genus-0 surface.
    pub fn euler_characteristic(&self) -> i64 {
        self.vertex_count() as i64 - self.edge_count() as i64 + self.face_count() as i64
    }

    /// The triangles' corners.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.tris
    }

    /// The face half-edge `h` belongs to.
    pub fn face(h: u32) -> u32 {
        h / 3
    }

    /// The next half-edge around the same face.
    pub fn next(h: u32) -> u32 {
        h - h % 3 + (h % 3 + 1) % 3
    }

    /// The previous half-edge around the same face.
    pub fn prev(h: u32) -> u32 {
        h - h % 3 + (h % 3 + 2) % 3
    }

    /// The opposite half-edge, or [`NO_PAIR`] on a boundary.
    pub fn pair(&self, h: u32) -> u32 {
        self.pair[h as usize]
    }

    /// The vertex half-edge `h` starts at.
    pub fn tail(&self, h: u32) -> u32 {
        self.tris[(h / 3) as usize][(h % 3) as usize]
    }

    /// The vertex half-edge `h` ends at (Haglund 2009's `vert`).
    pub fn head(&self, h: u32) -> u32 {
        self.tail(Self::next(h))
    }

    /// One outgoing half-edge of vertex `v`, or [`NO_PAIR`] if no face uses it.
    pub(crate) fn outgoing(&self, v: u32) -> u32 {
        self.out.get(v as usize).copied().unwrap_or(NO_PAIR)
    }

    /// Half-edges without an opposite (open edges); empty for a closed mesh.
    pub fn boundary_edges(&self) -> Vec<u32> {
        (0..self.pair.len() as u32).filter(|&h| self.pair[h as usize] == NO_PAIR).collect()
    }

    /// True when every edge has two faces.
    pub fn is_closed(&self) -> bool {
        self.pair.iter().all(|&p| p != NO_PAIR)
    }

    /// The outgoing half-edges of `v` in fan order, walking `pair(prev(h))`
    /// from [`Self::outgoing`]. On a boundary vertex the walk starts at the
    /// boundary and stops at the other side.
    pub fn fan(&self, v: u32) -> Vec<u32> {
        let start = self.outgoing(v);
        let mut fan = Vec::new();
        if start == NO_PAIR {
            return fan;
        }
        let mut h = start;
        loop {
            fan.push(h);
            let back = self.pair(Self::prev(h));
            if back == NO_PAIR || back == start || fan.len() > self.pair.len() {
                break;
            }
            h = back;
        }
        fan
    }

    /// The neighbours of `v` in fan order (the heads of its outgoing half-edges,
    /// plus the far end of the last face on a boundary).
    pub fn neighbours(&self, v: u32) -> Vec<u32> {
        let fan = self.fan(v);
        let mut n: Vec<u32> = fan.iter().map(|&h| self.head(h)).collect();
        if let Some(&last) = fan.last() {
            if self.pair(Self::prev(last)) == NO_PAIR {
                n.push(self.tail(Self::prev(last)));
            }
        }
        n
    }

    /// True when `v` lies on an open edge.
    pub(crate) fn is_boundary_vertex(&self, v: u32) -> bool {
        let h = self.outgoing(v);
        h != NO_PAIR && self.pair(h) == NO_PAIR
    }

    /// Vertices whose faces do not form one fan (several cones meeting at a
    /// point): the half-edge walk around them misses some of their faces.
    pub fn nonmanifold_vertices(&self) -> Vec<u32> {
        let mut uses = vec![0u32; self.positions.len()];
        for t in &self.tris {
            for &c in t {
                uses[c as usize] += 1;
            }
        }
        (0..self.positions.len() as u32).filter(|&v| uses[v as usize] as usize != self.fan(v).len()).collect()
    }

    /// The unit normal of face `f` (zero for a zero-area face).
    pub(crate) fn face_normal(&self, f: usize) -> DVec3 {
        let [a, b, c] = self.corners(f);
        (b - a).cross(c - a).normalize_or_zero()
    }

    /// The three corner positions of face `f`.
    pub fn corners(&self, f: usize) -> [DVec3; 3] {
        self.tris[f].map(|i| self.positions[i as usize])
    }

    /// Area-weighted vertex normals (unit, or zero for an unused vertex).
    pub(crate) fn vertex_normals(&self) -> Vec<DVec3> {
        let mut n = vec![DVec3::ZERO; self.positions.len()];
        for (f, t) in self.tris.iter().enumerate() {
            let [a, b, c] = self.corners(f);
            let w = (b - a).cross(c - a);
            for &i in t {
                n[i as usize] += w;
            }
        }
        n.into_iter().map(DVec3::normalize_or_zero).collect()
    }

    /// Signed volume (positive for a closed outward-oriented mesh).
    pub fn signed_volume(&self) -> f64 {
        (0..self.tris.len())
            .map(|f| {
                let [a, b, c] = self.corners(f);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    /// Consumes the mesh, returning its positions and triangles.
    pub fn into_parts(self) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        (self.positions, self.tris)
    }

    /// Checks the structure's invariants (the ones every operator must keep on
    /// a closed mesh, after Haglund 2009 §2.1.1): every pair is
    /// mutual and joins the same two vertices reversed, and `next³` is the identity.
    #[cfg(test)]
    pub(crate) fn check_invariants(&self) -> bool {
        (0..self.pair.len() as u32).all(|h| {
            let p = self.pair(h);
            let paired = p == NO_PAIR || (self.pair(p) == h && self.tail(p) == self.head(h) && self.head(p) == self.tail(h));
            paired && Self::next(Self::next(Self::next(h))) == h
        })
    }

    /// A flat-shaded prototype: three vertices per face carrying the face
    /// normal, positions rounded to f32 once per vertex so shared corners stay
    /// bit-identical (welding by position closes it again).
    pub(crate) fn to_prototype(&self) -> super::primitives::Prototype {
        flat_prototype(&self.positions, &self.tris)
    }
}

/// A flat-shaded prototype of any indexed triangles (no manifold check: UniGrafix
/// models may share edges between touching parts): three vertices per face
/// with its normal, positions rounded to f32 once per source vertex.
pub(crate) fn flat_prototype(positions: &[DVec3], tris: &[[u32; 3]]) -> super::primitives::Prototype {
    let never = || false;
    flat_prototype_until(positions, tris, &never).unwrap_or_default()
}

/// [`flat_prototype`] that asks `stop` every [`STOP_EVERY`] triangles
/// whether to give up (`None`), for imported models of millions of faces.
pub(crate) fn flat_prototype_until(positions: &[DVec3], tris: &[[u32; 3]], stop: &dyn Fn() -> bool) -> Option<super::primitives::Prototype> {
    let pos32: Vec<[f32; 3]> = positions.iter().map(|p| p.as_vec3().to_array()).collect();
    let mut proto = super::primitives::Prototype {
        positions: Vec::with_capacity(tris.len() * 3),
        normals: Vec::with_capacity(tris.len() * 3),
        indices: Vec::with_capacity(tris.len() * 3),
    };
    for (f, t) in tris.iter().enumerate() {
        if f % STOP_EVERY == STOP_EVERY - 1 && stop() {
            return None;
        }
        let Some(c) = t.iter().map(|&i| positions.get(i as usize).copied()).collect::<Option<Vec<DVec3>>>() else { continue };
        let n = (c[1] - c[0]).cross(c[2] - c[0]).normalize_or(DVec3::Z).as_vec3().to_array();
        for &i in t {
            proto.indices.push(proto.positions.len() as u32);
            proto.positions.push(pos32[i as usize]);
            proto.normals.push(n);
        }
    }
    Some(proto)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::primitives::tessellate;
    use crate::core::PrimitiveKind;

    fn he(kind: PrimitiveKind) -> HalfEdgeMesh {
        let p = tessellate(kind, 16);
        HalfEdgeMesh::from_indexed(&p.positions, &p.indices).expect("primitive is manifold")
    }

    #[test]
    fn platonic_counts() {
        for (kind, v, e, f) in [
            (PrimitiveKind::Tetrahedron, 4, 6, 4),
            (PrimitiveKind::Box, 8, 18, 12),
            (PrimitiveKind::Octahedron, 6, 12, 8),
            (PrimitiveKind::Icosahedron, 12, 30, 20),
        ] {
            let m = he(kind);
            assert_eq!((m.vertex_count(), m.edge_count(), m.face_count()), (v, e, f), "{kind:?}");
            assert_eq!(m.halfedge_count(), 3 * f);
            assert!(m.is_closed() && m.check_invariants());
            assert_eq!(m.euler_characteristic(), 2);
            assert!(m.nonmanifold_vertices().is_empty());
        }
    }

    #[test]
    fn fans_and_valence() {
        let m = he(PrimitiveKind::Icosahedron);
        for v in 0..12 {
            assert_eq!(m.fan(v).len(), 5);
            assert_eq!(m.neighbours(v).len(), 5);
        }
        let t = he(PrimitiveKind::Torus);
        assert_eq!(t.euler_characteristic(), 0);
    }

    #[test]
    fn rejects_bad_input() {
        let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z, DVec3::ONE];
        assert!(matches!(HalfEdgeMesh::new(p.clone(), vec![[0, 1, 2], [0, 1, 3]]), Err(HalfEdgeError::NonManifoldEdge { from: 0, to: 1 })));
        assert!(matches!(HalfEdgeMesh::new(p.clone(), vec![[0, 1, 1]]), Err(HalfEdgeError::Degenerate { .. })));
        assert!(matches!(HalfEdgeMesh::new(p.clone(), vec![[0, 1, 9]]), Err(HalfEdgeError::IndexOutOfRange { .. })));
        // Three faces on edge 0-1: two of them use the same directed edge.
        assert!(HalfEdgeMesh::new(p.clone(), vec![[0, 1, 2], [1, 0, 3], [1, 0, 4]]).is_err());
        // An open single triangle is accepted and reported.
        let open = HalfEdgeMesh::new(p.clone(), vec![[0, 1, 2]]).expect("open is fine");
        assert_eq!(open.boundary_edges().len(), 3);
        assert!(!open.is_closed());
        assert_eq!(open.neighbours(0), vec![1, 2]);
        // Bow tie: two triangles sharing only vertex 0.
        let bow = HalfEdgeMesh::new(p, vec![[0, 1, 2], [0, 3, 4]]).expect("edges are fine");
        assert_eq!(bow.nonmanifold_vertices(), vec![0]);
    }
}
