//! Path rules and what is made of them: a rule evaluated in a sub-machine
//! as a stream of `FRAME`s and `VERTEX`es (a [`Capture`], once per group),
//! convolved rules, animation bones and their tracks (and the tagging of
//! geometry with its bone), and the camera path of `camerarule`.

use super::adjust::Ctx;
use super::machine::{Machine, CAPTURE_SLOT};
use crate::core::frame::Frame;
use crate::ir::{GroupId, Target};
use crate::model::animation::{looped, Bone, CameraPath, Rig, BONE_BYTES};
use crate::model::scene::Scene;
use crate::model::EvalError;
use glam::DVec3;
use std::rc::Rc;

/// What a path or profile rule emitted.
#[derive(Debug, Default)]
pub(super) struct Capture {
    /// Stop once this many frames are captured (animation paths may recurse
    /// forever; only their first frames are needed).
    pub(super) frame_limit: Option<usize>,
    /// `FRAME {}` frames, in order.
    pub(super) frames: Vec<Frame>,
    /// `VERTEX {}` positions, in order.
    pub(super) vertices: Vec<DVec3>,
}

/// How many path, profile or camera rules may be evaluated one inside
/// another (a path rule whose body uses an animated rule whose path uses …).
/// Real grammars nest two or three; the bound keeps the call stack small.
pub(crate) const MAX_CAPTURE_NESTING: usize = 32;

impl<'p, 'b> Machine<'p, 'b> {
    /// Records which bone a new piece of geometry belongs to (when the scene has a rig).
    pub(super) fn tag(&mut self, tags: fn(&mut Rig) -> &mut Vec<u32>, bone: u32) -> Result<(), EvalError> {
        if let Some(rig) = &mut self.scene.rig {
            self.budget.reserve_memory(4)?;
            tags(rig).push(bone);
        }
        Ok(())
    }

    /// A call of animated rule `name` with transform rules `paths`: the frame
    /// its body runs in (the call frame composed with the track at time 0)
    /// and its bone (a new one when the scene has a rig).
    pub(super) fn bone(&mut self, name: &str, paths: &[GroupId], ctx: &Ctx) -> Result<(Frame, u32), EvalError> {
        let Some(samples) = self.scene.rig.as_ref().map(|r| r.timeline.samples) else {
            // No rig (inside a path rule): only time 0 matters.
            let mut frame = ctx.frame;
            for &p in paths {
                if let Some(f) = self.capture_group(p, Some(1))?.frames.first() {
                    frame = frame.then(f);
                }
            }
            return Ok((frame, ctx.bone));
        };
        let track = match self.track_index.get(paths) {
            Some(&t) => t,
            None => {
                let streams = paths.iter().map(|&p| self.capture_group(p, Some(samples as usize))).collect::<Result<Vec<_>, _>>()?;
                self.budget.reserve_memory(u64::from(samples).saturating_mul(std::mem::size_of::<Frame>() as u64))?;
                let frames: Vec<Frame> = (0..samples as usize)
                    .map(|k| streams.iter().fold(Frame::IDENTITY, |f, s| f.then(&looped(&s.frames, k))))
                    .collect();
                let Some(rig) = self.scene.rig.as_mut() else { return Ok((ctx.frame, ctx.bone)) };
                rig.tracks.push(frames);
                let t = (rig.tracks.len() - 1) as u32;
                self.track_index.insert(paths.to_vec(), t);
                t
            }
        };
        self.budget.reserve_memory(BONE_BYTES)?;
        let Some(rig) = self.scene.rig.as_mut() else { return Ok((ctx.frame, ctx.bone)) };
        let start = rig.tracks.get(track as usize).and_then(|t| t.first()).copied().unwrap_or(Frame::IDENTITY);
        let body = ctx.frame.then(&start);
        let parent_body = rig.bones.get(ctx.bone as usize).map_or(Frame::IDENTITY, |b| b.body);
        // A parent collapsed to zero scale hides its children anyway.
        let local = parent_body.inverse().map_or(Frame::IDENTITY, |inv| inv.then(&ctx.frame));
        let id = u32::try_from(rig.bones.len()).unwrap_or(u32::MAX);
        rig.bones.push(Bone { name: name.to_string(), parent: ctx.bone, local, body, track });
        Ok((body, id))
    }

    /// The camera path of `camerarule`, sampled on the timeline.
    pub(super) fn camera(&mut self) -> Result<Option<CameraPath>, EvalError> {
        let dirs = &self.ev.program.directives;
        let Some(g) = dirs.camerarule else { return Ok(None) };
        let lens = dirs.camera;
        let timeline = self.ev.timeline;
        let stream = self.capture_group(g, Some(timeline.samples as usize))?;
        let frames = match stream.frames.len() {
            0 => vec![Frame::IDENTITY],
            1 => vec![stream.frames[0]],
            _ => {
                self.budget.reserve_memory(u64::from(timeline.samples).saturating_mul(std::mem::size_of::<Frame>() as u64))?;
                (0..timeline.samples as usize).map(|k| looped(&stream.frames, k)).collect()
            }
        };
        Ok(Some(CameraPath { timeline, frames, lens }))
    }

    /// Evaluates a path or profile rule from the identity frame, once per evaluation.
    pub(super) fn capture_group(&mut self, g: GroupId, frame_limit: Option<usize>) -> Result<Rc<Capture>, EvalError> {
        if let Some(c) = self.captured.get(&g).filter(|c| c.frame_limit.is_none() || c.frame_limit == frame_limit) {
            return Ok(Rc::clone(c));
        }
        // A capture runs a machine of its own on the call stack, so a path
        // rule that is animated (or swept) by itself, directly or through
        // other path rules, would recurse until the stack overflows.
        if self.capturing.contains(&g) || self.capturing.len() >= MAX_CAPTURE_NESTING {
            let name = self.ev.program.groups.get(g as usize).map_or_else(String::new, |group| group.name.clone());
            return Err(EvalError::PathCycle { name, nesting: MAX_CAPTURE_NESTING });
        }
        let key = self.root_key.child(CAPTURE_SLOT, u64::from(g));
        let root = Ctx { frame: Frame::IDENTITY, colour: [0.0; 4], depth: 0, key, bone: 0, ns: 0 };
        let capture = Capture { frame_limit, ..Capture::default() };
        let mut sub = Machine::new(self.ev, &mut *self.budget, Scene::default(), Some(capture), self.root_key);
        sub.capturing = self.capturing.iter().copied().chain([g]).collect();
        let result = sub.run(Target::Group(g), root);
        sub.release();
        result?;
        let c = Rc::new(sub.capture.take().unwrap_or_default());
        self.captured.insert(g, Rc::clone(&c));
        Ok(c)
    }

    /// The frames of a convolved rule: frame i of the first path composed with
    /// frame i of each further path, as many as the shortest path has.
    pub(super) fn convolved(&mut self, paths: &[GroupId]) -> Result<Rc<Vec<Frame>>, EvalError> {
        let captures = paths.iter().map(|&p| self.capture_group(p, None)).collect::<Result<Vec<_>, _>>()?;
        let n = captures.iter().map(|c| c.frames.len()).min().unwrap_or(0);
        self.budget.reserve_memory((n as u64).saturating_mul(std::mem::size_of::<Frame>() as u64))?;
        let frames = (0..n)
            .map(|i| captures.iter().skip(1).fold(captures[0].frames[i], |f, c| f.then(&c.frames[i])))
            .collect();
        Ok(Rc::new(frames))
    }
}
