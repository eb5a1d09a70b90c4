//! The MDG evaluator, which also runs stacking strings and UniGrafix (they
//! lower into the same rule IR): binds request parameters to a program's
//! `@param`s and expands the IR depth-first into a [`Scene`](crate::model::Scene).
//! [`build_model`] is the front end the pipeline calls for these languages.

mod adjust;
pub mod evaluator;
mod lines;
mod machine;
pub mod params;
mod paths;
mod select;
mod shapes;

pub use evaluator::{evaluate, promised_bytes, EvalOptions};
pub use params::bind_params;

use crate::core::budget::Budget;
use crate::core::timing::{Phase, StageClock};
use crate::lang::{self, Language};
use crate::model::{BuildError, BuildRequest, Model};

/// Parses `source` as `language` (MDG, a stacking string or UniGrafix),
/// binds the request's parameters and evaluates it into a model under `budget`.
pub fn build_model(language: Language, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let program = lang::parse(language, source)?;
    let params = bind_params(&program, req.params)?;
    clock.lap(Phase::Parse);
    let options = EvalOptions { seed: req.seed, detail: req.detail, on_limit: req.on_limit, downstream: req.downstream };
    let scene = evaluate(&program, &params, &options, budget)?;
    Ok(Model {
        language,
        // The evaluator's own rule (evaluator.rs): the request's seed, else `randseed`, else 0.
        seed: req.seed.or(program.directives.randseed).unwrap_or(0),
        primitives: scene.instances.len() as u64,
        promised: promised_bytes(&scene, &options),
        scene,
        hierarchy: None,
        warnings: program.warnings,
    })
}
