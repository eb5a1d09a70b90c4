//! The scene format's version 2 writer (`docs/scene-format.md`): a model's
//! instances, non-instance meshes and hierarchy, laid out as the meshes the
//! flat formats write, so a reader that tessellates each record at the
//! header's detail gets those meshes triangle for triangle.
//!
//! The walk mirrors [`crate::mesh::build_meshes`] (merged or per kind): the
//! primitive instances, then each affine class, then swept lines and free
//! triangles (written as meshes), then the placed prototypes (isosurfaces,
//! modified meshes); a model with a hierarchy is its expansion alone, as in
//! the flat path. Transforms are the f32 values the mesher multiplies by,
//! colours the bytes it writes, so nothing is lost; a palette keeps colours
//! to one byte a record for most models.

use super::format::{
    index_width, put_hierarchy, CHECKSUM_BYTES, ENTRY_BYTES, ENTRY_BYTES_SCALED, FLAG_CHECKSUM, FLAG_PROVENANCE, FLAG_SCALED, FLAG_TRUNCATED, HEADER_BYTES, MAGIC, PARITY_BIT, RUN_AFFINE, RUN_HIERARCHY,
    RUN_MESH, RUN_PLACED, RUN_PRIMITIVES, SHAPE_BIT, SHAPE_BYTES, VERSION,
};
use crate::export::{ExportError, ExportOptions, Provenance};
use crate::core::budget::Budget;
use crate::core::PrimitiveKind;
use crate::geom::primitives::{self, Prototype};
use crate::geom::Mesh;
use crate::mesh::{is_drawable, MeshLayout};
use crate::model::hierarchy::Hierarchy;
use crate::model::scene::{AffineInstance, Instance, Scene};
use std::collections::BTreeMap;

/// Bytes of the largest instance record (an affine one with a 4-byte colour
/// index, see `run_bytes`): what a front end promises per placement of a
/// scene after a mesh's first, before it knows which runs it lands in.
pub(crate) const MAX_RECORD_BYTES: u64 = 1 + 4 + 48;

/// One run of records in a planned mesh; instance runs name the filter that
/// picks their records from the scene, so the plan holds no copies.
enum Run {
    /// Drawable instances (of one kind, or all).
    Primitives(Option<PrimitiveKind>),
    /// Drawable affine instances of one class.
    Affine(u32),
    /// Drawable placements of prototypes.
    Placed,
    /// A finished mesh.
    Mesh(Mesh),
    /// The hierarchy's expansion.
    Hierarchy,
}

/// A mesh of the output: its name and runs.
struct Planned {
    name: String,
    runs: Vec<Run>,
}

/// A placement of `scene.shapes[shape]` as the mesher converts it.
fn placed(scene: &Scene) -> impl Iterator<Item = (u32, Instance)> + '_ {
    scene.shape_instances.iter().filter(|s| (s.shape as usize) < scene.shapes.len()).filter_map(|s| {
        let i = Instance::new(PrimitiveKind::Box, &s.frame, s.colour.map(f64::from));
        is_drawable(&i).then_some((s.shape, i))
    })
}

/// The byte a mesher writes for a colour channel.
fn quantise(c: [f32; 4]) -> [u8; 4] {
    crate::core::quantise::rgba8(c)
}

