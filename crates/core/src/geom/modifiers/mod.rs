//! Mesh modifiers: operations stacked on a primitive (Anton Haglund,
//! *Procedural Modelling*, MSc thesis, Umeå University, 2009, §2.2.2: the
//! "stacking" of primitive plus modifier chain).
//!
//! Every modifier takes a [`HalfEdgeMesh`] and returns a new one. Each knows
//! its output size from its input before it builds anything, and
//! [`apply_all`] checks that size against the [`Budget`] (triangles, steps
//! and memory) before allocating, so a chain like `subdivide 12` fails with
//! a typed limit instead of running the process out of memory.
//!
//! Random modifiers (randomize, displace, random extrusion) draw from
//! [`StreamKey`] streams keyed by their own `seed`, so the same chain gives
//! byte-identical output everywhere.

mod deform;
mod extrude;
mod spikeify;
mod subdivide;
pub mod syntax;

pub(crate) use extrude::{Extrude, FaceSelect};
#[cfg(test)]
pub(crate) use subdivide::loop_beta;

use super::assembly::Assembly;
use super::halfedge::{halfedge_bytes, HalfEdgeError, HalfEdgeMesh};
use super::polyhedra::{self, Solid};
use super::primitives::{self, Prototype};
use crate::core::PrimitiveKind;
use crate::core::budget::{Budget, Limit, LimitExceeded};
use crate::core::rng::StreamKey;
use glam::DVec3;
use std::sync::Arc;

/// A coordinate axis of the primitive's local frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// Local X.
    X,
    /// Local Y.
    Y,
    /// Local Z.
    Z,
}

impl Axis {
    /// The axis' index (0, 1, 2).
    pub fn index(self) -> usize {
        self as usize
    }
}

/// One modifier with its parameters (see `docs/modifiers.md`).
#[derive(Debug, Clone, PartialEq)]
pub enum Modifier {
    /// Loop subdivision, `levels` times. `weight` multiplies β of Haglund
    /// 2009 eq 2.4 (1 is plain Loop); `smooth = false` only splits each triangle
    /// into four at exact edge midpoints.
    Subdivide {
        /// Number of subdivision steps.
        levels: u32,
        /// Multiplier of β in eq 2.4.
        weight: f64,
        /// False: split only, no smoothing.
        smooth: bool,
    },
    /// Every face becomes a three-sided spike (a tetrahedron on the face
    /// without its base) whose apex is `height` above the face centroid.
    Spikeify {
        /// Apex height above the face plane, in local units (> 0).
        height: f64,
    },
    /// Moves every vertex in a random direction by at most `amount` times the
    /// shortest edge (Haglund 2009 §4.3); `amount` < 0.5 keeps vertices apart.
    Randomize {
        /// Fraction of the shortest edge, in [0, 0.5).
        amount: f64,
        /// Random stream seed.
        seed: u64,
    },
    /// Per-face extrusion (Haglund 2009 §2.2.2).
    Extrude(Extrude),
    /// Moves a random `fraction` of the vertices along their normal by
    /// `amount` × U[0.5, 1.5] (Haglund 2009 §4.3's vertex displacer).
    Displace {
        /// Base displacement (negative pushes inward).
        amount: f64,
        /// Fraction of vertices moved, in [0, 1].
        fraction: f64,
        /// Random stream seed.
        seed: u64,
    },
    /// Adds a reflected copy through the plane `axis = offset`, winding reversed.
    Mirror {
        /// The plane's normal axis.
        axis: Axis,
        /// The plane's position along the axis.
        offset: f64,
    },
    /// Rotates each vertex about the axis by `degrees_per_unit` × its coordinate along it.
    Twist {
        /// The twist axis.
        axis: Axis,
        /// Degrees of rotation per local unit along the axis.
        degrees_per_unit: f64,
    },
    /// Bends the mesh's Y extent into an arc of `degrees` about the Z axis, towards +X.
    Bend {
        /// Total bend angle over the Y extent.
        degrees: f64,
    },
    /// Translates every vertex (Haglund 2009 eq 2.1); useful before `mirror`.
    Translate(DVec3),
    /// Scales every coordinate (Haglund 2009 eq 2.2); a negative product turns
    /// the winding inside out, so it is rejected.
    Scale(DVec3),
}

