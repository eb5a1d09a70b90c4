//! The one orchestrator: a request goes source → front end → [`Model`] →
//! stages (print, meshing, preview) → export → bytes, under one [`Budget`] made here.
//!
//! This is the one entry point the CLI and the service share, so the same
//! request gives the same bytes whichever front door it came through. Front
//! ends (rulemesh-lang's [`FrontEnd`](crate::lang::FrontEnd)s, one per
//! language) only make models; they never call back here.
//!
//! Deadlines: under `on_limit: error` every stage fails with the deadline
//! once it has passed. Under `truncate` the stages get shares of it — the
//! front end stops at [`EVAL_SHARE`] of the deadline, meshing after
//! [`MESH_SHARE`] of what is left — so that what is cut short is still
//! meshed and written before the deadline (writing takes one to two times
//! as long as meshing the same triangles, and cannot be cut).

use crate::core::budget::{Budget, LimitExceeded, Limits, OnLimit};
use crate::core::timing::{Phase, StageClock};
use crate::core::{Diagnostic, ParamValue, ParseError};
use crate::export::{self, ExportError, ExportMeta, ExportOptions, Format, OptionGroup, Provenance};
use crate::geom;
use crate::lang::{self, Language};
use crate::mesh::MeshLayout;
use crate::model::{BuildError, BuildRequest, Downstream, EvalError, Model};
use crate::print::PrintError;
use std::collections::BTreeMap;
use std::time::Duration;

pub mod key;
pub mod options;
mod feed;
mod route;
mod stages;

use route::Route;

pub use options::{InvalidOptions, LimitsOptions, RenderOptions};

pub use crate::core::timing::PhaseTimes;

/// Under `on_limit: truncate`, the share of the deadline the front end may
/// use: what it made by then is kept.
pub(crate) const EVAL_SHARE: f64 = 0.5;

/// Under `on_limit: truncate`, the share of the time left after the front
/// end that meshing may use (keeping the meshes made by then); the rest is
/// for export, which cannot be cut short without losing the whole model.
/// Writing the glb of what meshing made takes about 1.1× meshing's time on
/// an idle machine and more than 2× when other processes share the memory
/// bandwidth (a third, the share before, then left too little and the
/// answer was an empty model), so export gets four times meshing's share.
pub(crate) const MESH_SHARE: f64 = 0.2;

/// Everything that determines a render besides the source text.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderRequest {
    /// The language; detected from the source when `None`.
    pub language: Option<Language>,
    /// The seed; when `None`, the language's own seed directive (MDG
    /// `randseed`, L-system `seed:`, EisenScript `set seed`), else 0.
    pub seed: Option<u64>,
    /// Values for the grammar's `@param`s.
    pub params: BTreeMap<String, ParamValue>,
    /// Output format.
    pub format: Format,
    /// Limits, already clamped to the caller's ceiling.
    pub limits: Limits,
    /// Fail or truncate at a limit.
    pub on_limit: OnLimit,
    /// Tessellation detail (MIN_DETAIL..=MAX_DETAIL).
    pub detail: u32,
    /// One merged mesh or one per primitive kind.
    pub layout: MeshLayout,
    /// Encoding options of the output format (e.g. strips precision); they
    /// reach the stages after the model only.
    pub export_options: ExportOptions,
    /// The directory a Structure Synth JavaScript script's `Builder.load`
    /// reads from (the CLI passes the script's folder). `None` — the service —
    /// reads no files: only built-in library grammars load.
    pub script_dir: Option<std::path::PathBuf>,
    /// One picture of a Structure Synth JavaScript movie (0-based: the k-th
    /// picture-saving call), built alone as Structure Synth renders each
    /// picture; `None` builds the whole movie as one animated model. Other
    /// sources refuse it.
    pub frame: Option<u32>,
    /// Named files sent with the source (a vlab object's `.v`, `.a`, `.map`
    /// and `#include`d files): front ends resolve names against these only.
    /// Their bytes count against the source-size limit.
    pub files: BTreeMap<String, Vec<u8>>,
}

impl Default for RenderRequest {
    fn default() -> Self {
        RenderRequest {
            language: None,
            seed: None,
            params: BTreeMap::new(),
            format: Format::default(),
            limits: Limits::default(),
            on_limit: OnLimit::Error,
            detail: geom::DEFAULT_DETAIL,
            layout: MeshLayout::Merged,
            export_options: ExportOptions::default(),
            script_dir: None,
            frame: None,
            files: BTreeMap::new(),
        }
    }
}

