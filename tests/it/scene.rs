//! Scene format version 2 end to end (`docs/scene-format.md`): every golden
//! case (grammars, icons, golden sources, docs examples) rendered in process
//! as `scene` and as the flat glb; the scene decoded by the Rust decoder must
//! give the glb's meshes exactly (positions, normals, colours, indices, in
//! order). Then `clients/js/scene.mjs` decodes the same files in Node and
//! must give the Rust decoder's meshes (compared by CRC-32 of each array).

use crate::common::{decode_stl, repo, tempdir};
use crate::golden::{cases, Case};
use rulemesh::decode::scene::{decode_scene, decode_scene_meshes, DecodedScene};
use rulemesh::export::{ExportOptions, Format, Instancing};
use rulemesh::pipeline::{render, RenderRequest};
use serde_json::{json, Value};
use std::path::Path;
use std::process::Command;

/// A mesh as plain arrays.
#[derive(Debug, PartialEq)]
struct Flat {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    colours: Vec<[u8; 4]>,
    indices: Vec<u32>,
}

/// The elements of accessor `i` as little-endian byte groups of `size` bytes.
fn accessor<'a>(json: &Value, bin: &'a [u8], i: &Value, size: usize) -> Vec<&'a [u8]> {
    let acc = &json["accessors"][i.as_u64().expect("accessor") as usize];
    let view = &json["bufferViews"][acc["bufferView"].as_u64().expect("view") as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize + acc["byteOffset"].as_u64().unwrap_or(0) as usize;
    let stride = view["byteStride"].as_u64().map_or(size, |s| s as usize);
    (0..acc["count"].as_u64().expect("count") as usize).map(|k| &bin[start + k * stride..start + k * stride + size]).collect()
}

fn f3(b: &[u8]) -> [f32; 3] {
    [0, 1, 2].map(|c| f32::from_le_bytes(b[4 * c..4 * c + 4].try_into().expect("4 bytes")))
}

/// The meshes of a flat glb, in order; `None` when it carries a node graph
/// (animated grammars), whose meshes sit in their bones' frames.
fn glb_meshes(glb: &[u8]) -> Option<Vec<Flat>> {
    let u32_at = |o: usize| u32::from_le_bytes(glb[o..o + 4].try_into().expect("4 bytes")) as usize;
    let json_len = u32_at(12);
    let json: Value = serde_json::from_slice(&glb[20..20 + json_len]).expect("GLB JSON");
    if json.get("animations").is_some() {
        return None;
    }
    let bin = if glb.len() > 20 + json_len { &glb[28 + json_len..] } else { &[][..] };
    let meshes = json["meshes"].as_array().map(Vec::as_slice).unwrap_or_default();
    Some(
        meshes
            .iter()
            .map(|m| {
                let prims = m["primitives"].as_array().expect("primitives");
                assert_eq!(prims.len(), 1);
                let (p, a) = (&prims[0], &prims[0]["attributes"]);
                let idx = &json["accessors"][p["indices"].as_u64().expect("indices") as usize];
                let short = idx["componentType"].as_u64() == Some(5123);
                Flat {
                    positions: accessor(&json, bin, &a["POSITION"], 12).into_iter().map(f3).collect(),
                    normals: accessor(&json, bin, &a["NORMAL"], 12).into_iter().map(f3).collect(),
                    colours: accessor(&json, bin, &a["COLOR_0"], 4).into_iter().map(|b| b.try_into().expect("rgba")).collect(),
                    indices: accessor(&json, bin, &p["indices"], if short { 2 } else { 4 })
                        .into_iter()
                        .map(|b| if short { u32::from(u16::from_le_bytes([b[0], b[1]])) } else { u32::from_le_bytes(b.try_into().expect("4")) })
                        .collect(),
                }
            })
            .collect(),
    )
}

fn flat(d: &DecodedScene) -> Vec<Flat> {
    d.meshes.iter().map(|m| Flat { positions: m.mesh.positions.clone(), normals: m.mesh.normals.clone(), colours: m.mesh.colours.clone(), indices: m.mesh.indices.clone() }).collect()
}

