//! Structure Synth JavaScript scripts as movies: [`build_model`] runs the script
//! ([`crate::eisen::js`]), builds the EisenScript text of every frame
//! it pictured under the one request [`Budget`] (so the limits bind the sum
//! of all frames), and assembles one [`Model`] whose frames play in turn.
//!
//! Frame k is a node of its own whose scale track is 1 at sample k and 0 at
//! every other sample, sampled at [`MOVIE_FPS`] with STEP interpolation, so
//! exactly frame k shows from time k / fps until the next frame (LINEAR
//! would grow one frame while the last shrinks). Outputs without animation
//! (STL, strips, printing, quantised glTF, …) show frame 0, as they show
//! time 0 of any animation. A script that builds but pictures nothing shows
//! its last build; one that builds nothing gives an empty model.
//!
//! A request's `frame: k` builds the k-th picture alone (the script still
//! runs whole, recording every picture's text, which costs little): how
//! Structure Synth itself renders a movie, one picture under its own
//! limits at a time, where the whole movie under one budget may not fit.

use super::build::{self, Built};
use super::{build_options, parse_bound};
use crate::core::budget::{Budget, OnLimit};
use crate::core::timing::{Phase, StageClock};
use crate::core::{Diagnostic, Frame, ParseError, Span};
use crate::Language;
use crate::model::animation::{Bone, Rig, Timeline, BONE_BYTES};
use crate::model::scene::{AFFINE_INSTANCE_BYTES, FREE_VERTEX_BYTES};
use crate::model::{BuildError, BuildRequest, EvalError, Model, Scene};
use js::Loader;
use super::js;

/// Frames per second of a movie: one frame per picture the script saved.
pub(crate) const MOVIE_FPS: f64 = 30.0;

/// Builds the model of the JavaScript script `source` under `budget`.
pub fn build_model(source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let text = std::str::from_utf8(source).map_err(|_| ParseError::single(Span::new(1, 1), "the source is not valid UTF-8"))?;
    let loader = match req.script_dir {
        Some(dir) => Loader::Directory(dir.to_path_buf()),
        None => Loader::Library,
    };
    let seed = req.seed.unwrap_or(0);
    let movie = js::run(text, loader, seed, req.on_limit == OnLimit::Truncate, budget)?;
    clock.lap(Phase::Parse);
    let mut warnings = movie.warnings;
    let texts: Vec<&String> = match req.frame {
        // One picture, as Structure Synth builds and renders each picture alone.
        Some(k) => vec![movie.frames.get(k as usize).ok_or_else(|| no_such_frame(k, movie.frames.len()))?],
        None if movie.frames.is_empty() => movie.last_build.iter().collect(),
        None => movie.frames.iter().collect(),
    };
    if texts.is_empty() {
        warnings.push(Diagnostic::warning(Span::new(1, 1), "the script built nothing: the model is empty"));
    }
    let mut truncated = movie.truncated;
    let animated = req.animated;
    // Animated output splits the scene into one part per frame (a copy of
    // every element and its frame tag): promised with the rest of meshing's memory.
    let opts = |radius: f64| {
        let mut o = build_options(req, radius);
        if animated {
            o.downstream_bytes = o.downstream_bytes.map(|b| b.saturating_add(AFFINE_INSTANCE_BYTES + 4));
            o.vertex_bytes = o.vertex_bytes.saturating_add(FREE_VERTEX_BYTES + 4);
        }
        o
    };
    let mut frames: Vec<Built> = Vec::new();
    let mut promised = 0u64;
    for (k, text) in texts.iter().enumerate() {
        let (script, radius) = parse_bound(text.as_bytes(), req.params, seed).map_err(|e| match e {
            BuildError::Parse(p) => BuildError::Eval(EvalError::Script { message: format!("frame {k}: the EisenScript it builds does not parse: {p}") }),
            other => other,
        })?;
        for w in &script.warnings {
            // The position is in the EisenScript the JavaScript built, not in
            // the JavaScript file the caller names: say so, and point at line 1.
            let w = Diagnostic {
                severity: w.severity,
                span: Span::new(1, 1),
                message: format!("in the EisenScript the script builds, at {}:{}: {}", w.span.line, w.span.column, w.message),
            };
            if !warnings.contains(&w) {
                warnings.push(w);
            }
        }
        let built = build::build(&script, &opts(radius), budget)?;
        promised = promised.saturating_add(built.promised);
        if let Some(l) = built.scene.truncated {
            // Under `truncate` a frame cut short is kept only when it is the first.
            if frames.is_empty() {
                frames.push(built);
            }
            truncated.get_or_insert(l);
            break;
        }
        frames.push(built);
    }
    if let Err(e) = budget.check_deadline() {
        match req.on_limit {
            OnLimit::Error => return Err(e.into()),
            OnLimit::Truncate => {
                truncated.get_or_insert(e);
            }
        }
    }
    // The frames' promise is given back before assembling reserves the tracks.
    budget.release_memory(promised.saturating_add(movie.held_bytes));
    let (mut scene, primitives) = assemble(frames, animated, budget)?;
    scene.truncated = truncated;
    Ok(Model { language: Language::Eisenscript, scene, hierarchy: None, drawing: None, primitives, warnings, promised: 0, seed })
}

