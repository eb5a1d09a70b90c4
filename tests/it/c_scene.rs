//! The C scene decoder (`clients/c/rulemesh_scene.c`) against the Rust
//! reference decoder (`decode_scene_meshes`): built with gcc in strict C99
//! (`-std=c99 -Wall -Wextra -Werror -pedantic`) at -O2 and under
//! AddressSanitizer and UBSan, it must give byte-identical meshes (names,
//! positions, normals, colours, indices) for every library grammar's
//! `scene` output, refuse every truncation of the committed fixtures, and
//! accept and refuse exactly what the Rust decoder does for every flipped
//! byte of them (decoding the accepted ones to the same meshes). Its
//! libFuzzer target must build with clang and survive a short run. Needs
//! gcc and clang (scripts/test installs both).
//!
//! Why "refused or decoded as Rust decodes it" for flipped bytes of
//! `gem.rmscene`, where the strips tests say "refused": a scene carries a
//! checksum only when the request asks for one (`checksum: true`,
//! docs/scene-format.md, "Checksum"; by default none, so deployed decoders
//! and the golden scene rows stay as they were). Without it a flipped bit in
//! a transform, a colour or the detail is another valid scene, which both
//! decoders decode to the same meshes. The checksummed fixture
//! (`gem.crc.rmscene`) has every truncation and every flipped byte refused
//! by both decoders with the same error code.

use crate::c_decoder::{assert_same_lines, c_lines, compile, every_grammar, exec, fnv1a64, fuzz_smoke, SANITIZE, STRICT};
use crate::common::{repo, run, tempdir};
use rulemesh::decode::scene::{decode_scene_meshes, DecodedScene};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The triangle limit and version 1 detail `clients/c/scene_dump.c` decodes with.
const MAX_TRIANGLES: u64 = 20_000_000;
const V1_DETAIL: u32 = 16;

/// The driver, built at -O2 without sanitizers (scene_dump_o2; also with
/// `-Wconversion -Wshadow`, warning-free as clients/c/README.md says) and at
/// -O1 with them; the sanitised one is returned.
fn driver(dir: &Path) -> PathBuf {
    let sources = ["rulemesh_scene.c", "scene_dump.c"];
    compile("gcc", &[STRICT, &["-O2", "-Wconversion", "-Wshadow"]].concat(), &sources, &dir.join("scene_dump_o2"));
    let exe = dir.join("scene_dump");
    compile("gcc", &[STRICT, SANITIZE, &["-O1"]].concat(), &sources, &exe);
    exe
}

/// The driver built by clang under the same flags: clang's UBSan also
/// reports pointer arithmetic on NULL (`NULL + 0`), which gcc's does not
/// (the fuzz target's first finding was one).
fn clang_driver(dir: &Path) -> PathBuf {
    let exe = dir.join("scene_dump_clang");
    compile("clang", &[STRICT, SANITIZE, &["-O1"]].concat(), &["rulemesh_scene.c", "scene_dump.c"], &exe);
    exe
}

/// The Rust decoder's meshes in the driver's dump layout (clients/c/scene_dump.c).
fn rust_dump(d: &DecodedScene) -> Vec<u8> {
    let mut b = b"RMSS".to_vec();
    let u32le = |n: usize| u32::try_from(n).expect("fits").to_le_bytes();
    b.extend_from_slice(&u32le(d.meshes.len()));
    for m in &d.meshes {
        b.extend_from_slice(&u32le(m.name.len()));
        b.extend_from_slice(m.name.as_bytes());
        b.extend_from_slice(&u32le(m.mesh.positions.len()));
        b.extend_from_slice(&u32le(m.mesh.indices.len() / 3));
        for f in m.mesh.positions.iter().chain(&m.mesh.normals).flatten() {
            b.extend_from_slice(&f.to_bits().to_le_bytes());
        }
        b.extend(m.mesh.colours.iter().flatten());
        for i in &m.mesh.indices {
            b.extend_from_slice(&i.to_le_bytes());
        }
    }
    b
}

