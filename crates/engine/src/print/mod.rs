//! Printable output (`print=true`, `rulemesh render --print`): every part of
//! the model merged into one watertight, manifold, outward-oriented solid by
//! a robust boolean union, scaled to millimetres, with a printability report.
//!
//! A grammar's output is many overlapping closed parts (one per primitive
//! instance); a slicer needs their union, not their sum. Parts are found as
//! connected components of the welded triangles, checked with the half-edge
//! structure (open or non-manifold ones are left out and the report says
//! so), turned outward, and united by Manifold (`manifold-rs`), whose exact
//! predicates keep the result manifold even where surfaces touch.

mod bvh;
mod colour;
mod edt;
mod field;
pub mod findings;
mod fuse;
pub mod profile;
mod report;
mod rigid;
mod solid;
mod subtree;
mod tetra;
pub mod thickness;
mod union;

pub(crate) use profile::PrinterProfile;
pub use report::{measure, PrintSummary};
pub(crate) use report::PrintReport;

use crate::core::budget::{Budget, LimitExceeded};
use crate::geom::{Mesh, NamedMesh};
use crate::model::Hierarchy;
use serde::{Deserialize, Serialize};

/// What a request asks of printable output. Part of the export options (and
/// so of the cache key).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct PrintOptions {
    /// Merge into one printable solid.
    pub enabled: bool,
    /// Target length of the longest side in micrometres (0: one model unit is one millimetre).
    pub size_um: u32,
    /// Answer with the JSON printability report instead of the model.
    pub report: bool,
    /// What the printer can make: the report's findings are judged against
    /// it, and open surfaces are thickened to its minimum wall.
    pub profile: PrinterProfile,
}

/// The colour of a triangle whose mesh has none (linear RGBA8, light grey).
pub(crate) const PLAIN: [u8; 4] = [200, 200, 200, 255];

/// The thickest wall an open surface is given, as a fraction of the model's
/// longest side.
pub(crate) const MAX_WALL_FRACTION: f64 = 0.05;

/// Why no printable solid could be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PrintError {
    /// A limit ran out.
    #[error(transparent)]
    Limit(#[from] LimitExceeded),
    /// No part of the model is a closed solid.
    #[error("nothing printable: {0}")]
    NothingPrintable(String),
    /// The boolean union failed.
    #[error("boolean union failed: {0}")]
    Union(String),
    /// The model is pieces that do not touch, even with the gaps narrower
    /// than the printer resolves closed: a print would fall apart.
    #[error("separate_shells: the model is {shells} separate pieces that do not touch (gaps narrower than {gap_mm:.3} mm were closed; the rest are wider); print them one by one, or connect them in the grammar")]
    SeparatePieces {
        /// How many pieces.
        shells: u64,
        /// Gaps narrower than this were closed (mm).
        gap_mm: f64,
    },
    /// The size is out of range.
    #[error("size_mm must be in (0, 10000], found {0}")]
    BadSize(f64),
    /// The printer profile's minimum wall is out of range.
    #[error("min_wall_mm must be in (0, 100], found {0}")]
    BadMinWall(f64),
    /// The printer profile's build volume is not three sizes in range.
    #[error("build_volume_mm: {0}")]
    BadBuildVolume(String),
    /// The printer profile's triangle ceiling is out of range.
    #[error("triangle_ceiling must be in 1..=100000000, found {0}")]
    BadTriangleCeiling(u64),
}

impl PrintError {
    /// Whether the request's print options are at fault (a 400), not the model.
    pub fn is_bad_option(&self) -> bool {
        matches!(self, PrintError::BadSize(_) | PrintError::BadMinWall(_) | PrintError::BadBuildVolume(_) | PrintError::BadTriangleCeiling(_))
    }
}

/// Reads a `size_mm` value into micrometres.
pub(crate) fn size_um(size_mm: f64) -> Result<u32, PrintError> {
    if !(size_mm > 0.0 && size_mm <= 10_000.0) {
        return Err(PrintError::BadSize(size_mm));
    }
    Ok((size_mm * 1000.0).round().max(1.0) as u32)
}