/// The flat triangles of decoded meshes, as an STL lists them.
fn triangles(d: &DecodedScene) -> Vec<[[f32; 3]; 3]> {
    d.meshes.iter().flat_map(|m| m.mesh.indices.chunks_exact(3).map(|t| t.iter().map(|&i| m.mesh.positions[i as usize]).collect::<Vec<_>>().try_into().expect("3"))).collect()
}

fn request(case: &Case, format: Format) -> RenderRequest {
    RenderRequest {
        language: Some(case.language),
        format,
        script_dir: case.script_dir.clone(),
        export_options: ExportOptions { instancing: Instancing::Flat, ..ExportOptions::default() },
        limits: rulemesh::core::Limits { timeout_ms: 600_000, ..Default::default() },
        ..RenderRequest::default()
    }
}

/// The JSON the JS test compares with: per mesh, its name, counts and the CRC-32 of each array.
fn summary(d: &DecodedScene) -> Value {
    let crc = |b: &[u8]| crc32fast::hash(b);
    let meshes: Vec<Value> = d
        .meshes
        .iter()
        .map(|m| {
            let bytes32 = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
            let idx: Vec<u8> = m.mesh.indices.iter().flat_map(|x| x.to_le_bytes()).collect();
            json!({
                "name": m.name,
                "vertices": m.mesh.positions.len(),
                "triangles": m.mesh.indices.len() / 3,
                "positions": crc(&bytes32(m.mesh.positions.as_flattened())),
                "normals": crc(&bytes32(m.mesh.normals.as_flattened())),
                "colours": crc(m.mesh.colours.as_flattened()),
                "indices": crc(&idx),
            })
        })
        .collect();
    json!({ "detail": d.detail, "truncated": d.truncated, "meshes": meshes })
}

/// Writes `name.rmscene` and the Rust decoder's `name.scene.json` for the JS test.
pub(crate) fn write_fixture(dir: &Path, name: &str, bytes: &[u8], d: &DecodedScene) {
    std::fs::write(dir.join(format!("{name}.rmscene")), bytes).expect("write");
    std::fs::write(dir.join(format!("{name}.scene.json")), serde_json::to_vec(&summary(d)).expect("json")).expect("write");
}

