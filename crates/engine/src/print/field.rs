//! A union of closed parts sampled on a voxel grid: which samples lie inside
//! it, and how far each sample near the surface is from the nearest part
//! triangle. What `fuse` closes gaps on and extracts a surface from.

use super::colour::distance_to_triangle;
use super::union::Piece;
use crate::core::budget::{Budget, LimitExceeded};
use glam::DVec3;

/// A regular grid of samples: sample (i, j, k) is at `origin + h · (i, j, k)`;
/// flat arrays over it run x fastest.
#[derive(Debug, Clone, Copy)]
pub(super) struct Grid {
    /// The first sample.
    pub origin: DVec3,
    /// The spacing (model units).
    pub h: f64,
    /// Samples along x, y and z.
    pub n: [usize; 3],
}

impl Grid {
    /// How many samples.
    pub fn len(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    /// The flat index of sample (i, j, k).
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.n[0] * (j + self.n[1] * k)
    }

    /// Where sample (i, j, k) is.
    pub fn at(&self, i: usize, j: usize, k: usize) -> DVec3 {
        self.origin + DVec3::new(i as f64, j as f64, k as f64) * self.h
    }

    /// The samples whose coordinate along `axis` lies in `[lo, hi]`, as a
    /// half-open index range clamped to the grid.
    pub fn span(&self, axis: usize, lo: f64, hi: f64) -> std::ops::Range<usize> {
        let o = self.origin[axis];
        let first = ((lo - o) / self.h).ceil().max(0.0);
        let last = ((hi - o) / self.h).floor() + 1.0;
        let top = self.n[axis] as f64;
        let (first, last) = (first.min(top), last.clamp(0.0, top));
        if first >= last {
            return 0..0;
        }
        first as usize..last as usize
    }

    /// The nearest sample to `p`, clamped to the grid.
    pub fn nearest(&self, p: DVec3) -> usize {
        let g = (p - self.origin) / self.h;
        let c = |v: f64, n: usize| (v.round().max(0.0) as usize).min(n.saturating_sub(1));
        self.index(c(g.x, self.n[0]), c(g.y, self.n[1]), c(g.z, self.n[2]))
    }
}

