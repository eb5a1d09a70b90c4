//! Shared helpers: running the binary, validating glTF, reading admesh reports, decoding STL.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The `rulemesh` binary built for these tests.
pub fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_rulemesh"))
}

/// The repository root.
pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every grammar file in `grammars/` with the given extension, sorted.
pub fn grammar_files(ext: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(repo().join("grammars"))
        .expect("grammars/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == ext))
        .collect();
    v.sort();
    v
}

/// Runs `rulemesh` with `args`, feeding `stdin` if given.
pub fn run(args: &[&str], stdin: Option<&[u8]>) -> Output {
    let mut cmd = Command::new(bin());
    cmd.args(args).stdout(Stdio::piped()).stderr(Stdio::piped());
    cmd.stdin(if stdin.is_some() { Stdio::piped() } else { Stdio::null() });
    let mut child = cmd.spawn().expect("spawn rulemesh");
    if let Some(data) = stdin {
        use std::io::Write;
        let mut s = child.stdin.take().expect("stdin");
        // The child may exit early (e.g. source too large); a broken pipe is fine.
        let _ = s.write_all(data);
    }
    child.wait_with_output().expect("wait rulemesh")
}

/// Renders MDG `source` to `format` bytes through the CLI, panicking with stderr on failure.
pub fn render_source(source: &str, extra: &[&str]) -> Vec<u8> {
    let mut args = vec!["render", "-", "--language", "mdg"];
    args.extend_from_slice(extra);
    let out = run(&args, Some(source.as_bytes()));
    assert!(out.status.success(), "render failed: {}", String::from_utf8_lossy(&out.stderr));
    out.stdout
}

/// Validates glTF files with the Khronos validator; returns (errors, warnings, report) per file.
pub fn validate_gltf(files: &[PathBuf]) -> Vec<(u64, u64, String)> {
    let dir = std::env::var("GLTF_VALIDATOR_DIR")
        .unwrap_or_else(|_| repo().join(".tools/node_modules/gltf-validator").display().to_string());
    assert!(
        Path::new(&dir).join("package.json").exists(),
        "the Khronos glTF Validator is not installed at {dir}: run scripts/test, which installs it"
    );
    let out = Command::new("node")
        .arg(repo().join("scripts/validate-gltf.mjs"))
        .args(files)
        .env("GLTF_VALIDATOR_DIR", &dir)
        .output()
        .expect("node runs (scripts/test installs it)");
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let reports: Vec<serde_json::Value> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("validator line {l:?}: {e}")))
        .collect();
    assert_eq!(reports.len(), files.len(), "one report per file: {text}\n{}", String::from_utf8_lossy(&out.stderr));
    reports
        .into_iter()
        .map(|r| {
            (
                r["numErrors"].as_u64().expect("numErrors"),
                r["numWarnings"].as_u64().expect("numWarnings"),
                r.to_string(),
            )
        })
        .collect()
}

/// Peak resident set in bytes from the stderr of `/usr/bin/time -v`.
pub fn max_rss_bytes(gnu_time_stderr: &str) -> u64 {
    let kb: u64 = gnu_time_stderr
        .lines()
        .find_map(|l| l.trim().strip_prefix("Maximum resident set size (kbytes):"))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| panic!("no RSS in GNU time output:\n{gnu_time_stderr}"));
    kb * 1024
}

/// What admesh says about an STL file (exact edge matching only, no repairs).
#[derive(Debug, Default, PartialEq)]
pub struct AdmeshReport {
    pub facets: u64,
    pub open_edges: u64,
    pub parts: u64,
    pub degenerate: u64,
    pub reversed: u64,
    /// Edges whose two faces are wound the same way.
    pub backwards: u64,
    /// Facets with at least one edge no other facet shares.
    pub disconnected: u64,
    pub volume: f64,
    pub raw: String,
}

