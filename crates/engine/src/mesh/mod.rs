//! Scene → meshes: each instance's prototype transformed into world space.
//!
//! Each primitive kind present is tessellated once; every instance then
//! copies its prototype through its transform. Mesh buffers are accounted in
//! the [`Budget`] *before* they are allocated, with exact capacities, so the
//! accounted memory is the memory actually used. The per-kind prototypes are
//! not accounted: they are transient, at most one per kind, and bounded by
//! the detail limit (about 3 MB for all nine at `MAX_DETAIL`), and the
//! pipeline's up-front projection (mesh bytes + output size) does not include
//! them either.

use crate::geom::primitives::{self, Prototype};
use crate::geom::mesh::mesh_bytes;
use crate::geom::{Mesh, NamedMesh, STOP_EVERY};
use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::model::graph::NodeGraph;
use crate::model::scene::{AffineInstance, FreeVertex, Instance, Scene};
use crate::core::PrimitiveKind;
use glam::{Mat3, Vec3};

pub mod pieces;

/// How instances are grouped into meshes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MeshLayout {
    /// One mesh holding every instance.
    #[default]
    Merged,
    /// One mesh per primitive kind present.
    PerKind,
}

rulemesh_core::choice!(MeshLayout { Merged => "merged", PerKind => "per-kind" });

/// Whether an instance yields usable geometry ([`Instance::is_drawable`]:
/// scale 0 and non-finite transforms are skipped rather than written).
pub fn is_drawable(instance: &Instance) -> bool {
    instance.is_drawable()
}

/// Transforms every instance's prototype into world space and merges them,
/// reserving the buffers' bytes in `budget` before allocating.
///
/// * [`MeshLayout::Merged`] gives one mesh named `"model"` with the instances
///   in scene order; [`MeshLayout::PerKind`] gives one mesh per kind present,
///   named by the kind's lower-case keyword, in [`PrimitiveKind::ALL`] order.
/// * Reflected instances (`parity`) have their triangles' winding reversed so
///   faces still point outward.
/// * Instances that are not [drawable](is_drawable) (scale 0, non-finite) are
///   skipped. An empty scene gives no meshes.
///
/// Fails with a memory [`LimitExceeded`] before allocating a mesh that does
/// not fit, or whose vertex count would not fit 32-bit indices.
pub(crate) fn build_meshes(scene: &Scene, detail: u32, layout: MeshLayout, budget: &mut Budget) -> Result<Vec<NamedMesh>, LimitExceeded> {
    Ok(build_meshes_until(scene, detail, layout, OnLimit::Error, budget)?.0)
}

/// Stops meshing once the deadline has passed: under `truncate` by keeping
/// the meshes made so far and recording why, under `error` by failing.
/// Checked once every [`Cutoff::EVERY`] pieces, so it costs nothing.
struct Cutoff {
    on_limit: OnLimit,
    count: u32,
    cut: Option<LimitExceeded>,
}

impl Cutoff {
    /// Pieces (instances, lines) meshed between two looks at the clock.
    const EVERY: u32 = 256;

    fn new(on_limit: OnLimit) -> Cutoff {
        Cutoff { on_limit, count: 0, cut: None }
    }

    /// True when meshing must stop here (the deadline passed under `truncate`).
    fn stop(&mut self, budget: &Budget) -> Result<bool, LimitExceeded> {
        if self.cut.is_some() {
            return Ok(true);
        }
        self.count = self.count.wrapping_add(1);
        if self.count % Self::EVERY != 0 {
            return Ok(false);
        }
        self.check(budget)
    }

    /// [`Cutoff::stop`] without the count: reads the clock now (for work
    /// inside one large piece).
    fn check(&mut self, budget: &Budget) -> Result<bool, LimitExceeded> {
        if self.cut.is_some() {
            return Ok(true);
        }
        match (budget.check_deadline(), self.on_limit) {
            (Ok(()), _) => Ok(false),
            (Err(e), OnLimit::Error) => Err(e),
            (Err(e), OnLimit::Truncate) => {
                self.cut = Some(e);
                Ok(true)
            }
        }
    }
}

