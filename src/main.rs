//! The `rulemesh` command-line tool: render grammars to model files and check them.
//!
//! Exit codes: 0 ok, 2 parse or usage error, 3 limit exceeded, 1 any other failure.

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use rulemesh::core::{Limits, OnLimit, ParamValue};
use rulemesh::export::{Compression, ExportOptions, Format, GltfOptions, Instancing, StripsOptions};
use rulemesh::geom::DEFAULT_DETAIL;
use rulemesh::mesh::MeshLayout;
use rulemesh::lang::Language;
use rulemesh::core::Diagnostic;
use rulemesh::{render, RenderError, RenderRequest};
use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use rulemesh::core::Choice;

/// A clap value parser for one of the engine's [`Choice`] enums: the engine's
/// crates carry no command-line library, so the flag's possible values (and
/// `--help`'s list of them) come from the enum's own request names.
fn choice<T: Choice + Clone>() -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::TypedValueParser as _;
    clap::builder::PossibleValuesParser::new(T::names()).try_map(|name| {
        T::from_name(&name).ok_or_else(|| clap::Error::new(clap::error::ErrorKind::InvalidValue))
    })
}


/// Exit code for a parse or usage error.
const EXIT_USAGE: u8 = 2;
/// Exit code for an exceeded limit.
const EXIT_LIMIT: u8 = 3;
/// Exit code for any other failure.
const EXIT_FAILURE: u8 = 1;

#[derive(Parser)]
#[command(name = "rulemesh", version, about = "Shape grammars to 3D models (glTF, STL) under hard limits")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate a grammar and write the model.
    Render(RenderArgs),
    /// Parse a grammar and print diagnostics as `file:line:col: message`, without evaluating.
    Check(CheckArgs),
    /// Decode a `.strips` file (the reference decoder) and write it as glTF or STL.
    Decode(DecodeArgs),
    /// Render every grammar file in a directory to one labelled contact-sheet PNG (docs/gallery.md).
    Gallery(GalleryArgs),
    /// Run the HTTP and gRPC service (options also from `RULEMESH_*` variables).
    Serve(ServeArgs),
}

#[derive(Args)]
struct ServeArgs {
    #[command(flatten)]
    config: rulemesh::service::ServeConfig,
    /// Log level: error, warn, info, debug or trace.
    #[arg(long, env = "RULEMESH_LOG", default_value = "info")]
    log: tracing_subscriber::filter::LevelFilter,
    /// Log line format: text, or json (one object per line, with each request's stage timings as fields).
    #[arg(long, env = "RULEMESH_LOG_FORMAT", value_enum, default_value = "text")]
    log_format: rulemesh::service::telemetry::LogFormat,
    /// Export OpenTelemetry spans (one per request, one per pipeline stage) over OTLP/gRPC to this
    /// collector, e.g. http://127.0.0.1:4317; off when absent.
    #[arg(long, env = "RULEMESH_OTLP_ENDPOINT")]
    otlp_endpoint: Option<String>,
    /// Settings file (TOML, or JSON if named *.json); flags and RULEMESH_* variables override it.
    #[arg(long = "config", env = "RULEMESH_CONFIG")]
    config_file: Option<PathBuf>,
    /// Print the resolved settings as JSON and exit.
    #[arg(long)]
    print_config: bool,
}

#[derive(Args)]
struct GalleryArgs {
    /// Directory whose grammar files (.mdg, .ls, .es, .stack, .ug, .etol) are drawn, in name order.
    dir: PathBuf,
    /// Output PNG file.
    #[arg(short, long)]
    output: PathBuf,
    /// Tile side in pixels (picture plus a 12 px label band), 28-2060.
    #[arg(long, default_value_t = 160)]
    tile: u32,
    /// Tiles per row (fewer if there are fewer grammars).
    #[arg(long, default_value_t = 6)]
    columns: u32,
    /// Where the camera looks from.
    #[arg(long, value_parser = choice::<rulemesh::preview::View>(), default_value = "three-quarter")]
    view: rulemesh::preview::View,
    /// Sheet and picture background, `#rrggbb`.
    #[arg(long, default_value = "#ffffff")]
    background: String,
}

