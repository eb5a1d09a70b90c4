//! Winding agrees with normals (issue 16), for every grammar in `grammars/`
//! and every mesh output that carries normals: the plain, welded, quantised,
//! per-kind and low-detail GLB (and, for L-systems, the GPU-instanced and
//! the flat GLB), the strips format (read by the crate's decoder) and STL's
//! facet normals. Each triangle's normal by winding (counter-clockwise is
//! front, or clockwise under a node whose transform mirrors, as glTF says)
//! must point the same way as the mean of its vertex normals, both in world
//! space: an engine that culls back faces then shows every triangle.
//!
//! Tolerance: only triangles of (numerically) no area are skipped, those
//! whose cross product is below 10⁻⁶ of their longest edge squared (a sliver
//! a millionth as high as it is long, where the winding says nothing). The
//! meshopt variant is not read here: it is the quantised mesh, compressed.

use crate::common::{grammar_files, repo};
use glam::{DMat4, DQuat, DVec3};
use rulemesh::export::{Format, Instancing};
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderRequest};
use serde_json::Value;

/// One triangle in world space: corners and vertex normals (unit or zero).
type Tri = ([DVec3; 3], [DVec3; 3]);

/// The triangles whose winding disagrees with their vertex normals.
fn disagreeing(tris: &[Tri]) -> usize {
    tris.iter()
        .filter(|([a, b, c], n)| {
            let g = (*b - *a).cross(*c - *a);
            let longest = (*b - *a).length().max((*c - *a).length()).max((*c - *b).length());
            if g.length() <= 1e-6 * longest * longest {
                return false;
            }
            g.dot(n[0] + n[1] + n[2]) <= 0.0
        })
        .count()
}

/// The bytes of accessor `i`'s elements as f64 components (normalised integers scaled to [−1, 1] or [0, 1]).
fn accessor(json: &Value, bin: &[u8], i: u64) -> Vec<Vec<f64>> {
    let a = &json["accessors"][i as usize];
    let view = &json["bufferViews"][a["bufferView"].as_u64().expect("buffer view") as usize];
    let comps = match a["type"].as_str().expect("type") {
        "SCALAR" => 1,
        "VEC2" => 2,
        "VEC3" => 3,
        "VEC4" => 4,
        "MAT4" => 16,
        t => panic!("accessor type {t}"),
    };
    let ct = a["componentType"].as_u64().expect("component type");
    let size = match ct {
        5120 | 5121 => 1,
        5122 | 5123 => 2,
        5125 | 5126 => 4,
        _ => panic!("component type {ct}"),
    };
    let normalised = a["normalized"].as_bool().unwrap_or(false);
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
    let stride = view["byteStride"].as_u64().map_or(comps * size, |s| s as usize);
    let count = a["count"].as_u64().expect("count") as usize;
    (0..count)
        .map(|e| {
            (0..comps)
                .map(|k| {
                    let o = start + e * stride + k * size;
                    let b = &bin[o..o + size];
                    match (ct, normalised) {
                        (5126, _) => f64::from(f32::from_le_bytes(b.try_into().expect("4 bytes"))),
                        (5125, _) => f64::from(u32::from_le_bytes(b.try_into().expect("4 bytes"))),
                        (5123, false) => f64::from(u16::from_le_bytes(b.try_into().expect("2 bytes"))),
                        (5123, true) => f64::from(u16::from_le_bytes(b.try_into().expect("2 bytes"))) / 65535.0,
                        (5122, false) => f64::from(i16::from_le_bytes(b.try_into().expect("2 bytes"))),
                        (5122, true) => (f64::from(i16::from_le_bytes(b.try_into().expect("2 bytes"))) / 32767.0).max(-1.0),
                        (5121, false) => f64::from(b[0]),
                        (5121, true) => f64::from(b[0]) / 255.0,
                        (5120, false) => f64::from(b[0] as i8),
                        (_, _) => (f64::from(b[0] as i8) / 127.0).max(-1.0),
                    }
                })
                .collect()
        })
        .collect()
}

fn vec3(v: &[f64]) -> DVec3 {
    DVec3::new(v[0], v[1], v[2])
}

