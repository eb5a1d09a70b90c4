//! Reading a scene file's parts: the byte cursor, the header of either
//! version (with its provenance block) and the hierarchy section, and the
//! decoder's error. The layout is `docs/scene-format.md`'s; the constants
//! are the writer's (`crate::export::scene::format`).

use crate::core::PrimitiveKind;
use crate::export::scene::format::{
    CHECKSUM_BYTES, ENTRY_BYTES, ENTRY_BYTES_SCALED, ENTRY_BYTES_V1, FLAG_CHECKSUM, FLAG_PROVENANCE, FLAG_SCALED, FLAG_TRUNCATED, MAGIC, SHAPE_BIT, SHAPE_BYTES, VERSION,
    VERSION_1,
};
use crate::model::hierarchy::{Entry, Hierarchy, LeafShape, Object, Target};
use glam::{DQuat, DVec3};

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
    /// The header's `CHECKSUM` flag is set and the CRC-32 at the end does
    /// not match the bytes before it: a damaged byte (or a cut file).
    #[error("scene file is corrupted: CRC-32 is {computed:08x}, the file says {stored:08x}")]
    Checksum {
        /// The CRC-32 stored in the file's last four bytes.
        stored: u32,
        /// The CRC-32 of the bytes before them.
        computed: u32,
    },
}

/// A cursor over the input that fails with [`SceneError::Length`] at the end.
pub(crate) struct Reader<'a> {
    pub(crate) bytes: &'a [u8],
    pub(crate) at: usize,
}

impl<'a> Reader<'a> {
    pub(crate) fn take<const N: usize>(&mut self) -> Result<[u8; N], SceneError> {
        let s = self.slice(N)?;
        let mut a = [0u8; N];
        a.copy_from_slice(s);
        Ok(a)
    }
    pub(crate) fn slice(&mut self, n: usize) -> Result<&'a [u8], SceneError> {
        let end = self.at.checked_add(n).ok_or(SceneError::Length("truncated"))?;
        let s = self.bytes.get(self.at..end).ok_or(SceneError::Length("truncated"))?;
        self.at = end;
        Ok(s)
    }
    pub(crate) fn u8(&mut self) -> Result<u8, SceneError> {
        Ok(self.take::<1>()?[0])
    }
    pub(crate) fn u16(&mut self) -> Result<u16, SceneError> {
        Ok(u16::from_le_bytes(self.take()?))
    }
    pub(crate) fn u32(&mut self) -> Result<u32, SceneError> {
        Ok(u32::from_le_bytes(self.take()?))
    }
    pub(crate) fn f32s<const N: usize>(&mut self) -> Result<[f32; N], SceneError> {
        let mut v = [0f32; N];
        for x in &mut v {
            *x = f32::from_le_bytes(self.take()?);
        }
        Ok(v)
    }
    pub(crate) fn f64s<const N: usize>(&mut self) -> Result<[f64; N], SceneError> {
        let mut v = [0f64; N];
        for x in &mut v {
            *x = f64::from_le_bytes(self.take()?);
        }
        Ok(v)
    }
    /// Bytes left to read.
    pub(crate) fn left(&self) -> u64 {
        self.bytes.len().saturating_sub(self.at) as u64
    }
    /// Fails unless `count` records of at least `each` bytes can still follow,
    /// so a count is never an allocation the payload does not justify.
    pub(crate) fn room(&self, count: u64, each: u64) -> Result<(), SceneError> {
        if count.saturating_mul(each.max(1)) > self.left() {
            return Err(SceneError::Length("truncated"));
        }
        Ok(())
    }
}

/// A scene file's header, either version.
pub(crate) struct Header {
    /// 1 or 2.
    pub(crate) version: u16,
    /// Header flags.
    pub(crate) flags: u16,
    /// Tessellation detail (version 2; `None` in version 1, which does not say).
    pub(crate) detail: Option<u32>,
    /// Version 1: leaf shape and object counts. Version 2: palette and prototype counts.
    pub(crate) counts: (u32, u32),
    /// The provenance block, when the flag says there is one.
    pub(crate) provenance: Option<serde_json::Value>,
}

/// Reads the header (and the provenance block) of either version.
pub(crate) fn read_header(r: &mut Reader<'_>) -> Result<Header, SceneError> {
    if &r.take::<4>()? != MAGIC {
        return Err(SceneError::NotScene);
    }
    let version = r.u16()?;
    if version != VERSION_1 && version != VERSION {
        return Err(SceneError::NotScene);
    }
    let flags = r.u16()?;
    let known = FLAG_TRUNCATED | FLAG_PROVENANCE | if version == VERSION { FLAG_SCALED | FLAG_CHECKSUM } else { 0 };
    if flags & !known != 0 {
        return Err(SceneError::Header("unknown flag bits"));
    }
    if flags & FLAG_CHECKSUM != 0 {
        // Checked before anything else is read, so every damaged byte after
        // the flags is this error; the rest of the file is then read as if
        // it ended before the CRC (trailing bytes there are still refused).
        let body = r.bytes.len().checked_sub(CHECKSUM_BYTES).filter(|&n| n >= r.at).ok_or(SceneError::Length("truncated"))?;
        let (data, crc) = r.bytes.split_at(body);
        let stored = u32::from_le_bytes(crc.try_into().map_err(|_| SceneError::Length("truncated"))?);
        let computed = crc32fast::hash(data);
        if stored != computed {
            return Err(SceneError::Checksum { stored, computed });
        }
        r.bytes = data;
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

/// Reads `nshapes` leaf shapes and `nobjects` objects; `wide` entries (version
/// 2) hold f64 transforms, narrow ones (version 1) f32; `scaled` ones (the
/// header's [`FLAG_SCALED`]) also a positive f64 scale.
pub(crate) fn read_hierarchy(r: &mut Reader<'_>, nshapes: u32, nobjects: u32, wide: bool, scaled: bool) -> Result<Hierarchy, SceneError> {
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
pub(crate) fn truncation(flags: u16) -> Option<crate::core::LimitExceeded> {
    (flags & FLAG_TRUNCATED != 0).then(|| crate::core::LimitExceeded::recorded(crate::core::Limit::Memory))
}
