//! The render options are declared once (`pipeline::options`, issue 32):
//! these tests walk that declaration, field by field (the limits' fields
//! too), and check that each one reaches every door it names and the cache
//! key — the CLI (`rulemesh render --help` lists its flag, and the flag
//! gives the key the body gives), the HTTP body (the OpenAPI document has
//! it, and setting it changes the key), the URL query where it applies,
//! gRPC (the `.proto` has the field, and the conversion carries it), the
//! schema (which accepts the declared example and, where the field needs
//! another, refuses it alone, as the validator does) and the cache key
//! (changing only that field changes it, unless the declaration says why
//! not). A field added to the declaration alone fails here: it has no flag
//! value, proto field or key effect until every door carries it.

use super::*;
use rulemesh::core::Limits;
use rulemesh::lang::Language;
use rulemesh::pipeline::options::{Doors, Key, OptionField};
use rulemesh::pipeline::RenderOptions;
use rulemesh::service::request::{query_body, RenderBody};

/// A grammar with one parameter, so `params` has something to set.
const SOURCE: &str = "@param int count 3 1 10\nstartshape A\nrule A { count * { x 1 } BOX {} }\n";

/// One declared field, with the group it sits in (`limits`), if any.
struct Entry {
    group: Option<&'static str>,
    field: &'static OptionField,
}

impl Entry {
    /// `limits.max_depth`, or the field's own name.
    fn path(&self) -> String {
        self.group.map_or_else(|| self.field.name.to_string(), |g| format!("{g}.{}", self.field.name))
    }

    /// `context` with the example set: the JSON body's options.
    fn with_example(&self) -> Map {
        let mut body = self.context();
        match self.group {
            None => {
                body.insert(self.field.name.into(), self.field.example.clone());
            }
            Some(g) => {
                body.insert(g.into(), json!({ self.field.name: self.field.example }));
            }
        }
        body
    }

    /// The options under which the example matters.
    fn context(&self) -> Map {
        self.field.context.as_object().cloned().unwrap_or_default()
    }
}

type Map = serde_json::Map<String, Value>;

/// Every declared field, groups opened.
fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for f in RenderOptions::fields() {
        match f.group() {
            Some(inner) => out.extend(inner.iter().map(|g| Entry { group: Some(f.name), field: g })),
            None => out.push(Entry { group: None, field: f }),
        }
    }
    out
}

/// The cache key of a JSON body's options (`source` added), planned under
/// the CLI's ceiling.
fn body_key(options: &Map) -> Result<String, String> {
    let mut body = options.clone();
    body.insert("source".into(), Value::from(SOURCE));
    let body: RenderBody = serde_json::from_value(Value::Object(body)).map_err(|e| e.to_string())?;
    body.plan(&Limits::ceiling(), false).map(|p| p.key.hex()).map_err(|e| e.to_string())
}

/// A JSON value as a text door writes it (a flag's or a query's value).
fn text(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        Value::Array(items) => items.iter().map(|i| i.to_string()).collect::<Vec<_>>().join("x"),
        other => other.to_string(),
    }
}

/// The command-line arguments that set `name` (a field of `group`) to `value`.
fn flag_args(field: &OptionField, value: &Value) -> Vec<String> {
    if field.cli_flag.as_ref() == Some(value) {
        return vec![format!("--{}", field.flag())];
    }
    match value {
        Value::Object(params) => params.iter().flat_map(|(k, v)| ["--param".to_string(), format!("{k}={}", text(v))]).collect(),
        _ => vec![format!("--{}", field.flag()), text(value)],
    }
}

/// The arguments a body's options stand for on the command line.
fn cli_args(options: &Map) -> Vec<String> {
    let mut args = Vec::new();
    for (name, value) in options {
        let field = RenderOptions::fields().iter().find(|f| f.name == name).unwrap_or_else(|| panic!("`{name}` is declared"));
        match field.group() {
            Some(inner) => {
                for (k, v) in value.as_object().expect("a group is an object") {
                    args.extend(flag_args(inner.iter().find(|g| g.name == k).expect("declared"), v));
                }
            }
            None => args.extend(flag_args(field, value)),
        }
    }
    args
}

