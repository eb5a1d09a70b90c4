//! GPU instancing for every language (issue 15): a mesh placed more than
//! once is written once with `EXT_mesh_gpu_instancing` (TRANSLATION,
//! ROTATION, SCALE and `_COLOR_0`), mirrored placements get their own
//! reflected mesh, sheared EisenScript frames and meshes placed once stay
//! plain. Every instanced file is expanded here, instance by instance, and
//! compared with its flat twin (`instancing: flat`): the same triangles,
//! signed volume, area and centroid, and every triangle's winding agrees
//! with its normals as three.js transforms them. Then the Khronos validator
//! and three.js (`scripts/three-check/`) load the instanced files.

use crate::common::{grammar_files, repo, tempdir, three_check, validate_gltf};
use glam::{DQuat, DVec3};
use rulemesh::core::{Limit, Limits};
use rulemesh::export::{ExportOptions, Format, Instancing};
use rulemesh::lang::Language;
use rulemesh::{render, RenderError, RenderOutput, RenderRequest};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn req(language: Language, format: Format) -> RenderRequest {
    RenderRequest { language: Some(language), format, ..RenderRequest::default() }
}

fn flat(r: &RenderRequest) -> RenderRequest {
    RenderRequest { export_options: ExportOptions { instancing: Instancing::Flat, ..r.export_options }, ..r.clone() }
}

fn ok(src: &[u8], r: &RenderRequest) -> RenderOutput {
    render(src, r).unwrap_or_else(|e| panic!("{e}"))
}

/// A GLB's JSON and binary chunk.
fn chunks(glb: &[u8]) -> (Value, &[u8]) {
    let jl = u32::from_le_bytes(glb[12..16].try_into().expect("4 bytes")) as usize;
    let json = serde_json::from_slice(&glb[20..20 + jl]).expect("GLB JSON chunk");
    (json, glb.get(20 + jl + 8..).unwrap_or_default())
}

/// Accessor `i`'s components as f64 (float or unsigned integer data, tightly packed).
fn read(j: &Value, bin: &[u8], i: &Value) -> Vec<f64> {
    let a = &j["accessors"][i.as_u64().expect("accessor index") as usize];
    let view = &j["bufferViews"][a["bufferView"].as_u64().expect("view") as usize];
    let at = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    let width = match a["type"].as_str().expect("type") {
        "SCALAR" => 1,
        "VEC3" => 3,
        "VEC4" => 4,
        t => panic!("accessor type {t}"),
    };
    let n = a["count"].as_u64().expect("count") as usize * width;
    let word = |k: usize, size: usize| &bin[at + size * k..at + size * (k + 1)];
    match a["componentType"].as_u64().expect("component type") {
        5126 => (0..n).map(|k| f64::from(f32::from_le_bytes(word(k, 4).try_into().expect("4")))).collect(),
        5125 => (0..n).map(|k| f64::from(u32::from_le_bytes(word(k, 4).try_into().expect("4")))).collect(),
        5123 => (0..n).map(|k| f64::from(u16::from_le_bytes(word(k, 2).try_into().expect("2")))).collect(),
        c => panic!("component type {c}"),
    }
}

/// What a glb draws in world space.
#[derive(Debug, Default)]
struct Drawn {
    triangles: u64,
    instances: u64,
    /// Signed volume (winding decides its sign).
    volume: f64,
    area: f64,
    /// Area-weighted sum of triangle centroids.
    moment: DVec3,
    /// Area-weighted sum of the centroids' lengths: the scale the moment's
    /// rounding is measured against (a symmetric model's moment cancels to ~0).
    moment_scale: f64,
    /// Triangles whose winding disagrees with their (transformed) vertex normals.
    inside_out: u64,
    /// Negative SCALE components written.
    negative_scales: u64,
    /// Instances of nodes that carry `_COLOR_0`.
    coloured: u64,
}

