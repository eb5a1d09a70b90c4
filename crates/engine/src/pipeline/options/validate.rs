//! The one validator: raw [`RenderOptions`] → a [`RenderRequest`] with every
//! default filled in, every name parsed, every range checked and every
//! limit clamped to the caller's ceiling. The CLI, HTTP (body, query and
//! batch) and gRPC all call it, so a request means the same by every door,
//! and it accepts exactly what the published schema allows.

use super::{LimitsOptions, RenderOptions};
use crate::core::{Choice, Limits, OnLimit};
use crate::export::{parse_compression, ExportOptions, Format, GltfOptions, Instancing, OptionGroup, StripsOptions};
use crate::lang::Language;
use crate::mesh::MeshLayout;
use crate::preview::{PreviewOptions, View};
use crate::print::{PrintError, PrintOptions, PrinterProfile};
use crate::RenderRequest;

/// Why raw options do not make a request: the message names the option
/// and what it accepts. The service answers it as 400 `bad_request`, the
/// CLI as a usage error (exit code 2).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct InvalidOptions(pub String);

impl LimitsOptions {
    /// The defaults (a print's, [`Limits::defaults_for`], when `print`)
    /// overridden by the given fields, clamped to `ceiling`.
    pub fn resolve(&self, ceiling: &Limits, print: bool) -> Limits {
        let d = Limits::defaults_for(print);
        let LimitsOptions { max_depth, max_primitives, max_triangles, max_memory, timeout_ms, max_source_bytes, max_steps } = *self;
        Limits {
            max_depth: max_depth.unwrap_or(d.max_depth),
            max_primitives: max_primitives.unwrap_or(d.max_primitives),
            max_triangles: max_triangles.unwrap_or(d.max_triangles),
            max_memory: max_memory.unwrap_or(d.max_memory),
            timeout_ms: timeout_ms.unwrap_or(d.timeout_ms),
            max_source_bytes: max_source_bytes.unwrap_or(d.max_source_bytes),
            max_steps: max_steps.unwrap_or(d.max_steps),
        }
        .clamped_to(ceiling)
    }
}

impl RenderOptions {
    /// Validates the options into a request whose limits are clamped to
    /// `ceiling`. The request reads no files (`script_dir` is `None`; the
    /// CLI sets it afterwards).
    pub fn plan(self, ceiling: &Limits) -> Result<RenderRequest, InvalidOptions> {
        // Every field, by name: a field added to the declaration and not
        // used here is a compile error (or, bound and unused, a warning).
        let RenderOptions {
            language,
            seed,
            params,
            format,
            limits,
            on_limit,
            detail,
            frame,
            layout,
            position_bits,
            normal_bits,
            zstd,
            checksum,
            weld,
            quantize,
            compress,
            fit,
            instancing,
            print,
            size_mm,
            print_report,
            min_wall_mm,
            build_volume_mm,
            triangle_ceiling,
            size,
            view,
            background,
        } = self;
        let format = parse_format(format.as_deref())?;
        let preview = preview_options(format, size, view.as_deref(), background.as_deref())?;
        let checksum = checksum_option(format, checksum)?;
        let print = print_options(print, size_mm, print_report, min_wall_mm, build_volume_mm.as_deref(), triangle_ceiling)?;
        let strips = {
            let d = StripsOptions::default();
            let strips = StripsOptions { position_bits: position_bits.unwrap_or(d.position_bits), normal_bits: normal_bits.unwrap_or(d.normal_bits), zstd: zstd.unwrap_or(d.zstd) };
            strips.validate().map_err(InvalidOptions)?;
            strips
        };
        let gltf = GltfOptions {
            weld: weld.unwrap_or(false),
            quantize: quantize.unwrap_or(false),
            compress: parse_compression(compress.as_deref().unwrap_or("")).map_err(InvalidOptions)?,
        };
        let request = RenderRequest {
            language: parse_language(language.as_deref())?,
            seed,
            params,
            format,
            limits: limits.unwrap_or_default().resolve(ceiling, print.enabled),
            on_limit: parse_name::<OnLimit>("on_limit", on_limit.as_deref())?.unwrap_or(OnLimit::Error),
            detail: detail.unwrap_or(crate::geom::DEFAULT_DETAIL),
            layout: parse_name::<MeshLayout>("layout", layout.as_deref())?.unwrap_or(MeshLayout::Merged),
            export_options: ExportOptions {
                strips,
                gltf,
                fit_unit_box: parse_fit(fit.as_deref())?,
                instancing: parse_name::<Instancing>("instancing", instancing.as_deref())?.unwrap_or(Instancing::Gpu),
                print,
                preview,
                checksum,
            },
            script_dir: None,
            frame,
            // Content beside the source, not an option: the door that has
            // them (HTTP and gRPC bodies, the CLI's folder) sets them.
            files: Default::default(),
        };
        super::super::check_request(&request).map_err(|e| InvalidOptions(e.to_string()))?;
        Ok(request)
    }
}

/// Reads a name of a [`Choice`] enum (trimmed; absent or empty: `None`).
fn parse_name<T: Choice>(option: &str, name: Option<&str>) -> Result<Option<T>, InvalidOptions> {
    match name.map(str::trim) {
        None | Some("") => Ok(None),
        Some(n) => T::from_name(n).map(Some).ok_or_else(|| InvalidOptions(format!("unknown {option} `{n}` (known: {})", T::names().join(", ")))),
    }
}

