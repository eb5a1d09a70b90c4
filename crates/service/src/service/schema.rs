//! JSON Schemas (draft 2020-12) of render requests for one grammar: its
//! declared parameters (types, defaults, ranges, named presets) and every
//! render option, so a client (the playground, an app's settings screen)
//! can build a form and check a request before sending it.
//!
//! Served by `GET /v1/grammars/{name}/schema` and `POST /v1/schema`. A
//! document valid against the schema, with `source` (and `language`) added,
//! is a `POST /v1/render` body the server accepts as far as parameters and
//! options go: the bounds here are the ones the request parser and the
//! pipeline enforce (`tests/it/schema.rs` checks both sides with a JSON
//! Schema validator). Written by hand with `serde_json::json!` because the
//! options' allowed values (format names, bit depths, ranges) are rules of
//! the parser, not of the Rust types utoipa sees; a test keeps the two in
//! step (every field of [`RenderBody`](super::request::RenderBody) is here).

use crate::lang::eisen::LINE_RADIUS_PARAM;
use crate::lang::ir::{ParamDecl, ParamKind};
use crate::lang::Language;
use serde_json::{json, Map, Value};

/// The dialect every schema declares.
pub const DIALECT: &str = "https://json-schema.org/draft/2020-12/schema";

/// The request schema for a grammar called `title` in `language` with the
/// parameters `params` (in declaration order).
pub fn render_schema(title: &str, description: &str, language: Language, params: &[ParamDecl]) -> Value {
    let mut properties = Map::new();
    for p in params {
        properties.insert(p.name.clone(), param_schema(p));
    }
    if language == Language::Eisenscript {
        // Not declared by scripts: the half-thickness of lines, grid edges and dots.
        properties.insert(
            LINE_RADIUS_PARAM.to_string(),
            json!({
                "type": "number", "exclusiveMinimum": 0, "maximum": 0.5,
                "default": crate::lang::eisen::build::DEFAULT_LINE_RADIUS,
                "description": "Half-thickness of lines, grid edges and dots"
            }),
        );
    }
    let mut options = options();
    if let Some(props) = options.get_mut("properties").and_then(Value::as_object_mut) {
        props.insert(
            "params".to_string(),
            json!({
                "type": "object",
                "description": "The grammar's parameters; missing ones take their defaults",
                "properties": properties,
                "additionalProperties": false
            }),
        );
    }
    let mut schema = json!({
        "$schema": DIALECT,
        "title": title,
        "description": description,
        "x-rulemesh-language": language.name(),
    });
    if let (Some(s), Some(o)) = (schema.as_object_mut(), options.as_object()) {
        s.extend(o.clone());
    }
    schema
}

/// One parameter: its JSON type, default and bounds; named presets may be
/// given by name or index.
fn param_schema(p: &ParamDecl) -> Value {
    let mut s = match p.kind {
        ParamKind::Int => json!({ "type": "integer", "default": p.default as i64 }),
        ParamKind::Float => json!({ "type": "number", "default": number(p.default) }),
        // Booleans are also accepted as 0 and 1.
        ParamKind::Bool => json!({ "anyOf": [{ "type": "boolean" }, { "enum": [0, 1] }], "default": p.default != 0.0 }),
    };
    if let (Some((lo, hi)), Some(o)) = (p.range, s.as_object_mut()) {
        if p.kind != ParamKind::Bool {
            o.insert("minimum".into(), number(lo));
            o.insert("maximum".into(), number(hi));
        }
    }
    if !p.choices.is_empty() {
        // A preset's name stands for its index.
        let by_index = s.clone();
        s = json!({
            "anyOf": [{ "enum": p.choices }, by_index],
            "default": p.choices.get(p.default as usize).cloned().map_or(Value::from(p.default), Value::from),
            "x-rulemesh-presets": p.choices,
        });
    }
    s
}

