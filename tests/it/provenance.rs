//! Issue 20's reproducible outputs: every format with metadata carries the
//! engine, language, seed, parameters and model key, and a seed above 2⁶³
//! survives exactly (through the CLI here; HTTP and gRPC in
//! `service::http` / `service::grpc`'s 64-bit seed tests).

use crate::common::{repo, run};

/// 2⁶³ + 1: above f64's exact integers, so any float on the way would round it.
const SEED: &str = "9223372036854775809";

fn render_to(grammar: &str, name: &str, extra: &[&str]) -> Vec<u8> {
    let dir = std::env::temp_dir().join(format!("rulemesh-provenance-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out = dir.join(name);
    let g = repo().join("grammars").join(grammar);
    let mut args = vec!["render", g.to_str().expect("utf-8 path"), "--seed", SEED, "-o", out.to_str().expect("utf-8 path")];
    args.extend_from_slice(extra);
    let o = run(&args, None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::read(&out).expect("output")
}

fn check_json(v: &serde_json::Value, language: &str) {
    assert_eq!(v["engine"], format!("rulemesh {}", rulemesh::ENGINE_VERSION), "{v}");
    assert_eq!(v["language"], language, "{v}");
    assert_eq!(v["seed"], SEED, "{v}");
    assert!(v["params"].is_object(), "{v}");
    assert_eq!(v["model_key"].as_str().map(|k| k.len() == 64 && k.bytes().all(|b| b.is_ascii_hexdigit())), Some(true), "{v}");
}

#[test]
fn every_format_with_metadata_carries_a_seed_above_2_63() {
    // glTF: asset.extras.
    let gltf: serde_json::Value = serde_json::from_slice(&render_to("gem.mdg", "gem.gltf", &[])).expect("json");
    check_json(&gltf["asset"]["extras"], "mdg");
    // glb: the same JSON chunk.
    let glb = render_to("gem.mdg", "gem.glb", &[]);
    let len = u32::from_le_bytes(glb[12..16].try_into().expect("4 bytes")) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&glb[20..20 + len]).expect("json chunk");
    check_json(&doc["asset"]["extras"], "mdg");
    // The format is part of the model key, so glb and glTF keys differ.
    assert_ne!(doc["asset"]["extras"]["model_key"], gltf["asset"]["extras"]["model_key"]);
    // 3MF: <metadata name="rulemesh:seed">.
    let threemf = render_to("gem.mdg", "gem.3mf", &[]);
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(threemf)).expect("zip");
    let mut xml = String::new();
    std::io::Read::read_to_string(&mut zip.by_name("3D/3dmodel.model").expect("model"), &mut xml).expect("xml");
    assert!(xml.contains(&format!("<metadata name=\"rulemesh:seed\">{SEED}</metadata>")), "{xml:.600}");
    assert!(xml.contains("<metadata name=\"rulemesh:language\">mdg</metadata>"), "{xml:.600}");
    assert!(xml.contains("<metadata name=\"rulemesh:model-key\">"), "{xml:.600}");
    // PNG: tEXt chunks.
    let png = render_to("gem.mdg", "gem.png", &[]);
    let reader = ::png::Decoder::new(std::io::Cursor::new(png)).read_info().expect("png");
    let text: Vec<(String, String)> = reader.info().uncompressed_latin1_text.iter().map(|t| (t.keyword.clone(), t.text.clone())).collect();
    assert!(text.contains(&("rulemesh:seed".to_string(), SEED.to_string())), "{text:?}");
    // Binary STL: the 80-byte header.
    let stl = render_to("gem.mdg", "gem.stl", &[]);
    assert!(stl.starts_with(format!("rulemesh {} mdg seed={SEED}", rulemesh::ENGINE_VERSION).as_bytes()));
    // Scene: the provenance block after the header.
    let scene = render_to("sierpinski-bush.ls", "bush.rmscene", &[]);
    check_json(&rulemesh::decode::scene::scene_provenance(&scene).expect("reads").expect("present"), "lsystem");
    // Parameters are recorded as the request set them.
    let with = render_to("icosahedron-transformations.mdg", "ico.gltf", &["--param", "phase=0.5"]);
    let v: serde_json::Value = serde_json::from_slice(&with).expect("json");
    assert_eq!(v["asset"]["extras"]["params"], serde_json::json!({"phase": 0.5}));
}