#[derive(Args)]
struct DecodeArgs {
    /// The `.strips` file, or `-` for standard input.
    file: String,
    /// Output file (format from its extension: .glb, .gltf, .stl, .strips, .rmscene, .3mf, .ug, .png), or `-` for standard output.
    #[arg(short, long)]
    output: String,
    /// Output format (default: from the output extension, else glb).
    #[arg(long, value_parser = choice::<Format>())]
    format: Option<Format>,
}

#[derive(Args)]
struct RenderArgs {
    /// Grammar file, or `-` for standard input.
    file: String,
    /// Source language (default: from the file extension, then from the content).
    #[arg(long, value_parser = choice::<Language>())]
    language: Option<Language>,
    /// Random seed (default: the grammar's `randseed`, else 0).
    #[arg(long, conflicts_with = "seeds")]
    seed: Option<u64>,
    /// Render once per seed: `A..B` (both ends included) or `1,5,9`; the
    /// output must name each file with `{seed}`, e.g. `-o out/{seed}.glb`.
    #[arg(long, value_name = "LIST")]
    seeds: Option<String>,
    /// A grammar parameter, `name=value`; repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// Output format (default: from the output extension, else glb).
    #[arg(long, value_parser = choice::<Format>())]
    format: Option<Format>,
    /// Output file (format from its extension: .glb, .gltf, .stl, .strips, .rmscene, .3mf, .ug, .png), or `-` for standard output.
    #[arg(short, long, default_value = "-")]
    output: String,
    /// Deepest rule nesting.
    #[arg(long)]
    max_depth: Option<u32>,
    /// Most primitives.
    #[arg(long)]
    max_primitives: Option<u64>,
    /// Most triangles.
    #[arg(long)]
    max_triangles: Option<u64>,
    /// Most bytes of accounted memory (default 268435456, 256 MiB; with --print 671088640, 640 MiB).
    #[arg(long)]
    max_memory: Option<u64>,
    /// Wall-clock limit in milliseconds.
    #[arg(long)]
    timeout: Option<u64>,
    /// Most evaluation steps.
    #[arg(long)]
    max_steps: Option<u64>,
    /// Largest source in bytes.
    #[arg(long)]
    max_source_bytes: Option<u64>,
    /// What to do when a limit runs out.
    #[arg(long, value_parser = choice::<OnLimit>(), default_value = "error")]
    on_limit: OnLimit,
    /// Tessellation detail (segments around round primitives).
    #[arg(long, default_value_t = DEFAULT_DETAIL)]
    detail: u32,
    /// One merged mesh or one mesh per primitive kind.
    #[arg(long, value_parser = choice::<MeshLayout>(), default_value = "merged")]
    layout: MeshLayout,
    /// A Structure Synth JavaScript movie only: build its K-th saved picture alone (0-based), as Structure Synth renders one picture at a time.
    #[arg(long, value_name = "K")]
    frame: Option<u32>,
    /// strips format: bits per position axis (8, 10, 12 or 16).
    #[arg(long, default_value_t = StripsOptions::default().position_bits)]
    position_bits: u8,
    /// strips format: bits per octahedral normal component (8 or 16).
    #[arg(long, default_value_t = StripsOptions::default().normal_bits)]
    normal_bits: u8,
    /// strips format: wrap the body in zstd (the JavaScript decoder cannot read it).
    #[arg(long)]
    zstd: bool,
    /// glb/gltf: weld identical vertices and drop degenerate triangles.
    #[arg(long)]
    weld: bool,
    /// glb/gltf: KHR_mesh_quantization (16-bit positions, 8-bit normals; implies --weld).
    #[arg(long)]
    quantize: bool,
    /// glb/gltf: buffer compression (meshopt = EXT_meshopt_compression; implies --weld).
    #[arg(long, value_parser = choice::<Compression>(), default_value = "none")]
    compress: Compression,
    /// Scale and move the model into a unit box centred at the origin (every format).
    #[arg(long)]
    fit_unit_box: bool,
    /// glb/gltf: gpu (each mesh placed more than once written once, EXT_mesh_gpu_instancing) or flat (plain meshes).
    #[arg(long, value_parser = choice::<Instancing>(), default_value = "gpu")]
    instancing: Instancing,
    /// Merge every part into one watertight, outward-oriented solid in millimetres for 3D printing (docs/print.md).
    #[arg(long)]
    print: bool,
    /// With --print: scale so the longest side is this many millimetres.
    #[arg(long, value_name = "N", requires = "print")]
    size_mm: Option<f64>,
    /// With --print: write the JSON printability report instead of the model.
    #[arg(long, requires = "print")]
    print_report: bool,
    /// With --print: the printer's thinnest wall or feature in mm (default 0.8); thinner walls are reported as thin_wall.
    #[arg(long, value_name = "MM", requires = "print")]
    min_wall_mm: Option<f64>,
    /// With --print: the printer's build volume XxYxZ in mm (default 250x210x210); a larger model is reported as too_big.
    #[arg(long, value_name = "XxYxZ", requires = "print")]
    build_volume_mm: Option<String>,
    /// With --print: the most triangles the printer accepts (default 1000000); more are reported as too_many_triangles.
    #[arg(long, value_name = "N", requires = "print")]
    triangle_ceiling: Option<u64>,
    /// png: width and height in pixels (16-2048).
    #[arg(long, default_value_t = rulemesh::preview::DEFAULT_SIZE)]
    size: u32,
    /// png: where the camera looks from.
    #[arg(long, value_parser = choice::<rulemesh::preview::View>(), default_value = "three-quarter")]
    view: rulemesh::preview::View,
    /// png: `transparent`, or an opaque background colour `#rrggbb`.
    #[arg(long, default_value = "transparent")]
    background: String,
}

