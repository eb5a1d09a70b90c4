//! MDG hierarchies (issue 15, "Hierarchies for MDG"; docs/mdg.md): a
//! deterministic derivation is memoised into an object hierarchy for
//! `format=scene` and GPU-instanced glb. The binary bush of 2^18 − 1 boxes
//! is 18 objects; walking a hierarchy gives the flat derivation's instances
//! bit for bit; its instanced glb validates and draws the flat glb's
//! triangles; random selection and continuation are never shared.

use crate::common::{repo, tempdir, validate_gltf};
use rulemesh::core::{Budget, Limit, Limits, OnLimit};
use rulemesh::eval::{bind_params, evaluate, evaluate_hierarchy, EvalOptions};
use rulemesh::decode::scene::{decode_scene, decode_scene_meshes};
use rulemesh::export::{ExportOptions, Format, Instancing};
use rulemesh::lang::{self, Language};
use rulemesh::model::hierarchy::Hierarchy;
use rulemesh::model::instancing::rgba8;
use rulemesh::model::scene::{Instance, Scene};
use rulemesh::{render, RenderError, RenderOutput, RenderRequest};
use std::collections::BTreeMap;

/// The bush of bench/bush-262k.mdg with `maxdepth` levels below the root.
fn bush(maxdepth: u32) -> Vec<u8> {
    format!("startshape B\nmaxdepth {maxdepth}\nrule B {{ BOX {{}} B {{ y 1 rz 25 s 0.8 }} B {{ y 1 rz -25 s 0.8 }} }}\n").into_bytes()
}

fn req(format: Format) -> RenderRequest {
    RenderRequest { language: Some(Language::Mdg), format, ..RenderRequest::default() }
}

fn flat(r: &RenderRequest) -> RenderRequest {
    RenderRequest { export_options: ExportOptions { instancing: Instancing::Flat, ..r.export_options }, ..r.clone() }
}

fn ok(src: &[u8], r: &RenderRequest) -> RenderOutput {
    render(src, r).unwrap_or_else(|e| panic!("{e}"))
}

/// A bush whose two branches tint red and green: a subtree's key then
/// holds its inherited colour, (d + 1)(d + 2)/2 objects for d levels.
const TINTED: &[u8] = b"startshape B\nmaxdepth 6\nrule B { BOX {} B { y 1 rz 25 s 0.8 R 0.1 } B { y 1 rz -25 s 0.8 G 0.1 } }\n";

/// The library's hierarchy of `src` (None: not shared) and its flat derivation.
fn both(src: &[u8]) -> (Option<Hierarchy>, Scene) {
    let program = lang::mdg::parse(src).expect("parses");
    let params = bind_params(&program, &BTreeMap::new()).expect("params");
    let opts = EvalOptions::default();
    let h = evaluate_hierarchy(&program, &params, &opts, &mut Budget::new(Limits::default())).expect("hierarchy");
    let scene = evaluate(&program, &params, &opts, &mut Budget::new(Limits::default())).expect("flat");
    (h, scene)
}

#[test]
fn the_262k_box_bush_is_a_scene_of_18_objects() {
    let src = std::fs::read(repo().join("bench/bush-262k.mdg")).expect("bench file");
    // At default limits: the scene charges its 54 entries, not 262 143 boxes.
    let out = ok(&src, &req(Format::Scene));
    assert_eq!((out.primitives, out.triangles), (262_143, 262_143 * 12));
    assert!(out.bytes.len() < 5_000, "{} bytes", out.bytes.len());
    let h = decode_scene(&out.bytes).expect("decodes");
    assert_eq!((h.objects.len(), h.entry_count(), h.leaves()), (18, 3 * 17 + 1, 262_143));
    assert!(h.is_scaled());
    // Byte-identical reruns.
    assert_eq!(ok(&src, &req(Format::Scene)).bytes, out.bytes);
    // A smaller depth: depth + 1 objects.
    let h = decode_scene(&ok(&bush(6), &req(Format::Scene)).bytes).expect("decodes");
    assert_eq!((h.objects.len(), h.leaves()), (7, 127));
}