/// [`build_meshes`], stopping at the deadline: under `on_limit: truncate`
/// the meshes made by then are kept and the deadline is returned as the
/// reason they are partial; under `error` the deadline fails the call.
pub(crate) fn build_meshes_until(
    scene: &Scene,
    detail: u32,
    layout: MeshLayout,
    on_limit: OnLimit,
    budget: &mut Budget,
) -> Result<(Vec<NamedMesh>, Option<LimitExceeded>), LimitExceeded> {
    let mut cutoff = Cutoff::new(on_limit);
    let drawable = |i: &&Instance| is_drawable(i);
    // Which kinds are present, and the prototypes' sizes (computed without tessellating).
    let mut present = [false; PrimitiveKind::ALL.len()];
    for i in scene.instances.iter().filter(drawable) {
        present[i.kind as usize] = true;
    }
    let mut meshes = Vec::new();
    if present.iter().any(|&p| p) {
        build_instance_meshes(scene, detail, layout, &present, budget, &mut cutoff, &mut meshes)?;
    }
    build_affine_meshes(scene, detail, budget, &mut cutoff, &mut meshes)?;
    // Swept lines are their own mesh in either layout.
    if let Some(mesh) = crate::geom::sweep::sweep_lines(&scene.lines, &scene.profiles, detail, budget, &mut |b| cutoff.stop(b))? {
        meshes.push(NamedMesh { name: "lines".to_string(), mesh });
    }
    if let Some(mesh) = free_triangles(&scene.vertices, budget)? {
        meshes.push(NamedMesh { name: "vertices".to_string(), mesh });
    }
    if let Some(mesh) = placed_shapes(scene, budget, &mut cutoff)? {
        meshes.push(NamedMesh { name: "isosurfaces".to_string(), mesh });
    }
    Ok((meshes, cutoff.cut))
}

/// Meshes each bone's geometry in the bone's own coordinates and builds the
/// node graph (bones, animation samples, camera) that places them, for the
/// outputs that carry a node hierarchy.
pub(crate) fn build_with_graph(scene: &Scene, detail: u32, layout: MeshLayout, budget: &mut Budget) -> Result<(Vec<NamedMesh>, NodeGraph), LimitExceeded> {
    let mut meshes = Vec::new();
    let mut bones = Vec::new();
    match &scene.rig {
        Some(rig) => {
            for (bone, part) in rig.split(scene, budget)? {
                for m in build_meshes(&part, detail, layout, budget)? {
                    bones.push(bone);
                    meshes.push(m);
                }
            }
        }
        None => {
            meshes = build_meshes(scene, detail, layout, budget)?;
            bones = vec![0; meshes.len()];
        }
    }
    // A still camera is no node of the graph: it is written at time 0 like every other still.
    let graph = NodeGraph::new(scene.rig.as_ref(), scene.camera.as_ref().filter(|c| c.is_path()), &bones, budget)?;
    Ok((meshes, graph))
}

