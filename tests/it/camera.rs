//! One camera for every glTF writer: an MDG `camerarule` camera survives
//! welding, quantisation, meshopt compression and unit-box fitting (shown at
//! time 0, moved with the fitted model), as a Structure Synth camera does.

use crate::common::{tempdir, validate_gltf};
use rulemesh::export::{Compression, Format};
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderRequest};
use serde_json::Value;

/// The JSON chunk of a GLB, or the document of a .gltf.
fn document(bytes: &[u8]) -> Value {
    if bytes.starts_with(b"glTF") {
        let len = u32::from_le_bytes(bytes[12..16].try_into().expect("4 bytes")) as usize;
        serde_json::from_slice(&bytes[20..20 + len]).expect("GLB JSON chunk")
    } else {
        serde_json::from_slice(bytes).expect("glTF JSON")
    }
}

/// The camera node (a scene root or a child of one) and the camera it names.
fn camera(doc: &Value) -> Option<(Value, Value)> {
    let nodes = doc["nodes"].as_array()?;
    let node = nodes.iter().find(|n| n.get("camera").is_some())?.clone();
    let cam = doc["cameras"][node["camera"].as_u64()? as usize].clone();
    Some((node, cam))
}

fn translation(node: &Value) -> [f64; 3] {
    let t = node["translation"].as_array().expect("translation");
    [0, 1, 2].map(|i| t[i].as_f64().expect("number"))
}

/// The windmill's CAM is `FRAME { y -4 z -26 }`: the camera sits at (0, 4, 26).
const WINDMILL: &str = include_str!("../../grammars/windmill.mdg");

fn request(format: Format, edit: impl Fn(&mut RenderRequest)) -> RenderRequest {
    let mut r = RenderRequest { language: Some(Language::Mdg), format, ..RenderRequest::default() };
    edit(&mut r);
    r
}

#[test]
fn camerarule_camera_survives_every_gltf_writer() {
    let variants: Vec<(&str, RenderRequest)> = vec![
        ("plain.glb", request(Format::Glb, |_| {})),
        ("weld.glb", request(Format::Glb, |r| r.export_options.gltf.weld = true)),
        ("quantize.glb", request(Format::Glb, |r| r.export_options.gltf.quantize = true)),
        ("quantize.gltf", request(Format::Gltf, |r| r.export_options.gltf.quantize = true)),
        (
            "meshopt.glb",
            request(Format::Glb, |r| {
                r.export_options.gltf.quantize = true;
                r.export_options.gltf.compress = Compression::Meshopt;
            }),
        ),
        ("fit.glb", request(Format::Glb, |r| r.export_options.fit_unit_box = true)),
        (
            "fit-meshopt.glb",
            request(Format::Glb, |r| {
                r.export_options.fit_unit_box = true;
                r.export_options.gltf.quantize = true;
                r.export_options.gltf.compress = Compression::Meshopt;
            }),
        ),
    ];
    let dir = tempdir();
    let mut files = Vec::new();
    for (name, req) in &variants {
        let out = render(WINDMILL.as_bytes(), req).expect("windmill renders");
        let doc = document(&out.bytes);
        let (node, cam) = camera(&doc).unwrap_or_else(|| panic!("{name}: no camera"));
        assert_eq!(cam["name"], "camerarule", "{name}");
        assert_eq!(cam["type"], "perspective", "{name}");
        // The grammar sets no camerafov: seed 000's default 40°, near 0.1, far 1000.
        let p = &cam["perspective"];
        assert!((p["yfov"].as_f64().expect("yfov") - 40f64.to_radians()).abs() < 1e-6, "{name}: {p}");
        let t = translation(&node);
        if req.export_options.fit_unit_box {
            // The model moved by p ↦ (p − c)·k; the camera moved alike, and so did its planes.
            let k = p["znear"].as_f64().expect("znear") / 0.1;
            assert!(k > 0.0 && k < 1.0, "{name}: scale {k}");
            assert!((p["zfar"].as_f64().expect("zfar") / 1000.0 - k).abs() < 1e-6 * k.max(1.0), "{name}: {p}");
            // The camera is still in front of the model, nearer by the scale (exact
            // placement: `fitting_moves_the_camera_with_the_model`).
            assert!(t[2] > 0.0 && t[2] < 26.0, "{name}: {t:?}");
        } else {
            assert!((p["znear"].as_f64().expect("znear") - 0.1).abs() < 1e-6, "{name}: {p}");
            assert!((p["zfar"].as_f64().expect("zfar") - 1000.0).abs() < 1e-3, "{name}: {p}");
            assert!((t[0]).abs() < 1e-5 && (t[1] - 4.0).abs() < 1e-5 && (t[2] - 26.0).abs() < 1e-5, "{name}: {t:?}");
        }
        let path = dir.path().join(name);
        std::fs::write(&path, &out.bytes).expect("write");
        files.push(path);
    }
    for (file, (errors, _, report)) in files.iter().zip(validate_gltf(&files)) {
        assert_eq!(errors, 0, "{}: {report}", file.display());
    }
}