/// The driver's result line for one payload, computed with the Rust decoder.
fn rust_line(bytes: &[u8]) -> String {
    match decode_scene_meshes(bytes, V1_DETAIL, MAX_TRIANGLES) {
        Ok(d) => format!("ok {:016x}", fnv1a64(&rust_dump(&d))),
        Err(_) => "err".into(),
    }
}

fn render_scene(grammar: &Path) -> Vec<u8> {
    let out = run(&["render", grammar.to_str().expect("utf-8"), "--format", "scene"], None);
    assert!(out.status.success(), "{}: {}", grammar.display(), String::from_utf8_lossy(&out.stderr));
    out.stdout
}

/// Decodes `bytes` with `exe` into a dump and compares it with Rust's.
fn same_as_rust(exe: &Path, dir: &Path, name: &str, bytes: &[u8]) -> usize {
    let d = decode_scene_meshes(bytes, V1_DETAIL, MAX_TRIANGLES).unwrap_or_else(|e| panic!("{name}: {e}"));
    let input = dir.join("in.rmscene");
    let output = dir.join("out.dump");
    std::fs::write(&input, bytes).expect("write");
    let o = exec(exe, &[input.to_str().expect("utf-8"), output.to_str().expect("utf-8")]);
    assert!(o.status.success(), "{name}: {}", String::from_utf8_lossy(&o.stderr));
    let got = std::fs::read(&output).expect("dump written");
    let want = rust_dump(&d);
    if got != want {
        let at = got.iter().zip(&want).position(|(a, b)| a != b).unwrap_or(got.len().min(want.len()));
        panic!("{name}: C dump ({} bytes) differs from Rust's ({} bytes) at byte {at}", got.len(), want.len());
    }
    d.meshes.iter().map(|m| m.mesh.indices.len() / 3).sum()
}

#[test]
fn c_scene_decoder_matches_rust_on_every_grammar() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let grammars = every_grammar();
    assert!(grammars.len() >= 30, "{} grammars", grammars.len());
    let (mut hierarchies, mut triangles) = (0, 0);
    for g in &grammars {
        let bytes = render_scene(g);
        // A hierarchy (an L-system's, a deterministic MDG grammar's) is a run of type 5.
        hierarchies += usize::from(decode_scene_meshes(&bytes, V1_DETAIL, MAX_TRIANGLES).is_ok_and(|d| d.meshes.iter().any(|m| m.name == "isosurfaces")));
        triangles += same_as_rust(&exe, dir.path(), &g.display().to_string(), &bytes);
    }
    assert!(hierarchies >= 5 && triangles > 1_000_000, "{hierarchies} hierarchies, {triangles} triangles");
    // The committed fixtures, version 1 included (its detail is the caller's: 16).
    for f in ["gem.rmscene", "gem.crc.rmscene", "v1-sierpinski-tetrahedron.rmscene"] {
        let bytes = std::fs::read(repo().join("clients/js/fixtures").join(f)).expect("fixture");
        same_as_rust(&exe, dir.path(), f, &bytes);
    }
    // A checksummed hierarchy (`--checksum`) decodes as the Rust decoder decodes it.
    let g = repo().join("grammars/sierpinski-bush.ls");
    let out = run(&["render", g.to_str().expect("utf-8"), "--format", "scene", "--checksum"], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    same_as_rust(&exe, dir.path(), "sierpinski-bush --checksum", &out.stdout);
    // The -O2 build (the one apps use) decodes identically too.
    let bytes = render_scene(&repo().join("grammars/sierpinski-bush.ls"));
    same_as_rust(&dir.path().join("scene_dump_o2"), dir.path(), "sierpinski-bush -O2", &bytes);
}

