//! cpfg models from vlab (`tests/data/cpfg/`, provenance and GPL-3.0 licence
//! there) through the whole pipeline: every committed vlab object renders
//! with the files of its folder, the figures of *The Algorithmic Beauty of
//! Plants* (Prusinkiewicz & Lindenmayer, 1990) that the vlab course
//! reproduces draw the book's segment counts, stochastic models repeat per
//! seed, and the CLI finds `plant.v` beside `plant.l`.

#[path = "it/common.rs"]
mod common;

use rulemesh::core::budget::Limits;
use rulemesh::export::Format;
use rulemesh::lang::cpfg::companions::companions;
use rulemesh::lang::Language;
use rulemesh::{render, RenderError, RenderOutput, RenderRequest};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn data() -> PathBuf {
    common::repo().join("tests/data/cpfg")
}

/// The L-system file cpfg is run on in a vlab object (its `specifications`).
fn main_file(dir: &Path) -> PathBuf {
    let spec = std::fs::read_to_string(dir.join("specifications")).expect("specifications");
    let line = spec.lines().find(|l| l.trim_start().starts_with("cpfg ")).expect("a cpfg command");
    let l = line.split_whitespace().find(|w| w.ends_with(".l")).expect("an .l file");
    dir.join(l)
}

fn files_of(main: &Path, source: &[u8]) -> BTreeMap<String, Vec<u8>> {
    let dir = main.parent().expect("folder").to_path_buf();
    let stem = main.file_stem().and_then(|s| s.to_str()).expect("stem").to_string();
    companions(&stem, source, &|name: &str| std::fs::read(dir.join(name)).ok(), 1 << 20)
}

fn render_object(name: &str, format: Format, seed: Option<u64>) -> Result<RenderOutput, RenderError> {
    let main = main_file(&data().join(name));
    let source = std::fs::read(&main).expect("read");
    let req = RenderRequest { language: Some(Language::Cpfg), format, seed, files: files_of(&main, &source), limits: Limits::default(), ..RenderRequest::default() };
    render(&source, &req)
}

fn objects() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(data()).expect("data").filter_map(|e| e.ok()).filter(|e| e.path().is_dir()).map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// Every committed vlab object renders at the default limits, or stops at a
/// limit it names (the "Done when" over the committed subset).
#[test]
fn committed_vlab_objects_render() {
    let all = objects();
    assert_eq!(all.len(), 10);
    for name in &all {
        match render_object(name, Format::Glb, None) {
            Ok(out) => assert!(out.primitives > 0, "{name}: nothing drawn"),
            Err(e) => assert!(e.to_string().contains("limit"), "{name}: {e}"),
        }
    }
}

/// Segment counts of the book's figures as vlab draws them, from their folders.
#[test]
fn abop_figures_from_their_folders() {
    // The quadratic Koch curve (the generator of ABOP Figure 1.6's island, mirrored): 8^4 segments.
    assert_eq!(render_object("01-quadratic-Koch", Format::Glb, None).expect("koch").primitives, 4096);
    // Von Koch's snowflake curve (ABOP Figure 1.1): 4^4.
    assert_eq!(render_object("03-snowflake", Format::Glb, None).expect("snowflake").primitives, 256);
    // The compound leaf (ABOP Figure 1.24e at 4 steps): 130 internodes; with its homomorphism also 81 apices.
    assert_eq!(render_object("04-compound", Format::Glb, None).expect("compound").primitives, 130);
    assert_eq!(render_object("05-compound-homo", Format::Glb, None).expect("compound-homo").primitives, 211);
}

/// A stochastic model (`seed:`) gives the same bytes twice; another seed, another plant.
#[test]
fn stochastic_moss_repeats_per_seed() {
    let a = render_object("RandomMoss", Format::Stl, None).expect("moss");
    let b = render_object("RandomMoss", Format::Stl, None).expect("moss");
    assert_eq!(a.bytes, b.bytes);
    let c = render_object("RandomMoss", Format::Stl, Some(7)).expect("moss");
    let d = render_object("RandomMoss", Format::Stl, Some(7)).expect("moss");
    assert_eq!(c.bytes, d.bytes);
    assert_ne!(a.bytes, c.bytes);
}

/// `rulemesh render fractal.l` sends `fractal.v` (angle 90) and the rest:
/// the same bytes as a request carrying the folder's files.
#[test]
fn cli_finds_the_view_beside_the_l_file() {
    let dir = tempfile::tempdir().expect("tmp");
    let out = dir.path().join("koch.stl");
    let main = data().join("01-quadratic-Koch/fractal.l");
    let r = common::run(&["render", main.to_str().expect("utf8"), "-o", out.to_str().expect("utf8")], None);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let lib = render_object("01-quadratic-Koch", Format::Stl, None).expect("koch");
    assert_eq!(std::fs::read(&out).expect("written"), lib.bytes);
    // Without its view the angle is cpfg's default 45 and the picture differs.
    let source = std::fs::read(&main).expect("read");
    let bare = render(&source, &RenderRequest { language: Some(Language::Cpfg), format: Format::Stl, ..RenderRequest::default() }).expect("bare");
    assert_ne!(bare.bytes, lib.bytes);
}

/// Files count against the source-size limit.
#[test]
fn files_count_against_the_source_limit() {
    let mut files = BTreeMap::new();
    files.insert("big.v".to_string(), vec![b' '; 4096]);
    let limits = Limits { max_source_bytes: 1024, ..Limits::default() };
    let req = RenderRequest { language: Some(Language::Cpfg), files, limits, ..RenderRequest::default() };
    let e = render(b"Lsystem: 1\nAxiom: F\nendlsystem\n", &req).expect_err("over the limit");
    assert!(e.to_string().contains("source"), "{e}");
}

