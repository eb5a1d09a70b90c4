//! Golden output: every grammar in `grammars/`, every example in `docs/`
//! and the sources in `tests/golden/sources/` rendered to every format (and
//! format variant) that applies, compared by BLAKE3 hash with the committed
//! table `tests/golden/hashes.txt`.
//!
//! The table pins output bytes across refactoring: a row may change only in
//! a commit that says why. Failures are pinned too (`error:` plus the
//! error's kind), so a render that starts or stops failing shows up.
//! `RULEMESH_BLESS_GOLDEN=1 cargo test --release --test it golden` rewrites
//! the table instead of comparing.

use crate::common::repo;
use crate::docs::fenced_examples;
use rulemesh::export::{Compression, Format, Instancing};
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderError, RenderRequest};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// One source to render: its table name, language, bytes and script folder.
pub(crate) struct Case {
    pub(crate) name: String,
    pub(crate) language: Language,
    pub(crate) source: Vec<u8>,
    pub(crate) script_dir: Option<PathBuf>,
}

/// Every case, in a fixed order.
pub(crate) fn cases() -> Vec<Case> {
    let mut out = Vec::new();
    let from_dir = |dir: PathBuf, out: &mut Vec<Case>| {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).expect("folder exists").map(|e| e.expect("entry").path()).collect();
        files.sort();
        for f in files {
            // The registry's extensions: a new language's files join the table.
            let Some(language) = Language::from_extension(&f) else { continue };
            let name = f.strip_prefix(repo()).expect("under the repo").display().to_string();
            // `frame.es` is what the movie loads; it is a case of its own too.
            out.push(Case { name, language, source: std::fs::read(&f).expect("read"), script_dir: Some(dir.clone()) });
        }
    };
    from_dir(repo().join("grammars"), &mut out);
    from_dir(repo().join("grammars/icons"), &mut out);
    from_dir(repo().join("tests/golden/sources"), &mut out);
    let mut docs: Vec<PathBuf> = std::fs::read_dir(repo().join("docs")).expect("docs/").map(|e| e.expect("entry").path()).collect();
    docs.sort();
    for doc in docs.iter().filter(|p| p.extension().is_some_and(|e| e == "md")) {
        let text = std::fs::read_to_string(doc).expect("read doc");
        let stem = doc.file_name().and_then(|s| s.to_str()).expect("name");
        for (tag, language) in [("mdg", Language::Mdg), ("ls", Language::Lsystem), ("stack", Language::Stack), ("ug", Language::Ug)] {
            for (i, src) in fenced_examples(&text, tag).into_iter().enumerate() {
                out.push(Case { name: format!("docs/{stem}#{tag}{i}"), language, source: src.into_bytes(), script_dir: None });
            }
        }
    }
    out
}