/// Every truncation of the committed fixtures is refused; every byte of
/// them flipped (gem three ways, the version 1 file one way) is refused or
/// decoded exactly as the Rust decoder decodes it; hostile counts are refused. AddressSanitizer and
/// UBSan stay silent throughout (`exec` fails on a report).
#[test]
fn c_scene_decoder_refuses_damage_as_rust_does() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let mut accepted = 0;
    // gem (1 332 bytes, 3 656 triangles) flipped three ways at every byte.
    // The version 1 file (1 134 bytes, 917 504 triangles, about half a
    // second a decode under the sanitizers: ten minutes for every byte) is
    // flipped 0x80 at every byte of its first 64 (the header and its
    // counts) and every 16th after, about two minutes less; every byte with
    // RULEMESH_ALL_FLIPS=1 (the long run, docs/reliability.md).
    let every_flip = std::env::var_os("RULEMESH_ALL_FLIPS").is_some();
    for (f, masks) in [("gem.rmscene", &[0x01u8, 0x80, 0xff][..]), ("v1-sierpinski-tetrahedron.rmscene", &[0x80][..])] {
        let sampled = f.starts_with("v1-") && !every_flip;
        let path = repo().join("clients/js/fixtures").join(f);
        let bytes = std::fs::read(&path).expect("fixture");
        let p = path.to_str().expect("utf-8");
        let c = c_lines(&exec(&exe, &["--truncate", p]));
        assert_eq!(c.len(), bytes.len());
        assert!(c.iter().all(|l| l == "err"), "{f}: a truncation was accepted");
        assert!((0..bytes.len()).all(|n| rust_line(&bytes[..n]) == "err"), "{f}: Rust accepted a truncation");
        for &x in masks {
            let at: Vec<usize> = (0..bytes.len()).filter(|&i| !sampled || i < 64 || i % 16 == 0).collect();
            let flipped = |i: usize| {
                let mut b = bytes.clone();
                b[i] ^= x;
                b
            };
            // The sampled flips reach the C driver as a batch of whole files.
            let batch_path = dir.path().join("flips");
            if sampled {
                let mut batch = Vec::new();
                for &i in &at {
                    batch.extend_from_slice(&u32::try_from(bytes.len()).expect("fits").to_le_bytes());
                    batch.extend_from_slice(&flipped(i));
                }
                std::fs::write(&batch_path, &batch).expect("write");
            }
            let args: Vec<String> = if sampled {
                vec!["--batch".into(), batch_path.to_str().expect("utf-8").into()]
            } else {
                vec!["--mutate".into(), p.into(), x.to_string()]
            };
            // The C driver runs while the Rust decoder computes its lines.
            let (c, rust) = std::thread::scope(|s| {
                let c = s.spawn(|| c_lines(&exec(&exe, &args.iter().map(String::as_str).collect::<Vec<_>>())));
                let rust: Vec<String> = at.iter().map(|&i| rust_line(&flipped(i))).collect();
                (c.join().expect("the C driver's thread"), rust)
            });
            assert_same_lines(&format!("{f} xor {x:#04x}"), &c, &rust);
            accepted += c.iter().filter(|l| l.starts_with("ok")).count();
        }
    }
    // gem flipped once more under the clang build (its UBSan checks NULL + 0 too).
    let gem_path = repo().join("clients/js/fixtures/gem.rmscene");
    let gem_bytes = std::fs::read(&gem_path).expect("fixture");
    let c = c_lines(&exec(&clang_driver(dir.path()), &["--mutate", gem_path.to_str().expect("utf-8"), "128"]));
    let rust: Vec<String> = (0..gem_bytes.len())
        .map(|i| {
            let mut b = gem_bytes.clone();
            b[i] ^= 0x80;
            rust_line(&b)
        })
        .collect();
    assert_same_lines("gem.rmscene xor 0x80 (clang)", &c, &rust);
    // Flips in transforms and colours survive (gem.rmscene has no checksum): both
    // decoders decode them to the same changed meshes.
    assert!(accepted > 100, "{accepted} flipped files decoded: the comparison saw mostly refusals");

    // Hostile counts: every count field of gem (palette, prototypes,
    // provenance length, leaf shapes, objects, meshes, runs, records) and of
    // the version 1 file (leaf shapes, objects) set to huge values.
    let gem = std::fs::read(repo().join("clients/js/fixtures/gem.rmscene")).expect("fixture");
    let v1 = std::fs::read(repo().join("clients/js/fixtures/v1-sierpinski-tetrahedron.rmscene")).expect("fixture");
    let u32_at = |b: &[u8], at: usize| u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes")) as usize;
    let palette_end = 24 + u32_at(&gem, 20) + 4 * u32_at(&gem, 12);
    assert_eq!(u32_at(&gem, 16), 0, "gem has no prototypes");
    let name_len = usize::from(u16::from_le_bytes([gem[palette_end + 12], gem[palette_end + 13]]));
    let runs_at = palette_end + 14 + name_len;
    let gem_fields = [12, 16, 20, palette_end, palette_end + 4, palette_end + 8, runs_at, runs_at + 5];
    let mut batch = Vec::new();
    let mut rust = Vec::new();
    for (source, fields) in [(&gem, &gem_fields[..]), (&v1, &[8usize, 12][..])] {
        for &at in fields {
            for val in [u32::MAX, u32::MAX / 2, 0x8000_0000, 0x0100_0000] {
                let mut b = source.clone();
                b[at..at + 4].copy_from_slice(&val.to_le_bytes());
                batch.extend_from_slice(&u32::try_from(b.len()).expect("fits").to_le_bytes());
                batch.extend_from_slice(&b);
                rust.push(rust_line(&b));
            }
        }
    }
    assert!(rust.iter().all(|l| l == "err"), "Rust accepted a hostile count: {rust:?}");
    let path = dir.path().join("batch");
    std::fs::write(&path, &batch).expect("write");
    assert_same_lines("hostile counts", &c_lines(&exec(&exe, &["--batch", path.to_str().expect("utf-8")])), &rust);
}

