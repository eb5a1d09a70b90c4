//! Tests only: gltf-json as the oracle of `json_out`. [`to_gltf`] builds
//! the same document as gltf-json's typed `Root`, the way the writers
//! built it before rulemesh had its own tree (names as `String`s, bounds as
//! `Value` arrays of `f64`, extensions as maps made with `to_value`, scene
//! extras as a `BTreeMap` made raw), and the tests hold
//! `Root::to_vec`'s bytes equal to `root_json`'s, on a document with every
//! field and variant the tree has and on documents the builder makes.

use super::document::{plain, Doc};
use super::json_out::root_json;
use super::tree::{push, Accessor, Animation, Bounds, Buffer, Camera, Channel, Component, Instancing, Kind, Material, Mesh, MeshoptView, Node, Path, Root, Sampler, Target, View, EXT_INSTANCING, EXT_MESHOPT, KHR_QUANT};
use crate::export::ExportMeta;
use gltf_json as json;
use json::validation::{Checked::Valid, USize64};
use json::Index;
use serde_json::Value;
use std::collections::BTreeMap;

/// `root` as gltf-json's tree.
fn to_gltf(root: &Root<'_>) -> json::Root {
    let mut g = json::Root {
        asset: json::Asset {
            copyright: None,
            extensions: None,
            extras: root.provenance.clone(),
            generator: Some(format!("rulemesh {}", crate::ENGINE_VERSION)),
            min_version: None,
            version: "2.0".to_string(),
        },
        ..Default::default()
    };
    g.accessors = root.accessors.iter().map(accessor).collect();
    g.animations = root.animations.iter().map(animation).collect();
    g.buffers = root.buffers.iter().map(buffer).collect();
    g.buffer_views = root.views.iter().map(view).collect();
    g.scene = root.scene.map(Index::new);
    g.extensions_used = root.extensions.iter().map(|e| e.to_string()).collect();
    g.extensions_required = g.extensions_used.clone();
    g.cameras = root.cameras.iter().map(camera).collect();
    g.materials = root.materials.iter().map(material).collect();
    g.meshes = root.meshes.iter().map(mesh).collect();
    g.nodes = root.nodes.iter().map(node).collect();
    g.scenes = root.scenes.iter().map(scene).collect();
    g
}

/// An extension map of one object, as the writers made them.
fn extension(name: &str, value: Value) -> serde_json::Map<String, Value> {
    let mut map = serde_json::Map::new();
    map.insert(name.to_string(), value);
    map
}

/// Floats as a `Value` array of their `f64`s.
fn f64s(v: &[f32]) -> Value {
    Value::Array(v.iter().map(|&c| Value::from(f64::from(c))).collect())
}

/// An accessor, its bounds as the `Value` arrays the writers made.
fn accessor(a: &Accessor) -> json::Accessor {
    use json::accessor::{ComponentType, GenericComponentType, Type};
    let component = match a.component {
        Component::I8 => ComponentType::I8,
        Component::U8 => ComponentType::U8,
        Component::U16 => ComponentType::U16,
        Component::U32 => ComponentType::U32,
        Component::F32 => ComponentType::F32,
    };
    let kind = match a.kind {
        Kind::Scalar => Type::Scalar,
        Kind::Vec3 => Type::Vec3,
        Kind::Vec4 => Type::Vec4,
    };
    let (min, max) = match a.bounds {
        Some(Bounds::Float(lo, hi)) => (Some(f64s(&lo)), Some(f64s(&hi))),
        Some(Bounds::Grid(lo, hi)) => {
            let v = |x: [u16; 3]| Value::Array(x.iter().map(|&c| Value::from(c)).collect());
            (Some(v(lo)), Some(v(hi)))
        }
        Some(Bounds::Times(end)) => (Some(Value::Array(vec![Value::from(0.0)])), Some(Value::Array(vec![Value::from(f64::from(end))]))),
        None => (None, None),
    };
    json::Accessor {
        buffer_view: Some(Index::new(a.view)),
        byte_offset: a.byte_offset.map(USize64),
        count: USize64(a.count),
        component_type: Valid(GenericComponentType(component)),
        extensions: None,
        extras: None,
        type_: Valid(kind),
        min,
        max,
        name: None,
        normalized: a.normalized,
        sparse: None,
    }
}

