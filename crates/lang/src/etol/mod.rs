//! The ETOL token stream (Haglund 2009, Appendix A): [`syntax`] translates
//! it into an L-system, which [`crate::lsystem`] builds; diagnostics are
//! mapped back onto the tokens.

pub mod syntax;

use crate::core::budget::Budget;
use crate::core::timing::StageClock;
use crate::ir::ParamDecl;
use crate::model::{BuildError, BuildRequest, Model};
use crate::{Diagnostic, FrontEnd, Language, ParseError};

/// The front end of `language: "etol"`.
pub struct Etol;

impl FrontEnd for Etol {
    fn name(&self) -> &'static str {
        "etol"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["etol"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        let t = syntax::translate(source)?;
        let mut warnings = crate::lsystem::syntax::parse(t.source.as_bytes()).map_err(|e| t.map_error(e))?.warnings;
        t.map_warnings(&mut warnings);
        Ok(warnings)
    }
    /// ETOL streams declare no parameters (the stream is checked all the same).
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        self.check(source).map(|_| Vec::new())
    }
    /// An L-system's colour is part of each mesh it instances.
    fn colours_per_instance(&self) -> bool {
        false
    }
    /// The hierarchy's segments are capped cylinders; the turtle sweeps mitred tubes.
    fn own_hierarchy_geometry(&self) -> bool {
        true
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        build_etol_model(source, req, budget, clock)
    }
}

/// Builds the model of an ETOL token stream (Haglund 2009, Appendix A): the
/// stream is translated into an L-system, built by [`crate::lsystem::build_model`], and
/// diagnostics are mapped back into the token stream.
pub(crate) fn build_etol_model(source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let t = syntax::translate(source)?;
    match crate::lsystem::build_model(t.source.as_bytes(), req, budget, clock) {
        Ok(mut model) => {
            model.language = Language::Etol;
            t.map_warnings(&mut model.warnings);
            Ok(model)
        }
        Err(BuildError::Parse(e)) => Err(BuildError::Parse(t.map_error(e))),
        Err(e) => Err(e),
    }
}