/// The C driver's result lines with their error names ("err checksum"),
/// which `c_lines` folds into "err".
fn status_lines(o: &std::process::Output) -> Vec<String> {
    assert!(o.status.success(), "driver failed: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).lines().map(str::to_string).collect()
}

/// The Rust decoder's result for `bytes` as the C driver names it: "ok" or
/// "err <rmsc_status_name>" (for the errors a damaged checksummed file can
/// meet; any other is "err other", which no C line equals).
fn rust_status(bytes: &[u8]) -> String {
    use rulemesh::decode::scene::SceneError;
    match decode_scene_meshes(bytes, V1_DETAIL, MAX_TRIANGLES) {
        Ok(_) => "ok".into(),
        Err(e) => format!(
            "err {}",
            match e {
                SceneError::NotScene => "magic",
                SceneError::Length("truncated") => "truncated",
                SceneError::Length(_) => "trailing",
                SceneError::Header(_) => "header",
                SceneError::Checksum { .. } => "checksum",
                _ => "other",
            }
        ),
    }
}

/// `gem.crc.rmscene` (gem written with `checksum: true`): every truncation
/// and every byte flipped three ways (xor 0x01, 0x80, 0xff) is refused by
/// the C and the Rust decoder with the same error code: past the 8 bytes of
/// magic, version and flags, always `checksum`; within them `magic`,
/// `header` (an unknown flag bit) or `checksum` (a known flag toggled).
/// Clearing the `CHECKSUM` bit alone leaves the CRC as trailing bytes
/// (`trailing`), and setting it on the unchecked gem reads its last four
/// bytes as a CRC that does not match (`checksum`): a flipped flag never
/// turns one kind of file into a valid file of the other. The fixture
/// decodes to gem.rmscene's meshes.
#[test]
fn c_scene_decoder_refuses_every_damage_of_a_checksummed_file() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let fixtures = repo().join("clients/js/fixtures");
    let path = fixtures.join("gem.crc.rmscene");
    let p = path.to_str().expect("utf-8");
    let bytes = std::fs::read(&path).expect("fixture");
    let plain = std::fs::read(fixtures.join("gem.rmscene")).expect("fixture");
    assert_eq!(u16::from_le_bytes([bytes[6], bytes[7]]) & 8, 8, "the CHECKSUM flag is set");
    assert_eq!(&bytes[bytes.len() - 4..], &crc32fast::hash(&bytes[..bytes.len() - 4]).to_le_bytes(), "the last four bytes are the CRC-32");
    let meshes = |b: &[u8]| rust_dump(&decode_scene_meshes(b, V1_DETAIL, MAX_TRIANGLES).expect("decodes"));
    assert!(meshes(&bytes) == meshes(&plain), "the checksummed gem decodes to gem's meshes");
    // Every truncation.
    let c = status_lines(&exec(&exe, &["--truncate", p]));
    let rust: Vec<String> = (0..bytes.len()).map(|n| rust_status(&bytes[..n])).collect();
    assert_eq!(c, rust, "truncations: C and Rust differ");
    for (n, line) in rust.iter().enumerate() {
        let want = if n < 12 { "err truncated" } else { "err checksum" };
        assert_eq!(line, want, "cut at {n}");
    }
    // Every byte flipped three ways.
    for x in [0x01u8, 0x80, 0xff] {
        let c = status_lines(&exec(&exe, &["--mutate", p, &x.to_string()]));
        let rust: Vec<String> = (0..bytes.len())
            .map(|i| {
                let mut b = bytes.clone();
                b[i] ^= x;
                rust_status(&b)
            })
            .collect();
        assert_eq!(c.len(), bytes.len());
        if let Some(i) = (0..c.len()).find(|&i| c[i] != rust[i]) {
            panic!("xor {x:#04x} at byte {i}: C says {:?}, Rust says {:?}", c[i], rust[i]);
        }
        for (i, line) in rust.iter().enumerate() {
            let allowed: &[&str] = if i < 6 { &["err magic"] } else if i < 8 { &["err header", "err checksum"] } else { &["err checksum"] };
            assert!(allowed.contains(&line.as_str()), "xor {x:#04x} at byte {i}: {line}");
        }
    }
    // The flag bit itself, both ways.
    let mut cleared = bytes.clone();
    cleared[6] ^= 8;
    let mut set = plain.clone();
    set[6] ^= 8;
    let mut batch = Vec::new();
    for b in [&cleared, &set] {
        batch.extend_from_slice(&u32::try_from(b.len()).expect("fits").to_le_bytes());
        batch.extend_from_slice(b);
    }
    let batch_path = dir.path().join("flags");
    std::fs::write(&batch_path, &batch).expect("write");
    let c = status_lines(&exec(&exe, &["--batch", batch_path.to_str().expect("utf-8")]));
    assert_eq!(c, [rust_status(&cleared), rust_status(&set)]);
    assert_eq!(c, ["err trailing", "err checksum"]);
}