/// The bounds of a plain glTF's meshes, from the POSITION accessors' min and max.
fn bounds(doc: &Value) -> ([f64; 3], [f64; 3]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for a in doc["accessors"].as_array().expect("accessors") {
        if let (Some(min), Some(max)) = (a["min"].as_array(), a["max"].as_array()) {
            for i in 0..3 {
                lo[i] = lo[i].min(min[i].as_f64().expect("number"));
                hi[i] = hi[i].max(max[i].as_f64().expect("number"));
            }
        }
    }
    (lo, hi)
}

#[test]
fn fitting_moves_the_camera_with_the_model() {
    // A box seen by a Structure Synth camera: fitted, the camera has moved by
    // the same map p ↦ (p − centre)·k as the model, its planes scaled by k.
    let src = "set scale 1\nset pivot [10 0 0]\n{ x 10 s 4 } box\n";
    let req = |fit: bool| {
        let mut r = RenderRequest { language: Some(Language::Eisenscript), format: Format::Gltf, ..RenderRequest::default() };
        r.export_options.fit_unit_box = fit;
        r
    };
    let plain = document(&render(src.as_bytes(), &req(false)).expect("renders").bytes);
    let fitted = document(&render(src.as_bytes(), &req(true)).expect("renders").bytes);
    let (pn, pc) = camera(&plain).expect("camera");
    let (fnode, fc) = camera(&fitted).expect("camera kept when fitting");
    assert_eq!(translation(&pn), [10.0, 0.0, 20.0]);
    let (lo, hi) = bounds(&plain);
    let centre = [0, 1, 2].map(|a| (lo[a] + hi[a]) / 2.0);
    let k = 1.0 / (0..3).map(|a| hi[a] - lo[a]).fold(0.0, f64::max);
    assert!((k - 0.25).abs() < 1e-6, "the box's longest side is 4: {lo:?} {hi:?}");
    let (p, t) = (translation(&pn), translation(&fnode));
    for a in 0..3 {
        assert!((t[a] - (p[a] - centre[a]) * k).abs() < 1e-5, "axis {a}: {t:?} from {p:?}, centre {centre:?}");
    }
    let (fl, fh) = bounds(&fitted);
    assert!(fl.iter().chain(&fh).all(|v| v.abs() <= 0.5 + 1e-6), "{fl:?} {fh:?}");
    assert_eq!(pn["rotation"], fnode["rotation"]);
    assert_eq!(pc["perspective"]["yfov"], fc["perspective"]["yfov"]);
    let near = |c: &Value| c["perspective"]["znear"].as_f64().expect("znear");
    assert!((near(&fc) - near(&pc) * k).abs() < 1e-9, "{} {}", near(&fc), near(&pc));
}
