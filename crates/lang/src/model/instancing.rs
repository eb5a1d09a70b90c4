//! GPU instancing of a flat [`Scene`] (issue 15): which placements draw the
//! same mesh, in the form `EXT_mesh_gpu_instancing` carries them, and what a
//! front end charges for a placement when the output will be instanced.
//!
//! A *mesh* here is a primitive kind (at the request's detail) of one class
//! (EisenScript's `box::glass`; class 0 elsewhere), or a scene shape (an
//! MDG `mesh` declaration or isosurface), each possibly *mirrored*. When a
//! mesh is placed more than once, an instanced output writes it once and
//! each placement as translation, rotation, per-axis scale and colour
//! ([`Placement`]); everything else stays plain geometry ([`Plan::residual`]).
//!
//! Mirrored placements (negative determinant) get their own mesh, the
//! prototype reflected through its origin with its winding reversed, and a
//! positive scale: the extension composes its TRS "as for nodes", so by the
//! glTF rules a negative scale would make clockwise faces front-facing, but
//! three.js flips the winding only for an object whose whole matrix is
//! mirrored, never per instance. With no negative scale written, the
//! validator, the specification and every loader agree.
//!
//! A placement is instanced only when its linear part is a rotation times a
//! per-axis scale, possibly mirrored (columns orthogonal to
//! [`ORTHOGONALITY`]): every MDG and shape placement (similarities) and the
//! EisenScript frames whose scales come after their rotations. A sheared
//! EisenScript frame has no TRS form and stays a plain, exact mesh.

use super::scene::{AffineInstance, Instance, Scene, ShapeInstance, AFFINE_INSTANCE_BYTES, INSTANCE_BYTES, SHAPE_INSTANCE_BYTES};
use crate::core::budget::{Budget, LimitExceeded};
use crate::core::PrimitiveKind;
use crate::geom::primitives::{self, Prototype};
use glam::{Mat3, Quat, Vec3};

/// What an instanced mesh draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Source {
    /// A built-in primitive at the request's detail.
    Primitive(PrimitiveKind),
    /// A scene shape (index into [`Scene::shapes`]).
    Shape(u32),
}

/// One mesh an instanced output writes once: what it draws, the class whose
/// material it has, and whether it is the mirrored copy.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct MeshKey {
    /// Index into [`Scene::classes`] (0: the default class).
    pub class: u32,
    /// The geometry.
    pub source: Source,
    /// The prototype reflected through its origin (winding reversed).
    pub mirrored: bool,
}

/// One placement of a mesh as an instance: the point `p` of the (possibly
/// mirrored) prototype goes to `translation + rotation · (scale ⊙ p)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// The mesh placed.
    pub key: MeshKey,
    /// Where the prototype's origin goes.
    pub translation: Vec3,
    /// A unit rotation.
    pub rotation: Quat,
    /// Positive scale along the prototype's axes.
    pub scale: Vec3,
    /// Linear RGBA8, quantised as the mesh stage quantises vertex colours,
    /// so an instance looks exactly like its flat copy.
    pub colour: [u8; 4],
}

/// The largest |cos| between two columns of a linear map that still counts
/// as orthogonal: about ten times the rounding of a frame stored in f32.
pub(crate) const ORTHOGONALITY: f32 = 1e-6;

/// Splits a linear map into rotation, positive per-axis scale and whether
/// it mirrors, when its columns are orthogonal: `L = R·diag(s)` or, mirrored,
/// `L = R·diag(s)·(−I)` with `R` a rotation. `None` for a sheared, flat or
/// non-finite map.
pub(crate) fn decompose(linear: Mat3) -> Option<(Quat, Vec3, bool)> {
    let cols = [linear.x_axis, linear.y_axis, linear.z_axis];
    let scale = Vec3::new(cols[0].length(), cols[1].length(), cols[2].length());
    if !scale.is_finite() || scale.min_element() <= 0.0 {
        return None;
    }
    let [a, b, c] = [cols[0] / scale.x, cols[1] / scale.y, cols[2] / scale.z];
    if a.dot(b).abs() > ORTHOGONALITY || b.dot(c).abs() > ORTHOGONALITY || c.dot(a).abs() > ORTHOGONALITY {
        return None;
    }
    let r = Mat3::from_cols(a, b, c);
    let mirrored = r.determinant() < 0.0;
    let r = if mirrored { r * -1.0 } else { r };
    Some((Quat::from_mat3(&r).normalize(), scale, mirrored))
}