/// A node's local transform (matrix, or translation · rotation · scale).
fn local(node: &Value) -> DMat4 {
    let nums = |k: &str| node[k].as_array().map(|a| a.iter().map(|x| x.as_f64().expect("number")).collect::<Vec<f64>>());
    if let Some(m) = nums("matrix") {
        return DMat4::from_cols_slice(&m);
    }
    let t = nums("translation").map_or(DVec3::ZERO, |v| vec3(&v));
    let r = nums("rotation").map_or(DQuat::IDENTITY, |v| DQuat::from_xyzw(v[0], v[1], v[2], v[3]));
    let s = nums("scale").map_or(DVec3::ONE, |v| vec3(&v));
    DMat4::from_scale_rotation_translation(s, r, t)
}

/// Every triangle of a GLB's default scene, in world space, with its
/// corners swapped under a mirroring transform (so the test's winding is
/// the front face glTF defines).
fn glb_triangles(bytes: &[u8]) -> Vec<Tri> {
    let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().expect("4 bytes")) as usize;
    assert_eq!(&bytes[0..4], b"glTF");
    let json_len = u32_at(12);
    let json: Value = serde_json::from_slice(&bytes[20..20 + json_len]).expect("GLB JSON");
    let bin = if bytes.len() > 20 + json_len { &bytes[28 + json_len..28 + json_len + u32_at(20 + json_len)] } else { &[][..] };
    let mut out = Vec::new();
    let mut stack: Vec<(u64, DMat4)> =
        json["scenes"][json["scene"].as_u64().unwrap_or(0) as usize]["nodes"].as_array().expect("scene nodes").iter().map(|n| (n.as_u64().expect("node"), DMat4::IDENTITY)).collect();
    while let Some((n, parent)) = stack.pop() {
        let node = &json["nodes"][n as usize];
        let world = parent * local(node);
        for c in node["children"].as_array().into_iter().flatten() {
            stack.push((c.as_u64().expect("child"), world));
        }
        let Some(mesh) = node["mesh"].as_u64() else { continue };
        let inst = &node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
        let instances: Vec<DMat4> = if inst.is_object() {
            let get = |k: &str| inst[k].as_u64().map(|i| accessor(&json, bin, i));
            let (t, r, s) = (get("TRANSLATION"), get("ROTATION"), get("SCALE"));
            let count = [&t, &r, &s].iter().find_map(|a| a.as_ref().map(Vec::len)).unwrap_or(0);
            (0..count)
                .map(|i| {
                    let tr = t.as_ref().map_or(DVec3::ZERO, |a| vec3(&a[i]));
                    let ro = r.as_ref().map_or(DQuat::IDENTITY, |a| DQuat::from_xyzw(a[i][0], a[i][1], a[i][2], a[i][3]).normalize());
                    let sc = s.as_ref().map_or(DVec3::ONE, |a| vec3(&a[i]));
                    world * DMat4::from_scale_rotation_translation(sc, ro, tr)
                })
                .collect()
        } else {
            vec![world]
        };
        for prim in json["meshes"][mesh as usize]["primitives"].as_array().expect("primitives") {
            assert_eq!(prim["mode"].as_u64().unwrap_or(4), 4, "triangles");
            let attr = &prim["attributes"];
            let pos = accessor(&json, bin, attr["POSITION"].as_u64().expect("POSITION"));
            let Some(ni) = attr["NORMAL"].as_u64() else { panic!("a mesh without normals") };
            let nrm = accessor(&json, bin, ni);
            let idx: Vec<usize> = match prim["indices"].as_u64() {
                Some(i) => accessor(&json, bin, i).iter().map(|v| v[0] as usize).collect(),
                None => (0..pos.len()).collect(),
            };
            for m in &instances {
                let normal_m = glam::DMat3::from_mat4(*m).inverse().transpose();
                let mirrored = glam::DMat3::from_mat4(*m).determinant() < 0.0;
                for t in idx.chunks_exact(3) {
                    let t = [t[0], t[1], t[2]];
                    let p = t.map(|i| m.transform_point3(vec3(&pos[i])));
                    let q = t.map(|i| (normal_m * vec3(&nrm[i])).normalize_or_zero());
                    out.push(if mirrored { ([p[0], p[2], p[1]], [q[0], q[2], q[1]]) } else { (p, q) });
                }
            }
        }
    }
    out
}

