//! The front-end contract: what every language provides so that the
//! pipeline, the doors and the library can treat languages alike. One
//! implementation per language folder, registered once in the crate root's
//! `languages!` table.

use crate::core::budget::Budget;
use crate::core::timing::StageClock;
use crate::ir::ParamDecl;
use crate::model::{BuildError, BuildRequest, Model};
use crate::{Diagnostic, ParseError};

/// A language's front end: source bytes to diagnostics, declared
/// parameters, or the one [`Model`] the stages take.
///
/// A front end never calls back into the pipeline and never learns which
/// output is coming: the request says only whether a hierarchy is wanted
/// ([`BuildRequest::hierarchy`]) and what each primitive will cost
/// downstream, and the front end charges what it makes to the budget.
pub trait FrontEnd: Sync {
    /// The name requests and the CLI use (`"mdg"`, `"lsystem"`, …).
    fn name(&self) -> &'static str;

    /// File extensions read as this language, lower case, without the dot;
    /// the first is the one the library's grammars use.
    fn extensions(&self) -> &'static [&'static str];

    /// Parses `source` only to report its diagnostics (warnings on success).
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError>;

    /// [`check`](FrontEnd::check) with the request's named files beside the
    /// source (`BuildRequest::files`): a cpfg model's `#include`s and the
    /// function names its view predefines resolve against them, so `/check`
    /// of such a model agrees with its render. Languages that read no files
    /// ignore them.
    fn check_with(&self, source: &[u8], files: &std::collections::BTreeMap<String, Vec<u8>>) -> Result<Vec<Diagnostic>, ParseError> {
        let _ = files;
        self.check(source)
    }

    /// The parameters `source` declares (MDG `@param`, EisenScript GUI
    /// defines; empty where the language has none), read without evaluating.
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError>;

    /// Whether `source` is a movie whose frames a request may pick one of
    /// (`frame`): only Structure Synth's `#javascript` scripts are.
    fn plays_frames(&self, _source: &[u8]) -> bool {
        false
    }

    /// Whether a [`Hierarchy`](crate::model::Hierarchy) this front end builds
    /// draws the model differently from its flat geometry (an L-system's
    /// capped segments, where its turtle sweeps mitred tubes) instead of
    /// sharing the flat model's subtrees (MDG's memoised derivations, the
    /// default). It is the one thing beyond yes or no ([`BuildRequest::hierarchy`])
    /// that decides when the pipeline asks for a hierarchy, because it
    /// decides which geometry a format shows: such a language is asked only
    /// where the format instances (glTF, usdz, `scene`, so each shows one
    /// geometry whatever its options) and for printing where the union per
    /// subtree is needed (the pipeline's `print::EXACT_MAX_TRIANGLES`); a
    /// sharing language wherever a route takes a hierarchy without merging
    /// it (`scene`, instancing, streamed strips, printing). A language that
    /// builds no hierarchy ignores the question.
    fn own_hierarchy_geometry(&self) -> bool {
        false
    }

    /// Whether the models this front end makes carry a 2D
    /// [`Drawing`](crate::model::Drawing) (Context Free's designs do): the
    /// capability `drawing`, which a format written from a drawing (`svg`)
    /// needs, so a request for it is refused before a 3D model is evaluated.
    fn draws(&self) -> bool {
        false
    }

    /// Whether the leaves of a [`Hierarchy`](crate::model::Hierarchy) this
    /// front end builds take their colour per placement (MDG's, as its flat
    /// scenes do: an instanced writer then gives each placement its colour)
    /// rather than per mesh (L-systems', whose colour is part of the shape).
    fn colours_per_instance(&self) -> bool {
        true
    }

    /// Builds the model of `source` for `req` under `budget`, lapping
    /// `clock` at the parse and evaluation boundaries.
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError>;
}
