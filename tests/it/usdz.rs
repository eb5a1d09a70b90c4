//! USDZ (`docs/usdz.md`), checked by the real consumers: every library
//! grammar renders to a package that Pixar's usd-core opens and validates
//! with every validator it registers (`scripts/usd-check.py`), and that
//! three.js's `USDLoader` (what `USDZLoader` now is) loads in Chromium with
//! the glb's triangle count; the package layout is read byte by byte; a
//! model over the limits is refused; re-runs are byte-identical.

use crate::common::{bin, repo, run, tempdir, three_check};
use rulemesh::lang::Language;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The Python with usd-core (scripts/test installs it into .tools/venv,
/// beside trimesh; `TRIMESH_PYTHON` names that venv's Python).
fn usd_python() -> String {
    std::env::var("TRIMESH_PYTHON").unwrap_or_else(|_| repo().join(".tools/venv/bin/python").display().to_string())
}

/// Runs `scripts/usd-check.py` on `files`: one JSON report per file. Fails
/// when usd-core is missing (exit 2): a skipped check would check nothing.
fn usd_check(files: &[PathBuf]) -> Vec<serde_json::Value> {
    let out = Command::new(usd_python()).arg(repo().join("scripts/usd-check.py")).args(files).output().expect("python runs (scripts/test installs .tools/venv)");
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_ne!(out.status.code(), Some(2), "usd-core is missing (scripts/test installs it): {stderr}");
    let reports: Vec<serde_json::Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("usd-check line {l:?}: {e}")))
        .collect();
    assert_eq!(reports.len(), files.len(), "one report per file; stderr:\n{stderr}");
    reports
}

/// Every library grammar: `grammars/` and `grammars/icons/`, each file a
/// registered language reads.
fn library() -> Vec<PathBuf> {
    let mut v = Vec::new();
    for dir in [repo().join("grammars"), repo().join("grammars/icons")] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).expect("folder").filter_map(|e| e.ok().map(|e| e.path())).filter(|p| Language::from_extension(p).is_some()).collect();
        files.sort();
        v.extend(files);
    }
    v
}

/// Renders `grammar` to `out` through the CLI; the triangles the summary
/// line reports, or the error text when it fails.
fn render_to(grammar: &Path, out: &Path) -> Result<u64, String> {
    let o = run(&["render", grammar.to_str().expect("utf-8"), "-o", out.to_str().expect("utf-8")], None);
    let line = String::from_utf8_lossy(&o.stderr).to_string();
    if !o.status.success() {
        return Err(line);
    }
    Ok(line.split(", ").find_map(|p| p.strip_suffix(" triangles")).and_then(|t| t.parse().ok()).unwrap_or_else(|| panic!("no triangle count in {line}")))
}

#[test]
fn every_library_grammar_renders_validates_and_loads_in_three() {
    let dir = tempdir();
    let mut usdz = Vec::new();
    let mut glb = Vec::new();
    let mut names = Vec::new();
    for g in library() {
        // `icons/tree.mdg` and `tree.mdg` both exist: name files by their path.
        let rel = g.strip_prefix(repo().join("grammars")).expect("under grammars/").with_extension("");
        let stem = rel.to_str().expect("utf-8").replace('/', "-");
        let (u, b) = (dir.path().join(format!("{stem}.usdz")), dir.path().join(format!("{stem}.glb")));
        let t = render_to(&g, &u).unwrap_or_else(|e| panic!("{}: {e}", g.display()));
        assert_eq!(render_to(&g, &b).unwrap_or_else(|e| panic!("{}: {e}", g.display())), t, "{stem}");
        usdz.push(u);
        glb.push(b);
        names.push((stem, t));
    }
    assert!(names.len() >= 40, "only {} library grammars", names.len());
    for (r, (name, t)) in usd_check(&usdz).iter().zip(&names) {
        assert_eq!(r["ok"], true, "{name}: usd-core reports errors: {r}");
        assert_eq!(r["errors"].as_array().map(Vec::len), Some(0), "{name}: {r}");
        assert_eq!(r["triangles"].as_u64(), Some(*t), "{name}: {r}");
        assert_eq!(r["stage"]["defaultPrim"], "Model", "{name}: {r}");
        assert_eq!(r["stage"]["metersPerUnit"], 1.0, "{name}: {r}");
        assert_eq!(r["stage"]["upAxis"], "Y", "{name}: {r}");
        assert_eq!(r["stage"]["customLayerData"]["rulemesh"]["seed"].as_str().map(|s| s.parse::<u64>().is_ok()), Some(true), "{name}: {r}");
    }
    let mut both = usdz.clone();
    both.extend(glb);
    let reports = three_check(&both);
    let (u, g) = reports.split_at(usdz.len());
    for ((ru, rg), (name, t)) in u.iter().zip(g).zip(&names) {
        assert_eq!(ru["ok"], true, "{name}.usdz does not load in three.js: {ru}");
        assert_eq!(rg["ok"], true, "{name}.glb does not load in three.js: {rg}");
        assert_eq!(ru["triangles"], rg["triangles"], "{name}: usdz {ru} glb {rg}");
        assert_eq!(ru["triangles"].as_u64(), Some(*t), "{name}: {ru}");
    }
}

fn u16_at(b: &[u8], at: usize) -> usize {
    usize::from(u16::from_le_bytes([b[at], b[at + 1]]))
}

