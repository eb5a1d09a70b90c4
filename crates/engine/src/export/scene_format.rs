//! What the scene format's writer and reader share (`docs/scene-format.md`):
//! the constants, the errors, the byte reader, the header of either version
//! and the hierarchy section. Version 1 (an L-system hierarchy alone,
//! entries in f32) is still read.

use crate::core::PrimitiveKind;
use crate::model::hierarchy::{Entry, Hierarchy, LeafShape, Object, Target};
use glam::{DQuat, DVec3};

/// The first four bytes of every scene file.
pub const MAGIC: &[u8; 4] = b"RMSC";
/// The format version this module writes.
pub const VERSION: u16 = 2;
/// The first version (an L-system hierarchy alone), still read.
pub const VERSION_1: u16 = 1;
/// Header flag: the model was cut short by a limit.
pub const FLAG_TRUNCATED: u16 = 1;
/// Header flag: a provenance block follows the header (a `u32` byte length,
/// then that many bytes of UTF-8 JSON: engine, language, seed, parameters,
/// model key; see [`Provenance::json`](super::Provenance::json)).
pub const FLAG_PROVENANCE: u16 = 2;
/// Header flag (version 2): every hierarchy entry carries a uniform scale
/// (an `f64` after its rotation, [`ENTRY_BYTES_SCALED`] bytes an entry), as
/// MDG hierarchies need; set only when some entry's scale is not 1, so a
/// rigid (L-system) hierarchy is written exactly as before the flag existed.
pub const FLAG_SCALED: u16 = 4;
/// Bytes of the version 1 header.
pub const HEADER_BYTES_V1: usize = 24;
/// Bytes of the version 2 header.
pub const HEADER_BYTES: usize = 20;
/// Bytes per leaf shape record (both versions).
pub const SHAPE_BYTES: u64 = 28;
/// Bytes per hierarchy entry in version 1 (f32 transform).
pub const ENTRY_BYTES_V1: u64 = 36;
/// Bytes per hierarchy entry in version 2 (f64 transform, so a reader walks
/// the very numbers the server walked).
pub const ENTRY_BYTES: u64 = 64;
/// Bytes per hierarchy entry in version 2 under [`FLAG_SCALED`].
pub const ENTRY_BYTES_SCALED: u64 = 72;
/// Bit of an entry's reference that marks a leaf shape (else an object).
pub const SHAPE_BIT: u32 = 1 << 31;

/// Why bytes are not a scene file.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SceneError {
    /// The magic or the version is wrong.
    #[error("not a rulemesh scene (version 1 or {VERSION}) file")]
    NotScene,
    /// The data ends early or has trailing bytes.
    #[error("scene file is {0}")]
    Length(&'static str),
    /// A primitive kind code is out of range.
    #[error("unknown primitive kind {0}")]
    Kind(u8),
    /// An entry refers to a shape that does not exist or an object that is not earlier.
    #[error("object {object} refers to {target:?}, which is not an earlier object or a known shape")]
    Reference {
        /// The referring object.
        object: u32,
        /// The raw reference.
        target: u32,
    },
    /// A value is not finite.
    #[error("non-finite number in object {0}")]
    NonFinite(u32),
    /// The provenance block is not UTF-8 JSON, or a flag bit is unknown.
    #[error("scene header is malformed: {0}")]
    Header(&'static str),
    /// A mesh, run or record of a version 2 file is malformed.
    #[error("scene mesh {mesh} is malformed: {detail}")]
    Record {
        /// Index of the mesh in the file.
        mesh: u32,
        /// What is wrong.
        detail: &'static str,
    },
    /// Decoding would make more triangles than the caller allows.
    #[error("scene expands to {0} triangles, more than allowed")]
    TooLarge(u64),
}

/// A cursor over the input that fails with [`SceneError::Length`] at the end.
pub(super) struct Reader<'a> {
    pub(super) bytes: &'a [u8],
    pub(super) at: usize,
}

