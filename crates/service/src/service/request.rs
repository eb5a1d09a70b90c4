//! Requests in two stages, shared by HTTP and gRPC: a raw request exactly as
//! the client sent it ([`RenderBody`]), and a validated [`RenderPlan`] with
//! every default filled in, every limit clamped and the cache key computed.

use super::ServiceError;
use crate::pipeline::key::{cache_key, normalize_source};
use crate::cache::CacheKey;
use crate::core::{Limits, OnLimit, ParamValue};
use crate::export::{compact::parse_compression, ExportOptions, Format, GltfOptions, Instancing, StripsOptions};
use crate::geom::DEFAULT_DETAIL;
use crate::mesh::MeshLayout;
use crate::lang::Language;
use crate::preview::{PreviewOptions, View};
use crate::RenderRequest;
use serde::Deserialize;
use utoipa::ToSchema;
use std::collections::BTreeMap;
use std::sync::Arc;

/// `f` as a `u64` when it is a whole number from 0 to 2^64 − 1 (`8.0`):
/// JSON Schema's `integer` admits such numbers, so the server reads them.
fn integral_u64(f: f64) -> Option<u64> {
    (f.fract() == 0.0 && (0.0..18_446_744_073_709_551_616.0).contains(&f)).then_some(f as u64)
}

/// Reads an optional whole number sent as a JSON integer or as a number
/// with no fraction (`8.0`): JSON Schema's `integer`, which the published
/// schemas use, admits both, so the server must too. Null reads as absent.
fn whole<'de, D, T>(d: D) -> Result<Option<T>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: TryFrom<u64>,
{
    let Some(n) = Option::<serde_json::Number>::deserialize(d)? else { return Ok(None) };
    let value = n.as_u64().or_else(|| n.as_f64().and_then(integral_u64));
    match value.map(T::try_from) {
        Some(Ok(v)) => Ok(Some(v)),
        Some(Err(_)) => Err(serde::de::Error::custom(format!("{n} is out of range"))),
        None => Err(serde::de::Error::custom(format!("{n} is not a whole number ≥ 0"))),
    }
}

/// Reads `limits` as a JSON object only: serde would also read a struct
/// from an array of its fields in order, which the published schema (an
/// object) does not allow. Null reads as absent.
fn limits_object<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<LimitsBody>, D::Error> {
    match Option::<serde_json::Map<String, serde_json::Value>>::deserialize(d)? {
        None => Ok(None),
        Some(map) => serde_json::from_value(serde_json::Value::Object(map)).map(Some).map_err(serde::de::Error::custom),
    }
}

/// Client-supplied limits: every field optional, missing ones take the defaults.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LimitsBody {
    /// [`Limits::max_depth`]
    #[serde(default, deserialize_with = "whole")]
    pub max_depth: Option<u32>,
    /// [`Limits::max_primitives`]
    #[serde(default, deserialize_with = "whole")]
    pub max_primitives: Option<u64>,
    /// [`Limits::max_triangles`]
    #[serde(default, deserialize_with = "whole")]
    pub max_triangles: Option<u64>,
    /// [`Limits::max_memory`] (default 256 MiB; 640 MiB for a print, [`crate::core::budget::PRINT_MAX_MEMORY`])
    #[serde(default, deserialize_with = "whole")]
    pub max_memory: Option<u64>,
    /// [`Limits::timeout_ms`]
    #[serde(default, deserialize_with = "whole")]
    pub timeout_ms: Option<u64>,
    /// [`Limits::max_source_bytes`]
    #[serde(default, deserialize_with = "whole")]
    pub max_source_bytes: Option<u64>,
    /// [`Limits::max_steps`]
    #[serde(default, deserialize_with = "whole")]
    pub max_steps: Option<u64>,
}

impl LimitsBody {
    /// The defaults (a print's, [`Limits::defaults_for`], when `print`)
    /// overridden by the given fields, clamped to `ceiling`.
    pub fn resolve(&self, ceiling: &Limits, print: bool) -> Limits {
        let d = Limits::defaults_for(print);
        Limits {
            max_depth: self.max_depth.unwrap_or(d.max_depth),
            max_primitives: self.max_primitives.unwrap_or(d.max_primitives),
            max_triangles: self.max_triangles.unwrap_or(d.max_triangles),
            max_memory: self.max_memory.unwrap_or(d.max_memory),
            timeout_ms: self.timeout_ms.unwrap_or(d.timeout_ms),
            max_source_bytes: self.max_source_bytes.unwrap_or(d.max_source_bytes),
            max_steps: self.max_steps.unwrap_or(d.max_steps),
        }
        .clamped_to(ceiling)
    }
}