#[derive(Args)]
struct CheckArgs {
    /// Grammar file, or `-` for standard input.
    file: String,
    /// Source language (default: from the file extension, then from the content).
    #[arg(long, value_parser = choice::<Language>())]
    language: Option<Language>,
}

/// A failure with the exit code it maps to and the lines to print.
struct Failure {
    code: u8,
    lines: Vec<String>,
}

impl Failure {
    fn new(code: u8, line: String) -> Failure {
        Failure { code, lines: vec![line] }
    }
}

fn main() -> ExitCode {
    // Before any thread starts: large blocks go back to the system when freed.
    rulemesh::service::memory::tune_allocator();
    let matches = Cli::command().get_matches();
    let cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit());
    let result = match cli.command {
        Command::Render(args) => run_render(args),
        Command::Check(args) => run_check(args),
        Command::Decode(args) => run_decode(args),
        Command::Gallery(args) => run_gallery(args),
        Command::Serve(args) => match matches.subcommand_matches("serve") {
            Some(m) => run_serve(args, m),
            None => Err(Failure::new(EXIT_USAGE, "serve: no arguments".into())),
        },
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            let mut err = std::io::stderr().lock();
            for line in f.lines {
                let _ = writeln!(err, "{line}");
            }
            ExitCode::from(f.code)
        }
    }
}

/// Reads the source, refusing to read more than `max` bytes (plus one, to detect the overflow).
fn read_source(file: &str, max: u64) -> Result<Vec<u8>, Failure> {
    let mut buf = Vec::new();
    let res = if file == "-" {
        std::io::stdin().lock().take(max.saturating_add(1)).read_to_end(&mut buf)
    } else {
        std::fs::File::open(file).and_then(|f| f.take(max.saturating_add(1)).read_to_end(&mut buf))
    };
    res.map_err(|e| Failure::new(EXIT_FAILURE, format!("{file}: cannot read: {e}")))?;
    Ok(buf)
}

/// The directory a JavaScript script's `Builder.load` reads from: the
/// script's own (the working directory for stdin or a bare file name).
fn script_dir_of(file: &str) -> std::path::PathBuf {
    match Path::new(file).parent() {
        Some(p) if file != "-" && !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    }
}

/// The files a cpfg model's folder holds beside it (`plant.v`, `plant.a`,
/// `plant.map`, its `#include`s and what the view names), which the
/// request carries: front ends never read the disk themselves.
fn companions_of(file: &str, language: Option<Language>, source: &[u8], max: u64) -> std::collections::BTreeMap<String, Vec<u8>> {
    if file == "-" || language != Some(Language::Cpfg) {
        return Default::default();
    }
    let dir = script_dir_of(file);
    let stem = Path::new(file).file_stem().and_then(|s| s.to_str()).unwrap_or("");
    let read = |name: &str| std::fs::read(dir.join(name)).ok();
    rulemesh::lang::cpfg::companions::companions(stem, source, &read, max.saturating_sub(source.len() as u64))
}

fn language_for(file: &str, given: Option<Language>) -> Option<Language> {
    given.or_else(|| Language::from_extension(Path::new(file)))
}

