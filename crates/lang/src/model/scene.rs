//! The evaluator's output: primitive instances with transforms and colours.
//!
//! A `Scene` is what exporters ultimately describe; it knows nothing about
//! the language it came from. Instances are stored compactly in f32 (the
//! precision of every output format) so a million of them fit in ~52 MB.

use crate::core::budget::LimitExceeded;
use crate::core::frame::Frame;
use crate::core::PrimitiveKind;
use glam::{Mat3, Quat, Vec3};

/// One placed primitive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Instance {
    /// Which primitive.
    pub kind: PrimitiveKind,
    /// True when the transform is a reflection (odd parity): winding must flip.
    pub parity: bool,
    /// Translation of the primitive's origin.
    pub translation: Vec3,
    /// Rotation (unit).
    pub rotation: Quat,
    /// Uniform scale.
    pub scale: f32,
    /// Linear RGBA, each clamped to [0, 1].
    pub colour: [f32; 4],
}

impl Instance {
    /// Builds an instance from an evaluation frame and an unclamped colour.
    pub fn new(kind: PrimitiveKind, frame: &Frame, colour: [f64; 4]) -> Instance {
        Instance {
            kind,
            parity: frame.parity,
            translation: frame.translation.as_vec3(),
            rotation: frame.rotation.as_quat().normalize(),
            scale: frame.scale as f32,
            colour: colour.map(|c| c.clamp(0.0, 1.0) as f32),
        }
    }

    /// Whether the instance yields usable geometry. Instances with scale 0
    /// collapse to a point (every triangle degenerate), and non-finite
    /// transforms would poison bounds and normals, so both are skipped
    /// rather than written, flat or instanced.
    pub fn is_drawable(&self) -> bool {
        self.scale != 0.0 && self.scale.is_finite() && self.translation.is_finite() && self.rotation.is_finite()
    }

    /// The instance's placement as a frame (in f64, for composing).
    pub fn frame(&self) -> Frame {
        Frame {
            translation: self.translation.as_dvec3(),
            rotation: self.rotation.as_dquat(),
            scale: f64::from(self.scale),
            parity: self.parity,
        }
    }

    /// The same instance placed by `outer ∘ self` (re-expressed in another space).
    pub fn transformed(&self, outer: &Frame) -> Instance {
        let f = outer.then(&self.frame());
        Instance {
            kind: self.kind,
            parity: f.parity,
            translation: f.translation.as_vec3(),
            rotation: f.rotation.as_quat().normalize(),
            scale: f.scale as f32,
            colour: self.colour,
        }
    }

    /// The linear part s·σ·R as a matrix.
    pub fn linear(&self) -> Mat3 {
        let sign = if self.parity { -1.0 } else { 1.0 };
        Mat3::from_quat(self.rotation) * (sign * self.scale)
    }

    /// The normal matrix σ·R (inverse transpose of the linear part, without the scale).
    pub fn normal_matrix(&self) -> Mat3 {
        let sign = if self.parity { -1.0 } else { 1.0 };
        Mat3::from_quat(self.rotation) * sign
    }
}

/// A primitive placed by a general affine map (non-uniform scale, shear,
/// reflection), for languages whose frames are not similarities
/// (EisenScript's `s x y z` and `m`). Kept apart from [`Instance`] so the
/// similarity path stays as compact as it is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AffineInstance {
    /// Which primitive (its unit prototype, centred at the origin).
    pub kind: PrimitiveKind,
    /// The linear part: prototype coordinates to world directions.
    pub linear: Mat3,
    /// Where the prototype's origin goes.
    pub translation: Vec3,
    /// Linear RGBA, each clamped to [0, 1].
    pub colour: [f32; 4],
    /// Index into [`Scene::classes`] (0 is the default class): the output mesh
    /// and material the instance belongs to.
    pub class: u32,
}

impl AffineInstance {
    /// True when the map reverses orientation (det < 0): winding must flip.
    pub fn parity(&self) -> bool {
        self.linear.determinant() < 0.0
    }