/// Every prefix of a committed model, and each with one byte flipped, ends
/// in a model or a typed error under tight limits: a cheap stand-in for the
/// `render_cpfg` fuzz target that runs with the tests.
#[test]
fn damaged_models_end_in_models_or_errors() {
    let limits = Limits { max_steps: 20_000, max_primitives: 2_000, max_triangles: 100_000, max_memory: 32 << 20, timeout_ms: 2_000, ..Limits::default() };
    for name in ["01-Lychnis", "07-fractal-ferns", "query-position"] {
        let main = main_file(&data().join(name));
        let source = std::fs::read(&main).expect("read");
        let files = files_of(&main, &source);
        let req = RenderRequest { language: Some(Language::Cpfg), format: Format::Stl, files, limits, ..RenderRequest::default() };
        for cut in (0..source.len()).step_by(7) {
            let _ = render(&source[..cut], &req);
            let mut flipped = source.clone();
            flipped[cut] ^= 0x21;
            let _ = render(&flipped, &req);
        }
    }
}

/// The HTTP body's `files` (text, or `base64:` bytes) reach the request and
/// change the cache key; a name is only a key (no file is read), and a value
/// that is not base64 after the prefix is text, so no schema-valid body is refused.
#[test]
fn http_body_carries_files() {
    use rulemesh::service::RenderBody;
    let ceiling = Limits::default();
    let plan = |files: serde_json::Value| {
        let body: RenderBody = serde_json::from_value(serde_json::json!({ "source": "Lsystem: 1\nAxiom: F\nendlsystem\n", "language": "cpfg", "files": files })).expect("body");
        body.plan(&ceiling, false)
    };
    let a = plan(serde_json::json!({ "m.v": "angle increment: 90\n", "m.map": "base64:AAEC" })).expect("plan");
    assert_eq!(a.request.files["m.v"], b"angle increment: 90\n");
    assert_eq!(a.request.files["m.map"], vec![0u8, 1, 2]);
    let b = plan(serde_json::json!({ "m.v": "angle increment: 60\n", "m.map": "base64:AAEC" })).expect("plan");
    assert_ne!(a.key, b.key);
    let none = plan(serde_json::json!({})).expect("plan");
    assert_ne!(none.key, a.key);
    let odd = plan(serde_json::json!({ "../etc/passwd": "base64:%%" })).expect("plan");
    assert_eq!(odd.request.files["../etc/passwd"], b"base64:%%");
}

/// `/check` reads what a render reads: a model whose `#include` is among
/// the body's `files` (as a render body carries them) passes, and fails at
/// the directive's line without them; the Lychnis checks with its folder's
/// files, over HTTP and with the CLI's `rulemesh check` (which sends them).
#[test]
fn check_reads_the_files_a_render_reads() {
    use rulemesh::service::http::check;
    use rulemesh::service::request::CheckBody;
    let main = main_file(&data().join("01-Lychnis"));
    let source = std::fs::read_to_string(&main).expect("read");
    let files = files_of(&main, source.as_bytes());
    let text: BTreeMap<String, String> = files.iter().map(|(k, v)| (k.clone(), String::from_utf8(v.clone()).expect("text files"))).collect();
    let ceiling = Limits::default();
    let included = "Lsystem: 1\n#include \"rules.h\"\nAxiom: F\nRULE\nendlsystem\n".to_string();
    let rules: BTreeMap<String, String> = [("rules.h".to_string(), "#define RULE F --> FF\n".to_string())].into();
    let alone = check(CheckBody { source: included.clone(), language: None, files: BTreeMap::new() }, &ceiling).expect("report");
    assert!(!alone.ok, "{alone:?}");
    assert!(alone.diagnostics[0].span.line == 2 && alone.diagnostics[0].message.contains("rules.h"), "{alone:?}");
    let beside = check(CheckBody { source: included, language: None, files: rules }, &ceiling).expect("report");
    assert!(beside.ok, "{beside:?}");
    let with = check(CheckBody { source, language: None, files: text }, &ceiling).expect("report");
    assert!(with.ok && with.language == Some("cpfg"), "{with:?}");
    let r = common::run(&["check", main.to_str().expect("utf8")], None);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    // The files count against the source limit here too.
    let small = Limits { max_source_bytes: 2048, ..Limits::default() };
    assert!(rulemesh::pipeline::check_source_with(b"Lsystem: 1\nAxiom: F\nendlsystem\n", &files, None, &small).is_err());
}

/// A batch's members carry the body's `files`: every member of a seeds
/// batch over a cpfg model plans with its view, so it differs from the
/// same member without it.
#[test]
fn batch_members_carry_the_files() {
    use rulemesh::service::batch::from_json_body;
    let body = |files: serde_json::Value| serde_json::json!({ "source": "Lsystem: 1\nderivation length: 2\nAxiom: F\nF --> F+F\nendlsystem\n", "language": "cpfg", "seeds": [1, 2], "files": files }).to_string();
    let ceiling = Limits::default();
    let with = from_json_body(body(serde_json::json!({ "m.v": "angle increment: 90\n" })).as_bytes(), &ceiling).expect("batch");
    let without = from_json_body(body(serde_json::json!({})).as_bytes(), &ceiling).expect("batch");
    let (a, b) = (with.member_body(&with.members()[0]).plan(&ceiling, false).expect("plan"), without.member_body(&without.members()[0]).plan(&ceiling, false).expect("plan"));
    assert_eq!(a.request.files["m.v"], b"angle increment: 90\n");
    assert!(b.request.files.is_empty());
    assert_ne!(a.key, b.key);
}
