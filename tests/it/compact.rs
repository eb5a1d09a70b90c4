//! Compact glTF end to end: every built-in grammar rendered plain, welded,
//! quantised (`KHR_mesh_quantization`) and meshopt-compressed
//! (`EXT_meshopt_compression`, with and without quantisation) through the
//! CLI; every file passes the Khronos glTF Validator with no errors and
//! loads in three.js in headless Chromium (`scripts/three-check/`) with the
//! plain file's triangle count (or fewer, for degenerate triangles dropped).
//! Also: the same options on the HTTP route give the CLI's bytes, and
//! `--fit-unit-box` puts the model in the unit box.

use crate::common::{self, grammar_files, repo, run, tempdir, three_check, validate_gltf};
use serde_json::Value;
use std::path::Path;

/// The variants: file suffix and extra CLI arguments.
/// "plain" is the flat file (`--instancing flat`): the compact variants are
/// flat too, so it is what they shrink (the default instanced file of a
/// grammar with repeated meshes is smaller still; tests/it/gpu_instancing.rs).
const VARIANTS: &[(&str, &[&str])] = &[
    ("plain", &["--instancing", "flat"]),
    ("weld", &["--weld"]),
    ("quant", &["--quantize"]),
    ("meshopt", &["--compress", "meshopt"]),
    ("quant-meshopt", &["--quantize", "--compress", "meshopt"]),
];

fn render_to(grammar: &Path, out: &Path, extra: &[&str]) -> u64 {
    let mut args = vec!["render", grammar.to_str().expect("utf-8"), "-o", out.to_str().expect("utf-8")];
    args.extend_from_slice(extra);
    let o = run(&args, None);
    assert!(o.status.success(), "{}: {}", grammar.display(), String::from_utf8_lossy(&o.stderr));
    // "FILE: P primitives, T triangles, …"
    let line = String::from_utf8_lossy(&o.stderr).to_string();
    line.split(", ").find_map(|p| p.strip_suffix(" triangles")).and_then(|t| t.parse().ok()).unwrap_or_else(|| panic!("no triangle count in {line}"))
}

/// The length of a GLB's binary chunk (0 without one).
fn bin_len(bytes: &[u8]) -> usize {
    let jl = u32::from_le_bytes(bytes[12..16].try_into().expect("4 bytes")) as usize;
    bytes.get(20 + jl..20 + jl + 4).map_or(0, |b| u32::from_le_bytes(b.try_into().expect("4 bytes")) as usize)
}

fn glb_json(bytes: &[u8]) -> Value {
    let jl = u32::from_le_bytes(bytes[12..16].try_into().expect("4 bytes")) as usize;
    serde_json::from_slice(&bytes[20..20 + jl]).expect("GLB JSON chunk")
}

#[test]
fn every_grammar_validates_and_loads_in_three_in_every_variant() {
    let dir = tempdir();
    let mut files = Vec::new();
    let mut expected = Vec::new();
    for g in grammar_files("mdg") {
        let name = g.file_stem().and_then(|s| s.to_str()).expect("name").to_string();
        let mut plain_triangles = 0;
        let mut plain_bin = 0;
        for (suffix, extra) in VARIANTS {
            let out = dir.path().join(format!("{name}.{suffix}.glb"));
            let t = render_to(&g, &out, extra);
            let bytes = std::fs::read(&out).expect("output");
            if *suffix == "plain" {
                (plain_triangles, plain_bin) = (t, bin_len(&bytes));
            } else {
                // The binary chunk is what welding, quantisation and
                // compression act on: welding alone can find nothing to merge
                // (every vertex of a flat-shaded or swept mesh is distinct), the
                // others always shrink it. (The JSON grows by the extensions'
                // records, so a 60-vertex model's whole file may not shrink.)
                let bin = bin_len(&bytes);
                let bound = if *suffix == "weld" { plain_bin } else { plain_bin - 1 };
                assert!(bin <= bound, "{name}.{suffix}: binary chunk of {bin} bytes, plain {plain_bin}");
                let j = glb_json(&bytes);
                let used: Vec<&str> = j["extensionsUsed"].as_array().map(|a| a.iter().filter_map(Value::as_str).collect()).unwrap_or_default();
                assert_eq!(used.contains(&"KHR_mesh_quantization"), suffix.starts_with("quant"), "{name}.{suffix}");
                assert_eq!(used.contains(&"EXT_meshopt_compression"), suffix.ends_with("meshopt"), "{name}.{suffix}");
                // Determinism: the same request gives the same bytes.
                let again = dir.path().join(format!("{name}.{suffix}.again.glb"));
                render_to(&g, &again, extra);
                assert!(std::fs::read(&again).expect("again") == bytes, "{name}.{suffix}: not deterministic");
            }
            let animations = glb_json(&std::fs::read(&out).expect("output"))["animations"].as_array().map_or(0, Vec::len);
            files.push(out);
            expected.push((format!("{name}.{suffix}"), plain_triangles, animations));
        }
    }
    for ((errors, warnings, report), (name, _, _)) in validate_gltf(&files).iter().zip(&expected) {
        assert_eq!(*errors, 0, "{name}: {report}");
        assert_eq!(*warnings, 0, "{name}: {report}");
    }
    let reports = three_check(&files);
    for (r, (name, plain, animations)) in reports.iter().zip(&expected) {
        assert_eq!(r["ok"], true, "{name} does not load in three.js: {r}");
        // Animated grammars (windmill) keep their animation through GLTFLoader.
        assert_eq!(r["animations"].as_u64(), Some(*animations as u64), "{name}: {r}");
        let t = r["triangles"].as_u64().expect("triangles");
        if name.ends_with(".plain") {
            assert_eq!(t, *plain, "{name}: {r}");
        } else {
            // Welding drops only zero-area triangles (a handful at most).
            assert!(t <= *plain && t * 100 >= plain * 99, "{name}: {t} triangles in three.js, plain {plain}");
        }
    }
}