#[test]
fn walking_the_hierarchy_gives_the_flat_derivation_bit_for_bit() {
    let menger = std::fs::read(repo().join("grammars/menger.mdg")).expect("grammar");
    for (name, src) in [("bush 9", bush(9)), ("menger", menger), ("tinted", TINTED.to_vec())] {
        let (h, scene) = both(&src);
        let h = h.unwrap_or_else(|| panic!("{name} is shared"));
        let mut walked = Vec::new();
        h.walk(&mut |leaf| {
            let kind = h.shapes[leaf.shape as usize].kind;
            walked.push((Instance::new(kind, &leaf.frame(), [0.0; 4]), leaf.colour));
        });
        assert_eq!(walked.len(), scene.instances.len(), "{name}");
        for (k, ((w, colour), f)) in walked.iter().zip(&scene.instances).enumerate() {
            let same = (w.kind, w.parity, w.translation, w.rotation, w.scale) == (f.kind, f.parity, f.translation, f.rotation, f.scale);
            assert!(same && *colour == rgba8(f.colour), "{name}: leaf {k}: {w:?} {colour:?} vs flat {f:?}");
        }
    }
    // The decoded scene is the flat glb's mesh, and the STL's triangles.
    let src = bush(9);
    let d = decode_scene_meshes(&ok(&src, &req(Format::Scene)).bytes, 16, u64::MAX).expect("decodes");
    let stl = ok(&src, &req(Format::Stl));
    assert_eq!(d.meshes.iter().map(|m| m.mesh.indices.len() as u64 / 3).sum::<u64>(), stl.triangles);
    let tris: Vec<[[f32; 3]; 3]> = d.meshes.iter().flat_map(|m| m.mesh.indices.chunks_exact(3).map(|t| t.iter().map(|&i| m.mesh.positions[i as usize]).collect::<Vec<_>>().try_into().expect("3"))).collect();
    assert!(tris == crate::common::decode_stl(&stl.bytes), "decoded scene differs from the STL");
    // The JavaScript decoder walks scaled entries to the Rust decoder's meshes.
    let dir = tempdir();
    for (name, src) in [("bush-7", bush(7)), ("tinted", TINTED.to_vec())] {
        let bytes = ok(&src, &req(Format::Scene)).bytes;
        let d = decode_scene_meshes(&bytes, 16, u64::MAX).expect("decodes");
        crate::scene::write_fixture(dir.path(), name, &bytes, &d);
    }
    // And one with its checksum (the Node test reads every `.crc.rmscene`).
    let mut checked = req(Format::Scene);
    checked.export_options.checksum = true;
    let bytes = ok(&bush(7), &checked).bytes;
    let d = decode_scene_meshes(&bytes, 16, u64::MAX).expect("decodes");
    crate::scene::write_fixture(dir.path(), "bush-7.crc", &bytes, &d);
    assert_eq!(decode_scene(&ok(TINTED, &req(Format::Scene)).bytes).expect("decodes").objects.len(), 28);
    let o = std::process::Command::new("node")
        .arg("--test")
        .arg(repo().join("clients/js/scene.test.mjs"))
        .env("SCENE_FIXTURES", dir.path())
        .output()
        .unwrap_or_else(|e| panic!("node cannot run (scripts/test installs it): {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success() && text.contains("# fail 0"), "{text}");
}

#[test]
fn the_bush_as_instanced_glb_validates_and_draws_the_flat_triangles() {
    let src = bush(11);
    let r = req(Format::Glb);
    let (gpu, plain) = (ok(&src, &r), ok(&src, &flat(&r)));
    assert_eq!((gpu.primitives, gpu.triangles), (4095, 4095 * 12));
    assert_eq!((plain.primitives, plain.triangles), (gpu.primitives, gpu.triangles));
    assert!(gpu.bytes.len() * 5 < plain.bytes.len(), "instanced {} vs flat {}", gpu.bytes.len(), plain.bytes.len());
    // One box mesh drawn once per leaf, with TRS and colour.
    let jl = u32::from_le_bytes(gpu.bytes[12..16].try_into().expect("4")) as usize;
    let json: serde_json::Value = serde_json::from_slice(&gpu.bytes[20..20 + jl]).expect("json");
    let nodes = json["nodes"].as_array().expect("nodes");
    let instanced: Vec<&serde_json::Value> = nodes.iter().filter(|n| n["extensions"]["EXT_mesh_gpu_instancing"].is_object()).collect();
    assert_eq!((instanced.len(), json["meshes"].as_array().map(Vec::len)), (1, Some(1)), "{json}");
    assert_eq!(json["meshes"][0]["name"], "box");
    let attrs = &instanced[0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
    assert_eq!(json["accessors"][attrs["TRANSLATION"].as_u64().expect("T") as usize]["count"], 4095);
    assert!(attrs["SCALE"].is_u64(), "{attrs}");
    assert_eq!(ok(&src, &r).bytes, gpu.bytes, "byte-identical reruns");
    let dir = tempdir();
    let files: Vec<_> = [("bush.glb", &gpu.bytes), ("bush-flat.glb", &plain.bytes)]
        .iter()
        .map(|(n, b)| {
            let p = dir.path().join(n);
            std::fs::write(&p, b).expect("write");
            p
        })
        .collect();
    for (f, (errors, _, report)) in files.iter().zip(validate_gltf(&files)) {
        assert_eq!(errors, 0, "{}: {report}", f.display());
    }
}

#[test]
fn random_selection_and_continuation_are_not_shared() {
    let random = b"startshape B\nmaxdepth 6\nrule B { BOX {} B { y 1 s 0.8 } B { x 1 s 0.8 } }\nrule B 0.5 { SPHERE {} B { y 1 s 0.8 } B { x 1 s 0.8 } }\n";
    let continued = b"startshape B\nmaxdepth 6\nrule B { BOX {} B { y 1 s 0.8 } \\B { x 1 s 0.8 } }\n";
    let iterated = b"startshape A\nrule A { 4 * { x 2 } C {} }\nrule C { BOX {} BOX { y 1 } }\n";
    for (name, src) in [("random", &random[..]), ("continued", &continued[..]), ("iterated", &iterated[..])] {
        let (h, scene) = both(src);
        assert!(h.is_none(), "{name} must not be shared");
        // The scene holds the flat instances and no hierarchy; glb draws them all.
        let out = ok(src, &req(Format::Scene));
        assert_eq!(decode_scene(&out.bytes).expect("decodes").objects.len(), 0, "{name}");
        assert_eq!(out.primitives, scene.instances.len() as u64, "{name}");
        let glb = ok(src, &req(Format::Glb));
        assert_eq!((glb.primitives, glb.triangles), (ok(src, &flat(&req(Format::Glb))).primitives, ok(src, &flat(&req(Format::Glb))).triangles), "{name}");
    }
    // A deterministic grammar is shared: the same bush without the random alternative.
    assert!(both(&bush(6)).0.is_some());
}

#[test]
fn hierarchy_budgets_count_what_the_output_makes() {
    let src = bush(11);
    let limit = |r: &RenderRequest| match render(&src, r) {
        Err(RenderError::Limit(l)) => Some((l.limit, l.reached)),
        Err(e) => panic!("{e}"),
        Ok(_) => None,
    };
    let at = |format, max_primitives, on_limit| RenderRequest { limits: Limits { max_primitives, ..Limits::default() }, on_limit, ..req(format) };
    // Instanced glb materialises a transform per leaf; the scene its 34 entries and one shape.
    assert_eq!(limit(&at(Format::Glb, 4094, OnLimit::Error)), Some((Limit::Primitives, 4095)));
    assert_eq!(limit(&at(Format::Glb, 4095, OnLimit::Error)), None);
    assert_eq!(limit(&at(Format::Scene, 34, OnLimit::Error)), Some((Limit::Primitives, 35)));
    assert_eq!(limit(&at(Format::Scene, 35, OnLimit::Error)), None);
    // Truncation gives up the hierarchy for the flat derivation, which stops at the limit.
    let cut = ok(&src, &at(Format::Glb, 1000, OnLimit::Truncate));
    assert_eq!((cut.primitives, cut.truncated.map(|t| t.limit)), (1000, Some(Limit::Primitives)));
    // A depth beyond the depth limit is the same typed error as flat.
    let deep = b"startshape B\nrule B { BOX {} B { y 1 s 0.9 } B { x 1 s 0.9 } }\n";
    let depth = |r: &RenderRequest| match render(deep, &RenderRequest { limits: Limits { max_depth: 40, ..Limits::default() }, ..r.clone() }) {
        Err(RenderError::Limit(l)) => l.limit,
        other => panic!("{:?}", other.map(|o| o.primitives)),
    };
    assert_eq!((depth(&req(Format::Scene)), depth(&req(Format::Stl))), (Limit::Depth, Limit::Depth));
}
