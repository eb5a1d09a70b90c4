//! Deformers that move vertices without changing connectivity (randomize,
//! displace, twist, bend, translate) and the mirror, which adds a reflected copy.

use super::{uniform, Axis};
use crate::geom::halfedge::HalfEdgeMesh;
use glam::{DQuat, DVec3};

/// A copy of `m` with every position mapped by `f` (connectivity unchanged).
pub(super) fn map_positions(m: &HalfEdgeMesh, f: impl Fn(DVec3) -> DVec3) -> HalfEdgeMesh {
    let mut out = m.clone();
    for p in &mut out.positions {
        *p = f(*p);
    }
    out
}

/// The shortest edge length of `m` (0 for a mesh without edges).
fn shortest_edge(m: &HalfEdgeMesh) -> f64 {
    let mut d = f64::INFINITY;
    for h in 0..m.halfedge_count() as u32 {
        d = d.min(m.positions[m.tail(h) as usize].distance(m.positions[m.head(h) as usize]));
    }
    if d.is_finite() {
        d
    } else {
        0.0
    }
}

/// A uniformly distributed unit vector from two uniforms.
fn unit_from(u: f64, v: f64) -> DVec3 {
    let z = 2.0 * u - 1.0;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * std::f64::consts::PI * v;
    DVec3::new(r * libm::cos(phi), r * libm::sin(phi), z)
}

/// Jitters each vertex in a uniformly random direction by a length drawn
/// uniformly from [0, amount·d], d being the shortest edge. With amount < 0.5
/// no two vertices joined by an edge can meet.
pub(super) fn randomize(m: &HalfEdgeMesh, amount: f64, seed: u64) -> HalfEdgeMesh {
    let d = shortest_edge(m);
    let mut out = m.clone();
    for (i, p) in out.positions.iter_mut().enumerate() {
        let i = i as u64;
        *p += unit_from(uniform(seed, i, 0), uniform(seed, i, 1)) * (amount * d * uniform(seed, i, 2));
    }
    out
}

/// Moves a random `fraction` of the vertices along their vertex normals by
/// `amount`·U[0.5, 1.5] (Haglund 2009 §4.3's components 0.5 + U·1.0).
pub(super) fn displace(m: &HalfEdgeMesh, amount: f64, fraction: f64, seed: u64) -> HalfEdgeMesh {
    let normals = m.vertex_normals();
    let mut out = m.clone();
    for (i, p) in out.positions.iter_mut().enumerate() {
        let k = i as u64;
        if uniform(seed, k, 0) < fraction {
            *p += normals[i] * (amount * (0.5 + uniform(seed, k, 1)));
        }
    }
    out
}

/// Appends a copy reflected through the plane `axis = offset`, with each
/// copied triangle's winding reversed so it still faces outward.
pub(super) fn mirror(m: &HalfEdgeMesh, axis: Axis, offset: f64) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let n = m.vertex_count() as u32;
    let mut positions = m.positions.clone();
    positions.extend(m.positions.iter().map(|&p| {
        let mut q = p;
        q[axis.index()] = 2.0 * offset - p[axis.index()];
        q
    }));
    let mut tris = m.triangles().to_vec();
    tris.extend(m.triangles().iter().map(|t| [t[0] + n, t[2] + n, t[1] + n]));
    (positions, tris)
}

/// Rotates each vertex about `axis` by `radians_per_unit` × its coordinate along the axis.
pub(super) fn twist(m: &HalfEdgeMesh, axis: Axis, radians_per_unit: f64) -> HalfEdgeMesh {
    let dir = [DVec3::X, DVec3::Y, DVec3::Z][axis.index()];
    map_positions(m, |p| DQuat::from_axis_angle(dir, radians_per_unit * p[axis.index()]) * p)
}

/// Bends the Y extent of the mesh into an arc about an axis parallel to Z
/// (Barr's bend): a vertex at height y turns by θ·(y − y_min)/height about the
/// centre (R, y_min) with R = height/θ, so the bottom stays put and the
/// whole height sweeps θ. θ = 0 is the identity.
pub(super) fn bend(m: &HalfEdgeMesh, radians: f64) -> HalfEdgeMesh {
    let (lo, hi) = m.positions.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| (lo.min(p.y), hi.max(p.y)));
    let height = hi - lo;
    if radians == 0.0 || height <= 0.0 {
        return m.clone();
    }
    let k = radians / height;
    let r = 1.0 / k;
    map_positions(m, |p| {
        let a = k * (p.y - lo);
        DVec3::new(r - (r - p.x) * libm::cos(a), lo + (r - p.x) * libm::sin(a), p.z)
    })
}