/// One mesh per placed part — every primitive instance, shape placement,
/// affine instance and swept line on its own, then the free vertices — for printable output, which must unite closed parts and so
/// needs them apart: merged, touching parts weld into non-manifold clumps.
pub(crate) fn build_parts(scene: &Scene, detail: u32, budget: &mut Budget) -> Result<Vec<NamedMesh>, LimitExceeded> {
    let mut parts = Vec::new();
    let mut protos: Vec<Option<Prototype>> = vec![None; PrimitiveKind::ALL.len()];
    let placed = scene.shape_instances.iter().filter_map(|s| {
        let proto = scene.shapes.get(s.shape as usize)?;
        Some((proto, Instance::new(PrimitiveKind::Box, &s.frame, s.colour.map(f64::from)), None))
    });
    let instances = scene.instances.iter().map(|i| (None::<&Prototype>, *i, Some(i.kind)));
    for (shape, inst, kind) in instances.chain(placed.map(|(p, i, k)| (Some(p), i, k))) {
        if !is_drawable(&inst) {
            continue;
        }
        let proto = match (shape, kind) {
            (Some(p), _) => p,
            (None, Some(k)) => &*protos[k as usize].get_or_insert_with(|| primitives::tessellate(k, detail)),
            (None, None) => continue,
        };
        let (v, t) = (proto.positions.len() as u64, proto.indices.len() as u64 / 3);
        budget.reserve_memory(mesh_bytes(v, t))?;
        let mut mesh = Mesh::default();
        append_instance(&mut mesh, proto, &inst);
        parts.push(NamedMesh { name: "part".to_string(), mesh });
    }
    // Primitives placed by general affine maps (EisenScript's skews, Context
    // Free's tiles), each on its own as well.
    for inst in scene.affine.iter().filter(|a| a.is_drawable()) {
        let proto = &*protos[inst.kind as usize].get_or_insert_with(|| primitives::tessellate(inst.kind, detail));
        let (v, t) = (proto.positions.len() as u64, proto.indices.len() as u64 / 3);
        budget.reserve_memory(mesh_bytes(v, t))?;
        let mut mesh = Mesh::default();
        append_affine(&mut mesh, proto, inst);
        parts.push(NamedMesh { name: "part".to_string(), mesh });
    }
    // Each swept line on its own too: branches of one plant share positions.
    // A line that meets itself comes in runs that do not, each a part.
    for line in &scene.lines {
        for mesh in crate::geom::sweep::sweep_line_parts(line, &scene.profiles, detail, budget)? {
            parts.push(NamedMesh { name: "lines".to_string(), mesh });
        }
    }
    if let Some(mesh) = free_triangles(&scene.vertices, budget)? {
        parts.push(NamedMesh { name: "vertices".to_string(), mesh });
    }
    Ok(parts)
}

/// The scene's own shapes (isosurfaces) at each placement, in one mesh.
fn placed_shapes(scene: &Scene, budget: &mut Budget, cutoff: &mut Cutoff) -> Result<Option<Mesh>, LimitExceeded> {
    let sizes = |s: &crate::model::scene::ShapeInstance| {
        scene.shapes.get(s.shape as usize).map_or((0, 0), |p| (p.positions.len() as u64, p.indices.len() as u64 / 3))
    };
    let (v, t) = scene.shape_instances.iter().map(sizes).fold((0u64, 0u64), |(a, b), (v, t)| (a.saturating_add(v), b.saturating_add(t)));
    if t == 0 {
        return Ok(None);
    }
    if v > u64::from(u32::MAX) {
        return Err(budget.memory_refused(mesh_bytes(v, t)));
    }
    budget.reserve_memory(mesh_bytes(v, t))?;
    let mut mesh = Mesh {
        positions: Vec::with_capacity(v as usize),
        normals: Vec::with_capacity(v as usize),
        colours: Vec::with_capacity(v as usize),
        indices: Vec::with_capacity(3 * t as usize),
    };
    for s in &scene.shape_instances {
        if cutoff.stop(budget)? {
            break;
        }
        let Some(proto) = scene.shapes.get(s.shape as usize) else { continue };
        let placed = Instance::new(PrimitiveKind::Box, &s.frame, s.colour.map(f64::from));
        if !is_drawable(&placed) {
            continue;
        }
        // A shape can be millions of triangles (an expanded UniGrafix
        // assembly), so the clock is also read inside one placement.
        if !append_mapped_until(&mut mesh, proto, instance_map(&placed), placed.colour, placed.parity, &mut || cutoff.check(budget))? {
            break;
        }
    }
    Ok(Some(mesh))
}

