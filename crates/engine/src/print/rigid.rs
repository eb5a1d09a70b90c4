//! The union of a rigid hierarchy once per distinct subtree, kept in
//! Manifold between levels (issue 16's fast unions, for L-systems).
//!
//! An L-system's hierarchy places its subtrees by rotations and
//! translations only: the Sierpinski bush is 17 objects for its 35,310
//! tube segments, each level three copies of the one below turned 120°
//! apart. [`super::subtree`] unites a hierarchy's objects through `f32`
//! meshes snapped to a grid, which is what a similarity hierarchy needs
//! (the Menger sponge's sibling faces meet in exact arithmetic only on a
//! grid), but it costs a rigid one dearly: a tube's cap turned by 35° is no
//! longer exactly flat in `f32`, so Manifold cannot merge its triangles
//! into one face, and every level's union comes out with more triangles
//! than went in (three tubes: 84 triangles in, 144 out; the bush: 2.3
//! million triangles at the top level against 0.9 million kept in double
//! precision, and past the memory limit).
//!
//! So here each object's union stays a Manifold: children are placed by
//! Manifold's own transforms (double precision, lazy: three copies of a
//! subtree are one mesh until a boolean reads them), united by its batch
//! union, and read back once, at the root. Colours go through the union
//! as Manifold's original IDs: each (leaf shape, colour) is one original,
//! and every result triangle says which original it lies in.

use super::solid::Solid;
use super::{PrintError, PLAIN};
use crate::core::budget::Budget;
use crate::model::hierarchy::{Entry, Hierarchy, Target};
use glam::DMat3;
use std::collections::HashMap;

/// Bytes Manifold holds per triangle of each kept object's union between
/// levels (half-edges, normals, relations, collider): the bush's
/// 1,007,446-triangle root held 300 MiB resident after its union, under
/// 300 bytes a triangle. While an object is united, its input is charged
/// at `union::MANIFOLD_UNION_BYTES` instead (its children's own charge is
/// released first).
const MANIFOLD_TRIANGLE_BYTES: u64 = 300;

/// The union of rigid hierarchy `h` (whose shapes are `leaves`, closed and
/// outward), object by object. `None` when a placement is not finite,
/// Manifold refuses a piece, or nothing is drawn: the flat route decides.
pub(super) fn unite_rigid(h: &Hierarchy, leaves: &[Solid], budget: &mut Budget) -> Result<Option<Solid>, PrintError> {
    // One original per (shape, colour) placed, so colours can be traced.
    let mut originals: HashMap<(u32, [u8; 4]), manifold_rs::Manifold> = HashMap::new();
    let mut colour_of: HashMap<u32, [u8; 4]> = HashMap::new();
    for e in h.objects.iter().flat_map(|o| &o.entries) {
        let Target::Shape(s) = e.target else { continue };
        if originals.contains_key(&(s, e.colour)) {
            continue;
        }
        let Some(leaf) = leaves.get(s as usize) else { return Ok(None) };
        let m = to_manifold(leaf).simplify(0.0).as_original();
        let Ok(id) = u32::try_from(m.original_id()) else { return Ok(None) };
        if m.status() != 0 || m.is_empty() {
            return Ok(None);
        }
        colour_of.insert(id, e.colour);
        originals.insert((s, e.colour), m);
    }
    let used = h.multiplicities();
    let last_use = last_uses(h);
    // Each object's union (None: it draws nothing) and its triangles.
    let mut unions: Vec<Option<(manifold_rs::Manifold, u64)>> = Vec::with_capacity(h.objects.len());
    let mut held = vec![0u64; h.objects.len()];
    for (index, (object, &count)) in h.objects.iter().zip(&used).enumerate() {
        if count == 0 {
            unions.push(None);
            continue;
        }
        budget.check_deadline()?;
        let mut pieces: Vec<manifold_rs::Manifold> = Vec::with_capacity(object.entries.len());
        let mut input = 0u64;
        for e in &object.entries {
            let Some(m) = affine(e) else { return Ok(None) };
            let (source, tris) = match e.target {
                Target::Shape(s) => (originals.get(&(s, e.colour)), leaves.get(s as usize).map_or(0, |l| l.tris.len() as u64)),
                Target::Object(c) => match unions.get(c as usize) {
                    Some(Some((child, tris))) => (Some(child), *tris),
                    // A subtree that draws nothing takes no part.
                    _ => (None, 0),
                },
            };
            if let Some(source) = source {
                pieces.push(source.transformed(&m));
                input += tris;
            }
        }
        // Children no later object places are dropped: from here their
        // triangles are counted as this union's input (Manifold shares a
        // child's mesh with its placed copies until the boolean reads them).
        for (child, &last) in last_use.iter().enumerate() {
            if last == index && child != index {
                unions[child] = None;
                budget.release_memory(std::mem::take(&mut held[child]));
            }
        }
        let united = match pieces.len() {
            0 => None,
            // One piece placed alone (a closed leaf, or a child's union) is already a union.
            1 => pieces.pop().map(|p| (p, input)),
            _ => match unite(&pieces, input, budget)? {
                Some(u) => Some(u),
                // Manifold refused a piece: the flat route decides.
                None => return Ok(None),
            },
        };
        if let Some((_, tris)) = &united {
            held[index] = tris.saturating_mul(MANIFOLD_TRIANGLE_BYTES);
            budget.reserve_memory(held[index])?;
        }
        unions.push(united);
        crate::core::memprobe::mark("rigid.object", budget);
    }
    let root = unions.pop().flatten();
    budget.release_memory(held.iter().sum());
    let Some((root, _)) = root else { return Ok(None) };
    let solid = solid_of(&root, &colour_of);
    drop(root);
    crate::core::memprobe::mark("rigid.read_back", budget);
    Ok(Some(solid))
}