/// Linear RGBA in [0, 1] as RGBA8, rounded (the vertex colours' quantisation).
pub fn rgba8(colour: [f32; 4]) -> [u8; 4] {
    crate::core::quantise::rgba8(colour)
}

impl Placement {
    /// The mesh a drawable similarity instance places: [`Placement::of_instance`]'s
    /// key without the rest, which the evaluator's per-primitive charge
    /// ([`Tally::cost`]) does not need.
    pub(crate) fn key_of_instance(i: &Instance) -> Option<MeshKey> {
        i.is_drawable().then_some(MeshKey { class: 0, source: Source::Primitive(i.kind), mirrored: i.parity })
    }

    /// A drawable similarity instance (MDG, stacking strings, UniGrafix, L-system turtles).
    pub fn of_instance(i: &Instance) -> Option<Placement> {
        i.is_drawable().then(|| Placement {
            key: MeshKey { class: 0, source: Source::Primitive(i.kind), mirrored: i.parity },
            translation: i.translation,
            rotation: i.rotation,
            scale: Vec3::splat(i.scale),
            colour: rgba8(i.colour),
        })
    }

    /// A drawable affine instance (EisenScript) whose linear part has a TRS form.
    pub(crate) fn of_affine(a: &AffineInstance) -> Option<Placement> {
        if !a.is_drawable() {
            return None;
        }
        let (rotation, scale, mirrored) = decompose(a.linear)?;
        let key = MeshKey { class: a.class, source: Source::Primitive(a.kind), mirrored };
        Some(Placement { key, translation: a.translation, rotation, scale, colour: rgba8(a.colour) })
    }

    /// A drawable placement of a scene shape, mapped as the mesh stage maps it.
    pub(crate) fn of_shape(s: &ShapeInstance) -> Option<Placement> {
        let i = Instance::new(PrimitiveKind::Box, &s.frame, s.colour.map(f64::from));
        let p = Placement::of_instance(&i)?;
        Some(Placement { key: MeshKey { source: Source::Shape(s.shape), ..p.key }, ..p })
    }
}

/// The prototype of `key`: the primitive tessellated at `detail` or the
/// scene shape, reflected through the origin (positions and normals
/// negated, winding reversed) when mirrored. `None` for a shape `scene` lacks.
pub fn prototype(key: &MeshKey, scene: &Scene, detail: u32) -> Option<Prototype> {
    let mut p = match key.source {
        Source::Primitive(kind) => primitives::tessellate(kind, detail),
        Source::Shape(s) => scene.shapes.get(s as usize)?.clone(),
    };
    if key.mirrored {
        for v in p.positions.iter_mut().chain(p.normals.iter_mut()) {
            *v = v.map(|c| -c);
        }
        for t in p.indices.chunks_exact_mut(3) {
            t.swap(1, 2);
        }
    }
    Some(p)
}

/// Dense numbering of the [`MeshKey`]s a scene can use, in key order.
#[derive(Debug, Clone, Copy)]
struct Dense {
    classes: usize,
    shapes: usize,
}

impl Dense {
    /// Sources per class: the nine primitives, then the shapes.
    fn sources(&self) -> usize {
        PrimitiveKind::ALL.len() + self.shapes
    }

    fn len(&self) -> usize {
        self.classes.saturating_mul(self.sources()).saturating_mul(2)
    }

    fn index(&self, k: &MeshKey) -> Option<usize> {
        let source = match k.source {
            Source::Primitive(p) => p as usize,
            Source::Shape(s) if (s as usize) < self.shapes => PrimitiveKind::ALL.len() + s as usize,
            Source::Shape(_) => return None,
        };
        ((k.class as usize) < self.classes).then(|| ((k.class as usize * self.sources()) + source) * 2 + usize::from(k.mirrored))
    }

