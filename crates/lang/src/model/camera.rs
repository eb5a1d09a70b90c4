//! The one camera type every language makes and every format that can
//! carry a camera writes: a perspective lens and where the camera node is
//! at each sample of a timeline (one placement: a still camera).
//!
//! MDG's `camerarule` gives a camera path ([`CameraPath`], view frames on the
//! grammar's timeline); Structure Synth's viewer settings give a still
//! camera. Both become a [`Camera`] here, so the plain glTF writer animates
//! a moving one in the node graph, and every other glTF writer (quantised,
//! meshopt, unit-box fitted) shows it at time 0.

use crate::model::animation::{CameraPath, Timeline};
use crate::model::graph::Trs;

/// Near clipping distance of a camera whose source sets none (glTF requires
/// one; its far plane is then infinite).
pub(crate) const DEFAULT_ZNEAR: f32 = 0.01;

/// A perspective camera and its placement over time.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    /// The glTF camera's name (`camerarule` for MDG), if any.
    pub name: Option<String>,
    /// Vertical field of view, radians.
    pub yfov: f32,
    /// Near clipping distance.
    pub znear: f32,
    /// Far clipping distance; `None` is infinite.
    pub zfar: Option<f32>,
    /// The camera node's transform at each sample of [`Camera::timeline`]
    /// (a rigid motion; the camera looks down its local −Z).
    pub placements: Vec<Trs>,
    /// When the placements are sampled; `None` for a still camera.
    pub timeline: Option<Timeline>,
}

impl Camera {
    /// The camera of an MDG `camerarule` path: each view frame's inverse.
    pub(crate) fn from_path(path: &CameraPath) -> Camera {
        Camera {
            name: Some("camerarule".to_string()),
            yfov: path.lens.fov_degrees.to_radians() as f32,
            znear: path.lens.near as f32,
            zfar: Some(path.lens.far as f32),
            placements: path.frames.iter().map(Trs::of_view).collect(),
            timeline: Some(path.timeline),
        }
    }

    /// A still camera at `translation`, turned by the unit quaternion
    /// `rotation` (x, y, z, w), with vertical field of view `yfov` radians.
    pub fn still(translation: [f32; 3], rotation: [f32; 4], yfov: f32) -> Camera {
        Camera { name: None, yfov, znear: DEFAULT_ZNEAR, zfar: None, placements: vec![Trs { translation, rotation, scale: [1.0; 3] }], timeline: None }
    }

    /// Whether the camera moves on a timeline (and so needs a node graph to play).
    pub fn is_path(&self) -> bool {
        self.timeline.is_some()
    }

    /// Where the camera is at time 0.
    pub fn first(&self) -> Trs {
        self.placements.first().copied().unwrap_or(Trs { translation: [0.0; 3], rotation: [0.0, 0.0, 0.0, 1.0], scale: [1.0; 3] })
    }

    /// The same view of a model moved by `p ↦ (p − centre) · scale` (unit-box
    /// fitting): every placement moved alike and the clipping planes scaled,
    /// so the fitted model is seen exactly as the original was.
    pub fn fitted(&self, centre: [f64; 3], scale: f64) -> Camera {
        let mv = |t: [f32; 3]| [0, 1, 2].map(|a| ((f64::from(t[a]) - centre[a]) * scale) as f32);
        Camera {
            placements: self.placements.iter().map(|p| Trs { translation: mv(p.translation), ..*p }).collect(),
            znear: (f64::from(self.znear) * scale) as f32,
            zfar: self.zfar.map(|f| (f64::from(f) * scale) as f32),
            ..self.clone()
        }
    }
}
