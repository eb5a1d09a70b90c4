//! The node graph part of a plain glTF document: one node per bone (with
//! its parent), the animated camera, and the `"rulemesh"` animation whose
//! channels read the samples [`Tracks`] laid out after the meshes. Only
//! animated grammars and camera paths have a graph, so it is kept apart from
//! the meshes and materials of `document`.

use super::buffer::{accessor, Mover, Tracks};
use super::tree::{push, Animation, Bounds, Camera, Channel, Component, Ix, Kind, Node, Path, Root, Sampler, View};
use crate::model::graph::{NodeGraph, Trs};

/// The glTF perspective camera both the still camera node and the node
/// graph's camera use (the aspect ratio is left to the viewer).
pub(super) fn perspective(name: Option<&str>, yfov: f32, znear: f32, zfar: Option<f32>) -> Camera<'_> {
    Camera { name, yfov, zfar, znear }
}

/// Adds the graph's nodes, camera and animation to `root`. Returns, per
/// graph node, its glTF node, and the nodes that hang directly under the
/// model's root node (top-level bones and the camera).
pub(super) fn add_graph<'a>(root: &mut Root<'a>, g: &'a NodeGraph, tracks: &Tracks, buffer: Option<Ix>) -> (Vec<Ix>, Vec<Ix>) {
    let identity = Trs { translation: [0.0; 3], rotation: [0.0, 0.0, 0.0, 1.0], scale: [1.0; 3] };
    let nodes: Vec<Ix> = g.nodes.iter().map(|n| push(&mut root.nodes, Node::trs(&n.name, n.samples.first().unwrap_or(&identity)))).collect();
    let mut top = Vec::new();
    for (i, n) in g.nodes.iter().enumerate() {
        match n.parent.and_then(|p| nodes.get(p as usize)).and_then(|&p| root.nodes.get_mut(p as usize)) {
            Some(parent) => parent.children.push(nodes[i]),
            None => top.push(nodes[i]),
        }
    }
    let camera_node = g.camera.as_ref().map(|c| {
        let camera = push(&mut root.cameras, perspective(c.name.as_deref(), c.yfov, c.znear, c.zfar));
        let mut node = Node::trs("camera", c.placements.first().unwrap_or(&identity));
        node.scale = None;
        node.camera = Some(camera);
        let n = push(&mut root.nodes, node);
        top.push(n);
        n
    });
    let Some(buffer) = buffer.filter(|_| !tracks.channels.is_empty()) else { return (nodes, top) };
    let view = push(
        &mut root.views,
        View { buffer, byte_length: tracks.bytes.len() as u64, byte_offset: tracks.offset, byte_stride: None, name: Some("animation"), target: None, meshopt: None },
    );
    let mut times = accessor(view, tracks.count, Component::F32, Kind::Scalar, false);
    times.bounds = Some(Bounds::Times(tracks.end));
    let input = push(&mut root.accessors, times);
    let mut samplers = Vec::new();
    let mut channels = Vec::new();
    for &(mover, path, at) in &tracks.channels {
        let kind = if path == Path::Rotation { Kind::Vec4 } else { Kind::Vec3 };
        let mut out = accessor(view, tracks.count, Component::F32, kind, false);
        out.byte_offset = Some(at);
        let output = push(&mut root.accessors, out);
        samplers.push(Sampler { input, step: g.step, output });
        let node = match mover {
            Mover::Node(i) => nodes[i],
            Mover::Camera => match camera_node {
                Some(n) => n,
                None => continue,
            },
        };
        channels.push(Channel { sampler: (samplers.len() - 1) as Ix, node, path });
    }
    root.animations.push(Animation { channels, samplers });
    (nodes, top)
}
