//! The one glTF document builder behind every glTF writer: plain
//! ([`document`]), compact (`super::compact`: quantised, meshopt), animated
//! (the node graph of `graph`) and GPU-instanced (`gpu_instancing`).
//! [`Doc`] owns the asset, the root node `"rulemesh"`, the material
//! (shared, or one per mesh), the meshes with their nodes (hung under their
//! bone when there is a node graph), the extensions the document uses, and
//! at [`Doc::finish`] the still camera and the scene with its `extras`.
//! Writers describe their buffers, views and accessors through it; the
//! bytes those point at are laid out elsewhere (`buffer`, `compact`).
//!
//! The document is rulemesh's own small tree (`tree`, which says why it is
//! not gltf-json's), borrowing its names from the meshes and the model, and
//! `json_out` writes it.

use super::buffer::{accessor, view, Placement, Tracks};
use super::graph::add_graph;
use super::tree::{push, Bounds, Buffer, Component, Instancing, Ix, Kind, Material, Mesh, MeshoptView, Node, Root, Scene, Target, View, EXT_INSTANCING};
use crate::export::{ExportError, ExportMeta};

/// The vertex attributes of one mesh primitive.
pub(super) struct Attributes {
    /// POSITION.
    pub(super) position: Ix,
    /// NORMAL.
    pub(super) normal: Ix,
    /// COLOR_0.
    pub(super) colour: Ix,
}

/// A glTF document being built: the root plus what the builder needs to
/// finish it (the root node's children, the bones, the shared material).
pub(super) struct Doc<'a> {
    /// The document so far; writers push their buffers, views and accessors here.
    pub(super) root: Root<'a>,
    root_node: Ix,
    /// Nodes directly under the root node, in order.
    children: Vec<Ix>,
    /// Per node-graph node, its glTF node (empty without a graph).
    bones: Vec<Ix>,
    shared_material: Option<Ix>,
}

impl<'a> Doc<'a> {
    /// An empty document: the asset and the root node `"rulemesh"`.
    pub(super) fn new() -> Doc<'a> {
        let mut root = Root::default();
        let root_node = push(&mut root.nodes, Node { name: "rulemesh", ..Default::default() });
        Doc { root, root_node, children: Vec::new(), bones: Vec::new(), shared_material: None }
    }

    /// Makes room for `meshes` meshes of `views` views and accessors each,
    /// so the arrays grow once, not one element at a time.
    pub(super) fn reserve(&mut self, meshes: usize, views: usize) {
        self.root.accessors.reserve(meshes * views);
        self.root.views.reserve(meshes * views);
        self.root.meshes.reserve(meshes);
        self.root.nodes.reserve(meshes);
        self.children.reserve(meshes);
    }

    /// Adds a buffer of `byte_length` bytes; `uri` is None for GLB's own chunk.
    pub(super) fn buffer(&mut self, byte_length: u64, uri: Option<String>) -> Ix {
        push(&mut self.root.buffers, Buffer { byte_length, uri, meshopt_fallback: false })
    }

    /// Adds `EXT_meshopt_compression`'s fallback buffer: `byte_length`
    /// bytes of decoded layout with no data.
    pub(super) fn meshopt_fallback_buffer(&mut self, byte_length: u64) -> Ix {
        push(&mut self.root.buffers, Buffer { byte_length, uri: None, meshopt_fallback: true })
    }

    /// Adds a buffer view, with `EXT_meshopt_compression` when `meshopt` is given.
    pub(super) fn view(&mut self, mut view: View, meshopt: Option<MeshoptView>) -> Ix {
        view.meshopt = meshopt;
        push(&mut self.root.views, view)
    }

    /// Declares `name` used and required (once, in first-declared order).
    pub(super) fn require(&mut self, name: &'static str) {
        if !self.root.extensions.contains(&name) {
            self.root.extensions.push(name);
        }
    }

    /// Adds the node graph (bones, their animation, the animated camera)
    /// whose samples `tracks` places in `buffer`.
    pub(super) fn graph(&mut self, meta: &'a ExportMeta, tracks: &Tracks, buffer: Option<Ix>) {
        if let Some(g) = &meta.graph {
            let (bones, top) = add_graph(&mut self.root, g, tracks, buffer);
            self.bones = bones;
            self.children.extend(top);
        }
    }

    /// Adds a mesh named `name` of one TRIANGLES primitive, its material and
    /// its node, placed by `translation` and uniform `scale` when given (the
    /// compact writer's dequantisation), and hung under bone `bone` of the
    /// node graph when there is one, else under the root node. Returns the node.
    pub(super) fn mesh(&mut self, name: &'a str, attributes: Attributes, indices: Ix, meta: &ExportMeta, placement: Option<([f32; 3], f32)>, bone: Option<u32>) -> Ix {
        let material = match (meta.material_per_mesh, self.shared_material) {
            (true, _) => push(&mut self.root.materials, Material { name: Some(name) }),
            (false, Some(m)) => m,
            (false, None) => *self.shared_material.insert(push(&mut self.root.materials, Material { name: None })),
        };
        let Attributes { position, normal, colour } = attributes;
        let mesh = push(&mut self.root.meshes, Mesh { name, position, normal, colour, indices, material });
        let node = push(
            &mut self.root.nodes,
            Node { mesh: Some(mesh), name, translation: placement.map(|p| p.0), scale: placement.map(|p| [p.1; 3]), ..Default::default() },
        );
        match bone.and_then(|b| self.bones.get(b as usize)).and_then(|&b| self.root.nodes.get_mut(b as usize)) {
            Some(b) => b.children.push(node),
            None => self.children.push(node),
        }
        node
    }

    /// Draws `node`'s mesh once per instance with `EXT_mesh_gpu_instancing`,
    /// reading each instance's attributes from `instancing`.
    pub(super) fn instance(&mut self, node: Ix, instancing: Instancing) -> Result<(), ExportError> {
        let Some(n) = self.root.nodes.get_mut(node as usize) else {
            return Err(super::buffer::invalid("model", "an instanced node is missing from the document"));
        };
        n.instancing = Some(instancing);
        self.require(EXT_INSTANCING);
        Ok(())
    }

    /// Finishes the document: the root node's children, the still camera's
    /// node, the one scene with its `extras`, and the model's provenance in
    /// `asset.extras`.
    pub(super) fn finish(mut self, meta: &'a ExportMeta) -> Result<Root<'a>, ExportError> {
        if let Some(n) = self.root.nodes.get_mut(self.root_node as usize) {
            n.children = self.children;
        }
        let mut nodes = vec![self.root_node];
        if let Some(c) = &meta.camera {
            let at = c.first();
            let camera = push(&mut self.root.cameras, super::graph::perspective(c.name.as_deref(), c.yfov, c.znear, c.zfar));
            let node = Node { camera: Some(camera), name: "camera", rotation: Some(at.rotation), translation: Some(at.translation), ..Default::default() };
            nodes.push(push(&mut self.root.nodes, node));
        }
        let scene = push(&mut self.root.scenes, Scene { background: meta.background, truncated: meta.truncated, nodes });
        if let Some(p) = &meta.provenance {
            self.root.provenance = Some(p.raw_json()?);
        }
        self.root.scene = Some(scene);
        Ok(self.root)
    }
}

