//! The format registry (`crates/engine/src/export/formats.rs`) is the one
//! list of formats: every registered format is known, by the same name,
//! extension and MIME type, to every place that lists formats — the CLI's
//! `--format` and its output-extension detection, `POST /v1/render` and
//! `GET /v1/models/NAME.EXT` (with the `Content-Type` the registry names),
//! the request schema's and the OpenAPI document's enums, and the golden
//! table — and names and extensions do not collide. A format added to the
//! table alone is then checked everywhere (docs/extending.md).

use crate::common::{self, repo, run};
use rulemesh::export::{Format, OptionGroup, Writer, FORMATS};
use rulemesh::lang::Language;
use rulemesh::service::{self, ServeConfig};
use serde_json::{json, Value};
use std::time::Duration;

/// The library grammar every 3D format is rendered from (small, every such format applies).
const GRAMMAR: &str = "gem";

/// The library grammar a format written from a 2D drawing (`svg`) is
/// rendered from: a Context Free design, since no 3D language draws one.
const DRAWING: &str = "cfdg-spiral";

/// Whether `format` is written from a model's 2D drawing.
fn draws(format: Format) -> bool {
    matches!(format.info().writer, Writer::Drawing(_))
}

/// The library grammar `format` is checked with: its name, file and language.
fn grammar_for(format: Format) -> (&'static str, &'static str, Language) {
    if draws(format) {
        (DRAWING, "cfdg-spiral.cfdg", Language::Cfdg)
    } else {
        (GRAMMAR, "gem.mdg", Language::Mdg)
    }
}

fn source_for(format: Format) -> String {
    let (_, file, _) = grammar_for(format);
    std::fs::read_to_string(repo().join("grammars").join(file)).expect("library grammar")
}

fn gem_source() -> String {
    source_for(Format::Glb)
}

/// The format's library grammar rendered by the library in `format`, as the CLI and the service render it.
fn library_render(format: Format) -> Vec<u8> {
    let req = rulemesh::RenderRequest { language: Some(grammar_for(format).2), format, ..Default::default() };
    rulemesh::render(source_for(format).as_bytes(), &req).unwrap_or_else(|e| panic!("{}: {e}", format.name())).bytes
}

#[test]
fn names_and_extensions_are_unique_and_every_extension_names_a_format() {
    let names = Format::names();
    assert_eq!(names.len(), Format::ALL.len());
    assert_eq!(FORMATS.len(), Format::ALL.len());
    for (i, (&format, info)) in Format::ALL.iter().zip(FORMATS).enumerate() {
        assert_eq!(format.info().name, info.name, "FORMATS and Format::ALL in one order");
        assert!(!names[..i].contains(&info.name), "`{}` registered twice", info.name);
        assert!(!info.extensions.is_empty(), "{} has no extension", info.name);
        assert!(!info.mime.is_empty(), "{} has no MIME type", info.name);
        for ext in info.extensions {
            assert_eq!(*ext, ext.to_ascii_lowercase(), "{}: extensions are lower case", info.name);
            // An extension two formats share is served as the first one's; they must
            // then at least agree on what the bytes are called.
            let owner = Format::from_extension_name(ext).expect("claimed");
            assert_eq!(owner.content_type(), info.mime, ".{ext} is {} and {}", owner.name(), info.name);
        }
        assert_eq!(Format::parse(info.name), Some(format));
        assert_eq!(Format::parse(&info.name.to_ascii_uppercase()), Some(format));
    }
    // Each extension is listed once, in registry order.
    let exts = Format::extensions();
    for (i, e) in exts.iter().enumerate() {
        assert!(!exts[..i].contains(e), ".{e} listed twice");
    }
}

/// Whether `code` names `word` as a whole identifier.
fn names(code: &str, word: &str) -> bool {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    code.match_indices(word).any(|(i, _)| {
        let before = code[..i].chars().next_back();
        let after = code[i + word.len()..].chars().next();
        !before.is_some_and(ident) && !after.is_some_and(ident)
    })
}

