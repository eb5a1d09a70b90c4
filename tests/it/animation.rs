//! Animated MDG rules export as glTF animations: bone nodes with TRS
//! channels sampled at the grammar's fps, checked against hand-computed
//! quaternions; the camera of `camerarule`; validity in the Khronos validator.

use crate::common::{render_source, tempdir, validate_gltf};
use serde_json::Value;

/// Two nested bones: A turns by SPIN (rz 45° per frame, the first frame
/// already turned) and rises by LIFT (z 0.5 per frame); B, called from A at
/// x 2, turns by SPIN too. 4 fps for 1 s: samples at 0, 0.25, 0.5, 0.75, 1.
const RIG: &str = "startshape A
fps 4
duration 1
camerarule CAM
camerafov 50
rule A : SPIN : LIFT { BOX {} B {x 2} }
rule B : SPIN { SPHERE {} }
rule SPIN { 8/8 * {rz 360} FRAME {} }
rule LIFT { FRAME {} LIFT { z 0.5 } }
rule CAM { FRAME { z -20 } }
";

/// The JSON and BIN chunks of a GLB.
fn split_glb(b: &[u8]) -> (Value, Vec<u8>) {
    let word = |at: usize| u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes")) as usize;
    assert_eq!(&b[0..4], b"glTF");
    let json_len = word(12);
    let json: Value = serde_json::from_slice(&b[20..20 + json_len]).expect("JSON chunk");
    let bin_at = 20 + json_len;
    let bin_len = word(bin_at);
    (json, b[bin_at + 8..bin_at + 8 + bin_len].to_vec())
}

/// The f32 values of accessor `i` (tightly packed float accessors only).
fn floats(doc: &Value, bin: &[u8], i: u64) -> Vec<f32> {
    let a = &doc["accessors"][i as usize];
    assert_eq!(a["componentType"], 5126);
    let width = match a["type"].as_str().expect("type") {
        "SCALAR" => 1,
        "VEC3" => 3,
        "VEC4" => 4,
        t => panic!("{t}"),
    };
    let view = &doc["bufferViews"][a["bufferView"].as_u64().expect("view") as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) + a["byteOffset"].as_u64().unwrap_or(0);
    let n = a["count"].as_u64().expect("count") * width;
    (0..n)
        .map(|k| {
            let at = (start + 4 * k) as usize;
            f32::from_le_bytes(bin[at..at + 4].try_into().expect("4 bytes"))
        })
        .collect()
}

/// The samples of the channel moving node `node` along `path`, grouped per sample.
fn channel(doc: &Value, bin: &[u8], node: u64, path: &str) -> (Vec<f32>, Vec<Vec<f32>>) {
    let anim = &doc["animations"][0];
    let ch = anim["channels"]
        .as_array()
        .expect("channels")
        .iter()
        .find(|c| c["target"]["node"] == node && c["target"]["path"] == path)
        .unwrap_or_else(|| panic!("no {path} channel for node {node}"));
    let sampler = &anim["samplers"][ch["sampler"].as_u64().expect("sampler") as usize];
    assert_eq!(sampler["interpolation"], "LINEAR");
    let times = floats(doc, bin, sampler["input"].as_u64().expect("input"));
    let values = floats(doc, bin, sampler["output"].as_u64().expect("output"));
    let width = values.len() / times.len();
    (times, values.chunks(width).map(<[f32]>::to_vec).collect())
}

fn node_named(doc: &Value, name: &str) -> u64 {
    doc["nodes"].as_array().expect("nodes").iter().position(|n| n["name"] == name).unwrap_or_else(|| panic!("no node {name}")) as u64
}

/// rz(θ) as (x, y, z, w).
fn rz(degrees: f64) -> [f64; 4] {
    let h = degrees.to_radians() / 2.0;
    [0.0, 0.0, h.sin(), h.cos()]
}

/// Equal up to sign (q and −q are the same rotation).
fn same_rotation(q: &[f32], want: [f64; 4]) -> bool {
    let dot: f64 = q.iter().zip(want).map(|(a, b)| f64::from(*a) * b).sum();
    (dot.abs() - 1.0).abs() < 1e-6
}

fn close(a: &[f32], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (f64::from(*x) - y).abs() < 1e-5)
}