/// `rulemesh render FILE --cache-key ARGS…`'s key.
fn cli_key(file: &std::path::Path, args: &[String]) -> String {
    let mut all = vec!["render".to_string(), file.display().to_string(), "--cache-key".into()];
    all.extend(args.iter().cloned());
    let refs: Vec<&str> = all.iter().map(String::as_str).collect();
    let out = common::run(&refs, None);
    assert!(out.status.success(), "{all:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// The `message NAME { … }` block of the proto file.
fn proto_message<'a>(proto: &'a str, name: &str) -> &'a str {
    let start = proto.find(&format!("message {name} {{")).unwrap_or_else(|| panic!("message {name} in the proto"));
    let end = proto[start..].find("\n}").map_or(proto.len(), |e| start + e);
    &proto[start..end]
}

/// The key of the models route's URL for SOURCE written as `ext` with `query`.
fn query_key(ext: &str, query: &[(String, String)]) -> Result<String, String> {
    let body = query_body(SOURCE, Language::Mdg, ext, query).map_err(|e| e.to_string())?;
    body.plan(&Limits::ceiling(), false).map(|p| p.key.hex()).map_err(|e| e.to_string())
}

#[test]
fn every_declared_option_reaches_every_door_and_the_key() {
    let entries = entries();
    assert!(entries.len() >= 30, "{} fields", entries.len());
    let dir = common::tempdir();
    let file = dir.path().join("grammar.mdg");
    std::fs::write(&file, SOURCE).expect("write the grammar");
    let help = common::run(&["render", "--help"], None);
    let help = String::from_utf8_lossy(&help.stdout).to_string();
    let openapi: Value = serde_json::from_str(rulemesh::service::http::openapi_json_text()).expect("the OpenAPI document");
    let body_props = &openapi["components"]["schemas"]["RenderBody"]["properties"];
    let query_params: Vec<&str> = openapi["paths"]["/v1/models/{file}"]["get"]["parameters"].as_array().expect("parameters").iter().filter(|p| p["in"] == "query").filter_map(|p| p["name"].as_str()).collect();
    let schema = rulemesh::service::schema::render_schema("t", "", Language::Mdg, &[]);
    let proto = std::fs::read_to_string(common::repo().join("proto/rulemesh/v1/rulemesh.proto")).expect("the proto");
    for e in &entries {
        let f = e.field;
        let path = e.path();
        assert!(!f.doc.is_empty(), "{path}: no doc");
        assert!(!f.example.is_null(), "{path}: no example");
        // The cache key, through the body: only the field differs.
        let base = body_key(&e.context()).unwrap_or_else(|err| panic!("{path}: context refused: {err}"));
        let with = body_key(&e.with_example()).unwrap_or_else(|err| panic!("{path}: example refused: {err}"));
        match f.key {
            Key::Changes => assert_ne!(base, with, "{path}: the example does not change the cache key"),
            Key::Unchanged(why) => assert_eq!(base, with, "{path}: declared out of the key ({why}) but changes it"),
        }
        // The body's schema in the OpenAPI document, and the grammar schema.
        if f.doors.has(Doors::BODY) {
            let top = e.group.unwrap_or(f.name);
            assert!(body_props.get(top).is_some(), "{path}: not in the OpenAPI RenderBody");
            let declared = match e.group {
                None => &schema["properties"][f.name],
                Some(g) => &schema["properties"][g]["properties"][f.name],
            };
            assert!(declared.is_object() && declared != &json!({}), "{path}: not in the request schema");
        }
        // The CLI: a flag in --help, and the flag gives the body's key.
        if f.doors.has(Doors::CLI) {
            assert!(help.contains(&format!("--{}", f.flag())), "{path}: --{} is not in rulemesh render --help", f.flag());
            let cli_base = cli_key(&file, &cli_args(&e.context()));
            let cli_with = cli_key(&file, &cli_args(&e.with_example()));
            assert_eq!(cli_base, base, "{path}: the CLI's key without it differs from the body's");
            assert_eq!(cli_with, with, "{path}: the CLI's key with it differs from the body's");
        } else {
            assert!(!help.contains(&format!("--{} ", f.flag())), "{path}: a flag the declaration does not offer");
        }
        // The URL query: read, and changing the key as the body does.
        if f.doors.has(Doors::QUERY) {
            assert!(e.group.is_none(), "{path}: a group's field in a query");
            let mut ctx = e.context();
            let ext = ctx.remove("format").map_or_else(|| "glb".to_string(), |v| text(&v));
            let pairs = |m: &Map| -> Vec<(String, String)> {
                m.iter()
                    .flat_map(|(k, v)| match v {
                        Value::Object(params) => params.iter().map(|(p, pv)| (format!("p.{p}"), text(pv))).collect::<Vec<_>>(),
                        _ => vec![(k.clone(), text(v))],
                    })
                    .collect()
            };
            let mut with_ctx = ctx.clone();
            with_ctx.insert(f.name.into(), f.example.clone());
            let q_base = query_key(&ext, &pairs(&ctx)).unwrap_or_else(|err| panic!("{path}: query context refused: {err}"));
            let q_with = query_key(&ext, &pairs(&with_ctx)).unwrap_or_else(|err| panic!("{path}: query refused: {err}"));
            assert_ne!(q_base, q_with, "{path}: the query does not change the key");
            let print = f.name == "print" || f.needs.as_ref().is_some_and(|(o, _)| *o == "print");
            if f.name != "params" && !print {
                assert!(query_params.contains(&f.name), "{path}: not a documented query parameter of /v1/models");
            }
        } else if e.group.is_none() {
            let err = query_key("glb", &[(f.name.to_string(), text(&f.example))]).expect_err("not a query option");
            assert!(err.contains("unknown query parameter"), "{path}: {err}");
        }
        // gRPC: a field of that name in the request message (or, for a group's, in its message).
        if f.doors.has(Doors::GRPC) {
            let message = match e.group {
                None => proto_message(&proto, "RenderRequest"),
                Some(_) => proto_message(&proto, "Limits"),
            };
            assert!(message.contains(&format!(" {} = ", f.name)), "{path}: no field `{}` in the proto's message", f.name);
        }
        // A field that needs another is refused without it, by the validator and the schema alike.
        if let Some((other, _)) = &f.needs {
            let mut alone = e.with_example();
            alone.remove(*other);
            let refused = body_key(&alone).expect_err("refused without what it needs");
            assert!(refused.contains(other), "{path}: {refused}");
            let mut instance = alone.clone();
            instance.insert("source".into(), Value::from(SOURCE));
            let mut valid = e.with_example();
            valid.insert("source".into(), Value::from(SOURCE));
            assert_eq!(super::schema::validator_verdicts(&schema, &[Value::Object(valid), Value::Object(instance)]), [true, false], "{path}");
        }
    }
}

