//! The union of an instancing hierarchy, once per distinct subtree (issue
//! 16's fast unions).
//!
//! A hierarchy (MDG's memoised subtrees) places each distinct subtree
//! wherever it occurs: the level-3 Menger sponge is 20 copies of 20 copies
//! of 20 cubes, 4 objects for 8,000 cubes. The union of an object is the
//! union of its entries, each a leaf shape or a child object's union,
//! placed by the entry's similarity transform (rotation, uniform scale,
//! translation: a child's closed, outward union stays closed and outward).
//! So each object is united once, children first, from its children's
//! unions, and reused wherever it is placed: the sponge is three unions of
//! 20 pieces instead of one of 8,000, 20 times less triangles crossing
//! each other's boxes at the top, and Manifold's batch union (which already
//! composes pieces whose boxes are disjoint without a boolean) does the
//! rest.
//!
//! Every object's pieces are snapped to a grid of its own, 2⁻²⁰ of its
//! largest coordinate's power of two (as the flat union snaps the whole
//! model, `union::snap_grid`), so faces that coincide in exact arithmetic
//! (sibling sub-sponges' faces) coincide exactly and fuse. Colours go up
//! the same way: each object's united triangles take the colour of the
//! piece triangle they lie in (`colour::triangle_colours`), once per object.

use super::solid::{leaf_solid, Solid};
use super::union::{self, Piece};
use super::{colour, PrintError};
use crate::core::budget::Budget;
use crate::model::hierarchy::{Entry, Hierarchy, Target};
use glam::DVec3;

/// The union of a hierarchy's expansion and what the report needs of its parts.
pub(super) struct United {
    /// The root object's union.
    pub solid: Solid,
    /// Closed parts in the expansion (its leaves).
    pub parts: u64,
    /// The smallest bounding-box side of any placed part (model units).
    pub min_extent: f64,
}

/// Unites `h` object by object, children first, at `detail`. `None` when a
/// leaf shape is not one closed solid, a placement is not finite, Manifold
/// refuses an object's pieces, or nothing is drawn: the flat route (split
/// into parts, thickened or left out) then decides.
pub(super) fn unite_hierarchy(h: &Hierarchy, detail: u32, budget: &mut Budget) -> Result<Option<United>, PrintError> {
    let Some(leaves) = h.shapes.iter().map(|s| leaf_solid(&s.prototype(detail))).collect::<Option<Vec<Solid>>>() else {
        return Ok(None);
    };
    budget.charge_steps(h.leaves())?;
    let Some(min_extent) = min_extent(h, &leaves) else { return Ok(None) };
    if !h.is_scaled() {
        // Rigid (L-systems): kept in Manifold's double precision between levels.
        return Ok(super::rigid::unite_rigid(h, &leaves, budget)?.map(|solid| United { solid, parts: h.leaves(), min_extent }));
    }
    let used = h.multiplicities();
    let mut solids: Vec<Solid> = Vec::with_capacity(h.objects.len());
    let mut held = 0u64;
    for (object, &count) in h.objects.iter().zip(&used) {
        if count == 0 {
            solids.push(Solid::default());
            continue;
        }
        budget.check_deadline()?;
        // (Whether the entry places a child object, the placed piece.) Empty
        // pieces (a subtree that draws nothing) take no part.
        let placed: Vec<(bool, Solid)> = object
            .entries
            .iter()
            .map(|e| {
                let (source, colour) = match e.target {
                    Target::Shape(s) => (leaves.get(s as usize), Some(e.colour)),
                    Target::Object(c) => (solids.get(c as usize), None),
                };
                (matches!(e.target, Target::Object(_)), place(source.unwrap_or(&Solid::default()), e, colour))
            })
            .filter(|(_, p)| !p.tris.is_empty())
            .collect();
        if placed.iter().any(|(_, p)| p.positions.iter().any(|q| !q.is_finite())) {
            return Ok(None);
        }
        let solid = match placed.len() {
            0 => Solid::default(),
            // One child object placed alone is already a union: placing it is enough.
            1 if placed[0].0 => placed.into_iter().next().map(|(_, p)| p).unwrap_or_default(),
            _ => match unite_pieces(&placed.into_iter().map(|(_, p)| p).collect::<Vec<_>>(), budget) {
                // Manifold refused a piece (say, one snapped flat): the flat route decides.
                Err(PrintError::Union(_)) => return Ok(None),
                united => united?,
            },
        };
        held += solid.bytes();
        budget.reserve_memory(solid.bytes())?;
        solids.push(solid);
    }
    budget.release_memory(held);
    let solid = solids.pop().unwrap_or_default();
    if solid.tris.is_empty() {
        // Nothing drawn: the flat route says so.
        return Ok(None);
    }
    Ok(Some(United { solid, parts: h.leaves(), min_extent }))
}

