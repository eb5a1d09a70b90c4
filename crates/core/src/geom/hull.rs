//! 3D convex hull by incremental quickhull-style insertion.
//!
//! Written here rather than taken from a crate because the output must be
//! byte-identical for the same input (it is cached and compared) and the
//! degenerate inputs R. Wang's `ughull` lists ("Ughull — A 3D Convex Hull
//! Utility for the UniGrafix System", in Séquin (ed.) 1992) — fewer than four points,
//! all points on a line, all points in a plane — must come back as clear,
//! typed errors instead of a panic or an empty mesh. Points are inserted in
//! input order; each point outside the current hull removes the faces it
//! sees and is joined to their horizon. O(n·F), fine for the few thousand
//! points grammars produce; the budget bounds the rest.

use super::halfedge::{HalfEdgeError, HalfEdgeMesh};
use glam::DVec3;
use std::collections::HashSet;

/// Why a point set has no 3D hull.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub(crate) enum HullError {
    /// A coordinate is NaN or infinite.
    #[error("point {0} has a non-finite coordinate")]
    NonFinite(usize),
    /// Fewer than four distinct points.
    #[error("a 3D hull needs at least 4 distinct points, found {0}")]
    TooFewPoints(usize),
    /// Every point lies on one line.
    #[error("all points are collinear: the hull would be a segment")]
    Collinear,
    /// Every point lies in one plane.
    #[error("all points are coplanar: the hull would be a flat polygon")]
    Coplanar,
    /// The result failed the half-edge check (a numerical breakdown).
    #[error("hull is not a manifold: {0}")]
    Mesh(#[from] HalfEdgeError),
}

struct Face {
    v: [u32; 3],
    normal: DVec3,
    offset: f64,
    alive: bool,
}

fn face(p: &[DVec3], v: [u32; 3]) -> Face {
    let [a, b, c] = v.map(|i| p[i as usize]);
    let normal = (b - a).cross(c - a).normalize_or_zero();
    Face { v, normal, offset: normal.dot(a), alive: true }
}

