//! A memoised CFDG picture ([`Expansion`], `eval/run/memo.rs`) as an
//! object-instancing [`Hierarchy`] (Calgary instancing thesis §2.2): each
//! distinct expanded subtree one object, placed by its replacement's
//! adjustment wherever it occurs, so the bush's 262 143 squares are 18
//! objects, as the MDG bush's boxes are, and `scene` and instanced glTF
//! write them from it.
//!
//! Subtrees are shared by what was actually drawn, not by shape alone:
//! two nodes of one shape are the same object only when the same
//! replacements of theirs were kept (the minimum size and a truncation cut
//! a run in cfdg's largest-first order, not per subtree) and their
//! primitives have the same colours. So the hierarchy expands to exactly
//! the picture's primitives, whatever cut the run made.
//!
//! The flat tiles ([`super::tiles`]) are all one thickness and lifted by
//! their drawing order, which no object can hold (its instances are drawn
//! at different times). Here the thickness and lift are a generation's: an
//! object's own tiles fill `[0, t]` of its frame, its primitives stacked in
//! body order (each `t / m` thick for `m` primitives), and its child
//! objects stand on them, lifted by `t`. A descendant is always drawn after
//! its ancestors (a child is expanded only after its parent), so the top
//! view keeps cfdg's order wherever shapes of one line of descent overlap;
//! cousins of one generation are level. `t` is the flat tiles' thickness in
//! the start shape's frame, so every tile is that fraction of its own
//! shape's size (a similarity scales its thickness too).
//!
//! Given up (the flat tiles instead) when a replacement is not a
//! similarity (a flip, skew or unequal scale: the hierarchy's frames are
//! rotation, uniform scale and translation), a `z` changes the drawing
//! order, or a TRIANGLE is drawn (the Model has no triangular prototype).

use super::eval::state::Affine;
use super::eval::Picture;
use crate::core::budget::Budget;
use crate::core::PrimitiveKind;
use crate::model::hierarchy::{Entry, Hierarchy, LeafShape, Object, Target, ENTRY_BYTES};
use crate::model::EvalError;
use glam::{DQuat, DVec3};
use std::collections::HashMap;

const NONE: u32 = u32::MAX;
const LEAF: u32 = 1 << 31;

/// An edge's translation (x, y), rotation angle and uniform scale, and
/// for a primitive its slot among its body's `m` primitives: (k, m).
type Placement = (f64, f64, f64, f64, u32, u32);

/// Rotation angle and uniform scale of a non-mirrored similarity, else `None`.
fn similarity(m: &Affine) -> Option<(f64, f64)> {
    let s = m.sx.hypot(m.shy);
    let tol = 1e-9 * s;
    let ok = s.is_finite() && s > 0.0 && (m.sx - m.sy).abs() <= tol && (m.shx + m.shy).abs() <= tol && m.tx.is_finite() && m.ty.is_finite();
    ok.then(|| (m.shy.atan2(m.sx), s))
}

