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
//! Schema validator). The options' part is the pipeline's one declaration
//! of them ([`RenderOptions`], `pipeline::options`), each field's schema
//! written beside the field, so the schema, the validator and every door
//! read one list; this module adds the grammar's parameters and tightens
//! the OpenAPI document with it.

use crate::lang::eisen::LINE_RADIUS_PARAM;
use crate::lang::ir::{ParamDecl, ParamKind};
use crate::export::Format;
use crate::lang::Language;
use crate::pipeline::options::schema::options_schema;
use crate::pipeline::options::{Doors, RenderOptions};
use serde_json::{json, Map, Value};

/// The dialect every schema declares.
pub(crate) const DIALECT: &str = "https://json-schema.org/draft/2020-12/schema";

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

/// The render options of `POST /v1/render`, with the values the validator
/// accepts: the pipeline's one declaration ([`options_schema`]) and `source`.
fn options() -> Value {
    let mut options = options_schema();
    if let Some(props) = options.get_mut("properties").and_then(Value::as_object_mut) {
        props.insert("source".into(), json!({ "type": "string", "description": "Grammar source (added by the client; the schema is about the rest)" }));
        props.insert("files".into(), json!({ "type": "object", "additionalProperties": { "type": "string" }, "description": "Files beside the source (a cpfg model's .v, .a, .map, #includes): file name → text, or \"base64:\" and the bytes" }));
    }
    options
}

use crate::pipeline::options::schema::seed_text_pattern;