/// Expands every mesh node of `glb` (each instance of an instanced one, by
/// T·R·S, normals as three.js moves them: R·(n / s)) and sums what it draws.
fn drawn(glb: &[u8]) -> Drawn {
    let (j, bin) = chunks(glb);
    let mut d = Drawn::default();
    for node in j["nodes"].as_array().expect("nodes") {
        let Some(mesh) = node["mesh"].as_u64() else { continue };
        let prim = &j["meshes"][mesh as usize]["primitives"][0];
        let vec3s = |v: Vec<f64>| v.chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect::<Vec<_>>();
        let positions = vec3s(read(&j, bin, &prim["attributes"]["POSITION"]));
        let normals = vec3s(read(&j, bin, &prim["attributes"]["NORMAL"]));
        let indices: Vec<usize> = read(&j, bin, &prim["indices"]).into_iter().map(|i| i as usize).collect();
        let ext = &node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
        let placements: Vec<(DVec3, DQuat, DVec3)> = if ext.is_object() {
            let t = vec3s(read(&j, bin, &ext["TRANSLATION"]));
            // A missing ROTATION or SCALE is the identity for every instance.
            let r: Vec<DQuat> = if ext["ROTATION"].is_null() {
                vec![DQuat::IDENTITY; t.len()]
            } else {
                read(&j, bin, &ext["ROTATION"]).chunks_exact(4).map(|q| DQuat::from_xyzw(q[0], q[1], q[2], q[3])).collect()
            };
            let s = if ext["SCALE"].is_null() { vec![DVec3::ONE; t.len()] } else { vec3s(read(&j, bin, &ext["SCALE"])) };
            if !ext["_COLOR_0"].is_null() {
                d.coloured += t.len() as u64;
            }
            d.negative_scales += s.iter().map(|s| [s.x, s.y, s.z].iter().filter(|&&c| c < 0.0).count() as u64).sum::<u64>();
            d.instances += t.len() as u64;
            t.into_iter().zip(r).zip(s).map(|((t, r), s)| (t, r, s)).collect()
        } else {
            vec![(DVec3::ZERO, DQuat::IDENTITY, DVec3::ONE)]
        };
        for (t, r, s) in placements {
            for tri in indices.chunks_exact(3) {
                let tri = [tri[0], tri[1], tri[2]];
                let p = tri.map(|i| t + r * (s * positions[i]));
                let n = tri.map(|i| r * (normals[i] / s));
                let face = (p[1] - p[0]).cross(p[2] - p[0]);
                d.triangles += 1;
                d.volume += p[0].dot(p[1].cross(p[2])) / 6.0;
                d.area += face.length() / 2.0;
                d.moment += (p[0] + p[1] + p[2]) / 3.0 * (face.length() / 2.0);
                d.moment_scale += ((p[0] + p[1] + p[2]) / 3.0).length() * (face.length() / 2.0);
                if face.length() > 1e-9 && face.dot(n[0] + n[1] + n[2]) < 0.0 {
                    d.inside_out += 1;
                }
            }
        }
    }
    d
}

/// How the instanced file's drawing differs from the flat one's (empty when
/// it draws the same: same triangles, and the same volume, area and
/// centroid to f32 precision; no negative scale, and no more triangles
/// facing against their normals than the flat file has).
fn drawing_differences(name: &str, instanced: &[u8], flat: &[u8]) -> Vec<String> {
    let (a, b) = (drawn(instanced), drawn(flat));
    let mut out = Vec::new();
    if a.triangles != b.triangles || a.negative_scales != 0 || a.inside_out > b.inside_out {
        out.push(format!("{name}: {} triangles ({} inside out, {} negative scales), flat {} ({} inside out)", a.triangles, a.inside_out, a.negative_scales, b.triangles, b.inside_out));
    }
    let far = |x: f64, y: f64, scale: f64| (x - y).abs() > 1e-5 * (1.0 + scale);
    let m = b.moment_scale;
    for (what, x, y, scale) in [
        ("volume", a.volume, b.volume, b.volume.abs()),
        ("area", a.area, b.area, b.area),
        ("x moment", a.moment.x, b.moment.x, m),
        ("y moment", a.moment.y, b.moment.y, m),
        ("z moment", a.moment.z, b.moment.z, m),
    ] {
        if far(x, y, scale) {
            out.push(format!("{name}: {what} {x} vs flat {y}"));
        }
    }
    out
}

fn assert_same_drawing(name: &str, instanced: &[u8], flat: &[u8]) {
    let d = drawing_differences(name, instanced, flat);
    assert!(d.is_empty(), "{}", d.join("\n"));
}