#[test]
fn compact_gltf_json_validates_too() {
    let dir = tempdir();
    let g = repo().join("grammars/gem.mdg");
    let out = dir.path().join("gem.gltf");
    render_to(&g, &out, &["--quantize", "--compress", "meshopt"]);
    let j: Value = serde_json::from_slice(&std::fs::read(&out).expect("gltf")).expect("json");
    assert!(j["buffers"][0]["uri"].as_str().expect("uri").starts_with("data:application/octet-stream;base64,"));
    let r = validate_gltf(&[out]);
    assert_eq!((r[0].0, r[0].1), (0, 0), "{}", r[0].2);
}

#[test]
fn fit_unit_box_centres_and_scales() {
    let dir = tempdir();
    for g in grammar_files("mdg") {
        let out = dir.path().join("fit.glb");
        render_to(&g, &out, &["--fit-unit-box"]);
        let j = glb_json(&std::fs::read(&out).expect("glb"));
        // The model's box is the union over every mesh (lines, vertices and
        // isosurfaces are meshes of their own).
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for m in j["meshes"].as_array().expect("meshes") {
            let pos = &j["accessors"][m["primitives"][0]["attributes"]["POSITION"].as_u64().expect("pos") as usize];
            for a in 0..3 {
                lo[a] = lo[a].min(pos["min"][a].as_f64().expect("min"));
                hi[a] = hi[a].max(pos["max"][a].as_f64().expect("max"));
            }
        }
        let c = |k: &str, a: usize| if k == "min" { lo[a] } else { hi[a] };
        let ext = (0..3).map(|a| c("max", a) - c("min", a)).fold(0.0f64, f64::max);
        assert!((ext - 1.0).abs() < 1e-5, "{}: longest side {ext}", g.display());
        for a in 0..3 {
            assert!(c("min", a) >= -0.5 && c("max", a) <= 0.5, "{}", g.display());
            assert!((c("min", a) + c("max", a)).abs() < 1e-5, "{}: not centred on axis {a}", g.display());
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn http_route_options_match_the_cli() {
    let config = rulemesh::service::ServeConfig {
        http: "127.0.0.1:0".parse().expect("addr"),
        grpc: "127.0.0.1:0".parse().expect("addr"),
        ..rulemesh::service::ServeConfig::default()
    };
    let srv = rulemesh::service::start(config).await.expect("server starts");
    let base = format!("http://{}", srv.http_addr);
    let client = reqwest::Client::new();
    let source = std::fs::read_to_string(repo().join("grammars/gem.mdg")).expect("grammar");
    let cli = common::render_source(&source, &["--format", "glb", "--seed", "1", "--quantize", "--compress", "meshopt", "--fit-unit-box"]);
    let get = client.get(format!("{base}/v1/models/gem.glb?seed=1&quantize=true&compress=meshopt&fit=unit")).send().await.expect("GET");
    assert_eq!(get.status(), 200);
    assert!(get.bytes().await.expect("body").as_ref() == cli.as_slice(), "GET bytes differ from the CLI's");
    let body = serde_json::json!({"source": source, "seed": 1, "quantize": true, "compress": "meshopt", "fit": "unit"});
    let post = client.post(format!("{base}/v1/render")).json(&body).send().await.expect("POST");
    assert_eq!(post.status(), 200);
    assert!(post.bytes().await.expect("body").as_ref() == cli.as_slice(), "POST bytes differ from the CLI's");
    // The plain model is cached under another key.
    let plain = client.get(format!("{base}/v1/models/gem.glb?seed=1")).send().await.expect("GET");
    assert!(plain.bytes().await.expect("body").as_ref() != cli.as_slice());
    let bad = client.get(format!("{base}/v1/models/gem.glb?compress=draco")).send().await.expect("GET");
    assert_eq!(bad.status(), 400);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