/// The meshes [`crate::mesh::build_meshes`] would make, as runs; the lines
/// and free triangles are meshed here (and charged to `budget`).
fn plan(scene: &Scene, hierarchy: Option<&Hierarchy>, detail: u32, layout: MeshLayout, budget: &mut Budget) -> Result<Vec<Planned>, ExportError> {
    let mut out = Vec::new();
    let one = |name: &str, run: Run| Planned { name: name.to_string(), runs: vec![run] };
    if let Some(h) = hierarchy {
        if h.leaves() > 0 {
            out.push(one("isosurfaces", Run::Hierarchy));
        }
        return Ok(out);
    }
    let mut present = [false; PrimitiveKind::ALL.len()];
    for i in scene.instances.iter().filter(|i| is_drawable(i)) {
        present[i.kind as usize] = true;
    }
    if present.iter().any(|&p| p) {
        match layout {
            MeshLayout::Merged => out.push(one("model", Run::Primitives(None))),
            MeshLayout::PerKind => {
                for k in PrimitiveKind::ALL.into_iter().filter(|k| present[*k as usize]) {
                    out.push(one(&k.name().to_ascii_lowercase(), Run::Primitives(Some(k))));
                }
            }
        }
    }
    let classes = scene.affine.iter().map(|a| a.class).max().map_or(0, |c| c as usize + 1);
    for class in 0..classes {
        if scene.affine.iter().any(|a| a.class as usize == class && a.is_drawable()) {
            let name = match scene.classes.get(class).map(String::as_str) {
                None | Some("") => "model",
                Some(n) => n,
            };
            // Fits: classes index a u32 field.
            out.push(one(name, Run::Affine(class as u32)));
        }
    }
    let mut never = |b: &Budget| b.check_deadline().map(|()| false);
    if let Some(mesh) = crate::geom::sweep::sweep_lines(&scene.lines, &scene.profiles, detail, budget, &mut never)? {
        out.push(one("lines", Run::Mesh(mesh)));
    }
    if let Some(mesh) = crate::mesh::free_triangles(&scene.vertices, budget)? {
        out.push(one("vertices", Run::Mesh(mesh)));
    }
    let placed_triangles: u64 = scene.shape_instances.iter().filter_map(|s| scene.shapes.get(s.shape as usize)).map(|p| p.indices.len() as u64 / 3).sum();
    if placed_triangles > 0 {
        out.push(one("isosurfaces", Run::Placed));
    }
    Ok(out)
}

/// The records of a run as (kind, colour) pairs, for the palette and the counts.
fn colours_of<'a>(scene: &'a Scene, run: &'a Run) -> Box<dyn Iterator<Item = [u8; 4]> + 'a> {
    match run {
        Run::Primitives(only) => Box::new(primitive_members(scene, *only).map(|i| quantise(i.colour))),
        Run::Affine(class) => Box::new(affine_members(scene, *class).map(|a| quantise(a.colour))),
        Run::Placed => Box::new(placed(scene).map(|(_, i)| quantise(i.colour))),
        Run::Mesh(_) | Run::Hierarchy => Box::new(std::iter::empty()),
    }
}

fn primitive_members(scene: &Scene, only: Option<PrimitiveKind>) -> impl Iterator<Item = &Instance> {
    scene.instances.iter().filter(move |i| is_drawable(i) && only.map_or(true, |k| i.kind == k))
}

fn affine_members(scene: &Scene, class: u32) -> impl Iterator<Item = &AffineInstance> {
    scene.affine.iter().filter(move |a| a.class == class && a.is_drawable())
}


/// Bytes of one record of `run` (meshes: the whole mesh) with colour indices of `w` bytes.
fn run_bytes(scene: &Scene, run: &Run, w: u64) -> (u64, u64) {
    match run {
        Run::Primitives(only) => (primitive_members(scene, *only).count() as u64, 1 + w + 32),
        Run::Affine(class) => (affine_members(scene, *class).count() as u64, 1 + w + 48),
        Run::Placed => (placed(scene).count() as u64, 5 + w + 32),
        Run::Mesh(m) => (1, mesh_bytes(m)),
        Run::Hierarchy => (1, 0),
    }
}

/// Bytes of a written mesh: counts, positions, normals, colours, indices.
fn mesh_bytes(m: &Mesh) -> u64 {
    8 + 28 * m.positions.len() as u64 + 4 * m.indices.len() as u64
}

/// Bytes of a prototype: counts, positions, normals, indices.
fn prototype_bytes(p: &Prototype) -> u64 {
    8 + 24 * p.positions.len() as u64 + 4 * p.indices.len() as u64
}

fn put_f32s(out: &mut Vec<u8>, v: &[f32]) {
    for x in v {
        out.extend_from_slice(&x.to_le_bytes());
    }
}

fn put_u32(out: &mut Vec<u8>, v: u32) {
    out.extend_from_slice(&v.to_le_bytes());
}

fn put_index(out: &mut Vec<u8>, i: u32, w: usize) {
    out.extend_from_slice(&i.to_le_bytes()[..w]);
}

/// Writes an instance's placement: translation, rotation, scale (f32).
fn put_similarity(out: &mut Vec<u8>, i: &Instance) {
    put_f32s(out, &i.translation.to_array());
    put_f32s(out, &i.rotation.to_array());
    put_f32s(out, &[i.scale]);
}

