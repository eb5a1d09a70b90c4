//! Contacts become connections (issue 16): parts that touch at a point or
//! along an edge, or nearly touch, are fused into one solid with a
//! connection at least the closing radius thick.
//!
//! The exact union (`union`) keeps parts that only touch as separate shells
//! or as edges of four faces, and a gap a printer cannot resolve stays a
//! gap. Here the union is sampled on a voxel grid (`field`), closed
//! morphologically (dilated, then eroded, by a ball of the closing radius:
//! gaps narrower than twice the radius fill, nothing else grows), and only
//! the filled regions that join two pieces which were apart are kept as
//! bridges. The surface is then extracted from the sampled signed distance
//! with the bridges added, by marching tetrahedra (`tetra`: manifold by
//! construction, whatever the contacts were), and simplified by Manifold
//! within an eighth of a sample. Why a distance field and not an outward
//! offset of each part before the exact union: the offset doubled triangle
//! counts and fused only what it pushed into overlap; the closing finds
//! every contact, point, edge or near miss, at one resolution, and its
//! result is one manifold surface. The cost: the printed surface is the
//! sampled one (sharp edges rounded by about a sample), so this route is
//! taken only when the exact union is not one watertight shell.

use super::edt::squared_distances;
use super::field::{self, Grid};
use super::tetra;
use super::union::Piece;
use super::PrintError;
use crate::core::budget::{Budget, LimitExceeded};
use glam::DVec3;

/// Samples the grid may have: about 8 million (a 203³ cube), some 150 MB
/// of working arrays at most.
pub(crate) const MAX_SAMPLES: usize = 1 << 23;

/// Samples aimed at: the spacing is the closing radius's half, but no finer
/// than this many samples over the box needs.
const TARGET_SAMPLES: f64 = 3.0e6;

/// Bytes of working arrays per sample: the signed distance, the nearest
/// triangle, a distance transform, labels, and the inside flags.
const BYTES_PER_SAMPLE: u64 = 4 + 4 + 4 + 4 + 1 + 1;

/// Radius of the ball each bridge sample adds, in samples: more than half
/// the diagonal of a sample's square (0.707) so that samples next to each
/// other along a face diagonal make one connected bridge.
const BRIDGE_RADIUS: f64 = 0.9;

/// A fused solid: one closed manifold surface (model units).
pub(super) struct Fused {
    /// Shared positions.
    pub positions: Vec<DVec3>,
    /// Three per triangle, counter-clockwise seen from outside.
    pub indices: Vec<u32>,
    /// Each triangle's colour: the nearest part triangle's.
    pub colours: Vec<[u8; 4]>,
    /// What fusing did, for the report.
    pub stats: FuseStats,
}

/// What fusing did: the report's `fused_gap_mm`, `bridges`, `sample_mm`
/// and `filled_voids`.
#[derive(Debug, Clone, Copy)]
pub(super) struct FuseStats {
    /// The closing radius used (model units).
    pub closing: f64,
    /// The sample spacing (model units).
    pub spacing: f64,
    /// How many bridges joined pieces that were apart.
    pub bridges: u64,
    /// How many enclosed voids were filled.
    pub voids: u64,
}

impl FuseStats {
    /// The widest gap closed (model units): twice the closing radius.
    pub fn gap(&self) -> f64 {
        2.0 * self.closing
    }
}