/// Triangles from free `VERTEX` calls: every three consecutive vertices, in
/// the order and winding the grammar gave (a trailing one or two are dropped).
/// Public so the scene writer (`export::scene`) ships the very mesh the
/// flat formats write.
pub(crate) fn free_triangles(vertices: &[FreeVertex], budget: &mut Budget) -> Result<Option<Mesh>, LimitExceeded> {
    let t = vertices.len() / 3;
    if t == 0 {
        return Ok(None);
    }
    budget.reserve_memory(mesh_bytes(3 * t as u64, t as u64))?;
    let used = &vertices[..3 * t];
    let mesh = Mesh {
        positions: used.iter().map(|v| v.position.as_vec3().to_array()).collect(),
        normals: used.iter().map(|v| v.normal.as_vec3().to_array()).collect(),
        colours: used.iter().map(|v| crate::core::quantise::rgba8(v.colour)).collect(),
        // Fits: the vertex budget keeps counts far below u32::MAX.
        indices: (0..3 * t as u32).collect(),
    };
    Ok(Some(mesh))
}

fn build_instance_meshes(
    scene: &Scene,
    detail: u32,
    layout: MeshLayout,
    present: &[bool; PrimitiveKind::ALL.len()],
    budget: &mut Budget,
    cutoff: &mut Cutoff,
    meshes: &mut Vec<NamedMesh>,
) -> Result<(), LimitExceeded> {
    let drawable = |i: &&Instance| is_drawable(i);
    let mut protos: [Option<Prototype>; PrimitiveKind::ALL.len()] = Default::default();
    let groups: Vec<(String, Option<PrimitiveKind>)> = match layout {
        MeshLayout::Merged => vec![("model".to_string(), None)],
        MeshLayout::PerKind => PrimitiveKind::ALL
            .into_iter()
            .filter(|k| present[*k as usize])
            .map(|k| (k.name().to_ascii_lowercase(), Some(k)))
            .collect(),
    };
    for (name, only) in groups {
        let members = || scene.instances.iter().filter(drawable).filter(move |i| only.map_or(true, |k| i.kind == k));
        let (v, t) = members().fold((0u64, 0u64), |(v, t), i| {
            (v.saturating_add(primitives::vertex_count(i.kind, detail)), t.saturating_add(primitives::triangle_count(i.kind, detail)))
        });
        let bytes = mesh_bytes(v, t);
        if v > u64::from(u32::MAX) {
            // 32-bit indices cannot address this many vertices; report it as the
            // memory limit it would in practice exceed.
            return Err(budget.memory_refused(bytes));
        }
        budget.reserve_memory(bytes)?;
        // Both counts are ≤ u32::MAX (t ≤ 2v for every primitive) after the check above.
        let (vu, iu) = (v as usize, (t as usize).saturating_mul(3));
        let mut mesh = Mesh {
            positions: Vec::with_capacity(vu),
            normals: Vec::with_capacity(vu),
            colours: Vec::with_capacity(vu),
            indices: Vec::with_capacity(iu),
        };
        for inst in members() {
            if cutoff.stop(budget)? {
                break;
            }
            let proto = protos[inst.kind as usize].get_or_insert_with(|| primitives::tessellate(inst.kind, detail));
            append_instance(&mut mesh, proto, inst);
        }
        debug_assert!(cutoff.cut.is_some() || mesh.byte_size() == bytes);
        meshes.push(NamedMesh { name, mesh });
    }
    Ok(())
}

