//! The `rulemesh` command-line tool: render grammars to model files and check them.
//!
//! Exit codes: 0 ok, 2 parse or usage error, 3 limit exceeded, 1 any other failure.

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use rulemesh::core::Limits;
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::core::Diagnostic;
use rulemesh::pipeline::options::{Doors, Kind, OptionField};
use rulemesh::{render, RenderError, RenderOptions, RenderRequest};
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
    /// Per-request log lines: all, sampled (one in 100, and every internal error) or off. The line
    /// is short (method, route, status, ms, cache, bytes); stage timings are at debug level.
    #[arg(long, env = "RULEMESH_ACCESS_LOG", value_enum, default_value = "all")]
    access_log: rulemesh::service::access_log::AccessLog,
    /// Log lines queued for stderr before further lines are dropped (and counted in
    /// rulemesh_log_lines_dropped_total) rather than waited for.
    #[arg(long, env = "RULEMESH_LOG_BUFFER_LINES", default_value_t = rulemesh::service::telemetry::DEFAULT_LOG_BUFFER_LINES)]
    log_buffer_lines: usize,
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
    // The extensions are the format registry's (`output_help`).
    #[arg(short, long, help = output_help())]
    output: String,
    /// Output format (default: from the output extension, else glb).
    #[arg(long, value_parser = choice::<Format>())]
    format: Option<Format>,
}

#[derive(Args)]
struct RenderArgs {
    /// Grammar file, or `-` for standard input.
    file: String,
    /// Render once per seed: `A..B` (both ends included) or `1,5,9`; the
    /// output must name each file with `{seed}`, e.g. `-o out/{seed}.glb`.
    #[arg(long, value_name = "LIST", conflicts_with = "seed")]
    seeds: Option<String>,
    // The extensions are the format registry's (`output_help`).
    #[arg(short, long, default_value = "-", help = output_help())]
    output: String,
    /// Print the request's cache key (hex; the key the service's cache would
    /// store this model under) instead of rendering.
    #[arg(long)]
    cache_key: bool,
    /// The render options: one flag per field of the pipeline's declaration.
    #[command(flatten)]
    options: OptionFlags,
}

/// The render options as flags, one per field of the pipeline's one
/// declaration ([`RenderOptions::fields`]; the limits' fields are flags of
/// their own, `--max-depth`), read into the JSON object an HTTP body would
/// be, so the one deserializer and the one validator
/// ([`RenderOptions::plan`]) read the command line as they read the body.
/// Written by hand (clap's derive needs a field per flag): the flags come
/// from the declaration at run time.
struct OptionFlags(serde_json::Map<String, serde_json::Value>);

/// The declaration's fields offered on the command line, each with the
/// group it sits in (`limits`), if any.
fn cli_fields() -> Vec<(Option<&'static str>, &'static OptionField)> {
    let mut out = Vec::new();
    for f in RenderOptions::fields().iter().filter(|f| f.doors.has(Doors::CLI)) {
        match f.group() {
            Some(inner) => out.extend(inner.iter().filter(|g| g.doors.has(Doors::CLI)).map(|g| (Some(f.name), g))),
            None => out.push((None, f)),
        }
    }
    out
}

/// A field's help: its doc, the values its schema names and its default.
fn flag_help(f: &OptionField) -> String {
    let mut help = f.doc.clone();
    if let Some(values) = f.schema.get("enum").and_then(|v| v.as_array()).filter(|_| f.cli_flag.is_none()) {
        let names: Vec<String> = values.iter().map(|v| v.as_str().map_or_else(|| v.to_string(), str::to_string)).collect();
        help.push_str(&format!(" [possible values: {}]", names.join(", ")));
    }
    if let Some(d) = f.schema.get("default").filter(|_| f.cli_flag.is_none()) {
        help.push_str(&format!(" [default: {}]", d.as_str().map_or_else(|| d.to_string(), str::to_string)));
    }
    help
}

