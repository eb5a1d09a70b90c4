//! The node graph part of a plain glTF document: one node per bone (with
//! its parent), the animated camera, and the `"rulemesh"` animation whose
//! channels read the samples [`Tracks`] laid out after the meshes. Only
//! animated grammars and camera paths have a graph, so it is kept apart from
//! the meshes and materials of `document`.

use super::buffer::{accessor, Mover, Tracks};
use crate::model::graph::{NodeGraph, Trs};
use gltf_json as json;
use json::validation::{Checked::Valid, USize64};

/// The glTF perspective camera both the still camera node and the node
/// graph's camera use (the aspect ratio is left to the viewer).
pub(super) fn perspective(name: Option<String>, yfov: f32, znear: f32, zfar: Option<f32>) -> json::Camera {
    json::Camera {
        name,
        orthographic: None,
        perspective: Some(json::camera::Perspective { aspect_ratio: None, yfov, zfar, znear, extensions: None, extras: None }),
        type_: Valid(json::camera::Type::Perspective),
        extensions: None,
        extras: None,
    }
}

/// A glTF node with the transform `trs`.
fn trs_node(name: &str, trs: &Trs) -> json::Node {
    json::Node {
        name: Some(name.to_string()),
        translation: Some(trs.translation),
        rotation: Some(json::scene::UnitQuaternion(trs.rotation)),
        scale: Some(trs.scale),
        ..Default::default()
    }
}

/// Adds the graph's nodes, camera and animation to `root`. Returns, per
/// graph node, its glTF node, and the nodes that hang directly under the
/// model's root node (top-level bones and the camera).
pub(super) fn add_graph(root: &mut json::Root, g: &NodeGraph, tracks: &Tracks, buffer: Option<json::Index<json::Buffer>>) -> (Vec<json::Index<json::Node>>, Vec<json::Index<json::Node>>) {
    use json::accessor::{ComponentType, Type};
    let identity = Trs { translation: [0.0; 3], rotation: [0.0, 0.0, 0.0, 1.0], scale: [1.0; 3] };
    let nodes: Vec<_> = g.nodes.iter().map(|n| root.push(trs_node(&n.name, n.samples.first().unwrap_or(&identity)))).collect();
    let mut top = Vec::new();
    for (i, n) in g.nodes.iter().enumerate() {
        match n.parent.and_then(|p| nodes.get(p as usize)) {
            Some(&p) => root.nodes[p.value()].children.get_or_insert_with(Vec::new).push(nodes[i]),
            None => top.push(nodes[i]),
        }
    }
    let camera_node = g.camera.as_ref().map(|c| {
        let camera = root.push(perspective(c.name.clone(), c.yfov, c.znear, c.zfar));
        let mut node = trs_node("camera", c.placements.first().unwrap_or(&identity));
        node.scale = None;
        node.camera = Some(camera);
        let n = root.push(node);
        top.push(n);
        n
    });
    let Some(buffer) = buffer.filter(|_| !tracks.channels.is_empty()) else { return (nodes, top) };
    let view = root.push(json::buffer::View {
        buffer,
        byte_length: USize64(tracks.bytes.len() as u64),
        byte_offset: Some(USize64(tracks.offset)),
        byte_stride: None,
        name: Some("animation".to_string()),
        target: None,
        extensions: None,
        extras: None,
    });
    let mut times = accessor(view, tracks.count, ComponentType::F32, Type::Scalar, false);
    times.min = Some(json::Value::Array(vec![json::Value::from(0.0)]));
    times.max = Some(json::Value::Array(vec![json::Value::from(f64::from(tracks.end))]));
    let input = root.push(times);
    let mut samplers = Vec::new();
    let mut channels = Vec::new();
    for &(mover, property, at) in &tracks.channels {
        let type_ = if property == json::animation::Property::Rotation { Type::Vec4 } else { Type::Vec3 };
        let mut out = accessor(view, tracks.count, ComponentType::F32, type_, false);
        out.byte_offset = Some(USize64(at));
        let output = root.push(out);
        let interpolation = if g.step { json::animation::Interpolation::Step } else { json::animation::Interpolation::Linear };
        samplers.push(json::animation::Sampler { input, interpolation: Valid(interpolation), output, extensions: None, extras: None });
        let node = match mover {
            Mover::Node(i) => nodes[i],
            Mover::Camera => match camera_node {
                Some(n) => n,
                None => continue,
            },
        };
        channels.push(json::animation::Channel {
            sampler: json::Index::new((samplers.len() - 1) as u32),
            target: json::animation::Target { node, path: Valid(property), extensions: None, extras: None },
            extensions: None,
            extras: None,
        });
    }
    root.push(json::Animation { name: Some("rulemesh".to_string()), channels, samplers, extensions: None, extras: None });
    (nodes, top)
}
