//! A glTF document's JSON: rulemesh's own document ([`tree`](super::tree))
//! written as compact JSON, byte for byte what serde_json wrote for the
//! same document built as gltf-json's `Root` (`Root::to_vec`).
//!
//! Why by hand: in a fresh icon render (issue 33's `gem.glb`: 25
//! accessors and 25 views in 5 KB of JSON) serialising the document was a
//! quarter of the whole render's CPU, mostly serde's per-field machinery
//! around short keys and `serde_json::Value` bounds. Keys, integers, fixed
//! words and names that need no escaping are written here as plain bytes;
//! each float goes through serde_json (so f32 and f64 print exactly as
//! serde_json prints them, non-finite as `null`), as does a string that
//! needs escaping.
//!
//! The field orders are gltf-json 1.4.1's (`Cargo.lock`) declaration
//! orders, each field skipped exactly when its `skip_serializing_if` says;
//! extension objects, which gltf-json held as `serde_json::Map`s, have
//! their keys sorted as that map sorts them. `json_oracle`'s tests build
//! the same documents as gltf-json trees and hold the bytes equal; a new
//! gltf-json must be read against them before it is taken.

use super::tree::{Accessor, Animation, Bounds, Buffer, Camera, Ix, Material, Mesh, Node, Root, Scene, View, EXT_INSTANCING, EXT_MESHOPT};
use crate::export::ExportError;
use serde_json::ser::{CompactFormatter, Formatter};

/// `,"name":`, the text that starts field `name` of an object, for
/// [`Out::key`] and the field writers (one copy of a constant, where
/// writing the comma, quotes and colon byte by byte was most of the cost
/// of a small number field).
macro_rules! k {
    ($name:literal) => {
        concat!(",\"", $name, "\":")
    };
}

/// `root` as compact JSON: the bytes of gltf-json's `Root::to_vec` for the
/// same document.
pub(super) fn root_json(root: &Root<'_>) -> Result<Vec<u8>, ExportError> {
    // About what one accessor, view, node or mesh takes, with room to spare
    // for the asset, the scene and the extras: one allocation, not the
    // doubling from 128 bytes that serde_json's `to_vec` starts with.
    let items = root.accessors.len() + root.views.len() + root.nodes.len() + root.meshes.len() + root.materials.len();
    let uri = root.buffers.iter().filter_map(|b| b.uri.as_ref()).map(String::len).sum::<usize>();
    let mut o = Out { bytes: Vec::with_capacity(1024 + 160 * items + uri), first: true };
    o.bytes.push(b'{');
    o.array_field(k!("accessors"), &root.accessors, accessor)?;
    o.array_field(k!("animations"), &root.animations, animation)?;
    o.key(k!("asset"));
    asset(&mut o, root)?;
    o.array_field(k!("buffers"), &root.buffers, buffer)?;
    o.array_field(k!("bufferViews"), &root.views, view)?;
    if let Some(s) = root.scene {
        o.number(k!("scene"), s);
    }
    o.array_field(k!("extensionsUsed"), &root.extensions, |o, e| o.string(e))?;
    o.array_field(k!("extensionsRequired"), &root.extensions, |o, e| o.string(e))?;
    o.array_field(k!("cameras"), &root.cameras, camera)?;
    o.array_field(k!("materials"), &root.materials, material)?;
    o.array_field(k!("meshes"), &root.meshes, mesh)?;
    o.array_field(k!("nodes"), &root.nodes, node)?;
    o.array_field(k!("scenes"), &root.scenes, scene)?;
    o.bytes.push(b'}');
    Ok(o.bytes)
}

/// The JSON being written, and whether the open object has a field yet.
struct Out {
    /// The JSON so far.
    bytes: Vec<u8>,
    /// Whether the open object has no field yet (its first needs no comma).
    first: bool,
}