/// Steps charged per triangle that enters an object's union. An object
/// here is a batch of a few pieces (the bush's: three sub-bushes and three
/// branches), so a triangle goes through a boolean or two, where a flat
/// batch of thousands of parts puts it through about log₂(parts) of them
/// (`union::unite` charges 8).
const STEPS_PER_TRIANGLE: u64 = 4;

/// The batch union of `pieces` (`input` triangles in all) under the
/// deadline, and its triangle count; `None` when Manifold refuses a piece
/// (the result is empty).
fn unite(pieces: &[manifold_rs::Manifold], input: u64, budget: &mut Budget) -> Result<Option<(manifold_rs::Manifold, u64)>, PrintError> {
    crate::core::memprobe::note("rigid.union_input", input);
    let bytes = input.saturating_mul(super::union::MANIFOLD_UNION_BYTES);
    budget.reserve_memory(bytes)?;
    budget.charge_steps(input.saturating_mul(STEPS_PER_TRIANGLE))?;
    let timeout = budget.time_left().map(|t| u64::try_from(t.as_millis()).unwrap_or(u64::MAX).max(1));
    let result = manifold_rs::Manifold::batch_union(pieces, timeout);
    budget.release_memory(bytes);
    if result.status() == manifold_rs::Manifold::CANCELLED {
        budget.check_deadline()?;
        return Err(PrintError::Union("cancelled at the deadline".into()));
    }
    if result.status() != 0 || result.is_empty() {
        return Ok(None);
    }
    let tris = result.num_tri() as u64;
    Ok(Some((result, tris)))
}

/// Entry `e`'s placement as a column-major 3x4 affine map (rotation times
/// scale, then the translation); `None` when it is not finite.
fn affine(e: &Entry) -> Option<[f64; 12]> {
    let l = DMat3::from_quat(e.rotation) * e.scale;
    let t = e.translation;
    let m = [l.x_axis.x, l.x_axis.y, l.x_axis.z, l.y_axis.x, l.y_axis.y, l.y_axis.z, l.z_axis.x, l.z_axis.y, l.z_axis.z, t.x, t.y, t.z];
    m.iter().all(|v| v.is_finite()).then_some(m)
}

/// For each object, the index of the last object that places it (its own
/// index when none does: the root).
fn last_uses(h: &Hierarchy) -> Vec<usize> {
    let mut last: Vec<usize> = (0..h.objects.len()).collect();
    for (i, o) in h.objects.iter().enumerate() {
        for e in &o.entries {
            if let Target::Object(c) = e.target {
                if let Some(l) = last.get_mut(c as usize) {
                    *l = i;
                }
            }
        }
    }
    last
}

/// A closed solid as a Manifold (its positions in `f32`, as Manifold keeps meshes).
fn to_manifold(s: &Solid) -> manifold_rs::Manifold {
    let verts: Vec<f32> = s.positions.iter().flat_map(|q| q.as_vec3().to_array()).collect();
    let idx: Vec<u32> = s.tris.iter().flatten().copied().collect();
    manifold_rs::Manifold::from_mesh(manifold_rs::Mesh::new(&verts, &idx))
}