/// Runs `admesh --exact --normal-directions` and parses its report.
pub fn admesh(file: &Path) -> AdmeshReport {
    let out = Command::new("admesh")
        .args(["--exact", "--normal-directions"])
        .arg(file)
        .output()
        .expect("admesh runs (scripts/test installs it)");
    let raw = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(out.status.success(), "admesh failed on {}: {raw}", file.display());
    let first_num = |label: &str| -> f64 {
        let line = raw.lines().find(|l| l.trim_start().starts_with(label)).unwrap_or_else(|| panic!("no `{label}` in admesh output:\n{raw}"));
        let after = &line[line.find(':').expect("colon") + 1..];
        after.split_whitespace().next().and_then(|t| t.parse().ok()).unwrap_or_else(|| panic!("bad `{label}` line: {line}"))
    };
    let volume = raw
        .lines()
        .find_map(|l| l.split("Volume   :").nth(1))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(f64::NAN);
    AdmeshReport {
        facets: first_num("Number of facets") as u64,
        open_edges: first_num("Facets with 1 disconnected edge") as u64
            + 2 * first_num("Facets with 2 disconnected edges") as u64
            + 3 * first_num("Facets with 3 disconnected edges") as u64,
        parts: first_num("Number of parts") as u64,
        degenerate: first_num("Degenerate facets") as u64,
        reversed: first_num("Facets reversed") as u64,
        backwards: first_num("Backwards edges") as u64,
        disconnected: first_num("Total disconnected facets") as u64,
        volume,
        raw,
    }
}

/// Triangles of a binary STL file.
pub fn decode_stl(bytes: &[u8]) -> Vec<[[f32; 3]; 3]> {
    assert!(bytes.len() >= 84, "STL too short");
    let n = u32::from_le_bytes(bytes[80..84].try_into().expect("4 bytes")) as usize;
    assert_eq!(bytes.len(), 84 + 50 * n, "binary STL length");
    (0..n)
        .map(|i| {
            let f = &bytes[84 + 50 * i + 12..84 + 50 * i + 48];
            let v = |k: usize| -> [f32; 3] {
                let c = |j: usize| f32::from_le_bytes(f[(k * 3 + j) * 4..(k * 3 + j) * 4 + 4].try_into().expect("4 bytes"));
                [c(0), c(1), c(2)]
            };
            [v(0), v(1), v(2)]
        })
        .collect()
}

/// Signed volume enclosed by triangles (positive when they face outward).
pub fn signed_volume(tris: &[[[f32; 3]; 3]]) -> f64 {
    tris.iter()
        .map(|[a, b, c]| {
            let (a, b, c) = (a.map(f64::from), b.map(f64::from), c.map(f64::from));
            (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
        })
        .sum()
}

/// A fresh temporary directory.
pub fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().expect("temp dir")
}

/// The lines `child` writes to its piped stderr, read on a thread of their
/// own (a `rulemesh serve` logs as it runs; the tests wait for lines such as
/// "rulemesh serving" or a request's log line).
pub fn stderr_lines(child: &mut std::process::Child) -> std::sync::mpsc::Receiver<String> {
    use std::io::BufRead as _;
    let stderr = child.stderr.take().expect("stderr is piped");
    let (tx, rx) = std::sync::mpsc::channel::<String>();
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stderr).lines().map_while(Result::ok) {
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    rx
}

/// Runs the three.js harness on `files` in one browser session. Fails when
/// Chromium or three is missing (scripts/test installs both): a skipped check
/// would pass without checking anything.
pub fn three_check(files: &[PathBuf]) -> Vec<serde_json::Value> {
    let out = Command::new("node").arg(repo().join("scripts/three-check/check.mjs")).args(files).output().expect("node runs");
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_ne!(out.status.code(), Some(2), "the three.js check cannot run (scripts/test installs Chromium, three and playwright-core): {stderr}");
    let reports: Vec<serde_json::Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("three-check line {l:?}: {e}")))
        .collect();
    assert_eq!(reports.len(), files.len(), "one report per file; stderr:\n{stderr}");
    reports
}
