//! The `strips` format end to end: every grammar through the CLI, decoded by
//! the Rust reference decoder and by `clients/js/strips.mjs` in Node, against
//! the flat mesh (the binary STL of the same render).

use crate::common::{decode_stl, grammar_files, repo, run, tempdir};
use rulemesh::decode::strips::{decode_strips_full, DecodedStrips};
use std::path::{Path, PathBuf};
use std::process::Command;

fn render(grammar: &Path, extra: &[&str]) -> Vec<u8> {
    let mut args = vec!["render", grammar.to_str().expect("utf-8")];
    args.extend_from_slice(extra);
    let out = run(&args, None);
    assert!(out.status.success(), "{}: {}", grammar.display(), String::from_utf8_lossy(&out.stderr));
    out.stdout
}

fn stem(p: &Path) -> String {
    p.file_stem().and_then(|s| s.to_str()).expect("name").to_string()
}

/// Quantises a position on the file's grid: the spec's formula, written out
/// again here so the test does not trust the encoder.
fn grid(p: [f32; 3], d: &DecodedStrips) -> [u32; 3] {
    let max = f64::from((1u32 << d.position_bits) - 1);
    [0, 1, 2].map(|a| {
        let (lo, hi) = (f64::from(d.bbox_min[a]), f64::from(d.bbox_max[a]));
        if hi > lo {
            ((f64::from(p[a]) - lo) / (hi - lo) * max).round() as u32
        } else {
            0
        }
    })
}

/// Triangles as grid positions, each rotated so its smallest corner comes
/// first (so orientation is kept), zero-area ones dropped, sorted.
fn canonical(tris: impl Iterator<Item = [[u32; 3]; 3]>) -> Vec<[[u32; 3]; 3]> {
    let mut v: Vec<_> = tris
        .filter(|[a, b, c]| a != b && b != c && a != c)
        .map(|[a, b, c]| {
            if a <= b && a <= c {
                [a, b, c]
            } else if b <= a && b <= c {
                [b, c, a]
            } else {
                [c, a, b]
            }
        })
        .collect();
    v.sort();
    v
}

/// Checks a decoded file against the flat mesh's triangles: same triangles
/// (on the quantisation grid) with the same winding, and every decoded
/// position within the documented error bound of the grid point.
fn assert_same_triangles(name: &str, flat: &[[[f32; 3]; 3]], d: &DecodedStrips) {
    let m = &d.mesh;
    let max = f64::from((1u32 << d.position_bits) - 1);
    for p in &m.positions {
        for a in 0..3 {
            let ext = f64::from(d.bbox_max[a]) - f64::from(d.bbox_min[a]);
            let q = grid(*p, d)[a];
            let exact = f64::from(d.bbox_min[a]) + f64::from(q) * ext / max;
            // Dequantisation is exact up to one f32 rounding.
            assert!((f64::from(p[a]) - exact).abs() <= exact.abs() * 1.2e-7 + 1e-30, "{name}: {p:?}");
        }
    }
    let want = canonical(flat.iter().map(|t| t.map(|p| grid(p, d))));
    let got = canonical(m.indices.chunks_exact(3).map(|t| [0, 1, 2].map(|k| grid(m.positions[t[k] as usize], d))));
    assert!(!want.is_empty(), "{name}: no triangles");
    assert_eq!(got.len(), want.len(), "{name}: triangle count");
    assert!(got == want, "{name}: triangle sets differ");
    // Every flat-mesh vertex is within half a grid step of its grid point
    // (the bound the doc states), so matching on the grid is matching within it.
    for t in flat {
        for p in t {
            let g = grid(*p, d);
            for a in 0..3 {
                let ext = f64::from(d.bbox_max[a]) - f64::from(d.bbox_min[a]);
                let back = f64::from(d.bbox_min[a]) + f64::from(g[a]) * ext / max;
                assert!((back - f64::from(p[a])).abs() <= ext / (2.0 * max) * (1.0 + 1e-6) + 1e-6, "{name}: {p:?}");
            }
        }
    }
}

