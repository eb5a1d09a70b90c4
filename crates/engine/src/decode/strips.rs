//! The reference decoder of the `strips` format, versions 2 (one coded
//! mesh) and 3 (independently coded chunks). `docs/strips-format.md` is the
//! specification; `clients/js/strips.mjs` and `clients/c/rulemesh_strips.c`
//! are its twins. Every count is checked against the bytes that carry it
//! before anything is allocated, so damaged or hostile input is an error,
//! never a large allocation or a panic.

use crate::export::strips::format::*;
use crate::geom::strip::{self, RESTART};
use crate::geom::Mesh;
use std::io::Read;

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
    #[error("unsupported strips version {0} (this decoder reads versions 2 and 3)")]
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



fn u32_at(b: &[u8], off: usize) -> u32 {
    u32::from_le_bytes([b[off], b[off + 1], b[off + 2], b[off + 3]])
}

fn f32_at(b: &[u8], off: usize) -> f32 {
    f32::from_bits(u32_at(b, off))
}

/// Dequantises one position coordinate (f64 arithmetic, rounded once).
fn dequantise(q: u16, lo: f32, hi: f32, max: u32) -> f32 {
    let (lo, hi) = (f64::from(lo), f64::from(hi));
    (lo + f64::from(q) * (hi - lo) / f64::from(max)) as f32
}

/// Reads a little-endian `u32` from `body` at `*at`.
fn take_u32(body: &[u8], at: &mut usize, what: &str) -> Result<u32, StripsError> {
    let b = body.get(*at..*at + 4).ok_or_else(|| StripsError::Body(format!("{what} missing")))?;
    *at += 4;
    Ok(u32_at(b, 0))
}

/// Reads a `u32` length prefix and that many bytes from `body` at `*at`.
fn take_stream<'a>(body: &'a [u8], at: &mut usize, what: &str) -> Result<&'a [u8], StripsError> {
    let n = take_u32(body, at, &format!("{what} stream length"))? as usize;
    let rest = &body[*at..];
    let s = rest.get(..n).ok_or_else(|| StripsError::Body(format!("{what} stream says {n} bytes, only {} left", rest.len())))?;
    *at += n;
    Ok(s)
}

/// One chunk's streams and counts, checked against the streams' lengths.
struct Chunk<'a> {
    /// "chunk k: " in version 3 (for messages), empty in version 2.
    name: String,
    vertices: u64,
    triangles: u64,
    vstream: &'a [u8],
    istream: &'a [u8],
}

impl<'a> Chunk<'a> {
    /// Refuses counts the streams cannot hold (the safety limits of the spec).
    fn new(vertices: u64, triangles: u64, vstream: &'a [u8], istream: &'a [u8], name: String) -> Result<Chunk<'a>, StripsError> {
        if vertices > (vstream.len() as u64).saturating_mul(MAX_VERTICES_PER_STREAM_BYTE) + 256 {
            return Err(StripsError::Header(format!("{name}{vertices} vertices cannot fit in a {}-byte vertex stream", vstream.len())));
        }
        if triangles + INDEX_STREAM_OVERHEAD > istream.len() as u64 {
            return Err(StripsError::Header(format!("{name}{triangles} triangles cannot fit in a {}-byte index stream", istream.len())));
        }
        Ok(Chunk { name, vertices, triangles, vstream, istream })
    }
}