fn diagnostic_lines(file: &str, diags: &[Diagnostic]) -> Vec<String> {
    diags.iter().map(|d| format!("{file}:{d}")).collect()
}

fn parse_params(raw: &[String]) -> Result<BTreeMap<String, ParamValue>, Failure> {
    raw.iter()
        .map(|p| match p.split_once('=') {
            Some((k, v)) if !k.is_empty() => Ok((k.to_string(), ParamValue::Text(v.to_string()))),
            _ => Err(Failure::new(EXIT_USAGE, format!("--param expects NAME=VALUE, got `{p}`"))),
        })
        .collect()
}

/// The printer profile of `--min-wall-mm`, `--build-volume-mm` and
/// `--triangle-ceiling` (each checked; a bad one is a usage error).
fn printer_profile(args: &RenderArgs) -> Result<rulemesh::print::PrinterProfile, Failure> {
    let usage = |e: rulemesh::print::PrintError| Failure::new(EXIT_USAGE, e.to_string());
    let build = args.build_volume_mm.as_deref().map(rulemesh::print::profile::parse_build_volume).transpose().map_err(usage)?;
    rulemesh::print::PrinterProfile::from_request(args.min_wall_mm, build.as_deref(), args.triangle_ceiling).map_err(usage)
}

fn limits_from(args: &RenderArgs) -> Limits {
    let d = Limits::defaults_for(args.print);
    Limits {
        max_depth: args.max_depth.unwrap_or(d.max_depth),
        max_primitives: args.max_primitives.unwrap_or(d.max_primitives),
        max_triangles: args.max_triangles.unwrap_or(d.max_triangles),
        max_memory: args.max_memory.unwrap_or(d.max_memory),
        timeout_ms: args.timeout.unwrap_or(d.timeout_ms),
        max_source_bytes: args.max_source_bytes.unwrap_or(d.max_source_bytes),
        max_steps: args.max_steps.unwrap_or(d.max_steps),
    }
    .clamped_to(&Limits::ceiling())
}

/// The output format: the one given, else the output file's extension, else
/// (standard output, or a name without an extension) glb. An extension no
/// format has is a usage error that lists them, rather than glb bytes
/// under a name that says otherwise.
fn output_format(given: Option<Format>, output: &str) -> Result<Format, Failure> {
    if let Some(f) = given {
        return Ok(f);
    }
    let path = Path::new(output);
    match path.extension() {
        _ if output == "-" => Ok(Format::Glb),
        None => Ok(Format::Glb),
        Some(ext) => Format::from_extension(path).ok_or_else(|| {
            let names: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
            Failure::new(
                EXIT_USAGE,
                format!(
                    "{output}: unknown output extension `.{}` (known: {}); or name the format with --format ({})",
                    ext.to_string_lossy(),
                    Format::known_extensions(),
                    names.join(", ")
                ),
            )
        }),
    }
}

fn run_render(args: RenderArgs) -> Result<(), Failure> {
    let limits = limits_from(&args);
    // A printability report is JSON whatever the file is called (`report.json`);
    // the format only names the model it reports on (STL unless given).
    let format = match args.print_report {
        true => args.format.unwrap_or(Format::Stl),
        false => output_format(args.format, &args.output)?,
    };
    let req = RenderRequest {
        language: language_for(&args.file, args.language),
        seed: args.seed,
        params: parse_params(&args.params)?,
        format,
        limits,
        on_limit: args.on_limit,
        detail: args.detail,
        layout: args.layout,
        export_options: ExportOptions {
            strips: StripsOptions { position_bits: args.position_bits, normal_bits: args.normal_bits, zstd: args.zstd },
            gltf: GltfOptions { weld: args.weld, quantize: args.quantize, compress: args.compress },
            fit_unit_box: args.fit_unit_box,
            instancing: args.instancing,
            print: rulemesh::print::PrintOptions {
                enabled: args.print,
                size_um: match args.size_mm {
                    Some(mm) => rulemesh::print::size_um(mm).map_err(|e| Failure::new(EXIT_USAGE, e.to_string()))?,
                    None => 0,
                },
                report: args.print_report,
                profile: printer_profile(&args)?,
            },
            preview: rulemesh::preview::PreviewOptions {
                size: args.size,
                view: args.view,
                background: rulemesh::preview::parse_background(&args.background).map_err(|e| Failure::new(EXIT_USAGE, e))?,
            },
        },
        script_dir: Some(script_dir_of(&args.file)),
        frame: args.frame,
        files: Default::default(),
    };
    let source = read_source(&args.file, limits.max_source_bytes)?;
    let req = RenderRequest { files: companions_of(&args.file, req.language, &source, limits.max_source_bytes), ..req };
    let Some(list) = &args.seeds else {
        return render_one(&args.file, &source, &req, &args.output);
    };
    let seeds = parse_seeds(list)?;
    if !args.output.contains("{seed}") {
        return Err(Failure::new(EXIT_USAGE, format!("--seeds writes one file per seed: name them with {{seed}} in --output (e.g. out/{{seed}}.glb), not `{}`", args.output)));
    }
    for seed in seeds {
        let output = args.output.replace("{seed}", &seed.to_string());
        render_one(&args.file, &source, &RenderRequest { seed: Some(seed), ..req.clone() }, &output)?;
    }
    Ok(())
}