/// A union read back: positions, triangles, and each triangle's colour
/// from the original its run came from.
fn solid_of(m: &manifold_rs::Manifold, colour_of: &HashMap<u32, [u8; 4]>) -> Solid {
    let mesh = m.to_mesh();
    let props = mesh.num_props().max(3) as usize;
    let positions = mesh.vertices().chunks_exact(props).map(|v| glam::DVec3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))).collect();
    let indices = mesh.indices();
    let tris: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let mut colours = vec![PLAIN; tris.len()];
    let (ids, starts) = (mesh.run_original_ids(), mesh.run_indices());
    for (r, id) in ids.iter().enumerate() {
        let (Some(&from), Some(&to)) = (starts.get(r), starts.get(r + 1)) else { continue };
        let colour = colour_of.get(id).copied().unwrap_or(PLAIN);
        for c in colours.iter_mut().take(to as usize / 3).skip(from as usize / 3) {
            *c = colour;
        }
    }
    Solid { positions, tris, colours }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;
    use crate::core::PrimitiveKind;
    use crate::geom::halfedge::HalfEdgeMesh;
    use crate::model::hierarchy::{LeafShape, Object};
    use glam::{DQuat, DVec3};

    /// A tube segment 0.8 wide from the origin one unit up +Y, as the L-system turtle makes them.
    fn segment() -> LeafShape {
        LeafShape { kind: PrimitiveKind::Cylinder, scale: [0.8, 1.0, 0.8], offset: [0.0, 0.5, 0.0], tube: true }
    }

    fn entry(target: Target, translation: DVec3, rotation: DQuat, colour: [u8; 4]) -> Entry {
        Entry { target, translation, rotation, scale: 1.0, colour }
    }

    const RED: [u8; 4] = [255, 0, 0, 255];
    const BLUE: [u8; 4] = [0, 0, 255, 255];

    /// A two-segment red trunk (object 0) and a root that stands it up and
    /// branches three copies of it from its top, 35° out and 120° apart, with
    /// a blue segment straight up between them: a small Sierpinski bush.
    fn bush() -> Hierarchy {
        let trunk = Object { entries: vec![entry(Target::Shape(0), DVec3::ZERO, DQuat::IDENTITY, RED), entry(Target::Shape(0), DVec3::Y, DQuat::IDENTITY, RED)], leaves: 2 };
        let top = DVec3::Y * 2.0;
        let mut entries = vec![entry(Target::Object(0), DVec3::ZERO, DQuat::IDENTITY, [0; 4]), entry(Target::Shape(0), top, DQuat::IDENTITY, BLUE)];
        for i in 0..3 {
            let turn = DQuat::from_rotation_y((120.0 * i as f64).to_radians()) * DQuat::from_rotation_z(35f64.to_radians());
            entries.push(entry(Target::Object(0), top, turn, [0; 4]));
        }
        Hierarchy { shapes: vec![segment()], objects: vec![trunk, Object { entries, leaves: 9 }], truncated: None }
    }

    fn leaves(h: &Hierarchy) -> Vec<Solid> {
        h.shapes.iter().map(|s| super::super::solid::leaf_solid(&s.prototype(16)).expect("a closed tube")).collect()
    }

    #[test]
    fn a_small_bush_unites_into_one_closed_shell_with_its_leaves_colours() {
        let h = bush();
        let solid = unite_rigid(&h, &leaves(&h), &mut Budget::new(Limits::default())).expect("union").expect("solid");
        let m = HalfEdgeMesh::new(solid.positions.clone(), solid.tris.clone()).expect("manifold");
        assert!(m.is_closed() && m.nonmanifold_vertices().is_empty());
        let pieces = crate::print::joined_through_triangles(solid.positions.len(), solid.tris.iter().map(|t| t.as_slice()));
        let mut roots: Vec<u32> = (0..solid.positions.len() as u32).map(|v| { let mut r = v; while pieces[r as usize] != r { r = pieces[r as usize]; } r }).collect();
        roots.sort_unstable();
        roots.dedup();
        assert_eq!(roots.len(), 1, "one shell");
        // Nine octagonal segments of 0.8 across overlap at the fork: less than their sum.
        let segment = 8.0 * 0.5 * 0.4f64.powi(2) * (std::f64::consts::TAU / 8.0).sin();
        let volume = m.signed_volume();
        assert!(volume > 5.0 * segment && volume < 9.0 * segment, "{volume} against {segment} a segment");
        // Colours come through the union as Manifold's original IDs.
        assert!(solid.colours.contains(&RED) && solid.colours.contains(&BLUE));
        assert!(solid.colours.iter().all(|c| *c == RED || *c == BLUE));
        let on_blue_cap = |v: u32| {
            let p = solid.positions[v as usize];
            (p.y - 3.0).abs() < 1e-5 && p.x * p.x + p.z * p.z < 0.17
        };
        let cap: Vec<[u8; 4]> = solid.tris.iter().zip(&solid.colours).filter(|(t, _)| t.iter().all(|&v| on_blue_cap(v))).map(|(_, c)| *c).collect();
        assert!(!cap.is_empty() && cap.iter().all(|c| *c == BLUE), "the blue segment's top cap: {cap:?}");
        // The same hierarchy gives the same solid, vertex for vertex.
        let again = unite_rigid(&h, &leaves(&h), &mut Budget::new(Limits::default())).expect("union").expect("solid");
        assert_eq!((solid.positions, solid.tris, solid.colours), (again.positions, again.tris, again.colours));
    }

    #[test]
    fn the_union_is_charged_and_its_memory_returned() {
        let h = bush();
        let mut budget = Budget::new(Limits::default());
        unite_rigid(&h, &leaves(&h), &mut budget).expect("union").expect("solid");
        assert_eq!(budget.memory(), 0, "every reservation released");
        assert!(budget.steps() > 0);
        let tight = Limits { max_memory: 1_000, ..Limits::default() };
        let refused = unite_rigid(&h, &leaves(&h), &mut Budget::new(tight));
        assert!(matches!(refused, Err(PrintError::Limit(l)) if l.limit == crate::core::budget::Limit::Memory), "{refused:?}");
    }
}
