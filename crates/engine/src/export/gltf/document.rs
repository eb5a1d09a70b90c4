//! The one glTF document builder, on typed `gltf-json`, behind every glTF
//! writer: plain ([`document`]), compact (`super::compact`: quantised,
//! meshopt), animated (the node graph of `graph`) and GPU-instanced
//! (`gpu_instancing`). [`Doc`] owns the asset, the root node `"rulemesh"`,
//! the material (shared, or one per mesh), the meshes with their nodes
//! (hung under their bone when there is a node graph), the extensions the
//! document uses, and at [`Doc::finish`] the still camera and the scene
//! with its `extras`. Writers describe their buffers, views and accessors
//! through it; the bytes those point at are laid out elsewhere
//! (`buffer`, `compact`). Extensions gltf-json does not model
//! (`EXT_meshopt_compression`, `EXT_mesh_gpu_instancing`) are typed structs
//! here, serialised into the extension maps with serde.

use super::buffer::{accessor, view, Placement, Tracks};
use super::graph::add_graph;
use crate::export::{ExportError, ExportMeta};
use gltf_json as json;
use json::validation::{Checked::Valid, USize64};
use json::Index;
use std::collections::BTreeMap;

/// `EXT_meshopt_compression`: meshoptimizer's codecs on buffer views.
pub(super) const EXT_MESHOPT: &str = "EXT_meshopt_compression";
/// `KHR_mesh_quantization`: integer vertex attributes.
pub(super) const KHR_QUANT: &str = "KHR_mesh_quantization";
/// `EXT_mesh_gpu_instancing`: per-node instance transforms.
pub(crate) const EXT_INSTANCING: &str = "EXT_mesh_gpu_instancing";

/// `EXT_meshopt_compression` on a buffer view: where its encoded bytes are
/// and how to decode them into the view's (fallback) layout.
#[derive(serde::Serialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct MeshoptView {
    /// The buffer holding the encoded bytes.
    pub(super) buffer: u32,
    /// Where the encoded bytes start.
    pub(super) byte_offset: u64,
    /// How many encoded bytes there are.
    pub(super) byte_length: u64,
    /// Bytes per decoded element.
    pub(super) byte_stride: u64,
    /// Decoded elements.
    pub(super) count: u64,
    /// The codec: `ATTRIBUTES` (vertex codec) or `TRIANGLES` (index codec).
    pub(super) mode: &'static str,
}

/// `EXT_meshopt_compression` on a buffer: it has no data of its own and
/// only gives the decoded layout.
#[derive(serde::Serialize)]
struct MeshoptFallback {
    fallback: bool,
}

/// `EXT_mesh_gpu_instancing` on a node: the accessors of its instances.
#[derive(serde::Serialize)]
struct Instancing {
    attributes: InstanceAttributes,
}

/// The per-instance attributes rulemesh writes: rigid L-system segments
/// have no SCALE and carry their colour in their mesh; placed primitives
/// have ROTATION, SCALE and `_COLOR_0` (float RGB, which three.js reads into
/// `InstancedMesh.instanceColor`) where they differ between instances, and a
/// colour all instances share in their mesh.
#[derive(serde::Serialize)]
#[serde(rename_all = "UPPERCASE")]
struct InstanceAttributes {
    translation: u32,
    #[serde(skip_serializing_if = "Option::is_none")]
    rotation: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    scale: Option<u32>,
    #[serde(rename = "_COLOR_0", skip_serializing_if = "Option::is_none")]
    colour: Option<u32>,
}

/// The accessors of one instanced node's attributes.
pub(super) struct InstanceAccessors {
    /// TRANSLATION.
    pub(super) translation: Index<json::Accessor>,
    /// ROTATION, when written.
    pub(super) rotation: Option<Index<json::Accessor>>,
    /// SCALE, when written.
    pub(super) scale: Option<Index<json::Accessor>>,
    /// `_COLOR_0`, when written.
    pub(super) colour: Option<Index<json::Accessor>>,
}

/// One extension object keyed by its name, for gltf-json's extension maps.
fn extension(name: &str, value: impl serde::Serialize) -> Result<serde_json::Map<String, json::Value>, ExportError> {
    let mut map = serde_json::Map::new();
    map.insert(name.to_string(), serde_json::to_value(value)?);
    Ok(map)
}

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
    // Written, not parsed back: the map's text is JSON already.
    Ok(Some(serde_json::value::to_raw_value(&map)?))
}