/// Meshes of the scene's affine instances: one per class present, in class
/// order, named `model` for the default class and by the class name otherwise
/// (so `box::glass` ends up in a mesh and material called `glass`).
fn build_affine_meshes(scene: &Scene, detail: u32, budget: &mut Budget, cutoff: &mut Cutoff, meshes: &mut Vec<NamedMesh>) -> Result<(), LimitExceeded> {
    if scene.affine.is_empty() {
        return Ok(());
    }
    let classes = scene.affine.iter().map(|a| a.class).max().unwrap_or(0) as usize + 1;
    let mut protos: [Option<Prototype>; PrimitiveKind::ALL.len()] = Default::default();
    for class in 0..classes {
        let members = || scene.affine.iter().filter(move |a| a.class as usize == class && a.is_drawable());
        let (v, t) = members().fold((0u64, 0u64), |(v, t), i| {
            (v.saturating_add(primitives::vertex_count(i.kind, detail)), t.saturating_add(primitives::triangle_count(i.kind, detail)))
        });
        if t == 0 {
            continue;
        }
        let bytes = mesh_bytes(v, t);
        if v > u64::from(u32::MAX) {
            return Err(budget.memory_refused(bytes));
        }
        budget.reserve_memory(bytes)?;
        let mut mesh = Mesh {
            positions: Vec::with_capacity(v as usize),
            normals: Vec::with_capacity(v as usize),
            colours: Vec::with_capacity(v as usize),
            indices: Vec::with_capacity((t as usize).saturating_mul(3)),
        };
        for inst in members() {
            if cutoff.stop(budget)? {
                break;
            }
            let proto = protos[inst.kind as usize].get_or_insert_with(|| primitives::tessellate(inst.kind, detail));
            append_affine(&mut mesh, proto, inst);
        }
        let name = match scene.classes.get(class).map(String::as_str) {
            None | Some("") => "model".to_string(),
            Some(n) => n.to_string(),
        };
        meshes.push(NamedMesh { name, mesh });
    }
    Ok(())
}

/// Appends `proto` transformed by `inst` to `mesh`. Public so the scene
/// decoder (`decode::scene`) places primitives with the same arithmetic as
/// the flat formats, triangle for triangle.
pub(crate) fn append_instance(mesh: &mut Mesh, proto: &Prototype, inst: &Instance) {
    append_mapped(mesh, proto, instance_map(inst), inst.colour, inst.parity);
}

/// The (linear part, normal matrix, translation) an instance maps its prototype by.
fn instance_map(inst: &Instance) -> (Mat3, Mat3, Vec3) {
    (inst.linear(), inst.normal_matrix(), inst.translation)
}

/// Appends `proto` mapped by the affine `inst` to `mesh` (public for the
/// scene decoder, like [`append_instance`]).
pub(crate) fn append_affine(mesh: &mut Mesh, proto: &Prototype, inst: &AffineInstance) {
    append_mapped(mesh, proto, (inst.linear, inst.normal_matrix(), inst.translation), inst.colour, inst.parity());
}

/// Appends `proto` mapped by (linear part, normal matrix, translation) to
/// `mesh`: positions by the map, normals by the normal matrix (renormalised;
/// +Z if one collapses, so no normal is ever zero), winding flipped when the
/// map reverses orientation (`flip`).
fn append_mapped(mesh: &mut Mesh, proto: &Prototype, map: (Mat3, Mat3, Vec3), colour: [f32; 4], flip: bool) {
    let never = append_mapped_until(mesh, proto, map, colour, flip, &mut || Ok::<_, LimitExceeded>(false));
    debug_assert!(matches!(never, Ok(true)));
}

/// [`append_mapped`] that asks `stop` every [`STOP_EVERY`] vertices and
/// triangles whether to give up. Returns `Ok(false)` when it gave up, with
/// `mesh` as it was before the call (a half-copied piece would have
/// vertices without triangles).
fn append_mapped_until<E>(
    mesh: &mut Mesh,
    proto: &Prototype,
    (linear, normal_matrix, translation): (Mat3, Mat3, Vec3),
    colour: [f32; 4],
    flip: bool,
    stop: &mut dyn FnMut() -> Result<bool, E>,
) -> Result<bool, E> {
    let colour = crate::core::quantise::rgba8(colour);
    let (vertices, indices) = (mesh.positions.len(), mesh.indices.len());
    // Fits: the caller checked the total vertex count against u32::MAX.
    let base = vertices as u32;
    let mut given_up = false;
    for (k, (p, n)) in proto.positions.iter().zip(&proto.normals).enumerate() {
        if k % STOP_EVERY == STOP_EVERY - 1 && stop()? {
            given_up = true;
            break;
        }
        let p = linear * Vec3::from_array(*p) + translation;
        let n = (normal_matrix * Vec3::from_array(*n)).try_normalize().unwrap_or(Vec3::Z);
        mesh.positions.push(p.to_array());
        mesh.normals.push(n.to_array());
        mesh.colours.push(colour);
    }
    for (k, t) in proto.indices.chunks_exact(3).enumerate() {
        if given_up || (k % STOP_EVERY == STOP_EVERY - 1 && stop()?) {
            given_up = true;
            break;
        }
        if flip {
            mesh.indices.extend_from_slice(&[base + t[0], base + t[2], base + t[1]]);
        } else {
            mesh.indices.extend_from_slice(&[base + t[0], base + t[1], base + t[2]]);
        }
    }
    if given_up {
        mesh.positions.truncate(vertices);
        mesh.normals.truncate(vertices);
        mesh.colours.truncate(vertices);
        mesh.indices.truncate(indices);
    }
    Ok(!given_up)
}