/// Linear 8-bit RGBA of a CFDG colour (the flat tiles' conversion, quantised).
fn colour(rgba: &[f64; 4]) -> [u8; 4] {
    let lin = |c: f64| {
        let c = c.clamp(0.0, 1.0);
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let q = |v: f64| (v * 255.0).round().clamp(0.0, 255.0) as u8;
    [q(lin(rgba[0])), q(lin(rgba[1])), q(lin(rgba[2])), q(rgba[3])]
}

/// The hierarchy of `p` when its run was memoised and recorded and every
/// placement is a similarity; `None` leaves it to the flat tiles. Charges
/// the entries it makes.
pub fn hierarchy(p: &Picture, budget: &mut Budget) -> Result<Option<Hierarchy>, EvalError> {
    let Some(x) = p.memo.as_deref() else { return Ok(None) };
    let Some(start) = x.start else { return Ok(None) };
    if !x.recorded || p.shapes.iter().any(|s| s.kind > 1 || s.z != 0.0) {
        return Ok(None);
    }
    let Some((start_angle, start_scale)) = similarity(&start.transform) else { return Ok(None) };
    // Every edge a similarity that leaves z alone; its placement and, for
    // a primitive, its slot among the body's primitives.
    let mut place: Vec<Vec<Option<Placement>>> = Vec::with_capacity(x.plan.bodies.len());
    for body in &x.plan.bodies {
        let m = body.iter().filter(|e| e.leaf).count() as u32;
        let mut k = 0;
        let mut row = Vec::with_capacity(body.len());
        for e in body {
            let r = &e.relative;
            let Some((angle, scale)) = similarity(&r.transform) else { return Ok(None) };
            if r.tz != 0.0 || r.sz != 1.0 || (e.leaf && e.shape > 1) {
                return Ok(None);
            }
            row.push(Some((r.transform.tx, r.transform.ty, angle, scale, k, m)));
            k += u32::from(e.leaf);
        }
        place.push(row);
    }
    // The flat tiles' thickness in the start shape's frame.
    let px = p.to_pixels.sx.abs().max(1e-300);
    let extent = f64::from(p.width.max(p.height)) / px;
    let t = (extent * super::tiles::THICKNESS).max(f64::MIN_POSITIVE) / start_scale;
    // Finished order → index in the picture (absent: cut at the end).
    let mut drawn = vec![NONE; usize::try_from(p.finished).unwrap_or(0)];
    for (i, s) in p.shapes.iter().enumerate() {
        if let Some(slot) = usize::try_from(s.order).ok().and_then(|o| o.checked_sub(1)).and_then(|o| drawn.get_mut(o)) {
            *slot = i as u32;
        }
    }
    let mut h = Hierarchy { truncated: p.truncated, ..Hierarchy::default() };
    let mut leaf_ids: HashMap<(u8, u32, u32), u32> = HashMap::new();
    let mut leaf_shape = |kind: usize, k: u32, m: u32, shapes: &mut Vec<LeafShape>| -> u32 {
        *leaf_ids.entry((kind as u8, k, m)).or_insert_with(|| {
            let (th, z) = (t / f64::from(m), t * (f64::from(k) + 0.5) / f64::from(m));
            let (th, z) = (th as f32, z as f32);
            // A CIRCLE is a cylinder along +Y turned up to +Z by its entry.
            let (kind, scale, offset) = if kind == 0 { (PrimitiveKind::Cylinder, [1.0, th, 1.0], [0.0, z, 0.0]) } else { (PrimitiveKind::Box, [1.0, 1.0, th], [0.0, 0.0, z]) };
            shapes.push(LeafShape { kind, scale, offset, tube: false });
            (shapes.len() - 1) as u32
        })
    };
    let up = DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2);
    let leaf_entry = |shape: u32, kind: usize, c: [u8; 4], (tx, ty, angle, scale): (f64, f64, f64, f64)| {
        let rot = DQuat::from_rotation_z(angle);
        Entry { target: Target::Shape(shape), translation: DVec3::new(tx, ty, 0.0), rotation: if kind == 0 { rot * up } else { rot }, scale, colour: c }
    };
    let mut object_of = vec![NONE; x.first.len()];
    let mut interned: HashMap<(u32, Vec<u64>), u32> = HashMap::new();
    for n in (0..x.first.len()).rev() {
        let first = x.first[n];
        if first == NONE {
            continue;
        }
        let shape = x.shape[n] as usize;
        let (Some(body), Some(row)) = (x.plan.bodies.get(shape), place.get(shape)) else { continue };
        let mut entries = Vec::new();
        let mut key = Vec::new();
        let mut leaves = 0u64;
        if body.len() != row.len() {
            continue;
        }
        for (k, pl) in row.iter().enumerate() {
            let Some((tx, ty, angle, scale, slot, m)) = *pl else { continue };
            let Some(&out) = x.outcomes.get(first as usize + k) else { continue };
            if out == NONE {
                continue;
            }
            if out & LEAF != 0 {
                let Some(&i) = drawn.get((out & !LEAF) as usize) else { continue };
                let Some(s) = p.shapes.get(i as usize) else { continue };
                let c = colour(&s.rgba);
                let id = leaf_shape(s.kind, slot, m, &mut h.shapes);
                entries.push(leaf_entry(id, s.kind, c, (tx, ty, angle, scale)));
                key.push((k as u64) << 40 | 1 << 39 | u64::from(u32::from_le_bytes(c)));
                leaves += 1;
            } else if let Some(&o) = object_of.get(out as usize).filter(|&&o| o != NONE) {
                entries.push(Entry { target: Target::Object(o), translation: DVec3::new(tx, ty, t), rotation: DQuat::from_rotation_z(angle), scale, colour: [0; 4] });
                key.push((k as u64) << 40 | u64::from(o));
                leaves = leaves.saturating_add(h.objects[o as usize].leaves);
            }
        }
        if entries.is_empty() {
            continue;
        }
        let id = match interned.get(&(shape as u32, key.clone())) {
            Some(&id) => id,
            None => {
                budget.reserve_memory(ENTRY_BYTES * entries.len() as u64)?;
                h.objects.push(Object { entries, leaves });
                let id = (h.objects.len() - 1) as u32;
                interned.insert((shape as u32, key), id);
                id
            }
        };
        object_of[n] = id;
    }
    // The root: the start shape's object as it is when the start state is
    // the identity, else placed by it; a start primitive in an object of its own.
    let root_place = (start.transform.tx, start.transform.ty, start_angle, start_scale);
    let root_entry = if x.root == NONE {
        None
    } else if x.root & LEAF != 0 {
        let s = drawn.get((x.root & !LEAF) as usize).and_then(|&i| p.shapes.get(i as usize));
        s.map(|s| leaf_entry(leaf_shape(s.kind, 0, 1, &mut h.shapes), s.kind, colour(&s.rgba), root_place))
    } else {
        let o = object_of.get(x.root as usize).copied().unwrap_or(NONE);
        let identity = start.transform == Affine::default();
        if o != NONE && identity && o as usize + 1 == h.objects.len() {
            return Ok(Some(h));
        }
        (o != NONE).then(|| Entry { target: Target::Object(o), translation: DVec3::new(root_place.0, root_place.1, 0.0), rotation: DQuat::from_rotation_z(start_angle), scale: start_scale, colour: [0; 4] })
    };
    let Some(e) = root_entry else { return Ok(None) };
    {
        budget.reserve_memory(ENTRY_BYTES)?;
        let leaves = match e.target {
            Target::Object(o) => h.objects[o as usize].leaves,
            Target::Shape(_) => 1,
        };
        h.objects.push(Object { entries: vec![e], leaves });
    }
    Ok(Some(h))
}