/// A finished render.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOutput {
    /// The model in the requested format.
    pub bytes: Vec<u8>,
    /// The language the source was read as.
    pub language: Language,
    /// The seed the model was made with (the request's, else the grammar's
    /// own seed directive, else 0): sent back as the request's seed, it
    /// makes the same model, so the service reports it with every model.
    pub seed: u64,
    /// Primitive instances in the model.
    pub primitives: u64,
    /// Triangles in the model.
    pub triangles: u64,
    /// Set when a limit cut the model short (only with `on_limit = truncate`).
    pub truncated: Option<LimitExceeded>,
    /// The print stage's headline figures, for a printed model (STL or 3MF):
    /// measured once here and kept beside the bytes by every cache tier.
    pub print: Option<crate::print::PrintSummary>,
    /// Parser warnings.
    pub warnings: Vec<Diagnostic>,
    /// Wall-clock time of the whole pipeline.
    pub elapsed: Duration,
    /// Wall-clock time of each stage, for benchmarks and logs.
    pub phases: PhaseTimes,
}

/// Why a render failed.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The request itself is malformed (bad detail, undetectable language,
    /// a format the language cannot make).
    #[error("{0}")]
    BadRequest(String),
    /// The source does not parse.
    #[error(transparent)]
    Parse(#[from] ParseError),
    /// A limit ran out.
    #[error(transparent)]
    Limit(LimitExceeded),
    /// Evaluation failed for a reason in the source or parameters.
    #[error(transparent)]
    Eval(EvalError),
    /// `print=true` was asked of a model that cannot be printed as asked
    /// (nothing closed to print, a size out of range): the request's fault.
    #[error("print: {0}")]
    Unprintable(PrintError),
    /// The model is larger than the output format can hold (glTF's 4 GiB buffers).
    #[error("model too large for {format}: {detail}")]
    TooLarge {
        /// The format's name.
        format: &'static str,
        /// What overflowed.
        detail: String,
    },
    /// The print stage failed inside the server (not the request's fault:
    /// see [`RenderError::Unprintable`]).
    #[error("print: {0}")]
    Print(PrintError),
    /// Writing the output failed inside the server.
    #[error(transparent)]
    Export(ExportError),
}

impl From<EvalError> for RenderError {
    fn from(e: EvalError) -> Self {
        match e {
            EvalError::Limit(l) => RenderError::Limit(l),
            other => RenderError::Eval(other),
        }
    }
}

impl From<BuildError> for RenderError {
    fn from(e: BuildError) -> Self {
        match e {
            BuildError::Parse(p) => RenderError::Parse(p),
            BuildError::Eval(e) => e.into(),
        }
    }
}

impl From<LimitExceeded> for RenderError {
    fn from(e: LimitExceeded) -> Self {
        RenderError::Limit(e)
    }
}

impl From<ExportError> for RenderError {
    fn from(e: ExportError) -> Self {
        match e {
            ExportError::Limit(l) => RenderError::Limit(l),
            ExportError::TooLarge { format, detail } => RenderError::TooLarge { format, detail },
            other => RenderError::Export(other),
        }
    }
}

impl From<PrintError> for RenderError {
    fn from(e: PrintError) -> Self {
        match e {
            PrintError::Limit(l) => RenderError::Limit(l),
            // The model has nothing closed to print, or an option is off: the request's fault.
            e @ (PrintError::NothingPrintable(_) | PrintError::SeparatePieces { .. }) => RenderError::Unprintable(e),
            e if e.is_bad_option() => RenderError::Unprintable(e),
            other => RenderError::Print(other),
        }
    }
}

/// The language of `source`: the one named, else the detected one.
fn language_of(source: &[u8], language: Option<Language>) -> Result<Language, RenderError> {
    language
        .or_else(|| Language::detect(source))
        // A property of the source, not of the request's shape: reported as
        // a parse error at its start, so that a client (and the OpenAPI
        // document's contract) can tell it from a malformed request.
        .ok_or_else(|| RenderError::Parse(crate::core::ParseError::single(crate::core::Span::new(1, 1), "cannot detect the language of the source; name it explicitly")))
}

/// The parameters `source` declares (MDG `@param`, EisenScript GUI
/// defines; L-systems and ETOL declare none), for parameter schemas: read
/// from the parsed source without evaluating it.
pub fn declared_params(source: &[u8], language: Option<Language>, limits: &Limits) -> Result<(Language, Vec<lang::ir::ParamDecl>), RenderError> {
    Budget::check_source(limits, source.len() as u64)?;
    let language = language_of(source, language)?;
    Ok((language, language.front_end().declared_params(source)?))
}

/// Parses `source` only to report its diagnostics: the language read and its warnings.
pub fn check_source(source: &[u8], language: Option<Language>, limits: &Limits) -> Result<(Language, Vec<Diagnostic>), RenderError> {
    check_source_with(source, &BTreeMap::new(), language, limits)
}