#[test]
fn bone_transforms_match_hand_computed_quaternions_at_every_sample() {
    let glb = render_source(RIG, &["--format", "glb"]);
    let (doc, bin) = split_glb(&glb);
    let (a, b) = (node_named(&doc, "A"), node_named(&doc, "B"));
    // B hangs under A: its transform is relative to A's.
    assert!(doc["nodes"][a as usize]["children"].as_array().expect("A has children").contains(&Value::from(b)));

    let (times, rot_a) = channel(&doc, &bin, a, "rotation");
    assert_eq!(times, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    let (_, tr_a) = channel(&doc, &bin, a, "translation");
    let (_, sc_a) = channel(&doc, &bin, a, "scale");
    let (_, rot_b) = channel(&doc, &bin, b, "rotation");
    let (_, tr_b) = channel(&doc, &bin, b, "translation");
    for k in 0..5 {
        // SPIN's frame k is rz 45·(k + 1) (iterator copies start at 1);
        // LIFT's frame k is z 0.5·k; A's track is SPIN then LIFT.
        let turn = 45.0 * (k as f64 + 1.0);
        assert!(same_rotation(&rot_a[k], rz(turn)), "A rotation at sample {k}: {:?} vs {:?}", rot_a[k], rz(turn));
        assert!(close(&tr_a[k], [0.0, 0.0, 0.5 * k as f64]), "A translation at sample {k}: {:?}", tr_a[k]);
        assert!(close(&sc_a[k], [1.0; 3]));
        assert!(same_rotation(&rot_b[k], rz(turn)), "B rotation at sample {k}: {:?}", rot_b[k]);
        assert!(close(&tr_b[k], [2.0, 0.0, 0.0]), "B translation at sample {k}: {:?}", tr_b[k]);
    }
    // Rotations are sign-aligned sample to sample (LINEAR takes the short way).
    for w in rot_a.windows(2) {
        let dot: f32 = w[0].iter().zip(&w[1]).map(|(x, y)| x * y).sum();
        assert!(dot > 0.0);
    }
    // Each node's rest transform is its first sample.
    let rest = &doc["nodes"][a as usize]["rotation"];
    let rest: Vec<f32> = rest.as_array().expect("rotation").iter().map(|v| v.as_f64().expect("number") as f32).collect();
    assert!(same_rotation(&rest, rz(45.0)));

    // The camera: FRAME { z -20 } is the view transform, so the camera sits at z = +20.
    let cam = node_named(&doc, "camera");
    let node = &doc["nodes"][cam as usize];
    assert_eq!(node["camera"], 0);
    let t: Vec<f64> = node["translation"].as_array().expect("translation").iter().map(|v| v.as_f64().expect("number")).collect();
    assert_eq!(t, vec![0.0, 0.0, 20.0]);
    let yfov = doc["cameras"][0]["perspective"]["yfov"].as_f64().expect("yfov");
    assert!((yfov - 50f64.to_radians()).abs() < 1e-6);
}

#[test]
fn animated_models_validate_and_static_formats_show_time_zero() {
    let dir = tempdir();
    let mut files = Vec::new();
    for ext in ["glb", "gltf"] {
        let path = dir.path().join(format!("rig.{ext}"));
        std::fs::write(&path, render_source(RIG, &["--format", ext])).expect("write");
        files.push(path);
    }
    for (errors, warnings, report) in validate_gltf(&files) {
        assert_eq!((errors, warnings), (0, 0), "{report}");
    }
    // Re-runs are byte-identical.
    assert_eq!(render_source(RIG, &["--format", "glb"]), render_source(RIG, &["--format", "glb"]));
    // STL has no nodes: the sphere of B is where the pose at time 0 puts it,
    // 2 units from the axis at 45° (A's and B's turns do not move B's origin
    // off A's x axis turned by 45°).
    let stl = render_source(RIG, &["--format", "stl"]);
    let tris = crate::common::decode_stl(&stl);
    let far = tris.iter().flatten().map(|p| (p[0] * p[0] + p[1] * p[1]).sqrt()).fold(0.0f32, f32::max);
    // The unit sphere (radius 0.5) centred 2 from the axis reaches 2.5.
    assert!((far - 2.5).abs() < 0.02, "{far}");
    let centre_angle = tris
        .iter()
        .flatten()
        .filter(|p| (p[0] * p[0] + p[1] * p[1]).sqrt() > 1.6)
        .map(|p| p[1].atan2(p[0]).to_degrees())
        .sum::<f32>()
        / tris.iter().flatten().filter(|p| (p[0] * p[0] + p[1] * p[1]).sqrt() > 1.6).count() as f32;
    assert!((centre_angle - 45.0).abs() < 1.0, "{centre_angle}");
}

#[test]
fn frame_streams_are_bounded_by_the_budget() {
    // An hour at 240 fps is 864 001 samples per track: the memory budget says no.
    let src = "fps 240\nduration 3600\nstartshape A\nrule A : X { BOX {} }\nrule X { 1000000 * { rz 1 } FRAME {} }\n";
    let out = crate::common::run(&["render", "-", "--language", "mdg", "--format", "glb", "--max-memory", "16000000"], Some(src.as_bytes()));
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("limit exceeded: memory"), "{err}");
}
