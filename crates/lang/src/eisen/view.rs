//! Structure Synth's viewer settings (`set translation`, `rotation`, `pivot`,
//! `scale`, `perspective-angle`, as its GUI saves a view into a script),
//! turned into the one camera a glTF file carries.

use crate::eisen::syntax::CameraSetting;
use crate::model::Camera;
use glam::{DMat3, DVec3};

/// Structure Synth's default view: the model 20 units in front of the eye.
pub(crate) const DEFAULT_VIEW_TRANSLATION: [f64; 3] = [0.0, 0.0, -20.0];
/// Structure Synth's default vertical field of view, degrees.
pub(crate) const DEFAULT_PERSPECTIVE_ANGLE: f64 = 22.0;

/// The viewer settings seen so far: Structure Synth's view maps a world
/// point p to `translation + rotation · (scale · (p − pivot))`, the eye at
/// the view-space origin looking down −Z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct View {
    translation: DVec3,
    rotation: DMat3,
    pivot: DVec3,
    scale: f64,
    angle: f64,
}

impl Default for View {
    fn default() -> Self {
        View { translation: DVec3::from_array(DEFAULT_VIEW_TRANSLATION), rotation: DMat3::IDENTITY, pivot: DVec3::ZERO, scale: 1.0, angle: DEFAULT_PERSPECTIVE_ANGLE }
    }
}

impl View {
    /// The eye in world space: the inverse of the view map at the view origin.
    pub(super) fn camera(&self) -> Option<Camera> {
        // Structure Synth's saved rotations are rotations up to rounding; re-orthonormalise.
        let q = glam::DQuat::from_mat3(&self.rotation).normalize();
        if !q.is_finite() || !(self.scale.is_finite() && self.scale > 0.0) {
            return None;
        }
        let inverse = q.conjugate();
        let position = self.pivot - (inverse * self.translation) / self.scale;
        let fov = self.angle.clamp(1.0, 179.0).to_radians();
        position.is_finite().then(|| Camera::still(position.as_vec3().to_array(), inverse.as_quat().normalize().to_array(), fov as f32))
    }

    /// Applies one viewer setting.
    pub(super) fn set(&mut self, c: CameraSetting) {
        match c {
            CameraSetting::Translation(t) => self.translation = t,
            CameraSetting::Rotation(r) => self.rotation = r,
            CameraSetting::Pivot(p) => self.pivot = p,
            CameraSetting::Scale(s) => self.scale = s,
            CameraSetting::PerspectiveAngle(a) => self.angle = a,
        }
    }
}