/// Unites every closed part of `meshes` into one solid in millimetres and
/// measures it. The result is one mesh named "print" with flat normals.
/// With `options.report`, also measures the walls and judges the result
/// against the printer profile (the findings); without, the report is only
/// the measurements the response headers need.
pub(crate) fn make_printable(meshes: &[NamedMesh], options: &PrintOptions, budget: &mut Budget) -> Result<(Vec<NamedMesh>, PrintReport), PrintError> {
    options.profile.validate()?;
    let min_wall = options.profile.min_wall_mm();
    // Open surfaces become walls of the thinnest printable thickness at the
    // printed size (the profile's minimum wall), but at most 5 % of the model
    // (a 1-unit-is-1-mm model would otherwise turn into a blob of 0.8 mm walls).
    let (lo, hi) = bounds(meshes.iter().flat_map(|m| m.mesh.positions.iter()).map(|p| glam::Vec3::from_array(*p).as_dvec3()));
    let extent = (hi - lo).max_element();
    // The walls themselves add up to their thickness w to the longest side,
    // so the final scale is at least size / (extent + w): w = m · (extent + w)
    // / size keeps them at the minimum m or more once scaled.
    let wall = if extent > 0.0 && extent.is_finite() {
        let size = f64::from(options.size_um) / 1000.0;
        let w = match options.size_um {
            0 => min_wall,
            _ if size > min_wall => min_wall * extent / (size - min_wall),
            _ => f64::INFINITY,
        };
        w.min(MAX_WALL_FRACTION * extent)
    } else {
        0.0
    };
    let parts = union::split_parts(meshes, wall, budget)?;
    crate::core::memprobe::mark("print.parts", budget);
    let pieces = union::pieces(&parts.closed);
    let summary = PartSummary { parts: parts.closed.len() as u64, skipped: parts.skipped, thickened: parts.thickened, min_extent: parts.min_extent, wall, fused: None };
    // The exact union first: a model that prints as one watertight shell
    // prints exactly as modelled. A model of more triangles than
    // EXACT_MAX_TRIANGLES goes straight to fusing: which route a model takes
    // depends on the model alone, never on how fast the machine is, so the
    // same request gives the same bytes everywhere (or the same refusal).
    let mark = budget.mark();
    let triangles: usize = pieces.iter().map(|p| p.1.len()).sum();
    let exact = if triangles <= EXACT_MAX_TRIANGLES { exact_union(&pieces, options.size_um, budget)? } else { None };
    crate::core::memprobe::mark("print.exact_union", budget);
    if let Some((placed, measured)) = exact {
        let colours = colour::triangle_colours(&pieces, &parts.colours, &placed.united.0, &placed.united.1, budget)?;
        return finish(placed, measured, &colours, &summary, options, budget);
    }
    // The exact unions' work is thrown away: refunded (the clock goes on).
    budget.rewind(mark);
    fused(&pieces, &parts.colours, extent, summary, options, budget)
}