/// What a modifier chain starts from.
#[derive(Debug, Clone, PartialEq)]
pub enum MeshBase {
    /// A built-in primitive, tessellated at the request's detail.
    Primitive(PrimitiveKind),
    /// A named Platonic or Archimedean solid.
    Solid(Solid),
    /// A geodesic sphere of this frequency (icosahedron, each face split
    /// into frequency² triangles, pushed onto the sphere).
    Geodesic(u32),
    /// Indexed triangles given by the source.
    Indexed {
        /// Vertex positions.
        positions: Vec<DVec3>,
        /// CCW triangles.
        triangles: Vec<[u32; 3]>,
    },
    /// Nested instances of polygons (UniGrafix import), expanded only once
    /// the budget has admitted their counted size.
    Assembly(Arc<Assembly>),
}

impl MeshBase {
    /// Vertex and triangle counts of the base, for the budget before building.
    pub fn size(&self, detail: u32) -> (u64, u64) {
        match self {
            MeshBase::Primitive(k) => (primitives::vertex_count(*k, detail), primitives::triangle_count(*k, detail)),
            MeshBase::Solid(s) => s.size(),
            MeshBase::Geodesic(n) => polyhedra::geodesic_size(*n),
            MeshBase::Indexed { positions, triangles } => (positions.len() as u64, triangles.len() as u64),
            MeshBase::Assembly(a) => a.size(),
        }
    }

    /// Builds the base as a half-edge mesh (an assembly is expanded first; see [`build`]).
    fn build(&self, detail: u32) -> Result<HalfEdgeMesh, HalfEdgeError> {
        match self {
            MeshBase::Primitive(k) => {
                let p = primitives::tessellate(*k, detail);
                HalfEdgeMesh::from_indexed(&p.positions, &p.indices)
            }
            MeshBase::Solid(s) => s.mesh(),
            MeshBase::Geodesic(n) => polyhedra::geodesic(*n),
            MeshBase::Indexed { positions, triangles } => HalfEdgeMesh::new(positions.clone(), triangles.clone()),
            MeshBase::Assembly(a) => {
                let (positions, triangles) = a.expand_until(&|| false).ok_or(HalfEdgeError::Stopped)?;
                HalfEdgeMesh::new(positions, triangles)
            }
        }
    }
}

/// Builds `base` and applies `modifiers`, all under `budget`; returns the
/// flat-shaded prototype (its memory is not reserved: the caller keeps it).
pub fn build(base: &MeshBase, modifiers: &[Modifier], detail: u32, budget: &mut Budget) -> Result<Prototype, ModifyError> {
    if let MeshBase::Assembly(a) = base {
        // Admitted at its counted size, with what the expansion really
        // holds at its peak and the flat mesh the caller will keep; then
        // expanded under the deadline.
        let (corners, f) = a.size();
        budget.check_total(Limit::Triangles, f)?;
        budget.charge_steps(corners.saturating_add(f))?;
        let bytes = crate::geom::assembly::expansion_bytes(corners, f);
        budget.check_memory(bytes.saturating_add(crate::geom::mesh::mesh_bytes(f.saturating_mul(3), f)))?;
        budget.reserve_memory(bytes)?;
        let expanded = a.expand_until(&|| budget.check_deadline().is_err());
        budget.release_memory(bytes);
        let Some((positions, triangles)) = expanded else {
            budget.check_deadline()?;
            return Err(ModifyError::Stopped);
        };
        if modifiers.is_empty() {
            let flat = super::halfedge::flat_prototype_until(&positions, &triangles, &|| budget.check_deadline().is_err());
            return match flat {
                Some(p) => Ok(p),
                None => {
                    budget.check_deadline()?;
                    Err(ModifyError::Stopped)
                }
            };
        }
        let mesh = HalfEdgeMesh::new(positions, triangles).map_err(|source| ModifyError::Mesh { modifier: "base", source })?;
        return Ok(apply_all(mesh, modifiers, budget)?.to_prototype());
    }
    let (v, f) = base.size(detail);
    let bytes = admit(budget, v, f)?;
    if let (MeshBase::Indexed { positions, triangles }, []) = (base, modifiers) {
        // Drawn as given: imported models may have parts that touch along edges,
        // which no half-edge structure holds; only modifiers need one.
        budget.release_memory(bytes);
        return Ok(super::halfedge::flat_prototype(positions, triangles));
    }
    let mesh = base.build(detail).map_err(|source| ModifyError::Mesh { modifier: "base", source });
    budget.release_memory(bytes);
    let mesh = apply_all(mesh?, modifiers, budget)?;
    Ok(mesh.to_prototype())
}