/// [`check_source`] with named files beside the source (a cpfg model's
/// view and `#include`s, as [`RenderRequest::files`] carries them); the
/// files count against the source-size limit with the source, as in a render.
pub fn check_source_with(source: &[u8], files: &BTreeMap<String, Vec<u8>>, language: Option<Language>, limits: &Limits) -> Result<(Language, Vec<Diagnostic>), RenderError> {
    let bytes = files.values().fold(source.len() as u64, |n, f| n.saturating_add(f.len() as u64));
    Budget::check_source(limits, bytes)?;
    let language = language_of(source, language)?;
    Ok((language, language.front_end().check_with(source, files)?))
}

/// Rejects a request whose options are out of range before any work: the
/// one check of a request's options, which [`render`] runs and the service
/// runs too when it plans a request (so a batch is refused whole, before
/// any member renders).
pub(crate) fn check_request(req: &RenderRequest) -> Result<(), RenderError> {
    if !(geom::MIN_DETAIL..=geom::MAX_DETAIL).contains(&req.detail) {
        return Err(RenderError::BadRequest(format!("detail must be in {}..={}, got {}", geom::MIN_DETAIL, geom::MAX_DETAIL, req.detail)));
    }
    let group = req.format.info().options;
    if req.export_options.checksum && group != OptionGroup::Scene {
        // A request built in Rust, past the validator: the same refusal.
        return Err(RenderError::BadRequest(format!("checksum needs format=scene, not format={}", req.format.name())));
    }
    match group {
        OptionGroup::Strips => req.export_options.strips.validate().map_err(RenderError::BadRequest),
        OptionGroup::Preview => req.export_options.preview.validate().map_err(RenderError::BadRequest),
        OptionGroup::Gltf | OptionGroup::Scene | OptionGroup::None => Ok(()),
    }
}

/// Bytes the mesh buffers and the encoded output need per vertex and per
/// triangle (both are linear in the counts beyond a fixed `overhead`), and
/// per instance when the output instances repeated meshes: instanced glTF,
/// and `scene`, which writes every placement as a record and tessellates
/// nothing, so its placements are charged as instances too (issue 15:
/// "budgets count what is made").
fn downstream(req: &RenderRequest, route: &Route, overhead: u64) -> Downstream {
    let est = |v, t| export::estimated_size(req.format, v, t).saturating_sub(overhead);
    // Streamed strips build no mesh: only the output is promised.
    let mesh_bytes = |v, t| if route.streamed() { 0 } else { geom::mesh::mesh_bytes(v, t) };
    // Placements written as instances, each at the format's bound.
    let per_instance = route.writes_instances().then_some(req.format.info().size.per_instance);
    Downstream {
        per_vertex: mesh_bytes(1, 0).saturating_add(est(1, 0)),
        per_triangle: mesh_bytes(0, 1).saturating_add(est(0, 1)),
        per_instance,
    }
}

/// Calls the front end of `language`.
fn build_model(language: Language, source: &[u8], req: &BuildRequest<'_>, budget: &mut Budget, clock: &mut StageClock) -> Result<Model, BuildError> {
    let front_end = language.front_end();
    if req.frame.is_some() && !front_end.plays_frames(source) {
        let message = format!("`frame` picks one picture of a Structure Synth JavaScript movie (a `#javascript` script); this source is {}, not a movie", language.name());
        return Err(EvalError::Frame { message }.into());
    }
    front_end.build_model(source, req, budget, clock)
}

/// The share of the whole deadline at which meshing stops under `truncate`:
/// now plus [`MESH_SHARE`] of the time left.
fn mesh_share(budget: &Budget) -> f64 {
    let timeout = budget.limits().timeout_ms as f64;
    if timeout <= 0.0 {
        return 0.0;
    }
    let now = (budget.elapsed().as_secs_f64() * 1000.0 / timeout).min(1.0);
    now + (1.0 - now) * MESH_SHARE
}

/// Under `truncate`, records `e` as the reason the model is partial; under `error`, fails with it.
fn truncate_or_fail(on_limit: OnLimit, e: LimitExceeded, model: &mut Model) -> Result<(), RenderError> {
    match on_limit {
        OnLimit::Error => Err(RenderError::Limit(e)),
        OnLimit::Truncate => {
            model.truncate(e);
            Ok(())
        }
    }
}

/// The budget of one request: the only place one is made (outside tests),
/// so every stage of a request charges the same counters and one clock.
fn budget_for(limits: Limits) -> Budget {
    Budget::new(limits)
}