/// The `"rulemesh"` animation.
fn animation(a: &Animation) -> json::Animation {
    use json::animation::{Interpolation, Property};
    let channels = a
        .channels
        .iter()
        .map(|c| {
            let path = match c.path {
                Path::Translation => Property::Translation,
                Path::Rotation => Property::Rotation,
                Path::Scale => Property::Scale,
            };
            json::animation::Channel {
                sampler: Index::new(c.sampler),
                target: json::animation::Target { node: Index::new(c.node), path: Valid(path), extensions: None, extras: None },
                extensions: None,
                extras: None,
            }
        })
        .collect();
    let samplers = a
        .samplers
        .iter()
        .map(|s| json::animation::Sampler {
            input: Index::new(s.input),
            interpolation: Valid(if s.step { Interpolation::Step } else { Interpolation::Linear }),
            output: Index::new(s.output),
            extensions: None,
            extras: None,
        })
        .collect();
    json::Animation { name: Some("rulemesh".to_string()), channels, samplers, extensions: None, extras: None }
}

/// A buffer, the meshopt fallback flag as its extension map.
fn buffer(b: &Buffer) -> json::Buffer {
    let extensions = b.meshopt_fallback.then(|| json::extensions::buffer::Buffer { others: extension(EXT_MESHOPT, serde_json::json!({ "fallback": true })) });
    json::Buffer { byte_length: USize64(b.byte_length), name: None, uri: b.uri.clone(), extensions, extras: None }
}

/// A buffer view, the meshopt extension as a map (`to_value` of a struct sorted its keys so).
fn view(v: &View) -> json::buffer::View {
    use json::buffer::Target as T;
    let extensions = v.meshopt.map(|m| {
        let value = serde_json::json!({
            "buffer": m.buffer, "byteOffset": m.byte_offset, "byteLength": m.byte_length,
            "byteStride": m.byte_stride, "count": m.count, "mode": m.mode,
        });
        json::extensions::buffer::View { others: extension(EXT_MESHOPT, value) }
    });
    json::buffer::View {
        buffer: Index::new(v.buffer),
        byte_length: USize64(v.byte_length),
        byte_offset: Some(USize64(v.byte_offset)),
        byte_stride: v.byte_stride.map(|s| json::buffer::Stride(s as usize)),
        name: v.name.map(str::to_string),
        target: v.target.map(|t| Valid(if t == Target::Vertices { T::ArrayBuffer } else { T::ElementArrayBuffer })),
        extensions,
        extras: None,
    }
}

/// A perspective camera.
fn camera(c: &Camera<'_>) -> json::Camera {
    json::Camera {
        name: c.name.map(str::to_string),
        orthographic: None,
        perspective: Some(json::camera::Perspective { aspect_ratio: None, yfov: c.yfov, zfar: c.zfar, znear: c.znear, extensions: None, extras: None }),
        type_: Valid(json::camera::Type::Perspective),
        extensions: None,
        extras: None,
    }
}

/// The one material, as the builder made it.
fn material(m: &Material<'_>) -> json::Material {
    json::Material {
        name: m.name.map(str::to_string),
        pbr_metallic_roughness: json::material::PbrMetallicRoughness {
            base_color_factor: json::material::PbrBaseColorFactor([1.0, 1.0, 1.0, 1.0]),
            metallic_factor: json::material::StrengthFactor(0.0),
            roughness_factor: json::material::StrengthFactor(0.8),
            ..Default::default()
        },
        double_sided: false,
        ..Default::default()
    }
}

/// A mesh of one primitive, its attributes in a `BTreeMap`.
fn mesh(m: &Mesh<'_>) -> json::Mesh {
    let mut attributes = BTreeMap::new();
    attributes.insert(Valid(json::mesh::Semantic::Positions), Index::new(m.position));
    attributes.insert(Valid(json::mesh::Semantic::Normals), Index::new(m.normal));
    attributes.insert(Valid(json::mesh::Semantic::Colors(0)), Index::new(m.colour));
    let primitive = json::mesh::Primitive {
        attributes,
        extensions: None,
        extras: None,
        indices: Some(Index::new(m.indices)),
        material: Some(Index::new(m.material)),
        mode: Valid(json::mesh::Mode::Triangles),
        targets: None,
    };
    json::Mesh { extensions: None, extras: None, name: Some(m.name.to_string()), primitives: vec![primitive], weights: None }
}

