//! Model Design Grammars (Andersson 2015; `docs/mdg.md`): the parser
//! ([`syntax`], source → rule IR) and the evaluator ([`eval`], rule IR →
//! model), which also runs the stacking strings and UniGrafix that lower
//! into the same IR.

pub mod eval;
pub mod syntax;

pub use syntax::parse;

use crate::core::budget::Budget;
use crate::ir::Program;
use crate::parse_cache::ParseCache;
use std::sync::{Arc, LazyLock};
use crate::core::timing::StageClock;
use crate::ir::ParamDecl;
use crate::model::{BuildError, BuildRequest, Model};
use crate::{Diagnostic, FrontEnd, Language, ParseError};

/// MDG's front end.
pub struct Mdg;

/// MDG programs parsed in this process, by source (`parse_cache`): a
/// library grammar is parsed once, not once per render.
static PARSED: LazyLock<ParseCache<Program>> = LazyLock::new(ParseCache::default);

/// `source` parsed, from [`PARSED`] when it was parsed before.
fn parsed(source: &[u8]) -> Result<Arc<Program>, ParseError> {
    PARSED.get_or_parse(source, parse)
}

impl FrontEnd for Mdg {
    fn name(&self) -> &'static str {
        "mdg"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["mdg"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        parsed(source).map(|p| p.warnings.clone())
    }
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        parsed(source).map(|p| p.params.clone())
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        let program = parsed(source)?;
        eval::build_model(Language::Mdg, &program, req, budget, clock)
    }
}