/// The chunks of a body after its palette: version 2's one, version 3's list.
fn chunks(body: &[u8], mut at: usize, version: u8, vertex_count: u64, triangle_count: u64) -> Result<Vec<Chunk<'_>>, StripsError> {
    let mut out = Vec::new();
    if version == VERSION_ONE_MESH {
        let vstream = take_stream(body, &mut at, "vertex")?;
        let istream = take_stream(body, &mut at, "index")?;
        out.push(Chunk::new(vertex_count, triangle_count, vstream, istream, String::new())?);
    } else {
        let count = take_u32(body, &mut at, "chunk count")?;
        // Each chunk takes at least 16 bytes of counts and lengths (plus its
        // streams), so the list is never allocated beyond what the body justifies.
        if u64::from(count) * 16 > (body.len() - at) as u64 {
            return Err(StripsError::Header(format!("{count} chunks cannot fit in {} bytes", body.len() - at)));
        }
        out.reserve_exact(count as usize);
        let (mut v, mut t) = (0u64, 0u64);
        for k in 0..count {
            let cv = u64::from(take_u32(body, &mut at, "chunk vertex count")?);
            let ct = u64::from(take_u32(body, &mut at, "chunk triangle count")?);
            let vstream = take_stream(body, &mut at, "vertex")?;
            let istream = take_stream(body, &mut at, "index")?;
            out.push(Chunk::new(cv, ct, vstream, istream, format!("chunk {k}: "))?);
            v += cv;
            t += ct;
        }
        if (v, t) != (vertex_count, triangle_count) {
            return Err(StripsError::Header(format!("chunks hold {v} vertices and {t} triangles, the header says {vertex_count} and {triangle_count}")));
        }
    }
    if at != body.len() {
        return Err(StripsError::Body(format!("{} stray bytes after the index stream", body.len() - at)));
    }
    Ok(out)
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
    if version != VERSION_ONE_MESH && version != VERSION {
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
    let vertex_count = u64::from(u32_at(bytes, 32));
    let triangle_count = u64::from(u32_at(bytes, 36));
    let palette_len = u64::from(u32_at(bytes, 40));
    let raw_len = u64::from(u32_at(bytes, 48));
    let palette_flag = flags & FLAG_PALETTE != 0;
    if palette_flag != (palette_len > 0) || palette_len > MAX_PALETTE as u64 {
        return Err(StripsError::Header(format!("palette of {palette_len} entries with palette flag {palette_flag}")));
    }
    if vertex_count >= u64::from(RESTART) {
        return Err(StripsError::Header(format!("{vertex_count} vertices: the restart index is no vertex")));
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
    // Every chunk's counts are checked against its streams before anything is decoded.
    let chunks = chunks(body, pal_bytes, version, vertex_count, triangle_count)?;

    let pmax = (1u32 << pbits) - 1;
    let nmax = (1u32 << nbits) - 1;
    let mut mesh = Mesh {
        positions: Vec::with_capacity(vertex_count as usize),
        normals: Vec::with_capacity(vertex_count as usize),
        colours: Vec::with_capacity(vertex_count as usize),
        indices: Vec::with_capacity(triangle_count as usize * 3),
    };
    for chunk in &chunks {
        let c = &chunk.name;
        let raw: Vec<[u16; 8]> = meshopt::decode_vertex_buffer(chunk.vstream, chunk.vertices as usize)
            .map_err(|e| StripsError::Body(format!("{c}vertex stream does not decode: {e:?}")))?;
        let triangles: Vec<u32> = meshopt::decode_index_buffer(chunk.istream, chunk.triangles as usize * 3)
            .map_err(|e| StripsError::Body(format!("{c}index stream does not decode: {e:?}")))?;
        if let Some(i) = triangles.iter().find(|&&i| u64::from(i) >= chunk.vertices) {
            return Err(StripsError::Body(format!("{c}index {i} out of range ({} vertices)", chunk.vertices)));
        }
        if let Some(k) = triangles.chunks_exact(3).position(|t| t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            return Err(StripsError::Body(format!("{c}triangle {k} has a repeated index")));
        }
        // Fits: the total is below RESTART (checked above).
        let base = mesh.positions.len() as u32;
        mesh.indices.extend(triangles.iter().map(|&i| i + base));
        for (k, v) in raw.iter().enumerate() {
            let v = v.map(u16::from_le);
            if v[..3].iter().chain(&v[4..6]).zip([pmax, pmax, pmax, nmax, nmax]).any(|(&q, m)| u32::from(q) > m) || v[3] != 0 {
                return Err(StripsError::Body(format!("{c}vertex {k} has a value out of range for its bit count")));
            }
            mesh.positions.push([0, 1, 2].map(|a| dequantise(v[a], bbox_min[a], bbox_max[a], pmax)));
            mesh.normals.push(oct_decode([v[4], v[5]], nmax));
            let [c0, c1] = v[6].to_le_bytes();
            let [c2, c3] = v[7].to_le_bytes();
            let colour = match &palette {
                Some(p) => {
                    if [c1, c2, c3] != [0, 0, 0] {
                        return Err(StripsError::Body(format!("{c}vertex {k}: palette padding not zero")));
                    }
                    *p.get(c0 as usize).ok_or_else(|| StripsError::Body(format!("{c}vertex {k}: palette index {c0} out of range")))?
                }
                None => [c0, c1, c2, c3],
            };
            mesh.colours.push(colour);
        }
    }
    // Chunks use disjoint vertices, so one rebuild over all of them gives
    // each chunk's strip, the chunks separated by a restart.
    let strip = strip::restrip(&mesh.indices);
    Ok(DecodedStrips { mesh, strip, bbox_min, bbox_max, position_bits: pbits, normal_bits: nbits, palette })
}
