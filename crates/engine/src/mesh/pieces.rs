//! The flat model as a stream of pieces, for writers that encode as they go
//! (`strips` in chunks) and so must never hold a model-sized mesh.
//!
//! [`for_each_piece`] visits exactly what [`build_meshes_until`](super::build_meshes_until)
//! would put into its meshes, in the same order and with the same arithmetic
//! (a piece appended with [`append_piece`] gives the vertices the mesher
//! writes, bit for bit), plus the leaves of an instancing hierarchy, placed
//! as [`Hierarchy::expand`] and the mesher would place them, without
//! expanding it. Only swept lines and free triangles come as whole meshes
//! (the sweep joins neighbouring segments, so it is made in one go).

use super::{append_mapped, free_triangles, instance_map, is_drawable, Cutoff, MeshLayout};
use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::core::PrimitiveKind;
use crate::geom::primitives::{self, Prototype};
use crate::geom::Mesh;
use crate::model::scene::{Instance, Scene};
use crate::model::Hierarchy;
use glam::{Mat3, Vec3};

/// One piece of the flat model.
#[derive(Debug, Clone, Copy)]
pub enum Piece<'a> {
    /// A prototype placed by a map: (linear part, normal matrix, translation),
    /// its colour, and whether the map mirrors (winding flips).
    Placed {
        /// The tessellated shape, in its own coordinates.
        proto: &'a Prototype,
        /// Linear part, normal matrix and translation.
        map: (Mat3, Mat3, Vec3),
        /// Linear RGBA.
        colour: [f32; 4],
        /// True when the map mirrors.
        flip: bool,
    },
    /// A mesh made whole in world space (swept lines, free triangles).
    Whole(&'a Mesh),
}

impl Piece<'_> {
    /// Vertices and triangles the piece adds.
    pub fn counts(&self) -> (usize, usize) {
        match self {
            Piece::Placed { proto, .. } => (proto.positions.len(), proto.indices.len() / 3),
            Piece::Whole(m) => (m.positions.len(), m.triangle_count()),
        }
    }
}

/// Appends a [`Piece::Placed`] to `mesh` as the mesher would (a
/// [`Piece::Whole`] is appended as it is).
pub(crate) fn append_piece(mesh: &mut Mesh, piece: &Piece<'_>) {
    match *piece {
        Piece::Placed { proto, map, colour, flip } => append_mapped(mesh, proto, map, colour, flip),
        Piece::Whole(m) => {
            // Fits: callers keep their buffers far below u32::MAX vertices.
            let base = mesh.positions.len() as u32;
            mesh.positions.extend_from_slice(&m.positions);
            mesh.normals.extend_from_slice(&m.normals);
            mesh.colours.extend_from_slice(&m.colours);
            mesh.indices.extend(m.indices.iter().map(|&i| i + base));
        }
    }
}

/// Calls `sink` with every piece of `scene` (in the order of the merged
/// meshes of `layout`) and then every leaf of `hierarchy`, until `sink`
/// returns `Ok(false)`, it fails, or the deadline passes: under `truncate`
/// the walk then stops and the deadline is returned as the reason the model
/// is partial; under `error` it fails. Swept lines are charged to `budget`
/// as the mesher charges them; placed pieces are the caller's to account.
pub(crate) fn for_each_piece<E: From<LimitExceeded>>(
    scene: &Scene,
    hierarchy: Option<&Hierarchy>,
    detail: u32,
    layout: MeshLayout,
    on_limit: OnLimit,
    budget: &mut Budget,
    sink: &mut dyn FnMut(Piece<'_>, &mut Budget) -> Result<bool, E>,
) -> Result<Option<LimitExceeded>, E> {
    let mut cutoff = Cutoff::new(on_limit);
    let mut protos: [Option<Prototype>; PrimitiveKind::ALL.len()] = Default::default();
    let groups: Vec<Option<PrimitiveKind>> = match layout {
        MeshLayout::Merged => vec![None],
        MeshLayout::PerKind => PrimitiveKind::ALL.into_iter().map(Some).collect(),
    };
    for only in groups {
        for inst in scene.instances.iter().filter(|i| is_drawable(i) && only.map_or(true, |k| i.kind == k)) {
            if cutoff.stop(budget)? {
                return Ok(cutoff.cut);
            }
            let proto = &*protos[inst.kind as usize].get_or_insert_with(|| primitives::tessellate(inst.kind, detail));
            if !sink(Piece::Placed { proto, map: instance_map(inst), colour: inst.colour, flip: inst.parity }, budget)? {
                return Ok(None);
            }
        }
    }
    let classes = scene.affine.iter().map(|a| a.class as usize + 1).max().unwrap_or(0);
    for class in 0..classes {
        for a in scene.affine.iter().filter(|a| a.class as usize == class && a.is_drawable()) {
            if cutoff.stop(budget)? {
                return Ok(cutoff.cut);
            }
            let proto = &*protos[a.kind as usize].get_or_insert_with(|| primitives::tessellate(a.kind, detail));
            if !sink(Piece::Placed { proto, map: (a.linear, a.normal_matrix(), a.translation), colour: a.colour, flip: a.parity() }, budget)? {
                return Ok(None);
            }
        }
    }
    let whole = [
        crate::geom::sweep::sweep_lines(&scene.lines, &scene.profiles, detail, budget, &mut |b| cutoff.stop(b))?,
        free_triangles(&scene.vertices, budget)?,
    ];
    for mesh in whole.iter().flatten() {
        if cutoff.cut.is_some() {
            return Ok(cutoff.cut);
        }
        if !sink(Piece::Whole(mesh), budget)? {
            return Ok(None);
        }
    }
    drop(whole);
    for s in &scene.shape_instances {
        let Some(proto) = scene.shapes.get(s.shape as usize) else { continue };
        let placed = Instance::new(PrimitiveKind::Box, &s.frame, s.colour.map(f64::from));
        if !is_drawable(&placed) {
            continue;
        }
        if cutoff.stop(budget)? {
            return Ok(cutoff.cut);
        }
        if !sink(Piece::Placed { proto, map: instance_map(&placed), colour: placed.colour, flip: placed.parity }, budget)? {
            return Ok(None);
        }
    }
    if let Some(h) = hierarchy {
        // The leaves as `Hierarchy::expand` places them (a shape placement
        // whose colour is the leaf's byte over 255), one prototype per shape.
        let shapes: Vec<Prototype> = h.shapes.iter().map(|s| s.prototype(detail)).collect();
        let mut failed = None;
        h.walk_while(&mut |leaf| {
            let Some(proto) = shapes.get(leaf.shape as usize) else { return true };
            let colour = leaf.colour.map(|c| f64::from(f32::from(c) / 255.0));
            let placed = Instance::new(PrimitiveKind::Box, &leaf.frame(), colour);
            if !is_drawable(&placed) {
                return true;
            }
            match cutoff.stop(budget).map_err(E::from).and_then(|stop| if stop { Ok(false) } else { sink(Piece::Placed { proto, map: instance_map(&placed), colour: placed.colour, flip: placed.parity }, budget) }) {
                Ok(go_on) => go_on,
                Err(e) => {
                    failed = Some(e);
                    false
                }
            }
        });
        if let Some(e) = failed {
            return Err(e);
        }
    }
    Ok(cutoff.cut)
}
