//! `format=scene`: rulemesh's compact object-instancing format
//! (`docs/scene-format.md`), the seed 001 hierarchy written as it is, so its
//! size grows with the number of distinct subtrees, not with the segments.
//!
//! Little-endian throughout. A 24-byte header (magic `RMSC`, version, flags,
//! shape and object counts, expanded leaf count), then 28 bytes per leaf
//! shape, then the objects children first, each a `u32` entry count and 36
//! bytes per entry. [`decode_scene`] reads it back into a [`Hierarchy`]
//! (for tests and clients written in Rust).

use super::{ExportError, Provenance};
use crate::core::budget::Budget;
use crate::model::hierarchy::{Entry, Hierarchy, LeafShape, Object, Target};
use crate::core::PrimitiveKind;
use glam::{DQuat, DVec3};

/// The first four bytes of every scene file.
pub const MAGIC: &[u8; 4] = b"RMSC";
/// The format version this module writes and reads.
pub const VERSION: u16 = 1;
/// Header flag: the model was cut short by a limit.
pub const FLAG_TRUNCATED: u16 = 1;
/// Header flag: a provenance block follows the header (a `u32` byte length,
/// then that many bytes of UTF-8 JSON: engine, language, seed, parameters,
/// model key; see [`Provenance::json`]).
pub const FLAG_PROVENANCE: u16 = 2;
/// Bytes of the header.
pub const HEADER_BYTES: u64 = 24;
/// Bytes per leaf shape record.
pub const SHAPE_BYTES: u64 = 28;
/// Bytes per entry record.
pub const ENTRY_BYTES: u64 = 36;
/// Bit of an entry's reference that marks a leaf shape (else an object).
pub const SHAPE_BIT: u32 = 1 << 31;

/// Why bytes are not a scene file.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SceneError {
    /// The magic or the version is wrong.
    #[error("not a rulemesh scene (version {VERSION}) file")]
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
}

/// Exact encoded size of `h` with a provenance block of `provenance` bytes
/// (0 for none).
pub fn encoded_size(h: &Hierarchy, provenance: usize) -> u64 {
    let entries: u64 = h.entry_count();
    let block = if provenance > 0 { 4 + provenance as u64 } else { 0 };
    HEADER_BYTES + block + SHAPE_BYTES * h.shapes.len() as u64 + 4 * h.objects.len() as u64 + ENTRY_BYTES * entries
}

fn put_f32s(out: &mut Vec<u8>, v: &[f32]) {
    for x in v {
        out.extend_from_slice(&x.to_le_bytes());
    }
}

/// Writes `h` (with `provenance` after the header when given), reserving
/// its exact size in `budget` first.
pub fn write_scene(h: &Hierarchy, provenance: Option<&Provenance>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let block = provenance.map(|p| p.json().to_string()).unwrap_or_default();
    let size = encoded_size(h, block.len());
    let too_large = |what: &str| ExportError::TooLarge { format: "scene", detail: format!("more than 2³¹ {what}") };
    if h.shapes.len() as u64 >= u64::from(SHAPE_BIT) {
        return Err(too_large("shapes"));
    }
    if h.objects.len() as u64 >= u64::from(SHAPE_BIT) || h.objects.iter().any(|o| o.entries.len() as u64 > u64::from(u32::MAX)) {
        return Err(too_large("objects or entries"));
    }
    budget.reserve_memory(size)?;
    let mut out = Vec::with_capacity(size as usize);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    let flags = if h.truncated.is_some() { FLAG_TRUNCATED } else { 0 } | if block.is_empty() { 0 } else { FLAG_PROVENANCE };
    out.extend_from_slice(&flags.to_le_bytes());
    out.extend_from_slice(&(h.shapes.len() as u32).to_le_bytes());
    out.extend_from_slice(&(h.objects.len() as u32).to_le_bytes());
    out.extend_from_slice(&h.leaves().to_le_bytes());
    if !block.is_empty() {
        let len = u32::try_from(block.len()).map_err(|_| too_large("provenance bytes"))?;
        out.extend_from_slice(&len.to_le_bytes());
        out.extend_from_slice(block.as_bytes());
    }
    for s in &h.shapes {
        out.extend_from_slice(&[s.kind as u8, u8::from(s.tube), 0, 0]);
        put_f32s(&mut out, &s.scale);
        put_f32s(&mut out, &s.offset);
    }
    for o in &h.objects {
        // Fits: checked above.
        out.extend_from_slice(&(o.entries.len() as u32).to_le_bytes());
        for e in &o.entries {
            let r = match e.target {
                Target::Object(i) => i,
                Target::Shape(i) => i | SHAPE_BIT,
            };
            out.extend_from_slice(&r.to_le_bytes());
            put_f32s(&mut out, &e.translation.as_vec3().to_array());
            put_f32s(&mut out, &e.rotation.as_quat().normalize().to_array());
            out.extend_from_slice(&e.colour);
        }
    }
    debug_assert_eq!(out.len() as u64, size);
    Ok(out)
}

