//! Berkeley UniGrafix, the safe subset (Séquin (ed.) 1992; `docs/modifiers.md`): the parser ([`syntax`]) lowers a file into the rule IR, which MDG's evaluator runs.

pub mod syntax;

use crate::core::budget::Budget;
use crate::core::timing::StageClock;
use crate::ir::ParamDecl;
use crate::model::{BuildError, BuildRequest, Model};
use crate::{Diagnostic, FrontEnd, Language, ParseError};

/// The front end of `language: "ug"`.
pub struct Ug;

impl FrontEnd for Ug {
    fn name(&self) -> &'static str {
        "ug"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["ug"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        syntax::parse(source).map(|p| p.warnings)
    }
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        syntax::parse(source).map(|p| p.params)
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        crate::mdg::eval::build_model(Language::Ug, &syntax::parse(source)?, req, budget, clock)
    }
}