/// Fuses closed, outward `parts` (with each triangle's colour, parallel to
/// `parts`) into one surface, closing gaps narrower than twice `closing`
/// (model units). The spacing is half the closing radius, coarser (and the
/// radius twice the spacing) if the grid would exceed [`MAX_SAMPLES`].
pub(super) fn fuse(parts: &[Piece<'_>], colours: &[Vec<[u8; 4]>], closing: f64, budget: &mut Budget) -> Result<Fused, PrintError> {
    let (lo, hi) = super::bounds(parts.iter().flat_map(|p| p.0.iter().copied()));
    let size = hi - lo;
    if !(size.max_element() > 0.0 && size.is_finite() && closing > 0.0 && closing.is_finite()) {
        return Err(PrintError::Union("nothing to fuse".into()));
    }
    let volume = size.max(DVec3::splat(size.max_element() * 1e-3)).element_product();
    let mut h = (closing / 2.0).max((volume / TARGET_SAMPLES).cbrt());
    let mut closing = closing.max(2.0 * h);
    let samples = |h: f64, closing: f64| {
        let pad = closing + 3.0 * h;
        (size + DVec3::splat(2.0 * pad)) / h + DVec3::splat(2.0)
    };
    // At most MAX_SAMPLES, and at most half the steps the request has left
    // (a step per sample): a grid too coarse for the closing radius widens
    // it, which the report says (`fused_gap_mm`).
    let steps_left = budget.limits().max_steps.saturating_sub(budget.steps());
    let most = (MAX_SAMPLES as f64).min(steps_left as f64 / 2.0).max(1e5);
    while samples(h, closing).element_product() > most {
        h *= 1.1;
        closing = closing.max(2.0 * h);
    }
    let pad = closing + 3.0 * h;
    let n = samples(h, closing).to_array().map(|v| v.ceil() as usize);
    // An origin a fraction of a sample off the model's own coordinates: grid
    // samples then rarely fall exactly on a face, an edge or a corner of a
    // part placed on round numbers (the tie rule in `field` handles them).
    let origin = lo - DVec3::splat(pad) - DVec3::splat(h * 0.318_309_886);
    let grid = Grid { origin, h, n };
    let len = grid.len();
    crate::core::memprobe::note("fuse.samples", len as u64);
    let triangles: u64 = parts.iter().map(|p| p.1.len() as u64).sum();
    let bytes = (len as u64).saturating_mul(BYTES_PER_SAMPLE);
    budget.reserve_memory(bytes)?;
    // A step per sample (each pass over the grid is a few operations per
    // sample), and eight per triangle (its columns and its neighbourhood).
    budget.charge_steps((len as u64).saturating_add(triangles.saturating_mul(8)))?;

    let inside = field::inside(parts, &grid, budget)?;
    let band = 2.5 * h;
    let (distance, nearest) = field::near_surface(parts, &grid, band, budget)?;
    crate::core::memprobe::mark("fuse.field", budget);
    let closed = close(&inside, &grid, closing / h, budget)?;
    budget.check_deadline()?;
    let (bridge, bridges) = bridges(&inside, &closed, &grid, budget)?;
    drop(closed);
    crate::core::memprobe::mark("fuse.close", budget);
    budget.check_deadline()?;

    // The signed distance, positive inside, with each bridge sample's ball.
    let mut value: Vec<f32> = distance.iter().zip(&inside).map(|(d, &i)| if i { *d } else { -*d }).collect();
    drop(distance);
    if bridges > 0 {
        let mut reach: Vec<f32> = bridge.iter().map(|&b| if b { 0.0 } else { f32::INFINITY }).collect();
        squared_distances(&mut reach, n);
        budget.check_deadline()?;
        for (v, r) in value.iter_mut().zip(&reach) {
            let ball = (BRIDGE_RADIUS - f64::from(*r).sqrt()) * h;
            *v = v.max(ball as f32);
        }
    }
    // Enclosed voids (a hollow the parts close all round, pockets where
    // parts meet) are filled: a print would trap material in them, and each
    // is one more shell.
    let voids = fill_voids(&mut value, &inside, &bridge, &grid);
    drop(bridge);
    drop(inside);
    budget.check_deadline()?;
    let (positions, indices, surface_bytes) = tetra::surface(&value, &grid, budget)?;
    crate::core::memprobe::mark("fuse.surface", budget);
    drop(value);
    // Of the grid, only each sample's nearest triangle is kept (for the colours).
    let nearest_bytes = (len as u64).saturating_mul(4);
    budget.release_memory(bytes.saturating_sub(nearest_bytes));
    budget.check_deadline()?;
    // Simplifying can pinch a neck thinner than the tolerance into a vertex
    // and so split a piece in two: then less, then not at all. (An eighth
    // of a sample first: a quarter split tree, sphereflake and the knot,
    // and each failed try costs as much as a success.)
    let pieces = components(positions.len(), &indices);
    let mut simplified = None;
    for tolerance in [h / 8.0, h / 16.0] {
        let (p, i) = simplify(&positions, &indices, tolerance, budget)?;
        crate::core::memprobe::mark("fuse.simplify", budget);
        if components(p.len(), &i) <= pieces {
            simplified = Some((p, i));
            break;
        }
    }
    let (positions, indices) = simplified.unwrap_or((positions, indices));
    let flat: Vec<[u8; 4]> = colours.iter().flatten().copied().collect();
    let colours = indices
        .chunks_exact(3)
        .map(|t| {
            let centre = t.iter().map(|&v| positions.get(v as usize).copied().unwrap_or(DVec3::ZERO)).sum::<DVec3>() / 3.0;
            let near = nearest.get(grid.nearest(centre)).copied().unwrap_or(u32::MAX);
            flat.get(near as usize).or(flat.first()).copied().unwrap_or(super::PLAIN)
        })
        .collect();
    budget.release_memory(surface_bytes.saturating_add(nearest_bytes));
    Ok(Fused { positions, indices, colours, stats: FuseStats { closing, spacing: h, bridges, voids } })
}

/// Bytes charged per triangle of a surface Manifold simplifies: the mesh
/// it imports, the imported manifold, the copy `Simplify` works on (it
/// leaves its input untouched), their colliders, and the result read back.
/// Measured (RULEMESH_MEMORY_TRACE, glibc's mmap threshold fixed as `main`
/// sets it): plant-e's fused surface, 1,062,796 triangles, took the
/// process from 82 to 563 MiB resident, 474 bytes a triangle; 540 bounds
/// it (docs/print.md, "Memory"). It was 200 before issue 38.
pub(crate) const SIMPLIFY_BYTES_PER_TRIANGLE: u64 = 540;

/// The surface (shared positions, CCW triangles) simplified by Manifold
/// within `tolerance` (model units): marching tetrahedra cut every cell the
/// surface crosses into up to twelve triangles, most of them slivers on
/// flat faces. Manifold's `Simplify` collapses edges while the surface moves
/// less than the tolerance and keeps its topology manifold; where a
/// collapse would pinch two sheets together at a vertex, it keeps a copy of
/// the vertex for each sheet, at one position. A print's STL has positions
/// only and would weld the copies back into a pinch, so each copy but the
/// first is moved a sixth of the tolerance into its own sheet ([`unpinch`]).
/// Why not meshoptimizer's simplifier: its collapses do not check every
/// link condition, and on these surfaces it made edges of four faces.
/// Cancelled at the deadline.
fn simplify(positions: &[DVec3], indices: &[u32], tolerance: f64, budget: &mut Budget) -> Result<(Vec<DVec3>, Vec<u32>), PrintError> {
    crate::core::memprobe::note("simplify.triangles", indices.len() as u64 / 3);
    let bytes = (indices.len() as u64 / 3).saturating_mul(SIMPLIFY_BYTES_PER_TRIANGLE);
    budget.reserve_memory(bytes)?;
    budget.charge_steps(indices.len() as u64 / 3)?;
    let verts: Vec<f32> = positions.iter().flat_map(|p| p.as_vec3().to_array()).collect();
    // Manifold checks for cancellation between its phases, some of which
    // take a second on a million triangles: cancelled at three quarters of
    // the time left, it stops before the deadline, and what follows
    // (placing, measuring, writing) has the rest.
    let timeout = budget.time_left().map(|t| u64::try_from(t.mul_f64(0.75).as_millis()).unwrap_or(u64::MAX).max(1));
    let simplified = manifold_rs::Manifold::simplified(&manifold_rs::Mesh::new(&verts, indices), tolerance, timeout);
    budget.release_memory(bytes);
    if simplified.status() == manifold_rs::Manifold::CANCELLED {
        // Refused as at the deadline: what is left cannot finish the work.
        let elapsed = u64::try_from(budget.elapsed().as_millis()).unwrap_or(u64::MAX);
        return Err(LimitExceeded::deadline_passed(budget.limits().timeout_ms, elapsed).into());
    }
    if simplified.status() != 0 || simplified.is_empty() {
        return Err(PrintError::Union(format!("the fused surface was not accepted as a manifold (status {})", simplified.status())));
    }
    let (positions, indices) = super::union::triangles_of(&simplified);
    let mut positions: Vec<DVec3> = positions.iter().map(|p| glam::Vec3::from_array(*p).as_dvec3()).collect();
    unpinch(&mut positions, &indices, tolerance / 6.0);
    Ok((positions, indices))
}

/// Moves every vertex that shares its position (as `f32`) with an earlier
/// one by `step` towards the middle of its own triangles, so that copies of
/// a vertex kept apart by Manifold stay apart once welded by position.
fn unpinch(positions: &mut [DVec3], indices: &[u32], step: f64) {
    let key = |p: DVec3| p.as_vec3().to_array().map(f32::to_bits);
    let mut first: std::collections::HashMap<[u32; 3], usize> = std::collections::HashMap::new();
    let mut copies: Vec<usize> = Vec::new();
    for (v, p) in positions.iter().enumerate() {
        if *first.entry(key(*p)).or_insert(v) != v {
            copies.push(v);
        }
    }
    if copies.is_empty() {
        return;
    }
    // The sum of the centres of each copy's triangles, and how many.
    let mut towards: std::collections::HashMap<usize, (DVec3, f64)> = copies.iter().map(|&v| (v, (DVec3::ZERO, 0.0))).collect();
    for t in indices.chunks_exact(3) {
        let centre = t.iter().map(|&v| positions.get(v as usize).copied().unwrap_or(DVec3::ZERO)).sum::<DVec3>() / 3.0;
        for &v in t {
            if let Some(e) = towards.get_mut(&(v as usize)) {
                e.0 += centre;
                e.1 += 1.0;
            }
        }
    }
    for v in copies {
        if let Some((sum, count)) = towards.get(&v).copied().filter(|e| e.1 > 0.0) {
            let p = positions[v];
            positions[v] = p + (sum / count - p).normalize_or_zero() * step;
        }
    }
}

/// Fills the regions outside the solid (`inside` or `bridge`) that do not
/// reach the grid's border, sharing faces: `value` becomes half a sample
/// inside there. Returns how many regions were filled.
fn fill_voids(value: &mut [f32], inside: &[bool], bridge: &[bool], grid: &Grid) -> u64 {
    let outside = label(grid, |s| !inside[s] && !bridge[s]);
    let regions = outside.iter().copied().max().unwrap_or(0) as usize;
    // The grid's border is outside everything (the padding), all one region.
    let open = outside[0];
    let mut filled = vec![false; regions + 1];
    for (v, &r) in value.iter_mut().zip(&outside) {
        if r != 0 && r != open {
            *v = (grid.h / 2.0) as f32;
            filled[r as usize] = true;
        }
    }
    filled.iter().filter(|&&f| f).count() as u64
}

/// How many pieces the triangles make, joined through shared vertices.
fn components(vertices: usize, indices: &[u32]) -> usize {
    let mut root = super::joined_through_triangles(vertices, indices.chunks_exact(3));
    let mut used = vec![false; vertices];
    for &v in indices {
        used[v as usize] = true;
    }
    (0..vertices as u32).filter(|&v| used[v as usize] && super::find_root(&mut root, v) == v).count()
}

/// The morphological closing of `inside` by a ball of `radius` samples:
/// the samples within the radius of an inside one (the dilation), less
/// those within the radius of a sample outside the dilation (the erosion).
/// Checks the deadline between the passes.
fn close(inside: &[bool], grid: &Grid, radius: f64, budget: &Budget) -> Result<Vec<bool>, LimitExceeded> {
    let r2 = (radius * radius) as f32;
    let mut d: Vec<f32> = inside.iter().map(|&i| if i { 0.0 } else { f32::INFINITY }).collect();
    squared_distances(&mut d, grid.n);
    budget.check_deadline()?;
    // Seeds of the erosion: samples outside the dilation.
    for v in d.iter_mut() {
        *v = if *v <= r2 { f32::INFINITY } else { 0.0 };
    }
    squared_distances(&mut d, grid.n);
    Ok(d.iter().map(|&v| v > r2).collect())
}

/// The samples the closing added that join pieces which were apart: each
/// connected region of added samples (sharing faces) is kept if it touches
/// two or more connected pieces of `inside`. Also how many regions were
/// kept. Checks the deadline between the passes.
fn bridges(inside: &[bool], closed: &[bool], grid: &Grid, budget: &Budget) -> Result<(Vec<bool>, u64), LimitExceeded> {
    let pieces = label(grid, |s| inside[s]);
    budget.check_deadline()?;
    let added = label(grid, |s| closed[s] && !inside[s]);
    budget.check_deadline()?;
    // The pieces each added region touches, as (region, piece) pairs.
    let mut touches: Vec<(u32, u32)> = Vec::new();
    let [nx, ny, nz] = grid.n;
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let s = grid.index(i, j, k);
                let region = added[s];
                if region == 0 {
                    continue;
                }
                for (t, _) in neighbours_at(grid, i, j, k) {
                    if pieces[t] != 0 {
                        touches.push((region, pieces[t]));
                    }
                }
            }
        }
    }
    touches.sort_unstable();
    touches.dedup();
    let regions = added.iter().copied().max().unwrap_or(0) as usize;
    let mut joins = vec![0u32; regions + 1];
    for (region, _) in &touches {
        joins[*region as usize] += 1;
    }
    let keep: Vec<bool> = joins.iter().map(|&j| j >= 2).collect();
    let kept = keep.iter().filter(|&&k| k).count() as u64;
    Ok((added.iter().map(|&r| r != 0 && keep[r as usize]).collect(), kept))
}