/// Tightens the request schemas of the OpenAPI document (derived by utoipa
/// from the request structs, which accept any string where an option has
/// a fixed set of names) to what the server accepts, from the same
/// declaration as the per-grammar schemas ([`options`]): enums for names,
/// ranges for numbers, the seed's exact text form, and the rules that tie
/// options to `print` and to `format: png`. Each option also accepts
/// `null` (the server reads it as absent). schemathesis holds the two to
/// each other (tests/it/harden/schema.rs).
pub fn tighten_openapi(doc: &mut Value) {
    let strict = options();
    let Some(props) = strict.get("properties").and_then(Value::as_object) else { return };
    let nullable = |s: &Value, old: Option<&Value>| {
        let mut out = json!({ "anyOf": [s, { "type": "null" }] });
        if let Some(d) = old.and_then(|o| o.get("description")) {
            out["description"] = d.clone();
        }
        out
    };
    // A rule applies when its option is given and not null.
    let rules: Vec<Value> = strict
        .get("dependentSchemas")
        .and_then(Value::as_object)
        .map(|deps| {
            deps.iter()
                .map(|(name, then)| json!({ "if": { "properties": { name: { "not": { "type": "null" } } }, "required": [name] }, "then": then }))
                .collect()
        })
        .unwrap_or_default();
    let schemas = &mut doc["components"]["schemas"];
    for body in ["RenderBody", "BatchBody"] {
        let Some(fields) = schemas[body]["properties"].as_object_mut() else { continue };
        for (name, schema) in fields.iter_mut() {
            if name == "source" || name == "params" {
                continue;
            }
            if let Some(s) = props.get(name) {
                let mut strict = s.clone();
                // Inside `limits`, each field may be null too (read as absent).
                if let Some(inner) = strict.get_mut("properties").and_then(Value::as_object_mut) {
                    for v in inner.values_mut() {
                        *v = json!({ "anyOf": [v.clone(), { "type": "null" }] });
                    }
                }
                *schema = nullable(&strict, Some(schema));
            }
        }
        schemas[body]["allOf"] = Value::from(rules.clone());
        schemas[body]["additionalProperties"] = json!(false);
    }
    // A batch names its grammar once (`source` or a built-in `grammar`)
    // and varies it once (`seeds`, not with `seed`, or `sweep`): batch.rs.
    if let Some(all) = schemas["BatchBody"]["allOf"].as_array_mut() {
        let given = |name: &str| json!({ "properties": { name: { "not": { "type": "null" } } }, "required": [name] });
        all.push(json!({ "oneOf": [given("source"), given("grammar")] }));
        all.push(json!({ "oneOf": [given("seeds"), given("sweep")] }));
        all.push(json!({ "not": { "allOf": [given("seed"), given("seeds")] } }));
    }
    // Every swept parameter has at least one value.
    if let Some(sweep) = schemas["BatchBody"]["properties"].get_mut("sweep") {
        sweep["additionalProperties"]["minItems"] = json!(1);
        sweep["minProperties"] = json!(1);
    }
    // The limits' component, as strict as the body's `limits`.
    if let Some(limits) = schemas["RenderBody"]["properties"]["limits"]["anyOf"].get(0).cloned() {
        schemas["LimitsBody"] = limits;
    }
    if let Some(lang) = schemas["CheckBody"]["properties"].get_mut("language") {
        *lang = nullable(&props["language"], Some(lang));
    }
    schemas["Seed"] = json!({
        "description": "A seed: a whole number from 0 to 2^64 − 1, or the same as decimal digits",
        "anyOf": [
            { "type": "integer", "minimum": 0, "maximum": u64::MAX },
            { "type": "string", "pattern": seed_text_pattern() }
        ]
    });
    // What a model answer may be: every format's MIME type (the
    // registry's), and the printability report's JSON.
    for (path, method) in [("/v1/render", "post"), ("/v1/models/{file}", "get")] {
        if let Some(content) = doc["paths"][path][method]["responses"]["200"]["content"].as_object_mut() {
            let model = content.values().next().cloned().unwrap_or_else(|| json!({ "schema": { "type": "string", "format": "binary" } }));
            *content = model_media_types().into_iter().map(|m| (m.to_string(), model.clone())).collect();
            content.insert("application/json".into(), json!({ "schema": { "type": "object", "description": "print_report=true: the printability report" } }));
        }
    }
    // The models route's query: the declaration's query options, with the
    // same ranges and names, and a realistic file (of the registry's
    // extensions) so generated requests reach a model. The print options
    // are read from a query too but not listed: a query cannot say that
    // `size_mm` needs `print=true`, and a model may be unprintable, so a
    // generator would be told that requests the server refuses are valid.
    let extensions = Format::extensions();
    if let Some(params) = doc["paths"]["/v1/models/{file}"]["get"]["parameters"].as_array_mut() {
        let listed = RenderOptions::fields().iter().filter(|f| {
            let print = f.name == "print" || f.needs.as_ref().is_some_and(|(other, _)| *other == "print");
            f.doors.has(Doors::QUERY) && f.name != "params" && !print
        });
        let mut generated: Vec<Value> = listed
            .map(|f| {
                // A seed in a query is its decimal digits, read as a whole number.
                let schema = if f.name == "seed" { json!({ "type": "integer", "minimum": 0, "maximum": u64::MAX }) } else { f.schema.clone() };
                json!({ "name": f.name, "in": "query", "required": false, "description": f.doc, "schema": schema })
            })
            .collect();
        for p in params.iter_mut() {
            if p["name"] == "file" {
                p["description"] = json!(format!("NAME.EXT: NAME a built-in grammar, EXT one of {}", extensions.join(", ")));
                p["example"] = json!("gem.glb");
                p["schema"] = json!({
                    "type": "string",
                    "pattern": format!("^[^/]+\\.({})$", extensions.join("|")),
                    "examples": ["gem.glb", "hogeweg.stl", "gem.png", "tower.3mf"]
                });
            }
        }
        params.retain(|p| p["in"] != "query" || p["name"] == "p.<param>");
        let at = params.iter().position(|p| p["name"] == "file").map_or(0, |i| i + 1);
        for (i, g) in generated.drain(..).enumerate() {
            params.insert(at + i, g);
        }
    }
}

/// Every format's MIME type, each once, in the registry's order.
fn model_media_types() -> Vec<&'static str> {
    let mut types: Vec<&'static str> = Vec::new();
    for f in Format::ALL {
        if !types.contains(&f.content_type()) {
            types.push(f.content_type());
        }
    }
    types
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
