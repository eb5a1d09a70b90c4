//! A node hierarchy with sampled transforms, for formats that carry one
//! (glTF nodes, animations and cameras).
//!
//! Built from a scene's [`Rig`] and [`CameraPath`]; the glTF writers turn it
//! into nodes, one animation with TRS channels per bone, and a camera node.
//! Meshes are attached to nodes by index, so the meshes themselves stay
//! plain (each in its node's local coordinates).

use crate::model::animation::Rig;
use crate::model::Camera;
use crate::core::budget::{Budget, LimitExceeded};
use crate::core::Frame;

/// Translation, rotation and scale of a glTF node (rotation unit, x y z w).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trs {
    /// Translation.
    pub translation: [f32; 3],
    /// Unit quaternion, x y z w.
    pub rotation: [f32; 4],
    /// Scale per axis (all three equal; negative for a reflected frame).
    pub scale: [f32; 3],
}

impl Trs {
    /// The TRS of a similarity frame: a reflection (odd parity) becomes the
    /// scale −s on every axis, which is σ·s·R exactly.
    pub fn of(frame: &Frame) -> Trs {
        let q = frame.rotation.normalize();
        let s = (frame.sign() * frame.scale) as f32;
        Trs {
            translation: frame.translation.as_vec3().to_array(),
            rotation: [q.x as f32, q.y as f32, q.z as f32, q.w as f32],
            scale: [s; 3],
        }
    }

    /// The camera node of a view frame: its inverse, without scale or
    /// reflection (a glTF camera node should be a rigid motion).
    pub(crate) fn of_view(view: &Frame) -> Trs {
        // The camera sits at the point the view maps to the eye's origin,
        // turned by the inverse rotation; a view with zero scale has no inverse.
        let inv = view.inverse().unwrap_or(Frame::IDENTITY);
        Trs::of(&Frame { translation: inv.translation, rotation: inv.rotation, scale: 1.0, parity: false })
    }
}

/// One node of the hierarchy.
#[derive(Debug, Clone, PartialEq)]
pub struct GraphNode {
    /// Node name (the animated rule's name).
    pub name: String,
    /// Index of the parent node; `None` hangs it under the model's root node.
    pub parent: Option<u32>,
    /// The node-local transform per sample (one entry: not animated).
    pub samples: Vec<Trs>,
}

/// Nodes (parents before children), where each mesh hangs, sample times and a camera.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct NodeGraph {
    /// The nodes, parents first.
    pub nodes: Vec<GraphNode>,
    /// For each mesh handed to the writer, the node it hangs under (`None`: the root).
    pub mesh_nodes: Vec<Option<u32>>,
    /// Sample times in seconds (strictly increasing, starting at 0).
    pub times: Vec<f32>,
    /// The camera path, if the grammar has one: a placement per sample, or a
    /// single one when it does not move.
    pub camera: Option<Camera>,
    /// Samples hold until the next (glTF STEP interpolation) instead of LINEAR.
    pub step: bool,
}

/// One sample when every sample is the same (a node that does not move gets no channels).
fn still_if_constant(mut samples: Vec<Trs>) -> Vec<Trs> {
    if samples.windows(2).all(|w| w[0] == w[1]) {
        samples.truncate(1);
    }
    samples
}

impl NodeGraph {
    /// Builds the graph of `rig` (bones → nodes; bone 0, the root, becomes no
    /// node) and `camera`, for meshes made per bone in the order `mesh_bones`.
    /// Sampled transforms are charged to `budget` first.
    pub fn new(rig: Option<&Rig>, camera: Option<&Camera>, mesh_bones: &[u32], budget: &mut Budget) -> Result<NodeGraph, LimitExceeded> {
        let timeline = rig.map(|r| r.timeline).or(camera.and_then(|c| c.timeline));
        let samples = timeline.map_or(1, |t| t.samples as usize);
        let bones = rig.map_or(0, |r| r.bones.len().saturating_sub(1));
        let trs_bytes = std::mem::size_of::<Trs>() as u64;
        budget.reserve_memory((bones as u64 + 1).saturating_mul(samples as u64).saturating_mul(trs_bytes))?;
        let times = match timeline {
            Some(t) => (0..t.samples).map(|k| t.time(k) as f32).collect(),
            None => vec![0.0],
        };
        let mut nodes = Vec::with_capacity(bones);
        if let Some(rig) = rig {
            for (b, bone) in rig.bones.iter().enumerate().skip(1) {
                nodes.push(GraphNode {
                    name: bone.name.clone(),
                    // Bone b is node b − 1; the root bone 0 is no node.
                    parent: bone.parent.checked_sub(1),
                    samples: still_if_constant((0..samples).map(|k| Trs::of(&rig.pose(b, k))).collect()),
                });
            }
        }
        let camera = camera.map(|c| Camera { placements: still_if_constant(c.placements.clone()), ..c.clone() });
        let step = timeline.is_some_and(|t| t.step);
        Ok(NodeGraph { nodes, mesh_nodes: mesh_bones.iter().map(|b| b.checked_sub(1)).collect(), times, camera, step })
    }

    /// True when something moves (more than one sample of a node or the camera).
    pub fn is_animated(&self) -> bool {
        self.times.len() > 1 && (self.nodes.iter().any(|n| n.samples.len() > 1) || self.camera.as_ref().is_some_and(|c| c.placements.len() > 1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec3};

    #[test]
    fn camera_node_is_the_inverse_view() {
        let view = Frame::from_translation(DVec3::new(0.0, 0.0, -20.0));
        let t = Trs::of_view(&view);
        assert_eq!(t.translation, [0.0, 0.0, 20.0]);
        assert_eq!(t.scale, [1.0; 3]);
        let view = Frame::from_rotation(DQuat::from_rotation_y(std::f64::consts::FRAC_PI_2)).then(&view);
        let t = Trs::of_view(&view);
        // The camera sits where the view maps to the eye's origin.
        let p = DVec3::from_array(t.translation.map(f64::from));
        assert!(view.transform_point(p).length() < 1e-5, "{p}");
    }

    #[test]
    fn reflection_is_negative_scale() {
        let f = Frame { parity: true, scale: 2.0, ..Frame::IDENTITY };
        assert_eq!(Trs::of(&f).scale, [-2.0; 3]);
    }
}