/// The JSON shape of a grammar parameter's value (for the OpenAPI document;
/// requests are read as [`ParamValue`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize, ToSchema)]
#[serde(untagged)]
#[schema(as = ParamValue)]
pub enum ParamValueSchema {
    /// A number.
    Number(f64),
    /// A boolean.
    Bool(bool),
    /// Text read as a number or `true`/`false`.
    Text(String),
}

/// The JSON shape of a seed (for the OpenAPI document; requests are read
/// by [`seed_number_or_text`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize, ToSchema)]
#[serde(untagged)]
#[schema(as = Seed)]
pub enum SeedSchema {
    /// A whole number from 0 to 2^64 − 1.
    Number(u64),
    /// The same as decimal digits (up to 20).
    Text(String),
}

/// Reads a seed given as a JSON number or a decimal string, refusing
/// negatives, fractions and values beyond 2^64 − 1 with a message.
fn seed_number_or_text<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<u64>, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Raw {
        Number(u64),
        // An integral float (`5.0`): JSON Schema's `integer` admits it.
        Float(f64),
        Text(String),
    }
    match Option::<Raw>::deserialize(d) {
        Ok(None) => Ok(None),
        Ok(Some(Raw::Number(n))) => Ok(Some(n)),
        Ok(Some(Raw::Float(f))) => integral_u64(f).map(Some).ok_or_else(|| serde::de::Error::custom(format!("seed {f} is not a whole number from 0 to 2^64 - 1"))),
        Ok(Some(Raw::Text(t))) if !t.is_empty() && t.len() <= 20 && t.bytes().all(|b| b.is_ascii_digit()) => {
            t.parse().map(Some).map_err(|_| serde::de::Error::custom(format!("seed `{t}` is beyond 2^64 - 1")))
        }
        Ok(Some(Raw::Text(t))) => Err(serde::de::Error::custom(format!("seed `{t}` is not a whole number from 0 to 2^64 - 1"))),
        Err(_) => Err(serde::de::Error::custom("seed must be a whole number from 0 to 2^64 - 1, as a number or a decimal string")),
    }
}

/// One seed of a list (the batch route's `seeds`), read like `seed`: a
/// JSON number or a decimal string, 0 to 2^64 − 1, never null.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SeedValue(pub u64);

impl<'de> Deserialize<'de> for SeedValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        seed_number_or_text(d)?.map(SeedValue).ok_or_else(|| serde::de::Error::custom("a seed in a list must not be null"))
    }
}