impl<'a> Reader<'a> {
    pub(super) fn take<const N: usize>(&mut self) -> Result<[u8; N], SceneError> {
        let s = self.slice(N)?;
        let mut a = [0u8; N];
        a.copy_from_slice(s);
        Ok(a)
    }
    pub(super) fn slice(&mut self, n: usize) -> Result<&'a [u8], SceneError> {
        let end = self.at.checked_add(n).ok_or(SceneError::Length("truncated"))?;
        let s = self.bytes.get(self.at..end).ok_or(SceneError::Length("truncated"))?;
        self.at = end;
        Ok(s)
    }
    pub(super) fn u8(&mut self) -> Result<u8, SceneError> {
        Ok(self.take::<1>()?[0])
    }
    pub(super) fn u16(&mut self) -> Result<u16, SceneError> {
        Ok(u16::from_le_bytes(self.take()?))
    }
    pub(super) fn u32(&mut self) -> Result<u32, SceneError> {
        Ok(u32::from_le_bytes(self.take()?))
    }
    pub(super) fn f32s<const N: usize>(&mut self) -> Result<[f32; N], SceneError> {
        let mut v = [0f32; N];
        for x in &mut v {
            *x = f32::from_le_bytes(self.take()?);
        }
        Ok(v)
    }
    pub(super) fn f64s<const N: usize>(&mut self) -> Result<[f64; N], SceneError> {
        let mut v = [0f64; N];
        for x in &mut v {
            *x = f64::from_le_bytes(self.take()?);
        }
        Ok(v)
    }
    /// Bytes left to read.
    pub(super) fn left(&self) -> u64 {
        self.bytes.len().saturating_sub(self.at) as u64
    }
    /// Fails unless `count` records of at least `each` bytes can still follow,
    /// so a count is never an allocation the payload does not justify.
    pub(super) fn room(&self, count: u64, each: u64) -> Result<(), SceneError> {
        if count.saturating_mul(each.max(1)) > self.left() {
            return Err(SceneError::Length("truncated"));
        }
        Ok(())
    }
}

/// A scene file's header, either version.
pub(super) struct Header {
    /// 1 or 2.
    pub(super) version: u16,
    /// Header flags.
    pub(super) flags: u16,
    /// Tessellation detail (version 2; `None` in version 1, which does not say).
    pub(super) detail: Option<u32>,
    /// Version 1: leaf shape and object counts. Version 2: palette and prototype counts.
    pub(super) counts: (u32, u32),
    /// The provenance block, when the flag says there is one.
    pub(super) provenance: Option<serde_json::Value>,
}

/// Reads the header (and the provenance block) of either version.
pub(super) fn read_header(r: &mut Reader<'_>) -> Result<Header, SceneError> {
    if &r.take::<4>()? != MAGIC {
        return Err(SceneError::NotScene);
    }
    let version = r.u16()?;
    if version != VERSION_1 && version != VERSION {
        return Err(SceneError::NotScene);
    }
    let flags = r.u16()?;
    let known = FLAG_TRUNCATED | FLAG_PROVENANCE | if version == VERSION { FLAG_SCALED } else { 0 };
    if flags & !known != 0 {
        return Err(SceneError::Header("unknown flag bits"));
    }
    let (detail, counts) = if version == VERSION_1 {
        let counts = (r.u32()?, r.u32()?);
        let _leaves = u64::from_le_bytes(r.take()?);
        (None, counts)
    } else {
        let detail = u32::from(r.u16()?);
        if !(crate::geom::MIN_DETAIL..=crate::geom::MAX_DETAIL).contains(&detail) {
            return Err(SceneError::Header("detail out of range"));
        }
        if r.u16()? != 0 {
            return Err(SceneError::Header("reserved bytes are not zero"));
        }
        (Some(detail), (r.u32()?, r.u32()?))
    };
    let provenance = if flags & FLAG_PROVENANCE != 0 {
        let len = r.u32()? as usize;
        let text = r.slice(len)?;
        let text = std::str::from_utf8(text).map_err(|_| SceneError::Header("provenance is not UTF-8"))?;
        match serde_json::from_str::<serde_json::Value>(text) {
            Ok(v) if v.is_object() => Some(v),
            _ => return Err(SceneError::Header("provenance is not a JSON object")),
        }
    } else {
        None
    };
    Ok(Header { version, flags, detail, counts, provenance })
}

/// The provenance a scene file carries (engine, language, seed, parameters,
/// model key), as JSON, without decoding the rest.
pub fn scene_provenance(bytes: &[u8]) -> Result<Option<serde_json::Value>, SceneError> {
    Ok(read_header(&mut Reader { bytes, at: 0 })?.provenance)
}

