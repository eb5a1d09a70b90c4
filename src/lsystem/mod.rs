//! L-systems: derivation ([`derive`]) and turtle interpretation ([`turtle`])
//! of systems parsed by [`crate::lang::lsystem`], and [`render`], the
//! pipeline for `language: "lsystem"`: source → derived string → Scene →
//! meshes → bytes, under one [`Budget`].
//!
//! Context-free systems take the instancing route instead (issue 5, seed 001
//! ch. 4): source → derivation DAG ([`dag`]) → object hierarchy
//! ([`instance`]) → `format=scene` or `EXT_mesh_gpu_instancing` glTF, with
//! no string in between; the flat formats walk the DAG through the turtle.
//!
//! Limits: every module rewritten counts one evaluation step (`max_steps`),
//! every string is accounted in `max_memory` before it is allocated (so the
//! string length is bounded by both), and every segment counts as a
//! primitive (`max_primitives`) with its triangles (`max_triangles`).

pub mod dag;
pub mod derive;
pub mod instance;
pub mod turtle;

use crate::eval::budget::{Limit, LimitExceeded, OnLimit};
use crate::eval::hierarchy::Hierarchy;
use crate::eval::scene::{Scene, ShapeInstance, SHAPE_INSTANCE_BYTES};
use crate::eval::{Budget, EvalError, Frame};
use crate::export::{self, Format, Instancing};
use crate::geom::{self, primitives};
use crate::lang::ir::PrimitiveKind;
use crate::lang::{lsystem as lang_ls, Language};
use crate::pipeline::{check_detail, downstream, mesh_and_export, truncate_or_fail, RenderError, RenderOutput, RenderRequest, Stages};

pub use derive::{derive, Derivation, ModuleString};

/// Renders L-system `source` as the request says (the request's language is taken to be L-system).
///
/// Systems that [instance](dag::not_instanceable) are derived as a DAG of
/// distinct subtrees, never as a string: `format=scene` writes its object
/// hierarchy, glb/gltf draw it with `EXT_mesh_gpu_instancing` (or expanded,
/// with `instancing=flat`), and the other formats walk it through the turtle.
/// Other systems are derived in full under the budget.
pub fn render(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    check_detail(req)?;
    let mut budget = Budget::new(req.limits);
    let mut stages = Stages::start();
    Budget::check_source(&req.limits, source.len() as u64)?;
    let sys = lang_ls::parse(source)?;
    if let Some(name) = req.params.keys().next() {
        return Err(EvalError::UnknownParam { name: name.clone(), declared: String::new() }.into());
    }
    stages.lap(|p| &mut p.parse);
    let seed = req.seed.or(sys.seed).unwrap_or(0);
    let dag = match dag::not_instanceable(&sys) {
        Some(_) => None,
        None => match dag::build(&sys, seed, &mut budget) {
            Ok(d) => Some(d),
            // The DAG is built whole or not at all; truncation needs the string
            // (but a deadline is not restarted).
            Err(EvalError::Limit(l)) if req.on_limit == OnLimit::Truncate && l.limit != Limit::Deadline => {
                budget = Budget::new(req.limits);
                None
            }
            Err(e) => return Err(e.into()),
        },
    };
    // Printing takes the string path of STL (swept tubes with joints), so a
    // printed model and its report match whatever the format.
    let gltf = matches!(req.format, Format::Glb | Format::Gltf) && !req.export_options.print.enabled;
    if req.format == Format::Scene || (gltf && dag.is_some()) {
        match hierarchical(&sys, dag.as_ref(), seed, req, &mut budget, &mut stages) {
            Ok(out) => return finish(out, req, sys.warnings, budget, stages),
            Err(RenderError::Limit(l)) if req.on_limit == OnLimit::Truncate && req.format != Format::Scene && l.limit != Limit::Deadline => {
                budget = Budget::new(req.limits);
            }
            Err(e) => return Err(e),
        }
    }
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let cost = downstream(req, overhead);
    let opts = turtle::TurtleOptions {
        detail: req.detail,
        on_limit: req.on_limit,
        line_point_bytes: {
            let (v, t) = geom::sweep::per_point_bound(geom::sweep::profile_sides(req.detail));
            cost.bytes(v, t)
        },
        downstream_bytes: PrimitiveKind::ALL.map(|k| cost.bytes(primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail))),
    };
    // Reading the expansion costs a step per module (the string length), and
    // every segment is a primitive: what is known to exceed either is refused
    // before drawing, or (truncating) drawn from the string, which stops at the limit.
    let fits = |d: &dag::StringDag, budget: &Budget| -> Result<bool, LimitExceeded> {
        let (steps, segments) = (budget.steps().saturating_add(d.root().modules), d.root().segments);
        let over = if steps > req.limits.max_steps {
            LimitExceeded { limit: Limit::Steps, configured: req.limits.max_steps, reached: steps }
        } else if segments > req.limits.max_primitives {
            LimitExceeded { limit: Limit::Primitives, configured: req.limits.max_primitives, reached: segments }
        } else {
            return Ok(true);
        };
        match req.on_limit {
            OnLimit::Error => Err(over),
            OnLimit::Truncate => Ok(false),
        }
    };
    let walk = match &dag {
        Some(d) if fits(d, &budget)? => Some(d),
        _ => None,
    };
    let mut drawing = match walk {
        Some(d) => turtle::interpret_stream(&sys, &opts, &mut budget, &mut |sink| d.feed(d.root_index(), sink))?,
        None => {
            let derivation = derive::derive(&sys, seed, req.on_limit, &mut budget)?;
            let mut drawing = turtle::interpret(&sys, &derivation.string, &opts, &mut budget)?;
            if drawing.scene.truncated.is_none() {
                drawing.scene.truncated = derivation.truncated;
            }
            budget.release_memory(derivation.string.bytes());
            drawing
        }
    };
    stages.lap(|p| &mut p.eval);
    if let Err(e) = budget.check_deadline() {
        truncate_or_fail(req.on_limit, e, &mut drawing.scene)?;
    }
    budget.release_memory(drawing.promised.saturating_add(overhead));
    mesh_and_export(drawing.scene, req, Language::Lsystem, drawing.segments, sys.warnings, budget, stages)
}

