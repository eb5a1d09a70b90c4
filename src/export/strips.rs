//! The `strips` format (`application/vnd.rulemesh.strips`): one quantised,
//! stripified, compressed mesh for phone clients that fetch icons over slow
//! links and decode them on small CPUs. `docs/strips-format.md` specifies it
//! byte by byte; this module is the reference encoder and decoder, and
//! `clients/js/strips.mjs` the JavaScript decoder.
//!
//! Encoding: merge all meshes → quantise each vertex to 16 bytes (positions
//! relative to the bounding box, octahedral normals, colour or palette index)
//! → weld identical quantised vertices → optimise for the vertex cache and
//! stripify ([`crate::geom::strip`]) → meshoptimizer's vertex codec for the
//! vertices and its index buffer codec for the strip's triangles, in strip
//! order (the decoder rebuilds the strip from them with
//! [`strip::restrip`]) → optional zstd → header and CRC32.

use super::ExportError;
use crate::core::budget::Budget;
use crate::geom::strip::{self, RESTART};
use crate::geom::{Mesh, NamedMesh};
use std::collections::BTreeMap;
use std::io::Read;

/// The four bytes every strips file starts with.
pub const MAGIC: [u8; 4] = *b"RMST";
/// The format version this encoder writes and the decoder reads.
/// Version 2 stores the strip as its triangles (index buffer codec) where
/// version 1 stored the strip indices (index sequence codec); the decoders
/// read version 2 only.
pub const VERSION: u8 = 2;
/// Bytes before the body: magic, version, flags, bits, bounding box, counts, lengths.
pub const HEADER_LEN: usize = 52;
/// Bytes after the body: the CRC32.
pub const TRAILER_LEN: usize = 4;
/// Bytes of one quantised vertex in the vertex stream.
pub const VERTEX_BYTES: usize = 16;
/// Flag bit: the body is one zstd frame.
pub const FLAG_ZSTD: u8 = 1;
/// Flag bit: colours are indices into the palette.
pub const FLAG_PALETTE: u8 = 2;
/// Most palette entries (one byte per index).
pub const MAX_PALETTE: usize = 256;
/// The decoder refuses a zstd body that claims to expand more than this
/// many times (plus 64 KiB): our bodies are already compressed, so a larger
/// claim can only be a hostile file asking for a huge allocation.
pub const MAX_ZSTD_RATIO: u64 = 64;
/// A block of up to 256 vertices costs at least 4 control bytes in the
/// vertex codec (version 1), so a stream of `n` bytes cannot hold more than
/// `64·n` vertices (plus one block); the decoder refuses larger counts
/// before allocating.
pub const MAX_VERTICES_PER_STREAM_BYTE: u64 = 64;
/// The index buffer codec spends at least one code byte per triangle, after a
/// 1-byte header and before a 16-byte table, so `n` bytes cannot hold more
/// than `n − 17` triangles; the decoder refuses larger counts before allocating.
pub const INDEX_STREAM_OVERHEAD: u64 = 17;

/// Precision choices for the `strips` format (request options). Every other
/// format ignores them; they reach only the exporter, never the parser or
/// the evaluator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct StripsOptions {
    /// Bits per position axis, relative to the bounding box: 8, 10, 12 or 16.
    /// The error per axis is at most extent / (2·(2^bits − 1)).
    pub position_bits: u8,
    /// Bits per octahedral normal component: 8 or 16 (see the doc for the
    /// angular error of each).
    pub normal_bits: u8,
    /// Wrap the body in zstd. Off by default: the JavaScript decoder has no
    /// zstd, and the meshoptimizer codecs already remove most redundancy.
    pub zstd: bool,
}

impl Default for StripsOptions {
    /// 16-bit positions (sub-micrometre on a 1 m icon), 8-bit normals
    /// (under 1° off, invisible in flat-shaded icons), no zstd.
    fn default() -> Self {
        StripsOptions { position_bits: 16, normal_bits: 8, zstd: false }
    }
}

