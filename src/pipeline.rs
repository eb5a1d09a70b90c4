//! The whole render pipeline for one request: parse, bind, evaluate, mesh, export.
//!
//! This is the one entry point the CLI and the service share, so the same
//! request gives the same bytes whichever front door it came through.

use crate::eval::{self, bind_params, Budget, EvalError, EvalOptions, LimitExceeded, Limits, OnLimit, ParamValue};
use crate::export::{self, ExportError, ExportMeta, ExportOptions, Format};
use crate::geom::{self, MeshLayout};
use crate::lang::{self, Diagnostic, Language, ParseError};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

/// Everything that determines a render besides the source text.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderRequest {
    /// The language; detected from the source when `None`.
    pub language: Option<Language>,
    /// The seed; the grammar's `randseed`, else 0, when `None`.
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
    /// reach the exporter only.
    pub export_options: ExportOptions,
    /// The directory a Structure Synth JavaScript script's `Builder.load`
    /// reads from (the CLI passes the script's folder). `None` — the service —
    /// reads no files: only built-in library grammars load.
    pub script_dir: Option<std::path::PathBuf>,
}

impl Default for RenderRequest {
    fn default() -> Self {
        RenderRequest {
            language: None,
            seed: None,
            params: BTreeMap::new(),
            format: Format::Glb,
            limits: Limits::default(),
            on_limit: OnLimit::Error,
            detail: geom::DEFAULT_DETAIL,
            layout: MeshLayout::Merged,
            export_options: ExportOptions::default(),
            script_dir: None,
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
    /// Primitive instances in the model.
    pub primitives: u64,
    /// Triangles in the model.
    pub triangles: u64,
    /// Set when a limit cut the model short (only with `on_limit = truncate`).
    pub truncated: Option<LimitExceeded>,
    /// Parser warnings.
    pub warnings: Vec<Diagnostic>,
    /// Wall-clock time of the whole pipeline.
    pub elapsed: Duration,
    /// Wall-clock time of each stage, for benchmarks and logs.
    pub phases: PhaseTimes,
}

/// How long each pipeline stage took.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PhaseTimes {
    /// Parsing and parameter binding.
    pub parse: Duration,
    /// Evaluation (rule expansion) into a scene.
    pub eval: Duration,
    /// Tessellation and merging into meshes.
    pub mesh: Duration,
    /// Encoding the output bytes.
    pub export: Duration,
}

/// Why a render failed.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The request itself is malformed (bad detail, undetectable language).
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
    /// Writing the output failed.
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

impl From<LimitExceeded> for RenderError {
    fn from(e: LimitExceeded) -> Self {
        RenderError::Limit(e)
    }
}

impl From<ExportError> for RenderError {
    fn from(e: ExportError) -> Self {
        match e {
            ExportError::Limit(l) => RenderError::Limit(l),
            other => RenderError::Export(other),
        }
    }
}

/// Parses `source` as `language` (or the detected one), enforcing the source-size limit.
pub fn parse_source(source: &[u8], language: Option<Language>, limits: &Limits) -> Result<(Language, lang::ir::Program), RenderError> {
    Budget::check_source(limits, source.len() as u64)?;
    let language = match language.or_else(|| Language::detect(source)) {
        Some(l) => l,
        None => return Err(RenderError::BadRequest("cannot detect the language of the source; name it explicitly".into())),
    };
    Ok((language, lang::parse(language, source)?))
}

/// Parses `source` only to report its diagnostics: the language read and its warnings.
pub fn check_source(source: &[u8], language: Option<Language>, limits: &Limits) -> Result<(Language, Vec<Diagnostic>), RenderError> {
    Budget::check_source(limits, source.len() as u64)?;
    let language = match language.or_else(|| Language::detect(source)) {
        Some(l) => l,
        None => return Err(RenderError::BadRequest("cannot detect the language of the source; name it explicitly".into())),
    };
    Ok((language, lang::check(language, source)?))
}

/// Rejects a tessellation detail outside `MIN_DETAIL..=MAX_DETAIL`.
pub(crate) fn check_detail(req: &RenderRequest) -> Result<(), RenderError> {
    if !(geom::MIN_DETAIL..=geom::MAX_DETAIL).contains(&req.detail) {
        return Err(RenderError::BadRequest(format!(
            "detail must be in {}..={}, got {}",
            geom::MIN_DETAIL,
            geom::MAX_DETAIL,
            req.detail
        )));
    }
    Ok(())
}

/// Times the pipeline's stages: each `lap` records the time since the last one.
pub(crate) struct Stages {
    /// The times recorded so far.
    pub phases: PhaseTimes,
    mark: Instant,
}

impl Stages {
    /// Starts timing now.
    pub(crate) fn start() -> Stages {
        Stages { phases: PhaseTimes::default(), mark: Instant::now() }
    }