/// Library grammars and test sources of every language that places
/// primitives, with their languages.
fn library() -> Vec<(PathBuf, Language)> {
    let mut out: Vec<(PathBuf, Language)> = Vec::new();
    for (ext, language) in [("mdg", Language::Mdg), ("ls", Language::Lsystem)] {
        out.extend(grammar_files(ext).into_iter().map(|g| (g, language)));
    }
    let mut icons: Vec<PathBuf> = std::fs::read_dir(repo().join("grammars/icons")).expect("icons").map(|e| e.expect("entry").path()).collect();
    icons.sort();
    out.extend(icons.into_iter().filter(|p| p.extension().is_some_and(|e| e == "mdg")).map(|p| (p, Language::Mdg)));
    // The golden EisenScript sources that build a still model (movie.es plays frames).
    for name in ["camera-classes.es", "frame.es", "lines.es", "random.es"] {
        out.push((repo().join("tests/golden/sources").join(name), Language::Eisenscript));
    }
    out
}

/// Every library grammar renders as instanced glb and glTF that pass the
/// validator with no errors or warnings, draw what their flat twins draw,
/// and load in three.js with the flat triangle count and a colour per instance.
#[test]
fn library_grammars_instance_validate_and_load_in_three_like_their_flat_twins() {
    let dir = tempdir();
    let (mut files, mut expected) = (Vec::new(), Vec::new());
    let mut instanced_grammars = 0;
    let mut differences = Vec::new();
    for (path, language) in library() {
        let name = path.file_name().and_then(|s| s.to_str()).expect("name").to_string();
        let src = std::fs::read(&path).expect("read");
        let r = RenderRequest { script_dir: path.parent().map(Path::to_path_buf), ..req(language, Format::Glb) };
        let (gpu, plain) = (ok(&src, &r), ok(&src, &flat(&r)));
        assert_eq!((gpu.primitives, gpu.triangles), (plain.primitives, plain.triangles), "{name}");
        differences.extend(drawing_differences(&name, &gpu.bytes, &plain.bytes));
        let Drawn { instances, coloured, .. } = drawn(&gpu.bytes);
        instanced_grammars += usize::from(instances > 0);
        // Icons share names with grammars (tree.mdg): number the files.
        let glb = dir.path().join(format!("{}-{name}.glb", expected.len()));
        std::fs::write(&glb, &gpu.bytes).expect("write");
        let gltf = dir.path().join(format!("{}-{name}.gltf", expected.len()));
        std::fs::write(&gltf, ok(&src, &RenderRequest { format: Format::Gltf, ..r }).bytes).expect("write");
        files.extend([glb, gltf]);
        expected.push((name, gpu.triangles, instances, coloured));
    }
    assert!(differences.is_empty(), "{}", differences.join("\n"));
    assert!(instanced_grammars >= 20, "only {instanced_grammars} grammars instance");
    for (file, (errors, warnings, report)) in files.iter().zip(validate_gltf(&files)) {
        assert_eq!((errors, warnings), (0, 0), "{}: {report}", file.display());
    }
    let glbs: Vec<PathBuf> = files.iter().step_by(2).cloned().collect();
    for (r, (name, triangles, instances, coloured)) in three_check(&glbs).iter().zip(&expected) {
        assert_eq!(r["ok"], true, "{name} does not load in three.js: {r}");
        assert_eq!(r["triangles"].as_u64(), Some(*triangles), "{name}: {r}");
        assert_eq!(r["instances"].as_u64(), Some(*instances), "{name}: {r}");
        // `_COLOR_0` (on meshes whose instances differ in colour) becomes three.js's `instanceColor`.
        assert_eq!(r["coloured"].as_u64(), Some(*coloured), "{name}: {r}");
    }
}

/// The nodes of an instanced glb: (name, instances or 0 when plain).
fn nodes(glb: &[u8]) -> Vec<(String, u64)> {
    let (j, _) = chunks(glb);
    let count = |ext: &Value| ext["TRANSLATION"].as_u64().map_or(0, |a| j["accessors"][a as usize]["count"].as_u64().expect("count"));
    j["nodes"]
        .as_array()
        .expect("nodes")
        .iter()
        .filter(|n| n["mesh"].is_u64())
        .map(|n| (n["name"].as_str().expect("name").to_string(), count(&n["extensions"]["EXT_mesh_gpu_instancing"]["attributes"])))
        .collect()
}