/// The material every mesh is drawn with: white, metallic 0, roughness 0.8,
/// so vertex colours show; `name` when each mesh has its own.
fn material(name: Option<String>) -> json::Material {
    json::Material {
        name,
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

/// The vertex attributes of one mesh primitive.
pub(super) struct Attributes {
    /// POSITION.
    pub(super) position: Index<json::Accessor>,
    /// NORMAL.
    pub(super) normal: Index<json::Accessor>,
    /// COLOR_0.
    pub(super) colour: Index<json::Accessor>,
}

/// A glTF document being built: the typed root plus what the builder needs
/// to finish it (the root node's children, the bones, the shared material).
pub(super) struct Doc {
    /// The document so far; writers push their buffers, views and accessors here.
    pub(super) root: json::Root,
    root_node: Index<json::Node>,
    /// Nodes directly under the root node, in order.
    children: Vec<Index<json::Node>>,
    /// Per node-graph node, its glTF node (empty without a graph).
    bones: Vec<Index<json::Node>>,
    shared_material: Option<Index<json::Material>>,
}

impl Doc {
    /// An empty document: the asset and the root node `"rulemesh"`.
    pub(super) fn new() -> Doc {
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
        Doc { root, root_node, children: Vec::new(), bones: Vec::new(), shared_material: None }
    }

    /// Adds a buffer of `byte_length` bytes; `uri` is None for GLB's own chunk.
    pub(super) fn buffer(&mut self, byte_length: u64, uri: Option<String>) -> Index<json::Buffer> {
        self.root.push(json::Buffer { byte_length: USize64(byte_length), name: None, uri, extensions: None, extras: None })
    }

    /// Adds `EXT_meshopt_compression`'s fallback buffer: `byte_length`
    /// bytes of decoded layout with no data.
    pub(super) fn meshopt_fallback_buffer(&mut self, byte_length: u64) -> Result<Index<json::Buffer>, ExportError> {
        let others = extension(EXT_MESHOPT, MeshoptFallback { fallback: true })?;
        Ok(self.root.push(json::Buffer {
            byte_length: USize64(byte_length),
            name: None,
            uri: None,
            extensions: Some(json::extensions::buffer::Buffer { others }),
            extras: None,
        }))
    }

    /// Adds a buffer view, with `EXT_meshopt_compression` when `meshopt` is given.
    pub(super) fn view(&mut self, mut view: json::buffer::View, meshopt: Option<MeshoptView>) -> Result<Index<json::buffer::View>, ExportError> {
        if let Some(m) = meshopt {
            view.extensions = Some(json::extensions::buffer::View { others: extension(EXT_MESHOPT, m)? });
        }
        Ok(self.root.push(view))
    }

    /// Declares `name` used and required (once, in first-declared order).
    pub(super) fn require(&mut self, name: &str) {
        if !self.root.extensions_used.iter().any(|e| e == name) {
            self.root.extensions_used.push(name.to_string());
            self.root.extensions_required.push(name.to_string());
        }
    }

    /// Adds the node graph (bones, their animation, the animated camera)
    /// whose samples `tracks` places in `buffer`.
    pub(super) fn graph(&mut self, meta: &ExportMeta, tracks: &Tracks, buffer: Option<Index<json::Buffer>>) {
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
    pub(super) fn mesh(
        &mut self,
        name: &str,
        attributes: Attributes,
        indices: Index<json::Accessor>,
        meta: &ExportMeta,
        placement: Option<([f32; 3], f32)>,
        bone: Option<u32>,
    ) -> Index<json::Node> {
        let material = match (meta.material_per_mesh, self.shared_material) {
            (true, _) => self.root.push(material(Some(name.to_string()))),
            (false, Some(m)) => m,
            (false, None) => *self.shared_material.insert(self.root.push(material(None))),
        };
        let mut map = BTreeMap::new();
        map.insert(Valid(json::mesh::Semantic::Positions), attributes.position);
        map.insert(Valid(json::mesh::Semantic::Normals), attributes.normal);
        map.insert(Valid(json::mesh::Semantic::Colors(0)), attributes.colour);
        let mesh = self.root.push(json::Mesh {
            extensions: None,
            extras: None,
            name: Some(name.to_string()),
            primitives: vec![json::mesh::Primitive {
                attributes: map,
                extensions: None,
                extras: None,
                indices: Some(indices),
                material: Some(material),
                mode: Valid(json::mesh::Mode::Triangles),
                targets: None,
            }],
            weights: None,
        });
        let node = self.root.push(json::Node {
            mesh: Some(mesh),
            name: Some(name.to_string()),
            translation: placement.map(|p| p.0),
            scale: placement.map(|p| [p.1; 3]),
            ..Default::default()
        });
        match bone.and_then(|b| self.bones.get(b as usize)) {
            Some(&b) => self.root.nodes[b.value()].children.get_or_insert_with(Vec::new).push(node),
            None => self.children.push(node),
        }
        node
    }

    /// Draws `node`'s mesh once per instance with `EXT_mesh_gpu_instancing`,
    /// reading each instance's attributes from `a`.
    pub(super) fn instance(&mut self, node: Index<json::Node>, a: InstanceAccessors) -> Result<(), ExportError> {
        let index = |i: Index<json::Accessor>| i.value() as u32;
        let attributes = InstanceAttributes { translation: index(a.translation), rotation: a.rotation.map(index), scale: a.scale.map(index), colour: a.colour.map(index) };
        let ext = Instancing { attributes };
        let others = extension(EXT_INSTANCING, ext)?;
        let Some(n) = self.root.nodes.get_mut(node.value()) else {
            return Err(super::buffer::invalid("model", "an instanced node is missing from the document"));
        };
        n.extensions = Some(json::extensions::scene::Node { others });
        self.require(EXT_INSTANCING);
        Ok(())
    }

    /// Finishes the document: the root node's children, the still camera's
    /// node, the one scene with its `extras`, and the model's provenance in
    /// `asset.extras`.
    pub(super) fn finish(mut self, meta: &ExportMeta) -> Result<json::Root, ExportError> {
        if !self.children.is_empty() {
            self.root.nodes[self.root_node.value()].children = Some(self.children);
        }
        let mut nodes = vec![self.root_node];
        if let Some(c) = &meta.camera {
            let at = c.first();
            let camera = self.root.push(super::graph::perspective(c.name.clone(), c.yfov, c.znear, c.zfar));
            nodes.push(self.root.push(json::Node {
                camera: Some(camera),
                name: Some("camera".to_string()),
                rotation: Some(json::scene::UnitQuaternion(at.rotation)),
                translation: Some(at.translation),
                ..Default::default()
            }));
        }
        let scene = self.root.push(json::Scene { extensions: None, extras: scene_extras(meta)?, name: None, nodes });
        if let Some(p) = &meta.provenance {
            self.root.asset.extras = Some(p.raw_json()?);
        }
        self.root.scene = Some(scene);
        Ok(self.root)
    }
}

/// The plain writers' document, unfinished: per placed mesh its four views
/// (POSITION, NORMAL, COLOR_0, indices into the one buffer), accessors (with
/// POSITION bounds), mesh and node, plus the node graph. `uri` is the
/// buffer's URI (None for GLB). Returns the builder, each placed mesh's
/// node and the buffer (None when `buffer_len` is 0).
pub(super) fn plain(placed: &[Placement<'_>], buffer_len: u64, tracks: &Tracks, meta: &ExportMeta, uri: Option<String>) -> (Doc, Vec<Index<json::Node>>, Option<Index<json::Buffer>>) {
    use json::accessor::{ComponentType, Type};
    use json::buffer::Target;
    let mut doc = Doc::new();
    let buffer = (buffer_len > 0).then(|| doc.buffer(buffer_len, uri));
    doc.graph(meta, tracks, buffer);
    let mut nodes = Vec::with_capacity(placed.len());
    let Some(buffer) = buffer else { return (doc, nodes, None) };
    for (m, p) in placed {
        let n = p.vertices;
        let pv = doc.root.push(view(buffer, p.position_offset(), 12 * n as u64, Some(Target::ArrayBuffer)));
        let nv = doc.root.push(view(buffer, p.normal_offset(), 12 * n as u64, Some(Target::ArrayBuffer)));
        let cv = doc.root.push(view(buffer, p.colour_offset(), 4 * n as u64, Some(Target::ArrayBuffer)));
        let iv = doc.root.push(view(buffer, p.index_offset(), p.index_bytes(), Some(Target::ElementArrayBuffer)));
        let mut pos = accessor(pv, n, ComponentType::F32, Type::Vec3, false);
        pos.min = Some(vec3_value(p.min));
        pos.max = Some(vec3_value(p.max));
        let position = doc.root.push(pos);
        let normal = doc.root.push(accessor(nv, n, ComponentType::F32, Type::Vec3, false));
        let colour = doc.root.push(accessor(cv, n, ComponentType::U8, Type::Vec4, true));
        let index_type = if p.short { ComponentType::U16 } else { ComponentType::U32 };
        let idx = doc.root.push(accessor(iv, 3 * p.triangles, index_type, Type::Scalar, false));
        let bone = meta.graph.as_ref().and_then(|g| g.mesh_nodes.get(p.mesh).copied().flatten());
        nodes.push(doc.mesh(&m.name, Attributes { position, normal, colour }, idx, meta, None, bone));
    }
    (doc, nodes, Some(buffer))
}

/// The plain writers' JSON (see [`plain`]), serialised.
pub(super) fn document(placed: &[Placement<'_>], buffer_len: u64, tracks: &Tracks, meta: &ExportMeta, uri: Option<String>) -> Result<Vec<u8>, ExportError> {
    let (doc, _, _) = plain(placed, buffer_len, tracks, meta, uri);
    super::json_out::root_json(&doc.finish(meta)?)
}
