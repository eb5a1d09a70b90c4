//! A glTF document's JSON: the bytes serde_json writes for gltf-json's
//! `Root` (`Root::to_vec`), with the arrays that make up most of a
//! document (accessors, buffer views, meshes and nodes) written without
//! serde.
//!
//! Why: in a fresh icon render (issue 33's `gem.glb`: 25 accessors and 25
//! views in 5 KB of JSON) serialising the document was a quarter of the
//! whole render's CPU, mostly serde's per-field machinery around short
//! keys (`format_escaped_str` alone a third of it). Their keys, integers,
//! fixed words and names that need no escaping are written here as plain
//! bytes; floats, extensions, extras, sparse storage and the other objects
//! go through serde_json as before, field by field in gltf-json's
//! declaration order, so the output is the same bytes `Root::to_vec` gives.
//! The unit test compares the two on a document with every field these
//! writers set, and the golden table on every model.
//!
//! The field lists follow gltf-json 1.4.1 (`Cargo.lock`): a new version
//! that adds or reorders a field of these four types must be read against
//! them before it is taken (the golden table fails if a field rulemesh sets
//! moves; one it never sets would pass unnoticed).

use crate::export::ExportError;
use gltf_json as json;
use json::validation::Checked;
use serde::Serialize;

/// `root` as compact JSON: the bytes of `Root::to_vec`.
pub(super) fn root_json(root: &json::Root) -> Result<Vec<u8>, ExportError> {
    // About what one accessor, view, node or mesh takes, with room to spare
    // for the asset, the scene and the extras: one allocation, not the
    // doubling from 128 bytes that `to_vec` starts with.
    let items = root.accessors.len() + root.buffer_views.len() + root.nodes.len() + root.meshes.len() + root.materials.len();
    let mut o = Out { bytes: Vec::with_capacity(1024 + 160 * items), first: true };
    o.bytes.push(b'{');
    // gltf-json's `Root` fields in declaration order, each skipped exactly
    // when its `skip_serializing_if` says.
    o.array_field("accessors", &root.accessors, accessor)?;
    o.vec_field("animations", &root.animations)?;
    o.field("asset", &root.asset)?;
    o.vec_field("buffers", &root.buffers)?;
    o.array_field("bufferViews", &root.buffer_views, view)?;
    o.option_field("scene", &root.scene)?;
    o.option_field("extensions", &root.extensions)?;
    o.option_field("extras", &root.extras)?;
    o.vec_field("extensionsUsed", &root.extensions_used)?;
    o.vec_field("extensionsRequired", &root.extensions_required)?;
    o.vec_field("cameras", &root.cameras)?;
    o.vec_field("images", &root.images)?;
    o.vec_field("materials", &root.materials)?;
    o.array_field("meshes", &root.meshes, mesh)?;
    o.array_field("nodes", &root.nodes, node)?;
    o.vec_field("samplers", &root.samplers)?;
    o.vec_field("scenes", &root.scenes)?;
    o.vec_field("skins", &root.skins)?;
    o.vec_field("textures", &root.textures)?;
    o.bytes.push(b'}');
    Ok(o.bytes)
}

/// The JSON being written, and whether the open object has a field yet.
struct Out {
    bytes: Vec<u8>,
    first: bool,
}

impl Out {
    /// Starts field `name` of the open object (no key needs escaping).
    fn key(&mut self, name: &str) {
        if !self.first {
            self.bytes.push(b',');
        }
        self.first = false;
        self.bytes.push(b'"');
        self.bytes.extend_from_slice(name.as_bytes());
        self.bytes.extend_from_slice(b"\":");
    }

    /// A field whose value serde writes.
    fn field(&mut self, name: &str, value: &impl Serialize) -> Result<(), ExportError> {
        self.key(name);
        serde_json::to_writer(&mut self.bytes, value)?;
        Ok(())
    }

    /// A field skipped when `None` (`skip_serializing_if = "Option::is_none"`).
    fn option_field<T: Serialize>(&mut self, name: &str, value: &Option<T>) -> Result<(), ExportError> {
        match value {
            Some(v) => self.field(name, v),
            None => Ok(()),
        }
    }

    /// A field skipped when empty (`skip_serializing_if = "Vec::is_empty"`).
    fn vec_field<T: Serialize>(&mut self, name: &str, value: &[T]) -> Result<(), ExportError> {
        match value.is_empty() {
            true => Ok(()),
            false => self.field(name, &value),
        }
    }

