//! Animation (Andersson 2015 §4.4): bones, their frame tracks, the camera path,
//! and the split of a scene into per-bone pieces for exporters that carry a
//! node hierarchy (glTF).
//!
//! A call of an animated rule `rule A : X1 : X2 { … }` makes a *bone*. The
//! transform rules X1, X2 are evaluated once each, from the identity frame,
//! and the `FRAME {}`s they emit form streams; frame k of the bone's track
//! is X1's frame k composed with X2's frame k (parent first, as convolve
//! composes). The bone's body runs in `call frame ∘ track(t)`, so the
//! geometry it makes moves with the track; a bone called inside another
//! bone's body moves with its parent too (a hierarchy, like the thesis's
//! "articulation functions"). Choices the thesis leaves open, fixed here and
//! in docs/mdg.md: sample k is at time k / fps, there are
//! `round(duration · fps) + 1` samples (both ends), a stream shorter than
//! that loops, and static outputs show time 0.

use crate::core::budget::{Budget, LimitExceeded};
use crate::core::frame::Frame;
use crate::model::scene::{Scene, AFFINE_INSTANCE_BYTES, FREE_VERTEX_BYTES, INSTANCE_BYTES, LINE_POINT_BYTES, SHAPE_INSTANCE_BYTES};
use crate::ir::CameraLens;
use std::collections::BTreeMap;

/// Frames per second when the grammar sets no `fps`.
pub(crate) const DEFAULT_FPS: f64 = 30.0;

/// Animation length in seconds when the grammar sets no `duration`.
pub(crate) const DEFAULT_DURATION: f64 = 10.0;

/// When frames are sampled: `samples` ticks of `1 / fps` seconds from time 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timeline {
    /// Samples per second.
    pub fps: f64,
    /// Number of samples, at times 0, 1/fps, …, (samples − 1)/fps (≥ 1).
    pub samples: u32,
    /// Hold each sample until the next one (glTF STEP) instead of
    /// interpolating: movie frames that switch on and off must not cross-fade.
    pub step: bool,
}

impl Timeline {
    /// The timeline of a grammar's `fps` and `duration` (defaults 30 and 10 s).
    /// The parser bounds both, so the count fits easily in a `u32`.
    pub fn new(fps: Option<f64>, duration: Option<f64>) -> Timeline {
        let fps = fps.filter(|f| *f > 0.0 && f.is_finite()).unwrap_or(DEFAULT_FPS);
        let duration = duration.filter(|d| *d >= 0.0 && d.is_finite()).unwrap_or(DEFAULT_DURATION);
        let samples = ((duration * fps).round().min(f64::from(u32::MAX - 1)) as u32).saturating_add(1);
        Timeline { fps, samples, step: false }
    }

    /// The time of sample `k`, in seconds.
    pub fn time(&self, k: u32) -> f64 {
        f64::from(k) / self.fps
    }
}

/// Frame `k` of a stream that loops; the identity for an empty stream.
pub(crate) fn looped(frames: &[Frame], k: usize) -> Frame {
    match frames.len() {
        0 => Frame::IDENTITY,
        n => frames[k % n],
    }
}

/// One call of an animated rule.
#[derive(Debug, Clone, PartialEq)]
pub struct Bone {
    /// The animated rule's name (the glTF node's name).
    pub name: String,
    /// Index in [`Rig::bones`] of the enclosing bone (the root, 0, is its own parent).
    pub parent: u32,
    /// The call frame in the parent bone's body space (constant over time).
    pub local: Frame,
    /// The world frame of the bone's body at time 0: where its geometry was made.
    pub body: Frame,
    /// Index in [`Rig::tracks`] of the bone's animation.
    pub track: u32,
}