/// `grammars/mirror.mdg`: five pairs of arms of six joints (a sphere and a
/// cone), one arm of each pair mirrored with `fx`, around one gold bead.
/// Upright and mirrored meshes are apart, the mirrored ones reflected
/// through their origin with a positive scale, so winding is right for the
/// validator's reading of the extension and for three.js alike.
#[test]
fn mirrored_placements_get_their_own_reflected_mesh() {
    let src = std::fs::read(repo().join("grammars/mirror.mdg")).expect("grammar");
    let r = req(Language::Mdg, Format::Glb);
    let out = ok(&src, &r);
    assert_eq!(nodes(&out.bytes), [("sphere".to_string(), 31), ("sphere".to_string(), 30), ("cone".to_string(), 30), ("cone".to_string(), 30)]);
    let d = drawn(&out.bytes);
    assert_eq!((d.instances, d.negative_scales, d.inside_out), (121, 0, 0));
    assert!(d.volume > 0.0);
    assert_same_drawing("mirror.mdg", &out.bytes, &ok(&src, &flat(&r)).bytes);
    // Same request, same bytes.
    assert!(ok(&src, &r).bytes == out.bytes);
}

/// EisenScript: a uniform and a per-axis scale after the rotations share
/// the box mesh, mirrored boxes have their own, a sheared frame (a scale
/// between two rotations) and a sphere placed once stay plain and exact.
#[test]
fn eisenscript_frames_instance_when_they_have_a_trs_form() {
    let src = "box\n{ x 2 s 1 2 3 } box\n{ x 4 ry 40 s 0.5 } box\n{ x 6 fx } box\n{ x 8 fx s 1 1 2 } box\n\
               { x 10 rz 30 s 1 3 1 rz 30 } box\n{ x 12 rz 30 s 1 3 1 rz 45 } box\n{ x 14 } sphere\n";
    let r = req(Language::Eisenscript, Format::Glb);
    let out = ok(src.as_bytes(), &r);
    assert_eq!(out.primitives, 8);
    assert_eq!(nodes(&out.bytes), [("box".to_string(), 3), ("box".to_string(), 2), ("model".to_string(), 0)]);
    let (j, _) = chunks(&out.bytes);
    let plain = j["nodes"].as_array().expect("nodes").iter().find(|n| n["name"] == "model").expect("the plain mesh");
    let prim = &j["meshes"][plain["mesh"].as_u64().expect("mesh") as usize]["primitives"][0];
    // Two sheared boxes (12 triangles each) and the sphere (224 at detail 16).
    assert_eq!(j["accessors"][prim["indices"].as_u64().expect("indices") as usize]["count"], 3 * (2 * 12 + 224));
    assert_same_drawing("frames", &out.bytes, &ok(src.as_bytes(), &flat(&r)).bytes);
    assert_eq!(drawn(&out.bytes).inside_out, 0);
}

/// The triangle limit charges what instanced glb materialises: a mesh's
/// triangles once, then one per further placement. 10 000 spheres (224
/// triangles each at detail 16) are 2.24 M triangles flat, over the
/// default 2 M, and 224 + 9 999 instanced.
#[test]
fn instanced_glb_is_charged_what_it_makes_and_renders_past_the_flat_limit() {
    let src = b"startshape Field\nrule Field { 100 * { x 1 } 100 * { y 1 } SPHERE {} }\n";
    let r = req(Language::Mdg, Format::Glb);
    let limit = |r: &RenderRequest| match render(src, r) {
        Err(RenderError::Limit(l)) => Some((l.limit, l.reached)),
        Err(e) => panic!("{e}"),
        Ok(_) => None,
    };
    // 8 928 spheres fit in 2 M triangles; the next one is refused.
    assert_eq!(limit(&flat(&r)), Some((Limit::Triangles, 8_929 * 224)));
    let out = ok(src, &r);
    assert_eq!((out.primitives, out.triangles), (10_000, 2_240_000));
    assert_eq!(nodes(&out.bytes), [("sphere".to_string(), 10_000)]);
    // 52 bytes per instance (TRS and colour) plus one sphere: a 10th of the flat file.
    assert!(out.bytes.len() < 600_000, "{}", out.bytes.len());
    let at = |max_triangles| RenderRequest { limits: Limits { max_triangles, ..Limits::default() }, ..r.clone() };
    assert_eq!(limit(&at(224 + 9_999)), None);
    assert_eq!(limit(&at(224 + 9_998)), Some((Limit::Triangles, 224 + 9_999)));
    // Flat output, and formats that tessellate every placement, still count every triangle.
    assert_eq!(limit(&flat(&at(224 + 9_999))).map(|l| l.0), Some(Limit::Triangles));
    assert_eq!(limit(&RenderRequest { format: Format::Stl, ..at(224 + 9_999) }).map(|l| l.0), Some(Limit::Triangles));
}