    /// A field skipped when empty, its elements written by `write`.
    fn array_field<T>(&mut self, name: &str, items: &[T], write: fn(&mut Out, &T) -> Result<(), ExportError>) -> Result<(), ExportError> {
        if items.is_empty() {
            return Ok(());
        }
        self.key(name);
        self.array(items, write)
    }

    /// An array whose elements `write` writes (each an object of its own).
    fn array<T>(&mut self, items: &[T], write: fn(&mut Out, &T) -> Result<(), ExportError>) -> Result<(), ExportError> {
        self.bytes.push(b'[');
        for (k, item) in items.iter().enumerate() {
            if k > 0 {
                self.bytes.push(b',');
            }
            self.first = true;
            write(self, item)?;
        }
        self.bytes.push(b']');
        self.first = false;
        Ok(())
    }

    /// A number field.
    fn number(&mut self, name: &str, value: u64) {
        self.key(name);
        self.integer(value);
    }

    /// A bare integer.
    fn integer(&mut self, value: u64) {
        self.bytes.extend_from_slice(itoa::Buffer::new().format(value).as_bytes());
    }

    /// A string as serde_json writes it: as it is when nothing in it needs
    /// escaping (no quote, backslash or control character; serde_json leaves
    /// every other character, non-ASCII included, as it is), else by serde.
    fn string(&mut self, s: &str) -> Result<(), ExportError> {
        if s.bytes().all(|b| b >= 0x20 && b != b'"' && b != b'\\') {
            self.bytes.push(b'"');
            self.bytes.extend_from_slice(s.as_bytes());
            self.bytes.push(b'"');
        } else {
            serde_json::to_writer(&mut self.bytes, s)?;
        }
        Ok(())
    }

    /// A string field skipped when `None`.
    fn name_field(&mut self, name: &str, value: &Option<String>) -> Result<(), ExportError> {
        match value {
            Some(v) => {
                self.key(name);
                self.string(v)
            }
            None => Ok(()),
        }
    }

    /// An index field skipped when `None`.
    fn index_field<T>(&mut self, name: &str, value: Option<json::Index<T>>) {
        if let Some(i) = value {
            self.number(name, i.value() as u64);
        }
    }
}

/// The value of a `Checked` enum, or `None` for `Invalid` (which serde refuses).
fn valid<T: Copy>(c: &Checked<T>) -> Option<T> {
    match c {
        Checked::Valid(v) => Some(*v),
        Checked::Invalid => None,
    }
}

/// One accessor: by hand when it holds only numbers, bounds and fixed
/// words, else by serde.
fn accessor(o: &mut Out, a: &json::Accessor) -> Result<(), ExportError> {
    let plain = a.extensions.is_none() && a.extras.is_none() && a.name.is_none() && a.sparse.is_none();
    let (Some(component), Some(kind), true) = (valid(&a.component_type), valid(&a.type_), plain) else {
        serde_json::to_writer(&mut o.bytes, a)?;
        return Ok(());
    };
    o.bytes.push(b'{');
    if let Some(v) = a.buffer_view {
        o.number("bufferView", v.value() as u64);
    }
    if let Some(off) = a.byte_offset {
        o.number("byteOffset", off.0);
    }
    o.number("count", a.count.0);
    o.number("componentType", u64::from(component.0.as_gl_enum()));
    o.key("type");
    o.bytes.push(b'"');
    o.bytes.extend_from_slice(type_name(kind).as_bytes());
    o.bytes.push(b'"');
    o.option_field("min", &a.min)?;
    o.option_field("max", &a.max)?;
    if a.normalized {
        o.key("normalized");
        o.bytes.extend_from_slice(b"true");
    }
    o.bytes.push(b'}');
    Ok(())
}

/// An accessor type's word, as gltf-json writes it.
fn type_name(t: json::accessor::Type) -> &'static str {
    use json::accessor::Type;
    match t {
        Type::Scalar => "SCALAR",
        Type::Vec2 => "VEC2",
        Type::Vec3 => "VEC3",
        Type::Vec4 => "VEC4",
        Type::Mat2 => "MAT2",
        Type::Mat3 => "MAT3",
        Type::Mat4 => "MAT4",
    }
}

