//! Nested instances of polygon parts (UniGrafix's `def` … `i`), kept as a
//! tree until the meshing budget admits their expansion.
//!
//! Why not expand while parsing: 13 levels of three instances each are a
//! 200-byte source and 3.2 million triangles. Expanded in the parser, that
//! memory was never charged to the request's budget and the work never saw
//! its deadline (issue 17 measured 1.3 s of parsing under a 1 s deadline).
//! The parser now only resolves names and counts; [`Assembly::expand_until`]
//! runs where the budget is, and stops when asked.

use super::weld::{f64_key, weld_by_until};
use super::STOP_EVERY;
use glam::{DMat4, DVec3};

/// One definition: convex polygons (as corner positions, in the part's own
/// frame) and instances of other parts.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Part {
    /// Convex polygons, each fanned from its first corner.
    pub polygons: Vec<Vec<DVec3>>,
    /// Instances: the index of a part in [`Assembly::parts`] and its transform.
    pub children: Vec<(usize, DMat4)>,
}

/// A tree (a DAG: parts may be instanced many times) of [`Part`]s, with
/// its expanded size counted once, so the budget can admit it before any
/// of it is built.
#[derive(Debug, Clone, PartialEq)]
pub struct Assembly {
    parts: Vec<Part>,
    root: usize,
    corners: u64,
    triangles: u64,
}

/// Bytes [`Assembly::expand_until`] holds at its peak for `corners` and
/// `triangles`: the corners (24 each), their weld map entries (key, id and
/// the table's slack: about 40), the remap (4), the distinct positions
/// (24 at most) and the triangles (12 each).
pub(crate) fn expansion_bytes(corners: u64, triangles: u64) -> u64 {
    corners.saturating_mul(24 + 40 + 4 + 24).saturating_add(triangles.saturating_mul(12))
}

/// Why an assembly cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AssemblyError {
    /// A child index names no part, or the root is out of range.
    #[error("part {0} does not exist")]
    NoSuchPart(usize),
    /// A part instances itself, directly or through others.
    #[error("part {0} instances itself")]
    Cycle(usize),
}

impl Assembly {
    /// Makes an assembly drawing `parts[root]`. Counts its expanded corners
    /// and triangles (saturating, so a huge tree still fails the budget).
    pub fn new(parts: Vec<Part>, root: usize) -> Result<Assembly, AssemblyError> {
        if root >= parts.len() {
            return Err(AssemblyError::NoSuchPart(root));
        }
        let mut sizes: Vec<Option<(u64, u64)>> = vec![None; parts.len()];
        let mut visiting = vec![false; parts.len()];
        let (corners, triangles) = size_of(&parts, root, &mut sizes, &mut visiting)?;
        Ok(Assembly { parts, root, corners, triangles })
    }

    /// Corners and triangles of the expansion (before welding).
    pub fn size(&self) -> (u64, u64) {
        (self.corners, self.triangles)
    }

    /// Expands the tree depth-first (each part's polygons, then its
    /// instances in order) and welds corners at identical positions, so
    /// faces that share a source vertex share a mesh vertex; triangles
    /// that welding makes degenerate are dropped. `stop` is asked every
    /// [`STOP_EVERY`] polygons (and corners, while welding) whether to give up (`None`).
    pub fn expand_until(&self, stop: &dyn Fn() -> bool) -> Option<(Vec<DVec3>, Vec<[u32; 3]>)> {
        let capacity = usize::try_from(self.corners).unwrap_or(usize::MAX).min(1 << 24);
        let mut corners = Vec::with_capacity(capacity);
        let mut tris = Vec::new();
        let mut polygons = 0usize;
        // An explicit stack instead of recursion: depth is bounded by the
        // parser, but a loop cannot overflow whatever it is given.
        let mut pending: Vec<(usize, DMat4)> = vec![(self.root, DMat4::IDENTITY)];
        while let Some((index, m)) = pending.pop() {
            let part = &self.parts[index];
            for polygon in &part.polygons {
                polygons += 1;
                if polygons % STOP_EVERY == 0 && stop() {
                    return None;
                }
                let base = corners.len() as u32;
                corners.extend(polygon.iter().map(|p| m.transform_point3(*p)));
                for k in 1..polygon.len().saturating_sub(1) as u32 {
                    tris.push([base, base + k, base + k + 1]);
                }
            }
            // Reversed, so the first instance is expanded first.
            pending.extend(part.children.iter().rev().map(|(child, t)| (*child, m * *t)));
        }
        let (positions, remap) = weld_by_until(corners, |p| f64_key(&p.to_array()), stop)?;
        let tris = tris.into_iter().map(|t| t.map(|i| remap[i as usize])).filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]).collect();
        Some((positions, tris))
    }
}

/// Expanded (corners, triangles) of `parts[index]`, memoised in `sizes`.
fn size_of(parts: &[Part], index: usize, sizes: &mut [Option<(u64, u64)>], visiting: &mut [bool]) -> Result<(u64, u64), AssemblyError> {
    if let Some(size) = sizes[index] {
        return Ok(size);
    }
    if visiting[index] {
        return Err(AssemblyError::Cycle(index));
    }
    visiting[index] = true;
    let part = &parts[index];
    let mut corners: u64 = 0;
    let mut triangles: u64 = 0;
    for polygon in &part.polygons {
        corners = corners.saturating_add(polygon.len() as u64);
        triangles = triangles.saturating_add(polygon.len().saturating_sub(2) as u64);
    }
    for &(child, _) in &part.children {
        if child >= parts.len() {
            return Err(AssemblyError::NoSuchPart(child));
        }
        let (c, t) = size_of(parts, child, sizes, visiting)?;
        corners = corners.saturating_add(c);
        triangles = triangles.saturating_add(t);
    }
    visiting[index] = false;
    sizes[index] = Some((corners, triangles));
    Ok((corners, triangles))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Part {
        Part { polygons: vec![vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y]], children: Vec::new() }
    }

    #[test]
    fn nested_instances_count_and_expand_with_shared_corners_welded() {
        let row = Part { polygons: Vec::new(), children: vec![(0, DMat4::IDENTITY), (0, DMat4::from_translation(DVec3::X))] };
        let grid = Part { polygons: Vec::new(), children: vec![(1, DMat4::IDENTITY), (1, DMat4::from_translation(DVec3::Y))] };
        let a = Assembly::new(vec![square(), row, grid], 2).expect("a DAG");
        assert_eq!(a.size(), (16, 8));
        let (positions, tris) = a.expand_until(&|| false).expect("not stopped");
        // A 2×2 grid of unit squares has 3×3 distinct corners.
        assert_eq!((positions.len(), tris.len()), (9, 8));
        assert_eq!(tris[0], [0, 1, 2]);
    }

    #[test]
    fn cycles_and_missing_parts_are_refused_and_stop_is_obeyed() {
        let selfish = Part { polygons: Vec::new(), children: vec![(0, DMat4::IDENTITY)] };
        assert_eq!(Assembly::new(vec![selfish], 0), Err(AssemblyError::Cycle(0)));
        let dangling = Part { polygons: Vec::new(), children: vec![(5, DMat4::IDENTITY)] };
        assert_eq!(Assembly::new(vec![dangling], 0), Err(AssemblyError::NoSuchPart(5)));
        let many = Part { polygons: vec![square().polygons[0].clone(); STOP_EVERY + 1], children: Vec::new() };
        let a = Assembly::new(vec![many], 0).expect("one part");
        assert!(a.expand_until(&|| true).is_none());
        assert!(a.expand_until(&|| false).is_some());
    }
}
