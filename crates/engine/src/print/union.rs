//! Parts of a model and their boolean union.

use super::PrintError;
use crate::core::budget::Budget;
use crate::geom::halfedge::HalfEdgeMesh;
use crate::geom::NamedMesh;
use glam::DVec3;
use std::collections::HashMap;

/// A closed, outward part borrowed for a union or a colour search: its
/// positions and its CCW triangles (a [`HalfEdgeMesh`]'s, or a united
/// subtree's from `subtree`).
pub(super) type Piece<'a> = (&'a [DVec3], &'a [[u32; 3]]);

/// The pieces of closed half-edge parts.
pub(super) fn pieces(parts: &[HalfEdgeMesh]) -> Vec<Piece<'_>> {
    parts.iter().map(|p| (p.positions.as_slice(), p.triangles())).collect()
}

/// The closed parts of a model, and how many open ones were left out.
pub(super) struct Parts {
    /// Closed, outward-oriented parts.
    pub closed: Vec<HalfEdgeMesh>,
    /// The model's colour of each triangle of each closed part (parallel to
    /// `closed` and to each part's triangles): what the union's triangles
    /// take their colour from.
    pub colours: Vec<Vec<[u8; 4]>>,
    /// Parts that are open or not manifold and were left out.
    pub skipped: u64,
    /// Parts that are open or not manifold (free-vertex surfaces, loose
    /// triangles) and were thickened into walls, the model having no solid.
    pub thickened: u64,
    /// The smallest bounding-box side over the closed parts (model units):
    /// an estimate of the thinnest feature.
    pub min_extent: f64,
}

/// Most triangles of open or non-manifold parts that are thickened into
/// walls (each becomes a prism of its own for the union, eight triangles):
/// a surface of 10⁵ free triangles must not make a union of 10⁵ prisms.
pub(crate) const MAX_THICKENED_TRIANGLES: usize = 5_000;

/// Welds each mesh by exact position (never across meshes: touching parts
/// must stay apart) and splits its triangles into connected components, each
/// checked as a closed manifold. Components that are not (open surfaces,
/// loose triangles) are left out, unless no component is closed: then each
/// of their triangles becomes a prism `wall` thick, centred on the triangle,
/// if they have at most [`MAX_THICKENED_TRIANGLES`]; `wall` 0 never thickens.
pub(super) fn split_parts(meshes: &[NamedMesh], wall: f64, budget: &mut Budget) -> Result<Parts, PrintError> {
    let triangles: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    budget.charge_steps(triangles)?;
    let mut positions: Vec<DVec3> = Vec::new();
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(triangles as usize);
    let mut colours: Vec<[u8; 4]> = Vec::with_capacity(triangles as usize);
    for m in meshes {
        // Each mesh welds on its own: touching parts of different meshes stay apart.
        let (distinct, remap) = crate::geom::weld::weld_by(m.mesh.positions.iter().copied(), crate::geom::weld::f32_key);
        // Fits: the vertex total is bounded by the meshes' u32 indices.
        let base = positions.len() as u32;
        positions.extend(distinct.iter().map(|p| DVec3::from_array(p.map(f64::from))));
        for (k, t) in crate::geom::weld::welded_triangles(&m.mesh.indices, &remap) {
            tris.push(t.map(|i| i + base));
            // Light grey for a mesh without colours.
            colours.push(m.mesh.triangle_colour(k).unwrap_or(super::PLAIN));
        }
    }
    // Union-find over vertices joined by triangles.
    let mut parent = super::joined_through_triangles(positions.len(), tris.iter().map(|t| t.as_slice()));
    // Group triangles (their indices) by root, in order of first appearance (deterministic).
    let mut group_of: HashMap<u32, usize> = HashMap::new();
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (k, t) in tris.iter().enumerate() {
        let r = super::find_root(&mut parent, t[0]);
        let g = *group_of.entry(r).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(k);
    }
    let mut parts = Parts { closed: Vec::new(), colours: Vec::new(), skipped: 0, thickened: 0, min_extent: f64::INFINITY };
    // The open or non-manifold groups (their triangles' indices), and why the first one is not a solid.
    let mut open: Vec<Vec<usize>> = Vec::new();
    let mut why: Option<String> = None;
    for g in groups {
        let mut local: HashMap<u32, u32> = HashMap::new();
        let mut pos = Vec::new();
        let local_tris: Vec<[u32; 3]> = g
            .iter()
            .map(|&k| {
                tris[k].map(|v| {
                    *local.entry(v).or_insert_with(|| {
                        pos.push(positions[v as usize]);
                        (pos.len() - 1) as u32
                    })
                })
            })
            .collect();
        let flipped: Vec<[u32; 3]> = local_tris.iter().map(|t| [t[0], t[2], t[1]]).collect();
        // Why it is not a solid, and whether it can become a wall: only open
        // surfaces can; one that touches itself (the Koch curve's tube)
        // would become a hollow shell of itself.
        let (reason, thickenable) = match HalfEdgeMesh::new(pos.clone(), local_tris) {
            Ok(m) if m.is_closed() && m.nonmanifold_vertices().is_empty() => {
                let m = if m.signed_volume() < 0.0 { HalfEdgeMesh::new(pos, flipped).unwrap_or(m) } else { m };
                let (lo, hi) = super::bounds(m.positions.iter().copied());
                parts.min_extent = parts.min_extent.min((hi - lo).min_element());
                parts.closed.push(m);
                parts.colours.push(g.iter().map(|&k| colours[k]).collect());
                continue;
            }
            Ok(m) if !m.is_closed() => (format!("it is an open surface ({} boundary edges)", m.boundary_edges().len()), true),
            Ok(m) => (format!("its surface is pinched at {} vertices", m.nonmanifold_vertices().len()), false),
            Err(e) => (format!("its surface touches or crosses itself ({e})"), false),
        };
        why.get_or_insert(reason);
        if thickenable {
            open.push(g);
        } else {
            parts.skipped += 1;
        }
    }
    // A model of surfaces only is printed as walls. Next to solids, loose
    // surfaces are left out: they would meet the solids only along edges.
    let open_triangles: usize = open.iter().map(Vec::len).sum();
    if parts.closed.is_empty() && wall > 0.0 && open_triangles <= MAX_THICKENED_TRIANGLES {
        budget.charge_steps(open_triangles as u64 * 8)?;
        for &k in open.iter().flatten() {
            if let Some(p) = prism(&tris[k].map(|v| positions[v as usize]), wall) {
                parts.colours.push(vec![colours[k]; p.face_count()]);
                parts.closed.push(p);
            }
        }
        parts.thickened = open.len() as u64;
        parts.min_extent = wall;
    } else {
        parts.skipped += open.len() as u64;
    }
    let total = parts.skipped + parts.thickened + parts.closed.len() as u64;
    if parts.closed.is_empty() {
        let why = why.unwrap_or_else(|| "it has no triangles".into());
        let size = if open_triangles > MAX_THICKENED_TRIANGLES {
            format!("; its {open_triangles} triangles are too many to thicken into walls (at most {MAX_THICKENED_TRIANGLES})")
        } else {
            String::new()
        };
        return Err(PrintError::NothingPrintable(format!("none of the model's {total} parts is a closed solid: the first is not because {why}{size}")));
    }
    Ok(parts)
}