impl Modifier {
    /// The modifier's name as written in MDG.
    pub fn name(&self) -> &'static str {
        match self {
            Modifier::Subdivide { smooth: true, .. } => "subdivide",
            Modifier::Subdivide { smooth: false, .. } => "split",
            Modifier::Spikeify { .. } => "spikeify",
            Modifier::Randomize { .. } => "randomize",
            Modifier::Extrude(_) => "extrude",
            Modifier::Displace { .. } => "displace",
            Modifier::Mirror { .. } => "mirror",
            Modifier::Twist { .. } => "twist",
            Modifier::Bend { .. } => "bend",
            Modifier::Translate(_) => "translate",
            Modifier::Scale(_) => "scale",
        }
    }
}

/// Why a modifier chain failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModifyError {
    /// The output would exceed a limit; nothing was allocated.
    #[error(transparent)]
    Limit(#[from] LimitExceeded),
    /// The input (or an intermediate result) is not a manifold triangle mesh.
    #[error("{modifier}: {source}")]
    Mesh {
        /// The modifier that met it.
        modifier: &'static str,
        /// What is wrong.
        source: HalfEdgeError,
    },
    /// The caller's `stop` callback asked to give up part-way
    /// ([`apply_until`]); [`apply_all`] turns it into the deadline error.
    #[error("stopped before the modifier finished")]
    Stopped,
    /// A parameter is out of range.
    #[error("{modifier}: {message}")]
    Invalid {
        /// The modifier.
        modifier: &'static str,
        /// What is wrong.
        message: String,
    },
}

/// Output vertex and triangle counts of `m` applied to a mesh of `v`
/// vertices, `e` edges and `f` faces, computed without building anything.
/// Saturates instead of overflowing, so a huge request still fails the budget.
pub(crate) fn output_size(m: &Modifier, v: u64, e: u64, f: u64) -> (u64, u64, u64) {
    match m {
        Modifier::Subdivide { levels, .. } => {
            let (mut v, mut e, mut f) = (v, e, f);
            for _ in 0..*levels {
                let (nv, ne, nf) = (v.saturating_add(e), e.saturating_mul(2).saturating_add(f.saturating_mul(3)), f.saturating_mul(4));
                (v, e, f) = (nv, ne, nf);
                if f == u64::MAX {
                    break;
                }
            }
            (v, e, f)
        }
        Modifier::Spikeify { .. } => (v.saturating_add(f), e.saturating_add(f.saturating_mul(3)), f.saturating_mul(3)),
        Modifier::Extrude(x) => {
            // Upper bound: every face selected.
            let k = f.saturating_mul(u64::from(x.steps));
            (v.saturating_add(k.saturating_mul(3)), e.saturating_add(k.saturating_mul(9)), f.saturating_add(k.saturating_mul(6)))
        }
        Modifier::Mirror { .. } => (v.saturating_mul(2), e.saturating_mul(2), f.saturating_mul(2)),
        Modifier::Randomize { .. } | Modifier::Displace { .. } | Modifier::Twist { .. } | Modifier::Bend { .. } | Modifier::Translate(_) | Modifier::Scale(_) => (v, e, f),
    }
}

/// Checks an output of `v` vertices and `f` faces against the budget and
/// reserves its memory; the caller releases it when the mesh is dropped.
fn admit(budget: &mut Budget, v: u64, f: u64) -> Result<u64, LimitExceeded> {
    budget.check_total(Limit::Triangles, f)?;
    // Work is linear in the output: charge it as steps so time stays bounded and deterministic.
    budget.charge_steps(f.saturating_add(v))?;
    let bytes = halfedge_bytes(v, f);
    budget.reserve_memory(bytes)?;
    Ok(bytes)
}

/// Applies `ops` in order to `mesh`. Each step's output is admitted by the
/// budget before it is built; intermediate meshes' memory is released as
/// they are dropped, and the result's own memory is released on return (the
/// caller accounts for whatever it keeps).
pub(crate) fn apply_all(mesh: HalfEdgeMesh, ops: &[Modifier], budget: &mut Budget) -> Result<HalfEdgeMesh, ModifyError> {
    let mut held = admit(budget, mesh.vertex_count() as u64, mesh.face_count() as u64)?;
    let mut mesh = mesh;
    for op in ops {
        budget.check_deadline()?;
        let (v, _, f) = output_size(op, mesh.vertex_count() as u64, mesh.edge_count() as u64, mesh.face_count() as u64);
        let bytes = admit(budget, v, f)?;
        let out = apply_until(&mesh, op, &|| budget.check_deadline().is_err());
        budget.release_memory(held);
        held = bytes;
        mesh = match out {
            Ok(next) => next,
            Err(e) => {
                budget.release_memory(held);
                if e == ModifyError::Stopped {
                    // Stopped by the deadline: say so as the budget's own error.
                    budget.check_deadline()?;
                }
                return Err(e);
            }
        };
    }
    budget.release_memory(held);
    Ok(mesh)
}

