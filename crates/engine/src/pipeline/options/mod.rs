//! The render options, declared once: every option a request can carry,
//! whichever door it comes through (`rulemesh render`'s flags, the JSON body
//! of `POST /v1/render`, the URL query of `GET /v1/models/{file}`, gRPC's
//! `RenderRequest`), with what each door and the schema need to know of it.
//!
//! - [`RenderOptions`] is the raw request as a client sends it (every field
//!   optional) and, through [`RenderOptions::fields`], the table the doors
//!   read: the CLI makes its flags from it, the models route reads its query
//!   through it, and the JSON Schema ([`schema::options_schema`]) and the
//!   OpenAPI document are built from it.
//! - [`RenderOptions::plan`] (`validate.rs`) is the one validator: raw
//!   options → a [`RenderRequest`](crate::RenderRequest) with every default
//!   filled in, every name parsed and every limit clamped, for every door.
//! - The cache key (`pipeline::key`) takes the validated request apart
//!   field by field, with no `..`, so a field cannot be left out of it.
//!
//! `tests/it/options_fields.rs` walks [`RenderOptions::fields`] and checks
//! that each field reaches the CLI, the body, the query where it applies,
//! gRPC, the schema and the cache key.

use crate::core::{Choice, OnLimit, ParamValue};
use crate::lang::Language;
use serde::Deserialize;
use crate::export::Format;
use serde_json::json;
use std::collections::BTreeMap;

pub mod field;
pub mod read;
pub mod schema;
mod validate;
#[cfg(test)]
mod tests;

pub(crate) use field::declare_options;
pub use field::{Doors, Key, Kind, OptionField};
pub use read::SeedValue;
pub use validate::{parse_format, parse_language, preview_options, InvalidOptions};


/// A whole-number schema from `min` to `max`.
fn whole(min: u64, max: u64) -> serde_json::Value {
    json!({ "type": "integer", "minimum": min, "maximum": max })
}

/// `print: true`, which the printer's options need.
fn needs_print() -> Option<(&'static str, serde_json::Value)> {
    Some(("print", json!(true)))
}

/// `format: png`, which the picture's options need: the format registry's
/// picture format ([`Format::picture`]).
fn needs_png() -> Option<(&'static str, serde_json::Value)> {
    let picture = Format::picture().map_or("png", Format::name);
    Some(("format", json!(picture)))
}

/// `format: scene`, which `checksum` needs: the format registry's formats
/// that read [`OptionGroup::Scene`](crate::export::OptionGroup::Scene).
fn needs_scene() -> Option<(&'static str, serde_json::Value)> {
    let scene = Format::reading(crate::export::OptionGroup::Scene).first().map_or("scene", |f| f.name());
    Some(("format", json!(scene)))
}

declare_options! {
    /// Limits as a request gives them: every field optional; missing ones
    /// take the defaults ([`crate::core::Limits::defaults_for`]) and every
    /// one is clamped to the caller's ceiling.
    #[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize, serde::Serialize)]
    #[serde(deny_unknown_fields)]
    pub struct LimitsOptions {
        /// Deepest rule nesting.
        #[serde(default, deserialize_with = "read::whole")]
        max_depth: Option<u32> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u32::MAX.into()), example: json!(5) },
        /// Most primitives.
        #[serde(default, deserialize_with = "read::whole")]
        max_primitives: Option<u64> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u64::MAX), example: json!(1000) },
        /// Most triangles.
        #[serde(default, deserialize_with = "read::whole")]
        max_triangles: Option<u64> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u64::MAX), example: json!(100_000) },
        /// Most bytes of accounted memory (default 268435456, 256 MiB; for a
        /// print 671088640, 640 MiB, `PRINT_MAX_MEMORY`).
        #[serde(default, deserialize_with = "read::whole")]
        max_memory: Option<u64> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u64::MAX), example: json!(1 << 24) },
        /// Wall-clock limit in milliseconds.
        #[serde(default, deserialize_with = "read::whole")]
        timeout_ms: Option<u64> => {
            doors: Doors::NOT_QUERY, cli: Some("timeout"), kind: Kind::Whole, schema: whole(0, u64::MAX), example: json!(1000),
            key: Key::Unchanged("a model that finished in time is the same model under any longer timeout, and deadline-truncated models are never cached"),
        },
        /// Largest source in bytes.
        #[serde(default, deserialize_with = "read::whole")]
        max_source_bytes: Option<u64> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u64::MAX), example: json!(4096) },
        /// Most evaluation steps.
        #[serde(default, deserialize_with = "read::whole")]
        max_steps: Option<u64> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u64::MAX), example: json!(1000) },
    }
}

