//! The C strips decoder (`clients/c/`) against the Rust reference decoder:
//! built with gcc in strict C99 (`-std=c99 -Wall -Wextra -Werror -pedantic`)
//! under AddressSanitizer and UBSan, it must produce byte-identical arrays on
//! every grammar, accept and refuse exactly the damaged payloads the Rust
//! decoder accepts and refuses (every truncation, flipped bytes with and
//! without a fixed CRC), refuse zstd clearly, and its libFuzzer target must
//! build with clang and survive a short run. Needs gcc and clang (scripts/test
//! installs both); without them these tests fail rather than check nothing.

use crate::common::{repo, run, tempdir};
use rulemesh::decode::strips::{decode_strips_full, DecodedStrips};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub(crate) const STRICT: &[&str] = &["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"];
pub(crate) const SANITIZE: &[&str] = &["-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all", "-fno-omit-frame-pointer"];

fn c_file(name: &str) -> String {
    repo().join("clients/c").join(name).to_str().expect("utf-8").to_string()
}

/// Runs a compiler; panics with its diagnostics (a warning is an error).
pub(crate) fn compile(cc: &str, flags: &[&str], sources: &[&str], out: &Path) {
    let o = Command::new(cc)
        .args(flags)
        .args(sources.iter().map(|s| c_file(s)))
        .arg("-lm")
        .arg("-o")
        .arg(out)
        .output()
        .unwrap_or_else(|e| panic!("{cc} cannot run (scripts/test installs it): {e}"));
    assert!(o.status.success(), "{cc} {flags:?} failed:\n{}", String::from_utf8_lossy(&o.stderr));
}

/// The driver, built twice: at -O2 without sanitizers (optimisation enables
/// more of gcc's warnings) and at -O1 with them; the sanitised one is returned.
fn driver(dir: &Path) -> PathBuf {
    let sources = ["rulemesh_strips.c", "strips_dump.c"];
    compile("gcc", &[STRICT, &["-O2"]].concat(), &sources, &dir.join("strips_dump_o2"));
    let exe = dir.join("strips_dump");
    compile("gcc", &[STRICT, SANITIZE, &["-O1"]].concat(), &sources, &exe);
    exe
}

pub(crate) fn exec(exe: &Path, args: &[&str]) -> Output {
    let o = Command::new(exe).args(args).output().expect("run the C driver");
    let stderr = String::from_utf8_lossy(&o.stderr);
    // A sanitizer report is a failure whatever the exit status says.
    assert!(!stderr.contains("Sanitizer") && !stderr.contains("runtime error"), "{args:?}: {stderr}");
    o
}

/// Every grammar file under `grammars/` (any language), sorted.
pub(crate) fn every_grammar() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).expect("grammars/ exists").flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().and_then(|x| x.to_str()).is_some_and(|x| ["mdg", "ls", "es", "ug"].contains(&x)) {
                out.push(p);
            }
        }
    }
    let mut v = Vec::new();
    walk(&repo().join("grammars"), &mut v);
    v.sort();
    v
}

fn render(grammar: &Path, extra: &[&str]) -> Vec<u8> {
    let mut args = vec!["render", grammar.to_str().expect("utf-8"), "--format", "strips"];
    args.extend_from_slice(extra);
    let out = run(&args, None);
    assert!(out.status.success(), "{}: {}", grammar.display(), String::from_utf8_lossy(&out.stderr));
    out.stdout
}

/// The Rust decoder's output in the driver's dump layout (clients/c/strips_dump.c).
fn rust_dump(d: &DecodedStrips) -> Vec<u8> {
    let m = &d.mesh;
    let mut b = b"RMSD".to_vec();
    b.extend_from_slice(&[d.position_bits, d.normal_bits, 0, 0]);
    let palette = d.palette.as_ref().map_or(0, Vec::len);
    for n in [m.positions.len(), m.indices.len() / 3, d.strip.len(), palette] {
        b.extend_from_slice(&u32::try_from(n).expect("fits").to_le_bytes());
    }
    for f in m.positions.iter().chain(&m.normals).flatten() {
        b.extend_from_slice(&f.to_bits().to_le_bytes());
    }
    b.extend(m.colours.iter().flatten());
    for i in m.indices.iter().chain(&d.strip) {
        b.extend_from_slice(&i.to_le_bytes());
    }
    b
}

