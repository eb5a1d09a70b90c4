//! The surface where a sampled field crosses zero, by marching tetrahedra:
//! each grid cell is cut into six tetrahedra around its main diagonal (the
//! Kuhn subdivision, the same in every cell, so neighbouring cells' faces
//! are cut alike), the field is linear inside each, and its zero set there
//! is one triangle or a quad.
//!
//! Why tetrahedra and not marching cubes or surface nets (the
//! `fast-surface-nets` crate, used for isosurfaces in the models): the zero
//! set of a piecewise-linear field with no sample exactly zero is a closed
//! 2-manifold, so every result is a watertight solid with no ambiguous
//! cell and no vertex where two sheets kiss, which a print must be.
//! Marching cubes' ambiguous cases and surface nets' shared vertices can
//! both pinch. Manifold's `LevelSet` does the same on a body-centred grid,
//! but it walks a power-of-two hash grid over the whole box (7 s for a
//! 4-million-sample grid here) and merges vertices near grid points into
//! kissing ones. Written by hand for those reasons.

use super::field::Grid;
use crate::core::budget::{Budget, LimitExceeded};
use glam::DVec3;
use std::collections::HashMap;

/// The six tetrahedra of a cell, as corner numbers (bit 0: +x, bit 1: +y,
/// bit 2: +z): each walks from corner 0 to corner 7 along the axes in one
/// order.
const TETRAHEDRA: [[u8; 4]; 6] = [[0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]];

/// The offset of corner `c` of a cell.
fn corner(c: u8) -> [i64; 3] {
    [i64::from(c & 1), i64::from((c >> 1) & 1), i64::from((c >> 2) & 1)]
}