/// `POST /v1/render` as sent (and the gRPC `RenderRequest`, converted).
#[derive(Debug, Clone, Default, PartialEq, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RenderBody {
    /// Grammar source.
    pub source: String,
    /// A language's name (`"mdg"`, `"lsystem"`, `"eisenscript"`, …, `Language::ALL`); detected from the source when absent.
    pub language: Option<String>,
    /// Random seed: any 64-bit unsigned value, as a JSON number or as a
    /// decimal string (JSON numbers lose precision beyond 2^53 in most
    /// clients' parsers, so a seed such as 2^63 + 1 travels as text).
    #[serde(default, deserialize_with = "seed_number_or_text")]
    #[schema(value_type = Option<SeedSchema>)]
    pub seed: Option<u64>,
    /// Grammar parameters (numbers, booleans, or text read as either).
    #[serde(default)]
    #[schema(value_type = BTreeMap<String, ParamValueSchema>)]
    pub params: BTreeMap<String, ParamValue>,
    /// `"glb"` (default), `"gltf"`, `"stl"`, `"stl-ascii"`, `"strips"`,
    /// `"scene"` (instances, meshes and hierarchies; docs/scene-format.md), `"3mf"`,
    /// `"ug"` or `"png"` (a preview picture).
    pub format: Option<String>,
    /// Limits, each clamped to the server's ceiling.
    #[serde(default, deserialize_with = "limits_object")]
    pub limits: Option<LimitsBody>,
    /// `"error"` (default) or `"truncate"`.
    pub on_limit: Option<String>,
    /// Tessellation detail.
    #[serde(default, deserialize_with = "whole")]
    pub detail: Option<u32>,
    /// A Structure Synth JavaScript movie only: build its k-th saved
    /// picture alone (0-based), as Structure Synth renders one picture at a
    /// time; absent, the whole movie is one animated model. Any other source
    /// answers 400 `eval_error`.
    #[serde(default, deserialize_with = "whole")]
    pub frame: Option<u32>,
    /// `"merged"` (default) or `"per-kind"`.
    pub layout: Option<String>,
    /// `strips` only: bits per position axis (8, 10, 12 or 16; default 16).
    #[serde(default, deserialize_with = "whole")]
    pub position_bits: Option<u8>,
    /// `strips` only: bits per normal component (8 or 16; default 8).
    #[serde(default, deserialize_with = "whole")]
    pub normal_bits: Option<u8>,
    /// `strips` only: wrap the body in zstd (default false).
    pub zstd: Option<bool>,
    /// `glb`/`gltf` only: weld identical vertices (default false).
    pub weld: Option<bool>,
    /// `glb`/`gltf` only: `KHR_mesh_quantization` (default false).
    pub quantize: Option<bool>,
    /// `glb`/`gltf` only: `"none"` (default) or `"meshopt"` (`EXT_meshopt_compression`).
    pub compress: Option<String>,
    /// `"unit"`: scale and move the model into a unit box centred at the origin; `"none"` (default) leaves it.
    pub fit: Option<String>,
    /// `glb`/`gltf`: `"gpu"` (default: each mesh placed more than once is
    /// written once, `EXT_mesh_gpu_instancing`) or `"flat"` (plain meshes,
    /// for loaders without the extension).
    pub instancing: Option<String>,
    /// Merge every part into one watertight solid in millimetres for 3D printing (default false).
    pub print: Option<bool>,
    /// With `print`: scale so the longest side is this many millimetres (default: one unit is 1 mm).
    pub size_mm: Option<f64>,
    /// With `print`: answer with the JSON printability report instead of the model.
    pub print_report: Option<bool>,
    /// With `print`: the printer's thinnest wall or feature in millimetres,
    /// in (0, 100] (default 0.8); thinner walls are reported as `thin_wall`
    /// and open surfaces are thickened to it.
    pub min_wall_mm: Option<f64>,
    /// With `print`: the printer's build volume x, y, z in millimetres, each
    /// in (0, 10000] (default [250, 210, 210]); a larger model is reported as `too_big`.
    pub build_volume_mm: Option<Vec<f64>>,
    /// With `print`: the most triangles the printer accepts, 1 to 10⁸
    /// (default 1,000,000); more are reported as `too_many_triangles`.
    #[serde(default, deserialize_with = "whole")]
    pub triangle_ceiling: Option<u64>,
    /// `png` only: width and height in pixels (16–2048, default 256).
    #[serde(default, deserialize_with = "whole")]
    pub size: Option<u32>,
    /// `png` only: `"three-quarter"` (default), `"front"`, `"top"` or `"iso"`.
    pub view: Option<String>,
    /// `png` only: `"transparent"` (default) or an opaque `"#rrggbb"`.
    pub background: Option<String>,
    /// Named files beside the source (a cpfg model's `.v`, `.a`, `.map` and
    /// `#include`s, docs/cpfg.md): name → text, or `base64:` and the bytes.
    /// They count against `max_source_bytes` and are part of the cache key.
    #[serde(default)]
    pub files: BTreeMap<String, String>,
}

/// `POST /v1/check` as sent.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CheckBody {
    /// Grammar source.
    pub source: String,
    /// A language's name (`"mdg"`, `"lsystem"`, `"eisenscript"`, …, `Language::ALL`); detected from the source when absent.
    pub language: Option<String>,
}

/// A validated render: what to render, how, and under which cache key.
#[derive(Debug, Clone)]
pub struct RenderPlan {
    /// The source with line endings normalised.
    pub source: Arc<[u8]>,
    /// The pipeline request.
    pub request: RenderRequest,
    /// The cache key.
    pub key: CacheKey,
    /// Render afresh, ignoring the cache.
    pub no_cache: bool,
}