/// One buffer view: by hand when it holds only numbers, else by serde.
fn view(o: &mut Out, v: &json::buffer::View) -> Result<(), ExportError> {
    let target = v.target.as_ref().map(valid);
    if matches!(target, Some(None)) || v.extensions.is_some() || v.extras.is_some() || v.name.is_some() {
        serde_json::to_writer(&mut o.bytes, v)?;
        return Ok(());
    }
    o.bytes.push(b'{');
    o.number("buffer", v.buffer.value() as u64);
    o.number("byteLength", v.byte_length.0);
    if let Some(off) = v.byte_offset {
        o.number("byteOffset", off.0);
    }
    if let Some(s) = v.byte_stride {
        o.number("byteStride", s.0 as u64);
    }
    if let Some(Some(t)) = target {
        o.number("target", u64::from(match t {
            json::buffer::Target::ArrayBuffer => json::buffer::ARRAY_BUFFER,
            json::buffer::Target::ElementArrayBuffer => json::buffer::ELEMENT_ARRAY_BUFFER,
        }));
    }
    o.bytes.push(b'}');
    Ok(())
}

/// One mesh: its fields in gltf-json's order, the primitives by hand
/// unless one has extensions, extras or morph targets.
fn mesh(o: &mut Out, m: &json::Mesh) -> Result<(), ExportError> {
    if m.primitives.iter().any(|p| p.extensions.is_some() || p.extras.is_some() || p.targets.is_some()) {
        serde_json::to_writer(&mut o.bytes, m)?;
        return Ok(());
    }
    o.bytes.push(b'{');
    o.option_field("extensions", &m.extensions)?;
    o.option_field("extras", &m.extras)?;
    o.name_field("name", &m.name)?;
    o.key("primitives");
    o.array(&m.primitives, primitive)?;
    o.option_field("weights", &m.weights)?;
    o.bytes.push(b'}');
    Ok(())
}

/// One primitive with no extensions, extras or morph targets.
fn primitive(o: &mut Out, p: &json::mesh::Primitive) -> Result<(), ExportError> {
    o.bytes.push(b'{');
    o.key("attributes");
    o.bytes.push(b'{');
    // The map's own order, as serde walks it.
    for (k, (semantic, index)) in p.attributes.iter().enumerate() {
        if k > 0 {
            o.bytes.push(b',');
        }
        match semantic {
            Checked::Valid(s) => o.string(&s.to_string())?,
            // serde refuses an invalid key: so does this.
            Checked::Invalid => {
                serde_json::to_writer(&mut o.bytes, semantic)?;
            }
        }
        o.bytes.push(b':');
        o.integer(index.value() as u64);
    }
    o.bytes.push(b'}');
    o.index_field("indices", p.indices);
    o.index_field("material", p.material);
    match p.mode {
        Checked::Valid(json::mesh::Mode::Triangles) => {}
        Checked::Valid(mode) => o.number("mode", u64::from(mode.as_gl_enum())),
        Checked::Invalid => o.field("mode", &p.mode)?,
    }
    o.bytes.push(b'}');
    Ok(())
}