pub(crate) fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

/// The driver's result line for one payload, computed with the Rust decoder.
fn rust_line(bytes: &[u8]) -> String {
    match decode_strips_full(bytes) {
        Ok(d) => format!("ok {:016x}", fnv1a64(&rust_dump(&d))),
        Err(_) => "err".into(),
    }
}

/// The driver's lines with the C error kind dropped (the two decoders' error
/// types differ; which payloads fail, and what the others decode to, must not).
pub(crate) fn c_lines(o: &Output) -> Vec<String> {
    assert!(o.status.success(), "driver failed: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).lines().map(|l| if l.starts_with("err ") { "err".into() } else { l.to_string() }).collect()
}

pub(crate) fn assert_same_lines(what: &str, c: &[String], rust: &[String]) {
    assert_eq!(c.len(), rust.len(), "{what}: line count");
    if let Some(i) = (0..c.len()).find(|&i| c[i] != rust[i]) {
        panic!("{what}: payload {i}: C says {:?}, Rust says {:?}", c[i], rust[i]);
    }
}

#[test]
fn c_decoder_matches_rust_on_every_grammar() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let grammars = every_grammar();
    assert!(grammars.len() >= 30, "{} grammars", grammars.len());
    // Default options for every grammar, and the other precisions in turn.
    let others: [&[&str]; 4] = [
        &["--position-bits", "12", "--normal-bits", "16"],
        &["--position-bits", "10"],
        &["--position-bits", "8", "--normal-bits", "16"],
        &["--normal-bits", "16"],
    ];
    let mut chunked = 0;
    for (k, g) in grammars.iter().enumerate() {
        for extra in [&[][..], others[k % others.len()]] {
            let name = format!("{} {extra:?}", g.display());
            let bytes = render(g, extra);
            chunked += usize::from(bytes[4] == 3);
            let d = decode_strips_full(&bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(!d.mesh.indices.is_empty(), "{name}: no triangles");
            let input = dir.path().join("in.strips");
            let output = dir.path().join("out.dump");
            std::fs::write(&input, &bytes).expect("write");
            let o = exec(&exe, &[input.to_str().expect("utf-8"), output.to_str().expect("utf-8")]);
            assert!(o.status.success(), "{name}: {}", String::from_utf8_lossy(&o.stderr));
            let got = std::fs::read(&output).expect("dump written");
            let want = rust_dump(&d);
            if got != want {
                let at = got.iter().zip(&want).position(|(a, b)| a != b).unwrap_or(got.len().min(want.len()));
                panic!("{name}: C dump ({} bytes) differs from Rust's ({} bytes) at byte {at}", got.len(), want.len());
            }
        }
    }
    assert!(chunked >= 2, "{chunked} version 3 (chunked) files: the grammars over 65 536 triangles should be");
    // The -O2 build decodes identically too (one file; it is the build apps use).
    let g = repo().join("grammars/gem.mdg");
    let input = dir.path().join("gem.strips");
    std::fs::write(&input, render(&g, &[])).expect("write");
    let output = dir.path().join("gem.dump");
    let o = exec(&dir.path().join("strips_dump_o2"), &[input.to_str().expect("utf-8"), output.to_str().expect("utf-8")]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let d = decode_strips_full(&std::fs::read(&input).expect("read")).expect("decodes");
    assert!(std::fs::read(&output).expect("dump") == rust_dump(&d), "-O2 build differs");
}

/// Every truncation of a fixture, every byte of it flipped (CRC left broken:
/// refused), and every byte of two small files flipped with the CRC fixed (so
/// the damage reaches the stream decoders): the C decoder accepts exactly
/// what the Rust decoder accepts, decodes it to the same arrays, and
/// AddressSanitizer and UBSan stay silent.
#[test]
fn c_decoder_refuses_damage_as_rust_does() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let gem = repo().join("clients/js/fixtures/gem.strips");
    let gem_bytes = std::fs::read(&gem).expect("fixture");
    let gem_s = gem.to_str().expect("utf-8");

    let c = c_lines(&exec(&exe, &["--truncate", gem_s]));
    assert_eq!(c.len(), gem_bytes.len());
    assert!(c.iter().all(|l| l == "err"), "a truncation was accepted");
    let c = c_lines(&exec(&exe, &["--mutate", gem_s, "90", "0"]));
    assert_eq!(c.len(), gem_bytes.len());
    assert!(c.iter().all(|l| l == "err"), "a flipped byte passed the CRC");

    let small = [
        ("hilbert3d", render(&repo().join("grammars/hilbert3d.ls"), &[])),
        ("smooth-joints p12 n16", render(&repo().join("grammars/smooth-joints.mdg"), &["--position-bits", "12", "--normal-bits", "16"])),
    ];
    let mut accepted = 0;
    for (name, bytes) in &small {
        let path = dir.path().join("small.strips");
        std::fs::write(&path, bytes).expect("write");
        for x in [0x01u8, 0x5a, 0x80] {
            let c = c_lines(&exec(&exe, &["--mutate", path.to_str().expect("utf-8"), &x.to_string(), "1"]));
            let rust: Vec<String> = (0..bytes.len())
                .map(|i| {
                    let mut b = bytes.clone();
                    b[i] ^= x;
                    let end = b.len() - 4;
                    if i < end {
                        let crc = crc32fast::hash(&b[..end]);
                        b[end..].copy_from_slice(&crc.to_le_bytes());
                    }
                    rust_line(&b)
                })
                .collect();
            assert_same_lines(&format!("{name} xor {x:#04x}, CRC fixed"), &c, &rust);
            accepted += c.iter().filter(|l| l.starts_with("ok")).count();
        }
    }
    // Some flips survive (a palette colour, a bounding-box bit): those decode
    // to the same changed arrays in both decoders, which checks more than a
    // refusal does.
    assert!(accepted > 0, "no flipped payload decoded: the comparison saw only refusals");

    // Hostile counts and lengths with a valid CRC, each refused before any
    // allocation by both.
    // The same for a version 3 chunk list: chunk count, the first chunk's
    // counts and stream lengths.
    let v3 = as_chunks(&gem_bytes, 2);
    assert!(rust_line(&v3).starts_with("ok"), "the two-chunk file decodes");
    let at = 52 + 4 * u32::from_le_bytes([v3[40], v3[41], v3[42], v3[43]]) as usize;
    let header = [(32usize, u32::MAX - 1), (32, u32::MAX), (36, u32::MAX), (36, u32::MAX / 3), (40, 300), (40, 0), (44, u32::MAX), (48, u32::MAX), (48, 0)];
    let chunks = [(at, 3u32), (at, u32::MAX), (at, 1), (at + 4, u32::MAX), (at + 4, 0), (at + 8, u32::MAX), (at + 8, 1), (at + 12, u32::MAX), (at + 12, 5)];
    let mut batch = Vec::new();
    let mut rust = Vec::new();
    for (source, edits) in [(&gem_bytes, &header), (&v3, &chunks)] {
        for &(off, val) in edits {
            let mut b = source.clone();
            b[off..off + 4].copy_from_slice(&val.to_le_bytes());
            let end = b.len() - 4;
            let crc = crc32fast::hash(&b[..end]);
            b[end..].copy_from_slice(&crc.to_le_bytes());
            batch.extend_from_slice(&u32::try_from(b.len()).expect("fits").to_le_bytes());
            batch.extend_from_slice(&b);
            rust.push(rust_line(&b));
        }
    }
    assert!(rust.iter().all(|l| l == "err"));
    let path = dir.path().join("batch");
    std::fs::write(&path, &batch).expect("write");
    assert_same_lines("hostile header fields", &c_lines(&exec(&exe, &["--batch", path.to_str().expect("utf-8")])), &rust);
}

/// A strips version 3 file holding the one chunk of the version 2 file `v2`
/// `n` times (as `fuzz/make-seeds` makes its seeds): real version 3 files
/// start at 65 537 triangles, but the decoders take chunks of any size.
fn as_chunks(v2: &[u8], n: u32) -> Vec<u8> {
    let u32_at = |at: usize| u32::from_le_bytes([v2[at], v2[at + 1], v2[at + 2], v2[at + 3]]);
    let pal = 4 * u32_at(40) as usize;
    let (v, t) = (u32_at(32), u32_at(36));
    let mut raw = v2[52..52 + pal].to_vec();
    raw.extend_from_slice(&n.to_le_bytes());
    for _ in 0..n {
        raw.extend_from_slice(&v.to_le_bytes());
        raw.extend_from_slice(&t.to_le_bytes());
        raw.extend_from_slice(&v2[52 + pal..v2.len() - 4]);
    }
    let mut out = v2[..52].to_vec();
    out[4] = 3;
    out[32..36].copy_from_slice(&(v * n).to_le_bytes());
    out[36..40].copy_from_slice(&(t * n).to_le_bytes());
    let len = u32::try_from(raw.len()).expect("fits").to_le_bytes();
    out[44..48].copy_from_slice(&len);
    out[48..52].copy_from_slice(&len);
    out.extend_from_slice(&raw);
    let crc = crc32fast::hash(&out);
    out.extend_from_slice(&crc.to_le_bytes());
    out
}

#[test]
fn c_decoder_refuses_zstd_with_a_clear_message() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let path = dir.path().join("gem.zstd.strips");
    std::fs::write(&path, render(&repo().join("grammars/gem.mdg"), &["--zstd"])).expect("write");
    let o = exec(&exe, &[path.to_str().expect("utf-8"), dir.path().join("x").to_str().expect("utf-8")]);
    assert_eq!(o.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.contains("error zstd: this payload is zstd-wrapped"), "{stderr}");
}

