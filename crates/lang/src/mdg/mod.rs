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

/// A parsed MDG program and the evaluation set-up kept beside it.
struct Parsed {
    program: Program,
    setup: eval::SetupMemo,
}

/// MDG programs parsed in this process, by source (`parse_cache`): a
/// library grammar is parsed once, not once per render, and its constant
/// adjustments are evaluated once per parameter values (`eval::SetupMemo`).
static PARSED: LazyLock<ParseCache<Parsed>> = LazyLock::new(ParseCache::default);

/// `source` parsed, from [`PARSED`] when it was parsed before.
fn parsed(source: &[u8]) -> Result<Arc<Parsed>, ParseError> {
    PARSED.get_or_parse(source, |s| parse(s).map(|program| Parsed { program, setup: eval::SetupMemo::default() }))
}

impl FrontEnd for Mdg {
    fn name(&self) -> &'static str {
        "mdg"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["mdg"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        parsed(source).map(|p| p.program.warnings.clone())
    }
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        parsed(source).map(|p| p.program.params.clone())
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        let parsed = parsed(source)?;
        eval::build_model_kept(Language::Mdg, &parsed.program, Some(&parsed.setup), req, budget, clock)
    }
}