/// Writes `scene` (or, when there is one, `hierarchy`: the model's flat
/// scene is then its expansion) as a version 2 scene file, its meshes
/// grouped as `layout` says, with `provenance` after the header and, when
/// `options.checksum` asks for it, the CRC-32 of the whole file after the
/// last mesh ([`FLAG_CHECKSUM`]; without it the bytes are exactly those of
/// files written before the option existed). Reserves the exact size in
/// `budget` before allocating it. Returns the bytes and the triangles a
/// reader tessellates (what the flat formats would write).
pub(crate) fn write_scene(
    scene: &Scene,
    hierarchy: Option<&Hierarchy>,
    detail: u32,
    layout: MeshLayout,
    options: &ExportOptions,
    provenance: Option<&Provenance>,
    budget: &mut Budget,
) -> Result<(Vec<u8>, u64), ExportError> {
    let too_large = |what: &str| ExportError::TooLarge { format: super::SCENE.name, detail: format!("more than 2³¹ {what}") };
    let plan = plan(scene, hierarchy, detail, layout, budget)?;
    budget.check_deadline()?;
    let mut palette: BTreeMap<[u8; 4], u32> = BTreeMap::new();
    let mut order: Vec<[u8; 4]> = Vec::new();
    for run in plan.iter().flat_map(|m| &m.runs) {
        for c in colours_of(scene, run) {
            if !palette.contains_key(&c) {
                // Fits: at most 2³² colours exist.
                palette.insert(c, order.len() as u32);
                order.push(c);
            }
        }
    }
    let w = index_width(order.len());
    // The same text as `Provenance::json`, written directly (`raw_json`).
    let block = match provenance {
        Some(p) => p.raw_json()?.get().to_owned(),
        None => String::new(),
    };
    let protos: &[Prototype] = if hierarchy.is_some() { &[] } else { &scene.shapes };
    let empty = Hierarchy::default();
    let h = hierarchy.unwrap_or(&empty);
    if h.shapes.len() as u64 >= u64::from(SHAPE_BIT) || h.objects.len() as u64 >= u64::from(SHAPE_BIT) || protos.len() as u64 > u64::from(u32::MAX) {
        return Err(too_large("shapes, objects or prototypes"));
    }
    let mut size = HEADER_BYTES as u64 + if block.is_empty() { 0 } else { 4 + block.len() as u64 };
    size += 4 * order.len() as u64 + protos.iter().map(prototype_bytes).sum::<u64>();
    let scaled = h.is_scaled();
    let entry_bytes = if scaled { ENTRY_BYTES_SCALED } else { ENTRY_BYTES };
    size += 8 + SHAPE_BYTES * h.shapes.len() as u64 + 4 * h.objects.len() as u64 + entry_bytes * h.entry_count();
    size += 4;
    if options.checksum {
        size += CHECKSUM_BYTES as u64;
    }
    let mut triangles = 0u64;
    for m in &plan {
        size += 2 + m.name.len() as u64 + 4;
        for run in &m.runs {
            let (n, each) = run_bytes(scene, run, w as u64);
            if n > u64::from(u32::MAX) {
                return Err(too_large("records in a run"));
            }
            size += 5 + n * each;
            triangles = triangles.saturating_add(run_triangles(scene, h, run, detail));
        }
    }
    budget.reserve_memory(size)?;
    let mut out = Vec::with_capacity(size as usize);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    let truncated = hierarchy.map_or(scene.truncated, |h| h.truncated);
    let flags = if truncated.is_some() { FLAG_TRUNCATED } else { 0 } | if block.is_empty() { 0 } else { FLAG_PROVENANCE } | if scaled { FLAG_SCALED } else { 0 }
        | if options.checksum { FLAG_CHECKSUM } else { 0 };
    out.extend_from_slice(&flags.to_le_bytes());
    // Fits: the pipeline checked detail ≤ MAX_DETAIL.
    out.extend_from_slice(&(detail as u16).to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    // Fits: checked above (colours are at most 2³²).
    put_u32(&mut out, order.len() as u32);
    put_u32(&mut out, protos.len() as u32);
    if !block.is_empty() {
        put_u32(&mut out, u32::try_from(block.len()).map_err(|_| too_large("provenance bytes"))?);
        out.extend_from_slice(block.as_bytes());
    }
    for c in &order {
        out.extend_from_slice(c);
    }
    for p in protos {
        let (v, t) = (u32::try_from(p.positions.len()).map_err(|_| too_large("vertices"))?, u32::try_from(p.indices.len() / 3).map_err(|_| too_large("triangles"))?);
        put_u32(&mut out, v);
        put_u32(&mut out, t);
        put_f32s(&mut out, p.positions.as_flattened());
        put_f32s(&mut out, p.normals.as_flattened());
        for i in &p.indices[..3 * t as usize] {
            put_u32(&mut out, *i);
        }
    }
    put_u32(&mut out, h.shapes.len() as u32);
    put_u32(&mut out, h.objects.len() as u32);
    put_hierarchy(&mut out, h, scaled);
    put_u32(&mut out, u32::try_from(plan.len()).map_err(|_| too_large("meshes"))?);
    for m in &plan {
        out.extend_from_slice(&u16::try_from(m.name.len()).map_err(|_| too_large("bytes in a mesh name"))?.to_le_bytes());
        out.extend_from_slice(m.name.as_bytes());
        put_u32(&mut out, m.runs.len() as u32);
        for run in &m.runs {
            budget.check_deadline()?;
            put_run(&mut out, scene, run, &palette, w);
        }
    }
    if options.checksum {
        // crc32fast: the IEEE CRC-32 the strips writer uses too.
        let crc = crc32fast::hash(&out);
        put_u32(&mut out, crc);
    }
    debug_assert_eq!(out.len() as u64, size);
    Ok((out, triangles))
}

/// Triangles a reader makes of `run`.
fn run_triangles(scene: &Scene, h: &Hierarchy, run: &Run, detail: u32) -> u64 {
    match run {
        Run::Primitives(only) => primitive_members(scene, *only).map(|i| primitives::triangle_count(i.kind, detail)).sum(),
        Run::Affine(class) => affine_members(scene, *class).map(|a| primitives::triangle_count(a.kind, detail)).sum(),
        Run::Placed => placed(scene).map(|(s, _)| scene.shapes[s as usize].indices.len() as u64 / 3).sum(),
        Run::Mesh(m) => m.indices.len() as u64 / 3,
        Run::Hierarchy => h.triangles(detail),
    }
}

/// Writes one run: its type, its record count, its records.
fn put_run(out: &mut Vec<u8>, scene: &Scene, run: &Run, palette: &BTreeMap<[u8; 4], u32>, w: usize) {
    let colour = |c: [f32; 4]| palette.get(&quantise(c)).copied().unwrap_or(0);
    let (n, _) = run_bytes(scene, run, w as u64);
    let kind = match run {
        Run::Primitives(_) => RUN_PRIMITIVES,
        Run::Affine(_) => RUN_AFFINE,
        Run::Placed => RUN_PLACED,
        Run::Mesh(_) => RUN_MESH,
        Run::Hierarchy => RUN_HIERARCHY,
    };
    out.push(kind);
    // Fits: the caller checked every run's count against u32::MAX.
    put_u32(out, n as u32);
    match run {
        Run::Primitives(only) => {
            for i in primitive_members(scene, *only) {
                out.push(i.kind as u8 | if i.parity { PARITY_BIT } else { 0 });
                put_index(out, colour(i.colour), w);
                put_similarity(out, i);
            }
        }
        Run::Affine(class) => {
            for a in affine_members(scene, *class) {
                out.push(a.kind as u8);
                put_index(out, colour(a.colour), w);
                put_f32s(out, &a.linear.to_cols_array());
                put_f32s(out, &a.translation.to_array());
            }
        }
        Run::Placed => {
            for (shape, i) in placed(scene) {
                put_u32(out, shape);
                out.push(u8::from(i.parity));
                put_index(out, colour(i.colour), w);
                put_similarity(out, &i);
            }
        }
        Run::Mesh(m) => {
            // Fits: meshes address their vertices with u32 indices.
            put_u32(out, m.positions.len() as u32);
            put_u32(out, (m.indices.len() / 3) as u32);
            put_f32s(out, m.positions.as_flattened());
            put_f32s(out, m.normals.as_flattened());
            out.extend_from_slice(m.colours.as_flattened());
            for i in &m.indices[..m.indices.len() / 3 * 3] {
                put_u32(out, *i);
            }
        }
        Run::Hierarchy => {}
    }
}