/// Reads a language name.
pub fn parse_language(name: Option<&str>) -> Result<Option<Language>, ServiceError> {
    // The registry's names (rulemesh-lang's `languages!` table), case-insensitively.
    match name.map(str::trim) {
        None | Some("") => Ok(None),
        Some(n) => match Language::ALL.iter().copied().find(|l| l.name().eq_ignore_ascii_case(n)) {
            Some(l) => Ok(Some(l)),
            None => {
                let known: Vec<&str> = Language::ALL.iter().map(|l| l.name()).collect();
                Err(ServiceError::BadRequest(format!("unknown language `{n}` (known: {})", known.join(", "))))
            }
        },
    }
}

/// Reads a format name (also a URL extension).
pub fn parse_format(name: Option<&str>) -> Result<Format, ServiceError> {
    match name.map(|s| s.trim().to_ascii_lowercase()).as_deref() {
        None | Some("") | Some("glb") => Ok(Format::Glb),
        Some("gltf") => Ok(Format::Gltf),
        Some("stl") => Ok(Format::Stl),
        Some("stl-ascii") => Ok(Format::StlAscii),
        Some("strips") => Ok(Format::Strips),
        Some("scene") | Some("rmscene") => Ok(Format::Scene),
        Some("3mf") => Ok(Format::ThreeMf),
        Some("ug") => Ok(Format::Ug),
        Some("png") => Ok(Format::Png),
        Some(other) => {
            let known: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
            Err(ServiceError::BadRequest(format!("unknown format `{other}` (known: {})", known.join(", "))))
        }
    }
}

/// Reads the `png` fields; they need `format=png`. The size range is checked here too,
/// so a bad size is refused before the request is queued.
pub fn preview_options(format: Format, size: Option<u32>, view: Option<&str>, background: Option<&str>) -> Result<PreviewOptions, ServiceError> {
    if format != Format::Png && (size.is_some() || view.is_some() || background.is_some()) {
        return Err(ServiceError::BadRequest("size, view and background need format=png".into()));
    }
    let view = match view.map(str::trim) {
        None | Some("") => View::default(),
        Some(v) => View::from_name(v).ok_or_else(|| {
            let known: Vec<&str> = View::ALL.iter().map(|v| v.name()).collect();
            ServiceError::BadRequest(format!("unknown view `{v}` (known: {})", known.join(", ")))
        })?,
    };
    let background = crate::preview::parse_background(background.unwrap_or("")).map_err(ServiceError::BadRequest)?;
    let options = PreviewOptions { size: size.unwrap_or(crate::preview::DEFAULT_SIZE), view, background };
    options.validate().map_err(ServiceError::BadRequest)?;
    Ok(options)
}

fn parse_on_limit(name: Option<&str>) -> Result<OnLimit, ServiceError> {
    match name.map(str::trim) {
        None | Some("") | Some("error") => Ok(OnLimit::Error),
        Some("truncate") => Ok(OnLimit::Truncate),
        Some(other) => Err(ServiceError::BadRequest(format!("unknown on_limit `{other}` (known: error, truncate)"))),
    }
}

fn parse_layout(name: Option<&str>) -> Result<MeshLayout, ServiceError> {
    match name.map(str::trim) {
        None | Some("") | Some("merged") => Ok(MeshLayout::Merged),
        Some("per-kind") => Ok(MeshLayout::PerKind),
        Some(other) => Err(ServiceError::BadRequest(format!("unknown layout `{other}` (known: merged, per-kind)"))),
    }
}

/// Reads an `instancing` value: `"gpu"` (default) or `"flat"`.
pub fn parse_instancing(name: Option<&str>) -> Result<Instancing, ServiceError> {
    match name.map(str::trim) {
        None | Some("") | Some("gpu") => Ok(Instancing::Gpu),
        Some("flat") => Ok(Instancing::Flat),
        Some(other) => Err(ServiceError::BadRequest(format!("unknown instancing `{other}` (known: gpu, flat)"))),
    }
}