/// Reads a language name: the registry's names (rulemesh-lang's
/// `languages!` table), case-insensitively; absent or empty: detect it.
pub fn parse_language(name: Option<&str>) -> Result<Option<Language>, InvalidOptions> {
    match name.map(str::trim) {
        None | Some("") => Ok(None),
        Some(n) => match Language::ALL.iter().copied().find(|l| l.name().eq_ignore_ascii_case(n)) {
            Some(l) => Ok(Some(l)),
            None => {
                let known: Vec<&str> = Language::ALL.iter().map(|l| l.name()).collect();
                Err(InvalidOptions(format!("unknown language `{n}` (known: {})", known.join(", "))))
            }
        },
    }
}

/// Reads a format name (also a URL extension), through the format
/// registry ([`Format::parse`]): absent or empty is the default format.
pub fn parse_format(name: Option<&str>) -> Result<Format, InvalidOptions> {
    match name.map(str::trim) {
        None | Some("") => Ok(Format::default()),
        Some(n) => Format::parse(n).ok_or_else(|| InvalidOptions(format!("unknown format `{n}` (known: {})", Format::names().join(", ")))),
    }
}

/// Reads the picture options; they need a format that reads them (the
/// registry's [`OptionGroup::Preview`]: `png`). The size range is checked
/// here too, so a bad size is refused before the request is queued.
pub fn preview_options(format: Format, size: Option<u32>, view: Option<&str>, background: Option<&str>) -> Result<PreviewOptions, InvalidOptions> {
    if format.info().options != OptionGroup::Preview && (size.is_some() || view.is_some() || background.is_some()) {
        let pictures: Vec<String> = Format::reading(OptionGroup::Preview).iter().map(|f| format!("format={}", f.name())).collect();
        return Err(InvalidOptions(format!("size, view and background need {}", pictures.join(" or "))));
    }
    let view = match view.map(str::trim) {
        None | Some("") => View::default(),
        Some(v) => View::from_name(v).ok_or_else(|| {
            let known: Vec<&str> = View::ALL.iter().map(|v| v.name()).collect();
            InvalidOptions(format!("unknown view `{v}` (known: {})", known.join(", ")))
        })?,
    };
    let background = crate::preview::parse_background(background.unwrap_or("")).map_err(InvalidOptions)?;
    let options = PreviewOptions { size: size.unwrap_or(crate::preview::DEFAULT_SIZE), view, background };
    options.validate().map_err(InvalidOptions)?;
    Ok(options)
}

/// Reads `checksum`, which needs a format that carries it (the registry's
/// [`OptionGroup::Scene`]: `scene`). Given at all with another format, it
/// is refused by name, as the schema's `dependentSchemas` refuses it: a
/// client that asks for an integrity check must not get a file without
/// one, and `false` with a format that has no such option is a mistake too.
pub(crate) fn checksum_option(format: Format, checksum: Option<bool>) -> Result<bool, InvalidOptions> {
    if format.info().options != OptionGroup::Scene && checksum.is_some() {
        let scenes: Vec<String> = Format::reading(OptionGroup::Scene).iter().map(|f| format!("format={}", f.name())).collect();
        let why = match format.info().options {
            OptionGroup::Strips => format!("format={} always ends with a CRC-32 of its own", format.name()),
            _ => format!("format={} carries none", format.name()),
        };
        return Err(InvalidOptions(format!("checksum needs {} ({why})", scenes.join(" or "))));
    }
    Ok(checksum.unwrap_or(false))
}

/// Reads a `fit` value: `"unit"` → fit the unit box; `"none"` or absent → leave the model as it is.
fn parse_fit(name: Option<&str>) -> Result<bool, InvalidOptions> {
    match name.map(str::trim) {
        None | Some("") | Some("none") => Ok(false),
        Some("unit") => Ok(true),
        Some(other) => Err(InvalidOptions(format!("unknown fit `{other}` (known: none, unit)"))),
    }
}

/// Reads the print options; the others (`size_mm`, `print_report` and the
/// printer profile) need `print`.
fn print_options(
    print: Option<bool>,
    size_mm: Option<f64>,
    report: Option<bool>,
    min_wall_mm: Option<f64>,
    build_volume_mm: Option<&[f64]>,
    triangle_ceiling: Option<u64>,
) -> Result<PrintOptions, InvalidOptions> {
    let enabled = print.unwrap_or(false);
    let profile_named = min_wall_mm.is_some() || build_volume_mm.is_some() || triangle_ceiling.is_some();
    if !enabled && (size_mm.is_some() || report == Some(true) || profile_named) {
        return Err(InvalidOptions("size_mm, print_report, min_wall_mm, build_volume_mm and triangle_ceiling need print=true".into()));
    }
    let bad = |e: PrintError| InvalidOptions(format!("print: {e}"));
    let size_um = match size_mm {
        Some(mm) => crate::print::size_um(mm).map_err(bad)?,
        None => 0,
    };
    let profile = PrinterProfile::from_request(min_wall_mm, build_volume_mm, triangle_ceiling).map_err(bad)?;
    Ok(PrintOptions { enabled, size_um, report: report.unwrap_or(false), profile })
}