/// The error for a `frame` the script does not save.
fn no_such_frame(k: u32, saved: usize) -> EvalError {
    let message = match saved {
        0 => format!("the script saves no picture, so it has no frame {k} (without `frame` it shows what it built last)"),
        n => format!("the script saves {n} pictures (frames 0 to {}); there is no frame {k}", n - 1),
    };
    EvalError::Frame { message }
}

/// One scene of `frames`: frame 0 alone unless `animated` and there are
/// several, else every frame under its own bone (see the module docs).
/// Returns the scene and its object count.
fn assemble(frames: Vec<Built>, animated: bool, budget: &mut Budget) -> Result<(Scene, u64), BuildError> {
    let n = frames.len();
    if n <= 1 || !animated {
        return Ok(frames.into_iter().next().map(|b| (b.scene, b.objects)).unwrap_or_default());
    }
    let samples = u32::try_from(n).unwrap_or(u32::MAX);
    // One track of n samples per frame (the tags were promised while building).
    let track_bytes = (n as u64).saturating_mul(n as u64).saturating_mul(std::mem::size_of::<Frame>() as u64);
    budget.reserve_memory(track_bytes.saturating_add(BONE_BYTES.saturating_mul(n as u64)))?;
    let mut rig = Rig::new(Timeline { fps: MOVIE_FPS, samples, step: true });
    let mut objects = 0u64;
    let mut iter = frames.into_iter();
    let Some(first) = iter.next() else { return Ok((Scene::default(), 0)) };
    let mut scene = Scene { classes: first.scene.classes.clone(), camera: first.scene.camera.clone(), background: first.scene.background, ..Scene::default() };
    for (k, built) in std::iter::once(first).chain(iter).enumerate() {
        let bone = (k + 1) as u32;
        rig.bones.push(Bone { name: format!("frame {k}"), parent: 0, local: Frame::IDENTITY, body: Frame::IDENTITY, track: bone });
        rig.tracks.push((0..n).map(|j| if j == k { Frame::IDENTITY } else { Frame::from_scale(0.0) }).collect());
        objects = objects.saturating_add(built.objects);
        let remap: Vec<u32> = built
            .scene
            .classes
            .iter()
            .map(|c| match scene.classes.iter().position(|m| m == c) {
                Some(i) => i as u32,
                None => {
                    scene.classes.push(c.clone());
                    (scene.classes.len() - 1) as u32
                }
            })
            .collect();
        for mut a in built.scene.affine {
            a.class = remap.get(a.class as usize).copied().unwrap_or(0);
            scene.affine.push(a);
            rig.affine_bone.push(bone);
        }
        for v in built.scene.vertices {
            scene.vertices.push(v);
            rig.vertex_bone.push(bone);
        }
    }
    scene.rig = Some(rig);
    Ok((scene, objects))
}
