//! The front end of `language: "cpfg"`: L-systems written for cpfg, the
//! L-system program of L-studio and vlab (Prusinkiewicz's group at the
//! University of Calgary; `AlgorithmicBotany/vlab`, folder `cpfg/`, and its
//! manual `docs/CPFGManual.pdf`, 2022), as published with *The Algorithmic
//! Beauty of Plants* and the vlab course. See `docs/cpfg.md`.
//!
//! source (+ the request's `files`) → preprocessor and parser ([`syntax`])
//! → derivation with `{ }` blocks, decomposition and homomorphism
//! ([`derive`], [`eval`]) → cpfg's turtle read onto the L-system turtle
//! ([`lower`], `crate::lsystem::turtle`) with the view file's settings
//! ([`view`]) → [`Model`]. A hierarchy, where the request wants one, is the
//! L-system front end's instancing of the drawn string
//! (`crate::lsystem::dag::from_string`, `crate::lsystem::instance`).
//!
//! Limits: every module rewritten, every statement and loop iteration of a
//! block and every module the turtle reads is a step; strings are charged
//! to memory before they grow; every segment and sphere is a primitive.

pub mod companions;
pub mod derive;
pub mod eval;
pub(crate) mod func;
pub mod lower;
pub mod string;
pub mod syntax;
pub mod view;

use crate::core::budget::{Budget, OnLimit};
use crate::core::timing::{Phase, StageClock};
use crate::core::PrimitiveKind;
use crate::geom::{primitives, sweep};
use crate::ir::ParamDecl;
use crate::lsystem::turtle;
use crate::model::{BuildError, BuildRequest, EvalError, Model};
use crate::{Diagnostic, FrontEnd, Language, ParseError, Span};
use std::collections::BTreeMap;

/// The files of a request with extension `ext`, in name order.
fn with_ext<'a>(files: &'a BTreeMap<String, Vec<u8>>, ext: &str) -> Vec<(&'a String, &'a Vec<u8>)> {
    files.iter().filter(|(n, _)| n.rsplit('.').next().is_some_and(|e| e.eq_ignore_ascii_case(ext)) && n.contains('.')).collect()
}

/// The view of a request: its `.v`, `.a` and `.map` files (the first of
/// each in name order; the CLI sends the main file's own), with warnings.
pub(crate) fn read_view(files: &BTreeMap<String, Vec<u8>>, warnings: &mut Vec<Diagnostic>) -> view::View {
    let mut v = view::View::default();
    let pick = |ext: &str, warnings: &mut Vec<Diagnostic>| {
        let all = with_ext(files, ext);
        if all.len() > 1 {
            warnings.push(Diagnostic::warning(Span::new(1, 1), format!("several .{ext} files were sent; {} is used", all[0].0)));
        }
        all.first().map(|(_, b)| b.as_slice())
    };
    if let Some(b) = pick("v", warnings) {
        v.read(&String::from_utf8_lossy(b), &|name| files.get(name).map(|f| String::from_utf8_lossy(f).into_owned()));
    }
    if let Some(b) = pick("a", warnings) {
        v.read_animation(&String::from_utf8_lossy(b));
    }
    if let Some(b) = pick("map", warnings) {
        v.read_map(b);
    }
    for m in &v.unreadable {
        warnings.push(Diagnostic::warning(Span::new(1, 1), format!("cannot read {m}; func() of it gives 0")));
    }
    for m in &v.missing {
        warnings.push(Diagnostic::warning(Span::new(1, 1), format!("the view names {m}, which was not sent; what it defines is not drawn")));
    }
    v
}

/// The macros cpfg predefines for a function gallery's names (`-DNAME=id`,
/// `cpfg/generate.c`, `PreprocessLsystem`).
pub(crate) fn predefined(view: &view::View) -> Vec<(String, String)> {
    if !view.gallery {
        return Vec::new();
    }
    view.functions.iter().enumerate().filter(|(_, f)| !f.name.is_empty()).map(|(i, f)| (f.name.clone(), (i + 1).to_string())).collect()
}

/// One warning per `func` id that no function of the request's files
/// answered, at its first call (`Machine::missing_funcs`).
fn missing_function_warnings(machine: &eval::Machine) -> Vec<Diagnostic> {
    machine
        .missing_funcs
        .iter()
        .map(|(id, span)| Diagnostic::warning(*span, format!("func({id}, …) has no function: none of the files sent (a .fset or .func) defines function {id}, so it gives 0, as cpfg's does")))
        .collect()
}