/// gRPC carries every option: a request with every field set converts into
/// options with every field set (the literal below lists every proto field,
/// so a new one does not compile until it is given here).
#[test]
fn grpc_requests_carry_every_declared_option() {
    let request = pb::RenderRequest {
        source: SOURCE.into(),
        language: "mdg".into(),
        seed: Some(7),
        params: [("count".to_string(), "2".to_string())].into(),
        format: "stl".into(),
        limits: Some(pb::Limits { max_depth: Some(1), max_primitives: Some(2), max_triangles: Some(3), max_memory: Some(4), timeout_ms: Some(5), max_source_bytes: Some(6), max_steps: Some(7) }),
        on_limit: "truncate".into(),
        detail: Some(9),
        no_cache: true,
        layout: "per-kind".into(),
        position_bits: Some(12),
        normal_bits: Some(16),
        zstd: Some(true),
        weld: Some(true),
        quantize: Some(true),
        compress: "meshopt".into(),
        fit: "unit".into(),
        instancing: "flat".into(),
        print: Some(true),
        size_mm: Some(50.0),
        print_report: Some(true),
        min_wall_mm: Some(0.4),
        build_volume_mm: vec![100.0, 100.0, 80.0],
        triangle_ceiling: Some(5000),
        size: Some(64),
        view: "top".into(),
        background: "#ff8000".into(),
        frame: Some(1),
        checksum: Some(true),
        files: [("model.v".to_string(), b"angle factor: 8\n".to_vec())].into(),
    };
    let body = RenderBody::from(request);
    // The files are content beside the source, not an option: carried too.
    assert_eq!(body.files.get("model.v").map(String::as_str), Some("angle factor: 8\n"));
    let options = serde_json::to_value(&body.options).expect("options as JSON");
    let empty = |v: &Value| v.is_null() || v.as_object().is_some_and(|o| o.is_empty());
    for e in entries().iter().filter(|e| e.field.doors.has(Doors::GRPC)) {
        let value = match e.group {
            None => &options[e.field.name],
            Some(g) => &options[g][e.field.name],
        };
        assert!(!empty(value), "{}: gRPC's RenderRequest does not carry it", e.path());
    }
}
