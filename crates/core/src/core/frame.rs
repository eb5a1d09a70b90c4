//! Local coordinate frames: translation, unit quaternion, uniform scale and
//! reflection parity (Andersson 2015 §3.3 and §4.2, with its misprinted
//! equations corrected: docs/mdg.md, "Choices").
//!
//! A frame maps a local point p to `t + s·σ·R(q)·p`, where σ = −1 when the
//! parity is odd. A reflection across the plane with unit normal n equals
//! −Rot(n, π), and −I commutes with every linear map, so reflections are
//! tracked as a parity bit plus a half-turn in the quaternion. This keeps
//! the quaternion unit (no s² scaling: `s k` scales lengths by k) and
//! lets exporters flip winding exactly when the determinant is negative.

use glam::{DMat3, DQuat, DVec3};

/// A similarity transform with optional reflection, in f64 for stable long chains.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Where the local origin is.
    pub translation: DVec3,
    /// The rotation part, always unit length.
    pub rotation: DQuat,
    /// Uniform length scale, always > 0 or exactly 0.
    pub scale: f64,
    /// True when the frame is left-handed (an odd number of reflections).
    pub parity: bool,
}

impl Default for Frame {
    fn default() -> Self {
        Frame::IDENTITY
    }
}

impl Frame {
    /// The identity frame.
    pub const IDENTITY: Frame = Frame {
        translation: DVec3::ZERO,
        rotation: DQuat::IDENTITY,
        scale: 1.0,
        parity: false,
    };

    /// A pure translation.
    pub fn from_translation(v: DVec3) -> Frame {
        Frame { translation: v, ..Frame::IDENTITY }
    }

    /// A pure rotation by a unit quaternion.
    pub fn from_rotation(q: DQuat) -> Frame {
        Frame { rotation: q, ..Frame::IDENTITY }
    }

    /// A uniform scale; a negative `k` is a scale by |k| composed with a point reflection.
    pub fn from_scale(k: f64) -> Frame {
        Frame { scale: k.abs(), parity: k < 0.0, ..Frame::IDENTITY }
    }

    /// A reflection across the plane through the origin with normal `n`
    /// (need not be unit; a zero normal gives the identity).
    pub fn reflection(n: DVec3) -> Frame {
        let Some(axis) = n.try_normalize() else {
            return Frame::IDENTITY;
        };
        Frame {
            rotation: DQuat::from_axis_angle(axis, std::f64::consts::PI),
            parity: true,
            ..Frame::IDENTITY
        }
    }

    /// `self ∘ local`: the frame reached by applying `local` inside `self`.
    /// This is how adjustments compose, left to right in the local frame.
    pub fn then(&self, local: &Frame) -> Frame {
        Frame {
            translation: self.transform_point(local.translation),
            rotation: (self.rotation * local.rotation).normalize(),
            scale: self.scale * local.scale,
            parity: self.parity ^ local.parity,
        }
    }

    /// Maps a local point to the parent space.
    pub fn transform_point(&self, p: DVec3) -> DVec3 {
        self.translation + self.transform_vector(p)
    }

    /// Maps a local direction (no translation) to the parent space, scale included.
    pub(crate) fn transform_vector(&self, v: DVec3) -> DVec3 {
        self.sign() * self.scale * (self.rotation * v)
    }

    /// Maps a local unit normal to the parent space: the inverse transpose of the linear part,
    /// which for a similarity is σ·R (unit length kept).
    pub fn transform_normal(&self, n: DVec3) -> DVec3 {
        self.sign() * (self.rotation * n)
    }

    /// −1 for odd parity, +1 otherwise.
    pub fn sign(&self) -> f64 {
        if self.parity {
            -1.0
        } else {
            1.0
        }
    }

    /// The linear part as a matrix (s·σ·R).
    pub fn linear(&self) -> DMat3 {
        DMat3::from_quat(self.rotation) * (self.sign() * self.scale)
    }

    /// The determinant of the linear part; negative exactly when `parity` is set (and scale > 0).
    pub fn determinant(&self) -> f64 {
        self.sign() * self.scale.powi(3)
    }

    /// The inverse transform, so geometry can be re-expressed in a frame's
    /// local coordinates (animation bones). `None` for a zero scale, which
    /// collapses space and cannot be undone.
    pub fn inverse(&self) -> Option<Frame> {
        if !(self.scale > 0.0) || !self.scale.is_finite() {
            return None;
        }
        let rotation = self.rotation.conjugate();
        let scale = 1.0 / self.scale;
        // p = t + s·σ·R·q  ⇔  q = −(σ/s)·R⁻¹·t + (σ/s)·R⁻¹·p, and σ commutes with R.
        Some(Frame { translation: -(self.sign() * scale) * (rotation * self.translation), rotation, scale, parity: self.parity })
    }

    /// True when every component is finite.
    pub fn is_finite(&self) -> bool {
        self.translation.is_finite() && self.rotation.is_finite() && self.scale.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn adjustments_compose_in_the_local_frame() {
        // rz 90 then x 1: moves along the rotated x axis, i.e. world +y.
        let f = Frame::from_rotation(DQuat::from_rotation_z(FRAC_PI_2))
            .then(&Frame::from_translation(DVec3::X));
        assert!(close(f.translation, DVec3::Y));
        // s 2 then x 1: moves 2.
        let f = Frame::from_scale(2.0).then(&Frame::from_translation(DVec3::X));
        assert!(close(f.translation, DVec3::new(2.0, 0.0, 0.0)));
    }

    #[test]
    fn reflection_matches_the_mirror_matrix_and_sets_parity() {
        let f = Frame::reflection(DVec3::X);
        assert!(f.parity);
        assert!(close(f.transform_point(DVec3::new(1.0, 2.0, 3.0)), DVec3::new(-1.0, 2.0, 3.0)));
        assert!(f.determinant() < 0.0);
        let twice = f.then(&f);
        assert!(!twice.parity);
        assert!(close(twice.transform_point(DVec3::new(1.0, 2.0, 3.0)), DVec3::new(1.0, 2.0, 3.0)));
        // Oblique plane: n = (1,1,0)/√2 maps x to −y.
        let f = Frame::reflection(DVec3::new(1.0, 1.0, 0.0));
        assert!(close(f.transform_point(DVec3::X), -DVec3::Y));
    }

    #[test]
    fn negative_scale_is_a_point_reflection() {
        let f = Frame::from_scale(-2.0);
        assert!(f.parity);
        assert!(close(f.transform_point(DVec3::ONE), DVec3::splat(-2.0)));
    }
}