/// Every bone of an animated scene and which bone each piece of geometry belongs to.
///
/// The per-element vectors run parallel to the scene's `instances`, `lines`,
/// `vertices` and `shape_instances`; geometry made outside every animated
/// rule belongs to the root bone 0. A swept line belongs to the bone where it
/// started (a line that crosses bones does not bend with the later ones).
#[derive(Debug, Clone, PartialEq)]
pub struct Rig {
    /// When the tracks are sampled.
    pub timeline: Timeline,
    /// Bone 0 is the root: identity frames, no animation.
    pub bones: Vec<Bone>,
    /// Sampled track frames, each `timeline.samples` long except track 0 (the identity).
    pub tracks: Vec<Vec<Frame>>,
    /// Bone of each scene instance.
    pub instance_bone: Vec<u32>,
    /// Bone of each scene polyline.
    pub line_bone: Vec<u32>,
    /// Bone of each free vertex (a triangle goes with its first vertex).
    pub vertex_bone: Vec<u32>,
    /// Bone of each shape instance.
    pub shape_instance_bone: Vec<u32>,
    /// Bone of each affine instance (EisenScript movie frames).
    pub affine_bone: Vec<u32>,
}

/// Bytes accounted per bone (its record and its four tag vectors' share).
pub(crate) const BONE_BYTES: u64 = std::mem::size_of::<Bone>() as u64 + 32;

impl Rig {
    /// An empty rig: just the root bone.
    pub fn new(timeline: Timeline) -> Rig {
        Rig {
            timeline,
            bones: vec![Bone { name: "root".into(), parent: 0, local: Frame::IDENTITY, body: Frame::IDENTITY, track: 0 }],
            tracks: vec![vec![Frame::IDENTITY]],
            instance_bone: Vec::new(),
            line_bone: Vec::new(),
            vertex_bone: Vec::new(),
            shape_instance_bone: Vec::new(),
            affine_bone: Vec::new(),
        }
    }

    /// The node-local transform of `bone` at sample `k`: its call frame in the
    /// parent's body space, then its track's frame k.
    pub fn pose(&self, bone: usize, k: usize) -> Frame {
        let Some(b) = self.bones.get(bone) else { return Frame::IDENTITY };
        let track = self.tracks.get(b.track as usize).map_or(&[][..], |t| &t[..]);
        b.local.then(&looped(track, k))
    }

    /// Splits `scene` into one scene per bone that has geometry, each in its
    /// bone's body coordinates (so placing it by the bone's world transform
    /// at time 0 gives back the original). Ordered by bone index. Geometry of
    /// a bone whose body frame has zero scale (invisible) is dropped.
    pub fn split(&self, scene: &Scene, budget: &mut Budget) -> Result<Vec<(u32, Scene)>, LimitExceeded> {
        let points: u64 = scene.lines.iter().map(|l| l.points.len() as u64).sum();
        let copies = (scene.instances.len() as u64)
            .saturating_mul(INSTANCE_BYTES)
            .saturating_add(points.saturating_mul(LINE_POINT_BYTES))
            .saturating_add((scene.vertices.len() as u64).saturating_mul(FREE_VERTEX_BYTES))
            .saturating_add((scene.shape_instances.len() as u64).saturating_mul(SHAPE_INSTANCE_BYTES))
            .saturating_add((scene.affine.len() as u64).saturating_mul(AFFINE_INSTANCE_BYTES));
        budget.reserve_memory(copies)?;
        let inverse: Vec<Option<Frame>> = self.bones.iter().map(|b| b.body.inverse()).collect();
        let bone_of = |tags: &[u32], i: usize| tags.get(i).copied().unwrap_or(0);
        let mut parts: BTreeMap<u32, Scene> = BTreeMap::new();
        fn part<'a>(parts: &'a mut BTreeMap<u32, Scene>, inverse: &'a [Option<Frame>], b: u32) -> Option<(&'a Frame, &'a mut Scene)> {
            let inv = inverse.get(b as usize)?.as_ref()?;
            Some((inv, parts.entry(b).or_default()))
        }
        for (i, inst) in scene.instances.iter().enumerate() {
            if let Some((inv, s)) = part(&mut parts, &inverse, bone_of(&self.instance_bone, i)) {
                s.instances.push(inst.transformed(inv));
            }
        }
        for (i, line) in scene.lines.iter().enumerate() {
            if let Some((inv, s)) = part(&mut parts, &inverse, bone_of(&self.line_bone, i)) {
                let mut l = line.clone();
                for p in &mut l.points {
                    p.frame = inv.then(&p.frame);
                }
                s.lines.push(l);
            }
        }
        for (t, tri) in scene.vertices.chunks_exact(3).enumerate() {
            if let Some((inv, s)) = part(&mut parts, &inverse, bone_of(&self.vertex_bone, 3 * t)) {
                for v in tri {
                    let mut v = *v;
                    v.position = inv.transform_point(v.position);
                    v.normal = inv.transform_normal(v.normal).normalize_or_zero();
                    s.vertices.push(v);
                }
            }
        }
        for (i, si) in scene.shape_instances.iter().enumerate() {
            if let Some((inv, s)) = part(&mut parts, &inverse, bone_of(&self.shape_instance_bone, i)) {
                let mut si = *si;
                si.frame = inv.then(&si.frame);
                s.shape_instances.push(si);
            }
        }
        for (i, a) in scene.affine.iter().enumerate() {
            if let Some((inv, s)) = part(&mut parts, &inverse, bone_of(&self.affine_bone, i)) {
                let mut a = *a;
                let lin = inv.linear().as_mat3();
                a.linear = lin * a.linear;
                a.translation = inv.transform_point(a.translation.as_dvec3()).as_vec3();
                s.affine.push(a);
            }
        }
        // Lines and shape instances index the scene's profiles and shapes: give
        // each part that uses them its own copy (charged to the budget).
        let shape_bytes: u64 = scene
            .shapes
            .iter()
            .map(|p| crate::geom::mesh::mesh_bytes(p.positions.len() as u64, (p.indices.len() / 3) as u64))
            .sum();
        let profile_bytes: u64 = scene.profiles.iter().map(|p| 24 * p.len() as u64).sum();
        for s in parts.values_mut() {
            if !s.shape_instances.is_empty() {
                budget.reserve_memory(shape_bytes)?;
                s.shapes = scene.shapes.clone();
            }
            if !s.lines.is_empty() {
                budget.reserve_memory(profile_bytes)?;
                s.profiles = scene.profiles.clone();
            }
            // Affine instances name their class (their mesh and material) by index.
            s.classes = scene.classes.clone();
        }
        Ok(parts.into_iter().collect())
    }
}