/// The closed prism `wall` thick whose middle is the triangle `t`, wound
/// outward; `None` for a triangle with no area (it has no normal).
fn prism(t: &[DVec3; 3], wall: f64) -> Option<HalfEdgeMesh> {
    let n = (t[1] - t[0]).cross(t[2] - t[0]).try_normalize()?;
    let h = n * (wall / 2.0);
    // 0..3 the top (+n side, wound like t), 3..6 the bottom.
    let positions: Vec<DVec3> = t.iter().map(|p| *p + h).chain(t.iter().map(|p| *p - h)).collect();
    let mut tris = vec![[0, 1, 2], [3, 5, 4]];
    for i in 0..3u32 {
        let j = (i + 1) % 3;
        tris.push([i, i + 3, j + 3]);
        tris.push([i, j + 3, j]);
    }
    HalfEdgeMesh::new(positions, tris).ok().filter(|m| m.is_closed() && m.signed_volume() > 0.0)
}

/// Bits of precision a part's coordinates keep below the largest coordinate
/// of the model: coordinates are snapped to a grid of `2^(e - SNAP_BITS)`,
/// where `2^e` bounds every coordinate (about a millionth of the model).
pub(crate) const SNAP_BITS: i32 = 20;

/// The snapping grid of `parts`: a power of two such that every coordinate
/// is less than `2^SNAP_BITS` steps from the origin (so a snapped coordinate
/// is exact in `f32`); 0 for no snapping (an empty or degenerate model).
///
/// Why: parts that share a face in exact arithmetic (a Menger sponge's
/// cubes, placed by different chains of transforms) come out of `f32`
/// meshing a few ulps apart, overlapping or leaving gaps of 10⁻⁸. Manifold
/// keeps those slivers exactly, and the level-3 sponge came out as 1,506
/// pieces around them. On the grid such faces coincide exactly and fuse.
pub(super) fn snap_grid(parts: &[Piece<'_>]) -> f64 {
    let largest = parts.iter().flat_map(|p| p.0.iter()).map(|q| q.abs().max_element()).fold(0.0, f64::max);
    if !(largest > 0.0 && largest.is_finite()) {
        return 0.0;
    }
    // largest = f · 2^e with f in [0.5, 1): every coordinate is below 2^e.
    let (_, e) = libm::frexp(largest);
    libm::ldexp(1.0, e - SNAP_BITS)
}

/// `q` on the grid of step `grid` (a power of two, so each step is exact).
pub(super) fn snap(q: DVec3, grid: f64) -> DVec3 {
    if grid > 0.0 {
        (q / grid).round() * grid
    } else {
        q
    }
}

/// The union of closed parts, by Manifold's batch union, as shared
/// positions and CCW triangles, their vertices snapped to `grid` first (0:
/// not snapped; [`snap_grid`] says why and `make_printable` when).
pub(super) fn unite(parts: &[Piece<'_>], grid: f64, budget: &mut Budget) -> Result<(Vec<DVec3>, Vec<u32>), PrintError> {
    let total: u64 = parts.iter().map(|p| p.1.len() as u64).sum();
    crate::core::memprobe::note("union.input", total);
    let bytes = total.saturating_mul(MANIFOLD_UNION_BYTES);
    budget.reserve_memory(bytes)?;
    budget.charge_steps(total.saturating_mul(8))?;
    let (positions, indices) = batch_union(parts, grid, budget)?;
    budget.release_memory(bytes);
    Ok((positions.iter().map(|p| glam::Vec3::from_array(*p).as_dvec3()).collect(), indices))
}

/// Bytes charged per triangle that enters a Manifold union, for the
/// whole union: the inputs' Manifolds (half-edges, normals, relations,
/// collider; a lazily placed copy made real when the boolean reads it),
/// the boolean's intermediate data and the result. Measured
/// (RULEMESH_MEMORY_TRACE, glibc's mmap threshold fixed as `main` sets
/// it): the Sierpinski bush's top union, 999,210 triangles in, took the
/// process 552 MiB over its idle size, 580 bytes a triangle; 600 bounds
/// it (docs/print.md, "Memory"). It was 200 before issue 38, a third of
/// what Manifold really held.
pub(super) const MANIFOLD_UNION_BYTES: u64 = 600;

/// One batch union of `parts`, their vertices snapped to `grid` (0: not
/// snapped), cancelled at the budget's deadline.
fn batch_union(parts: &[Piece<'_>], grid: f64, budget: &Budget) -> Result<(Vec<[f32; 3]>, Vec<u32>), PrintError> {
    let manifolds: Vec<manifold_rs::Manifold> = parts
        .iter()
        .map(|p| {
            let verts: Vec<f32> = p.0.iter().flat_map(|q| snap(*q, grid).as_vec3().to_array()).collect();
            let idx: Vec<u32> = p.1.iter().flatten().copied().collect();
            manifold_rs::Manifold::from_mesh(manifold_rs::Mesh::new(&verts, &idx))
        })
        .collect();
    budget.check_deadline()?;
    // One batch union, not a tree of pairwise ones: Manifold composes parts
    // whose boxes are disjoint without a boolean and unites the rest
    // smallest first. Pairwise, parts touching only along an edge (diagonal
    // cubes of the level-3 sponge) were united before the part that fills
    // the corner between them, and the seam they left survived as edges of
    // four faces. The union cannot check the budget itself, so it is
    // cancelled at the deadline (at least a millisecond from now).
    let timeout = budget.time_left().map(|t| u64::try_from(t.as_millis()).unwrap_or(u64::MAX).max(1));
    let result = manifold_rs::Manifold::batch_union(&manifolds, timeout);
    drop(manifolds);
    if result.status() == manifold_rs::Manifold::CANCELLED {
        budget.check_deadline()?;
        return Err(PrintError::Union("cancelled at the deadline".into()));
    }
    if result.is_empty() {
        return Err(PrintError::Union("the union is empty (a part was rejected by Manifold)".into()));
    }
    Ok(triangles_of(&result))
}

/// A manifold's positions (the first three of each vertex's properties)
/// and triangles.
pub(super) fn triangles_of(m: &manifold_rs::Manifold) -> (Vec<[f32; 3]>, Vec<u32>) {
    let mesh = m.to_mesh();
    let props = mesh.num_props().max(3) as usize;
    let positions: Vec<[f32; 3]> = mesh.vertices().chunks_exact(props).map(|v| [v[0], v[1], v[2]]).collect();
    (positions, mesh.indices())
}