/// Labels the connected regions (sharing faces) of the samples `member`
/// picks, 1, 2, ... in scan order; 0 for samples outside every region.
fn label(grid: &Grid, member: impl Fn(usize) -> bool) -> Vec<u32> {
    let mut labels = vec![0u32; grid.len()];
    let mut next = 0u32;
    let mut stack: Vec<[usize; 3]> = Vec::new();
    let [nx, ny, nz] = grid.n;
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let s = grid.index(i, j, k);
                if labels[s] != 0 || !member(s) {
                    continue;
                }
                next += 1;
                labels[s] = next;
                stack.push([i, j, k]);
                while let Some([a, b, c]) = stack.pop() {
                    for (t, at) in neighbours_at(grid, a, b, c) {
                        if labels[t] == 0 && member(t) {
                            labels[t] = next;
                            stack.push(at);
                        }
                    }
                }
            }
        }
    }
    labels
}

/// The up to six samples sharing a face with (i, j, k): flat index and position.
fn neighbours_at(grid: &Grid, i: usize, j: usize, k: usize) -> impl Iterator<Item = (usize, [usize; 3])> + '_ {
    const STEPS: [[i64; 3]; 6] = [[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]];
    STEPS.iter().filter_map(move |d| {
        let at = [i as i64 + d[0], j as i64 + d[1], k as i64 + d[2]];
        if (0..3).any(|a| at[a] < 0 || at[a] >= grid.n[a] as i64) {
            return None;
        }
        let at = at.map(|v| v as usize);
        Some((grid.index(at[0], at[1], at[2]), at))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use super::super::field::tests::cuboid;
    use crate::core::budget::Limits;
    use crate::geom::halfedge::HalfEdgeMesh;

    /// Fuses boxes, checks the result is closed, manifold and unpinched, and
    /// gives it with its volume and how many pieces it is.
    fn fuse_boxes(boxes: &[(DVec3, DVec3)], closing: f64) -> (Fused, f64, i64) {
        let meshes: Vec<_> = boxes.iter().map(|(lo, hi)| cuboid(*lo, *hi)).collect();
        let parts: Vec<Piece<'_>> = meshes.iter().map(|(p, t)| (p.as_slice(), t.as_slice())).collect();
        let colours: Vec<Vec<[u8; 4]>> = meshes.iter().map(|m| vec![[255, 0, 0, 255]; m.1.len()]).collect();
        let fused = fuse(&parts, &colours, closing, &mut Budget::new(Limits::defaults_for(true))).expect("fused");
        let tris: Vec<[u32; 3]> = fused.indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
        let m = HalfEdgeMesh::new(fused.positions.clone(), tris).expect("manifold");
        assert!(m.is_closed() && m.nonmanifold_vertices().is_empty());
        // Unpinched: no two vertices share a position.
        let mut at: Vec<[u32; 3]> = fused.positions.iter().map(|p| p.as_vec3().to_array().map(f32::to_bits)).collect();
        at.sort_unstable();
        assert!(at.windows(2).all(|w| w[0] != w[1]));
        let (volume, chi) = (m.signed_volume(), m.euler_characteristic());
        assert_eq!(fused.colours, vec![[255, 0, 0, 255]; fused.indices.len() / 3]);
        (fused, volume, chi)
    }

    /// Two cubes touching only along an edge (a union leaves four faces on
    /// it) fuse into one closed solid of about their volume, with a bridge.
    #[test]
    fn cubes_touching_along_an_edge_become_one_solid() {
        let (fused, volume, chi) = fuse_boxes(&[(DVec3::ZERO, DVec3::ONE), (DVec3::new(1.0, 1.0, 0.0), DVec3::new(2.0, 2.0, 1.0))], 0.02);
        assert_eq!(chi, 2, "one piece, no hole");
        assert!(fused.stats.bridges >= 1);
        assert!((volume - 2.0).abs() < 0.02, "{volume}");
    }

    /// Cubes further apart than twice the closing radius stay two pieces;
    /// nearer, they are bridged.
    #[test]
    fn a_gap_closes_only_below_twice_the_closing_radius() {
        let apart = [(DVec3::ZERO, DVec3::ONE), (DVec3::new(1.1, 0.0, 0.0), DVec3::new(2.1, 1.0, 1.0))];
        let (fused, _, chi) = fuse_boxes(&apart, 0.03);
        assert_eq!((chi, fused.stats.bridges), (4, 0), "two pieces");
        let (fused, volume, chi) = fuse_boxes(&apart, 0.08);
        assert_eq!((chi, fused.stats.bridges), (2, 1), "bridged");
        assert!(volume > 2.0 && volume < 2.1, "{volume}");
    }

    /// Six slabs closing a hollow box print as the solid box: the void is filled.
    #[test]
    fn an_enclosed_void_is_filled() {
        let (lo, hi, t) = (DVec3::ZERO, DVec3::splat(1.0), 0.2);
        let slabs: Vec<(DVec3, DVec3)> = (0..3)
            .flat_map(|axis| {
                let mut a_hi = hi;
                a_hi[axis] = t;
                let mut b_lo = lo;
                b_lo[axis] = 1.0 - t;
                [(lo, a_hi), (b_lo, hi)]
            })
            .collect();
        let (fused, volume, chi) = fuse_boxes(&slabs, 0.02);
        assert_eq!((chi, fused.stats.voids), (2, 1));
        assert!((volume - 1.0).abs() < 0.02, "{volume}");
    }
}