    fn key(&self, i: usize) -> MeshKey {
        let (rest, mirrored) = (i / 2, i % 2 == 1);
        let (class, source) = (rest / self.sources(), rest % self.sources());
        let source = match PrimitiveKind::ALL.get(source) {
            Some(&p) => Source::Primitive(p),
            None => Source::Shape((source - PrimitiveKind::ALL.len()) as u32),
        };
        MeshKey { class: class as u32, source, mirrored }
    }
}

/// What differs between the placements of one instanced mesh. A writer
/// leaves out the attributes that do not vary (the identity rotation, unit
/// scale, one colour baked into the mesh), so a grid of a million boxes
/// costs 12 bytes per box on the wire instead of 52.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Varying {
    /// Some placement has a rotation other than the identity.
    pub rotation: bool,
    /// Some placement has a scale other than 1 on some axis.
    pub scale: bool,
    /// Not every placement has the same colour.
    pub colour: bool,
    /// The first placement's colour: every placement's when `colour` is false.
    pub first_colour: [u8; 4],
}

impl Varying {
    /// Nothing varies yet: the state before the first placement is seen.
    pub const NONE: Varying = Varying { rotation: false, scale: false, colour: false, first_colour: [0; 4] };

    /// Notes one more placement by its rotation, per-axis scale and RGBA8
    /// colour; `first` says whether it is the mesh's first. Every writer
    /// that leaves attributes out decides with this, so a flat scene and a
    /// hierarchy of the same model leave out the same ones.
    pub fn note(&mut self, rotation: Quat, scale: Vec3, colour: [u8; 4], first: bool) {
        // Exact comparisons: only a placement that is exactly the identity
        // may lose its attribute, so the instanced output stays exact.
        self.rotation |= rotation != Quat::IDENTITY;
        self.scale |= scale != Vec3::ONE;
        if first {
            self.first_colour = colour;
        } else {
            self.colour |= colour != self.first_colour;
        }
    }

    /// [`Varying::note`] of a placement.
    fn see(&mut self, p: &Placement, first: bool) {
        self.note(p.rotation, p.scale, p.colour, first);
    }
}

/// Which meshes of a scene an instanced output writes once, with how many
/// placements each: those placed at least twice, in [`MeshKey`] order.
#[derive(Debug, Clone)]
pub struct Plan {
    dense: Dense,
    /// Per dense index, the mesh's slot in [`Plan::meshes`] (`u32::MAX`: plain).
    slots: Vec<u32>,
    meshes: Vec<(MeshKey, u64)>,
    /// Per instanced mesh, what differs between its placements.
    varying: Vec<Varying>,
    /// Instanced placements among the scene's similarity, affine and shape
    /// placements: where one equals its list's length, the residual of that
    /// list is empty without a pass over it.
    covered: [u64; 3],
}

/// Largest number of dense keys a plan numbers; a scene with more classes
/// times shapes (none in practice) stays plain.
const MAX_KEYS: usize = 1 << 20;

impl Plan {
    /// Counts the placements of every mesh in `scene` (one pass, no copies).
    pub fn new(scene: &Scene) -> Plan {
        let dense = Dense { classes: scene.classes.len().max(1), shapes: scene.shapes.len() };
        if dense.len() > MAX_KEYS {
            return Plan { dense: Dense { classes: 0, shapes: 0 }, slots: Vec::new(), meshes: Vec::new(), varying: Vec::new(), covered: [0; 3] };
        }
        // Per dense key: placements, what varies, and placements per list.
        let mut counts = vec![(0u64, Varying::NONE, [0u64; 3]); dense.len()];
        // Similarity instances (nearly every placement of an MDG scene) are
        // noted without building their placements, and their colour is
        // rounded only when its bits differ from the mesh's first (equal
        // bits round equally): what `see` of their placements would note.
        let mut first_bits = vec![[0u32; 4]; dense.len()];
        for i in &scene.instances {
            let Some(at) = Placement::key_of_instance(i).and_then(|k| dense.index(&k)) else { continue };
            let (Some((n, v, lists)), Some(first)) = (counts.get_mut(at), first_bits.get_mut(at)) else { continue };
            let bits = i.colour.map(f32::to_bits);
            let colour = if *n == 0 || bits != *first { rgba8(i.colour) } else { v.first_colour };
            if *n == 0 {
                *first = bits;
            }
            v.note(i.rotation, Vec3::splat(i.scale), colour, *n == 0);
            *n += 1;
            lists[0] += 1;
        }
        for_each_placement(scene, 1, &mut |list, p| {
            if let Some((n, v, lists)) = dense.index(&p.key).and_then(|i| counts.get_mut(i)) {
                v.see(p, *n == 0);
                *n += 1;
                lists[list] += 1;
            }
        });
        let mut slots = vec![u32::MAX; counts.len()];
        let (mut meshes, mut varying, mut covered) = (Vec::new(), Vec::new(), [0u64; 3]);
        for (i, &(n, v, lists)) in counts.iter().enumerate() {
            if n >= 2 {
                slots[i] = meshes.len() as u32;
                meshes.push((dense.key(i), n));
                varying.push(v);
                for (c, l) in covered.iter_mut().zip(lists) {
                    *c += l;
                }
            }
        }
        Plan { dense, slots, meshes, varying, covered }
    }