#[test]
fn no_writer_names_the_registry() {
    // Each format folder reads its own descriptor; the registry, above the
    // folders, is the only code that knows every format (docs/extending.md).
    let export = repo().join("crates/engine/src/export");
    let mut folders: Vec<_> = std::fs::read_dir(&export).expect("export/").map(|e| e.expect("entry").path()).filter(|p| p.is_dir()).collect();
    folders.sort();
    assert!(folders.len() >= 7, "{folders:?}");
    let mut files = Vec::new();
    while let Some(dir) = folders.pop() {
        for entry in std::fs::read_dir(&dir).expect("folder") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    for file in files {
        let text = std::fs::read_to_string(&file).expect("read");
        // Tests may reach anywhere, as in scripts/layers.py.
        let code: String = text.lines().take_while(|l| !l.trim_start().starts_with("#[cfg(test)]")).filter(|l| !l.trim_start().starts_with("//")).collect::<Vec<_>>().join("\n");
        for word in ["Format", "FORMATS", "estimated_size", "flat_sink", "formats"] {
            assert!(!names(&code, word), "{} names the registry's `{word}`", file.display());
        }
    }
}

#[test]
fn the_cli_knows_every_format_by_name_and_by_extension() {
    let dir = common::tempdir();
    let help = run(&["render", "--help"], None);
    let help = String::from_utf8_lossy(&help.stdout).to_string();
    for &format in Format::ALL {
        let info = format.info();
        let grammar = repo().join("grammars").join(grammar_for(format).1);
        let grammar = grammar.to_str().expect("utf-8 path");
        // --format NAME, to a file whose name says nothing.
        let named = dir.path().join(format!("named-{}.out", info.name));
        let out = run(&["render", grammar, "--format", info.name, "-o", named.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "--format {}: {}", info.name, String::from_utf8_lossy(&out.stderr));
        assert_eq!(std::fs::read(&named).expect("written"), library_render(format), "--format {}", info.name);
        // Every extension of the format, detected from the output's name.
        for ext in info.extensions {
            let file = dir.path().join(format!("by-extension-{}.{ext}", info.name));
            let out = run(&["render", grammar, "-o", file.to_str().expect("utf-8")], None);
            assert!(out.status.success(), "-o *.{ext}: {}", String::from_utf8_lossy(&out.stderr));
            let detected = Format::from_extension_name(ext).expect("claimed");
            assert_eq!(std::fs::read(&file).expect("written"), library_render(detected), "-o *.{ext}");
            assert!(help.contains(&format!(".{ext}")), "render --help does not list .{ext}:\n{help}");
        }
        assert!(help.contains(info.name), "render --help does not list {}:\n{help}", info.name);
    }
    // An extension no format has is a usage error listing the registry's.
    let grammar = repo().join("grammars").join("gem.mdg");
    let grammar = grammar.to_str().expect("utf-8 path");
    let out = run(&["render", grammar, "-o", dir.path().join("x.nope").to_str().expect("utf-8")], None);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    for ext in Format::extensions() {
        assert!(stderr.contains(&format!(".{ext}")), "{stderr}");
    }
}

#[test]
fn the_golden_table_renders_every_format() {
    let variants: Vec<&str> = crate::golden::variants(Language::Mdg).into_iter().map(|(v, _)| v).collect();
    let table = std::fs::read_to_string(repo().join("tests/golden/hashes.txt")).expect("golden table");
    for &format in Format::ALL {
        let name = format.name();
        assert!(variants.contains(&name), "golden.rs has no `{name}` variant");
        let row = format!("grammars/{} {name} ", grammar_for(format).1);
        assert!(table.lines().any(|l| l.starts_with(&row)), "tests/golden/hashes.txt has no row `{row}…`");
    }
}

async fn get(url: String) -> reqwest::Response {
    let client = reqwest::Client::builder().timeout(Duration::from_secs(120)).no_gzip().no_brotli().no_zstd().build().expect("client");
    client.get(url).send().await.expect("request")
}

fn content_type(r: &reqwest::Response) -> String {
    r.headers().get("content-type").and_then(|v| v.to_str().ok()).unwrap_or("").to_string()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_service_serves_every_format_with_its_mime_type_and_lists_it_in_its_schemas() {
    let config = ServeConfig {
        http: "127.0.0.1:0".parse().expect("addr"),
        grpc: "127.0.0.1:0".parse().expect("addr"),
        body_limit: 256 * 1024,
        ..ServeConfig::default()
    };
    let srv = service::start(config).await.expect("server starts");
    let base = format!("http://{}", srv.http_addr);
    let client = reqwest::Client::builder().timeout(Duration::from_secs(120)).no_gzip().no_brotli().no_zstd().build().expect("client");
    for &format in Format::ALL {
        let info = format.info();
        // POST /v1/render by name (and by any case).
        let (grammar, _, language) = grammar_for(format);
        for name in [info.name.to_string(), info.name.to_ascii_uppercase()] {
            let body = json!({ "source": source_for(format), "language": language.name(), "format": name });
            let r = client.post(format!("{base}/v1/render")).json(&body).send().await.expect("request");
            assert_eq!(r.status(), 200, "format {name}");
            assert_eq!(content_type(&r), info.mime, "format {name}");
            assert_eq!(r.bytes().await.expect("body").to_vec(), library_render(format), "format {name}");
        }
        // GET /v1/models/NAME.EXT for every extension: the format that claims it.
        for ext in info.extensions {
            let owner = Format::from_extension_name(ext).expect("claimed");
            let r = get(format!("{base}/v1/models/{grammar}.{ext}")).await;
            assert_eq!(r.status(), 200, "/v1/models/{grammar}.{ext}");
            assert_eq!(content_type(&r), owner.content_type(), "/v1/models/{grammar}.{ext}");
            assert_eq!(r.bytes().await.expect("body").to_vec(), library_render(owner), "/v1/models/{grammar}.{ext}");
        }
        if draws(format) {
            // A 3D language has no drawing: a typed 400 naming the capability, by either route.
            let body = json!({ "source": gem_source(), "language": "mdg", "format": info.name });
            let r = client.post(format!("{base}/v1/render")).json(&body).send().await.expect("request");
            assert_eq!(r.status(), 400, "gem as {}", info.name);
            let err: Value = r.json().await.expect("error body");
            assert_eq!(err["error"]["code"], "bad_request", "{err}");
            assert!(err["error"]["message"].as_str().is_some_and(|m| m.contains("capability `drawing`")), "{err}");
            let r = get(format!("{base}/v1/models/{GRAMMAR}.{}", format.extension())).await;
            assert_eq!(r.status(), 400, "/v1/models/{GRAMMAR}.{}", format.extension());
        }
    }
    assert_eq!(get(format!("{base}/v1/models/{GRAMMAR}.nope")).await.status(), 404);

    // The per-grammar schema's enum and its rule for the picture options.
    let schema: Value = get(format!("{base}/v1/grammars/{GRAMMAR}/schema")).await.json().await.expect("schema");
    assert_eq!(schema["properties"]["format"]["enum"], json!(Format::names()), "{}", schema["properties"]["format"]);
    assert_eq!(schema["properties"]["format"]["default"], json!(Format::default().name()));
    let pictures: Vec<&str> = Format::reading(OptionGroup::Preview).iter().map(|f| f.name()).collect();
    // The options declaration ties the picture options to the registry's
    // picture format (one today: `png`).
    assert_eq!(pictures, ["png"]);
    assert_eq!(schema["dependentSchemas"]["size"]["properties"]["format"]["const"], json!(pictures[0]));

    // The OpenAPI document: the request bodies' enums, the models route's
    // extensions and every MIME type it may answer with.
    let doc: Value = get(format!("{base}/openapi.json")).await.json().await.expect("OpenAPI");
    for body in ["RenderBody", "BatchBody"] {
        let format = &doc["components"]["schemas"][body]["properties"]["format"];
        assert_eq!(format["anyOf"][0]["enum"], json!(Format::names()), "{body}: {format}");
    }
    let models = &doc["paths"]["/v1/models/{file}"]["get"];
    let file = models["parameters"].as_array().expect("parameters").iter().find(|p| p["name"] == "file").expect("file parameter");
    let pattern = file["schema"]["pattern"].as_str().expect("a pattern");
    let content = models["responses"]["200"]["content"].as_object().expect("content");
    for &format in Format::ALL {
        for ext in format.info().extensions {
            assert!(pattern.contains(&format!("|{ext}|")) || pattern.contains(&format!("({ext}|")) || pattern.contains(&format!("|{ext})")), "{pattern} lacks {ext}");
        }
        assert!(content.contains_key(format.content_type()), "the models route does not list {}", format.content_type());
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