/// Applies one modifier (no budget check: use [`apply_all`] on untrusted input).
pub fn apply(mesh: &HalfEdgeMesh, op: &Modifier) -> Result<HalfEdgeMesh, ModifyError> {
    apply_until(mesh, op, &|| false)
}

/// [`apply`] that asks `stop` now and then, inside the long loops, whether
/// to give up ([`ModifyError::Stopped`]): one subdivision of a mesh of
/// millions of triangles takes seconds, so checking the deadline only
/// between modifiers overran it threefold (issue 17's stacking string).
pub(crate) fn apply_until(mesh: &HalfEdgeMesh, op: &Modifier, stop: &dyn Fn() -> bool) -> Result<HalfEdgeMesh, ModifyError> {
    let name = op.name();
    let invalid = |message: String| ModifyError::Invalid { modifier: name, message };
    let rebuild = |positions: Vec<DVec3>, tris: Vec<[u32; 3]>| {
        HalfEdgeMesh::new_until(positions, tris, stop).map_err(|source| match source {
            HalfEdgeError::Stopped => ModifyError::Stopped,
            source => ModifyError::Mesh { modifier: name, source },
        })
    };
    match op {
        Modifier::Subdivide { levels, weight, smooth } => {
            if !weight.is_finite() {
                return Err(invalid(format!("weight {weight} is not finite")));
            }
            // Subdivided from `mesh` itself, not a clone of it: copying a
            // mesh of millions of triangles is work no deadline check sees.
            let mut m: Option<HalfEdgeMesh> = None;
            for _ in 0..*levels {
                let (p, t) = subdivide::subdivide_once(m.as_ref().unwrap_or(mesh), *weight, *smooth, stop).ok_or(ModifyError::Stopped)?;
                m = Some(rebuild(p, t)?);
            }
            Ok(m.unwrap_or_else(|| mesh.clone()))
        }
        Modifier::Spikeify { height } => {
            if !(height.is_finite() && *height > 0.0) {
                return Err(invalid(format!("height must be a positive number, found {height}")));
            }
            let (p, t) = spikeify::spikeify(mesh, *height);
            rebuild(p, t)
        }
        Modifier::Extrude(x) => {
            x.validate().map_err(invalid)?;
            let (p, t) = extrude::extrude(mesh, x);
            rebuild(p, t)
        }
        Modifier::Mirror { axis, offset } => {
            if !offset.is_finite() {
                return Err(invalid(format!("offset {offset} is not finite")));
            }
            let (p, t) = deform::mirror(mesh, *axis, *offset);
            rebuild(p, t)
        }
        Modifier::Randomize { amount, seed } => {
            if !(0.0..0.5).contains(amount) {
                return Err(invalid(format!("amount must be in [0, 0.5) so vertices stay apart, found {amount}")));
            }
            Ok(deform::randomize(mesh, *amount, *seed))
        }
        Modifier::Displace { amount, fraction, seed } => {
            if !amount.is_finite() || !(0.0..=1.0).contains(fraction) {
                return Err(invalid(format!("needs a finite amount and a fraction in [0, 1], found {amount} and {fraction}")));
            }
            Ok(deform::displace(mesh, *amount, *fraction, *seed))
        }
        Modifier::Twist { axis, degrees_per_unit } => {
            if !degrees_per_unit.is_finite() {
                return Err(invalid(format!("angle {degrees_per_unit} is not finite")));
            }
            Ok(deform::twist(mesh, *axis, degrees_per_unit.to_radians()))
        }
        Modifier::Bend { degrees } => {
            if !degrees.is_finite() || degrees.abs() > 360.0 {
                return Err(invalid(format!("angle must be within ±360°, found {degrees}")));
            }
            Ok(deform::bend(mesh, degrees.to_radians()))
        }
        Modifier::Translate(d) => {
            if !d.is_finite() {
                return Err(invalid(format!("offset {d} is not finite")));
            }
            Ok(deform::map_positions(mesh, |p| p + *d))
        }
        Modifier::Scale(k) => {
            if !(k.is_finite() && k.x * k.y * k.z > 0.0) {
                return Err(invalid(format!("factors must be finite with a positive product, found {k}")));
            }
            Ok(deform::map_positions(mesh, |p| p * *k))
        }
    }
}

/// A uniform number in [0, 1) for draw `slot` of item `index` of stream `seed`.
fn uniform(seed: u64, index: u64, slot: u32) -> f64 {
    StreamKey::root(seed).child(0, index).uniform(slot)
}

#[cfg(test)]
mod tests;
