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

use crate::core::budget::{Budget, Limit, LimitExceeded, Limits, OnLimit};
use crate::core::timing::{Phase, StageClock};
use crate::core::{Diagnostic, ParamValue, ParseError};
use crate::export::{self, ExportError, ExportMeta, ExportOptions, Format, Instancing, OptionGroup, Provenance, Writer};
use crate::geom;
use crate::lang::{self, Language};
use crate::mesh::{self, MeshLayout};
use crate::model::{instancing, BuildError, BuildRequest, Downstream, EvalError, HierarchyUse, Model};
use crate::print::PrintError;
use std::collections::BTreeMap;
use std::time::Duration;

pub mod key;
pub mod options;

pub use options::{InvalidOptions, LimitsOptions, RenderOptions};

pub use crate::core::timing::PhaseTimes;

/// Under `on_limit: truncate`, the share of the deadline the front end may
/// use: what it made by then is kept.
pub const EVAL_SHARE: f64 = 0.5;

/// Under `on_limit: truncate`, the share of the time left after the front
/// end that meshing may use (keeping the meshes made by then); the rest is
/// for export, which cannot be cut short without losing the whole model.
/// Writing the glb of what meshing made takes about 1.1× meshing's time on
/// an idle machine and more than 2× when other processes share the memory
/// bandwidth (a third, the share before, then left too little and the
/// answer was an empty model), so export gets four times meshing's share.
pub const MESH_SHARE: f64 = 0.2;

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
            ExportError::Print(p) => p.into(),
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
            other => RenderError::Export(ExportError::Print(other)),
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
    Budget::check_source(limits, source.len() as u64)?;
    let language = language_of(source, language)?;
    Ok((language, language.front_end().check(source)?))
}

/// Rejects a request whose options are out of range before any work: the
/// one check of a request's options, which [`render`] runs and the service
/// runs too when it plans a request (so a batch is refused whole, before
/// any member renders).
pub fn check_request(req: &RenderRequest) -> Result<(), RenderError> {
    if !(geom::MIN_DETAIL..=geom::MAX_DETAIL).contains(&req.detail) {
        return Err(RenderError::BadRequest(format!("detail must be in {}..={}, got {}", geom::MIN_DETAIL, geom::MAX_DETAIL, req.detail)));
    }
    match req.format.info().options {
        OptionGroup::Strips => req.export_options.strips.validate().map_err(RenderError::BadRequest),
        OptionGroup::Preview => req.export_options.preview.validate().map_err(RenderError::BadRequest),
        OptionGroup::Gltf | OptionGroup::None => Ok(()),
    }
}

/// True when the request's output carries a node hierarchy with animation
/// (a format with a node graph, plain, not fitted or printed: glTF);
/// everything else shows time 0.
fn graph_capable(req: &RenderRequest) -> bool {
    req.format.info().caps.node_graph && req.export_options.gltf.is_plain() && !req.export_options.fit_unit_box && !req.export_options.print.enabled
}

/// Whether the request's output can use an instancing hierarchy.
fn hierarchy_use(req: &RenderRequest) -> HierarchyUse {
    let info = req.format.info();
    match info.writer {
        // Written from the model as made (scene).
        Writer::Model(_) => HierarchyUse::Required,
        // Printing unites once per distinct subtree where there is a hierarchy.
        _ if req.export_options.print.enabled => HierarchyUse::Union,
        _ if info.caps.instancing => HierarchyUse::Preferred,
        _ if streamed(req) => HierarchyUse::Streamed,
        _ => HierarchyUse::Never,
    }
}

/// Whether the output writes each repeated mesh once with
/// `EXT_mesh_gpu_instancing` (a format that can, glTF, under `instancing:
/// gpu`, the default): plain glTF only — compact (welded, quantised,
/// meshopt), fitted and printed output is flat.
fn gpu_instancing(req: &RenderRequest) -> bool {
    let opts = &req.export_options;
    req.format.info().caps.instancing && opts.instancing == Instancing::Gpu && opts.gltf.is_plain() && !opts.fit_unit_box && !opts.print.enabled
}

/// Whether the output is written from the model a chunk at a time (no
/// merged mesh, a hierarchy walked rather than expanded): every request
/// for a streamed format (strips) but printed or unit-box-fitted ones,
/// which need the whole mesh first.
fn streamed(req: &RenderRequest) -> bool {
    req.format.info().caps.streamed && !req.export_options.print.enabled && !req.export_options.fit_unit_box
}

/// Whether instanced glTF is written as .glb (binary) rather than .gltf (text).
fn binary(format: Format) -> bool {
    !format.info().caps.text
}