/// The zero set of `values` (on `grid`, positive inside) as shared
/// positions and triangles wound counter-clockwise seen from outside (where
/// the field is negative). Samples that are exactly zero count as outside.
/// Checks the deadline once per layer of cells, and charges the surface
/// to `budget` as it grows ([`SURFACE_BYTES_PER_VERTEX`], in steps of
/// [`CHARGE_STEP`] vertices), so a surface too big for the memory limit is
/// refused while it is made, not after; the bytes charged are returned
/// with it, for the caller to release when it lets the surface go.
pub(super) fn surface(values: &[f32], grid: &Grid, budget: &mut Budget) -> Result<(Vec<DVec3>, Vec<u32>, u64), LimitExceeded> {
    let [nx, ny, nz] = grid.n;
    let mut charged = 0u64;
    let mut positions: Vec<DVec3> = Vec::new();
    let mut indices: Vec<u32> = Vec::new();
    // The vertex on each crossed grid edge, by its two samples' indices.
    let mut on_edge: HashMap<(usize, usize), u32> = HashMap::new();
    let inside = |s: usize| values.get(s).is_some_and(|v| *v > 0.0);
    let plane = nx * ny;
    for k in 0..nz.saturating_sub(1) {
        budget.check_deadline()?;
        // Cells of this layer and later ones touch samples of layer k and
        // above only: the crossings on edges that start below it are never
        // looked up again. Dropping them keeps the map to about two layers'
        // crossings instead of the whole surface's (a vertex's index is
        // still the order of its first appearance, so the result is the same).
        if k > 0 {
            let first = k * plane;
            on_edge.retain(|&(a, _), _| a >= first);
        }
        for j in 0..ny.saturating_sub(1) {
            for i in 0..nx.saturating_sub(1) {
                let sample = |c: u8| {
                    let o = corner(c);
                    grid.index(i + o[0] as usize, j + o[1] as usize, k + o[2] as usize)
                };
                let corners: [usize; 8] = std::array::from_fn(|c| sample(c as u8));
                let count = corners.iter().filter(|&&s| inside(s)).count();
                if count == 0 || count == 8 {
                    continue;
                }
                // A cell adds at most nineteen vertices (a crossing on each of its edges).
                if positions.len() as u64 + 19 > charged / SURFACE_BYTES_PER_VERTEX {
                    budget.reserve_memory(CHARGE_STEP * SURFACE_BYTES_PER_VERTEX)?;
                    charged += CHARGE_STEP * SURFACE_BYTES_PER_VERTEX;
                }
                for tet in TETRAHEDRA {
                    let (ins, outs): (Vec<u8>, Vec<u8>) = tet.iter().partition(|&&c| inside(corners[c as usize]));
                    let mut vertex = |a: u8, b: u8| {
                        let (sa, sb) = (corners[a as usize], corners[b as usize]);
                        let key = (sa.min(sb), sa.max(sb));
                        *on_edge.entry(key).or_insert_with(|| {
                            positions.push(crossing(values, grid, sa, sb));
                            (positions.len() - 1) as u32
                        })
                    };
                    match (ins.as_slice(), outs.as_slice()) {
                        ([p], [q1, q2, q3]) | ([q1, q2, q3], [p]) => {
                            // The triangle faces away from p if p is inside, towards it if not.
                            let away = ins.len() == 1;
                            let (q2, q3) = if (orientation(*p, *q1, *q2, *q3) > 0) == away { (*q2, *q3) } else { (*q3, *q2) };
                            let t = [vertex(*p, *q1), vertex(*p, q2), vertex(*p, q3)];
                            indices.extend_from_slice(&t);
                        }
                        ([a, b], [c, d]) => {
                            // Inside a, b; outside c, d: the quad ac, ad, bd, bc faces c and d
                            // when (a, b, c, d) is positively oriented.
                            let (c, d) = if orientation(*a, *b, *c, *d) > 0 { (*c, *d) } else { (*d, *c) };
                            let quad = [vertex(*a, c), vertex(*a, d), vertex(*b, d), vertex(*b, c)];
                            indices.extend_from_slice(&[quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]]);
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    Ok((positions, indices, charged))
}

/// Bytes charged per surface vertex: its f64 position (24) and the f32
/// copy Manifold imports (12), about two triangles' indices (24), and its
/// share of the two layers' edge map; a marching-tetrahedra surface has
/// about two triangles per vertex (plant-e's: 1,062,796 triangles).
pub(crate) const SURFACE_BYTES_PER_VERTEX: u64 = 80;

/// Vertices charged at a time.
const CHARGE_STEP: u64 = 16_384;

/// The sign of the volume of the tetrahedron of corners (p, a, b, c),
/// exactly (integer offsets).
fn orientation(p: u8, a: u8, b: u8, c: u8) -> i64 {
    let [p, a, b, c] = [p, a, b, c].map(corner);
    let d = |u: [i64; 3]| [u[0] - p[0], u[1] - p[1], u[2] - p[2]];
    let (u, v, w) = (d(a), d(b), d(c));
    (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])).signum()
}

/// Where the field crosses zero on the edge between samples `a` and `b`
/// (one inside, one not), by linear interpolation, kept a thousandth of
/// the edge from either end so that no two crossings coincide.
fn crossing(values: &[f32], grid: &Grid, a: usize, b: usize) -> DVec3 {
    let at = |s: usize| {
        let (i, rest) = (s % grid.n[0], s / grid.n[0]);
        grid.at(i, rest % grid.n[1], rest / grid.n[1])
    };
    let (va, vb) = (f64::from(values[a]), f64::from(values[b]));
    let t = if va != vb { (va / (va - vb)).clamp(1e-3, 1.0 - 1e-3) } else { 0.5 };
    at(a).lerp(at(b), t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::halfedge::HalfEdgeMesh;

    /// Two balls that overlap a little give one closed, outward, manifold
    /// surface of about their volume; two apart give two.
    #[test]
    fn the_surface_of_two_balls_is_closed_and_outward() {
        for (gap, shells) in [(-0.2, 1usize), (0.3, 2)] {
            let grid = Grid { origin: DVec3::splat(-1.5), h: 0.1, n: [52, 31, 31] };
            let centres = [DVec3::ZERO, DVec3::new(2.0 + gap, 0.0, 0.0)];
            let mut values = vec![0.0f32; grid.len()];
            for k in 0..31 {
                for j in 0..31 {
                    for i in 0..52 {
                        let p = grid.at(i, j, k);
                        values[grid.index(i, j, k)] = centres.iter().map(|c| 1.0 - p.distance(*c)).fold(f64::MIN, f64::max) as f32;
                    }
                }
            }
            let mut budget = Budget::new(crate::core::budget::Limits::default());
            let (positions, indices, charged) = surface(&values, &grid, &mut budget).expect("in time");
            assert_eq!(budget.memory(), charged);
            assert!(charged >= positions.len() as u64 * SURFACE_BYTES_PER_VERTEX, "{charged} for {} vertices", positions.len());
            let tris: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
            let m = HalfEdgeMesh::new(positions, tris).expect("manifold");
            assert!(m.is_closed() && m.nonmanifold_vertices().is_empty());
            let ball = 4.0 / 3.0 * std::f64::consts::PI;
            let v = m.signed_volume();
            assert!(v > 0.0 && (v - 2.0 * ball).abs() < 0.1 * ball * 2.0, "volume {v}");
            assert_eq!(m.euler_characteristic(), 2 * shells as i64);
        }
    }
}