/// A node, the instancing extension as a map.
fn node(n: &Node<'_>) -> json::Node {
    let extensions = n.instancing.map(|i: Instancing| {
        let mut attributes = serde_json::Map::new();
        attributes.insert("TRANSLATION".to_string(), Value::from(i.translation));
        for (name, a) in [("ROTATION", i.rotation), ("SCALE", i.scale), ("_COLOR_0", i.colour)] {
            if let Some(a) = a {
                attributes.insert(name.to_string(), Value::from(a));
            }
        }
        json::extensions::scene::Node { others: extension(EXT_INSTANCING, serde_json::json!({ "attributes": attributes })) }
    });
    json::Node {
        camera: n.camera.map(Index::new),
        children: (!n.children.is_empty()).then(|| n.children.iter().map(|&c| Index::new(c)).collect()),
        extensions,
        mesh: n.mesh.map(Index::new),
        name: Some(n.name.to_string()),
        rotation: n.rotation.map(json::scene::UnitQuaternion),
        scale: n.scale,
        translation: n.translation,
        ..Default::default()
    }
}

/// The scene, its extras a `BTreeMap` made raw, as the builder made them.
fn scene(s: &super::tree::Scene) -> json::Scene {
    let mut map = BTreeMap::new();
    if let Some(bg) = s.background {
        map.insert("background", f64s(&bg));
    }
    if s.truncated {
        map.insert("truncated", Value::Bool(true));
    }
    let extras = (!map.is_empty()).then(|| serde_json::value::to_raw_value(&map).expect("extras"));
    json::Scene { extensions: None, extras, name: None, nodes: s.nodes.iter().map(|&n| Index::new(n)).collect() }
}

/// Asserts `root_json` gives gltf-json's bytes for `root`.
fn assert_same(root: &Root<'_>) {
    let ours = String::from_utf8(root_json(root).expect("ours")).expect("utf-8");
    let theirs = String::from_utf8(to_gltf(root).to_vec().expect("gltf-json")).expect("utf-8");
    assert_eq!(ours, theirs);
}