/// Writes meshes that come from outside a render (the CLI's `decode` of a
/// strips file) in `format`, under a budget of `limits`, with default
/// format options and no metadata: through the format's flat sink, as a
/// render's meshes are written, or for a picture format (`png`) through
/// the preview stage, run here, then the format's encoder.
pub fn write_meshes(format: Format, meshes: Vec<geom::NamedMesh>, limits: &Limits) -> Result<Vec<u8>, RenderError> {
    let mut budget = budget_for(*limits);
    // Writing a large model takes a share of the deadline; a late one is not started.
    budget.check_deadline()?;
    let (meta, options) = (ExportMeta::default(), ExportOptions::default());
    if let export::Writer::Picture(encode) = format.info().writer {
        let image = crate::preview::render(&meshes, &options.preview, &mut budget).map_err(ExportError::from)?;
        return Ok(encode(&image, None, &mut budget)?);
    }
    Ok(feed::meshes(meshes, export::flat_sink(format, &options)?, &meta, &mut budget)?)
}

/// Encodes an RGBA picture made outside a render (the CLI's `gallery`
/// contact sheet) as PNG, under a budget of `limits`, so even that image is
/// charged through the one budget constructor.
pub fn write_picture(width: u32, height: u32, rgba: &[u8], text: &export::png::TextChunks, limits: &Limits) -> Result<Vec<u8>, RenderError> {
    Ok(export::png::write_rgba(width, height, rgba, text, &mut budget_for(*limits))?)
}

/// Renders `source` as the request says. Never panics on bad input; every
/// failure is a typed [`RenderError`].
pub fn render(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    check_request(req)?;
    let files_len: u64 = req.files.values().map(|f| f.len() as u64).sum();
    Budget::check_source(&req.limits, (source.len() as u64).saturating_add(files_len))?;
    let language = language_of(source, req.language)?;
    let route = Route::of(req);
    if matches!(route, Route::Drawing(_)) && !language.front_end().draws() {
        // Refused before anything is evaluated: the language makes no drawing.
        return Err(stages::no_drawing(req.format, language).into());
    }
    let truncating = req.on_limit == OnLimit::Truncate;
    let mut budget = budget_for(req.limits);
    let mut clock = StageClock::start();
    // Promise the memory that meshing and export will need while evaluating,
    // so the memory limit binds (or truncates) as primitives are made.
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let own = language.front_end().own_hierarchy_geometry();
    let mut build = BuildRequest {
        seed: req.seed,
        params: &req.params,
        detail: req.detail,
        on_limit: req.on_limit,
        downstream: downstream(req, &route, overhead),
        hierarchy: route.wants_hierarchy(own),
        animated: route.animated(),
        script_dir: req.script_dir.as_deref(),
        frame: req.frame,
        files: &req.files,
        // A picture's side, for languages that evaluate in pixels (Context Free).
        canvas: route.canvas(req),
        picture_only: route.picture_only(),
        print: req.export_options.print.enabled,
    };
    budget.set_stage_share(truncating.then_some(EVAL_SHARE));
    crate::core::memprobe::mark("start", &budget);
    let start = budget.mark();
    let mut model = build_model(language, source, &build, &mut budget, &mut clock)?;
    // A hierarchy is charged as the route writes it; one over a limit under
    // `truncate`, or one the route does not keep, is given up (its charges
    // refunded, the clock running on) for the flat model, which stops at the limit.
    let keep = match &model.hierarchy {
        None => true,
        Some(h) => match route.charge_hierarchy(h, req.detail, &budget) {
            Ok(()) => route.keeps_hierarchy(h, req.detail, own),
            Err(_) if truncating => false,
            Err(e) => return Err(e.into()),
        },
    };
    if !keep {
        drop(model);
        budget.rewind(start);
        build.hierarchy = false;
        model = build_model(language, source, &build, &mut budget, &mut clock)?;
    }
    clock.lap(Phase::Eval);
    crate::core::memprobe::mark("eval", &budget);
    budget.check_deadline().or_else(|e| truncate_or_fail(req.on_limit, e, &mut model))?;
    budget.release_memory(model.promised.saturating_add(overhead));
    budget.set_stage_share(truncating.then(|| mesh_share(&budget)));
    // Parameters in one spelling (text `0.5` from the CLI is the number 0.5
    // from a JSON body), so the recorded parameters and key match across doors.
    let params: BTreeMap<String, ParamValue> = req.params.iter().map(|(k, v)| (k.clone(), v.canonical())).collect();
    let model_key = key::model_key(&key::normalize_source(source), req, &params).hex();
    let provenance = Provenance { language: model.language, seed: model.seed, params, model_key };
    let out = stages::run(route, model, provenance, req, &mut budget, &mut clock);
    budget.set_stage_share(None);
    let out = out?;
    // Writing is not interruptible: under `error` a model finished after the
    // deadline still fails with it (under `truncate` it is whole, and kept).
    if req.on_limit == OnLimit::Error {
        budget.check_deadline()?;
    }
    crate::core::memprobe::mark("export", &budget);
    Ok(RenderOutput { elapsed: budget.elapsed(), phases: clock.phases, ..out })
}