/// Reads a `fit` value: `"unit"` → fit the unit box; `"none"` or absent → leave the model as it is.
pub fn parse_fit(name: Option<&str>) -> Result<bool, ServiceError> {
    match name.map(str::trim) {
        None | Some("") | Some("none") => Ok(false),
        Some("unit") => Ok(true),
        Some(other) => Err(ServiceError::BadRequest(format!("unknown fit `{other}` (known: none, unit)"))),
    }
}

/// Reads the print fields of `body`; the others (`size_mm`, `print_report`
/// and the printer profile) need `print`.
pub fn print_options(body: &RenderBody) -> Result<crate::print::PrintOptions, ServiceError> {
    let enabled = body.print.unwrap_or(false);
    let profile_named = body.min_wall_mm.is_some() || body.build_volume_mm.is_some() || body.triangle_ceiling.is_some();
    if !enabled && (body.size_mm.is_some() || body.print_report == Some(true) || profile_named) {
        return Err(ServiceError::BadRequest("size_mm, print_report, min_wall_mm, build_volume_mm and triangle_ceiling need print=true".into()));
    }
    let bad = |e: crate::print::PrintError| ServiceError::BadRequest(format!("print: {e}"));
    let size_um = match body.size_mm {
        Some(mm) => crate::print::size_um(mm).map_err(bad)?,
        None => 0,
    };
    let profile = crate::print::PrinterProfile::from_request(body.min_wall_mm, body.build_volume_mm.as_deref(), body.triangle_ceiling).map_err(bad)?;
    Ok(crate::print::PrintOptions { enabled, size_um, report: body.print_report.unwrap_or(false), profile })
}

impl RenderBody {
    /// Validates the request against the server's `ceiling`.
    pub fn plan(self, ceiling: &Limits, no_cache: bool) -> Result<RenderPlan, ServiceError> {
        let format = parse_format(self.format.as_deref())?;
        let preview = preview_options(format, self.size, self.view.as_deref(), self.background.as_deref())?;
        let print = print_options(&self)?;
        let request = RenderRequest {
            language: parse_language(self.language.as_deref())?,
            seed: self.seed,
            params: self.params,
            format,
            limits: self.limits.unwrap_or_default().resolve(ceiling, print.enabled),
            on_limit: parse_on_limit(self.on_limit.as_deref())?,
            detail: self.detail.unwrap_or(DEFAULT_DETAIL),
            layout: parse_layout(self.layout.as_deref())?,
            export_options: {
                let d = StripsOptions::default();
                let strips = StripsOptions {
                    position_bits: self.position_bits.unwrap_or(d.position_bits),
                    normal_bits: self.normal_bits.unwrap_or(d.normal_bits),
                    zstd: self.zstd.unwrap_or(d.zstd),
                };
                strips.validate().map_err(ServiceError::BadRequest)?;
                let gltf = GltfOptions {
                    weld: self.weld.unwrap_or(false),
                    quantize: self.quantize.unwrap_or(false),
                    compress: parse_compression(self.compress.as_deref().unwrap_or("")).map_err(ServiceError::BadRequest)?,
                };
                let fit_unit_box = parse_fit(self.fit.as_deref())?;
                let instancing = parse_instancing(self.instancing.as_deref())?;
                ExportOptions { strips, gltf, fit_unit_box, instancing, print, preview }
            },
            // The service reads no files: Builder.load takes library grammars only.
            script_dir: None,
            frame: self.frame,
            files: decode_files(self.files)?,
        };
        crate::pipeline::check_request(&request).map_err(|e| ServiceError::BadRequest(e.to_string()))?;
        let source: Arc<[u8]> = normalize_source(self.source.as_bytes()).into();
        let key = cache_key(&source, &request);
        Ok(RenderPlan { source, request, key, no_cache })
    }
}