/// Contacts become connections: `pieces` (closed, outward) fused into one
/// solid with gaps narrower than the printer's minimum wall at the printed
/// size closed (but at most a hundredth of `extent`, the model's longest
/// side, so that a model printed at its 1-unit-is-1-mm size does not melt
/// into a blob), and the surface re-extracted; refused as separate pieces
/// if it is still more than one (unless the report is asked for).
fn fused(pieces: &[union::Piece<'_>], colours: &[Vec<[u8; 4]>], extent: f64, summary: PartSummary, options: &PrintOptions, budget: &mut Budget) -> Result<(Vec<NamedMesh>, PrintReport), PrintError> {
    // The printed scale: the fused solid spans the parts' box (thickened
    // walls included), whose longest side becomes `size_mm`.
    let (plo, phi) = bounds(pieces.iter().flat_map(|p| p.0.iter().copied()));
    let pieces_extent = (phi - plo).max_element();
    let scale = match options.size_um {
        _ if !(pieces_extent > 0.0 && pieces_extent.is_finite()) => 1.0,
        0 => 1.0,
        size => f64::from(size) / 1000.0 / pieces_extent,
    };
    let closing = (options.profile.min_wall_mm() / 2.0 / scale).min(CLOSING_FRACTION * extent);
    let fused = fuse::fuse(pieces, colours, closing, budget)?;
    let summary = PartSummary { fused: Some(fused.stats), ..summary };
    let placed = place_charged((fused.positions, fused.indices), options.size_um, budget)?;
    let measured = measure(&placed.scaled, &placed.indices);
    if measured.shells > 1 && !options.report {
        return Err(PrintError::SeparatePieces { shells: measured.shells, gap_mm: fused.stats.gap() * placed.scale });
    }
    finish(placed, measured, &fused.colours, &summary, options, budget)
}

/// The largest closing radius of the fused route, as a fraction of the
/// model's longest side: a model printed at its own size (one unit a
/// millimetre, often a few millimetres across) would otherwise have every
/// gap under the printer's minimum wall closed, detail and all.
pub(crate) const CLOSING_FRACTION: f64 = 0.01;

/// Most triangles (over all parts) for which the exact union is tried
/// before fusing. Its cost grows with the triangles that overlap: the
/// largest model here that prints exactly is hogeweg's 50,208 triangles
/// (1.1 s); the knot's, spiral-rings' and sic-lattice's 96,000 to 98,304
/// took most of the deadline to come out not watertight, or ran past it,
/// and fused they print in 2 to 9 s. Above it a flat model is fused
/// (sampled), so the pipeline keeps a language's own-geometry hierarchy for
/// printing only above it (`Route::keeps_hierarchy`): an L-system's capped
/// segments are then united exactly once per distinct subtree (the
/// Sierpinski bush: one exact shell in about 5 s, where fusing cannot
/// resolve its tubes within the limits); below, the turtle's mitred sweeps
/// are united exactly, and the print is what it always was.
pub const EXACT_MAX_TRIANGLES: usize = 64_000;

/// The exact union of `pieces`, placed, if it is one watertight shell:
/// snapped to a grid first (src/print/union.rs, `snap_grid`: parts that
/// share faces in exact arithmetic then share them exactly and fuse).
/// Snapping also moves curved parts by up to half a step, which can turn a
/// near miss into a contact along an edge (the truncated icosahedron's
/// tubes and balls: four edges of four faces), so if the snapped result has
/// edges not shared by exactly two faces, the parts are united again
/// unsnapped. `None` if neither is one watertight shell; else the union
/// placed, with its measurements.
fn exact_union(pieces: &[union::Piece<'_>], size_um: u32, budget: &mut Budget) -> Result<Option<(Placed, PrintReport)>, PrintError> {
    for grid in [union::snap_grid(pieces), 0.0] {
        let united = union::unite(pieces, grid, budget)?;
        let placed = place_charged(united, size_um, budget)?;
        let measured = measure(&placed.scaled, &placed.indices);
        if measured.nonmanifold_edges == 0 {
            // Unsnapped, pieces apart stay apart: no second try.
            return Ok((measured.is_watertight && measured.shells == 1).then_some((placed, measured)));
        }
        budget.release_memory(placed.charged);
    }
    Ok(None)
}

/// Unites the expansion of an instancing hierarchy (shapes at `detail`)
/// once per distinct object, children first (`subtree`), and measures it as
/// [`make_printable`] does. `None` when the flat route must decide instead:
/// a leaf shape is not one closed solid, or the union has edges not shared
/// by exactly two faces or is several pieces (the flat route then tries the
/// parts snapped to the model's grid and unsnapped, then fusing).
pub(crate) fn make_printable_hierarchy(h: &Hierarchy, detail: u32, options: &PrintOptions, budget: &mut Budget) -> Result<Option<(Vec<NamedMesh>, PrintReport)>, PrintError> {
    options.profile.validate()?;
    // The flat route charges its own work: what this one did is refunded if it gives up.
    let mark = budget.mark();
    let united = subtree::unite_hierarchy(h, detail, budget)?;
    crate::core::memprobe::mark("print.hierarchy_union", budget);
    let Some(united) = united else {
        budget.rewind(mark);
        return Ok(None);
    };
    let subtree::United { solid, parts, min_extent } = united;
    let indices: Vec<u32> = solid.tris.iter().flatten().copied().collect();
    let placed = place_charged((solid.positions, indices), options.size_um, budget)?;
    let measured = measure(&placed.scaled, &placed.indices);
    let summary = PartSummary { parts, skipped: 0, thickened: 0, min_extent, wall: 0.0, fused: None };
    if measured.nonmanifold_edges == 0 && measured.shells == 1 {
        return finish(placed, measured, &solid.colours, &summary, options, budget).map(Some);
    }
    if !h.is_scaled() {
        // A rigid hierarchy's union (L-systems': capped segments) is one
        // closed surface in Manifold, but where parts only kiss, at a point
        // or along an edge (a plant's leaf on its twig), its vertices meet
        // once written in f32, or it is pieces: fused, as the flat route
        // would fuse its parts, but from the union, whose triangles are a
        // fraction of the parts' (and without expanding the segments).
        let Placed { united: (positions, _), charged, .. } = placed;
        budget.release_memory(charged);
        let (lo, hi) = bounds(positions.iter().copied());
        let extent = (hi - lo).max_element();
        let tris = solid.tris;
        return fused(&[(positions.as_slice(), tris.as_slice())], &[solid.colours], extent, summary, options, budget).map(Some);
    }
    budget.rewind(mark);
    Ok(None)
}

/// What the report says of the parts that went into a union.
struct PartSummary {
    /// Closed parts united (thickening prisms included).
    parts: u64,
    /// Open or non-manifold parts left out.
    skipped: u64,
    /// Open parts thickened into walls.
    thickened: u64,
    /// The smallest bounding-box side of a part (model units).
    min_extent: f64,
    /// The thickness walls were given (model units).
    wall: f64,
    /// What fusing did, when the parts were fused (`fuse`) rather than
    /// united exactly.
    fused: Option<fuse::FuseStats>,
}

/// The printed mesh and its report from a placed union, its measurements
/// ([`measure`], taken by the caller to decide on it) and the colour of each
/// of its (unplaced) triangles.
fn finish(placed: Placed, mut report: PrintReport, colours: &[[u8; 4]], parts: &PartSummary, options: &PrintOptions, budget: &mut Budget) -> Result<(Vec<NamedMesh>, PrintReport), PrintError> {
    crate::core::memprobe::note("finish.triangles", placed.indices.len() as u64 / 3);
    let Placed { scaled, indices, kept, scale, voids, charged, .. } = placed;
    let colours: Vec<[u8; 4]> = kept.iter().map(|&k| colours.get(k).copied().unwrap_or(PLAIN)).collect();
    let mesh = flat_mesh(&scaled, &indices, &colours);
    report.parts = parts.parts;
    report.skipped_parts = parts.skipped;
    report.thickened_parts = parts.thickened;
    report.wall_mm = if parts.thickened > 0 { parts.wall * scale } else { 0.0 };
    report.min_feature_mm = parts.min_extent * scale;
    report.scale = scale;
    report.filled_voids = voids;
    if let Some(f) = parts.fused {
        report.fused_gap_mm = f.gap() * scale;
        report.bridges = f.bridges;
        report.sample_mm = f.spacing * scale;
        report.filled_voids += f.voids;
    }
    if options.report {
        let min_wall = options.profile.min_wall_mm();
        let walls = thickness::measure_walls(&scaled, &indices, min_wall, budget)?;
        report.thinnest_wall_mm = walls.thinnest.map(|w| w.0);
        report.thinnest_wall_at_mm = walls.thinnest.map(|w| w.1);
        report.wall_rays = walls.rays;
        report.thin_wall_places = walls.thin;
        report.thin_wall_area_mm2 = walls.thin_area;
        report.judge(&options.profile);
    }
    budget.release_memory(charged);
    Ok((vec![NamedMesh { name: "print".into(), mesh }], report))
}

/// A union placed on the build plate: in millimetres, +Z up, its short
/// edges collapsed and its flat pieces dropped.
struct Placed {
    /// The union as Manifold gave it (model units, Y up): what colours are
    /// looked up against.
    united: (Vec<glam::DVec3>, Vec<u32>),
    /// Placed positions (mm).
    scaled: Vec<[f32; 3]>,
    /// Placed triangles.
    indices: Vec<u32>,
    /// Each placed triangle's index in `united`.
    kept: Vec<usize>,
    /// Millimetres per model unit.
    scale: f64,
    /// Enclosed voids filled (their walls dropped).
    voids: u64,
    /// Accounted memory of placing and finishing it ([`FINISH_BYTES_PER_TRIANGLE`]),
    /// released by [`finish`].
    charged: u64,
}

/// Bytes charged per triangle of a union while it is placed, measured and
/// written as the flat-shaded print mesh: the union read back (f64
/// positions, triangles, colours), its placed f32 copy, the edge
/// collapse's and shell search's maps, and the flat mesh (three vertices
/// with normal and colour per triangle). Measured (RULEMESH_MEMORY_TRACE):
/// the Sierpinski bush's 1,007,446 triangles take 152 MiB over the union
/// read back, 158 bytes a triangle; 200 bounds it (docs/print.md, "Memory").
pub(crate) const FINISH_BYTES_PER_TRIANGLE: u64 = 200;

/// Places `united` as [`place`] does, after charging its finishing to
/// `budget` (refused by the memory limit before anything is allocated).
fn place_charged(united: (Vec<glam::DVec3>, Vec<u32>), size_um: u32, budget: &mut Budget) -> Result<Placed, LimitExceeded> {
    let charged = (united.1.len() as u64 / 3).saturating_mul(FINISH_BYTES_PER_TRIANGLE);
    budget.reserve_memory(charged)?;
    Ok(Placed { charged, ..place(united, size_um) })
}

/// Places a union (`size_um` 0: one model unit is a millimetre).
fn place(united: (Vec<glam::DVec3>, Vec<u32>), size_um: u32) -> Placed {
    // Models are Y-up (glTF, the preview: a tower grows along +Y); printers
    // build along +Z (3MF's build direction, slicers' convention). Turning
    // +Y to +Z (a rotation, so winding and volume are kept) stands a tower
    // or a vase on its foot and lays a gear or a pendant drawn in the XZ
    // plane flat on the plate.
    let positions: Vec<glam::DVec3> = united.0.iter().map(|p| glam::DVec3::new(p.x, -p.z, p.y)).collect();
    let (lo, hi) = bounds(positions.iter().copied());
    let longest = (hi - lo).max_element();
    let scale = if size_um > 0 && longest > 0.0 { f64::from(size_um) / 1000.0 / longest } else { 1.0 };
    // Rest the solid on z = 0, centred in x and y: how a slicer places it anyway.
    let offset = glam::DVec3::new(-(lo.x + hi.x) / 2.0, -(lo.y + hi.y) / 2.0, -lo.z);
    let scaled: Vec<[f32; 3]> = positions.iter().map(|p| ((*p + offset) * scale).as_vec3().to_array()).collect();
    // Manifold leaves edges a few f32 ulps long, which slicers and checkers
    // (trimesh merges within 1e-8) fuse into non-manifold edges: collapse
    // edges shorter than a millionth of the size.
    let (scaled, indices, kept) = collapse_short_edges(scaled, &united.1, (longest * scale) * 1e-6);
    let (indices, kept, voids) = drop_flat_shells(&scaled, indices, kept);
    Placed { united, scaled, indices, kept, scale, voids, charged: 0 }
}

/// Merges the two ends of every edge shorter than `eps` (and vertices at
/// identical positions), then drops the triangles that thereby lose an edge;
/// also gives the index of each kept triangle in `indices`.
/// Collapsing only along edges keeps the surface closed and manifold; merging
/// unconnected near points could pinch it.
fn collapse_short_edges(positions: Vec<[f32; 3]>, indices: &[u32], eps: f64) -> (Vec<[f32; 3]>, Vec<u32>, Vec<usize>) {
    let mut root: Vec<u32> = (0..positions.len() as u32).collect();
    let at = |i: u32| glam::Vec3::from_array(positions.get(i as usize).copied().unwrap_or([0.0; 3])).as_dvec3();
    for t in indices.chunks_exact(3) {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if at(a).distance(at(b)) < eps {
                let (ra, rb) = (find_root(&mut root, a), find_root(&mut root, b));
                if ra != rb {
                    // Keep the lower index: deterministic whatever the triangle order.
                    root[ra.max(rb) as usize] = ra.min(rb);
                }
            }
        }
    }
    let merged: Vec<[f32; 3]> = (0..positions.len() as u32).map(|v| positions[find_root(&mut root, v) as usize]).collect();
    let (welded, remap) = crate::geom::weld::weld_by(merged, crate::geom::weld::f32_key);
    let mut out = Vec::with_capacity(indices.len());
    let mut kept = Vec::with_capacity(indices.len() / 3);
    for (k, t) in crate::geom::weld::welded_triangles(indices, &remap) {
        out.extend_from_slice(&t);
        kept.push(k);
    }
    (welded, out, kept)
}

/// Most volume a connected piece of the union may have, relative to the cube
/// of its bounding box's diagonal, and still count as flat (no material).
pub(crate) const FLAT_SHELL: f64 = 1e-6;

/// Drops the connected pieces of the mesh that enclose no volume: pairs of
/// triangles back to back, or flat fans, that Manifold 3.5.4 leaves beside
/// the solid where faces of parts coincide (the ring's 6-triangle sheet
/// 0.8 mm across, the lamp shade's 4-triangle one; |volume| about 10⁻⁹ of
/// their diagonal cubed, a real piece 10⁻³ or more). They print nothing and
/// would count as separate shells. Also fills enclosed voids: a piece
/// wound inward (negative volume) is the wall of a cavity inside the solid
/// (where tubes cross, the Sierpinski bush's union closes 18 tetrahedral
/// pockets of 3·10⁻⁷ mm³), which would trap resin or powder and count as
/// a shell; dropping its wall fills it, as fusing fills voids. Keeps
/// everything if nothing would be left. Also filters `kept` (each
/// triangle's index in the union) alike, and says how many voids it filled.
fn drop_flat_shells(positions: &[[f32; 3]], indices: Vec<u32>, kept: Vec<usize>) -> (Vec<u32>, Vec<usize>, u64) {
    let mut root = joined_through_triangles(positions.len(), indices.chunks_exact(3));
    let at = |i: u32| glam::Vec3::from_array(positions.get(i as usize).copied().unwrap_or([0.0; 3])).as_dvec3();
    // Per piece (by root): signed volume and bounding box.
    let mut pieces: std::collections::BTreeMap<u32, (f64, glam::DVec3, glam::DVec3)> = std::collections::BTreeMap::new();
    for t in indices.chunks_exact(3) {
        let (a, b, c) = (at(t[0]), at(t[1]), at(t[2]));
        let r = find_root(&mut root, t[0]);
        let e = pieces.entry(r).or_insert((0.0, glam::DVec3::splat(f64::INFINITY), glam::DVec3::splat(f64::NEG_INFINITY)));
        e.0 += a.dot(b.cross(c)) / 6.0;
        e.1 = e.1.min(a).min(b).min(c);
        e.2 = e.2.max(a).max(b).max(c);
    }
    let flat = |v: f64, lo: glam::DVec3, hi: glam::DVec3| v.abs() <= FLAT_SHELL * (hi - lo).length().powi(3);
    let dropped: std::collections::BTreeSet<u32> = pieces.iter().filter(|(_, (v, lo, hi))| *v < 0.0 || flat(*v, *lo, *hi)).map(|(r, _)| *r).collect();
    if dropped.is_empty() || dropped.len() == pieces.len() {
        return (indices, kept, 0);
    }
    let voids = pieces.iter().filter(|(r, (v, lo, hi))| dropped.contains(r) && !flat(*v, *lo, *hi)).count() as u64;
    let mut out = Vec::with_capacity(indices.len());
    let mut out_kept = Vec::with_capacity(kept.len());
    for (t, k) in indices.chunks_exact(3).zip(kept) {
        if !dropped.contains(&find_root(&mut root, t[0])) {
            out.extend_from_slice(t);
            out_kept.push(k);
        }
    }
    (out, out_kept, voids)
}

/// A union-find forest over `vertices` vertices in which the corners of
/// each of `triangles` are joined: [`find_root`] then gives each vertex its
/// connected piece.
pub(super) fn joined_through_triangles<'a>(vertices: usize, triangles: impl IntoIterator<Item = &'a [u32]>) -> Vec<u32> {
    let mut root: Vec<u32> = (0..vertices as u32).collect();
    for t in triangles {
        let Some((&first, rest)) = t.split_first() else { continue };
        let a = find_root(&mut root, first);
        for &c in rest {
            let b = find_root(&mut root, c);
            if a != b {
                root[b as usize] = a;
            }
        }
    }
    root
}