/// What the hierarchical route made: final bytes, or a flat scene still to mesh.
enum Made {
    Bytes { bytes: Vec<u8>, leaves: u64, triangles: u64, truncated: Option<LimitExceeded> },
    Flat { scene: Scene, leaves: u64 },
}

/// The object hierarchy of `sys` (from its DAG when it has a balanced one,
/// else from the string derived in full), written as the request says.
fn hierarchical(
    sys: &lang_ls::LSystem,
    dag: Option<&dag::StringDag>,
    seed: u64,
    req: &RenderRequest,
    budget: &mut Budget,
    stages: &mut Stages,
) -> Result<Made, RenderError> {
    let h = match dag {
        Some(d) if d.balanced() => instance::build(sys, d, budget)?,
        _ => {
            let derivation = derive::derive(sys, seed, req.on_limit, budget)?;
            let flat = dag::from_string(sys, &derivation.string, budget)?;
            budget.release_memory(derivation.string.bytes());
            let mut h = instance::build(sys, &flat, budget)?;
            h.truncated = derivation.truncated;
            h
        }
    };
    stages.lap(|p| &mut p.eval);
    budget.check_deadline()?;
    // Refuse, before any expansion, a model whose segments or triangles exceed the limits.
    let limits = budget.limits();
    let leaves = h.leaves();
    if leaves > limits.max_primitives {
        return Err(LimitExceeded { limit: Limit::Primitives, configured: limits.max_primitives, reached: leaves }.into());
    }
    let triangles = h.triangles(req.detail);
    if triangles > limits.max_triangles {
        return Err(LimitExceeded { limit: Limit::Triangles, configured: limits.max_triangles, reached: triangles }.into());
    }
    let opts = &req.export_options;
    // Printing unites the expanded parts into one solid, so it never instances.
    let gpu = opts.instancing == Instancing::Gpu && opts.gltf.is_plain() && !opts.fit_unit_box && !opts.print.enabled;
    let truncated = h.truncated;
    match req.format {
        Format::Scene => Ok(Made::Bytes { bytes: export::scene::write_scene(&h, budget)?, leaves, triangles, truncated }),
        Format::Glb | Format::Gltf if gpu => {
            let bytes = write_instanced(&h, req, budget)?;
            Ok(Made::Bytes { bytes, leaves, triangles, truncated })
        }
        _ => Ok(Made::Flat { scene: expand(&h, req.detail, budget)?, leaves }),
    }
}

