//! Object-instancing hierarchies (Calgary instancing thesis §2.2, §4.2): objects that are
//! lists of (child object or leaf shape, rigid or similarity transform, colour).
//!
//! A [`Hierarchy`] is what an instanced L-system (or a shareable MDG
//! grammar, `eval::memo`) evaluates to instead of a flat
//! [`Scene`](crate::model::Scene): each distinct subtree of the derivation is one
//! object, placed wherever the subtree occurs, so the hierarchy grows with the
//! number of distinct subtrees (the b-grammar), not with the number of
//! segments. Exporters either write it as it is (`format=scene`), walk it to
//! write per-instance transforms (`EXT_mesh_gpu_instancing`), or expand it
//! into a flat scene.
//!
//! Objects are stored children first: an entry of object `i` refers only to
//! objects `j < i` (the thesis's ordering condition), so the hierarchy is
//! acyclic by construction and the root is the last object.

use crate::core::budget::{Budget, LimitExceeded};
use crate::core::frame::Frame;
use crate::model::scene::{Scene, ShapeInstance, SHAPE_INSTANCE_BYTES};
use crate::geom::primitives::{self, Prototype};
use crate::core::PrimitiveKind;
use glam::{DQuat, DVec3};
use std::collections::BTreeMap;

/// A leaf shape: a built-in primitive scaled per axis, then moved by `offset`,
/// in the frame its entry places it in. One exists per distinct segment look
/// (kind, length, width), so it can become one shared mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeafShape {
    /// The primitive.
    pub kind: PrimitiveKind,
    /// Scale along local x, y, z (the primitive is unit-sized).
    pub scale: [f32; 3],
    /// Translation applied after the scale.
    pub offset: [f32; 3],
    /// A tube segment: tessellated with the sides of a swept tube's profile
    /// (half the detail, at least 4) rather than the full detail, so an
    /// instanced tube costs what the swept one would.
    pub tube: bool,
}

impl LeafShape {
    /// The bare unit primitive (MDG's leaves): no scale, no offset, so its
    /// prototype is the tessellation the flat mesher uses, bit for bit.
    pub fn primitive(kind: PrimitiveKind) -> LeafShape {
        LeafShape { kind, scale: [1.0; 3], offset: [0.0; 3], tube: false }
    }

    /// True for a [`LeafShape::primitive`]: its prototype is left untouched
    /// (scaling by 1 would still renormalise the normals and lose -0.0).
    pub fn is_bare(&self) -> bool {
        self.scale == [1.0; 3] && self.offset == [0.0; 3] && !self.tube
    }

    /// The primitive tessellated at `detail` with this shape's scale and offset
    /// baked in (normals follow the inverse transpose of the scale).
    pub fn prototype(&self, detail: u32) -> Prototype {
        let mut p = primitives::tessellate(self.kind, self.detail(detail));
        if self.is_bare() {
            return p;
        }
        let [sx, sy, sz] = self.scale;
        for v in &mut p.positions {
            *v = [v[0] * sx + self.offset[0], v[1] * sy + self.offset[1], v[2] * sz + self.offset[2]];
        }
        let inv = |s: f32| if s == 0.0 { 0.0 } else { 1.0 / s };
        for n in &mut p.normals {
            let m = glam::Vec3::new(n[0] * inv(sx), n[1] * inv(sy), n[2] * inv(sz)).normalize_or_zero();
            *n = m.to_array();
        }
        p
    }

    /// Triangles of one placement at `detail`.
    pub fn triangles(&self, detail: u32) -> u64 {
        primitives::triangle_count(self.kind, self.detail(detail))
    }

    /// The detail this shape is tessellated at under a request's `detail`.
    pub fn detail(&self, detail: u32) -> u32 {
        if self.tube {
            u32::try_from(crate::geom::sweep::profile_sides(detail)).unwrap_or(detail)
        } else {
            detail
        }
    }
}

/// What an entry places.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Target {
    /// Another object (always of a lower index).
    Object(u32),
    /// A leaf shape (index into [`Hierarchy::shapes`]).
    Shape(u32),
}

/// One placement inside an object: a target in a frame relative to the
/// object's, rigid (L-systems) or a similarity (MDG: a uniform scale too;
/// mirrored frames are never shared, so there is no parity).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    /// What is placed.
    pub target: Target,
    /// Where the target's origin goes, in the object's frame.
    pub translation: DVec3,
    /// The target's rotation relative to the object (unit).
    pub rotation: DQuat,
    /// The target's uniform scale relative to the object (1 for rigid entries,
    /// always > 0): composed as [`Frame::then`] composes, so a walk reproduces
    /// the frames of the derivation it was built from bit for bit.
    pub scale: f64,
    /// Linear RGBA of a leaf in 0..=255 (objects carry their leaves' own colours; 0 for them).
    pub colour: [u8; 4],
}

/// A list of placements.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Object {
    /// The placements, in drawing order.
    pub entries: Vec<Entry>,
    /// Leaves in the object's full expansion (saturating), for budgets before any walk.
    pub leaves: u64,
}

/// A leaf of the expanded hierarchy: a shape in world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedLeaf {
    /// Index into [`Hierarchy::shapes`].
    pub shape: u32,
    /// World translation.
    pub translation: DVec3,
    /// World rotation (unit).
    pub rotation: DQuat,
    /// World uniform scale (1 in a rigid hierarchy).
    pub scale: f64,
    /// Linear RGBA in 0..=255.
    pub colour: [u8; 4],
}