impl Out {
    /// Starts a field of the open object: `key` is its `,"name":` (made
    /// by [`k!`]), written in one copy, the comma left out for the
    /// object's first field.
    #[inline]
    fn key(&mut self, key: &str) {
        let text = if self.first { key.strip_prefix(',').unwrap_or(key) } else { key };
        self.first = false;
        self.bytes.extend_from_slice(text.as_bytes());
    }

    /// Starts field `name` of the open object, for a name held in a
    /// constant (no key needs escaping).
    fn named_key(&mut self, name: &str) {
        if !self.first {
            self.bytes.push(b',');
        }
        self.first = false;
        self.bytes.push(b'"');
        self.bytes.extend_from_slice(name.as_bytes());
        self.bytes.extend_from_slice(b"\":");
    }

    /// A `true` field (a flag written only when set).
    fn true_field(&mut self, key: &str) {
        self.key(key);
        self.bytes.extend_from_slice(b"true");
    }

    /// The open object's `"extensions":{"NAME":{…}}` field, the one
    /// extension it carries, its object's fields written by `fields`.
    fn extension(&mut self, name: &str, fields: impl FnOnce(&mut Out)) {
        self.key(k!("extensions"));
        self.open();
        self.named_key(name);
        self.open();
        fields(self);
        self.close();
        self.close();
    }

    /// Opens an object.
    #[inline]
    fn open(&mut self) {
        self.bytes.push(b'{');
        self.first = true;
    }

    /// Closes the open object (a field of an enclosing object follows with a comma).
    #[inline]
    fn close(&mut self) {
        self.bytes.push(b'}');
        self.first = false;
    }

    /// A field skipped when empty (`skip_serializing_if = "Vec::is_empty"`),
    /// its elements written by `write`.
    fn array_field<T>(&mut self, name: &str, items: &[T], write: fn(&mut Out, &T) -> Result<(), ExportError>) -> Result<(), ExportError> {
        if items.is_empty() {
            return Ok(());
        }
        self.key(name);
        self.array(items, write)
    }

    /// An array whose elements `write` writes.
    fn array<T>(&mut self, items: &[T], write: fn(&mut Out, &T) -> Result<(), ExportError>) -> Result<(), ExportError> {
        self.bytes.push(b'[');
        for (k, item) in items.iter().enumerate() {
            if k > 0 {
                self.bytes.push(b',');
            }
            write(self, item)?;
        }
        self.bytes.push(b']');
        self.first = false;
        Ok(())
    }

    /// An array of indices.
    fn indices(&mut self, items: &[Ix]) {
        self.bytes.push(b'[');
        for (k, &i) in items.iter().enumerate() {
            if k > 0 {
                self.bytes.push(b',');
            }
            self.integer(u64::from(i));
        }
        self.bytes.push(b']');
    }

    /// A number field.
    #[inline]
    fn number(&mut self, name: &str, value: impl Into<u64>) {
        self.key(name);
        self.integer(value.into());
    }

    /// A bare integer.
    #[inline]
    fn integer(&mut self, value: u64) {
        self.bytes.extend_from_slice(itoa::Buffer::new().format(value).as_bytes());
    }

    /// A float as serde_json writes an `f32` (gltf-json's transform and
    /// material fields): its own formatter's text for a finite value,
    /// `null` for any other, as its `serialize_f32` does, without a
    /// serializer around it.
    fn f32(&mut self, value: f32) -> Result<(), ExportError> {
        match value.is_finite() {
            true => CompactFormatter.write_f32(&mut self.bytes, value).map_err(serde_json::Error::io)?,
            false => self.bytes.extend_from_slice(b"null"),
        }
        Ok(())
    }

    /// A float as serde_json writes an `f64` (gltf-json's bounds and
    /// rulemesh's extras, made as `Value`s from `f64::from(f32)`), as
    /// [`Out::f32`] does.
    fn f64(&mut self, value: f64) -> Result<(), ExportError> {
        match value.is_finite() {
            true => CompactFormatter.write_f64(&mut self.bytes, value).map_err(serde_json::Error::io)?,
            false => self.bytes.extend_from_slice(b"null"),
        }
        Ok(())
    }