/// Writes `h` as instanced glTF: one mesh per (leaf shape, colour), one
/// instance per leaf, transforms written as the hierarchy is walked.
fn write_instanced(h: &Hierarchy, req: &RenderRequest, budget: &mut Budget) -> Result<Vec<u8>, RenderError> {
    let counts = h.leaf_counts();
    let mut index: Vec<Vec<([u8; 4], usize)>> = vec![Vec::new(); h.shapes.len()];
    let mut meshes = Vec::with_capacity(counts.len());
    for (i, &(shape, colour)) in counts.keys().enumerate() {
        let Some(s) = h.shapes.get(shape as usize) else { continue };
        let p = s.prototype(req.detail);
        budget.reserve_memory(geom::meshing::mesh_bytes(p.positions.len() as u64, p.indices.len() as u64 / 3))?;
        let mesh = geom::Mesh { colours: vec![colour; p.positions.len()], positions: p.positions, normals: p.normals, indices: p.indices };
        meshes.push(geom::NamedMesh { name: format!("segment-{i}"), mesh });
        if let Some(v) = index.get_mut(shape as usize) {
            v.push((colour, i));
        }
    }
    let counts: Vec<u64> = counts.values().copied().collect();
    let meta = export::ExportMeta { background: None, truncated: h.truncated.is_some(), graph: None, material_per_mesh: false, camera: None };
    let bytes = export::gltf::write_instanced(&meshes, &counts, &meta, req.format == Format::Glb, budget, &mut |sink| {
        h.walk(&mut |leaf| {
            let Some(&(_, mesh)) = index.get(leaf.shape as usize).and_then(|v| v.iter().find(|(c, _)| *c == leaf.colour)) else { return };
            sink(mesh, leaf.translation.as_vec3().to_array(), leaf.rotation.as_quat().normalize().to_array());
        })
    })?;
    Ok(bytes)
}

/// Expands `h` into a flat scene: each leaf shape once, placed at every leaf.
fn expand(h: &Hierarchy, detail: u32, budget: &mut Budget) -> Result<Scene, LimitExceeded> {
    let mut scene = Scene::default();
    budget.reserve_memory(h.leaves().saturating_mul(SHAPE_INSTANCE_BYTES))?;
    scene.shapes = h.shapes.iter().map(|s| s.prototype(detail)).collect();
    scene.shape_instances.reserve_exact(h.leaves() as usize);
    h.walk(&mut |leaf| {
        let frame = Frame { translation: leaf.translation, rotation: leaf.rotation, scale: 1.0, parity: false };
        scene.shape_instances.push(ShapeInstance { shape: leaf.shape, frame, colour: leaf.colour.map(|c| f32::from(c) / 255.0) });
    });
    scene.truncated = h.truncated;
    Ok(scene)
}

/// The summary of a hierarchical render.
fn finish(made: Made, req: &RenderRequest, warnings: Vec<crate::lang::Diagnostic>, budget: Budget, mut stages: Stages) -> Result<RenderOutput, RenderError> {
    match made {
        Made::Flat { scene, leaves } => mesh_and_export(scene, req, Language::Lsystem, leaves, warnings, budget, stages),
        Made::Bytes { bytes, leaves, triangles, truncated } => {
            stages.lap(|p| &mut p.export);
            // Writing is not interruptible; a model finished after the deadline still fails with it.
            budget.check_deadline()?;
            Ok(RenderOutput {
                bytes,
                language: Language::Lsystem,
                primitives: leaves,
                triangles,
                truncated,
                warnings,
                elapsed: budget.elapsed(),
                phases: stages.phases,
            })
        }
    }
}