impl PlacedLeaf {
    /// The leaf's world frame (never mirrored).
    pub fn frame(&self) -> Frame {
        Frame { translation: self.translation, rotation: self.rotation, scale: self.scale, parity: false }
    }
}

/// An object-instancing hierarchy; see the module documentation.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Hierarchy {
    /// The distinct leaf shapes.
    pub shapes: Vec<LeafShape>,
    /// The objects, children before parents; the last one is the root.
    pub objects: Vec<Object>,
    /// Set when a limit cut the model short (only with `on_limit = truncate`).
    pub truncated: Option<LimitExceeded>,
}

/// Bytes accounted per stored entry.
pub const ENTRY_BYTES: u64 = std::mem::size_of::<Entry>() as u64;

impl Hierarchy {
    /// Expands the hierarchy into a flat scene, each leaf shape once and
    /// placed at every leaf, for outputs that cannot instance. The placements
    /// are charged to `budget` first.
    pub fn expand(&self, detail: u32, budget: &mut Budget) -> Result<Scene, LimitExceeded> {
        let mut scene = Scene::default();
        budget.reserve_memory(self.leaves().saturating_mul(SHAPE_INSTANCE_BYTES))?;
        scene.shapes = self.shapes.iter().map(|s| s.prototype(detail)).collect();
        scene.shape_instances.reserve_exact(self.leaves() as usize);
        self.walk(&mut |leaf| {
            scene.shape_instances.push(ShapeInstance { shape: leaf.shape, frame: leaf.frame(), colour: leaf.colour.map(|c| f32::from(c) / 255.0) });
        });
        scene.truncated = self.truncated;
        Ok(scene)
    }

    /// Leaves in the full expansion (0 when there is no root).
    pub fn leaves(&self) -> u64 {
        self.objects.last().map_or(0, |o| o.leaves)
    }

    /// True when some entry scales its target (an MDG hierarchy): the scene
    /// format then writes each entry's scale and instanced glTF a SCALE per instance.
    pub fn is_scaled(&self) -> bool {
        self.objects.iter().flat_map(|o| &o.entries).any(|e| e.scale != 1.0)
    }

    /// Entries over all objects: the size of the hierarchy.
    pub fn entry_count(&self) -> u64 {
        self.objects.iter().map(|o| o.entries.len() as u64).sum()
    }

    /// How often each object occurs in the expansion (the root once), saturating.
    pub fn multiplicities(&self) -> Vec<u64> {
        let mut mult = vec![0u64; self.objects.len()];
        if let Some(last) = mult.last_mut() {
            *last = 1;
        }
        for i in (0..self.objects.len()).rev() {
            let m = mult[i];
            for e in &self.objects[i].entries {
                if let Target::Object(c) = e.target {
                    if let Some(slot) = mult.get_mut(c as usize) {
                        *slot = slot.saturating_add(m);
                    }
                }
            }
        }
        mult
    }

    /// Leaves per (shape, colour) in the expansion, in (shape, colour) order:
    /// the instance count of each mesh an instanced export writes.
    pub fn leaf_counts(&self) -> BTreeMap<(u32, [u8; 4]), u64> {
        let mult = self.multiplicities();
        let mut out = BTreeMap::new();
        for (o, m) in self.objects.iter().zip(mult) {
            for e in &o.entries {
                if let Target::Shape(s) = e.target {
                    let c = out.entry((s, e.colour)).or_insert(0u64);
                    *c = c.saturating_add(m);
                }
            }
        }
        out
    }

    /// Triangles of the full expansion at `detail` (saturating).
    pub fn triangles(&self, detail: u32) -> u64 {
        self.leaf_counts().iter().fold(0u64, |acc, (&(s, _), &n)| {
            let t = self.shapes.get(s as usize).map_or(0, |sh| sh.triangles(detail));
            acc.saturating_add(t.saturating_mul(n))
        })
    }

    /// Calls `f` with every leaf of the expansion in world space, depth first
    /// in entry order (the order the turtle drew them). The walk keeps its own
    /// stack, one frame per level, so a deep hierarchy (say, a decoded file)
    /// cannot overflow the thread's stack; its cost is the number of leaves,
    /// which [`Hierarchy::leaves`] tells before walking.
    pub fn walk(&self, f: &mut dyn FnMut(&PlacedLeaf)) {
        self.walk_while(&mut |leaf| {
            f(leaf);
            true
        });
    }

    /// [`Hierarchy::walk`] that stops as soon as `f` returns false (a
    /// question about the leaves answered before the last one).
    pub fn walk_while(&self, f: &mut dyn FnMut(&PlacedLeaf) -> bool) {
        let Some(root) = self.objects.len().checked_sub(1) else { return };
        // (object, next entry, object's world frame). `Frame::then` with scale
        // 1 is the rigid composition t + r·t', (r·r')‾ bit for bit.
        let mut stack: Vec<(usize, usize, Frame)> = vec![(root, 0, Frame::IDENTITY)];
        while let Some(top) = stack.last_mut() {
            let (object, next, world) = *top;
            let Some(e) = self.objects.get(object).and_then(|o| o.entries.get(next)) else {
                stack.pop();
                continue;
            };
            top.1 += 1;
            let here = world.then(&Frame { translation: e.translation, rotation: e.rotation, scale: e.scale, parity: false });
            match e.target {
                Target::Object(c) if (c as usize) < object => stack.push((c as usize, 0, here)),
                Target::Object(_) => {}
                Target::Shape(shape) => {
                    if !f(&PlacedLeaf { shape, translation: here.translation, rotation: here.rotation, scale: here.scale, colour: e.colour }) {
                        return;
                    }
                }
            }
        }
    }
}