/// The most seeds one `--seeds` list may name: a typo such as `1..1000000000`
/// is refused rather than left writing files for days.
const MAX_CLI_SEEDS: u64 = 100_000;

/// Reads `--seeds`: `A..B` (both ends included, A ≤ B) or a comma list, in
/// the order given; each seed 0 to 2^64 − 1.
fn parse_seeds(list: &str) -> Result<Vec<u64>, Failure> {
    let bad = |why: String| Failure::new(EXIT_USAGE, format!("--seeds `{list}`: {why} (expected A..B or a comma list such as 1,5,9)"));
    let seed = |t: &str| t.trim().parse::<u64>().map_err(|_| bad(format!("`{}` is not a whole number from 0 to 2^64 - 1", t.trim())));
    let seeds: Vec<u64> = match list.split_once("..") {
        Some((a, b)) => {
            let (a, b) = (seed(a)?, seed(b)?);
            if a > b {
                return Err(bad(format!("the range is empty ({a} > {b})")));
            }
            if b - a >= MAX_CLI_SEEDS {
                return Err(bad(format!("more than {MAX_CLI_SEEDS} seeds")));
            }
            (a..=b).collect()
        }
        None => list.split(',').map(seed).collect::<Result<_, _>>()?,
    };
    if seeds.len() as u64 > MAX_CLI_SEEDS {
        return Err(bad(format!("more than {MAX_CLI_SEEDS} seeds")));
    }
    Ok(seeds)
}

/// Renders `source` as `req` says into `output`, reporting counts and stage
/// times (and any warnings) on standard error.
fn render_one(file: &str, source: &[u8], req: &RenderRequest, output: &str) -> Result<(), Failure> {
    let out = render(source, req).map_err(|e| render_failure(file, e))?;
    for w in &out.warnings {
        eprintln!("{file}:{w}");
    }
    write_output(output, &out.bytes)?;
    let truncated = match out.truncated {
        Some(t) => format!(", TRUNCATED at {} limit (configured {}, reached {})", t.limit.name(), t.configured, t.reached),
        None => String::new(),
    };
    let ms = |d: std::time::Duration| d.as_secs_f64() * 1000.0;
    // The stages that ran (a scene has no mesh stage; print=true adds print).
    let stages: Vec<String> = out.phases.ran().map(|(p, d)| format!("{} {:.1}", p.name(), ms(d))).collect();
    // The seed too when the request named one (a `--seeds` run says which file is which).
    let seed = req.seed.map_or_else(String::new, |s| format!(" seed {s}"));
    eprintln!(
        "{file}{seed}: {} primitives, {} triangles, {} bytes ({:?}) in {:.1} ms ({}){}",
        out.primitives,
        out.triangles,
        out.bytes.len(),
        req.format,
        ms(out.elapsed),
        stages.join(", "),
        truncated
    );
    Ok(())
}

fn write_output(path: &str, bytes: &[u8]) -> Result<(), Failure> {
    let res = if path == "-" {
        let mut out = std::io::stdout().lock();
        out.write_all(bytes).and_then(|()| out.flush())
    } else {
        std::fs::write(PathBuf::from(path), bytes)
    };
    res.map_err(|e| Failure::new(EXIT_FAILURE, format!("{path}: cannot write: {e}")))
}

