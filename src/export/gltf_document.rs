//! The JSON document of the plain glTF writers: the asset, the root node,
//! the one buffer, a material (shared, or one per mesh), and per placed mesh
//! its buffer views, accessors (with POSITION bounds), mesh and node, hung
//! under its bone when there is a node graph; then the static camera and the
//! scene with its `extras`. The binary side is `gltf_buffer`, the bones and
//! animation `gltf_graph`; this module only describes what they lay out.

use super::gltf_buffer::{accessor, view, Placement, Tracks};
use super::gltf_graph::add_graph;
use super::{ExportError, ExportMeta};
use gltf_json as json;
use json::validation::{Checked::Valid, USize64};
use std::collections::BTreeMap;

fn vec3_value(v: [f32; 3]) -> json::Value {
    json::Value::Array(v.iter().map(|&c| json::Value::from(f64::from(c))).collect())
}

/// The scene's `extras`: background colour and truncation, when present.
fn scene_extras(meta: &ExportMeta) -> Result<json::Extras, ExportError> {
    let mut map = BTreeMap::new();
    if let Some(bg) = meta.background {
        map.insert("background", json::Value::Array(bg.iter().map(|&c| json::Value::from(f64::from(c))).collect()));
    }
    if meta.truncated {
        map.insert("truncated", json::Value::Bool(true));
    }
    if map.is_empty() {
        return Ok(None);
    }
    Ok(Some(json::extras::RawValue::from_string(serde_json::to_string(&map)?)?))
}

/// Builds the glTF JSON. `uri` is the buffer's URI (None for GLB).
pub(super) fn document(placed: &[Placement<'_>], buffer_len: u64, tracks: &Tracks, meta: &ExportMeta, uri: Option<String>) -> Result<Vec<u8>, ExportError> {
    use json::accessor::{ComponentType, Type};
    use json::buffer::Target;
    let mut root = json::Root {
        asset: json::Asset {
            copyright: None,
            extensions: None,
            extras: None,
            generator: Some(format!("rulemesh {}", crate::ENGINE_VERSION)),
            min_version: None,
            version: "2.0".to_string(),
        },
        ..Default::default()
    };
    let root_node = root.push(json::Node { name: Some("rulemesh".to_string()), ..Default::default() });
    let buffer = (buffer_len > 0).then(|| root.push(json::Buffer { byte_length: USize64(buffer_len), name: None, uri, extensions: None, extras: None }));
    let (graph_nodes, mut children) = match &meta.graph {
        Some(g) => add_graph(&mut root, g, tracks, buffer),
        None => (Vec::new(), Vec::new()),
    };
    if let (false, Some(buffer)) = (placed.is_empty(), buffer) {
        let material = |name: Option<String>| json::Material {
            name,
            pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                base_color_factor: json::material::PbrBaseColorFactor([1.0, 1.0, 1.0, 1.0]),
                metallic_factor: json::material::StrengthFactor(0.0),
                roughness_factor: json::material::StrengthFactor(0.8),
                ..Default::default()
            },
            double_sided: false,
            ..Default::default()
        };
        let shared = (!meta.material_per_mesh).then(|| root.push(material(None)));
        for (m, p) in placed {
            let material = match shared {
                Some(s) => s,
                None => root.push(material(Some(m.name.clone()))),
            };
            let n = p.vertices;
            let pv = root.push(view(buffer, p.position_offset(), 12 * n as u64, Target::ArrayBuffer));
            let nv = root.push(view(buffer, p.normal_offset(), 12 * n as u64, Target::ArrayBuffer));
            let cv = root.push(view(buffer, p.colour_offset(), 4 * n as u64, Target::ArrayBuffer));
            let iv = root.push(view(buffer, p.index_offset(), p.index_bytes(), Target::ElementArrayBuffer));
            let mut pos = accessor(pv, n, ComponentType::F32, Type::Vec3, false);
            pos.min = Some(vec3_value(p.min));
            pos.max = Some(vec3_value(p.max));
            let pos = root.push(pos);
            let nrm = root.push(accessor(nv, n, ComponentType::F32, Type::Vec3, false));
            let col = root.push(accessor(cv, n, ComponentType::U8, Type::Vec4, true));
            let index_type = if p.short { ComponentType::U16 } else { ComponentType::U32 };
            let idx = root.push(accessor(iv, 3 * p.triangles, index_type, Type::Scalar, false));
            let mut attributes = BTreeMap::new();
            attributes.insert(Valid(json::mesh::Semantic::Positions), pos);
            attributes.insert(Valid(json::mesh::Semantic::Normals), nrm);
            attributes.insert(Valid(json::mesh::Semantic::Colors(0)), col);
            let mesh = root.push(json::Mesh {
                extensions: None,
                extras: None,
                name: Some(m.name.clone()),
                primitives: vec![json::mesh::Primitive {
                    attributes,
                    extensions: None,
                    extras: None,
                    indices: Some(idx),
                    material: Some(material),
                    mode: Valid(json::mesh::Mode::Triangles),
                    targets: None,
                }],
                weights: None,
            });
            let node = root.push(json::Node { mesh: Some(mesh), name: Some(m.name.clone()), ..Default::default() });
            let parent = meta.graph.as_ref().and_then(|g| g.mesh_nodes.get(p.mesh).copied().flatten()).and_then(|i| graph_nodes.get(i as usize));
            match parent {
                Some(&b) => root.nodes[b.value()].children.get_or_insert_with(Vec::new).push(node),
                None => children.push(node),
            }
        }
    }
    if !children.is_empty() {
        root.nodes[root_node.value()].children = Some(children);
    }
    let mut nodes = vec![root_node];
    if let Some(c) = &meta.camera {
        let at = c.first();
        let camera = root.push(super::gltf_graph::perspective(c.name.clone(), c.yfov, c.znear, c.zfar));
        nodes.push(root.push(json::Node {
            camera: Some(camera),
            name: Some("camera".to_string()),
            rotation: Some(json::scene::UnitQuaternion(at.rotation)),
            translation: Some(at.translation),
            ..Default::default()
        }));
    }
    let scene = root.push(json::Scene { extensions: None, extras: scene_extras(meta)?, name: None, nodes });
    root.scene = Some(scene);
    Ok(root.to_vec()?)
}