fn u32_at(b: &[u8], at: usize) -> usize {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]]) as usize
}

/// Walks a zip's local headers from the start (APPNOTE 4.3.7): for each
/// entry its name, compression method, general-purpose flags, data offset
/// and sizes, until the central directory.
fn local_entries(b: &[u8]) -> Vec<(String, usize, usize, usize, usize, usize)> {
    let mut out = Vec::new();
    let mut at = 0;
    while b.get(at..at + 4) == Some(b"PK\x03\x04") {
        let (flags, method) = (u16_at(b, at + 6), u16_at(b, at + 8));
        let (compressed, size) = (u32_at(b, at + 18), u32_at(b, at + 22));
        let (name_len, extra_len) = (u16_at(b, at + 26), u16_at(b, at + 28));
        let name = String::from_utf8(b[at + 30..at + 30 + name_len].to_vec()).expect("utf-8 name");
        let data = at + 30 + name_len + extra_len;
        out.push((name, method, flags, data, compressed, size));
        at = data + compressed;
    }
    assert_eq!(b.get(at..at + 4), Some(&b"PK\x01\x02"[..]), "the central directory follows the last entry's data");
    out
}

#[test]
fn the_package_is_stored_aligned_and_starts_with_the_layer() {
    for grammar in ["gem.mdg", "plant-a.ls", "menger.mdg"] {
        let out = run(&["render", repo().join("grammars").join(grammar).to_str().expect("utf-8"), "--format", "usdz"], None);
        assert!(out.status.success(), "{grammar}: {}", String::from_utf8_lossy(&out.stderr));
        let b = out.stdout;
        let entries = local_entries(&b);
        // gem is flat: its one layer; the L-system and the Menger sponge are
        // hierarchies: the layer, then a prototype layer per leaf shape.
        assert_eq!(entries.len() == 1, grammar == "gem.mdg", "{grammar}: {} entries", entries.len());
        for (k, (name, method, flags, data, compressed, size)) in entries.iter().enumerate() {
            match k {
                0 => assert_eq!(name, "model.usda", "{grammar}: the default layer is the first entry"),
                _ => assert_eq!(*name, format!("prototypes/P_{}.usda", k - 1), "{grammar}"),
            }
            assert_eq!(*method, 0, "{grammar} {name}: stored, not compressed");
            assert_eq!(flags & 1, 0, "{grammar} {name}: not encrypted");
            assert_eq!(flags & 8, 0, "{grammar} {name}: sizes in the local header, no data descriptor");
            assert_eq!(data % 64, 0, "{grammar} {name}: data at {data}, not 64-byte aligned");
            assert_eq!(compressed, size, "{grammar} {name}");
            assert!(b[*data..data + size].starts_with(b"#usda 1.0\n"), "{grammar} {name}");
        }
        // The first entry's padding is Pixar's extra field (header id 0x1986).
        let (name, _, _, data, _, _) = &entries[0];
        let extra = &b[30 + name.len()..*data];
        assert_eq!(u16_at(extra, 0), 0x1986, "{grammar}: {extra:?}");
        // The end of central directory: one entry, no comment.
        let eocd = b.len() - 22;
        assert_eq!(&b[eocd..eocd + 4], b"PK\x05\x06", "{grammar}");
        assert_eq!(u16_at(&b, eocd + 10), entries.len(), "{grammar}");
    }
}

#[test]
fn reruns_are_byte_identical_through_the_cli() {
    for grammar in ["gem.mdg", "stochastic-plant.ls"] {
        let path = repo().join("grammars").join(grammar);
        let render = || run(&["render", path.to_str().expect("utf-8"), "--format", "usdz", "--seed", "7"], None).stdout;
        let a = render();
        assert!(a.len() > 1000, "{grammar}");
        assert!(a == render(), "{grammar}: not deterministic");
    }
}

#[test]
fn a_model_over_the_limits_is_refused_within_memory() {
    // As for every format (tests/it/hostile.rs): flat, each box promises
    // its mesh and its share of the output, so under 64 MB the memory limit
    // binds during evaluation, long before the writer could allocate.
    let dir = tempdir();
    let src = dir.path().join("hostile.mdg");
    std::fs::write(&src, b"startshape A\nrule A { 1000000000 * {x 1} BOX {} }").expect("write");
    let out = dir.path().join("out.usdz");
    let o = Command::new("/usr/bin/time")
        .arg("-v")
        .arg(bin())
        .args(["render", src.to_str().expect("utf-8"), "-o", out.to_str().expect("utf-8"), "--max-memory", "64000000"])
        .output()
        .expect("GNU time runs (scripts/test installs it)");
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(err.contains("Exit status: 3"), "{err}");
    assert!(err.contains("limit exceeded: memory"), "{err}");
    let rss = crate::common::max_rss_bytes(&err);
    assert!(rss < 128 * 1000 * 1000, "peak RSS {rss}");
    assert!(!out.exists() || std::fs::metadata(&out).map(|m| m.len()).unwrap_or(0) == 0, "no package is written");
}

#[test]
fn the_service_route_names_usdz_with_its_mime_type() {
    use rulemesh::export::Format;
    let f = Format::parse("usdz").expect("usdz is registered");
    assert_eq!(f.content_type(), "model/vnd.usdz+zip");
    assert_eq!(Format::from_extension(Path::new("x.USDZ")), Some(f));
    assert!(!f.is_text());
}