impl clap::Args for OptionFlags {
    fn augment_args(mut cmd: clap::Command) -> clap::Command {
        use clap::{Arg, ArgAction};
        for (_, f) in cli_fields() {
            let flag = f.flag();
            let arg = Arg::new(flag.clone()).long(flag).help(flag_help(f));
            cmd = cmd.arg(match (&f.cli_flag, f.kind) {
                (Some(_), _) => arg.action(ArgAction::SetTrue),
                (None, Kind::Params) => arg.action(ArgAction::Append).value_name("NAME=VALUE"),
                (None, _) => arg.action(ArgAction::Set).value_name(f.name.to_ascii_uppercase()),
            });
        }
        cmd
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl FromArgMatches for OptionFlags {
    fn from_arg_matches(m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        use serde_json::{Map, Value};
        let bad = |msg: String| clap::Error::raw(clap::error::ErrorKind::ValueValidation, format!("{msg}\n"));
        let mut top = Map::new();
        for (group, f) in cli_fields() {
            let id = f.flag();
            let value = match (&f.cli_flag, f.kind) {
                (Some(v), _) => m.get_flag(&id).then(|| v.clone()),
                (None, Kind::Params) => match m.get_many::<String>(&id) {
                    None => None,
                    Some(pairs) => {
                        let mut params = Map::new();
                        for p in pairs {
                            match p.split_once('=') {
                                Some((k, v)) if !k.is_empty() => params.insert(k.to_string(), Value::from(v)),
                                _ => return Err(bad(format!("--param expects NAME=VALUE, got `{p}`"))),
                            };
                        }
                        Some(Value::Object(params))
                    }
                },
                (None, kind) => match m.get_one::<String>(&id) {
                    None => None,
                    Some(text) => Some(kind.read_text(text).map_err(|e| bad(format!("--{id} `{text}`: {e}")))?),
                },
            };
            let Some(value) = value else { continue };
            match group {
                None => top.insert(f.name.to_string(), value),
                Some(g) => top.entry(g).or_insert_with(|| Value::Object(Map::new())).as_object_mut().and_then(|o| o.insert(f.name.to_string(), value)),
            };
        }
        Ok(OptionFlags(top))
    }

    fn update_from_arg_matches(&mut self, m: &clap::ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
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

/// The `--output` help: the extensions come from the format registry.
fn output_help() -> String {
    format!("Output file (format from its extension: {}), or `-` for standard output.", Format::known_extensions())
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
        _ if output == "-" => Ok(Format::default()),
        None => Ok(Format::default()),
        Some(ext) => Format::from_extension(path).ok_or_else(|| {
            let names = Format::names();
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
    let usage = |e: String| Failure::new(EXIT_USAGE, format!("{}: {e}", args.file));
    let mut fields = args.options.0;
    // The language: as given, else from the file's extension (else the
    // pipeline detects it from the content).
    if !fields.contains_key("language") {
        if let Some(l) = Language::from_extension(Path::new(&args.file)) {
            fields.insert("language".into(), l.name().into());
        }
    }
    // The format: as given, else from the output's extension. A
    // printability report is JSON whatever the file is called
    // (`report.json`); the format only names the model it reports on (STL
    // unless given).
    if !fields.contains_key("format") {
        let format = match fields.get("print_report") == Some(&serde_json::Value::Bool(true)) {
            true => Format::Stl,
            false => output_format(None, &args.output)?,
        };
        fields.insert("format".into(), format.name().into());
    }
    let options: RenderOptions = serde_json::from_value(serde_json::Value::Object(fields)).map_err(|e| usage(e.to_string()))?;
    let mut req = options.plan(&Limits::ceiling()).map_err(|e| usage(e.to_string()))?;
    req.script_dir = Some(script_dir_of(&args.file));
    let source = read_source(&args.file, req.limits.max_source_bytes)?;
    // A cpfg model's companions (its view, colour map, includes) beside the file.
    req.files = companions_of(&args.file, req.language, &source, req.limits.max_source_bytes);
    if args.cache_key {
        let key = rulemesh::pipeline::key::cache_key(&rulemesh::pipeline::key::normalize_source(&source), &req);
        println!("{}", key.hex());
        return Ok(());
    }
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
        e @ RenderError::Print(_) => Failure::new(EXIT_FAILURE, format!("{file}: {e}")),
    }
}

fn run_check(args: CheckArgs) -> Result<(), Failure> {
    let limits = Limits::default();
    let source = read_source(&args.file, limits.max_source_bytes)?;
    let language = language_for(&args.file, args.language);
    // A cpfg model is checked with the files a render of it sends.
    let files = companions_of(&args.file, language, &source, limits.max_source_bytes);
    match rulemesh::pipeline::check_source_with(&source, &files, language, &limits) {
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
    Ok(rulemesh::preview::Image { size: frame.width, height: frame.height, rgba: buf })
}

/// Largest `.strips` file `decode` reads (a phone icon is a few kilobytes).
const MAX_STRIPS_BYTES: u64 = 1 << 30;

fn run_decode(args: DecodeArgs) -> Result<(), Failure> {
    let format = output_format(args.format, &args.output)?;
    let bytes = read_source(&args.file, MAX_STRIPS_BYTES)?;
    if bytes.len() as u64 > MAX_STRIPS_BYTES {
        return Err(Failure::new(EXIT_USAGE, format!("{}: larger than {MAX_STRIPS_BYTES} bytes", args.file)));
    }
    let mesh = rulemesh::decode::decode_strips(&bytes).map_err(|e| Failure::new(EXIT_FAILURE, format!("{}: {e}", args.file)))?;
    let triangles = mesh.triangle_count();
    let meshes = vec![rulemesh::geom::NamedMesh { name: "model".into(), mesh }];
    let out = rulemesh::pipeline::write_meshes(format, meshes, &Limits::ceiling()).map_err(|e| Failure::new(EXIT_FAILURE, format!("{}: {e}", args.file)))?;
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
    // `concurrency`; a few spare threads cover the disk tier's reads and writes.
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .max_blocking_threads(config.concurrency() + 4)
        .build()
        .map_err(|e| Failure::new(EXIT_FAILURE, format!("cannot start the runtime: {e}")))?;
    let telemetry = {
        // The OTLP exporter's connection is made on this runtime.
        let _entered = runtime.enter();
        rulemesh::service::access_log::set_mode(args.access_log);
        rulemesh::service::telemetry::init(args.log, args.log_format, args.otlp_endpoint.as_deref(), config.worker_id.as_deref(), args.log_buffer_lines)
            .map_err(|e| Failure::new(EXIT_FAILURE, format!("serve: {e}")))?
    };
    let served = runtime.block_on(rulemesh::service::serve(config, rulemesh::service::shutdown_signal()));
    telemetry.shutdown();
    served.map_err(|e| Failure::new(EXIT_FAILURE, format!("serve: {e}")))
}