/// The root of `v` in the union-find forest `root` (each entry its parent,
/// a root its own), halving the path on the way.
pub(super) fn find_root(root: &mut [u32], mut v: u32) -> u32 {
    while root[v as usize] != v {
        root[v as usize] = root[root[v as usize] as usize];
        v = root[v as usize];
    }
    v
}

/// The bounding box (min and max corners) of `points`.
fn bounds(points: impl IntoIterator<Item = glam::DVec3>) -> (glam::DVec3, glam::DVec3) {
    points.into_iter().fold((glam::DVec3::splat(f64::INFINITY), glam::DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), q| (lo.min(q), hi.max(q)))
}

/// A flat-shaded mesh: three vertices per triangle (positions copied bit for
/// bit, so welding by position restores the shared vertices), each triangle
/// in its colour.
fn flat_mesh(positions: &[[f32; 3]], indices: &[u32], colours: &[[u8; 4]]) -> Mesh {
    let mut m = Mesh::default();
    for (t, colour) in indices.chunks_exact(3).zip(colours) {
        let [a, b, c] = [0, 1, 2].map(|k| glam::Vec3::from_array(positions[t[k] as usize]));
        let n = (b - a).cross(c - a).normalize_or(glam::Vec3::Z).to_array();
        for p in [a, b, c] {
            m.indices.push(m.positions.len() as u32);
            m.positions.push(p.to_array());
            m.normals.push(n);
            m.colours.push(*colour);
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A 3-unit cube with a 1-unit cavity in its middle (the cavity's wall
    /// wound inward, as Manifold writes it), and a flat sheet beside it.
    fn cube_with_cavity_and_sheet() -> (Vec<DVec3>, Vec<u32>) {
        let (mut positions, outer) = field::tests::cuboid(DVec3::ZERO, DVec3::splat(3.0));
        let (inner_p, inner) = field::tests::cuboid(DVec3::ONE, DVec3::splat(2.0));
        let mut indices: Vec<u32> = outer.iter().flatten().copied().collect();
        indices.extend(inner.iter().flat_map(|t| [t[0] + 8, t[2] + 8, t[1] + 8]));
        positions.extend(inner_p);
        // Two triangles back to back: encloses nothing.
        let s = positions.len() as u32;
        positions.extend([DVec3::new(5.0, 0.0, 0.0), DVec3::new(6.0, 0.0, 0.0), DVec3::new(5.0, 1.0, 0.0)]);
        indices.extend([s, s + 1, s + 2, s, s + 2, s + 1]);
        (positions, indices)
    }

    #[test]
    fn a_union_with_a_cavity_prints_filled_as_one_shell() {
        let placed = place(cube_with_cavity_and_sheet(), 0);
        // The cavity is filled (its wall dropped, counted); the sheet is dropped, not counted.
        assert_eq!(placed.voids, 1);
        assert_eq!(placed.indices.len(), 12 * 3);
        let m = measure(&placed.scaled, &placed.indices);
        assert_eq!((m.shells, m.is_watertight, m.nonmanifold_edges), (1, true, 0));
        assert!((m.volume_mm3 - 27.0).abs() < 1e-9, "{}", m.volume_mm3);
    }
}