/// One object's union of its placed pieces, snapped to its own grid, with
/// each united triangle's colour.
fn unite_pieces(placed: &[Solid], budget: &mut Budget) -> Result<Solid, PrintError> {
    let pieces: Vec<Piece<'_>> = placed.iter().map(|p| (p.positions.as_slice(), p.tris.as_slice())).collect();
    let grid = union::snap_grid(&pieces);
    let (positions, indices) = union::unite(&pieces, grid, budget)?;
    // Colours against the snapped pieces: the union's faces lie in them.
    let snapped: Vec<Vec<DVec3>> = placed.iter().map(|p| p.positions.iter().map(|q| union::snap(*q, grid)).collect()).collect();
    let snapped_pieces: Vec<Piece<'_>> = snapped.iter().zip(placed).map(|(s, p)| (s.as_slice(), p.tris.as_slice())).collect();
    let colours: Vec<Vec<[u8; 4]>> = placed.iter().map(|p| p.colours.clone()).collect();
    let colours = colour::triangle_colours(&snapped_pieces, &colours, &positions, &indices, budget)?;
    let tris = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    Ok(Solid { positions, tris, colours })
}

/// `s` placed by entry `e` (its colour replaced by `colour`, a leaf's).
fn place(s: &Solid, e: &Entry, colour: Option<[u8; 4]>) -> Solid {
    let positions = s.positions.iter().map(|p| e.translation + e.rotation * (*p * e.scale)).collect();
    let colours = match colour {
        Some(c) => vec![c; s.tris.len()],
        None => s.colours.clone(),
    };
    Solid { positions, tris: s.tris.clone(), colours }
}