/// Writes the hierarchy section's body (leaf shapes, then objects with f64
/// entries, each with its scale when `scaled`, which the header's
/// [`FLAG_SCALED`] says); the caller writes the two counts first.
pub(super) fn put_hierarchy(out: &mut Vec<u8>, h: &Hierarchy, scaled: bool) {
    for s in &h.shapes {
        out.extend_from_slice(&[s.kind as u8, u8::from(s.tube), 0, 0]);
        for x in s.scale.iter().chain(&s.offset) {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    for o in &h.objects {
        // Fits: the writer checked every count against 2³¹.
        out.extend_from_slice(&(o.entries.len() as u32).to_le_bytes());
        for e in &o.entries {
            let r = match e.target {
                Target::Object(i) => i,
                Target::Shape(i) => i | SHAPE_BIT,
            };
            out.extend_from_slice(&r.to_le_bytes());
            for x in e.translation.to_array().iter().chain(&e.rotation.to_array()) {
                out.extend_from_slice(&x.to_le_bytes());
            }
            if scaled {
                out.extend_from_slice(&e.scale.to_le_bytes());
            }
            out.extend_from_slice(&e.colour);
        }
    }
}

/// Reads `nshapes` leaf shapes and `nobjects` objects; `wide` entries (version
/// 2) hold f64 transforms, narrow ones (version 1) f32; `scaled` ones (the
/// header's [`FLAG_SCALED`]) also a positive f64 scale.
pub(super) fn read_hierarchy(r: &mut Reader<'_>, nshapes: u32, nobjects: u32, wide: bool, scaled: bool) -> Result<Hierarchy, SceneError> {
    r.room(u64::from(nshapes), SHAPE_BYTES)?;
    r.room(u64::from(nobjects), 4)?;
    let mut h = Hierarchy { shapes: Vec::with_capacity(nshapes as usize), objects: Vec::with_capacity(nobjects as usize), truncated: None };
    for _ in 0..nshapes {
        let [k, flags, _, _] = r.take::<4>()?;
        let kind = *PrimitiveKind::ALL.get(k as usize).ok_or(SceneError::Kind(k))?;
        let (scale, offset) = (r.f32s::<3>()?, r.f32s::<3>()?);
        if scale.iter().chain(&offset).any(|v| !v.is_finite()) {
            return Err(SceneError::Header("non-finite leaf shape"));
        }
        h.shapes.push(LeafShape { kind, scale, offset, tube: flags & 1 != 0 });
    }
    let entry_bytes = match (wide, scaled) {
        (false, _) => ENTRY_BYTES_V1,
        (true, false) => ENTRY_BYTES,
        (true, true) => ENTRY_BYTES_SCALED,
    };
    for o in 0..nobjects {
        let n = r.u32()?;
        r.room(u64::from(n), entry_bytes)?;
        let mut obj = Object { entries: Vec::with_capacity(n as usize), leaves: 0 };
        for _ in 0..n {
            let raw = r.u32()?;
            let target = if raw & SHAPE_BIT != 0 { Target::Shape(raw & !SHAPE_BIT) } else { Target::Object(raw) };
            let (t, q) = if wide {
                (r.f64s::<3>()?, r.f64s::<4>()?)
            } else {
                (r.f32s::<3>()?.map(f64::from), r.f32s::<4>()?.map(f64::from))
            };
            let scale = if scaled { r.f64s::<1>()?[0] } else { 1.0 };
            let colour = r.take::<4>()?;
            if t.iter().chain(&q).any(|v| !v.is_finite()) || !(scale.is_finite() && scale > 0.0) {
                return Err(SceneError::NonFinite(o));
            }
            let leaves = match target {
                Target::Shape(s) if s < nshapes => 1,
                Target::Object(c) if c < o => h.objects[c as usize].leaves,
                _ => return Err(SceneError::Reference { object: o, target: raw }),
            };
            obj.leaves = obj.leaves.saturating_add(leaves);
            obj.entries.push(Entry { target, translation: DVec3::from_array(t), rotation: DQuat::from_array(q), scale, colour });
        }
        h.objects.push(obj);
    }
    Ok(h)
}

/// The truncation placeholder a decoded file carries: the file says a limit
/// cut the model short, not which, so the memory limit stands for it.
pub(super) fn truncation(flags: u16) -> Option<crate::core::LimitExceeded> {
    (flags & FLAG_TRUNCATED != 0).then(|| crate::core::LimitExceeded::recorded(crate::core::Limit::Memory))
}