    /// The normal matrix: the inverse transpose of the linear part, up to a
    /// positive factor (the cofactor matrix, signed by the determinant, so it
    /// stays finite for nearly flat maps). Normals must be renormalised.
    pub fn normal_matrix(&self) -> Mat3 {
        let [a, b, c] = [self.linear.x_axis, self.linear.y_axis, self.linear.z_axis];
        let cof = Mat3::from_cols(b.cross(c), c.cross(a), a.cross(b));
        if self.parity() {
            cof * -1.0
        } else {
            cof
        }
    }

    /// Whether the instance yields usable geometry (finite, not flat).
    pub fn is_drawable(&self) -> bool {
        let d = self.linear.determinant();
        d.is_finite() && d != 0.0 && self.translation.is_finite()
    }
}

/// Bytes accounted per stored affine instance.
pub(crate) const AFFINE_INSTANCE_BYTES: u64 = std::mem::size_of::<AffineInstance>() as u64;

pub use crate::geom::sweep::{LinePoint, Polyline};

/// A free vertex from `VERTEX {}`: every three consecutive ones make a triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeVertex {
    /// World position.
    pub position: glam::DVec3,
    /// World unit normal.
    pub normal: glam::DVec3,
    /// Linear RGBA, each clamped to [0, 1].
    pub colour: [f32; 4],
}

/// One placement of a scene shape (an isosurface).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeInstance {
    /// Index into [`Scene::shapes`].
    pub shape: u32,
    /// Where it is placed.
    pub frame: Frame,
    /// Linear RGBA, each clamped to [0, 1].
    pub colour: [f32; 4],
}

/// Bytes accounted per stored shape placement.
pub(crate) const SHAPE_INSTANCE_BYTES: u64 = std::mem::size_of::<ShapeInstance>() as u64;

/// Bytes accounted per stored free vertex.
pub(crate) const FREE_VERTEX_BYTES: u64 = std::mem::size_of::<FreeVertex>() as u64;

/// Bytes accounted per stored line point (for the memory budget).
pub(crate) const LINE_POINT_BYTES: u64 = std::mem::size_of::<LinePoint>() as u64;

/// Everything an evaluation produced.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    /// Primitive instances in evaluation (depth-first) order.
    pub instances: Vec<Instance>,
    /// Swept lines from MOVETO/LINETO/SLINETO, in drawing order.
    pub lines: Vec<Polyline>,
    /// Line cross-sections from profile rules: points in the profile's local frame.
    pub profiles: Vec<Vec<glam::DVec3>>,
    /// Free vertices from `VERTEX {}` outside profile rules.
    pub vertices: Vec<FreeVertex>,
    /// Meshes made during evaluation (isosurfaces), placed by [`Scene::shape_instances`].
    pub shapes: Vec<crate::geom::primitives::Prototype>,
    /// Placements of [`Scene::shapes`].
    pub shape_instances: Vec<ShapeInstance>,
    /// Primitives placed by general affine maps (EisenScript), in evaluation order.
    pub affine: Vec<AffineInstance>,
    /// Names of the classes [`AffineInstance::class`] indexes (`box::shiny` → `shiny`);
    /// index 0 is the default class. Empty when no language uses classes.
    pub classes: Vec<String>,
    /// Clear colour from `background`, if the grammar set one.
    pub background: Option<[f32; 4]>,
    /// Set when evaluation stopped at a limit and `on_limit = truncate` kept the partial result.
    pub truncated: Option<LimitExceeded>,
    /// Animation bones (calls of animated rules) and which bone each piece
    /// of geometry belongs to; `None` when the grammar animates nothing.
    pub rig: Option<crate::model::animation::Rig>,
    /// The camera: MDG's `camerarule` path or Structure Synth's viewer settings.
    pub camera: Option<crate::model::Camera>,
}

/// Bytes accounted per stored instance (for the memory budget).
pub const INSTANCE_BYTES: u64 = std::mem::size_of::<Instance>() as u64;