    /// Records the time since the last lap into the slot `which` picks.
    pub(crate) fn lap(&mut self, which: fn(&mut PhaseTimes) -> &mut Duration) {
        *which(&mut self.phases) = self.mark.elapsed();
        self.mark = Instant::now();
    }
}

/// The stages every language shares after evaluation: meshing, export and
/// the summary. `primitives` is what the language counts as its primitives.
pub(crate) fn mesh_and_export(
    scene: eval::Scene,
    req: &RenderRequest,
    language: Language,
    primitives: u64,
    warnings: Vec<Diagnostic>,
    mut budget: Budget,
    mut stages: Stages,
) -> Result<RenderOutput, RenderError> {
    let print = req.export_options.print;
    let (meshes, graph) = if print.enabled {
        // Printing unites closed parts, so it needs them apart (and shows time 0).
        let parts = geom::meshing::build_parts(&scene, req.detail, &mut budget)?;
        let (solid, report) = crate::print::make_printable(&parts, &print, &mut budget).map_err(|e| match e {
            crate::print::PrintError::Limit(l) => RenderError::Limit(l),
            // The model has nothing closed to print: the request's fault, not the server's.
            e @ (crate::print::PrintError::NothingPrintable(_) | crate::print::PrintError::BadSize(_)) => RenderError::BadRequest(format!("print: {e}")),
            other => RenderError::Export(ExportError::Print(other)),
        })?;
        if print.report {
            let bytes = serde_json::to_vec_pretty(&report).map_err(|e| RenderError::Export(e.into()))?;
            return Ok(RenderOutput { bytes, language, primitives, triangles: report.triangles, truncated: scene.truncated, warnings, elapsed: budget.elapsed(), phases: stages.phases });
        }
        (solid, None)
    } else if carries_graph(&scene, req) {
        let (meshes, graph) = mesh_with_graph(&scene, req, &mut budget)?;
        (meshes, Some(graph))
    } else {
        (geom::build_meshes(&scene, req.detail, req.layout, &mut budget)?, None)
    };
    stages.lap(|p| &mut p.mesh);
    let meta = ExportMeta {
        background: scene.background,
        truncated: scene.truncated.is_some(),
        graph,
        material_per_mesh: !scene.classes.is_empty(),
        camera: scene.view,
    };
    let bytes = export::export_with(req.format, &meshes, &meta, &req.export_options, &mut budget)?;
    stages.lap(|p| &mut p.export);
    let triangles = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    Ok(RenderOutput {
        bytes,
        language,
        primitives,
        triangles,
        truncated: scene.truncated,
        warnings,
        elapsed: budget.elapsed(),
        phases: stages.phases,
    })
}

/// True when the scene has bones or a camera and the request's format can
/// carry a node hierarchy: plain glTF (the quantised and compressed writers,
/// STL, strips and unit-box fitting show the model at time 0 instead).
fn carries_graph(scene: &eval::Scene, req: &RenderRequest) -> bool {
    (scene.rig.is_some() || scene.camera.is_some()) && graph_capable(req)
}

/// True when the request's output carries a node hierarchy with animation
/// (plain glTF, not printed); everything else shows time 0.
pub(crate) fn graph_capable(req: &RenderRequest) -> bool {
    matches!(req.format, Format::Glb | Format::Gltf) && req.export_options.gltf.is_plain() && !req.export_options.fit_unit_box && !req.export_options.print.enabled
}

/// Meshes each bone's geometry in the bone's own coordinates and builds the
/// node graph (bones, animation samples, camera) that places them.
fn mesh_with_graph(
    scene: &eval::Scene,
    req: &RenderRequest,
    budget: &mut Budget,
) -> Result<(Vec<geom::NamedMesh>, export::graph::NodeGraph), RenderError> {
    let mut meshes = Vec::new();
    let mut bones = Vec::new();
    match &scene.rig {
        Some(rig) => {
            for (bone, part) in rig.split(scene, budget)? {
                for m in geom::build_meshes(&part, req.detail, req.layout, budget)? {
                    bones.push(bone);
                    meshes.push(m);
                }
            }
        }
        None => {
            meshes = geom::build_meshes(scene, req.detail, req.layout, budget)?;
            bones = vec![0; meshes.len()];
        }
    }
    let graph = export::graph::NodeGraph::new(scene.rig.as_ref(), scene.camera.as_ref(), &bones, budget)?;
    Ok((meshes, graph))
}

/// Renders an ETOL token stream (seed 003 appendix A) through the L-system
/// front end; diagnostics point back into the token stream.
fn render_etol(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    Budget::check_source(&req.limits, source.len() as u64)?;
    let t = lang::etol::translate(source)?;
    let as_lsystem = RenderRequest { language: Some(Language::Lsystem), ..req.clone() };
    match crate::lsystem::render(t.source.as_bytes(), &as_lsystem) {
        Ok(mut out) => {
            out.language = Language::Etol;
            t.map_warnings(&mut out.warnings);
            Ok(out)
        }
        Err(RenderError::Parse(e)) => Err(RenderError::Parse(t.map_error(e))),
        Err(e) => Err(e),
    }
}

/// Renders `source` as the request says. Never panics on bad input; every
/// failure is a typed [`RenderError`].
pub fn render(source: &[u8], req: &RenderRequest) -> Result<RenderOutput, RenderError> {
    check_detail(req)?;
    if req.format == Format::Strips {
        req.export_options.strips.validate().map_err(RenderError::BadRequest)?;
    }
    match req.language.or_else(|| Language::detect(source)) {
        Some(Language::Lsystem) => return crate::lsystem::render(source, req),
        Some(Language::Etol) => return render_etol(source, req),
        Some(Language::Eisenscript) => return crate::eisen::render(source, req),
        _ => {}
    }
    if req.format == Format::Scene {
        return Err(RenderError::BadRequest("format `scene` writes object-instancing hierarchies, which only L-systems make".into()));
    }
    let mut budget = Budget::new(req.limits);
    let mut stages = Stages::start();
    let (language, program) = parse_source(source, req.language, &req.limits)?;
    let params = bind_params(&program, &req.params)?;
    stages.lap(|p| &mut p.parse);
    // Promise the memory that meshing and export will need while evaluating,
    // so the memory limit binds (or truncates) as primitives are made.
    let overhead = export::estimated_size(req.format, 0, 0);
    budget.reserve_memory(overhead)?;
    let options = EvalOptions {
        seed: req.seed,
        detail: req.detail,
        on_limit: req.on_limit,
        downstream: downstream(req, overhead),
    };
    let mut scene = eval::evaluate(&program, &params, &options, &mut budget)?;
    stages.lap(|p| &mut p.eval);
    budget.check_deadline().or_else(|e| truncate_or_fail(req.on_limit, e, &mut scene))?;
    budget.release_memory(eval::promised_bytes(&scene, &options).saturating_add(overhead));
    let primitives = scene.instances.len() as u64;
    mesh_and_export(scene, req, language, primitives, program.warnings, budget, stages)
}

/// Under `truncate`, records `e` as the reason the scene is partial; under `error`, fails with it.
pub(crate) fn truncate_or_fail(on_limit: OnLimit, e: LimitExceeded, scene: &mut eval::Scene) -> Result<(), RenderError> {
    match on_limit {
        OnLimit::Error => Err(RenderError::Limit(e)),
        OnLimit::Truncate => {
            scene.truncated.get_or_insert(e);
            Ok(())
        }
    }
}

/// Bytes the mesh buffers and the encoded output need per vertex and per
/// triangle (both are linear in the counts beyond a fixed overhead).
pub(crate) fn downstream(req: &RenderRequest, overhead: u64) -> eval::Downstream {
    let est = |v, t| export::estimated_size(req.format, v, t).saturating_sub(overhead);
    eval::Downstream {
        per_vertex: crate::geom::meshing::mesh_bytes(1, 0).saturating_add(est(1, 0)),
        per_triangle: crate::geom::meshing::mesh_bytes(0, 1).saturating_add(est(0, 1)),
    }
}