/// Reads a JSON body into `T`, with serde's message (and position) on failure.
pub fn from_json<T: serde::de::DeserializeOwned>(body: &[u8]) -> Result<T, ServiceError> {
    serde_json::from_slice(body).map_err(|e| ServiceError::BadRequest(format!("malformed JSON request: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_and_clamping() {
        let body: RenderBody = from_json(br#"{"source":"startshape A","limits":{"max_primitives":999999999999}}"#).expect("parses");
        let plan = body.plan(&Limits { max_primitives: 1000, ..Limits::ceiling() }, false).expect("valid");
        assert_eq!(plan.request.limits.max_primitives, 1000);
        assert_eq!(plan.request.format, Format::Glb);
        assert_eq!(plan.request.detail, DEFAULT_DETAIL);
    }

    #[test]
    fn bad_fields_are_bad_requests() {
        for bad in [
            r#"{"source":"x","format":"obj"}"#,
            r#"{"source":"x","language":"cfdg"}"#,
            r#"{"source":"x","on_limit":"maybe"}"#,
            r#"{"source":"x","layout":"spread"}"#,
            r#"{"source":"x","format":"png","size":8}"#,
            r#"{"source":"x","format":"png","size":4096}"#,
            r#"{"source":"x","format":"png","view":"side"}"#,
            r#"{"source":"x","format":"png","background":"red"}"#,
            r#"{"source":"x","format":"glb","size":64}"#,
        ] {
            let body: RenderBody = from_json(bad.as_bytes()).expect("json ok");
            assert!(matches!(body.plan(&Limits::ceiling(), false), Err(ServiceError::BadRequest(_))), "{bad}");
        }
        for bad in [
            r#"{"source":1}"#,
            r#"{"src":"x"}"#,
            r#"{"source":"x","seed":-1}"#,
            r#"{"source":"x","seed":1.5}"#,
            r#"{"source":"x","seed":"-1"}"#,
            r#"{"source":"x","seed":"18446744073709551616"}"#,
            r#"{"source":"x","seed":"0x10"}"#,
            "{",
            r#"{"source":"x","limits":{"max_foo":1}}"#,
        ] {
            assert!(matches!(from_json::<RenderBody>(bad.as_bytes()), Err(ServiceError::BadRequest(_))), "{bad}");
        }
    }

    #[test]
    fn seeds_are_64_bit_as_numbers_or_decimal_text() {
        let seed = |json: &str| from_json::<RenderBody>(json.as_bytes()).expect("parses").seed;
        assert_eq!(seed(r#"{"source":"x","seed":9223372036854775809}"#), Some((1 << 63) + 1));
        assert_eq!(seed(r#"{"source":"x","seed":"9223372036854775809"}"#), Some((1 << 63) + 1));
        assert_eq!(seed(r#"{"source":"x","seed":"18446744073709551615"}"#), Some(u64::MAX));
        assert_eq!(seed(r#"{"source":"x","seed":null}"#), None);
        assert_eq!(seed(r#"{"source":"x"}"#), None);
    }

    #[test]
    fn png_options_are_read() {
        let body: RenderBody = from_json(br##"{"source":"x","format":"png","size":64,"view":"iso","background":"#ff8000"}"##).expect("json");
        let plan = body.plan(&Limits::ceiling(), false).expect("valid");
        assert_eq!(plan.request.format, Format::Png);
        assert_eq!(plan.request.export_options.preview, PreviewOptions { size: 64, view: View::Iso, background: Some([255, 128, 0]) });
        let plain: RenderBody = from_json(br#"{"source":"x","format":"png"}"#).expect("json");
        assert_eq!(plain.plan(&Limits::ceiling(), false).expect("valid").request.export_options.preview, PreviewOptions::default());
    }

    #[test]
    fn crlf_and_lf_share_a_key() {
        let a: RenderBody = from_json(br#"{"source":"startshape A\r\nrule A { BOX {} }\r\n"}"#).expect("json");
        let b: RenderBody = from_json(br#"{"source":"startshape A\nrule A { BOX {} }\n"}"#).expect("json");
        assert_eq!(a.plan(&Limits::ceiling(), false).expect("a").key, b.plan(&Limits::ceiling(), false).expect("b").key);
    }
}

/// The body's `files` as bytes: text as UTF-8, `base64:…` decoded (a
/// value that is not valid base64 after the prefix is text). Names are only
/// keys the front end looks up (nothing is read from disk), so any is kept.
fn decode_files(files: BTreeMap<String, String>) -> Result<BTreeMap<String, Vec<u8>>, ServiceError> {
    use base64::Engine as _;
    Ok(files
        .into_iter()
        .map(|(name, text)| {
            let decoded = text.strip_prefix("base64:").and_then(|b| base64::engine::general_purpose::STANDARD.decode(b.trim()).ok());
            (name, decoded.unwrap_or_else(|| text.into_bytes()))
        })
        .collect())
}