/// Bytes the mesh buffers and the encoded output need per vertex and per
/// triangle (both are linear in the counts beyond a fixed `overhead`), and
/// per instance when the output instances repeated meshes: instanced glTF,
/// and `scene`, which writes every placement as a record and tessellates
/// nothing, so its placements are charged as instances too (issue 15:
/// "budgets count what is made").
fn downstream(req: &RenderRequest, overhead: u64) -> Downstream {
    let est = |v, t| export::estimated_size(req.format, v, t).saturating_sub(overhead);
    // Streamed strips build no mesh: only the output is promised.
    let mesh_bytes = |v, t| if streamed(req) { 0 } else { geom::mesh::mesh_bytes(v, t) };
    // Placements written as instances: every one from the model (scene),
    // the repeats under GPU instancing; each at the format's bound.
    let info = req.format.info();
    let instances = matches!(info.writer, Writer::Model(_)) || gpu_instancing(req);
    let per_instance = instances.then_some(info.size.per_instance);
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
/// strips file) in `format`, under a budget of `limits`.
pub fn write_meshes(format: Format, meshes: &[geom::NamedMesh], limits: &Limits) -> Result<Vec<u8>, RenderError> {
    Ok(export::export(format, meshes, &ExportMeta::default(), &mut budget_for(*limits))?)
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
    if matches!(req.format.info().writer, Writer::Drawing(_)) && !language.front_end().draws() {
        // Refused before anything is evaluated: the language makes no drawing.
        return Err(no_drawing(req.format, language).into());
    }
    let truncating = req.on_limit == OnLimit::Truncate;
    let mut budget = budget_for(req.limits);
    let mut clock = StageClock::start();
    // Promise the memory that meshing and export will need while evaluating,
    // so the memory limit binds (or truncates) as primitives are made.
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let build = BuildRequest {
        seed: req.seed,
        params: &req.params,
        detail: req.detail,
        on_limit: req.on_limit,
        downstream: downstream(req, overhead),
        hierarchy: hierarchy_use(req),
        animated: graph_capable(req),
        script_dir: req.script_dir.as_deref(),
        frame: req.frame,
        files: &req.files,
        // A picture's side, for languages that evaluate in pixels (Context Free).
        canvas: matches!(req.format.info().writer, Writer::Picture(_)).then_some(req.export_options.preview.size),
    };
    budget.set_stage_share(truncating.then_some(EVAL_SHARE));
    crate::core::memprobe::mark("start", &budget);
    let mut model = build_model(language, source, &build, &mut budget, &mut clock)?;
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
    let out = stages(model, provenance, req, &mut budget, &mut clock);
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

/// The stages every model goes through after its front end: the hierarchy
/// written as it is or expanded, then printing or meshing, then export.
fn stages(mut model: Model, provenance: Provenance, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    let opts = &req.export_options;
    if let Writer::Model(write) = req.format.info().writer {
        // Instances, hierarchy and the meshes that are not instances, as made (docs/scene-format.md).
        let h = model.hierarchy.take();
        let (bytes, triangles) = write(&model.scene, h.as_ref(), req.detail, req.layout, Some(&provenance), budget)?;
        clock.lap(Phase::Export);
        let truncated = h.as_ref().map_or(model.scene.truncated, |h| h.truncated);
        return Ok(summary(bytes, &model, triangles, truncated));
    }
    match (req.format.info().writer, model.drawing.take()) {
        // A 2D design as SVG, as cfdg -V writes it.
        (Writer::Drawing(write), Some(drawing)) => {
            let bytes = write(&drawing, Some(&provenance), budget)?;
            clock.lap(Phase::Export);
            return Ok(summary(bytes, &model, 0, model.scene.truncated));
        }
        (Writer::Drawing(_), None) => return Err(no_drawing(req.format, model.language).into()),
        // A 2D design's picture is the drawing itself, not a view of its tiles
        // (a print is a solid: its picture is the preview's).
        (Writer::Picture(encode), Some(drawing)) if !opts.print.enabled => {
            let image = crate::preview::drawing::render(&drawing, &opts.preview, budget).map_err(ExportError::from)?;
            clock.lap(Phase::Preview);
            let bytes = encode(&image, Some(&provenance), budget)?;
            clock.lap(Phase::Export);
            return Ok(summary(bytes, &model, 0, model.scene.truncated));
        }
        _ => {}
    }
    if streamed(req) {
        return strips_from_model(model, provenance, req, budget, clock);
    }
    // A print of a hierarchy unites once per distinct subtree, or (a leaf
    // that is no solid, a union with bad edges) expands it for the flat route.
    let mut printed = None;
    if let Some(h) = model.hierarchy.take_if(|_| opts.print.enabled) {
        printed = crate::print::make_printable_hierarchy(&h, req.detail, &opts.print, budget)?;
        match printed {
            Some(_) => model.scene.truncated = h.truncated,
            None => model.hierarchy = Some(h),
        }
    }
    if let Some(h) = model.hierarchy.take() {
        let bytes = match gpu_instancing(req) {
            true => {
                let meta = ExportMeta {
                    background: model.scene.background,
                    truncated: h.truncated.is_some(),
                    graph: None,
                    material_per_mesh: false,
                    camera: None,
                    provenance: Some(provenance.clone()),
                };
                // MDG's instances carry their colours, as its flat scenes' do; L-systems' meshes do.
                let per_instance_colour = model.language.front_end().colours_per_instance();
                Some(export::gltf::instanced::write_instanced(&h, req.detail, binary(req.format), &meta, per_instance_colour, budget)?)
            }
            false => None,
        };
        match bytes {
            Some(bytes) => {
                clock.lap(Phase::Export);
                return Ok(summary(bytes, &model, h.triangles(req.detail), h.truncated));
            }
            None => model.scene = h.expand(req.detail, budget)?,
        }
    }
    // Animation and camera paths play in a node graph, which is written flat.
    let graph_route = (model.scene.rig.is_some() || model.scene.camera.as_ref().is_some_and(|c| c.is_path())) && graph_capable(req);
    if gpu_instancing(req) && !graph_route {
        if let Some(out) = instanced_scene(&mut model, &provenance, req, budget, clock)? {
            return Ok(out);
        }
    }
    let scene = &model.scene;
    let print = opts.print;
    let mut print_summary = None;
    let (mut meshes, graph, cut) = if print.enabled {
        let (solid, report) = match printed {
            Some(done) => done,
            None => {
                // Printing unites closed parts, so it needs them apart (and shows time 0).
                let parts = mesh::build_parts(scene, req.detail, budget)?;
                clock.lap(Phase::Mesh);
                crate::print::make_printable(&parts, &print, budget)?
            }
        };
        clock.lap(Phase::Print);
        crate::core::memprobe::mark("print", budget);
        if print.report {
            let bytes = serde_json::to_vec_pretty(&report).map_err(|e| RenderError::Export(e.into()))?;
            clock.lap(Phase::Export);
            return Ok(summary(bytes, &model, report.triangles, scene.truncated));
        }
        print_summary = Some(report.summary());
        (solid, None, None)
    } else if graph_route {
        let (meshes, graph) = mesh::build_with_graph(scene, req.detail, req.layout, budget)?;
        if gpu_instancing(req) {
            // The front end charged repeats as instances, but a node graph
            // is written flat: its triangles meet the limit here.
            let drawn: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
            budget.check_total(Limit::Triangles, drawn)?;
        }
        (meshes, Some(graph), None)
    } else {
        let (meshes, cut) = mesh::build_meshes_until(scene, req.detail, req.layout, req.on_limit, budget)?;
        (meshes, None, cut)
    };
    if !print.enabled {
        clock.lap(Phase::Mesh);
    }
    let truncated = scene.truncated.or(cut);
    if req.format.info().caps.positions_only {
        // Before the output is allocated, so a big model's peak stays under 2× the file.
        export::keep_positions_only(&mut meshes);
    }
    budget.set_stage_share(None);
    let in_graph = graph.is_some();
    let meta = ExportMeta {
        background: scene.background,
        truncated: truncated.is_some(),
        graph,
        material_per_mesh: !scene.classes.is_empty(),
        // A camera path plays in the node graph; otherwise the camera is shown at time 0.
        camera: scene.camera.clone().filter(|c| !(c.is_path() && in_graph)),
        provenance: Some(provenance),
    };
    let drawn: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    let (bytes, triangles, truncated) = if let Writer::Picture(encode) = req.format.info().writer {
        // The preview stage, then its encoding: a picture needs no fitting or metadata.
        let image = crate::preview::render(&meshes, &opts.preview, budget).map_err(ExportError::from)?;
        clock.lap(Phase::Preview);
        (encode(&image, meta.provenance.as_ref(), budget)?, drawn, truncated)
    } else {
        let written = export::export_with(req.format, &meshes, &meta, opts, budget);
        empty_if_late(written, drawn, truncated, meta, req, budget)?
    };
    clock.lap(Phase::Export);
    Ok(RenderOutput { print: print_summary, ..summary(bytes, &model, triangles, truncated) })
}

/// The written model with its triangles and truncation, or — when writing
/// failed at the deadline under `truncate` — too late to write what was
/// made: the answer is then an empty model that says why, still (nearly)
/// within the deadline.
fn empty_if_late(
    written: Result<Vec<u8>, ExportError>,
    drawn: u64,
    truncated: Option<LimitExceeded>,
    meta: ExportMeta,
    req: &RenderRequest,
    budget: &mut Budget,
) -> Result<(Vec<u8>, u64, Option<LimitExceeded>), RenderError> {
    match written {
        Ok(bytes) => Ok((bytes, drawn, truncated)),
        Err(ExportError::Limit(e)) if e.limit == Limit::Deadline && req.on_limit == OnLimit::Truncate => {
            budget.lift_deadline();
            let meta = ExportMeta { truncated: true, graph: None, ..meta };
            Ok((export::export_with(req.format, &[], &meta, &req.export_options, budget)?, 0, truncated.or(Some(e))))
        }
        Err(e) => Err(e.into()),
    }
}

/// A flat scene as GPU-instanced glTF: every mesh placed more than once
/// written once and drawn per placement, the rest meshed plain beside it.
/// `None` when no mesh repeats (the plain writer then makes the same bytes
/// a flat request would).
fn instanced_scene(model: &mut Model, provenance: &Provenance, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<Option<RenderOutput>, RenderError> {
    let plan = instancing::Plan::new(&model.scene);
    if plan.is_empty() {
        return Ok(None);
    }
    let prototypes = export::gltf::instanced::prototypes(&plan, &model.scene, req.detail, budget)?;
    let residual = plan.residual(&mut model.scene, budget)?;
    let (meshes, cut) = mesh::build_meshes_until(&residual, req.detail, req.layout, req.on_limit, budget)?;
    budget.release_memory(instancing::residual_bytes(instancing::residual_counts(&residual)));
    drop(residual);
    clock.lap(Phase::Mesh);
    budget.set_stage_share(None);
    let truncated = model.scene.truncated.or(cut);
    let instanced = plan.meshes().iter().zip(&prototypes).map(|((_, n), p)| n.saturating_mul(p.mesh.triangle_count() as u64));
    let drawn = meshes.iter().map(|m| m.mesh.triangle_count() as u64).chain(instanced).fold(0u64, u64::saturating_add);
    let scene = &model.scene;
    let meta = ExportMeta {
        background: scene.background,
        truncated: truncated.is_some(),
        graph: None,
        material_per_mesh: !scene.classes.is_empty(),
        camera: scene.camera.clone(),
        provenance: Some(provenance.clone()),
    };
    let written = budget.check_deadline().map_err(ExportError::from).and_then(|()| {
        export::gltf::instanced::write_scene(scene, &plan, prototypes, meshes, &meta, binary(req.format), budget)
    });
    let (bytes, triangles, truncated) = empty_if_late(written, drawn, truncated, meta, req, budget)?;
    clock.lap(Phase::Export);
    Ok(Some(summary(bytes, model, triangles, truncated)))
}

/// Strips written from the model a chunk at a time (docs/strips-format.md):
/// a first pass for the bounds and palette (timed as meshing, and cut at the
/// meshing deadline under `truncate`), then the chunks, each tessellated,
/// coded and appended in turn. No merged mesh is built and a hierarchy is
/// walked, not expanded.
fn strips_from_model(mut model: Model, provenance: Provenance, req: &RenderRequest, budget: &mut Budget, clock: &mut StageClock) -> Result<RenderOutput, RenderError> {
    let h = model.hierarchy.take();
    let src = export::strips::ModelSource { scene: &model.scene, hierarchy: h.as_ref(), detail: req.detail, layout: req.layout };
    let survey = export::strips::survey_model(&src, req.on_limit, budget)?;
    clock.lap(Phase::Mesh);
    budget.set_stage_share(None);
    let truncated = h.as_ref().and_then(|h| h.truncated).or(model.scene.truncated).or(survey.cut);
    let meta = ExportMeta {
        background: model.scene.background,
        truncated: truncated.is_some(),
        graph: None,
        material_per_mesh: false,
        camera: None,
        provenance: Some(provenance),
    };
    let written = export::strips::write_strips_model(&src, &survey, &req.export_options.strips, budget);
    let (bytes, triangles, truncated) = empty_if_late(written, survey.triangles(), truncated, meta, req, budget)?;
    clock.lap(Phase::Export);
    Ok(summary(bytes, &model, triangles, truncated))
}

/// The typed refusal of a drawing format (`svg`) for a language whose
/// models have no 2D drawing: a client error naming the capability.
fn no_drawing(format: Format, language: Language) -> ExportError {
    let name = format.name();
    ExportError::InvalidOptions { format: name, detail: export::no_drawing(name, &format!("`{}` models", language.name())) }
}

/// The output of a render whose bytes are written (times are filled in by [`render`]).
fn summary(bytes: Vec<u8>, model: &Model, triangles: u64, truncated: Option<LimitExceeded>) -> RenderOutput {
    RenderOutput {
        bytes,
        language: model.language,
        seed: model.seed,
        primitives: model.primitives,
        triangles,
        truncated,
        print: None,
        warnings: model.warnings.clone(),
        elapsed: Duration::ZERO,
        phases: PhaseTimes::default(),
    }
}