impl StripsOptions {
    /// Checks the bit counts against the ones the format allows.
    pub fn validate(&self) -> Result<(), String> {
        if !matches!(self.position_bits, 8 | 10 | 12 | 16) {
            return Err(format!("strips position bits must be 8, 10, 12 or 16, got {}", self.position_bits));
        }
        if !matches!(self.normal_bits, 8 | 16) {
            return Err(format!("strips normal bits must be 8 or 16, got {}", self.normal_bits));
        }
        Ok(())
    }
}

/// Why a strips payload was rejected. Every message says what was wrong,
/// so a client can tell a truncated download from a wrong file.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum StripsError {
    /// Fewer bytes than the fixed header and trailer.
    #[error("strips payload truncated: {len} bytes, the header and CRC alone need {min}")]
    TooShort {
        /// Bytes received.
        len: usize,
        /// Bytes needed.
        min: usize,
    },
    /// The first four bytes are not `RMST`.
    #[error("not a strips payload (bad magic)")]
    BadMagic,
    /// The total length disagrees with the header's body length.
    #[error("strips payload truncated or padded: the header promises {expected} bytes, got {actual}")]
    Length {
        /// Bytes the header promises.
        expected: u64,
        /// Bytes received.
        actual: usize,
    },
    /// The CRC32 at the end does not match the bytes before it.
    #[error("strips payload corrupted: CRC32 is {computed:08x}, the file says {stored:08x}")]
    Checksum {
        /// The CRC stored in the file.
        stored: u32,
        /// The CRC of the bytes received.
        computed: u32,
    },
    /// A version this decoder does not know.
    #[error("unsupported strips version {0} (this decoder reads version 2)")]
    Version(u8),
    /// Any other header field out of range.
    #[error("invalid strips header: {0}")]
    Header(String),
    /// The body (or one of its streams) does not decode.
    #[error("invalid strips body: {0}")]
    Body(String),
}

/// A decoded strips file, with the strip itself and the quantisation facts
/// (for clients and tests that want more than a triangle list).
#[derive(Debug, Clone, PartialEq)]
pub struct DecodedStrips {
    /// The mesh; `indices` is the triangle list as stored (in strip order,
    /// each triangle possibly rotated by the index codec, winding kept).
    pub mesh: Mesh,
    /// The strip index sequence rebuilt from the triangles by
    /// [`strip::restrip`], with [`RESTART`] between strips.
    pub strip: Vec<u32>,
    /// Bounding box minimum (the quantisation origin).
    pub bbox_min: [f32; 3],
    /// Bounding box maximum.
    pub bbox_max: [f32; 3],
    /// Bits per position axis.
    pub position_bits: u8,
    /// Bits per normal component.
    pub normal_bits: u8,
    /// The palette, when colours are palette indices.
    pub palette: Option<Vec<[u8; 4]>>,
}

/// Quantises `v` in `[0, 1]` to `0..=max`.
fn quantise_unit(v: f64, max: u32) -> u16 {
    (v * f64::from(max)).round().clamp(0.0, f64::from(max)) as u16
}

/// Octahedral encoding of a normal to two values in `0..=max` (zero normals
/// encode as +Z, so decoding always yields a unit vector).
pub fn oct_encode(n: [f32; 3], max: u32) -> [u16; 2] {
    let [x, y, z] = n.map(f64::from);
    let l1 = x.abs() + y.abs() + z.abs();
    let (mut u, mut v) = if l1 > 0.0 && l1.is_finite() { (x / l1, y / l1) } else { (0.0, 0.0) };
    if l1 > 0.0 && z < 0.0 {
        let (ou, ov) = (u, v);
        u = (1.0 - ov.abs()) * if ou >= 0.0 { 1.0 } else { -1.0 };
        v = (1.0 - ou.abs()) * if ov >= 0.0 { 1.0 } else { -1.0 };
    }
    [quantise_unit(u * 0.5 + 0.5, max), quantise_unit(v * 0.5 + 0.5, max)]
}