declare_options! {
    /// Everything a render request carries besides its source, as the
    /// client sent it: the one declaration every door reads (module docs).
    #[derive(Debug, Clone, Default, PartialEq, Deserialize, serde::Serialize)]
    #[serde(deny_unknown_fields)]
    pub struct RenderOptions {
        /// A language's name (`mdg`, `lsystem`, `eisenscript`, …); detected
        /// from the source when absent (on the command line, first from the
        /// file's extension).
        language: Option<String> => {
            doors: Doors::NOT_QUERY, kind: Kind::Text,
            schema: json!({ "enum": Language::ALL.iter().map(|l| l.name()).collect::<Vec<_>>() }),
            example: json!("eisenscript"),
        },
        /// Random seed: any 64-bit unsigned value, as a JSON number or as a
        /// decimal string (JSON numbers lose precision beyond 2^53 in most
        /// clients' parsers, so a seed such as 2^63 + 1 travels as text);
        /// absent, the grammar's own seed directive, else 0.
        #[serde(default, deserialize_with = "read::seed_number_or_text")]
        seed: Option<u64> => {
            kind: Kind::Seed, schema: schema::seed_schema(), example: json!("9223372036854775809"),
        },
        /// Grammar parameters (numbers, booleans, or text read as either;
        /// `--param NAME=VALUE` on the command line, `p.NAME=VALUE` in a URL query).
        #[serde(default)]
        params: BTreeMap<String, ParamValue> => {
            cli: Some("param"), kind: Kind::Params,
            schema: json!({ "type": "object", "additionalProperties": { "anyOf": [{ "type": "number" }, { "type": "boolean" }, { "type": "string" }] } }),
            example: json!({ "count": "2" }),
        },
        /// Output format: `glb` (default), `gltf`, `stl`, `stl-ascii`,
        /// `strips`, `scene` (instances, meshes and hierarchies;
        /// docs/scene-format.md), `3mf`, `ug` or `png` (a preview picture);
        /// on the command line, by default from the output file's extension.
        format: Option<String> => {
            doors: Doors::NOT_QUERY, kind: Kind::Text,
            schema: json!({ "enum": Format::names(), "default": Format::default().name() }), example: json!("stl"),
        },
        /// Limits, each clamped to the server's ceiling.
        #[serde(default, deserialize_with = "read::limits_object")]
        limits: Option<LimitsOptions> => {
            doors: Doors::NOT_QUERY, kind: Kind::Group(LimitsOptions::fields),
            schema: schema::group_schema(LimitsOptions::fields(), "Limits, each clamped to the server's ceiling"),
        },
        /// What to do when a limit runs out: `error` (default) or `truncate`.
        on_limit: Option<String> => {
            doors: Doors::NOT_QUERY, kind: Kind::Text,
            schema: json!({ "enum": OnLimit::names(), "default": "error" }), example: json!("truncate"),
        },
        /// Tessellation detail (segments around round primitives).
        #[serde(default, deserialize_with = "read::whole")]
        detail: Option<u32> => {
            kind: Kind::Whole,
            schema: json!({ "type": "integer", "minimum": crate::geom::MIN_DETAIL, "maximum": crate::geom::MAX_DETAIL, "default": crate::geom::DEFAULT_DETAIL }),
            example: json!(9),
        },
        /// A Structure Synth JavaScript movie only: build its k-th saved
        /// picture alone (0-based), as Structure Synth renders one picture
        /// at a time; absent, the whole movie is one animated model. Any
        /// other source is refused (`eval_error`).
        #[serde(default, deserialize_with = "read::whole")]
        frame: Option<u32> => { doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: whole(0, u32::MAX.into()), example: json!(1) },
        /// `merged` (default: one mesh) or `per-kind` (one mesh per primitive kind).
        layout: Option<String> => {
            doors: Doors::NOT_QUERY, kind: Kind::Text,
            schema: json!({ "enum": crate::mesh::MeshLayout::names(), "default": "merged" }), example: json!("per-kind"),
        },
        /// `strips` only: bits per position axis (8, 10, 12 or 16; default 16).
        #[serde(default, deserialize_with = "read::whole")]
        position_bits: Option<u8> => {
            doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: json!({ "enum": [8, 10, 12, 16], "default": 16 }),
            example: json!(12), context: json!({ "format": "strips" }),
        },
        /// `strips` only: bits per octahedral normal component (8 or 16; default 8).
        #[serde(default, deserialize_with = "read::whole")]
        normal_bits: Option<u8> => {
            doors: Doors::NOT_QUERY, kind: Kind::Whole, schema: json!({ "enum": [8, 16], "default": 8 }),
            example: json!(16), context: json!({ "format": "strips" }),
        },
        /// `strips` only: wrap the body in zstd (default false; the
        /// JavaScript decoder cannot read it).
        zstd: Option<bool> => {
            doors: Doors::NOT_QUERY, cli_flag: Some(json!(true)), kind: Kind::Bool, schema: json!({ "type": "boolean", "default": false }),
            example: json!(true), context: json!({ "format": "strips" }),
        },
        /// `scene` only: end the file with a CRC-32 of its bytes, so a
        /// decoder refuses any damaged byte (default false: the file then
        /// reads in decoders from before the checksum existed;
        /// docs/scene-format.md, "Checksum"). Refused with any other format
        /// (`strips` always carries one; the others carry none rulemesh adds).
        checksum: Option<bool> => {
            cli_flag: Some(json!(true)), kind: Kind::Bool, needs: needs_scene(),
            schema: json!({ "type": "boolean", "default": false }),
            example: json!(true), context: json!({ "format": "scene" }),
        },
        /// `glb`/`gltf` only: weld identical vertices and drop degenerate
        /// triangles (default false).
        weld: Option<bool> => { cli_flag: Some(json!(true)), kind: Kind::Bool, schema: json!({ "type": "boolean", "default": false }), example: json!(true) },
        /// `glb`/`gltf` only: `KHR_mesh_quantization`, 16-bit positions and
        /// 8-bit normals (default false; implies welding).
        quantize: Option<bool> => { cli_flag: Some(json!(true)), kind: Kind::Bool, schema: json!({ "type": "boolean", "default": false }), example: json!(true) },
        /// `glb`/`gltf` only: buffer compression, `none` (default) or
        /// `meshopt` (`EXT_meshopt_compression`; implies welding).
        compress: Option<String> => {
            kind: Kind::Text, schema: json!({ "enum": crate::export::Compression::names(), "default": "none" }), example: json!("meshopt"),
        },
        /// `unit`: scale and move the model into a unit box centred at the
        /// origin (every format; on the command line `--fit-unit-box`);
        /// `none` (default) leaves it.
        fit: Option<String> => {
            cli: Some("fit-unit-box"), cli_flag: Some(json!("unit")), kind: Kind::Text,
            schema: json!({ "enum": ["none", "unit"], "default": "none" }), example: json!("unit"),
        },
        /// `glb`/`gltf`: `gpu` (default: each mesh placed more than once is
        /// written once, `EXT_mesh_gpu_instancing`) or `flat` (plain meshes,
        /// for loaders without the extension; the default for phones over
        /// HTTP, docs/loaders.md).
        instancing: Option<String> => {
            kind: Kind::Text,
            schema: json!({ "enum": crate::export::Instancing::names(), "default": "gpu" }), example: json!("flat"),
        },
        /// Merge every part into one watertight, outward-oriented solid in
        /// millimetres for 3D printing (default false; docs/print.md).
        print: Option<bool> => {
            cli_flag: Some(json!(true)), kind: Kind::Bool, schema: json!({ "type": "boolean", "default": false }),
            example: json!(true), context: json!({ "format": "stl" }),
        },
        /// With `print`: scale so the longest side is this many millimetres
        /// (default: one unit is 1 mm).
        size_mm: Option<f64> => {
            kind: Kind::Number, schema: json!({ "type": "number", "exclusiveMinimum": 0, "maximum": 10000 }), needs: needs_print(),
            example: json!(50), context: json!({ "format": "stl", "print": true }),
        },
        /// With `print`: answer with the JSON printability report instead of the model.
        print_report: Option<bool> => {
            cli_flag: Some(json!(true)), kind: Kind::Bool, schema: json!({ "type": "boolean", "default": false }), needs: needs_print(),
            example: json!(true), context: json!({ "format": "stl", "print": true }),
        },
        /// With `print`: the printer's thinnest wall or feature in
        /// millimetres, in (0, 100] (default 0.8); thinner walls are
        /// reported as `thin_wall` and open surfaces are thickened to it.
        min_wall_mm: Option<f64> => {
            kind: Kind::Number, needs: needs_print(),
            schema: json!({ "type": "number", "exclusiveMinimum": 0, "maximum": crate::print::profile::MAX_MIN_WALL_MM, "default": f64::from(crate::print::profile::DEFAULT_MIN_WALL_UM) / 1000.0 }),
            example: json!(0.4), context: json!({ "format": "stl", "print": true }),
        },
        /// With `print`: the printer's build volume x, y, z in millimetres,
        /// each in (0, 10000] (default 250, 210, 210; `XxYxZ` as text); a
        /// larger model is reported as `too_big`.
        build_volume_mm: Option<Vec<f64>> => {
            kind: Kind::Volume, needs: needs_print(),
            schema: json!({
                "type": "array",
                "items": { "type": "number", "exclusiveMinimum": 0, "maximum": crate::print::profile::MAX_BUILD_MM },
                "minItems": 3,
                "maxItems": 3,
                "default": crate::print::profile::DEFAULT_BUILD_UM.map(|v| f64::from(v) / 1000.0)
            }),
            example: json!([100.0, 100.0, 80.0]), context: json!({ "format": "stl", "print": true }),
        },
        /// With `print`: the most triangles the printer accepts, 1 to 10⁸
        /// (default 1,000,000); more are reported as `too_many_triangles`.
        #[serde(default, deserialize_with = "read::whole")]
        triangle_ceiling: Option<u64> => {
            kind: Kind::Whole, needs: needs_print(),
            schema: json!({ "type": "integer", "minimum": 1, "maximum": crate::print::profile::MAX_TRIANGLE_CEILING, "default": crate::print::profile::DEFAULT_TRIANGLE_CEILING }),
            example: json!(5000), context: json!({ "format": "stl", "print": true }),
        },
        /// `png` only: width and height in pixels (16–2048, default 256).
        #[serde(default, deserialize_with = "read::whole")]
        size: Option<u32> => {
            kind: Kind::Whole, needs: needs_png(),
            schema: json!({ "type": "integer", "minimum": crate::preview::MIN_SIZE, "maximum": crate::preview::MAX_SIZE, "default": crate::preview::DEFAULT_SIZE }),
            example: json!(64), context: json!({ "format": "png" }),
        },
        /// `png` only: where the camera looks from, `three-quarter`
        /// (default), `front`, `top` or `iso`.
        view: Option<String> => {
            kind: Kind::Text, needs: needs_png(),
            schema: json!({ "enum": crate::preview::View::names(), "default": crate::preview::View::default().name() }),
            example: json!("top"), context: json!({ "format": "png" }),
        },
        /// `png` only: `transparent` (default) or an opaque `#rrggbb`.
        background: Option<String> => {
            kind: Kind::Text, needs: needs_png(),
            schema: json!({ "type": "string", "pattern": "^\\s*(|[Tt][Rr][Aa][Nn][Ss][Pp][Aa][Rr][Ee][Nn][Tt]|#?[0-9A-Fa-f]{6})\\s*$", "default": "transparent" }),
            example: json!("#ff8000"), context: json!({ "format": "png" }),
        },
    }
}