    /// What differs between the placements of each instanced mesh, in the
    /// order of [`Plan::meshes`].
    pub fn varying(&self) -> &[Varying] {
        &self.varying
    }

    /// The instanced meshes and their placement counts, in key order.
    pub fn meshes(&self) -> &[(MeshKey, u64)] {
        &self.meshes
    }

    /// True when no mesh is placed twice: the output is plain.
    pub fn is_empty(&self) -> bool {
        self.meshes.is_empty()
    }

    /// Instances over all instanced meshes.
    pub fn instances(&self) -> u64 {
        self.meshes.iter().map(|m| m.1).sum()
    }

    /// The slot in [`Plan::meshes`] of an instanced mesh.
    pub fn slot(&self, key: &MeshKey) -> Option<usize> {
        let s = *self.slots.get(self.dense.index(key)?)?;
        (s != u32::MAX).then_some(s as usize)
    }

    /// Calls `f` with every instanced placement of `scene` and its mesh's
    /// slot, in scene order (similarity instances, affine instances, shape
    /// placements), so a writer can put each straight into its output.
    pub fn walk(&self, scene: &Scene, f: &mut dyn FnMut(usize, &Placement)) {
        for_each_placement(scene, 0, &mut |_, p| {
            if let Some(s) = self.slot(&p.key) {
                f(s, p);
            }
        });
    }

    /// The plain rest of `scene`: the placements not instanced (copied, and
    /// charged to `budget`), with the swept lines, free vertices, profiles
    /// and shapes moved out of `scene` (whose placements [`Plan::walk`]
    /// still reads). Release [`Plan::residual_bytes`] of it once meshed.
    pub fn residual(&self, scene: &mut Scene, budget: &mut Budget) -> Result<Scene, LimitExceeded> {
        let plain_instance = |i: &&Instance| Placement::of_instance(i).and_then(|p| self.slot(&p.key)).is_none();
        let plain_affine = |a: &&AffineInstance| Placement::of_affine(a).and_then(|p| self.slot(&p.key)).is_none();
        let plain_shape = |s: &&ShapeInstance| Placement::of_shape(s).and_then(|p| self.slot(&p.key)).is_none();
        // A list the plan instances entirely has an empty residual: skip its
        // two passes (a million-box grid is all instances).
        let [i, a, s] = [scene.instances.len(), scene.affine.len(), scene.shape_instances.len()].map(|n| n as u64);
        let full = [self.covered[0] == i, self.covered[1] == a, self.covered[2] == s];
        let counts = (
            if full[0] { 0 } else { scene.instances.iter().filter(plain_instance).count() as u64 },
            if full[1] { 0 } else { scene.affine.iter().filter(plain_affine).count() as u64 },
            if full[2] { 0 } else { scene.shape_instances.iter().filter(plain_shape).count() as u64 },
        );
        budget.reserve_memory(residual_bytes(counts))?;
        Ok(Scene {
            instances: if full[0] { Vec::new() } else { scene.instances.iter().filter(plain_instance).copied().collect() },
            affine: if full[1] { Vec::new() } else { scene.affine.iter().filter(plain_affine).copied().collect() },
            shape_instances: if full[2] { Vec::new() } else { scene.shape_instances.iter().filter(plain_shape).copied().collect() },
            lines: std::mem::take(&mut scene.lines),
            profiles: std::mem::take(&mut scene.profiles),
            vertices: std::mem::take(&mut scene.vertices),
            shapes: std::mem::take(&mut scene.shapes),
            classes: scene.classes.clone(),
            background: scene.background,
            truncated: scene.truncated,
            rig: None,
            camera: None,
        })
    }
}