/// Decodes an octahedral normal; the arithmetic (in f64, rounded to f32 at
/// the end) is the one the spec and the JavaScript decoder use, so both
/// decoders produce identical floats.
pub fn oct_decode(q: [u16; 2], max: u32) -> [f32; 3] {
    let m = f64::from(max);
    let mut x = f64::from(q[0]) / m * 2.0 - 1.0;
    let mut y = f64::from(q[1]) / m * 2.0 - 1.0;
    let z = 1.0 - x.abs() - y.abs();
    if z < 0.0 {
        let (ox, oy) = (x, y);
        x = (1.0 - oy.abs()) * if ox >= 0.0 { 1.0 } else { -1.0 };
        y = (1.0 - ox.abs()) * if oy >= 0.0 { 1.0 } else { -1.0 };
    }
    let len = (x * x + y * y + z * z).sqrt();
    [(x / len) as f32, (y / len) as f32, (z / len) as f32]
}

/// Dequantises one position coordinate (f64 arithmetic, rounded once).
fn dequantise(q: u16, lo: f32, hi: f32, max: u32) -> f32 {
    let (lo, hi) = (f64::from(lo), f64::from(hi));
    (lo + f64::from(q) * (hi - lo) / f64::from(max)) as f32
}

/// Checks every mesh (in order, so the first bad one is named) and returns
/// the index of each mesh's first vertex in the merged numbering (the format
/// holds a single mesh) and the total vertex count.
fn vertex_bases(meshes: &[NamedMesh]) -> Result<(Vec<u32>, usize), ExportError> {
    let mut bases = Vec::with_capacity(meshes.len());
    let mut total = 0usize;
    for nm in meshes {
        let m = &nm.mesh;
        let bad = |detail: String| ExportError::InvalidMesh { name: nm.name.clone(), detail };
        if m.normals.len() != m.positions.len() || m.colours.len() != m.positions.len() {
            return Err(bad("attribute arrays of different lengths".into()));
        }
        if m.indices.len() % 3 != 0 {
            return Err(bad("index count not a multiple of 3".into()));
        }
        if m.positions.iter().flatten().any(|c| !c.is_finite()) {
            return Err(bad("non-finite position".into()));
        }
        if let Some(&i) = m.indices.iter().find(|&&i| i as usize >= m.positions.len()) {
            return Err(bad(format!("index {i} out of range")));
        }
        let too_large = || ExportError::TooLarge { format: "strips", detail: "more than 2^32 - 2 vertices".into() };
        bases.push(u32::try_from(total).map_err(|_| too_large())?);
        total += m.positions.len();
        if total >= RESTART as usize {
            return Err(too_large());
        }
    }
    Ok((bases, total))
}

