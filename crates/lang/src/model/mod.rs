//! The one model every front end hands to the stages: a [`Scene`] of
//! placed primitives, free meshes, swept lines, an animation rig and a
//! camera, plus an instancing [`Hierarchy`] where the language builds one.
//! Also the contract of a front end: what it is asked ([`BuildRequest`])
//! and how it fails ([`BuildError`]).

pub mod animation;
pub mod camera;
pub mod drawing;
pub mod error;
pub mod graph;
pub mod hierarchy;
pub mod instancing;
pub mod request;
pub mod scene;

pub use camera::Camera;
pub use drawing::Drawing;
pub use error::EvalError;
pub use hierarchy::Hierarchy;
pub use request::{BuildRequest, Downstream};
pub use scene::{Instance, Scene};

use crate::core::{Diagnostic, LimitExceeded, ParseError};
use crate::Language;

/// What a front end made of one source. The stages read only this: they
/// never look at the source or ask which language it was, except to name it.
#[derive(Debug)]
pub struct Model {
    /// The language the source was read as.
    pub language: Language,
    /// The flat geometry (empty, but for the background, when the model is a [`Model::hierarchy`]).
    pub scene: Scene,
    /// The instancing hierarchy, when the language built one instead of a
    /// flat scene (context-free L-systems and shareable MDG grammars, when
    /// the request can use it; the scene then keeps only the background).
    pub hierarchy: Option<Hierarchy>,
    /// The flat 2D drawing, for a language that draws one (Context Free):
    /// what `format=svg` writes and `format=png` rasterises instead of a
    /// preview of the scene. `None` for the 3D languages, which the `svg`
    /// format then refuses.
    pub drawing: Option<Drawing>,
    /// Primitives as the language counts them (instances, segments, objects).
    pub primitives: u64,
    /// Parser and evaluator warnings.
    pub warnings: Vec<Diagnostic>,
    /// Memory the front end reserved on behalf of later stages (see
    /// [`Downstream`]); the pipeline releases it before meshing reserves the real buffers.
    pub promised: u64,
    /// The seed the model was made with: the request's, else the grammar's
    /// own seed directive, else 0. Sent back as the request's seed it makes
    /// the same model, which is why outputs record it (their provenance).
    pub seed: u64,
}

impl Model {
    /// Records `e` as the reason the model is partial (the first reason wins).
    pub fn truncate(&mut self, e: LimitExceeded) {
        match &mut self.hierarchy {
            Some(h) => h.truncated.get_or_insert(e),
            None => self.scene.truncated.get_or_insert(e),
        };
    }
}

/// Why a front end could not make a model.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BuildError {
    /// The source does not parse.
    #[error(transparent)]
    Parse(#[from] ParseError),
    /// Evaluation failed (a limit, a bad parameter, a script error, …).
    #[error(transparent)]
    Eval(#[from] EvalError),
}

impl From<LimitExceeded> for BuildError {
    fn from(e: LimitExceeded) -> Self {
        BuildError::Eval(EvalError::Limit(e))
    }
}