/// Builds the libFuzzer target `clients/c/{target}.c` with `decoder` under
/// clang (`-fsanitize=fuzzer,address,undefined`), seeds its corpus with the
/// committed fixtures ending in `.{ext}` (at least two) and `extra` files,
/// and runs 20 000 inputs: none may be a finding. The strips and scene
/// decoders' smoke runs share it.
pub(crate) fn fuzz_smoke(target: &str, decoder: &str, ext: &str, extra: &[(&str, Vec<u8>)]) {
    let dir = tempdir();
    let exe = dir.path().join(target);
    let flags = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-g", "-O1", "-fsanitize=fuzzer,address,undefined", "-fno-sanitize-recover=all"];
    compile("clang", &flags, &[&format!("{target}.c"), decoder], &exe);
    let corpus = dir.path().join("corpus");
    std::fs::create_dir_all(&corpus).expect("mkdir");
    let mut seeds = 0;
    for e in std::fs::read_dir(repo().join("clients/js/fixtures")).expect("fixtures").flatten() {
        if e.path().extension().is_some_and(|x| x == ext) {
            std::fs::copy(e.path(), corpus.join(e.file_name())).expect("copy seed");
            seeds += 1;
        }
    }
    assert!(seeds >= 2, "{seeds} seeds");
    for (name, bytes) in extra {
        std::fs::write(corpus.join(name), bytes).expect("write seed");
    }
    let o = Command::new(&exe)
        .arg(&corpus)
        .args(["-runs=20000", "-seed=1", "-max_len=20000", "-timeout=10", "-rss_limit_mb=2048"])
        .output()
        .expect("run the fuzz target");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "fuzz target found something:\n{stderr}");
    assert!(stderr.contains("Done 20000 runs"), "{stderr}");
}

/// The strips decoder's libFuzzer target runs 20 000 inputs from the
/// committed fixtures without a finding. The long runs are documented in
/// clients/c/README.md.
#[test]
fn c_fuzz_target_survives_a_smoke_run() {
    // The fixtures' .strips files seed it (their .json neighbours are not
    // strips), and a version 3 file of two chunks (a real one is far over -max_len).
    let gradient = std::fs::read(repo().join("clients/js/fixtures/gradient.strips")).expect("fixture");
    fuzz_smoke("fuzz_strips", "rulemesh_strips.c", "strips", &[("gradient.v3.strips", as_chunks(&gradient, 2))]);
}

