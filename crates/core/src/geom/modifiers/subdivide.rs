//! Loop subdivision with Haglund 2009's weight (eqs 2.4–2.6).

use crate::geom::halfedge::{HalfEdgeMesh, NO_PAIR};
use crate::geom::STOP_EVERY;
use glam::DVec3;

/// β of Haglund 2009 eq 2.6 for a vertex of valence `n`:
/// (1/n)·(5/8 − (3 + 2·cos(2π/n))²/64). 3/16 at n = 3, 1/16 at n = 6.
pub(crate) fn loop_beta(n: usize) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let c = 3.0 + 2.0 * libm::cos(2.0 * std::f64::consts::PI / n as f64);
    (0.625 - c * c / 64.0) / n as f64
}

/// One Loop step: a new vertex per edge, each triangle split into four.
/// With `smooth`, edge vertices use the 3/8–1/8 mask (eq 2.5) and old
/// interior vertices move by eq 2.4 with β′ = `weight`·β; boundary edges and
/// vertices are not smoothed (Haglund 2009 gives no boundary rules), so open
/// meshes keep their rims. Without `smooth` new vertices are exact midpoints
/// and old vertices stay put (Haglund 2009 §4.2's `subdivide(weight, false)`,
/// rather than §2.2.2's β = 0, which would still apply the 3/8–1/8 edge mask).
/// `stop` is asked every [`STOP_EVERY`] edges and faces whether to give up
/// (`None`): one step of a large mesh takes longer than a deadline may allow.
pub(super) fn subdivide_once(m: &HalfEdgeMesh, weight: f64, smooth: bool, stop: &dyn Fn() -> bool) -> Option<(Vec<DVec3>, Vec<[u32; 3]>)> {
    let nv = m.vertex_count();
    let mut positions: Vec<DVec3> = Vec::with_capacity(nv + m.edge_count());
    // Old vertices (eq 2.4).
    for v in 0..nv as u32 {
        // Each vertex walks its ring: millions of them take longer than
        // the deadline's slack, so this loop asks too.
        if v as usize % STOP_EVERY == STOP_EVERY - 1 && stop() {
            return None;
        }
        let p = m.positions[v as usize];
        if !smooth || m.is_boundary_vertex(v) || m.outgoing(v) == NO_PAIR {
            positions.push(p);
            continue;
        }
        let ring = m.neighbours(v);
        let n = ring.len();
        let beta = weight * loop_beta(n);
        let sum = ring.iter().fold(DVec3::ZERO, |acc, &i| acc + m.positions[i as usize]);
        positions.push((1.0 - n as f64 * beta) * p + beta * sum);
    }
    // Edge vertices (eq 2.5), one per undirected edge, indexed per half-edge.
    let mut edge_vertex = vec![u32::MAX; m.halfedge_count()];
    for h in 0..m.halfedge_count() as u32 {
        if h as usize % STOP_EVERY == STOP_EVERY - 1 && stop() {
            return None;
        }
        let p = m.pair(h);
        if p != NO_PAIR && p < h {
            continue;
        }
        let a = m.positions[m.tail(h) as usize];
        let b = m.positions[m.head(h) as usize];
        let q = if smooth && p != NO_PAIR {
            let c = m.positions[m.tail(HalfEdgeMesh::prev(h)) as usize];
            let d = m.positions[m.tail(HalfEdgeMesh::prev(p)) as usize];
            0.375 * (a + b) + 0.125 * (c + d)
        } else {
            0.5 * (a + b)
        };
        let id = positions.len() as u32;
        positions.push(q);
        edge_vertex[h as usize] = id;
        if p != NO_PAIR {
            edge_vertex[p as usize] = id;
        }
    }
    let mut tris = Vec::with_capacity(m.face_count() * 4);
    for (f, t) in m.triangles().iter().enumerate() {
        if f % STOP_EVERY == STOP_EVERY - 1 && stop() {
            return None;
        }
        let h = 3 * f;
        let [mab, mbc, mca] = [edge_vertex[h], edge_vertex[h + 1], edge_vertex[h + 2]];
        tris.push([t[0], mab, mca]);
        tris.push([t[1], mbc, mab]);
        tris.push([t[2], mca, mbc]);
        tris.push([mab, mbc, mca]);
    }
    Some((positions, tris))
}