/// The format variants rendered for a language: (variant name, request):
/// every format of the registry at its defaults, under its request name
/// (a new format's rows join the table), then the option variants.
pub(crate) fn variants(language: Language) -> Vec<(&'static str, RenderRequest)> {
    let base = RenderRequest {
        language: Some(language),
        // Generous: a deadline hit on a loaded machine would make the table flaky.
        limits: rulemesh::core::Limits { timeout_ms: 600_000, ..Default::default() },
        ..RenderRequest::default()
    };
    let with = |format: Format, f: &dyn Fn(&mut RenderRequest)| {
        let mut r = RenderRequest { format, ..base.clone() };
        f(&mut r);
        r
    };
    let mut v: Vec<(&'static str, RenderRequest)> = Format::ALL.iter().map(|&f| (f.name(), with(f, &|_| {}))).collect();
    v.extend([
        ("strips-zstd", with(Format::Strips, &|r| r.export_options.strips.zstd = true)),
        ("glb-weld", with(Format::Glb, &|r| r.export_options.gltf.weld = true)),
        ("glb-quantize", with(Format::Glb, &|r| r.export_options.gltf.quantize = true)),
        (
            "glb-meshopt",
            with(Format::Glb, &|r| {
                r.export_options.gltf.quantize = true;
                r.export_options.gltf.compress = Compression::Meshopt;
            }),
        ),
        ("gltf-quantize", with(Format::Gltf, &|r| r.export_options.gltf.quantize = true)),
        ("glb-fit", with(Format::Glb, &|r| r.export_options.fit_unit_box = true)),
        ("glb-per-kind", with(Format::Glb, &|r| r.layout = rulemesh::mesh::MeshLayout::PerKind)),
        ("glb-detail-4", with(Format::Glb, &|r| r.detail = 4)),
    ]);
    // glb/gltf instance repeated meshes by default; the flat files are pinned too.
    v.push(("glb-flat", with(Format::Glb, &|r| r.export_options.instancing = Instancing::Flat)));
    v.push(("gltf-flat", with(Format::Gltf, &|r| r.export_options.instancing = Instancing::Flat)));
    // The scene with its opt-in CRC-32 (docs/scene-format.md, "Checksum"); the plain `scene` rows are unchanged by it.
    v.push(("scene-checksum", with(Format::Scene, &|r| r.export_options.checksum = true)));
    v
}

/// The table cell of one render: the output's hash and its summary counts,
/// or the kind of error it failed with.
fn cell(result: Result<rulemesh::RenderOutput, RenderError>) -> String {
    match result {
        Ok(out) => format!(
            "{} p={} t={}{}",
            blake3::hash(&out.bytes).to_hex(),
            out.primitives,
            out.triangles,
            out.truncated.map(|l| format!(" truncated={:?}", l.limit)).unwrap_or_default()
        ),
        Err(RenderError::Limit(l)) => format!("error:limit:{:?}:{}", l.limit, l.reached),
        Err(RenderError::Parse(_)) => "error:parse".into(),
        Err(RenderError::Eval(_)) => "error:eval".into(),
        // A print stage's internal failure was an export error before it had
        // a variant of its own; the cell keeps its spelling.
        Err(RenderError::Export(_) | RenderError::Print(_)) => "error:export".into(),
        Err(RenderError::BadRequest(_)) => "error:bad-request".into(),
        Err(RenderError::Unprintable(_)) => "error:unprintable".into(),
        Err(RenderError::TooLarge { .. }) => "error:too-large".into(),
    }
}

/// Renders every (case, variant) pair on all cores; rows keyed "case variant".
fn table() -> BTreeMap<String, String> {
    let jobs: Vec<(String, Vec<u8>, RenderRequest)> = cases()
        .into_iter()
        .flat_map(|c| {
            variants(c.language).into_iter().map(move |(v, mut r)| {
                r.script_dir = c.script_dir.clone();
                (format!("{} {v}", c.name), c.source.clone(), r)
            })
        })
        .collect();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let rows = std::sync::Mutex::new(BTreeMap::new());
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((key, source, req)) = jobs.get(i) else { break };
                let c = cell(render(source, req));
                rows.lock().expect("no poisoned lock").insert(key.clone(), c);
            });
        }
    });
    rows.into_inner().expect("no poisoned lock")
}

#[test]
fn golden_hashes_are_unchanged() {
    let path = repo().join("tests/golden/hashes.txt");
    let now = table();
    assert!(now.len() > 1000, "only {} rows", now.len());
    let text: String = now.iter().map(|(k, v)| format!("{k} {v}\n")).collect();
    if std::env::var_os("RULEMESH_BLESS_GOLDEN").is_some() {
        std::fs::write(&path, text).expect("write the table");
        return;
    }
    let committed = std::fs::read_to_string(&path).expect("tests/golden/hashes.txt (bless with RULEMESH_BLESS_GOLDEN=1)");
    let was: BTreeMap<String, String> = committed
        .lines()
        .filter_map(|l| {
            let (case, rest) = l.split_once(' ')?;
            let (variant, value) = rest.split_once(' ')?;
            Some((format!("{case} {variant}"), value.to_string()))
        })
        .collect();
    let mut diffs = Vec::new();
    for (k, v) in &now {
        match was.get(k) {
            Some(w) if w == v => {}
            Some(w) => diffs.push(format!("changed {k}\n   was {w}\n   now {v}")),
            None => diffs.push(format!("new     {k} {v}")),
        }
    }
    for k in was.keys().filter(|k| !now.contains_key(*k)) {
        diffs.push(format!("gone    {k}"));
    }
    assert!(diffs.is_empty(), "{} golden rows differ:\n{}", diffs.len(), diffs.join("\n"));
}