/// The number of derivation steps: the L-system's `derivation length:`,
/// else the animation file's `last frame:`, else 0.
pub fn steps(sys: &syntax::Cpfg, view: &view::View) -> u32 {
    sys.derivation_length.or(view.last_frame).unwrap_or(0)
}

/// Builds the model of cpfg `source` (with the request's files) under `budget`.
pub fn build_model(source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let mut warnings = Vec::new();
    let mut view = read_view(req.files, &mut warnings);
    let mut sys = syntax::parse_with(source, req.files, &predefined(&view))?;
    sys.warnings.extend(warnings);
    if let Some(name) = req.params.keys().next() {
        return Err(EvalError::UnknownParam { name: name.clone(), declared: String::new() }.into());
    }
    clock.lap(Phase::Parse);
    let mut d = derive::Deriver::new(&sys, req.seed);
    d.machine.funcs = std::mem::take(&mut view.functions);
    let derived = d.derive(steps(&sys, &view), Some(&view), req.on_limit, budget)?;
    let drawn = d.homomorphism(&derived.string, budget)?;
    budget.release_memory(derived.string.bytes());
    sys.warnings.extend(missing_function_warnings(&d.machine));
    let lowered = lower::lower(&drawn, &view, budget)?;
    budget.release_memory(drawn.bytes());
    let shell = lower::shell(&view);
    let seed = req.seed.or(sys.seed.map(|s| s as u64)).unwrap_or(0);
    let wants = req.hierarchy && lowered.spheres.is_empty() && derived.truncated.is_none();
    if wants {
        let flat = crate::lsystem::dag::from_string(&shell, &lowered.string, budget)?;
        let h = crate::lsystem::instance::build(&shell, &flat, budget)?;
        let primitives = h.leaves();
        return Ok(Model { language: Language::Cpfg, scene: Default::default(), hierarchy: Some(h), drawing: None, primitives, warnings: sys.warnings, promised: 0, seed });
    }
    let cost = req.downstream;
    let opts = turtle::TurtleOptions {
        detail: req.detail,
        on_limit: req.on_limit,
        line_point_bytes: {
            let (v, t) = sweep::per_point_bound(sweep::profile_sides(req.detail));
            cost.bytes(v, t)
        },
        downstream_bytes: PrimitiveKind::ALL.map(|k| cost.bytes(primitives::vertex_count(k, req.detail), primitives::triangle_count(k, req.detail))),
    };
    let mut drawing = turtle::interpret(&shell, &lowered.string, &opts, budget)?;
    let spheres = lowered.spheres.len() as u64;
    drawing.scene.instances.extend(lowered.spheres);
    if drawing.scene.truncated.is_none() {
        drawing.scene.truncated = derived.truncated;
    }
    if req.on_limit == OnLimit::Error {
        if let Some(l) = drawing.scene.truncated {
            return Err(EvalError::Limit(l).into());
        }
    }
    Ok(Model { language: Language::Cpfg, scene: drawing.scene, hierarchy: None, drawing: None, primitives: drawing.segments + spheres, warnings: sys.warnings, promised: drawing.promised, seed })
}

/// The front end of `language: "cpfg"`.
pub struct Cpfg;

impl FrontEnd for Cpfg {
    fn name(&self) -> &'static str {
        "cpfg"
    }
    fn extensions(&self) -> &'static [&'static str] {
        &["l"]
    }
    fn check(&self, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
        syntax::parse(source).map(|s| s.warnings)
    }
    /// Parses as a render does: the view's warnings, then the source's,
    /// with `#include` and the view's function names read from `files`.
    fn check_with(&self, source: &[u8], files: &BTreeMap<String, Vec<u8>>) -> Result<Vec<Diagnostic>, ParseError> {
        let mut warnings = Vec::new();
        let view = read_view(files, &mut warnings);
        let sys = syntax::parse_with(source, files, &predefined(&view))?;
        warnings.extend(sys.warnings);
        Ok(warnings)
    }
    /// cpfg models declare no request parameters (the source is checked all the same).
    fn declared_params(&self, source: &[u8]) -> Result<Vec<ParamDecl>, ParseError> {
        syntax::parse(source).map(|_| Vec::new())
    }
    /// A cpfg model's colour is part of each mesh it instances, as an L-system's.
    fn colours_per_instance(&self) -> bool {
        false
    }
    /// Its hierarchy is the L-systems' (capped segments; the turtle sweeps tubes).
    fn own_hierarchy_geometry(&self) -> bool {
        true
    }
    fn build_model(&self, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
        build_model(source, req, budget, clock)
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod figures_tests;
