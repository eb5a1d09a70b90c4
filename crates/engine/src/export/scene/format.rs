//! The scene format's layout (`docs/scene-format.md`): the constants the
//! writer writes and the reader (`crate::decode::scene`) checks, and the
//! hierarchy section's writer. Version 1 (an L-system hierarchy alone,
//! entries in f32) is still read, never written.

use crate::model::hierarchy::{Hierarchy, Target};

/// The first four bytes of every scene file.
pub const MAGIC: &[u8; 4] = b"RMSC";
/// The format version this module writes.
pub(crate) const VERSION: u16 = 2;
/// The first version (an L-system hierarchy alone), still read.
pub(crate) const VERSION_1: u16 = 1;
/// Header flag: the model was cut short by a limit.
pub const FLAG_TRUNCATED: u16 = 1;
/// Header flag: a provenance block follows the header (a `u32` byte length,
/// then that many bytes of UTF-8 JSON: engine, language, seed, parameters,
/// model key; see [`Provenance::json`](crate::export::Provenance::json)).
pub const FLAG_PROVENANCE: u16 = 2;
/// Header flag (version 2): every hierarchy entry carries a uniform scale
/// (an `f64` after its rotation, [`ENTRY_BYTES_SCALED`] bytes an entry), as
/// MDG hierarchies need; set only when some entry's scale is not 1, so a
/// rigid (L-system) hierarchy is written exactly as before the flag existed.
pub const FLAG_SCALED: u16 = 4;
/// Header flag (version 2): the file ends with [`CHECKSUM_BYTES`] bytes, a
/// little-endian CRC-32 (IEEE 802.3's polynomial, reflected `0xEDB88320`,
/// as zlib, PNG and the `strips` format compute it) of every byte before
/// them. Written only when a request asks for it (`checksum: true`), so
/// every other file, its golden row and every deployed decoder stay as they
/// were; a decoder from before the flag refuses such a file (an unknown
/// flag bit) rather than misread it.
pub const FLAG_CHECKSUM: u16 = 8;
/// Bytes of the CRC-32 after the last mesh under [`FLAG_CHECKSUM`].
pub const CHECKSUM_BYTES: usize = 4;
/// Bytes of the version 2 header (version 1's was 24: docs/scene-format.md).
pub(crate) const HEADER_BYTES: usize = 20;
/// Bytes per leaf shape record (both versions).
pub const SHAPE_BYTES: u64 = 28;
/// Bytes per hierarchy entry in version 1 (f32 transform).
pub(crate) const ENTRY_BYTES_V1: u64 = 36;
/// Bytes per hierarchy entry in version 2 (f64 transform, so a reader walks
/// the very numbers the server walked).
pub const ENTRY_BYTES: u64 = 64;
/// Bytes per hierarchy entry in version 2 under [`FLAG_SCALED`].
pub(crate) const ENTRY_BYTES_SCALED: u64 = 72;
/// Bit of an entry's reference that marks a leaf shape (else an object).
pub const SHAPE_BIT: u32 = 1 << 31;

/// Run type: primitive instances placed by similarities.
pub const RUN_PRIMITIVES: u8 = 1;
/// Run type: primitive instances placed by general affine maps.
pub const RUN_AFFINE: u8 = 2;
/// Run type: placements of the file's prototype meshes.
pub const RUN_PLACED: u8 = 3;
/// Run type: meshes written out (swept lines, free triangles).
pub const RUN_MESH: u8 = 4;
/// Run type: the file's hierarchy, expanded here.
pub const RUN_HIERARCHY: u8 = 5;
/// Bit of a primitive record's kind byte that marks a mirrored placement.
pub const PARITY_BIT: u8 = 0x80;
/// Bytes of a colour index for a palette of `n` colours.
pub(crate) fn index_width(n: usize) -> usize {
    match n {
        0..=256 => 1,
        257..=65_536 => 2,
        _ => 4,
    }
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