/// The bounding box of the vertices triangles use (zero when none do).
fn used_bounds(meshes: &[NamedMesh]) -> ([f32; 3], [f32; 3]) {
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    let mut any = false;
    for m in meshes {
        for &i in &m.mesh.indices {
            let p = m.mesh.positions[i as usize];
            any = true;
            for a in 0..3 {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
        }
    }
    if any {
        (lo, hi)
    } else {
        ([0.0; 3], [0.0; 3])
    }
}

/// The palette when the colours triangles use fit in one byte (sorted, so
/// output is deterministic), else empty.
fn palette_of(meshes: &[NamedMesh]) -> BTreeMap<[u8; 4], u8> {
    let mut set = std::collections::BTreeSet::new();
    let mut last = None;
    for m in meshes {
        for &i in &m.mesh.indices {
            let c = m.mesh.colours[i as usize];
            // Neighbouring corners mostly share a colour: skip the set then.
            if last != Some(c) {
                last = Some(c);
                set.insert(c);
                if set.len() > MAX_PALETTE {
                    return BTreeMap::new();
                }
            }
        }
    }
    set.into_iter().enumerate().map(|(k, c)| (c, k as u8)).collect()
}

/// Quantises every vertex of every mesh to the format's 16 bytes (merged
/// numbering) and returns them with the merged triangle list, minus the
/// triangles whose corners quantise to the same position (they cover no area).
fn quantise(meshes: &[NamedMesh], bases: &[u32], total: usize, bounds: ([f32; 3], [f32; 3]), palette: Option<&BTreeMap<[u8; 4], u8>>, opts: &StripsOptions) -> (Vec<[u16; 8]>, Vec<u32>) {
    let (lo, hi) = bounds;
    let pmax = (1u32 << opts.position_bits) - 1;
    let nmax = (1u32 << opts.normal_bits) - 1;
    let ext: [f64; 3] = [0, 1, 2].map(|a| f64::from(hi[a]) - f64::from(lo[a]));
    let mut quantised = Vec::with_capacity(total);
    let mut last: Option<([u8; 4], [u8; 4])> = None;
    let mut last_normal: Option<([f32; 3], [u16; 2])> = None;
    for m in meshes {
        let m = &m.mesh;
        for ((p, &n), &c) in m.positions.iter().zip(&m.normals).zip(&m.colours) {
            let q = |a: usize| if ext[a] > 0.0 { quantise_unit((f64::from(p[a]) - f64::from(lo[a])) / ext[a], pmax) } else { 0 };
            // Neighbouring vertices mostly share a normal (flat faces): encode it once.
            let n = match last_normal {
                Some((from, to)) if from.map(f32::to_bits) == n.map(f32::to_bits) => to,
                _ => {
                    let to = oct_encode(n, nmax);
                    last_normal = Some((n, to));
                    to
                }
            };
            let c = match palette {
                Some(map) => match last {
                    Some((from, to)) if from == c => to,
                    _ => {
                        let to = [map.get(&c).copied().unwrap_or(0), 0, 0, 0];
                        last = Some((c, to));
                        to
                    }
                },
                None => c,
            };
            quantised.push([q(0), q(1), q(2), 0, n[0], n[1], u16::from_le_bytes([c[0], c[1]]), u16::from_le_bytes([c[2], c[3]])].map(u16::to_le));
        }
    }
    let triangles: usize = meshes.iter().map(|m| m.mesh.indices.len()).sum();
    let mut indices = Vec::with_capacity(triangles);
    for (m, &base) in meshes.iter().zip(bases) {
        for t in m.mesh.indices.chunks_exact(3) {
            let t = [t[0] + base, t[1] + base, t[2] + base];
            let p = |k: usize| &quantised[t[k] as usize][..3];
            if p(0) != p(1) && p(1) != p(2) && p(0) != p(2) {
                indices.extend_from_slice(&t);
            }
        }
    }
    (quantised, indices)
}

/// Encodes `meshes` (merged into one) as a strips file. Deterministic: the
/// same meshes and options give the same bytes.
///
/// Built for models of millions of triangles: the meshes are read in place
/// (never merged into a copy), the quantised vertices are the only
/// vertex-sized copy until the strip is made, and the body is written
/// straight into the output after its header.
pub fn write_strips(meshes: &[NamedMesh], opts: &StripsOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    opts.validate().map_err(|detail| ExportError::InvalidOptions { format: "strips", detail })?;
    let (v, t) = meshes.iter().fold((0u64, 0u64), |(v, t), m| (v + m.mesh.positions.len() as u64, t + m.mesh.triangle_count() as u64));
    budget.reserve_memory(super::estimated_size(super::Format::Strips, v, t))?;
    let (bases, total) = vertex_bases(meshes)?;
    // Each phase below is one pass over the model: the deadline is looked at between them.
    budget.check_deadline()?;
    let (lo, hi) = used_bounds(meshes);
    let distinct = palette_of(meshes);
    let palette = t > 0 && !distinct.is_empty();
    let (quantised, indices) = quantise(meshes, &bases, total, (lo, hi), palette.then_some(&distinct), opts);
    budget.check_deadline()?;
    // The strip travels as its triangles, in strip order: the index buffer
    // codec stores them in fewer bytes than the sequence codec stores the
    // strip, and the decoder rebuilds the strip with `strip::restrip`.
    let (vertices, triangles) = strip::weld_stripify(&quantised, indices);
    drop(quantised);
    budget.check_deadline()?;

    let len32 = |n: usize| u32::try_from(n).map_err(|_| ExportError::TooLarge { format: "strips", detail: "stream over 4 GiB".into() });
    let vstream = meshopt::encode_vertex_buffer_level(&vertices, 3, Some(1))
        .map_err(|e| ExportError::TooLarge { format: "strips", detail: format!("vertex codec: {e:?}") })?;
    let (vertex_count, triangle_count) = (len32(vertices.len())?, len32(triangles.len() / 3)?);
    drop(vertices);
    let istream = meshopt::encode_index_buffer(&triangles, vertex_count as usize)
        .map_err(|e| ExportError::TooLarge { format: "strips", detail: format!("index codec: {e:?}") })?;
    drop(triangles);

    // The header is filled in once the body's lengths are known.
    let pal_len = if palette { distinct.len() * 4 } else { 0 };
    let mut out = Vec::with_capacity(HEADER_LEN + pal_len + 8 + vstream.len() + istream.len() + TRAILER_LEN);
    out.resize(HEADER_LEN, 0);
    if palette {
        for c in distinct.keys() {
            out.extend_from_slice(c);
        }
    }
    out.extend_from_slice(&len32(vstream.len())?.to_le_bytes());
    out.extend_from_slice(&vstream);
    drop(vstream);
    out.extend_from_slice(&len32(istream.len())?.to_le_bytes());
    out.extend_from_slice(&istream);
    drop(istream);
    let raw_len = len32(out.len() - HEADER_LEN)?;
    let mut flags = 0u8;
    if palette {
        flags |= FLAG_PALETTE;
    }
    if opts.zstd {
        budget.check_deadline()?;
        flags |= FLAG_ZSTD;
        // Level 19, single-threaded, no checksum or dictionary: deterministic.
        let body = zstd::bulk::compress(&out[HEADER_LEN..], 19).map_err(|e| ExportError::TooLarge { format: "strips", detail: format!("zstd: {e}") })?;
        out.truncate(HEADER_LEN);
        out.extend_from_slice(&body);
    }
    let body_len = len32(out.len() - HEADER_LEN)?;

    let mut header = Vec::with_capacity(HEADER_LEN);
    header.extend_from_slice(&MAGIC);
    header.extend_from_slice(&[VERSION, flags, opts.position_bits, opts.normal_bits]);
    for c in lo.iter().chain(&hi) {
        header.extend_from_slice(&c.to_le_bytes());
    }
    header.extend_from_slice(&vertex_count.to_le_bytes());
    header.extend_from_slice(&triangle_count.to_le_bytes());
    header.extend_from_slice(&(if palette { distinct.len() as u32 } else { 0 }).to_le_bytes());
    header.extend_from_slice(&body_len.to_le_bytes());
    header.extend_from_slice(&raw_len.to_le_bytes());
    debug_assert_eq!(header.len(), HEADER_LEN);
    out[..HEADER_LEN].copy_from_slice(&header);
    let crc = crc32fast::hash(&out);
    out.extend_from_slice(&crc.to_le_bytes());
    Ok(out)
}

fn u32_at(b: &[u8], off: usize) -> u32 {
    u32::from_le_bytes([b[off], b[off + 1], b[off + 2], b[off + 3]])
}

fn f32_at(b: &[u8], off: usize) -> f32 {
    f32::from_bits(u32_at(b, off))
}

/// Reads a `u32` length prefix and that many bytes from `body` at `*at`.
fn take_stream<'a>(body: &'a [u8], at: &mut usize, what: &str) -> Result<&'a [u8], StripsError> {
    let rest = body.get(*at..).unwrap_or_default();
    if rest.len() < 4 {
        return Err(StripsError::Body(format!("{what} stream length missing")));
    }
    let n = u32_at(rest, 0) as usize;
    let s = rest.get(4..4 + n).ok_or_else(|| StripsError::Body(format!("{what} stream says {n} bytes, only {} left", rest.len() - 4)))?;
    *at += 4 + n;
    Ok(s)
}