/// The smallest bounding-box side of any leaf placed in the expansion
/// (what the flat route's `min_extent` measures), `None` when a placement
/// is not finite. One pass over the leaves, each shape's positions placed.
fn min_extent(h: &Hierarchy, leaves: &[Solid]) -> Option<f64> {
    let mut least = f64::INFINITY;
    h.walk(&mut |leaf| {
        if let Some(s) = leaves.get(leaf.shape as usize) {
            let (lo, hi) = super::bounds(s.positions.iter().map(|p| leaf.translation + leaf.rotation * (*p * leaf.scale)));
            least = least.min((hi - lo).min_element());
        }
    });
    least.is_finite().then_some(least)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;
    use crate::core::PrimitiveKind;
    use crate::geom::halfedge::HalfEdgeMesh;
    use crate::model::hierarchy::{LeafShape, Object};
    use glam::DQuat;

    /// An entry placing `target` at `t` scaled by `s`.
    fn entry(target: Target, t: DVec3, s: f64, colour: [u8; 4]) -> Entry {
        Entry { target, translation: t, rotation: DQuat::IDENTITY, scale: s, colour }
    }

    /// The 20 kept cells of a 3 × 3 × 3 split (at most one zero coordinate).
    fn cells() -> Vec<DVec3> {
        const R: [f64; 3] = [-1.0, 0.0, 1.0];
        R.iter().flat_map(|&x| R.iter().flat_map(move |&y| R.iter().map(move |&z| DVec3::new(x, y, z)))).filter(|c| c.to_array().iter().filter(|v| **v == 0.0).count() <= 1).collect()
    }

    /// A Menger sponge of `levels` objects over one box (20^levels leaves), as MDG memoises it.
    fn sponge(levels: usize) -> Hierarchy {
        let mut objects = Vec::new();
        for level in 0..levels {
            let target = if level == 0 { Target::Shape(0) } else { Target::Object(level as u32 - 1) };
            let entries = cells().into_iter().map(|c| entry(target, c / 3.0, 1.0 / 3.0, [200, 150, 60, 255])).collect();
            objects.push(Object { entries, leaves: 20u64.pow(level as u32 + 1) });
        }
        Hierarchy { shapes: vec![LeafShape::primitive(PrimitiveKind::Box)], objects, truncated: None }
    }

    /// The united solid as a checked half-edge mesh (closed, no pinched vertex) and its volume.
    fn closed_volume(s: &Solid) -> f64 {
        let m = HalfEdgeMesh::new(s.positions.clone(), s.tris.clone()).expect("manifold");
        assert!(m.is_closed() && m.nonmanifold_vertices().is_empty());
        m.signed_volume()
    }

    #[test]
    fn a_level_two_sponge_unites_per_subtree_into_one_closed_solid_of_its_volume() {
        let mut budget = Budget::new(Limits::default());
        let u = unite_hierarchy(&sponge(2), 8, &mut budget).expect("union").expect("boxes are solids");
        assert_eq!(u.parts, 400);
        assert!((u.min_extent - 1.0 / 9.0).abs() < 1e-12, "{}", u.min_extent);
        let volume = closed_volume(&u.solid);
        // Snapped to 2^-20: each box moves by under a millionth.
        assert!((volume - (20.0f64 / 27.0).powi(2)).abs() < 1e-5, "{volume}");
        // The same hierarchy gives the same solid, vertex for vertex.
        let again = unite_hierarchy(&sponge(2), 8, &mut budget).expect("union").expect("solids");
        assert_eq!((u.solid.positions, u.solid.tris), (again.solid.positions, again.solid.tris));
    }

    #[test]
    fn colours_follow_the_leaves_up_the_hierarchy() {
        // Object 0: a red box overlapping a blue one; the root places it twice, end to end.
        let (red, blue) = ([255, 0, 0, 255], [0, 0, 255, 255]);
        let pair = Object { entries: vec![entry(Target::Shape(0), DVec3::ZERO, 1.0, red), entry(Target::Shape(0), DVec3::X * 0.5, 1.0, blue)], leaves: 2 };
        let root = Object { entries: vec![entry(Target::Object(0), DVec3::ZERO, 1.0, [0; 4]), entry(Target::Object(0), DVec3::X * 1.5, 1.0, [0; 4])], leaves: 4 };
        let h = Hierarchy { shapes: vec![LeafShape::primitive(PrimitiveKind::Box)], objects: vec![pair, root], truncated: None };
        let u = unite_hierarchy(&h, 8, &mut Budget::new(Limits::default())).expect("union").expect("solids");
        // Boxes at 0, 0.5, 1.5 and 2: one block from -0.5 to 2.5 (the pairs touch at x = 1).
        assert!((closed_volume(&u.solid) - 3.0).abs() < 1e-9);
        for (t, c) in u.solid.tris.iter().zip(&u.solid.colours) {
            let x = t.iter().map(|&v| u.solid.positions[v as usize].x).sum::<f64>() / 3.0;
            // Where only one box's face is (the overlaps' coplanar faces may go either way).
            let only = |a: f64, b: f64| x > a && x < b;
            if only(-1.0, -0.05) || only(1.05, 1.45) {
                assert_eq!(*c, red, "x {x}");
            } else if only(0.55, 0.95) || only(2.05, 3.0) {
                assert_eq!(*c, blue, "x {x}");
            }
        }
        assert!(u.solid.colours.contains(&blue) && u.solid.colours.contains(&red));
    }

    #[test]
    fn a_subtree_that_draws_nothing_takes_no_part() {
        let box_shape = vec![LeafShape::primitive(PrimitiveKind::Box)];
        let empty = Object { entries: Vec::new(), leaves: 0 };
        let grey = [200, 200, 200, 255];
        let root = Object { entries: vec![entry(Target::Object(0), DVec3::ZERO, 1.0, [0; 4]), entry(Target::Shape(0), DVec3::ZERO, 1.0, grey)], leaves: 1 };
        let h = Hierarchy { shapes: box_shape.clone(), objects: vec![empty.clone(), root], truncated: None };
        let u = unite_hierarchy(&h, 8, &mut Budget::new(Limits::default())).expect("union").expect("a box");
        assert!((closed_volume(&u.solid) - 1.0).abs() < 1e-9);
        // Nothing at all: the flat route says why.
        let nothing = Object { entries: vec![entry(Target::Object(0), DVec3::ZERO, 1.0, [0; 4])], leaves: 0 };
        let h = Hierarchy { shapes: box_shape, objects: vec![empty, nothing], truncated: None };
        assert!(unite_hierarchy(&h, 8, &mut Budget::new(Limits::default())).expect("no error").is_none());
    }
}