#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::core::budget::{Limit, Limits};
    use crate::geom::testing::{assert_closed, signed_volume};
    use glam::Quat;

    pub(crate) fn inst(kind: PrimitiveKind, t: [f32; 3], scale: f32, parity: bool) -> Instance {
        Instance {
            kind,
            parity,
            translation: Vec3::from_array(t),
            rotation: Quat::from_rotation_y(0.3) * Quat::from_rotation_x(0.2),
            scale,
            colour: [1.0, 0.5, 0.0, 1.0],
        }
    }

    pub(crate) fn scene(instances: Vec<Instance>) -> Scene {
        Scene { instances, ..Scene::default() }
    }

    #[test]
    fn a_large_piece_is_copied_in_runs_and_rolled_back_when_stopped() {
        let n = 3 * STOP_EVERY as u32;
        let proto = Prototype { positions: vec![[1.0, 2.0, 3.0]; n as usize], normals: vec![[0.0, 0.0, 1.0]; n as usize], indices: (0..n).collect() };
        let map = (Mat3::IDENTITY, Mat3::IDENTITY, Vec3::X);
        let mut mesh = Mesh::default();
        append_mapped(&mut mesh, &proto, map, [1.0; 4], false);
        let before = mesh.clone();
        let mut asked = 0;
        let whole = append_mapped_until(&mut mesh, &proto, map, [1.0; 4], false, &mut || {
            asked += 1;
            Ok::<_, LimitExceeded>(asked == 4)
        });
        // Three runs of vertices asked about, then the first run of triangles.
        assert_eq!((whole, asked), (Ok(false), 4));
        assert_eq!(mesh, before);
        assert_eq!(mesh.positions[0], [2.0, 2.0, 3.0]);
    }

    #[test]
    fn empty_scene_gives_no_meshes() {
        let mut b = Budget::new(Limits::default());
        assert!(build_meshes(&Scene::default(), 16, MeshLayout::Merged, &mut b).unwrap().is_empty());
        assert!(build_meshes(&Scene::default(), 16, MeshLayout::PerKind, &mut b).unwrap().is_empty());
        assert_eq!(b.memory(), 0);
    }

    #[test]
    fn merged_counts_colours_and_budget() {
        let s = scene(PrimitiveKind::ALL.iter().enumerate().map(|(k, &kind)| inst(kind, [k as f32, 0.0, 0.0], 1.0, false)).collect());
        let mut b = Budget::new(Limits::default());
        let m = build_meshes(&s, 12, MeshLayout::Merged, &mut b).unwrap();
        assert_eq!(m.len(), 1);
        assert_eq!(m[0].name, "model");
        let v: u64 = PrimitiveKind::ALL.iter().map(|&k| primitives::vertex_count(k, 12)).sum();
        let t: u64 = PrimitiveKind::ALL.iter().map(|&k| primitives::triangle_count(k, 12)).sum();
        assert_eq!(m[0].mesh.positions.len() as u64, v);
        assert_eq!(m[0].mesh.triangle_count() as u64, t);
        assert_eq!(b.memory(), mesh_bytes(v, t));
        assert_eq!(m[0].mesh.byte_size(), mesh_bytes(v, t));
        assert!(m[0].mesh.colours.iter().all(|&c| c == [255, 128, 0, 255]));
        for n in &m[0].mesh.normals {
            assert!((Vec3::from_array(*n).length() - 1.0).abs() < 1e-5);
        }
    }

    #[test]
    fn per_kind_order_and_names() {
        let s = scene(vec![
            inst(PrimitiveKind::Torus, [0.0; 3], 1.0, false),
            inst(PrimitiveKind::Box, [1.0, 0.0, 0.0], 1.0, false),
            inst(PrimitiveKind::Torus, [2.0, 0.0, 0.0], 1.0, false),
        ]);
        let mut b = Budget::new(Limits::default());
        let m = build_meshes(&s, 8, MeshLayout::PerKind, &mut b).unwrap();
        let names: Vec<&str> = m.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["box", "torus"]);
        assert_eq!(m[1].mesh.triangle_count() as u64, 2 * primitives::triangle_count(PrimitiveKind::Torus, 8));
        let (v, e, f) = assert_closed(&m[1].mesh.positions, &m[1].mesh.indices);
        assert_eq!(v as i64 - e as i64 + f as i64, 0); // two tori: χ = 0 + 0
    }

    #[test]
    fn reflection_flips_winding() {
        for kind in PrimitiveKind::ALL {
            let s = scene(vec![inst(kind, [0.5, 1.0, 2.0], 2.0, true)]);
            let mut b = Budget::new(Limits::default());
            let m = build_meshes(&s, 16, MeshLayout::Merged, &mut b).unwrap();
            let mesh = &m[0].mesh;
            assert!(signed_volume(&mesh.positions, &mesh.indices) > 0.0, "{kind:?}");
            // Normals still agree with the (flipped) winding.
            for t in mesh.indices.chunks_exact(3) {
                let [a, b, c] = [0, 1, 2].map(|k| Vec3::from_array(mesh.positions[t[k] as usize]));
                let face = (b - a).cross(c - a).normalize();
                assert!(face.dot(Vec3::from_array(mesh.normals[t[0] as usize])) > 0.2, "{kind:?}");
            }
        }
        // A mirrored box keeps volume 8 at scale 2.
        let s = scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 2.0, true)]);
        let m = build_meshes(&s, 16, MeshLayout::Merged, &mut Budget::new(Limits::default())).unwrap();
        assert!((signed_volume(&m[0].mesh.positions, &m[0].mesh.indices) - 8.0).abs() < 1e-4);
    }

    #[test]
    fn zero_scale_instances_are_skipped() {
        let s = scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 0.0, false), inst(PrimitiveKind::Sphere, [0.0; 3], 1.0, false)]);
        let mut b = Budget::new(Limits::default());
        let m = build_meshes(&s, 16, MeshLayout::PerKind, &mut b).unwrap();
        assert_eq!(m.len(), 1);
        assert_eq!(m[0].name, "sphere");
        let s = scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 0.0, false)]);
        assert!(build_meshes(&s, 16, MeshLayout::Merged, &mut b).unwrap().is_empty());
    }

    #[test]
    fn budget_refusal_before_allocating() {
        let s = scene(vec![inst(PrimitiveKind::Sphere, [0.0; 3], 1.0, false)]);
        let mut b = Budget::new(Limits { max_memory: 1000, ..Limits::default() });
        let e = build_meshes(&s, 64, MeshLayout::Merged, &mut b).unwrap_err();
        assert_eq!(e.limit, Limit::Memory);
        assert_eq!(e.configured, 1000);
        assert_eq!(e.reached, mesh_bytes(primitives::vertex_count(PrimitiveKind::Sphere, 64), primitives::triangle_count(PrimitiveKind::Sphere, 64)));
        assert_eq!(b.memory(), 0);
    }
}