/// Decodes a strips file into a triangle-list mesh. Never panics, and never
/// allocates more than the payload's own size justifies (see the limits in
/// `docs/strips-format.md`); any damage is a [`StripsError`].
pub fn decode_strips(bytes: &[u8]) -> Result<Mesh, StripsError> {
    decode_strips_full(bytes).map(|d| d.mesh)
}

/// Like [`decode_strips`], also returning the strip and the quantisation facts.
pub fn decode_strips_full(bytes: &[u8]) -> Result<DecodedStrips, StripsError> {
    let min = HEADER_LEN + TRAILER_LEN;
    if bytes.len() < min {
        return Err(StripsError::TooShort { len: bytes.len(), min });
    }
    if bytes[..4] != MAGIC {
        return Err(StripsError::BadMagic);
    }
    let body_len = u64::from(u32_at(bytes, 44));
    let expected = body_len + min as u64;
    if expected != bytes.len() as u64 {
        return Err(StripsError::Length { expected, actual: bytes.len() });
    }
    let end = bytes.len() - TRAILER_LEN;
    let (stored, computed) = (u32_at(bytes, end), crc32fast::hash(&bytes[..end]));
    if stored != computed {
        return Err(StripsError::Checksum { stored, computed });
    }
    let (version, flags, pbits, nbits) = (bytes[4], bytes[5], bytes[6], bytes[7]);
    if version != VERSION {
        return Err(StripsError::Version(version));
    }
    if flags & !(FLAG_ZSTD | FLAG_PALETTE) != 0 {
        return Err(StripsError::Header(format!("unknown flags {flags:#04x}")));
    }
    StripsOptions { position_bits: pbits, normal_bits: nbits, zstd: false }.validate().map_err(StripsError::Header)?;
    let bbox_min = [f32_at(bytes, 8), f32_at(bytes, 12), f32_at(bytes, 16)];
    let bbox_max = [f32_at(bytes, 20), f32_at(bytes, 24), f32_at(bytes, 28)];
    if bbox_min.iter().chain(&bbox_max).any(|c| !c.is_finite()) || (0..3).any(|a| bbox_min[a] > bbox_max[a]) {
        return Err(StripsError::Header("bounding box not finite or min > max".into()));
    }
    let vertex_count = u32_at(bytes, 32) as u64;
    let triangle_count = u32_at(bytes, 36) as u64;
    let palette_len = u32_at(bytes, 40) as u64;
    let raw_len = u32_at(bytes, 48) as u64;
    let palette_flag = flags & FLAG_PALETTE != 0;
    if palette_flag != (palette_len > 0) || palette_len > MAX_PALETTE as u64 {
        return Err(StripsError::Header(format!("palette of {palette_len} entries with palette flag {palette_flag}")));
    }
    let stored_body = &bytes[HEADER_LEN..end];
    let owned;
    let body: &[u8] = if flags & FLAG_ZSTD != 0 {
        if raw_len > body_len.saturating_mul(MAX_ZSTD_RATIO) + 65536 {
            return Err(StripsError::Header(format!("zstd body of {body_len} bytes claims {raw_len} bytes raw")));
        }
        let mut out = Vec::new();
        zstd::stream::read::Decoder::new(stored_body)
            .and_then(|d| d.take(raw_len + 1).read_to_end(&mut out))
            .map_err(|e| StripsError::Body(format!("zstd: {e}")))?;
        owned = out;
        &owned
    } else {
        stored_body
    };
    if body.len() as u64 != raw_len {
        return Err(StripsError::Body(format!("body is {} bytes, the header says {raw_len}", body.len())));
    }
    let pal_bytes = palette_len as usize * 4;
    let palette: Option<Vec<[u8; 4]>> =
        palette_flag.then(|| body.get(..pal_bytes).unwrap_or_default().chunks_exact(4).map(|c| [c[0], c[1], c[2], c[3]]).collect());
    if palette.as_ref().is_some_and(|p| p.len() as u64 != palette_len) {
        return Err(StripsError::Body("palette cut short".into()));
    }
    let mut at = pal_bytes;
    let vstream = take_stream(body, &mut at, "vertex")?;
    let istream = take_stream(body, &mut at, "index")?;
    if at != body.len() {
        return Err(StripsError::Body(format!("{} stray bytes after the index stream", body.len() - at)));
    }
    if vertex_count > (vstream.len() as u64).saturating_mul(MAX_VERTICES_PER_STREAM_BYTE) + 256 || vertex_count >= u64::from(RESTART) {
        return Err(StripsError::Header(format!("{vertex_count} vertices cannot fit in a {}-byte vertex stream", vstream.len())));
    }
    if triangle_count + INDEX_STREAM_OVERHEAD > istream.len() as u64 {
        return Err(StripsError::Header(format!("{triangle_count} triangles cannot fit in a {}-byte index stream", istream.len())));
    }
    let raw: Vec<[u16; 8]> = meshopt::decode_vertex_buffer(vstream, vertex_count as usize)
        .map_err(|e| StripsError::Body(format!("vertex stream does not decode: {e:?}")))?;
    let triangles: Vec<u32> = meshopt::decode_index_buffer(istream, triangle_count as usize * 3)
        .map_err(|e| StripsError::Body(format!("index stream does not decode: {e:?}")))?;
    if let Some(i) = triangles.iter().find(|&&i| u64::from(i) >= vertex_count) {
        return Err(StripsError::Body(format!("index {i} out of range ({vertex_count} vertices)")));
    }
    if let Some(k) = triangles.chunks_exact(3).position(|t| t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
        return Err(StripsError::Body(format!("triangle {k} has a repeated index")));
    }

    let pmax = (1u32 << pbits) - 1;
    let nmax = (1u32 << nbits) - 1;
    let mut mesh = Mesh {
        positions: Vec::with_capacity(raw.len()),
        normals: Vec::with_capacity(raw.len()),
        colours: Vec::with_capacity(raw.len()),
        indices: Vec::new(),
    };
    for (k, v) in raw.iter().enumerate() {
        let v = v.map(u16::from_le);
        if v[..3].iter().chain(&v[4..6]).zip([pmax, pmax, pmax, nmax, nmax]).any(|(&q, m)| u32::from(q) > m) || v[3] != 0 {
            return Err(StripsError::Body(format!("vertex {k} has a value out of range for its bit count")));
        }
        mesh.positions.push([0, 1, 2].map(|a| dequantise(v[a], bbox_min[a], bbox_max[a], pmax)));
        mesh.normals.push(oct_decode([v[4], v[5]], nmax));
        let [c0, c1] = v[6].to_le_bytes();
        let [c2, c3] = v[7].to_le_bytes();
        let colour = match &palette {
            Some(p) => {
                if [c1, c2, c3] != [0, 0, 0] {
                    return Err(StripsError::Body(format!("vertex {k}: palette padding not zero")));
                }
                *p.get(c0 as usize).ok_or_else(|| StripsError::Body(format!("vertex {k}: palette index {c0} out of range")))?
            }
            None => [c0, c1, c2, c3],
        };
        mesh.colours.push(colour);
    }
    let strip = strip::restrip(&triangles);
    mesh.indices = triangles;
    Ok(DecodedStrips { mesh, strip, bbox_min, bbox_max, position_bits: pbits, normal_bits: nbits, palette })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;

    fn cube() -> Vec<NamedMesh> {
        use crate::export::gltf::tests::{all_nine, meshes_of};
        meshes_of(&all_nine(), 12, crate::mesh::MeshLayout::PerKind)
    }

    fn enc(opts: StripsOptions) -> Vec<u8> {
        write_strips(&cube(), &opts, &mut Budget::new(Limits::default())).unwrap()
    }

    #[test]
    fn oct_error_bounds() {
        // The bounds the doc states: 8-bit under 1.2°, 16-bit under 0.03°.
        for (bits, bound_deg) in [(8u8, 1.2f64), (16, 0.03)] {
            let max = (1u32 << bits) - 1;
            let mut worst = 0f64;
            let n = 200;
            for i in 0..=n {
                for j in 0..=2 * n {
                    let th = std::f64::consts::PI * f64::from(i) / f64::from(n);
                    let ph = std::f64::consts::PI * f64::from(j) / f64::from(n);
                    let v = [th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()].map(|c| c as f32);
                    let d = oct_decode(oct_encode(v, max), max);
                    let dot: f64 = (0..3).map(|a| f64::from(v[a]) * f64::from(d[a])).sum();
                    worst = worst.max(dot.clamp(-1.0, 1.0).acos().to_degrees());
                }
            }
            eprintln!("{bits}-bit normals: worst {worst}°");
            assert!(worst < bound_deg, "{bits}-bit normals: worst {worst}°");
        }
    }

    #[test]
    fn round_trip_all_option_combinations() {
        for pb in [8, 10, 12, 16] {
            for nb in [8, 16] {
                for zstd in [false, true] {
                    let opts = StripsOptions { position_bits: pb, normal_bits: nb, zstd };
                    let bytes = enc(opts);
                    assert_eq!(bytes, enc(opts), "deterministic");
                    let d = decode_strips_full(&bytes).unwrap();
                    assert_eq!((d.position_bits, d.normal_bits), (pb, nb));
                    assert!(d.palette.is_some());
                    assert!(d.mesh.triangle_count() > 100);
                }
            }
        }
    }

    #[test]
    fn every_truncation_and_byte_flip_is_rejected() {
        let bytes = enc(StripsOptions { zstd: true, ..Default::default() });
        for n in 0..bytes.len() {
            assert!(decode_strips(&bytes[..n]).is_err(), "truncated to {n}");
        }
        for i in 0..bytes.len() {
            let mut b = bytes.clone();
            b[i] ^= 0x5a;
            assert!(decode_strips(&b).is_err(), "flipped byte {i}");
        }
        let mut b = bytes.clone();
        b[HEADER_LEN + 3] ^= 1;
        assert!(matches!(decode_strips(&b), Err(StripsError::Checksum { .. })));
        assert!(matches!(decode_strips(&bytes[..bytes.len() - 1]), Err(StripsError::Length { .. })));
    }

    #[test]
    fn hostile_counts_are_refused_before_allocating() {
        let bytes = enc(StripsOptions::default());
        for (off, val) in [(32usize, u32::MAX - 1), (36, u32::MAX), (36, u32::MAX / 3), (40, 300), (48, u32::MAX)] {
            let mut b = bytes.clone();
            b[off..off + 4].copy_from_slice(&val.to_le_bytes());
            let end = b.len() - 4;
            let crc = crc32fast::hash(&b[..end]);
            b[end..].copy_from_slice(&crc.to_le_bytes());
            assert!(decode_strips(&b).is_err(), "offset {off} = {val}");
        }
    }

    #[test]
    fn empty_model_round_trips() {
        let bytes = write_strips(&[], &StripsOptions::default(), &mut Budget::new(Limits::default())).unwrap();
        let d = decode_strips(&bytes).unwrap();
        assert!(d.positions.is_empty() && d.indices.is_empty());
    }
}
