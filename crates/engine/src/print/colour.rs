//! The model's colours on the united solid, for colour printers (3MF).
//!
//! Manifold cuts the parts' faces where they cross and drops what is
//! inside, but never moves a face: every triangle of the union lies in a
//! triangle of one part. So each united triangle takes the colour of the
//! part triangle that its centre lies on (facing the same way), found
//! through a uniform grid over the parts' triangles. Where two parts'
//! faces coincide, the first part's colour wins (deterministic).

use crate::core::budget::{Budget, LimitExceeded};
use super::union::Piece;
use glam::DVec3;
use std::collections::HashMap;

/// Most grid cells along the longest side: enough that a cell holds a few
/// part triangles for models of up to about a million of them.
const MAX_CELLS: f64 = 96.0;

/// A part triangle: its corners and colour.
struct Source {
    corners: [DVec3; 3],
    normal: DVec3,
    colour: [u8; 4],
}

/// The colour of each triangle of the union (`positions`, `indices`: three
/// per triangle), from the parts it was made of (`colours` parallel to
/// `parts` and to each part's triangles). A one-colour model needs no
/// search. Charges a step per grid entry.
pub(super) fn triangle_colours(parts: &[Piece<'_>], colours: &[Vec<[u8; 4]>], positions: &[DVec3], indices: &[u32], budget: &mut Budget) -> Result<Vec<[u8; 4]>, LimitExceeded> {
    let count = indices.len() / 3;
    let first = colours.iter().flatten().next().copied().unwrap_or(super::PLAIN);
    if colours.iter().flatten().all(|c| *c == first) {
        return Ok(vec![first; count]);
    }
    let sources: Vec<Source> = parts
        .iter()
        .zip(colours)
        .flat_map(|(p, cs)| {
            p.1.iter().zip(cs).map(|(t, &colour)| {
                let corners = t.map(|v| p.0.get(v as usize).copied().unwrap_or(DVec3::ZERO));
                let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalize_or_zero();
                Source { corners, normal, colour }
            })
        })
        .collect();
    let (lo, hi) = super::bounds(sources.iter().flat_map(|s| s.corners));
    let extent = (hi - lo).max_element();
    if !(extent > 0.0 && extent.is_finite()) {
        return Ok(vec![first; count]);
    }
    let cells = (sources.len() as f64).cbrt().clamp(1.0, MAX_CELLS);
    let grid = Grid { lo, cell: extent / cells, top: cells as i32 - 1 };
    // A corner rounded to f32 by Manifold may sit just outside its face's box.
    let eps = extent * 1e-5;
    let spans: Vec<([i32; 3], [i32; 3])> = sources.iter().map(|s| grid.span(&s.corners, eps)).collect();
    let entries: u64 = spans.iter().map(|(a, b)| (0..3).map(|k| (b[k] - a[k] + 1) as u64).product::<u64>()).sum();
    budget.charge_steps(entries.saturating_add(count as u64))?;
    let mut cell_of: HashMap<[i32; 3], Vec<u32>> = HashMap::new();
    for (k, (a, b)) in spans.iter().enumerate() {
        for x in a[0]..=b[0] {
            for y in a[1]..=b[1] {
                for z in a[2]..=b[2] {
                    cell_of.entry([x, y, z]).or_default().push(k as u32);
                }
            }
        }
    }
    let at = |i: u32| positions.get(i as usize).copied().unwrap_or(DVec3::ZERO);
    Ok(indices
        .chunks_exact(3)
        .map(|t| {
            let [a, b, c] = [at(t[0]), at(t[1]), at(t[2])];
            let centre = (a + b + c) / 3.0;
            let normal = (b - a).cross(c - a);
            let candidates = cell_of.get(&grid.cell_of(centre)).map(Vec::as_slice).unwrap_or_default();
            // Nearest part triangle facing the same way; the first on a tie.
            let mut best: Option<(bool, f64, u32)> = None;
            for &k in candidates {
                let s = &sources[k as usize];
                let key = (s.normal.dot(normal) <= 0.0, distance_to_triangle(centre, &s.corners), k);
                if best.is_none_or(|b| (key.0, key.1) < (b.0, b.1)) {
                    best = Some(key);
                }
            }
            best.map_or(first, |(_, _, k)| sources[k as usize].colour)
        })
        .collect())
}

/// A uniform grid of cubes `cell` wide from `lo`, `top + 1` along each axis.
struct Grid {
    lo: DVec3,
    cell: f64,
    top: i32,
}

impl Grid {
    /// The cell holding `p` (clamped into the grid).
    fn cell_of(&self, p: DVec3) -> [i32; 3] {
        ((p - self.lo) / self.cell).floor().to_array().map(|v| (v as i32).clamp(0, self.top))
    }

    /// The first and last cells of the box around `corners`, grown by `eps`.
    fn span(&self, corners: &[DVec3; 3], eps: f64) -> ([i32; 3], [i32; 3]) {
        let (lo, hi) = super::bounds(corners.iter().copied());
        (self.cell_of(lo - DVec3::splat(eps)), self.cell_of(hi + DVec3::splat(eps)))
    }
}

/// The distance from `p` to the triangle `t` (closest point by Voronoi
/// region, Ericson, *Real-Time Collision Detection* §5.1.5). Also what
/// `field` samples the parts' distance with.
pub(super) fn distance_to_triangle(p: DVec3, t: &[DVec3; 3]) -> f64 {
    let [a, b, c] = *t;
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return p.distance(a);
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return p.distance(b);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return p.distance(a + ab * (d1 / (d1 - d3)));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return p.distance(c);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return p.distance(a + ac * (d2 / (d2 - d6)));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return p.distance(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    let denom = va + vb + vc;
    if denom.abs() < f64::MIN_POSITIVE {
        // A triangle of no area: its nearest corner.
        return p.distance(a).min(p.distance(b)).min(p.distance(c));
    }
    p.distance(a + ab * (vb / denom) + ac * (vc / denom))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_to_a_triangle_by_region() {
        let t = [DVec3::ZERO, DVec3::X, DVec3::Y];
        assert_eq!(distance_to_triangle(DVec3::new(0.25, 0.25, 2.0), &t), 2.0);
        assert_eq!(distance_to_triangle(DVec3::new(-3.0, 0.0, 4.0), &t), 5.0);
        assert!((distance_to_triangle(DVec3::new(1.0, 1.0, 0.0), &t) - 0.5f64.sqrt()).abs() < 1e-12);
        assert_eq!(distance_to_triangle(DVec3::new(0.5, -1.0, 0.0), &t), 1.0);
    }
}