/// The triangles of a strips file, by the crate's own decoder.
fn strips_triangles(bytes: &[u8]) -> Vec<Tri> {
    let d = rulemesh::decode::strips::decode_strips_full(bytes).expect("strips decode");
    let m = &d.mesh;
    let p = |i: u32| DVec3::from_array(m.positions[i as usize].map(f64::from));
    let n = |i: u32| DVec3::from_array(m.normals[i as usize].map(f64::from));
    m.indices.chunks_exact(3).map(|t| ([p(t[0]), p(t[1]), p(t[2])], [n(t[0]), n(t[1]), n(t[2])])).collect()
}

/// The facets of a binary STL, each corner carrying the facet's normal.
fn stl_triangles(bytes: &[u8]) -> Vec<Tri> {
    let count = u32::from_le_bytes(bytes[80..84].try_into().expect("4 bytes")) as usize;
    (0..count)
        .map(|i| {
            let f = &bytes[84 + 50 * i..84 + 50 * i + 48];
            let v = |k: usize| DVec3::from_array([0, 1, 2].map(|j| f64::from(f32::from_le_bytes(f[(k * 3 + j) * 4..(k * 3 + j) * 4 + 4].try_into().expect("4 bytes")))));
            let n = v(0);
            ([v(1), v(2), v(3)], [n; 3])
        })
        .collect()
}

/// The variants checked for a language: name, request, decoder.
fn variants(language: Language) -> Vec<(&'static str, RenderRequest, fn(&[u8]) -> Vec<Tri>)> {
    let base = RenderRequest { language: Some(language), ..RenderRequest::default() };
    let with = |format: Format, f: &dyn Fn(&mut RenderRequest)| {
        let mut r = RenderRequest { format, ..base.clone() };
        f(&mut r);
        r
    };
    let glb = glb_triangles as fn(&[u8]) -> Vec<Tri>;
    let mut v = vec![
        ("glb", with(Format::Glb, &|_| {}), glb),
        ("glb-weld", with(Format::Glb, &|r| r.export_options.gltf.weld = true), glb),
        ("glb-quantize", with(Format::Glb, &|r| r.export_options.gltf.quantize = true), glb),
        ("glb-per-kind", with(Format::Glb, &|r| r.layout = rulemesh::mesh::MeshLayout::PerKind), glb),
        ("glb-detail-4", with(Format::Glb, &|r| r.detail = 4), glb),
        ("strips", with(Format::Strips, &|_| {}), strips_triangles as fn(&[u8]) -> Vec<Tri>),
        ("stl", with(Format::Stl, &|_| {}), stl_triangles as fn(&[u8]) -> Vec<Tri>),
    ];
    if language == Language::Lsystem {
        v.push(("glb-flat", with(Format::Glb, &|r| r.export_options.instancing = Instancing::Flat), glb));
    }
    v
}

#[test]
fn winding_agrees_with_normals_in_every_grammar_and_format() {
    let mut files = grammar_files("mdg");
    files.extend(grammar_files("ls"));
    assert!(files.len() >= 30, "only {} grammars", files.len());
    let mut bad = Vec::new();
    let mut checked = 0usize;
    for g in &files {
        let language = if g.extension().is_some_and(|e| e == "ls") { Language::Lsystem } else { Language::Mdg };
        let source = std::fs::read(g).expect("read grammar");
        for (name, mut req, decode) in variants(language) {
            req.script_dir = Some(repo().join("grammars"));
            let out = render(&source, &req).unwrap_or_else(|e| panic!("{} {name}: {e}", g.display()));
            let tris = decode(&out.bytes);
            assert!(!tris.is_empty(), "{} {name}: no triangles", g.display());
            checked += tris.len();
            let n = disagreeing(&tris);
            if n > 0 {
                bad.push(format!("{} {name}: {n} of {} triangles", g.file_name().and_then(|s| s.to_str()).unwrap_or("?"), tris.len()));
            }
        }
    }
    assert!(checked > 1_000_000, "only {checked} triangles checked");
    assert!(bad.is_empty(), "winding disagrees with normals in {} renders:\n{}", bad.len(), bad.join("\n"));
}

#[test]
fn the_check_catches_a_flipped_triangle() {
    let up = [DVec3::Z; 3];
    let ccw = [DVec3::ZERO, DVec3::X, DVec3::Y];
    let cw = [DVec3::ZERO, DVec3::Y, DVec3::X];
    assert_eq!(disagreeing(&[(ccw, up), (cw, up), ([DVec3::ZERO, DVec3::X, DVec3::X * 2.0], up)]), 1);
}