/// A bound as a JSON number: integral values as integers (so an integer
/// parameter's bounds read as integers).
fn number(v: f64) -> Value {
    if v.fract() == 0.0 && v.abs() < 9.0e15 {
        Value::from(v as i64)
    } else {
        Value::from(v)
    }
}

/// The render options of `POST /v1/render` (every field but `source`,
/// `language` and `params`), with the values the parser accepts.
fn options() -> Value {
    let formats = ["glb", "gltf", "stl", "stl-ascii", "strips", "scene", "3mf", "ug", "png"];
    let views: Vec<&str> = crate::preview::View::ALL.iter().map(|v| v.name()).collect();
    json!({
        "type": "object",
        "additionalProperties": false,
        "properties": {
            "source": { "type": "string", "description": "Grammar source (added by the client; the schema is about the rest)" },
            "language": { "enum": Language::ALL.iter().map(|l| l.name()).collect::<Vec<_>>() },
            "seed": {
                "description": "Random seed: any 64-bit unsigned value, as a number or (beyond 2^53, where JSON numbers lose precision) a decimal string",
                "anyOf": [
                    { "type": "integer", "minimum": 0, "maximum": u64::MAX },
                    { "type": "string", "pattern": "^[0-9]{1,20}$" }
                ]
            },
            "format": { "enum": formats, "default": "glb" },
            "limits": {
                "type": "object",
                "additionalProperties": false,
                "description": "Limits, each clamped to the server's ceiling",
                "properties": {
                    "max_depth": { "type": "integer", "minimum": 0, "maximum": u32::MAX },
                    "max_primitives": { "type": "integer", "minimum": 0 },
                    "max_triangles": { "type": "integer", "minimum": 0 },
                    "max_memory": { "type": "integer", "minimum": 0 },
                    "timeout_ms": { "type": "integer", "minimum": 0 },
                    "max_source_bytes": { "type": "integer", "minimum": 0 },
                    "max_steps": { "type": "integer", "minimum": 0 }
                }
            },
            "on_limit": { "enum": ["error", "truncate"], "default": "error" },
            "detail": { "type": "integer", "minimum": crate::geom::MIN_DETAIL, "maximum": crate::geom::MAX_DETAIL, "default": crate::geom::DEFAULT_DETAIL },
            "layout": { "enum": ["merged", "per-kind"], "default": "merged" },
            "frame": { "type": "integer", "minimum": 0, "maximum": u32::MAX },
            "position_bits": { "enum": [8, 10, 12, 16], "default": 16 },
            "normal_bits": { "enum": [8, 16], "default": 8 },
            "zstd": { "type": "boolean", "default": false },
            "weld": { "type": "boolean", "default": false },
            "quantize": { "type": "boolean", "default": false },
            "compress": { "enum": ["none", "meshopt"], "default": "none" },
            "fit": { "enum": ["none", "unit"], "default": "none" },
            "instancing": { "enum": ["gpu", "flat"], "default": "gpu" },
            "print": { "type": "boolean", "default": false },
            "size_mm": { "type": "number", "exclusiveMinimum": 0, "maximum": 10000 },
            "print_report": { "type": "boolean", "default": false },
            "min_wall_mm": { "type": "number", "exclusiveMinimum": 0, "maximum": crate::print::profile::MAX_MIN_WALL_MM, "default": f64::from(crate::print::profile::DEFAULT_MIN_WALL_UM) / 1000.0 },
            "build_volume_mm": {
                "type": "array",
                "items": { "type": "number", "exclusiveMinimum": 0, "maximum": crate::print::profile::MAX_BUILD_MM },
                "minItems": 3,
                "maxItems": 3,
                "default": crate::print::profile::DEFAULT_BUILD_UM.map(|v| f64::from(v) / 1000.0)
            },
            "triangle_ceiling": { "type": "integer", "minimum": 1, "maximum": crate::print::profile::MAX_TRIANGLE_CEILING, "default": crate::print::profile::DEFAULT_TRIANGLE_CEILING },
            "size": { "type": "integer", "minimum": crate::preview::MIN_SIZE, "maximum": crate::preview::MAX_SIZE, "default": crate::preview::DEFAULT_SIZE },
            "view": { "enum": views, "default": crate::preview::View::default().name() },
            "background": { "type": "string", "pattern": "^\\s*(|[Tt][Rr][Aa][Nn][Ss][Pp][Aa][Rr][Ee][Nn][Tt]|#?[0-9A-Fa-f]{6})\\s*$", "default": "transparent" }
        },
        // `size_mm`, `print_report` and the printer profile only with `print: true`.
        "dependentSchemas": {
            "size_mm": { "properties": { "print": { "const": true } }, "required": ["print"] },
            "print_report": { "properties": { "print": { "const": true } }, "required": ["print"] },
            "min_wall_mm": { "properties": { "print": { "const": true } }, "required": ["print"] },
            "build_volume_mm": { "properties": { "print": { "const": true } }, "required": ["print"] },
            "triangle_ceiling": { "properties": { "print": { "const": true } }, "required": ["print"] },
            // `size`, `view` and `background` only with `format: png`.
            "size": { "properties": { "format": { "const": "png" } }, "required": ["format"] },
            "view": { "properties": { "format": { "const": "png" } }, "required": ["format"] },
            "background": { "properties": { "format": { "const": "png" } }, "required": ["format"] }
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Span;

    fn decl(name: &str, kind: ParamKind, default: f64, range: Option<(f64, f64)>, choices: &[&str]) -> ParamDecl {
        ParamDecl { name: name.into(), kind, default, range, choices: choices.iter().map(|c| c.to_string()).collect(), span: Span::new(1, 1) }
    }

    #[test]
    fn every_render_body_field_is_described() {
        let body = serde_json::to_value(<super::super::request::RenderBody as utoipa::PartialSchema>::schema()).expect("schema as JSON");
        let fields: Vec<&String> = body["properties"].as_object().expect("properties").keys().collect();
        let schema = render_schema("t", "", Language::Mdg, &[]);
        let described: Vec<&String> = schema["properties"].as_object().expect("properties").keys().collect();
        assert_eq!(fields, described);
    }

    #[test]
    fn parameters_carry_type_default_bounds_and_presets() {
        let params = [
            decl("n", ParamKind::Int, 3.0, Some((1.0, 8.0)), &[]),
            decl("r", ParamKind::Float, 0.25, Some((0.0, 1.5)), &[]),
            decl("shiny", ParamKind::Bool, 1.0, None, &[]),
            decl("cut", ParamKind::Int, 1.0, Some((0.0, 2.0)), &["round", "princess", "emerald"]),
        ];
        let s = render_schema("gem", "A gem", Language::Mdg, &params);
        assert_eq!(s["$schema"], DIALECT);
        let p = &s["properties"]["params"]["properties"];
        assert_eq!(p["n"], json!({ "type": "integer", "default": 3, "minimum": 1, "maximum": 8 }));
        assert_eq!(p["r"], json!({ "type": "number", "default": 0.25, "minimum": 0, "maximum": 1.5 }));
        assert_eq!(render_schema("t", "", Language::Mdg, &[decl("z", ParamKind::Float, 0.0, None, &[])])["properties"]["params"]["properties"]["z"]["default"], 0);
        assert_eq!(p["shiny"]["default"], true);
        assert_eq!(p["cut"]["default"], "princess");
        assert_eq!(p["cut"]["anyOf"][0]["enum"], json!(["round", "princess", "emerald"]));
        assert_eq!(s["properties"]["params"]["additionalProperties"], false);
        assert!(s["properties"]["params"]["properties"].get(LINE_RADIUS_PARAM).is_none());
        let e = render_schema("es", "", Language::Eisenscript, &[]);
        assert_eq!(e["properties"]["params"]["properties"][LINE_RADIUS_PARAM]["exclusiveMinimum"], 0);
    }
}