/// One node: its fields in gltf-json's order; numbers and the name by
/// hand, floats, extensions and extras by serde.
fn node(o: &mut Out, n: &json::Node) -> Result<(), ExportError> {
    o.bytes.push(b'{');
    o.index_field("camera", n.camera);
    if let Some(children) = &n.children {
        o.key("children");
        o.bytes.push(b'[');
        for (k, c) in children.iter().enumerate() {
            if k > 0 {
                o.bytes.push(b',');
            }
            o.integer(c.value() as u64);
        }
        o.bytes.push(b']');
    }
    o.option_field("extensions", &n.extensions)?;
    o.option_field("extras", &n.extras)?;
    o.option_field("matrix", &n.matrix)?;
    o.index_field("mesh", n.mesh);
    o.name_field("name", &n.name)?;
    o.option_field("rotation", &n.rotation)?;
    o.option_field("scale", &n.scale)?;
    o.option_field("translation", &n.translation)?;
    o.index_field("skin", n.skin);
    o.option_field("weights", &n.weights)?;
    o.bytes.push(b'}');
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use json::accessor::{ComponentType, GenericComponentType, Type};
    use json::buffer::{Stride, Target};
    use json::validation::{Checked::Valid, USize64};
    use json::Index;

    /// A document with every kind of accessor and view the writers make,
    /// and some they do not (names with quotes and escapes, extras).
    fn mixed() -> json::Root {
        let mut root = json::Root::default();
        let buffer = root.push(json::Buffer { byte_length: USize64(4096), name: None, uri: None, extensions: None, extras: None });
        for (k, target) in [None, Some(Valid(Target::ArrayBuffer)), Some(Valid(Target::ElementArrayBuffer)), Some(Valid(Target::ArrayBuffer))].into_iter().enumerate() {
            root.push(json::buffer::View {
                buffer,
                byte_length: USize64(12 * k as u64 + 1),
                byte_offset: (k % 2 == 1).then_some(USize64(8 * k as u64)),
                byte_stride: (k == 2).then_some(Stride(12)),
                name: (k == 3).then(|| "a \"named\" view\n".to_string()),
                target,
                extensions: None,
                extras: None,
            });
        }
        let kinds = [(ComponentType::F32, Type::Vec3), (ComponentType::U8, Type::Vec4), (ComponentType::U16, Type::Scalar), (ComponentType::U32, Type::Scalar), (ComponentType::I16, Type::Mat4), (ComponentType::I8, Type::Vec2)];
        for (k, (component, kind)) in kinds.into_iter().enumerate() {
            let mut a = json::Accessor {
                buffer_view: (k != 5).then(|| Index::new(k as u32 % 4)),
                byte_offset: (k % 2 == 0).then_some(USize64(4 * k as u64)),
                count: USize64(1000 + k as u64),
                component_type: Valid(GenericComponentType(component)),
                extensions: None,
                extras: None,
                type_: Valid(kind),
                min: None,
                max: None,
                name: (k == 4).then(|| "ünïcode \\ name".to_string()),
                normalized: k == 1,
                sparse: None,
            };
            if k == 0 {
                a.min = Some(serde_json::json!([-0.5, 1e-7, 3.0]));
                a.max = Some(serde_json::json!([0.1, 123456.789, 1e30]));
            }
            if k == 3 {
                a.extras = Some(json::extras::RawValue::from_string("{\"x\":1}".to_string()).expect("raw"));
            }
            root.push(a);
        }
        for (k, name) in ["plain", "quo\"ted", "tab\there", "ünï"].into_iter().enumerate() {
            let mut attributes = std::collections::BTreeMap::new();
            attributes.insert(Valid(json::mesh::Semantic::Colors(0)), Index::new(2));
            attributes.insert(Valid(json::mesh::Semantic::Positions), Index::new(0));
            attributes.insert(Valid(json::mesh::Semantic::Normals), Index::new(1));
            if k == 3 {
                attributes.insert(Valid(json::mesh::Semantic::TexCoords(1)), Index::new(4));
            }
            let mode = if k == 2 { json::mesh::Mode::Lines } else { json::mesh::Mode::Triangles };
            let primitive = json::mesh::Primitive { attributes, extensions: None, extras: None, indices: (k != 1).then(|| Index::new(3)), material: (k == 0).then(|| Index::new(0)), mode: Valid(mode), targets: None };
            let mesh = root.push(json::Mesh { extensions: None, extras: None, name: Some(name.to_string()), primitives: vec![primitive], weights: (k == 3).then(|| vec![0.25, 1.5]) });
            root.push(json::Node {
                mesh: Some(mesh),
                name: (k != 1).then(|| name.to_string()),
                translation: (k % 2 == 0).then_some([1.5, -2.25, 1e-9]),
                scale: (k == 2).then_some([0.1; 3]),
                rotation: (k == 3).then_some(json::scene::UnitQuaternion([0.0, 0.70710677, 0.0, 0.70710677])),
                children: (k == 1).then(|| vec![Index::new(0), Index::new(2)]),
                camera: (k == 2).then(|| Index::new(0)),
                matrix: None,
                ..Default::default()
            });
        }
        root.nodes[0].extras = Some(json::extras::RawValue::from_string("[1,2]".to_string()).expect("raw"));
        root.extensions_used.push("EXT_mesh_gpu_instancing".to_string());
        root.asset.generator = Some("rulemesh test".to_string());
        root
    }

    #[test]
    fn the_bytes_are_serde_jsons() {
        let root = mixed();
        assert_eq!(String::from_utf8(root_json(&root).unwrap()).unwrap(), String::from_utf8(root.to_vec().unwrap()).unwrap());
        let empty = json::Root::default();
        assert_eq!(root_json(&empty).unwrap(), empty.to_vec().unwrap());
        // An invalid enum is refused by both.
        let mut bad = mixed();
        bad.buffer_views[1].target = Some(json::validation::Checked::Invalid);
        assert!(root_json(&bad).is_err() && bad.to_vec().is_err());
        let mut bad = mixed();
        bad.accessors[0].type_ = json::validation::Checked::Invalid;
        assert!(root_json(&bad).is_err() && bad.to_vec().is_err());
    }
}