#[test]
fn every_grammar_round_trips_with_every_precision() {
    for g in grammar_files("mdg") {
        let name = stem(&g);
        let flat = decode_stl(&render(&g, &["--format", "stl"]));
        // Strips are a flat mesh format: smaller than the flat glb (an
        // instanced glb of a grammar of repeated meshes can be smaller still).
        let glb = render(&g, &["--format", "glb", "--instancing", "flat"]);
        for (pb, nb, zstd) in [("16", "8", false), ("16", "16", true), ("12", "8", false), ("10", "16", false), ("8", "8", true)] {
            let mut args = vec!["--format", "strips", "--position-bits", pb, "--normal-bits", nb];
            if zstd {
                args.push("--zstd");
            }
            let bytes = render(&g, &args);
            assert_eq!(bytes, render(&g, &args), "{name}: two encodes differ");
            assert!(bytes.len() < glb.len(), "{name}: strips {} bytes, glb {}", bytes.len(), glb.len());
            let d = decode_strips_full(&bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_same_triangles(&format!("{name} p{pb} n{nb} zstd={zstd}"), &flat, &d);
            // Normals are unit length; colours come from the palette.
            for n in &d.mesh.normals {
                let l = n.iter().map(|c| f64::from(*c).powi(2)).sum::<f64>().sqrt();
                assert!((l - 1.0).abs() < 1e-5, "{name}: normal {n:?}");
            }
            assert!(d.palette.is_some(), "{name}: icons have few colours");
        }
    }
}

#[test]
fn decode_command_writes_glb_and_stl_and_rejects_damage() {
    let dir = tempdir();
    let g = repo().join("grammars/gem.mdg");
    let strips = dir.path().join("gem.strips");
    // The extension picks the format.
    let out = run(&["render", g.to_str().expect("utf-8"), "-o", strips.to_str().expect("utf-8")], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&strips).expect("written");
    assert_eq!(&bytes[..4], b"RMST");
    let flat = decode_stl(&render(&g, &["--format", "stl"]));
    // Every format written from meshes, and png through the preview stage.
    for ext in ["stl", "glb", "png"] {
        let o = dir.path().join(format!("back.{ext}"));
        let out = run(&["decode", strips.to_str().expect("utf-8"), "-o", o.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let written = std::fs::read(&o).expect("written");
        if ext == "stl" {
            assert_eq!(decode_stl(&written).len(), flat.len());
        } else if ext == "png" {
            assert_eq!(&written[..8], b"\x89PNG\r\n\x1a\n");
        } else {
            assert_eq!(&written[..4], b"glTF");
        }
    }
    let mut bad = bytes.clone();
    bad[70] ^= 0x10;
    let badp = dir.path().join("bad.strips");
    std::fs::write(&badp, &bad).expect("write");
    let out = run(&["decode", badp.to_str().expect("utf-8"), "-o", "-"], None);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("corrupted"), "{}", String::from_utf8_lossy(&out.stderr));
    std::fs::write(&badp, &bytes[..bytes.len() / 2]).expect("write");
    let out = run(&["decode", badp.to_str().expect("utf-8"), "-o", "-"], None);
    assert!(String::from_utf8_lossy(&out.stderr).contains("truncated"), "{}", String::from_utf8_lossy(&out.stderr));
    // Bad option values are usage errors.
    let out = run(&["render", g.to_str().expect("utf-8"), "--format", "strips", "--position-bits", "7"], None);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
}

/// What the Rust decoder read, as JSON for the Node test.
fn expected_json(d: &DecodedStrips) -> String {
    serde_json::json!({
        "position_bits": d.position_bits,
        "normal_bits": d.normal_bits,
        "positions": d.mesh.positions,
        "normals": d.mesh.normals,
        "colours": d.mesh.colours,
        "strip": d.strip,
        "triangles": d.mesh.indices,
    })
    .to_string()
}

fn write_fixture(dir: &Path, name: &str, bytes: &[u8]) -> (PathBuf, String) {
    let d = decode_strips_full(bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
    let path = dir.join(format!("{name}.strips"));
    std::fs::write(&path, bytes).expect("write");
    let json = expected_json(&d);
    std::fs::write(dir.join(format!("{name}.json")), &json).expect("write");
    (path, json)
}

/// The committed fixtures of `clients/js/fixtures` (what `node --test
/// clients/js/` reads when run alone) must be what the encoder writes today.
/// Regenerate them with `RULEMESH_BLESS=1 cargo test strips`.
#[test]
fn committed_js_fixtures_match_the_encoder() {
    let fixtures = repo().join("clients/js/fixtures");
    let bless = std::env::var_os("RULEMESH_BLESS").is_some();
    for (name, extra) in [("gem", vec![]), ("gradient", vec!["--position-bits", "12", "--normal-bits", "16"])] {
        let mut args = vec!["--format", "strips"];
        args.extend(extra);
        let bytes = render(&repo().join(format!("grammars/{name}.mdg")), &args);
        if bless {
            std::fs::create_dir_all(&fixtures).expect("mkdir");
            write_fixture(&fixtures, name, &bytes);
        }
        let committed = std::fs::read(fixtures.join(format!("{name}.strips"))).expect("fixture exists (RULEMESH_BLESS=1 makes it)");
        assert!(committed == bytes, "clients/js/fixtures/{name}.strips is stale: rerun with RULEMESH_BLESS=1");
        let json = std::fs::read_to_string(fixtures.join(format!("{name}.json"))).expect("fixture json");
        assert_eq!(json, expected_json(&decode_strips_full(&bytes).expect("decodes")), "{name}.json is stale");
    }
}

/// Runs `node --test clients/js/` on one file per grammar (and a zstd one,
/// which the JS decoder must refuse clearly). Fails without Node (scripts/test
/// installs it): a skipped run would check nothing.
#[test]
fn js_decoder_matches_rust_on_every_grammar() {
    let dir = tempdir();
    for g in grammar_files("mdg") {
        write_fixture(dir.path(), &stem(&g), &render(&g, &["--format", "strips"]));
    }
    let z = render(&repo().join("grammars/gem.mdg"), &["--format", "strips", "--zstd"]);
    std::fs::write(dir.path().join("gem.zstd.strips"), z).expect("write");
    let o = Command::new("node")
        .arg("--test")
        .arg(repo().join("clients/js/"))
        .env("STRIPS_FIXTURES", dir.path())
        .output()
        .unwrap_or_else(|e| panic!("node cannot run (scripts/test installs it): {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "node --test clients/js/ failed:\n{text}");
    assert!(text.contains("# fail 0"), "{text}");
    // The grammars over 65 536 triangles are version 3 (chunks): their damage test ran.
    assert!(text.contains("ok ") && text.contains("version 3 chunk lists that disagree"), "{text}");
}

/// Streamed strips of a memoised MDG derivation (a hierarchy, walked leaf by
/// leaf) charge what they make: every leaf a primitive and every triangle,
/// as the flat derivation does; the limits are typed errors, and the bytes
/// are those of the flat mesh (the same file as from the meshes).
#[test]
fn streamed_hierarchy_is_charged_as_flat_geometry() {
    use rulemesh::core::{Limit, Limits};
    use rulemesh::export::Format;
    use rulemesh::{render, RenderError, RenderRequest};
    // 2^10 - 1 = 1023 boxes of 12 triangles, shared as a hierarchy of 10 objects.
    let src = b"startshape B\nmaxdepth 9\nrule B { BOX {} B { y 1 rz 25 s 0.8 } B { y 1 rz -25 s 0.8 } }\n";
    let req = |limits: Limits| RenderRequest { format: Format::Strips, limits, ..RenderRequest::default() };
    let out = render(src, &req(Limits::default())).expect("renders");
    assert_eq!((out.primitives, out.triangles), (1023, 1023 * 12));
    for (limits, want) in [
        (Limits { max_triangles: 1023 * 12 - 1, ..Limits::default() }, Limit::Triangles),
        (Limits { max_primitives: 1022, ..Limits::default() }, Limit::Primitives),
    ] {
        match render(src, &req(limits)) {
            Err(RenderError::Limit(e)) => assert_eq!(e.limit, want),
            other => panic!("{want:?}: {:?}", other.map(|o| o.triangles)),
        }
    }
    // The same bytes as the flat scene's meshes: fitted output is written
    // from the whole mesh (fitting needs it), so compare the decoded
    // triangles with the STL of the same render instead.
    let flat = decode_stl(&render(src, &RenderRequest { format: Format::Stl, ..RenderRequest::default() }).expect("stl").bytes);
    let d = decode_strips_full(&out.bytes).expect("decodes");
    assert_same_triangles("hierarchy", &flat, &d);
}