/// The plain writers' document, unfinished: per placed mesh its four views
/// (POSITION, NORMAL, COLOR_0, indices into the one buffer), accessors (with
/// POSITION bounds), mesh and node, plus the node graph. `uri` is the
/// buffer's URI (None for GLB); `extra_views` is how many more views and
/// accessors per mesh the caller will add (room is made for them). Returns
/// the builder, each placed mesh's node and the buffer (None when
/// `buffer_len` is 0).
pub(super) fn plain<'a>(
    placed: &[Placement<'a>],
    buffer_len: u64,
    tracks: &Tracks,
    meta: &'a ExportMeta,
    uri: Option<String>,
    extra_views: usize,
) -> (Doc<'a>, Vec<Ix>, Option<Ix>) {
    let mut doc = Doc::new();
    let buffer = (buffer_len > 0).then(|| doc.buffer(buffer_len, uri));
    doc.graph(meta, tracks, buffer);
    let mut nodes = Vec::with_capacity(placed.len());
    let Some(buffer) = buffer else { return (doc, nodes, None) };
    doc.reserve(placed.len(), 4 + extra_views);
    for (m, p) in placed {
        let n = p.vertices;
        let pv = push(&mut doc.root.views, view(buffer, p.position_offset(), 12 * n as u64, Some(Target::Vertices)));
        let nv = push(&mut doc.root.views, view(buffer, p.normal_offset(), 12 * n as u64, Some(Target::Vertices)));
        let cv = push(&mut doc.root.views, view(buffer, p.colour_offset(), 4 * n as u64, Some(Target::Vertices)));
        let iv = push(&mut doc.root.views, view(buffer, p.index_offset(), p.index_bytes(), Some(Target::Indices)));
        let mut pos = accessor(pv, n, Component::F32, Kind::Vec3, false);
        pos.bounds = Some(Bounds::Float(p.min, p.max));
        let position = push(&mut doc.root.accessors, pos);
        let normal = push(&mut doc.root.accessors, accessor(nv, n, Component::F32, Kind::Vec3, false));
        let colour = push(&mut doc.root.accessors, accessor(cv, n, Component::U8, Kind::Vec4, true));
        let index_type = if p.short { Component::U16 } else { Component::U32 };
        let idx = push(&mut doc.root.accessors, accessor(iv, 3 * p.triangles, index_type, Kind::Scalar, false));
        let bone = meta.graph.as_ref().and_then(|g| g.mesh_nodes.get(p.mesh).copied().flatten());
        nodes.push(doc.mesh(&m.name, Attributes { position, normal, colour }, idx, meta, None, bone));
    }
    (doc, nodes, Some(buffer))
}

/// The plain writers' JSON (see [`plain`]), serialised.
pub(super) fn document(placed: &[Placement<'_>], buffer_len: u64, tracks: &Tracks, meta: &ExportMeta, uri: Option<String>) -> Result<Vec<u8>, ExportError> {
    let (doc, _, _) = plain(placed, buffer_len, tracks, meta, uri, 0);
    super::json_out::root_json(&doc.finish(meta)?)
}
