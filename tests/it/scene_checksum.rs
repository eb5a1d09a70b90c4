//! The scene format's opt-in checksum (`checksum: true`,
//! docs/scene-format.md, "Checksum"), through the pipeline and the doors:
//! without it the bytes are those of before the option (the golden table
//! pins them); with it the file is the same scene with the `CHECKSUM` flag
//! and a CRC-32 after its last mesh, decoding to the same meshes, and the
//! Rust decoder refuses every damaged byte of every library grammar's
//! checksummed scene. Asked for with another format it is refused by name
//! (body, CLI, gRPC), and ignored by the models route's query for other
//! extensions, as the picture's options are. The C decoder's side is
//! `c_scene::c_scene_decoder_refuses_every_damage_of_a_checksummed_file`;
//! the JavaScript decoder's, `clients/js/scene.test.mjs`.

use crate::common::{repo, run};
use crate::golden::cases;
use rulemesh::core::Limits;
use rulemesh::decode::scene::{decode_scene_meshes, SceneError};
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderRequest};
use rulemesh::service::request::{query_body, RenderBody};
use serde_json::{json, Value};

/// Renders every library grammar (grammars/, icons included) as a scene
/// with and without the checksum: the checksummed file is the plain one
/// with the flag set, a provenance block of the same length (its model key
/// names the option) and the CRC-32 after it; both decode to the same
/// meshes; every byte of the checksummed file flipped (xor 0x01, 0x80 and
/// 0xff at every byte up to 4 KiB, every 61st beyond) is refused, after the
/// flags always as `SceneError::Checksum`.
#[test]
fn every_library_scene_with_a_checksum_refuses_every_flipped_byte() {
    let library: Vec<_> = cases().into_iter().filter(|c| c.name.starts_with("grammars/")).collect();
    assert!(library.len() >= 30, "{} library grammars", library.len());
    let mut checked = 0;
    for case in &library {
        let mut req = RenderRequest {
            language: Some(case.language),
            format: Format::Scene,
            script_dir: case.script_dir.clone(),
            limits: Limits { timeout_ms: 600_000, ..Default::default() },
            ..RenderRequest::default()
        };
        let Ok(plain) = render(&case.source, &req) else { continue };
        req.export_options.checksum = true;
        let crc = render(&case.source, &req).unwrap_or_else(|e| panic!("{}: {e}", case.name)).bytes;
        let plain = plain.bytes;
        let n = crc.len() - 4;
        assert_eq!(n, plain.len(), "{}: four bytes longer", case.name);
        let flags = u16::from_le_bytes([crc[6], crc[7]]);
        assert_eq!(flags, u16::from_le_bytes([plain[6], plain[7]]) | 8, "{}: the CHECKSUM flag added", case.name);
        assert_eq!(crc[n..], crc32fast::hash(&crc[..n]).to_le_bytes(), "{}: the CRC-32 of the bytes before it", case.name);
        let decode = |b: &[u8]| decode_scene_meshes(b, 16, u64::MAX).map(|d| d.meshes);
        assert_eq!(decode(&crc).unwrap_or_else(|e| panic!("{}: {e}", case.name)), decode(&plain).expect("plain decodes"), "{}: the same meshes", case.name);
        for i in (0..crc.len()).filter(|&i| i < 4096 || i % 61 == 0) {
            for x in [0x01u8, 0x80, 0xff] {
                let mut b = crc.clone();
                b[i] ^= x;
                match decode(&b) {
                    Err(SceneError::Checksum { .. }) => {}
                    Err(e) if i < 8 => assert!(matches!(e, SceneError::NotScene | SceneError::Header(_)), "{} xor {x:#04x} at {i}: {e}", case.name),
                    other => panic!("{} xor {x:#04x} at byte {i}: {:?}", case.name, other.map(|m| m.len())),
                }
            }
        }
        checked += 1;
    }
    assert!(checked >= 30, "{checked} grammars checked");
}

/// A small MDG grammar for the door checks.
const SOURCE: &str = "startshape A\nrule A { 3 * { x 1 } BOX {} SPHERE { y 2 } }\n";

fn body_key(options: Value) -> Result<String, String> {
    let mut body = options;
    body["source"] = Value::from(SOURCE);
    let body: RenderBody = serde_json::from_value(body).map_err(|e| e.to_string())?;
    body.plan(&Limits::ceiling(), false).map(|p| p.key.hex()).map_err(|e| e.to_string())
}

fn query_key(ext: &str, query: &[(&str, &str)]) -> Result<String, String> {
    let pairs: Vec<(String, String)> = query.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
    let body = query_body(SOURCE, Language::Mdg, ext, &pairs).map_err(|e| e.to_string())?;
    body.plan(&Limits::ceiling(), false).map(|p| p.key.hex()).map_err(|e| e.to_string())
}

/// `checksum` is refused by name with every format but `scene` (even as
/// `false`, as the schema's `dependentSchemas` refuses it), with a word on
/// strips' own CRC; `false` with `scene` is the default (same key); the
/// CLI's `--checksum` says the same; the models route ignores it for other
/// extensions, so one query string serves every format of a model.
#[test]
fn checksum_is_a_scene_option_refused_elsewhere_by_name() {
    let plain = body_key(json!({ "format": "scene" })).expect("scene");
    assert_eq!(body_key(json!({ "format": "scene", "checksum": false })).expect("scene, false"), plain);
    assert_ne!(body_key(json!({ "format": "scene", "checksum": true })).expect("scene, true"), plain);
    for format in ["glb", "stl", "3mf", "usdz", "png"] {
        for value in [true, false] {
            let err = body_key(json!({ "format": format, "checksum": value })).expect_err("refused");
            assert!(err.contains("checksum needs format=scene"), "{format}: {err}");
        }
    }
    let err = body_key(json!({ "format": "strips", "checksum": true })).expect_err("refused");
    assert!(err.contains("checksum needs format=scene (format=strips always ends with a CRC-32 of its own)"), "{err}");
    // A request built in Rust, past the validator, is refused by the pipeline.
    let req = RenderRequest { format: Format::Glb, export_options: rulemesh::export::ExportOptions { checksum: true, ..Default::default() }, ..RenderRequest::default() };
    assert!(render(SOURCE.as_bytes(), &req).is_err_and(|e| e.to_string().contains("checksum needs format=scene")));
    // The CLI.
    let g = repo().join("grammars/gem.mdg");
    let g = g.to_str().expect("utf-8");
    let o = run(&["render", g, "--format", "glb", "--checksum", "-o", "-"], None);
    assert_eq!(o.status.code(), Some(2), "a usage error");
    assert!(String::from_utf8_lossy(&o.stderr).contains("checksum needs format=scene"), "{}", String::from_utf8_lossy(&o.stderr));
    let o = run(&["render", g, "--format", "scene", "--checksum", "-o", "-"], None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(o.stdout[6] & 8, 8, "the CHECKSUM flag");
    // The models route's query.
    assert_eq!(query_key("glb", &[("checksum", "true")]).expect("ignored for glb"), query_key("glb", &[]).expect("glb"));
    assert_ne!(query_key("rmscene", &[("checksum", "true")]).expect("scene"), query_key("rmscene", &[]).expect("scene"));
    assert!(query_key("glb", &[("checksum", "maybe")]).is_err_and(|e| e.contains("true or false")), "checked all the same");
}