/// Bytes of a residual scene's copied placements (similarity, affine, shape).
pub fn residual_bytes((instances, affine, shapes): (u64, u64, u64)) -> u64 {
    instances
        .saturating_mul(INSTANCE_BYTES)
        .saturating_add(affine.saturating_mul(AFFINE_INSTANCE_BYTES))
        .saturating_add(shapes.saturating_mul(SHAPE_INSTANCE_BYTES))
}

/// The placements of a residual scene, for [`residual_bytes`].
pub fn residual_counts(residual: &Scene) -> (u64, u64, u64) {
    (residual.instances.len() as u64, residual.affine.len() as u64, residual.shape_instances.len() as u64)
}

/// Every placement of `scene` with a TRS form, in scene order, with the
/// list it comes from (0 similarity, 1 affine, 2 shape placements), from
/// list `from` on.
fn for_each_placement(scene: &Scene, from: usize, f: &mut dyn FnMut(usize, &Placement)) {
    if from == 0 {
        for p in scene.instances.iter().filter_map(Placement::of_instance) {
            f(0, &p);
        }
    }
    for p in scene.affine.iter().filter_map(Placement::of_affine) {
        f(1, &p);
    }
    for p in scene.shape_instances.iter().filter_map(Placement::of_shape) {
        f(2, &p);
    }
}

/// What a front end charges per placement when the output is instanced
/// (see [`Downstream::per_instance`](super::Downstream::per_instance)): the
/// first placement of a mesh costs what a flat copy costs (it may stay a
/// plain mesh, and an instanced mesh's prototype is written once), each
/// further one a triangle and the bytes of one instance. So the triangle
/// limit counts what is materialised — prototypes plus instances — and the
/// memory promise follows the output.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tally {
    per_instance: Option<u64>,
    /// Per (class, kind, mirrored) of a primitive, whether one was placed.
    primitives: Vec<bool>,
    /// Per (shape, mirrored), whether one was placed.
    shapes: Vec<bool>,
}

/// Classes a [`Tally`] numbers; placements of classes beyond it are charged flat.
const TALLY_CLASSES: usize = 1 << 12;
/// Shapes a [`Tally`] numbers; placements of shapes beyond it are charged flat.
const TALLY_SHAPES: usize = 1 << 16;

impl Tally {
    /// A tally for an output that writes `per_instance` bytes per instance,
    /// or charges every placement flat (`None`).
    pub fn new(per_instance: Option<u64>) -> Tally {
        Tally { per_instance, primitives: Vec::new(), shapes: Vec::new() }
    }

    /// The (triangles, bytes) to charge for one more placement of `key`
    /// (`None`: a placement with no TRS form) whose flat copy has
    /// `triangles` and needs `bytes`.
    pub fn cost(&mut self, key: Option<MeshKey>, triangles: u64, bytes: u64) -> (u64, u64) {
        let (Some(per_instance), Some(k)) = (self.per_instance, key) else { return (triangles, bytes) };
        let slot = match k.source {
            Source::Primitive(p) if (k.class as usize) < TALLY_CLASSES => {
                let i = (k.class as usize * PrimitiveKind::ALL.len() + p as usize) * 2 + usize::from(k.mirrored);
                grown(&mut self.primitives, i)
            }
            Source::Shape(s) if (s as usize) < TALLY_SHAPES && k.class == 0 => grown(&mut self.shapes, s as usize * 2 + usize::from(k.mirrored)),
            _ => return (triangles, bytes),
        };
        if std::mem::replace(slot, true) {
            (1, per_instance)
        } else {
            (triangles, bytes)
        }
    }
}

/// Entry `i` of `v`, growing it with `false` as needed.
fn grown(v: &mut Vec<bool>, i: usize) -> &mut bool {
    if v.len() <= i {
        v.resize(i + 1, false);
    }
    &mut v[i]
}

#[cfg(test)]
mod tests;
