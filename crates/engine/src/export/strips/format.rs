//! What every part of the `strips` format shares: the constants of the
//! container, the request options and the octahedral normal's encoding
//! (`docs/strips-format.md`). The encoder (`export::strips` and its
//! `chunk`) and the decoder (`crate::decode::strips`) both build on it, and
//! `export::strips` re-exports it.

/// The four bytes every strips file starts with.
pub const MAGIC: [u8; 4] = *b"RMST";
/// The format version of a model cut into several chunks: the body is a
/// list of independently coded chunks, so neither the encoder nor a decoder
/// ever holds more than one chunk's working arrays. The decoders read it and
/// [`VERSION_ONE_MESH`].
pub(crate) const VERSION: u8 = 3;
/// The format version of a model of one chunk (at most [`CHUNK_TRIANGLES`](super::chunk::CHUNK_TRIANGLES)
/// triangles): the body is that chunk's two streams, byte for byte what
/// version 2 always was (so icons did not change). Version 2 stores the
/// strip as its triangles (index buffer codec) where version 1 stored the
/// strip indices (index sequence codec); version 1 is not read.
pub(crate) const VERSION_ONE_MESH: u8 = 2;
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
pub(crate) const MAX_ZSTD_RATIO: u64 = 64;
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

/// Octahedral encoding of a normal to two values in `0..=max` (zero normals
/// encode as +Z, so decoding always yields a unit vector).
pub(crate) fn oct_encode(n: [f32; 3], max: u32) -> [u16; 2] {
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

/// Quantises `v` in `[0, 1]` to `0..=max`: `(v * max).round()` clamped
/// to `0..=max` (NaN to 0). Rounded here rather than with `f64::round`,
/// which is a call of libm's `round` on x86-64's baseline, once per
/// coordinate of every strips vertex (issue 33's profile). The value is
/// clamped to `-1..=max + 1` first, which rounds to the same clamped
/// result, so the cast truncates exactly; half-way cases go away from
/// zero, as `f64::round` does.
pub(crate) fn quantise_unit(v: f64, max: u32) -> u16 {
    let max = f64::from(max);
    // `clamp` keeps NaN, and NaN casts to 0, as before.
    let x = (v * max).clamp(-1.0, max + 1.0);
    let t = x as i64;
    let frac = x - t as f64;
    let rounded = t + i64::from(frac >= 0.5) - i64::from(frac <= -0.5);
    // Fits: 0..=max, and max < 2^16.
    rounded.clamp(0, max as i64) as u16
}


#[cfg(test)]
mod tests {
    use super::quantise_unit;

    /// `f64::round`'s answer, the rule `quantise_unit` keeps.
    fn reference(v: f64, max: u32) -> u16 {
        (v * f64::from(max)).round().clamp(0.0, f64::from(max)) as u16
    }

    #[test]
    fn quantise_unit_rounds_as_f64_round_does() {
        let specials = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -0.0, 0.0, 1.0, -1e300, 1e300, f64::MIN_POSITIVE, 1.0 + f64::EPSILON, -f64::EPSILON];
        for max in [255u32, 1023, 4095, 65535] {
            for v in specials {
                assert_eq!(quantise_unit(v, max), reference(v, max), "{v} at {max}");
            }
            // Every half-way point and its neighbours, below, inside and above 0..=1.
            for k in -4i64..=2 * i64::from(max) + 4 {
                let half = (k as f64 + 0.5) / f64::from(max);
                for v in [half, f64::from_bits(half.to_bits() + 1), f64::from_bits(half.to_bits().wrapping_sub(1)), k as f64 / f64::from(max)] {
                    assert_eq!(quantise_unit(v, max), reference(v, max), "{v} at {max}");
                }
            }
        }
    }
}