/// A document with every field and variant of the tree: names that need
/// escaping, every component, kind and bounds, odd floats, both
/// extensions, cameras, a stepped animation, named materials.
fn mixed() -> Root<'static> {
    let mut r = Root::default();
    push(&mut r.buffers, Buffer { byte_length: 4096, uri: Some("data:application/octet-stream;base64,QUJD".to_string()), meshopt_fallback: false });
    push(&mut r.buffers, Buffer { byte_length: 8192, uri: None, meshopt_fallback: true });
    let meshopt = MeshoptView { buffer: 0, byte_offset: 16, byte_length: 100, byte_stride: 12, count: 9, mode: "ATTRIBUTES" };
    for (k, target) in [None, Some(Target::Vertices), Some(Target::Indices), Some(Target::Vertices)].into_iter().enumerate() {
        let name = (k == 3).then_some("animation");
        push(&mut r.views, View { buffer: (k % 2) as u32, byte_length: 12 * k as u64 + 1, byte_offset: 8 * k as u64, byte_stride: (k == 2).then_some(12), name, target, meshopt: (k == 1).then_some(meshopt) });
    }
    let kinds = [(Component::F32, Kind::Vec3), (Component::U8, Kind::Vec4), (Component::U16, Kind::Scalar), (Component::U32, Kind::Scalar), (Component::I8, Kind::Vec3), (Component::F32, Kind::Scalar)];
    let bounds = [
        Some(Bounds::Float([-0.5, 1e-7, -0.0], [0.1, 123456.79, 3e30])),
        None,
        Some(Bounds::Grid([0, 7, 65535], [65535, 33897, 1])),
        None,
        None,
        Some(Bounds::Times(2.0416667)),
    ];
    for (k, ((component, kind), bounds)) in kinds.into_iter().zip(bounds).enumerate() {
        push(&mut r.accessors, Accessor { view: k as u32 % 4, byte_offset: (k % 2 == 0).then_some(4 * k as u64), count: 1000 + k as u64, component, kind, bounds, normalized: k == 1 });
    }
    push(&mut r.cameras, Camera { name: Some("cam \"era\""), yfov: 0.6981317, zfar: Some(1000.0), znear: 0.1 });
    push(&mut r.cameras, Camera { name: None, yfov: 1.0, zfar: None, znear: 0.01 });
    push(&mut r.materials, Material { name: None });
    push(&mut r.materials, Material { name: Some("box::glass\t\u{1}") });
    for (k, name) in ["plain", "quo\"ted", "tab\there", "ünï \\"].into_iter().enumerate() {
        let m = push(&mut r.meshes, Mesh { name, position: 0, normal: 1, colour: 2, indices: 3, material: (k % 2) as u32 });
        let instancing = match k {
            1 => Some(Instancing { translation: 5, rotation: None, scale: None, colour: None }),
            2 => Some(Instancing { translation: 5, rotation: Some(6), scale: Some(7), colour: Some(8) }),
            _ => None,
        };
        push(
            &mut r.nodes,
            Node {
                camera: (k == 2).then_some(0),
                children: if k == 1 { vec![0, 2] } else { Vec::new() },
                instancing,
                mesh: Some(m),
                name,
                rotation: (k == 3).then_some([-0.0, 0.70710677, 0.0, 0.70710677]),
                scale: (k == 2).then_some([0.1; 3]),
                translation: (k % 2 == 0).then_some([1.5, f32::NAN, 1e-9]),
            },
        );
    }
    let channels = vec![Channel { sampler: 0, node: 1, path: Path::Translation }, Channel { sampler: 1, node: 1, path: Path::Rotation }, Channel { sampler: 2, node: 3, path: Path::Scale }];
    let samplers = (0..3).map(|k| Sampler { input: 5, step: k == 1, output: 4 }).collect();
    r.animations.push(Animation { channels, samplers });
    r.animations.push(Animation { channels: Vec::new(), samplers: Vec::new() });
    push(&mut r.scenes, super::tree::Scene { background: Some([0.1, 0.1, 0.15, 1.0]), truncated: true, nodes: vec![0] });
    push(&mut r.scenes, super::tree::Scene { background: None, truncated: true, nodes: Vec::new() });
    push(&mut r.scenes, super::tree::Scene { background: Some([0.0; 4]), truncated: false, nodes: vec![1, 2] });
    r.scene = Some(0);
    r.extensions = vec![EXT_MESHOPT, KHR_QUANT, EXT_INSTANCING];
    r.provenance = Some(serde_json::value::RawValue::from_string("{\"engine\":\"x\",\"params\":{\"a\":0.5}}".to_string()).expect("raw"));
    r
}

/// Every field and variant, the empty tree and the empty document.
#[test]
fn the_bytes_are_gltf_jsons() {
    assert_same(&mixed());
    assert_same(&Root::default());
    assert_same(&Doc::new().finish(&ExportMeta::default()).expect("empty"));
}

/// Documents the plain builder makes, with and without extras, camera,
/// named materials, a URI and an instanced node.
#[test]
fn built_documents_are_gltf_jsons() {
    use super::buffer::{place, Tracks};
    use crate::export::gltf::tests::{all_nine, meshes_of};
    use crate::mesh::MeshLayout;
    let meshes = meshes_of(&all_nine(), 8, MeshLayout::PerKind);
    let (placed, len) = place(&meshes).expect("placed");
    let camera = crate::model::Camera { name: Some("view".to_string()), yfov: 0.8, znear: 0.1, zfar: None, placements: Vec::new(), timeline: None };
    for (k, meta) in [
        ExportMeta::default(),
        ExportMeta { background: Some([0.25, 0.5, 1.0, 1.0]), truncated: true, material_per_mesh: true, camera: Some(camera), ..ExportMeta::default() },
    ]
    .iter()
    .enumerate()
    {
        let (mut doc, nodes, _) = plain(&placed, len, &Tracks::default(), meta, (k == 1).then(|| "data:x".to_string()), 0);
        doc.instance(nodes[1], Instancing { translation: 0, rotation: Some(1), scale: None, colour: Some(2) }).expect("node");
        assert_same(&doc.finish(meta).expect("finished"));
    }
}