/// Every case renders as `scene`; its decoding is the flat glb (or, for
/// animated models, the STL's triangles); then Node's decoder agrees.
#[test]
fn decoded_scene_is_the_flat_glb_triangle_for_triangle_in_rust_and_js() {
    let dir = tempdir();
    let jobs: Vec<Case> = cases();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let checked = std::sync::Mutex::new((0usize, 0usize, Vec::<String>::new()));
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(case) = jobs.get(i) else { break };
                let Ok(scene) = render(&case.source, &request(case, Format::Scene)) else {
                    // A case that fails as a scene must fail flat too (pinned by the golden table).
                    assert!(render(&case.source, &request(case, Format::Stl)).is_err(), "{}: scene fails, STL renders", case.name);
                    continue;
                };
                let d = decode_scene_meshes(&scene.bytes, 16, u64::MAX).unwrap_or_else(|e| panic!("{}: {e}", case.name));
                let tris: usize = d.meshes.iter().map(|m| m.mesh.indices.len() / 3).sum();
                assert_eq!(tris as u64, scene.triangles, "{}", case.name);
                let glb = render(&case.source, &request(case, Format::Glb)).expect("glb renders");
                let how = match glb_meshes(&glb.bytes) {
                    Some(want) => {
                        let got = flat(&d);
                        assert_eq!(got.len(), want.len(), "{}: mesh count", case.name);
                        for (k, (g, w)) in got.iter().zip(&want).enumerate() {
                            assert!(g == w, "{}: mesh {k} ({}) differs from the flat glb", case.name, d.meshes[k].name);
                        }
                        0
                    }
                    None => {
                        let stl = render(&case.source, &request(case, Format::Stl)).expect("stl renders");
                        assert!(triangles(&d) == decode_stl(&stl.bytes), "{}: triangles differ from the STL", case.name);
                        1
                    }
                };
                let name = case.name.replace(['/', '#', '.'], "_");
                // Node decodes the models up to 50 000 triangles (every kind of
                // record and run occurs there); the largest few would only add seconds.
                if tris <= 50_000 {
                    write_fixture(dir.path(), &name, &scene.bytes, &d);
                }
                let mut c = checked.lock().expect("no poisoned lock");
                if how == 0 { c.0 += 1 } else { c.1 += 1 }
                c.2.push(name);
            });
        }
    });
    let (by_glb, by_stl, _) = checked.into_inner().expect("no poisoned lock");
    assert!(by_glb >= 100 && by_stl >= 3, "{by_glb} cases checked against the glb, {by_stl} against the STL");
    // The committed version 1 file decodes as it did, in Rust and in JS.
    let v1 = std::fs::read(repo().join("clients/js/fixtures/v1-sierpinski-tetrahedron.rmscene")).expect("v1 fixture");
    let h = decode_scene(&v1).expect("v1 decodes");
    assert_eq!((h.leaves(), h.objects.len(), h.entry_count()), (4096, 7, 25));
    let v1d = decode_scene_meshes(&v1, 16, u64::MAX).expect("v1 meshes");
    write_fixture(dir.path(), "v1-sierpinski-tetrahedron", &v1, &v1d);
    // The committed fixtures (what `node --test clients/js/` reads alone)
    // are what the encoder and the Rust decoder make today.
    let fixtures = repo().join("clients/js/fixtures");
    let gem = jobs.iter().find(|c| c.name == "grammars/gem.mdg").expect("gem is a case");
    let bytes = render(&gem.source, &request(gem, Format::Scene)).expect("gem renders").bytes;
    let d = decode_scene_meshes(&bytes, 16, u64::MAX).expect("gem decodes");
    // gem with `checksum: true` (docs/scene-format.md, "Checksum"), also for Node.
    let mut checked_req = request(gem, Format::Scene);
    checked_req.export_options.checksum = true;
    let crc = render(&gem.source, &checked_req).expect("gem renders with a checksum").bytes;
    let crc_d = decode_scene_meshes(&crc, 16, u64::MAX).expect("checksummed gem decodes");
    assert!(crc_d.meshes == d.meshes, "the checksummed gem has gem's meshes");
    write_fixture(dir.path(), "gem.crc", &crc, &crc_d);
    if std::env::var_os("RULEMESH_BLESS").is_some() {
        write_fixture(&fixtures, "gem", &bytes, &d);
        write_fixture(&fixtures, "gem.crc", &crc, &crc_d);
        write_fixture(&fixtures, "v1-sierpinski-tetrahedron", &v1, &v1d);
    }
    for (name, bytes, d) in [("gem", &bytes, &d), ("gem.crc", &crc, &crc_d), ("v1-sierpinski-tetrahedron", &v1, &v1d)] {
        let committed = std::fs::read(fixtures.join(format!("{name}.rmscene"))).expect("fixture exists (RULEMESH_BLESS=1 makes it)");
        assert!(&committed == bytes, "clients/js/fixtures/{name}.rmscene is stale: rerun with RULEMESH_BLESS=1");
        let json: Value = serde_json::from_slice(&std::fs::read(fixtures.join(format!("{name}.scene.json"))).expect("fixture json")).expect("json");
        assert_eq!(json, summary(d), "clients/js/fixtures/{name}.scene.json is stale: rerun with RULEMESH_BLESS=1");
    }
    let o = Command::new("node")
        .arg("--test")
        .arg(repo().join("clients/js/"))
        .env("SCENE_FIXTURES", dir.path())
        .output()
        .unwrap_or_else(|e| panic!("node cannot run (scripts/test installs it): {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "node --test clients/js/ failed:\n{text}");
    assert!(text.contains("# fail 0"), "{text}");
}

/// The WebAssembly kernel the JavaScript decoder embeds
/// (`clients/js/kernel-wasm.mjs`) is what its C sources build to with
/// Debian's clang and wasm-ld: nobody can change the decoder's arithmetic
/// without the reviewable C, nor the C without rebuilding the kernel.
#[test]
fn js_kernel_is_what_its_c_sources_build_to() {
    let o = Command::new("bash")
        .arg(repo().join("scripts/build-js-kernel"))
        .arg("--check")
        .output()
        .unwrap_or_else(|e| panic!("bash cannot run: {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "scripts/build-js-kernel --check (needs clang and lld, which scripts/test installs):\n{text}");
    assert!(text.contains("matches"), "{text}");
}