/// Each instance's `_COLOR_0` is its flat copy's vertex colour: gradient.mdg's
/// hundred tiles, each its own colour, as RGBA8 → float and back.
#[test]
fn instance_colours_are_the_flat_vertex_colours() {
    let src = std::fs::read(repo().join("grammars/gradient.mdg")).expect("grammar");
    let r = req(Language::Mdg, Format::Glb);
    let (glb, plain) = (ok(&src, &r).bytes, ok(&src, &flat(&r)).bytes);
    let (j, bin) = chunks(&glb);
    let node = j["nodes"].as_array().expect("nodes").iter().find(|n| n["name"] == "box").expect("the box node");
    let rgb = |v: &[f64]| [v[0], v[1], v[2]].map(|c| (c * 255.0).round() as u8);
    let mut instanced: Vec<[u8; 3]> = read(&j, bin, &node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["_COLOR_0"]).chunks_exact(3).map(rgb).collect();
    let (j, bin) = chunks(&plain);
    let colours = read_u8(&j, bin, &j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"]);
    // 24 vertices per box, in scene order as the instances are.
    let mut flat: Vec<[u8; 3]> = colours.chunks_exact(4 * 24).map(|v| [v[0], v[1], v[2]]).collect();
    assert_eq!(instanced.len(), 100);
    assert_eq!(instanced, flat);
    instanced.dedup();
    flat.dedup();
    assert_eq!(instanced.len(), 100, "every tile has its own colour");
}

/// Accessor `i`'s bytes (unsigned byte components, tightly packed).
fn read_u8(j: &Value, bin: &[u8], i: &Value) -> Vec<u8> {
    let a = &j["accessors"][i.as_u64().expect("accessor index") as usize];
    assert_eq!(a["componentType"], 5121);
    let view = &j["bufferViews"][a["bufferView"].as_u64().expect("view") as usize];
    let at = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    bin[at..at + 4 * a["count"].as_u64().expect("count") as usize].to_vec()
}

/// Attributes that do not vary between a mesh's instances are left out
/// (the extension's identity) and one shared colour goes into the mesh: a
/// grid of one-colour boxes carries TRANSLATION alone, 12 bytes per box,
/// and draws and colours what its flat twin does.
#[test]
fn instances_that_only_move_carry_translation_alone() {
    let src = b"startshape A\nrule A { 10 * {x 2} Row {} }\nrule Row { 10 * {y 2} BOX { G 1 } }\n";
    let r = req(Language::Mdg, Format::Glb);
    let (gpu, plain) = (ok(src, &r), ok(src, &flat(&r)));
    let (j, bin) = chunks(&gpu.bytes);
    let node = j["nodes"].as_array().expect("nodes").iter().find(|n| n["name"] == "box").expect("the box node");
    let attributes = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"].as_object().expect("instanced");
    assert_eq!(attributes.keys().collect::<Vec<_>>(), ["TRANSLATION"]);
    assert_eq!(j["accessors"][attributes["TRANSLATION"].as_u64().expect("accessor") as usize]["count"], 100);
    let d = drawn(&gpu.bytes);
    assert_eq!((d.instances, d.coloured, d.triangles), (100, 0, 1200));
    assert_same_drawing("grid", &gpu.bytes, &plain.bytes);
    // The shared colour is in the prototype's vertex colours, as in every flat box.
    let mesh = node["mesh"].as_u64().expect("mesh") as usize;
    let colours = read_u8(&j, bin, &j["meshes"][mesh]["primitives"][0]["attributes"]["COLOR_0"]);
    let (pj, pbin) = chunks(&plain.bytes);
    let flat_colours = read_u8(&pj, pbin, &pj["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"]);
    assert_eq!(colours.chunks_exact(4).collect::<std::collections::BTreeSet<_>>(), flat_colours.chunks_exact(4).collect());
    assert_eq!(colours.chunks_exact(4).collect::<std::collections::BTreeSet<_>>().len(), 1);
    assert_eq!(&colours[..4], [0, 255, 0, 255], "green");
    // Rotated copies keep ROTATION.
    let turned = b"startshape A\nrule A { 10 * {rz 30} BOX {} }\n";
    let (j, _) = chunks(&ok(turned, &r).bytes);
    let node = j["nodes"].as_array().expect("nodes").iter().find(|n| n["name"] == "box").expect("the box node");
    let keys: Vec<String> = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"].as_object().expect("instanced").keys().cloned().collect();
    assert_eq!(keys, ["ROTATION", "TRANSLATION"]);
}