fn render_failure(file: &str, e: RenderError) -> Failure {
    match e {
        RenderError::Parse(p) => Failure { code: EXIT_USAGE, lines: diagnostic_lines(file, &p.diagnostics) },
        RenderError::Limit(l) => Failure::new(EXIT_LIMIT, format!("{file}: {l}")),
        RenderError::BadRequest(m) => Failure::new(EXIT_USAGE, format!("{file}: {m}")),
        // Errors in the source's numbers or in the given parameters are usage errors;
        // those that point into the source read like parse errors (`file:line:col: …`).
        RenderError::Eval(ev) if ev.span().is_some() => Failure::new(EXIT_USAGE, format!("{file}:{ev}")),
        RenderError::Eval(ev) => Failure::new(EXIT_USAGE, format!("{file}: {ev}")),
        // Nothing printable: the model's fault, as a usage error (the message says why).
        e @ RenderError::Unprintable(_) => Failure::new(EXIT_USAGE, format!("{file}: {e}")),
        e @ RenderError::TooLarge { .. } => Failure::new(EXIT_LIMIT, format!("{file}: {e}")),
        RenderError::Export(x) => Failure::new(EXIT_FAILURE, format!("{file}: {x}")),
    }
}

fn run_check(args: CheckArgs) -> Result<(), Failure> {
    let limits = Limits::default();
    let source = read_source(&args.file, limits.max_source_bytes)?;
    match rulemesh::pipeline::check_source(&source, language_for(&args.file, args.language), &limits) {
        Ok((_, warnings)) => {
            for line in diagnostic_lines(&args.file, &warnings) {
                println!("{line}");
            }
            Ok(())
        }
        Err(e) => Err(render_failure(&args.file, e)),
    }
}

/// Renders each grammar file of a directory (default limits and seeds) into
/// one tile of a contact sheet. A grammar that fails gets a tile saying so;
/// the sheet is still written, and the failures are listed on stderr with
/// exit code 1.
fn run_gallery(args: GalleryArgs) -> Result<(), Failure> {
    use rulemesh::preview::sheet::{compose, picture_size, Tile, TileContent, MIN_TILE};
    let max_tile = rulemesh::preview::MAX_SIZE + rulemesh::preview::sheet::LABEL_HEIGHT;
    if !(MIN_TILE..=max_tile).contains(&args.tile) {
        return Err(Failure::new(EXIT_USAGE, format!("--tile must be in {MIN_TILE}..={max_tile}, got {}", args.tile)));
    }
    let background = match rulemesh::preview::parse_background(&args.background).map_err(|e| Failure::new(EXIT_USAGE, e))? {
        Some(c) => c,
        None => return Err(Failure::new(EXIT_USAGE, "gallery: the sheet needs an opaque --background `#rrggbb`".into())),
    };
    let dir = args.dir.display().to_string();
    let mut files: Vec<PathBuf> = std::fs::read_dir(&args.dir)
        .map_err(|e| Failure::new(EXIT_FAILURE, format!("{dir}: cannot read: {e}")))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file() && Language::from_extension(p).is_some())
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(Failure::new(EXIT_USAGE, format!("{dir}: no grammar files (.mdg, .ls, .es, .stack, .ug, .etol)")));
    }
    let mut failed = Vec::new();
    let mut tiles = Vec::new();
    for path in &files {
        let file = path.display().to_string();
        let label = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| file.clone());
        let content = match render_tile(path, picture_size(args.tile), args.view, background) {
            Ok(img) => TileContent::Picture(img),
            Err(f) => {
                let msg = f.lines.first().cloned().unwrap_or_default();
                failed.extend(f.lines);
                TileContent::Failed(msg.strip_prefix(&format!("{file}")).unwrap_or(&msg).trim_start_matches([':', ' ']).to_string())
            }
        };
        tiles.push(Tile { label, content });
    }
    let sheet = compose(&tiles, args.columns, args.tile, background);
    let text = vec![("Software", format!("rulemesh {} gallery", env!("CARGO_PKG_VERSION")))];
    let bytes = rulemesh::pipeline::write_picture(sheet.width, sheet.height, &sheet.rgba, &text, &Limits::ceiling())
        .map_err(|e| Failure::new(EXIT_FAILURE, format!("gallery: {e}")))?;
    let out = args.output.display().to_string();
    write_output(&out, &bytes)?;
    eprintln!("{out}: {} grammars ({} failed), {}x{} px, {} bytes", files.len(), failed.len(), sheet.width, sheet.height, bytes.len());
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Failure { code: EXIT_FAILURE, lines: failed })
    }
}

