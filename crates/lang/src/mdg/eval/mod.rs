//! The MDG evaluator, which also runs stacking strings and UniGrafix (they
//! lower into the same rule IR): binds request parameters to a program's
//! `@param`s and expands the IR depth-first into a [`Scene`](crate::model::Scene).
//! [`build_model`] is what their front ends ([`crate::mdg::Mdg`],
//! [`crate::stack::Stack`], [`crate::ug::Ug`]) call once they have parsed.

mod adjust;
pub mod evaluator;
mod lines;
mod machine;
mod memo;
pub mod params;
mod paths;
mod select;
mod setup;
mod shapes;
mod share;

pub use evaluator::{evaluate, evaluate_hierarchy, EvalOptions};
pub(crate) use evaluator::promised_bytes;
pub use params::bind_params;
pub use setup::SetupMemo;

use crate::core::budget::Budget;
use crate::core::timing::{Phase, StageClock};
use crate::ir::Program;
use crate::Language;
use crate::core::budget::OnLimit;
use crate::model::scene::Scene;
use crate::model::{BuildError, BuildRequest, EvalError, Hierarchy, Model};

/// Binds the request's parameters to `program` (parsed from MDG, a
/// stacking string or UniGrafix: `language` says which) and evaluates it
/// into a model under `budget`.
///
/// Where the output writes a hierarchy as it is (`format=scene`) or
/// instances it (GPU-instanced glTF), a program whose derivation can be
/// memoised is built as an object [`Hierarchy`](crate::model::Hierarchy)
/// ([`evaluate_hierarchy`], docs/mdg.md); every other output, and every other
/// program, gets the flat derivation, exactly as before hierarchies existed.
pub fn build_model(language: Language, program: &Program, req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    build_model_kept(language, program, None, req, budget, clock)
}

/// [`build_model`] with `memo`, the set-up kept beside a parsed program
/// between its evaluations (module `setup`): MDG passes its parse cache's.
pub fn build_model_kept(language: Language, program: &Program, memo: Option<&SetupMemo>, req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let params = bind_params(program, req.params)?;
    clock.lap(Phase::Parse);
    let options = EvalOptions { seed: req.seed, detail: req.detail, on_limit: req.on_limit, downstream: req.downstream };
    // The evaluator's own rule (evaluator.rs): the request's seed, else `randseed`, else 0.
    let seed = req.seed.or(program.directives.randseed).unwrap_or(0);
    let ev = machine::Evaluator::new(program, &params, &options, memo)?;
    if let Some(h) = hierarchy(&ev, req, budget)? {
        return Ok(Model { language, seed, primitives: h.leaves(), promised: 0, scene: Scene { background: evaluator::background(program), ..Scene::default() }, hierarchy: Some(h), drawing: None, warnings: program.warnings.clone() });
    }
    let scene = evaluator::scene_of(&ev, &options, budget)?;
    Ok(Model {
        language,
        seed,
        primitives: scene.instances.len() as u64,
        promised: promised_bytes(&scene, &options),
        scene,
        hierarchy: None,
        drawing: None,
        warnings: program.warnings.clone(),
    })
}

/// The program's hierarchy when the request asks for one and the program
/// shares something, charged for what building it makes (the pipeline
/// charges its size or expansion as the route writes it). Under `truncate`
/// a hierarchy that does not fit is given up (its charges refunded) for the
/// flat derivation, which stops at the limit.
fn hierarchy(ev: &machine::Evaluator<'_>, req: &BuildRequest<'_>, budget: &mut Budget) -> Result<Option<Hierarchy>, BuildError> {
    if !req.hierarchy {
        return Ok(None);
    }
    let mark = budget.mark();
    match evaluator::hierarchy_of(ev, budget) {
        Ok(h) => Ok(h),
        Err(EvalError::Limit(_)) if req.on_limit == OnLimit::Truncate => {
            budget.rewind(mark);
            Ok(None)
        }
        Err(e) => Err(e.into()),
    }
}
