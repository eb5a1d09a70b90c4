//! Model Design Grammars (Andersson 2015; `docs/mdg.md`): the parser
//! ([`syntax`], source → rule IR) and the evaluator ([`eval`], rule IR →
//! model), which also runs the stacking strings and UniGrafix that lower
//! into the same IR.

pub mod eval;
pub mod syntax;

pub use syntax::parse;

use crate::core::budget::Budget;
use crate::core::timing::StageClock;
use crate::ir::ParamDecl;
use crate::model::{BuildError, BuildRequest, Model};
use crate::{Diagnostic, FrontEnd, Language, ParseError};

/// MDG's front end.
pub struct Mdg;

impl FrontEnd for Mdg {
    fn name(&self) -> &'static str {
        "mdg"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["mdg"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        parse(source).map(|p| p.warnings)
    }
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        parse(source).map(|p| p.params)
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        eval::build_model(Language::Mdg, parse(source)?, req, budget, clock)
    }
}