/// Which samples lie inside the union of `parts` (closed, outward), by the
/// winding number along each column of samples parallel to z: a column
/// enters a part where it crosses a triangle facing down and leaves where it
/// crosses one facing up, and a sample is inside when more have been entered
/// than left below it. Which triangle a column through a shared edge or
/// corner crosses is decided by a tie rule (below) that gives it to exactly
/// one of the triangles around it, so a closed part is entered and left
/// equally often on every column.
/// Checks the deadline every 1,024 triangles.
pub(super) fn inside(parts: &[Piece<'_>], grid: &Grid, budget: &Budget) -> Result<Vec<bool>, LimitExceeded> {
    // (column, z, +1 entering / -1 leaving) for every crossing.
    let mut crossings: Vec<(u32, f64, i8)> = Vec::new();
    for (positions, tris) in parts {
        for (n, t) in tris.iter().enumerate() {
            if n % 1024 == 1023 {
                budget.check_deadline()?;
            }
            let [a, b, c] = t.map(|v| positions.get(v as usize).copied().unwrap_or(DVec3::ZERO));
            column_crossings(a, b, c, grid, &mut crossings);
        }
    }
    crossings.sort_unstable_by(|x, y| x.0.cmp(&y.0).then(x.1.total_cmp(&y.1)).then(x.2.cmp(&y.2)));
    let mut inside = vec![false; grid.len()];
    let plane = grid.n[0] * grid.n[1];
    let mut run = 0;
    while run < crossings.len() {
        let column = crossings[run].0 as usize;
        let end = run + crossings[run..].iter().take_while(|c| c.0 as usize == column).count();
        let mut winding = 0i32;
        let mut next = run;
        for k in 0..grid.n[2] {
            let z = grid.origin.z + k as f64 * grid.h;
            while next < end && crossings[next].1 < z {
                winding += i32::from(crossings[next].2);
                next += 1;
            }
            if winding > 0 {
                inside[column + plane * k] = true;
            }
        }
        run = end;
    }
    Ok(inside)
}

/// Pushes the crossing of triangle (a, b, c) with every column of samples
/// whose (x, y) lies in its projection.
fn column_crossings(a: DVec3, b: DVec3, c: DVec3, grid: &Grid, out: &mut Vec<(u32, f64, i8)>) {
    let area = cross2(b - a, c - a);
    if area == 0.0 || !area.is_finite() {
        // Seen edge-on from above: no column passes through its inside.
        return;
    }
    // Counter-clockwise seen from +z: an outward triangle facing up (the
    // column leaves the part there); else the column enters it.
    let (p, delta) = if area > 0.0 { ([a, b, c], -1) } else { ([a, c, b], 1) };
    let lo = a.min(b).min(c);
    let hi = a.max(b).max(c);
    for j in grid.span(1, lo.y, hi.y) {
        for i in grid.span(0, lo.x, hi.x) {
            let q = grid.at(i, j, 0);
            let e = [edge(p[1], p[2], q), edge(p[2], p[0], q), edge(p[0], p[1], q)];
            let owned = |k: usize| {
                let (from, to) = (p[(k + 1) % 3], p[(k + 2) % 3]);
                e[k] > 0.0 || (e[k] == 0.0 && owns_edge(from, to))
            };
            if !(owned(0) && owned(1) && owned(2)) {
                continue;
            }
            let sum = e[0] + e[1] + e[2];
            if !(sum > 0.0) {
                continue;
            }
            let z = (e[0] * p[0].z + e[1] * p[1].z + e[2] * p[2].z) / sum;
            // Fits: the grid has far fewer than 2³² columns (fuse caps it).
            out.push(((i + grid.n[0] * j) as u32, z, delta));
        }
    }
}

/// Twice the signed area of the parallelogram of `u` and `v` seen from +z.
fn cross2(u: DVec3, v: DVec3) -> f64 {
    u.x * v.y - u.y * v.x
}

/// Which side of the edge from `from` to `to` the point `q` is on (seen from
/// +z, positive on the left), computed from the edge's lesser end whichever
/// way it runs, so that the two triangles sharing an edge get exactly
/// opposite values and a point on it is on it for both.
fn edge(from: DVec3, to: DVec3, q: DVec3) -> f64 {
    if (from.x, from.y) <= (to.x, to.y) {
        cross2(to - from, q - from)
    } else {
        -cross2(from - to, q - to)
    }
}

/// The tie rule: a column exactly on an edge belongs to the triangle on the
/// edge's left when the edge runs down (or along +x when level). Of the two
/// triangles sharing an edge, which run it opposite ways, exactly one owns it.
fn owns_edge(from: DVec3, to: DVec3) -> bool {
    to.y < from.y || (to.y == from.y && to.x > from.x)
}

/// For every sample within `band` of a triangle of `parts`: the distance to
/// the nearest one and that triangle's index (counting through the parts in
/// order); `band` and `u32::MAX` elsewhere. Checks the deadline every 1,024
/// triangles.
pub(super) fn near_surface(parts: &[Piece<'_>], grid: &Grid, band: f64, budget: &Budget) -> Result<(Vec<f32>, Vec<u32>), LimitExceeded> {
    let mut distance = vec![band as f32; grid.len()];
    let mut nearest = vec![u32::MAX; grid.len()];
    let mut index = 0u32;
    for (positions, tris) in parts {
        for t in tris.iter() {
            if index % 1024 == 1023 {
                budget.check_deadline()?;
            }
            let [a, b, c] = t.map(|v| positions.get(v as usize).copied().unwrap_or(DVec3::ZERO));
            let lo = a.min(b).min(c) - DVec3::splat(band);
            let hi = a.max(b).max(c) + DVec3::splat(band);
            for k in grid.span(2, lo.z, hi.z) {
                for j in grid.span(1, lo.y, hi.y) {
                    for i in grid.span(0, lo.x, hi.x) {
                        let s = grid.index(i, j, k);
                        let d = distance_to_triangle(grid.at(i, j, k), &[a, b, c]) as f32;
                        if d < distance[s] {
                            distance[s] = d;
                            nearest[s] = index;
                        }
                    }
                }
            }
            index = index.saturating_add(1);
        }
    }
    Ok((distance, nearest))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::geom::halfedge::HalfEdgeMesh;

    /// A box's corners and outward triangles, from `lo` to `hi` (for the
    /// print stage's tests: `fuse`'s too).
    pub(in crate::print) fn cuboid(lo: DVec3, hi: DVec3) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let p: Vec<DVec3> = (0..8).map(|i| DVec3::new([lo.x, hi.x][i & 1], [lo.y, hi.y][(i >> 1) & 1], [lo.z, hi.z][(i >> 2) & 1])).collect();
        let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        (p, quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect())
    }

    /// A unit cube moved by `offset`.
    fn cube(offset: DVec3) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        cuboid(offset, offset + DVec3::ONE)
    }

    /// Samples inside two overlapping cubes are exactly those within either
    /// cube, including samples exactly on grid-aligned faces' planes (the
    /// tie rule), and the distance near the surface is exact.
    #[test]
    fn inside_and_near_surface_sample_two_overlapping_cubes() {
        let (pa, ta) = cube(DVec3::ZERO);
        let (pb, tb) = cube(DVec3::new(0.5, 0.5, 0.5));
        assert!(HalfEdgeMesh::new(pa.clone(), ta.clone()).map(|m| m.signed_volume() > 0.0).unwrap_or(false));
        let parts: Vec<Piece<'_>> = vec![(&pa, &ta), (&pb, &tb)];
        // Samples every quarter unit from -0.5: some lie exactly on faces.
        let grid = Grid { origin: DVec3::splat(-0.5), h: 0.25, n: [11, 11, 11] };
        let budget = Budget::new(crate::core::budget::Limits::default());
        let inside = inside(&parts, &grid, &budget).expect("in time");
        let within = |p: DVec3, o: f64| (0..3).all(|k| p[k] > o && p[k] < o + 1.0);
        let mut boundary = 0;
        for k in 0..11 {
            for j in 0..11 {
                for i in 0..11 {
                    let p = grid.at(i, j, k);
                    let on_face = (0..3).any(|a| [0.0, 1.0, 0.5, 1.5].contains(&p[a]));
                    if on_face {
                        boundary += 1;
                        continue;
                    }
                    assert_eq!(inside[grid.index(i, j, k)], within(p, 0.0) || within(p, 0.5), "at {p}");
                }
            }
        }
        assert!(boundary > 0);
        let (distance, nearest) = near_surface(&parts, &grid, 0.6, &budget).expect("in time");
        let s = grid.index(2, 2, 2); // (0, 0, 0): a corner of the first cube
        assert_eq!((distance[s], nearest[s] < 12), (0.0, true));
        let s = grid.index(0, 4, 4); // (-0.5, 0.5, 0.5): half a unit left of it
        assert_eq!(distance[s], 0.5);
        let s = grid.index(10, 10, 10); // (2, 2, 2): beyond the band
        assert_eq!((distance[s], nearest[s]), (0.6, u32::MAX));
    }
}