/// The scene decoder's libFuzzer target runs 20 000 inputs from the
/// committed scene fixtures without a finding. The 10-minute run is
/// recorded in docs/reliability.md.
#[test]
fn c_scene_fuzz_target_survives_a_smoke_run() {
    fuzz_smoke("fuzz_scene", "rulemesh_scene.c", "rmscene", &[]);
}

/// `clients/c/module.modulemap` (Swift's `import RulemeshC`) is a valid
/// Clang module whose umbrella header declares both decoders: clang's
/// module loader, the one Swift's ClangImporter uses, imports it in an
/// Objective-C file (no Swift toolchain here), warning-free.
#[test]
fn c_module_map_imports_both_decoders() {
    let dir = tempdir();
    let src = dir.path().join("import.m");
    std::fs::write(&src, "@import RulemeshC;\nint main(void) { rmsc_error e; rms_error f; (void)e; (void)f; return rmsc_inspect_scratch(1) > 0 ? 0 : 1; }\n").expect("write");
    let cache = dir.path().join("modules");
    let o = Command::new("clang")
        .args(["-fmodules", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-x", "objective-c"])
        .arg(format!("-fmodules-cache-path={}", cache.display()))
        .arg("-I")
        .arg(repo().join("clients/c"))
        .arg(&src)
        .output()
        .unwrap_or_else(|e| panic!("clang cannot run (scripts/test installs it): {e}"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// A version 2 scene whose prototype is `proto` (V, T; no data) placed
/// once, plus a written mesh of `mesh` (V, T; no data): the files of the
/// fuzzer's first finding (empty pieces made the decoder compute NULL + 0).
fn empty_pieces(proto: bool, mesh: bool) -> Vec<u8> {
    let mut b = b"RMSC".to_vec();
    b.extend_from_slice(&2u16.to_le_bytes());
    b.extend_from_slice(&0u16.to_le_bytes());
    b.extend_from_slice(&16u16.to_le_bytes());
    b.extend_from_slice(&0u16.to_le_bytes());
    b.extend_from_slice(&1u32.to_le_bytes()); // one colour
    b.extend_from_slice(&u32::from(proto).to_le_bytes());
    b.extend_from_slice(&[200, 100, 50, 255]);
    if proto {
        b.extend_from_slice(&[0; 8]); // V = 0, T = 0
    }
    b.extend_from_slice(&[0; 8]); // no leaf shapes, no objects
    b.extend_from_slice(&1u32.to_le_bytes()); // one mesh
    b.extend_from_slice(&1u16.to_le_bytes());
    b.push(b'm');
    b.extend_from_slice(&(u32::from(proto) + u32::from(mesh)).to_le_bytes());
    if proto {
        b.push(3); // placed
        b.extend_from_slice(&1u32.to_le_bytes());
        b.extend_from_slice(&0u32.to_le_bytes());
        b.extend_from_slice(&[0, 0]); // not mirrored, colour 0
        for f in [0.0f32, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0] {
            b.extend_from_slice(&f.to_le_bytes());
        }
    }
    if mesh {
        b.push(4); // a written mesh
        b.extend_from_slice(&1u32.to_le_bytes());
        b.extend_from_slice(&[0; 8]);
    }
    b
}

/// Files with empty prototypes and meshes decode to empty meshes in both
/// decoders, with no sanitizer report: the regression test of the C scene
/// fuzz target's first finding (docs/reliability.md).
#[test]
fn c_scene_decoder_decodes_empty_pieces_as_rust_does() {
    let dir = tempdir();
    let exe = driver(dir.path());
    // (the gcc build alone would not have caught the finding: see clang_driver)
    let mut batch = Vec::new();
    let mut rust = Vec::new();
    for (proto, mesh) in [(true, false), (false, true), (true, true), (false, false)] {
        let b = empty_pieces(proto, mesh);
        batch.extend_from_slice(&u32::try_from(b.len()).expect("fits").to_le_bytes());
        batch.extend_from_slice(&b);
        rust.push(rust_line(&b));
    }
    assert!(rust.iter().all(|l| l.starts_with("ok")), "{rust:?}");
    let path = dir.path().join("batch");
    std::fs::write(&path, &batch).expect("write");
    let p = path.to_str().expect("utf-8");
    assert_same_lines("empty pieces", &c_lines(&exec(&exe, &["--batch", p])), &rust);
    assert_same_lines("empty pieces (clang)", &c_lines(&exec(&clang_driver(dir.path()), &["--batch", p])), &rust);
}

/// gem.rmscene with its provenance block replaced by `json`.
fn with_provenance(gem: &[u8], json: &[u8]) -> Vec<u8> {
    let m = u32::from_le_bytes(gem[20..24].try_into().expect("4 bytes")) as usize;
    let mut b = gem[..20].to_vec();
    b.extend_from_slice(&u32::try_from(json.len()).expect("fits").to_le_bytes());
    b.extend_from_slice(json);
    b.extend_from_slice(&gem[24 + m..]);
    b
}

/// The provenance check (`clients/c/rulemesh_text.inc`, a port of serde_json's
/// rules) accepts exactly the blocks the Rust decoder's serde_json accepts:
/// every byte of gem's provenance replaced by each JSON-significant
/// character, and hand-made edge cases (numbers at f64's range, surrogate
/// escapes, nesting at serde_json's limit of 127, control characters, bad
/// UTF-8, other top-level values).
#[test]
fn c_scene_decoder_reads_provenance_as_serde_json_does() {
    let dir = tempdir();
    let exe = driver(dir.path());
    let gem = std::fs::read(repo().join("clients/js/fixtures/gem.rmscene")).expect("fixture");
    let m = u32::from_le_bytes(gem[20..24].try_into().expect("4 bytes")) as usize;
    let prov = gem[24..24 + m].to_vec();
    let mut cases: Vec<Vec<u8>> = Vec::new();
    for i in 0..prov.len() {
        for &c in b"{}[]\":,\\ \t\n0159-+.eEutfnrb/aA\x00\x1f\x7f" {
            let mut p = prov.clone();
            p[i] = c;
            cases.push(p);
        }
    }
    let nest = |n: usize| format!("{{\"a\":{}1{}}}", "[".repeat(n), "]".repeat(n)).into_bytes();
    let big = format!("{{\"n\":1{}}}", "0".repeat(400)).into_bytes();
    let small = format!("{{\"n\":0.{}1}}", "0".repeat(400)).into_bytes();
    let manual: Vec<&[u8]> = vec![
        b"{}", b" {} ", b"{} x", b"[]", b"1", b"\"s\"", b"null", b"",
        b"{\"n\":1e308}", b"{\"n\":1e309}", b"{\"n\":1.7976931348623157e308}", b"{\"n\":1.7976931348623159e308}",
        b"{\"n\":-1e400}", b"{\"n\":0e999999999999}", b"{\"n\":1e-999999999999}", b"{\"n\":1e99999999999}",
        b"{\"n\":18446744073709551615}", b"{\"n\":18446744073709551616}", b"{\"n\":-9223372036854775809}",
        b"{\"n\":01}", b"{\"n\":1.}", b"{\"n\":.5}", b"{\"n\":1e}", b"{\"n\":-}", b"{\"n\":1E+2}", b"{\"n\":-0}",
        b"{\"s\":\"\\ud800\"}", b"{\"s\":\"\\ud800\\udc00\"}", b"{\"s\":\"\\udc00\"}", b"{\"s\":\"\\ud800\\u0041\"}",
        b"{\"s\":\"\\uD83D\\uDE00\"}", b"{\"s\":\"\\u00e9\"}", b"{\"s\":\"\\x\"}", b"{\"s\":\"\t\"}",
        b"{\"s\":\"\xc3\xa9\"}", b"{\"s\":\"\xc3\"}", b"{\"s\":\"\xed\xa0\x80\"}", b"{\"s\":\"\xf4\x90\x80\x80\"}",
        b"{\"a\":1,}", b"{\"a\":1,\"a\":2}", b"{\"a\" 1}", b"{,}", b"{\"a\":[1,2,]}", b"{\"a\":tru}", b"{\"a\":nulll}",
    ];
    cases.extend(manual.iter().map(|c| c.to_vec()));
    cases.extend([nest(126), nest(127), nest(128), big, small]);
    let mut batch = Vec::new();
    let mut rust = Vec::new();
    for c in &cases {
        let b = with_provenance(&gem, c);
        batch.extend_from_slice(&u32::try_from(b.len()).expect("fits").to_le_bytes());
        batch.extend_from_slice(&b);
        rust.push(rust_line(&b));
    }
    let ok = rust.iter().filter(|l| l.starts_with("ok")).count();
    assert!(ok > 100 && ok < rust.len() - 100, "{ok} of {} accepted: the cases should go both ways", rust.len());
    let path = dir.path().join("batch");
    std::fs::write(&path, &batch).expect("write");
    let c = c_lines(&exec(&exe, &["--batch", path.to_str().expect("utf-8")]));
    assert_eq!(c.len(), rust.len());
    if let Some(i) = (0..c.len()).find(|&i| c[i] != rust[i]) {
        panic!("provenance {:?}: C says {}, Rust says {}", String::from_utf8_lossy(&cases[i]), c[i], rust[i]);
    }
}