    /// An array of `f32`s.
    fn f32s(&mut self, values: &[f32]) -> Result<(), ExportError> {
        self.floats(values, Out::f32)
    }

    /// An array of `f32`s each written as its `f64`.
    fn f64s(&mut self, values: &[f32]) -> Result<(), ExportError> {
        self.floats(values, |o, v| o.f64(f64::from(v)))
    }

    /// An array of `values`, each written by `write`.
    fn floats(&mut self, values: &[f32], write: fn(&mut Out, f32) -> Result<(), ExportError>) -> Result<(), ExportError> {
        self.bytes.push(b'[');
        for (k, &v) in values.iter().enumerate() {
            if k > 0 {
                self.bytes.push(b',');
            }
            write(self, v)?;
        }
        self.bytes.push(b']');
        Ok(())
    }

    /// An optional `f32` array field.
    fn f32s_field(&mut self, name: &str, values: Option<&[f32]>) -> Result<(), ExportError> {
        match values {
            Some(v) => {
                self.key(name);
                self.f32s(v)
            }
            None => Ok(()),
        }
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

    /// A string field.
    fn string_field(&mut self, name: &str, value: &str) -> Result<(), ExportError> {
        self.key(name);
        self.string(value)
    }

    /// A fixed word, which needs no escaping, as a string.
    #[inline]
    fn word_field(&mut self, name: &str, word: &str) {
        self.key(name);
        self.bytes.push(b'"');
        self.bytes.extend_from_slice(word.as_bytes());
        self.bytes.push(b'"');
    }

    /// An index field skipped when `None`.
    #[inline]
    fn index_field(&mut self, name: &str, value: Option<Ix>) {
        if let Some(i) = value {
            self.number(name, i);
        }
    }
}

/// `asset`: the provenance in `extras`, the generator and the version
/// (gltf-json's `Asset`: copyright, extensions, extras, generator,
/// minVersion, version).
fn asset(o: &mut Out, root: &Root<'_>) -> Result<(), ExportError> {
    o.open();
    if let Some(p) = &root.provenance {
        o.key(k!("extras"));
        o.bytes.extend_from_slice(p.get().as_bytes());
    }
    o.key(k!("generator"));
    // The version is a crate version (digits, dots, letters): no escaping,
    // so no `format!`; serde writes it should that ever change.
    let version = crate::ENGINE_VERSION;
    if version.bytes().all(|b| b >= 0x20 && b != b'"' && b != b'\\') {
        o.bytes.extend_from_slice(b"\"rulemesh ");
        o.bytes.extend_from_slice(version.as_bytes());
        o.bytes.push(b'"');
    } else {
        o.string(&format!("rulemesh {version}"))?;
    }
    o.word_field(k!("version"), "2.0");
    o.close();
    Ok(())
}

/// One accessor (gltf-json's `Accessor`: bufferView, byteOffset, count,
/// componentType, extensions, extras, type, min, max, name, normalized,
/// sparse).
fn accessor(o: &mut Out, a: &Accessor) -> Result<(), ExportError> {
    o.open();
    o.number(k!("bufferView"), a.view);
    if let Some(off) = a.byte_offset {
        o.number(k!("byteOffset"), off);
    }
    o.number(k!("count"), a.count);
    o.number(k!("componentType"), a.component.gl());
    o.word_field(k!("type"), a.kind.word());
    match a.bounds {
        Some(Bounds::Float(min, max)) => {
            o.key(k!("min"));
            o.f64s(&min)?;
            o.key(k!("max"));
            o.f64s(&max)?;
        }
        Some(Bounds::Grid(min, max)) => {
            for (name, v) in [(k!("min"), min), (k!("max"), max)] {
                o.key(name);
                o.bytes.push(b'[');
                for (k, c) in v.into_iter().enumerate() {
                    if k > 0 {
                        o.bytes.push(b',');
                    }
                    o.integer(u64::from(c));
                }
                o.bytes.push(b']');
            }
        }
        Some(Bounds::Times(end)) => {
            o.key(k!("min"));
            o.f64s(&[0.0])?;
            o.key(k!("max"));
            o.f64s(&[end])?;
        }
        None => {}
    }
    if a.normalized {
        o.true_field(k!("normalized"));
    }
    o.close();
    Ok(())
}

/// The `"rulemesh"` animation (gltf-json's `Animation`: extensions, extras,
/// channels, name, samplers; `Channel`: sampler, target; `Target`: node,
/// path; `Sampler`: input, interpolation, output).
fn animation(o: &mut Out, a: &Animation) -> Result<(), ExportError> {
    o.open();
    o.array_field(k!("channels"), &a.channels, |o, c| {
        o.open();
        o.number(k!("sampler"), c.sampler);
        o.key(k!("target"));
        o.open();
        o.number(k!("node"), c.node);
        o.word_field(k!("path"), c.path.word());
        o.close();
        o.close();
        Ok(())
    })?;
    o.word_field(k!("name"), "rulemesh");
    o.array_field(k!("samplers"), &a.samplers, |o, s| {
        o.open();
        o.number(k!("input"), s.input);
        o.word_field(k!("interpolation"), if s.step { "STEP" } else { "LINEAR" });
        o.number(k!("output"), s.output);
        o.close();
        Ok(())
    })?;
    o.close();
    Ok(())
}

/// One buffer (gltf-json's `Buffer`: byteLength, name, uri, extensions, extras).
fn buffer(o: &mut Out, b: &Buffer) -> Result<(), ExportError> {
    o.open();
    o.number(k!("byteLength"), b.byte_length);
    if let Some(uri) = &b.uri {
        o.string_field(k!("uri"), uri)?;
    }
    if b.meshopt_fallback {
        o.extension(EXT_MESHOPT, |o| o.true_field(k!("fallback")));
    }
    o.close();
    Ok(())
}

/// One buffer view (gltf-json's `View`: buffer, byteLength, byteOffset,
/// byteStride, name, target, extensions, extras; the meshopt extension's
/// keys sorted, as its `Map` held them).
fn view(o: &mut Out, v: &View) -> Result<(), ExportError> {
    o.open();
    o.number(k!("buffer"), v.buffer);
    o.number(k!("byteLength"), v.byte_length);
    o.number(k!("byteOffset"), v.byte_offset);
    if let Some(s) = v.byte_stride {
        o.number(k!("byteStride"), s);
    }
    if let Some(name) = v.name {
        o.string_field(k!("name"), name)?;
    }
    if let Some(t) = v.target {
        o.number(k!("target"), t.gl());
    }
    if let Some(m) = &v.meshopt {
        o.extension(EXT_MESHOPT, |o| {
            o.number(k!("buffer"), m.buffer);
            o.number(k!("byteLength"), m.byte_length);
            o.number(k!("byteOffset"), m.byte_offset);
            o.number(k!("byteStride"), m.byte_stride);
            o.number(k!("count"), m.count);
            o.word_field(k!("mode"), m.mode);
        });
    }
    o.close();
    Ok(())
}

/// One perspective camera (gltf-json's `Camera`: name, orthographic,
/// perspective, type; `Perspective`: aspectRatio, yfov, zfar, znear).
fn camera(o: &mut Out, c: &Camera<'_>) -> Result<(), ExportError> {
    o.open();
    if let Some(name) = c.name {
        o.string_field(k!("name"), name)?;
    }
    o.key(k!("perspective"));
    o.open();
    o.key(k!("yfov"));
    o.f32(c.yfov)?;
    if let Some(zfar) = c.zfar {
        o.key(k!("zfar"));
        o.f32(zfar)?;
    }
    o.key(k!("znear"));
    o.f32(c.znear)?;
    o.close();
    o.word_field(k!("type"), "perspective");
    o.close();
    Ok(())
}

/// The one material, white, metallic 0, roughness 0.8 (gltf-json's
/// `Material`: alphaCutoff, alphaMode, doubleSided, name,
/// pbrMetallicRoughness, the textures, emissiveFactor; the factors are
/// `f32`s and print as here).
fn material(o: &mut Out, m: &Material<'_>) -> Result<(), ExportError> {
    o.bytes.extend_from_slice(b"{\"alphaMode\":\"OPAQUE\",\"doubleSided\":false");
    o.first = false;
    if let Some(name) = m.name {
        o.string_field(k!("name"), name)?;
    }
    o.bytes.extend_from_slice(b",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1.0,1.0,1.0,1.0],\"metallicFactor\":0.0,\"roughnessFactor\":0.8},\"emissiveFactor\":[0.0,0.0,0.0]}");
    Ok(())
}

/// One mesh of one TRIANGLES primitive (gltf-json's `Mesh`: extensions,
/// extras, name, primitives, weights; `Primitive`: attributes in its
/// `BTreeMap`'s order, extensions, extras, indices, material, mode when not
/// TRIANGLES, targets).
fn mesh(o: &mut Out, m: &Mesh<'_>) -> Result<(), ExportError> {
    o.open();
    o.string_field(k!("name"), m.name)?;
    o.key(k!("primitives"));
    o.bytes.extend_from_slice(b"[{\"attributes\":{\"POSITION\":");
    o.integer(u64::from(m.position));
    o.bytes.extend_from_slice(b",\"NORMAL\":");
    o.integer(u64::from(m.normal));
    o.bytes.extend_from_slice(b",\"COLOR_0\":");
    o.integer(u64::from(m.colour));
    o.bytes.extend_from_slice(b"},\"indices\":");
    o.integer(u64::from(m.indices));
    o.bytes.extend_from_slice(b",\"material\":");
    o.integer(u64::from(m.material));
    o.bytes.extend_from_slice(b"}]");
    o.close();
    Ok(())
}

/// One node (gltf-json's `Node`: camera, children, extensions, extras,
/// matrix, mesh, name, rotation, scale, translation, skin, weights; the
/// instancing extension's attributes sorted, as its `Map` held them).
fn node(o: &mut Out, n: &Node<'_>) -> Result<(), ExportError> {
    o.open();
    o.index_field(k!("camera"), n.camera);
    if !n.children.is_empty() {
        o.key(k!("children"));
        o.indices(&n.children);
    }
    if let Some(i) = &n.instancing {
        o.extension(EXT_INSTANCING, |o| {
            o.key(k!("attributes"));
            o.open();
            o.index_field(k!("ROTATION"), i.rotation);
            o.index_field(k!("SCALE"), i.scale);
            o.number(k!("TRANSLATION"), i.translation);
            o.index_field(k!("_COLOR_0"), i.colour);
            o.close();
        });
    }
    o.index_field(k!("mesh"), n.mesh);
    o.string_field(k!("name"), n.name)?;
    o.f32s_field(k!("rotation"), n.rotation.as_ref().map(|r| &r[..]))?;
    o.f32s_field(k!("scale"), n.scale.as_ref().map(|s| &s[..]))?;
    o.f32s_field(k!("translation"), n.translation.as_ref().map(|t| &t[..]))?;
    o.close();
    Ok(())
}

/// The scene (gltf-json's `Scene`: extensions, extras, name, nodes; the
/// extras' keys sorted, as the `BTreeMap` they were made from held them).
fn scene(o: &mut Out, s: &Scene) -> Result<(), ExportError> {
    o.open();
    if s.background.is_some() || s.truncated {
        o.key(k!("extras"));
        o.open();
        if let Some(bg) = &s.background {
            o.key(k!("background"));
            o.f64s(bg)?;
        }
        if s.truncated {
            o.true_field(k!("truncated"));
        }
        o.close();
    }
    if !s.nodes.is_empty() {
        o.key(k!("nodes"));
        o.indices(&s.nodes);
    }
    o.close();
    Ok(())
}