/// The convex hull of `points` as a closed, outward-oriented triangle mesh
/// whose vertices are the hull's corners (interior and duplicate points are
/// dropped). Coplanar hull faces come out as several triangles.
pub(crate) fn convex_hull(points: &[DVec3]) -> Result<HalfEdgeMesh, HullError> {
    if let Some(i) = points.iter().position(|p| !p.is_finite()) {
        return Err(HullError::NonFinite(i));
    }
    // Exact duplicates first (stable: the first occurrence is kept).
    let mut seen = HashSet::with_capacity(points.len());
    let p: Vec<DVec3> = points.iter().copied().filter(|q| seen.insert(q.to_array().map(f64::to_bits))).collect();
    if p.len() < 4 {
        return Err(HullError::TooFewPoints(p.len()));
    }
    let extent = p.iter().fold(0.0f64, |m, q| m.max(q.abs().max_element())).max(f64::MIN_POSITIVE);
    let eps = 1e-9 * extent;
    // Initial tetrahedron: an extreme point, the farthest from it, the
    // farthest from their line, the farthest from their plane.
    let i0 = (0..p.len()).min_by(|&a, &b| p[a].x.total_cmp(&p[b].x)).unwrap_or(0);
    let far = |f: &dyn Fn(DVec3) -> f64| (0..p.len()).max_by(|&a, &b| f(p[a]).total_cmp(&f(p[b]))).unwrap_or(0);
    let i1 = far(&|q| q.distance(p[i0]));
    if p[i1].distance(p[i0]) <= eps {
        return Err(HullError::TooFewPoints(1));
    }
    let axis = (p[i1] - p[i0]).normalize();
    let off_line = |q: DVec3| (q - p[i0]).reject_from_normalized(axis).length();
    let i2 = far(&off_line);
    if off_line(p[i2]) <= eps {
        return Err(HullError::Collinear);
    }
    let n = (p[i1] - p[i0]).cross(p[i2] - p[i0]).normalize();
    let off_plane = |q: DVec3| (q - p[i0]).dot(n).abs();
    let i3 = far(&off_plane);
    if off_plane(p[i3]) <= eps {
        return Err(HullError::Coplanar);
    }
    let [a, b, c, d] = [i0, i1, i2, i3].map(|i| i as u32);
    let mut faces: Vec<Face> = if (p[i3] - p[i0]).dot(n) < 0.0 {
        vec![face(&p, [a, b, c]), face(&p, [a, c, d]), face(&p, [a, d, b]), face(&p, [b, d, c])]
    } else {
        vec![face(&p, [a, c, b]), face(&p, [a, b, d]), face(&p, [a, d, c]), face(&p, [b, c, d])]
    };
    for (i, q) in p.iter().enumerate() {
        if [i0, i1, i2, i3].contains(&i) {
            continue;
        }
        let visible: Vec<usize> = (0..faces.len()).filter(|&f| faces[f].alive && faces[f].normal.dot(*q) - faces[f].offset > eps).collect();
        if visible.is_empty() {
            continue;
        }
        let mut edges = HashSet::with_capacity(visible.len() * 3);
        for &f in &visible {
            let v = faces[f].v;
            for k in 0..3 {
                edges.insert((v[k], v[(k + 1) % 3]));
            }
        }
        let mut horizon: Vec<(u32, u32)> = Vec::new();
        for &f in &visible {
            faces[f].alive = false;
            let v = faces[f].v;
            for k in 0..3 {
                let (s, t) = (v[k], v[(k + 1) % 3]);
                if !edges.contains(&(t, s)) {
                    horizon.push((s, t));
                }
            }
        }
        for (s, t) in horizon {
            faces.push(face(&p, [s, t, i as u32]));
        }
        faces.retain(|f| f.alive);
    }
    // Keep only used vertices, in first-use order.
    let mut remap = vec![u32::MAX; p.len()];
    let mut positions = Vec::new();
    let mut tris = Vec::with_capacity(faces.len());
    for f in &faces {
        tris.push(f.v.map(|i| {
            let slot = &mut remap[i as usize];
            if *slot == u32::MAX {
                *slot = positions.len() as u32;
                positions.push(p[i as usize]);
            }
            *slot
        }));
    }
    Ok(HalfEdgeMesh::new(positions, tris)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_with_interior_points() {
        let mut pts = Vec::new();
        for x in [-1.0, 1.0] {
            for y in [-1.0, 1.0] {
                for z in [-1.0, 1.0] {
                    pts.push(DVec3::new(x, y, z));
                }
            }
        }
        pts.push(DVec3::ZERO);
        pts.push(DVec3::new(0.5, 0.2, -0.3));
        pts.push(DVec3::new(1.0, 0.0, 0.0)); // on a face
        let h = convex_hull(&pts).expect("cube");
        assert!(h.is_closed());
        assert_eq!(h.euler_characteristic(), 2);
        assert!((h.signed_volume() - 8.0).abs() < 1e-9, "{}", h.signed_volume());
        assert!(h.vertex_count() >= 8 && h.vertex_count() <= 9);
    }

    #[test]
    fn degenerate_inputs_are_clear_errors() {
        let e = |pts: &[DVec3]| convex_hull(pts).unwrap_err();
        assert_eq!(e(&[DVec3::ZERO, DVec3::X, DVec3::Y]), HullError::TooFewPoints(3));
        assert_eq!(e(&[DVec3::ZERO, DVec3::ZERO, DVec3::ZERO, DVec3::ZERO, DVec3::X]), HullError::TooFewPoints(2));
        assert_eq!(e(&[DVec3::ZERO, DVec3::X, DVec3::X * 2.0, DVec3::X * 3.0]), HullError::Collinear);
        assert_eq!(e(&[DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE.with_z(0.0), DVec3::new(3.0, 2.0, 0.0)]), HullError::Coplanar);
        assert_eq!(e(&[DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(f64::NAN, 0.0, 0.0)]), HullError::NonFinite(3));
    }
}