/// A cursor over the input that fails with [`SceneError::Length`] at the end.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self) -> Result<[u8; N], SceneError> {
        let end = self.at.checked_add(N).ok_or(SceneError::Length("truncated"))?;
        let s = self.bytes.get(self.at..end).ok_or(SceneError::Length("truncated"))?;
        self.at = end;
        let mut a = [0u8; N];
        a.copy_from_slice(s);
        Ok(a)
    }
    fn u32(&mut self) -> Result<u32, SceneError> {
        Ok(u32::from_le_bytes(self.take()?))
    }
    fn f32s<const N: usize>(&mut self) -> Result<[f32; N], SceneError> {
        let mut v = [0f32; N];
        for x in &mut v {
            *x = f32::from_le_bytes(self.take()?);
        }
        Ok(v)
    }
}

/// The header fields: flags, shape and object counts, and the provenance
/// block (a JSON object) when the flag says there is one.
fn read_header(r: &mut Reader<'_>) -> Result<(u16, u32, u32, Option<serde_json::Value>), SceneError> {
    if &r.take::<4>()? != MAGIC || u16::from_le_bytes(r.take()?) != VERSION {
        return Err(SceneError::NotScene);
    }
    let flags = u16::from_le_bytes(r.take()?);
    if flags & !(FLAG_TRUNCATED | FLAG_PROVENANCE) != 0 {
        return Err(SceneError::Header("unknown flag bits"));
    }
    let (nshapes, nobjects) = (r.u32()?, r.u32()?);
    let _leaves = u64::from_le_bytes(r.take()?);
    let provenance = if flags & FLAG_PROVENANCE != 0 {
        let len = r.u32()? as usize;
        let end = r.at.checked_add(len).ok_or(SceneError::Length("truncated"))?;
        let text = r.bytes.get(r.at..end).ok_or(SceneError::Length("truncated"))?;
        r.at = end;
        let text = std::str::from_utf8(text).map_err(|_| SceneError::Header("provenance is not UTF-8"))?;
        match serde_json::from_str::<serde_json::Value>(text) {
            Ok(v) if v.is_object() => Some(v),
            _ => return Err(SceneError::Header("provenance is not a JSON object")),
        }
    } else {
        None
    };
    Ok((flags, nshapes, nobjects, provenance))
}

/// The provenance a scene file carries (engine, language, seed, parameters,
/// model key), as JSON, without decoding the hierarchy.
pub fn scene_provenance(bytes: &[u8]) -> Result<Option<serde_json::Value>, SceneError> {
    Ok(read_header(&mut Reader { bytes, at: 0 })?.3)
}

/// Reads a scene file back into a hierarchy (leaf counts recomputed; the
/// truncation flag becomes a placeholder [`Hierarchy::truncated`] of the
/// memory limit, since the file does not say which limit it was).
pub fn decode_scene(bytes: &[u8]) -> Result<Hierarchy, SceneError> {
    let mut r = Reader { bytes, at: 0 };
    let (flags, nshapes, nobjects, _provenance) = read_header(&mut r)?;
    // Every record is at least 4 bytes, so counts beyond the length are malformed, not allocations to make.
    if (u64::from(nshapes) + u64::from(nobjects)).saturating_mul(4) > bytes.len() as u64 {
        return Err(SceneError::Length("truncated"));
    }
    let mut h = Hierarchy { shapes: Vec::with_capacity(nshapes as usize), objects: Vec::with_capacity(nobjects as usize), truncated: None };
    for _ in 0..nshapes {
        let [k, flags, _, _] = r.take::<4>()?;
        let kind = *PrimitiveKind::ALL.get(k as usize).ok_or(SceneError::Kind(k))?;
        let (scale, offset) = (r.f32s::<3>()?, r.f32s::<3>()?);
        h.shapes.push(LeafShape { kind, scale, offset, tube: flags & 1 != 0 });
    }
    for o in 0..nobjects {
        let n = r.u32()?;
        if u64::from(n).saturating_mul(ENTRY_BYTES) > (bytes.len() - r.at) as u64 {
            return Err(SceneError::Length("truncated"));
        }
        let mut obj = Object { entries: Vec::with_capacity(n as usize), leaves: 0 };
        for _ in 0..n {
            let raw = r.u32()?;
            let target = if raw & SHAPE_BIT != 0 { Target::Shape(raw & !SHAPE_BIT) } else { Target::Object(raw) };
            let (t, q) = (r.f32s::<3>()?, r.f32s::<4>()?);
            let colour = r.take::<4>()?;
            if t.iter().chain(&q).any(|v| !v.is_finite()) {
                return Err(SceneError::NonFinite(o));
            }
            let leaves = match target {
                Target::Shape(s) if s < nshapes => 1,
                Target::Object(c) if c < o => h.objects[c as usize].leaves,
                _ => return Err(SceneError::Reference { object: o, target: raw }),
            };
            obj.leaves = obj.leaves.saturating_add(leaves);
            let translation = DVec3::new(t[0].into(), t[1].into(), t[2].into());
            let rotation = DQuat::from_xyzw(q[0].into(), q[1].into(), q[2].into(), q[3].into());
            obj.entries.push(Entry { target, translation, rotation, colour });
        }
        h.objects.push(obj);
    }
    if r.at != bytes.len() {
        return Err(SceneError::Length("followed by trailing bytes"));
    }
    if flags & FLAG_TRUNCATED != 0 {
        h.truncated = Some(crate::core::LimitExceeded::recorded(crate::core::Limit::Memory));
    }
    Ok(h)
}