/// The camera of `camerarule`: a view transform per sample.
///
/// Choice (docs/mdg.md): a camera frame is the *view* transform, world to
/// eye, as in the thesis's OpenGL renderer, so `FRAME { z -20 }` puts the
/// model 20 units in front of a camera looking down −z (C.3's "adjust camera
/// distance here"). The camera's place in the world is the inverse frame.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CameraPath {
    /// When the frames are sampled.
    pub timeline: Timeline,
    /// One view frame per sample (a single frame for a still camera).
    pub frames: Vec<Frame>,
    /// Field of view and clipping planes.
    pub lens: CameraLens,
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec3};

    #[test]
    fn timeline_counts_both_ends() {
        assert_eq!(Timeline::new(Some(4.0), Some(1.0)).samples, 5);
        assert_eq!(Timeline::new(None, None).samples, 301);
        assert_eq!(Timeline::new(Some(24.0), Some(0.0)).samples, 1);
        assert!((Timeline::new(Some(4.0), Some(1.0)).time(3) - 0.75).abs() < 1e-12);
    }

    #[test]
    fn streams_loop() {
        let f = |x| Frame::from_translation(DVec3::new(x, 0.0, 0.0));
        let s = [f(1.0), f(2.0), f(3.0)];
        assert_eq!(looped(&s, 4), f(2.0));
        assert_eq!(looped(&[], 7), Frame::IDENTITY);
    }

    #[test]
    fn inverse_undoes_a_reflected_scaled_frame() {
        let f = Frame { translation: DVec3::new(1.0, -2.0, 3.0), rotation: DQuat::from_rotation_y(0.7), scale: 2.5, parity: true };
        let inv = f.inverse().expect("invertible");
        let p = DVec3::new(0.3, 0.4, -5.0);
        assert!((inv.transform_point(f.transform_point(p)) - p).length() < 1e-12);
        assert!((f.then(&inv).translation).length() < 1e-12);
        assert!(Frame::from_scale(0.0).inverse().is_none());
    }
}