/// One grammar's preview, decoded back to pixels for the sheet.
fn render_tile(path: &Path, size: u32, view: rulemesh::preview::View, background: [u8; 3]) -> Result<rulemesh::preview::Image, Failure> {
    let file = path.display().to_string();
    let limits = Limits::default();
    let mut req = RenderRequest { language: language_for(&file, None), format: Format::Png, limits, script_dir: Some(script_dir_of(&file)), ..RenderRequest::default() };
    req.export_options.preview = rulemesh::preview::PreviewOptions { size, view, background: Some(background) };
    let source = read_source(&file, limits.max_source_bytes)?;
    let out = render(&source, &req).map_err(|e| render_failure(&file, e))?;
    let bad = |e: String| Failure::new(EXIT_FAILURE, format!("{file}: cannot decode its preview: {e}"));
    let mut reader = png::Decoder::new(std::io::Cursor::new(&out.bytes)).read_info().map_err(|e| bad(e.to_string()))?;
    let mut buf = vec![0; reader.output_buffer_size().ok_or_else(|| bad("too large".into()))?];
    let frame = reader.next_frame(&mut buf).map_err(|e| bad(e.to_string()))?;
    buf.truncate(frame.buffer_size());
    Ok(rulemesh::preview::Image { size: frame.width, rgba: buf })
}

/// Largest `.strips` file `decode` reads (a phone icon is a few kilobytes).
const MAX_STRIPS_BYTES: u64 = 1 << 30;

fn run_decode(args: DecodeArgs) -> Result<(), Failure> {
    let format = output_format(args.format, &args.output)?;
    let bytes = read_source(&args.file, MAX_STRIPS_BYTES)?;
    if bytes.len() as u64 > MAX_STRIPS_BYTES {
        return Err(Failure::new(EXIT_USAGE, format!("{}: larger than {MAX_STRIPS_BYTES} bytes", args.file)));
    }
    let mesh = rulemesh::export::decode_strips(&bytes).map_err(|e| Failure::new(EXIT_FAILURE, format!("{}: {e}", args.file)))?;
    let triangles = mesh.triangle_count();
    let meshes = [rulemesh::geom::NamedMesh { name: "model".into(), mesh }];
    let out = rulemesh::pipeline::write_meshes(format, &meshes, &Limits::ceiling()).map_err(|e| Failure::new(EXIT_FAILURE, format!("{}: {e}", args.file)))?;
    write_output(&args.output, &out)?;
    eprintln!("{}: {} triangles, {} bytes ({:?})", args.file, triangles, out.len(), format);
    Ok(())
}

fn run_serve(args: ServeArgs, matches: &clap::ArgMatches) -> Result<(), Failure> {
    let config = match &args.config_file {
        Some(path) => {
            let file = rulemesh::service::config::ConfigFile::read(path).map_err(|e| Failure::new(EXIT_USAGE, format!("serve: {e}")))?;
            args.config.resolve(matches, file)
        }
        None => args.config,
    };
    if args.print_config {
        let json = serde_json::to_string_pretty(&config).map_err(|e| Failure::new(EXIT_FAILURE, format!("serve: {e}")))?;
        println!("{json}");
        return Ok(());
    }
    // The blocking pool only runs renders, which the engine already limits to
    // `concurrency`; a few spare threads cover moka and file work.
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .max_blocking_threads(config.concurrency() + 4)
        .build()
        .map_err(|e| Failure::new(EXIT_FAILURE, format!("cannot start the runtime: {e}")))?;
    let telemetry = {
        // The OTLP exporter's connection is made on this runtime.
        let _entered = runtime.enter();
        rulemesh::service::telemetry::init(args.log, args.log_format, args.otlp_endpoint.as_deref(), config.worker_id.as_deref())
            .map_err(|e| Failure::new(EXIT_FAILURE, format!("serve: {e}")))?
    };
    let served = runtime.block_on(rulemesh::service::serve(config, rulemesh::service::shutdown_signal()));
    telemetry.shutdown();
    served.map_err(|e| Failure::new(EXIT_FAILURE, format!("serve: {e}")))
}
