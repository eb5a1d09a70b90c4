//! The plain glTF writers' binary buffer: the format's size limits and
//! container constants, where each mesh goes ([`Placed`], [`place`], after
//! [`check_mesh`]) and where the animation samples follow ([`Tracks`]), the
//! buffer-view and accessor records that describe those regions, and how
//! the bytes are streamed ([`Sink`]: raw for GLB, [`Base64`] for `.gltf`).
//! Everything here is about bytes and offsets; the JSON document that
//! points into the buffer is built in `document` and `graph`.

use crate::export::{ExportError, ExportMeta};
use crate::core::budget::Budget;
use crate::geom::{NamedMesh, STOP_EVERY};
use crate::model::graph::{NodeGraph, Trs};
use super::tree::{Accessor, Component, Ix, Kind, Path, Target, View};

/// glTF buffers (and GLB files) address at most 2³² − 1 bytes.
pub(super) const MAX_BYTES: u64 = u32::MAX as u64;
/// The largest vertex count indexed with UNSIGNED_SHORT (65535 itself is the
/// primitive-restart value and may not appear as an index).
pub(super) const MAX_SHORT_VERTICES: usize = 65535;
/// The GLB header magic.
pub(super) const GLB_MAGIC: &[u8; 4] = b"glTF";
/// The GLB chunk type of the JSON chunk.
pub(super) const CHUNK_JSON: u32 = 0x4E4F_534A;
/// The GLB chunk type of the binary chunk.
pub(super) const CHUNK_BIN: u32 = 0x004E_4942;
/// The URI prefix of an embedded buffer.
pub(super) const DATA_URI: &str = "data:application/octet-stream;base64,";

/// Where one mesh's data lives in the binary buffer.
pub(super) struct Placed {
    /// Index of the mesh in the writer's input (for the node graph).
    pub(super) mesh: usize,
    pub(super) vertices: usize,
    pub(super) triangles: usize,
    /// Indices as u16 (else u32).
    pub(super) short: bool,
    pub(super) offset: u64,
    pub(super) min: [f32; 3],
    pub(super) max: [f32; 3],
}

impl Placed {
    /// Where the POSITION data starts.
    pub(super) fn position_offset(&self) -> u64 {
        self.offset
    }
    /// Where the NORMAL data starts.
    pub(super) fn normal_offset(&self) -> u64 {
        self.offset + 12 * self.vertices as u64
    }
    /// Where the COLOR_0 data starts.
    pub(super) fn colour_offset(&self) -> u64 {
        self.offset + 24 * self.vertices as u64
    }
    /// Where the indices start.
    pub(super) fn index_offset(&self) -> u64 {
        self.offset + 28 * self.vertices as u64
    }
    /// The byte length of the indices.
    pub(super) fn index_bytes(&self) -> u64 {
        3 * self.triangles as u64 * if self.short { 2 } else { 4 }
    }
    /// The first byte after this mesh.
    pub(super) fn end(&self) -> u64 {
        self.index_offset() + self.index_bytes()
    }
}

/// `n` rounded up to a multiple of 4.
pub(super) fn align4(n: u64) -> u64 {
    n.saturating_add(3) & !3
}

/// An [`ExportError::InvalidMesh`] for mesh `name`.
pub(super) fn invalid(name: &str, detail: impl Into<String>) -> ExportError {
    ExportError::InvalidMesh { name: name.to_string(), detail: detail.into() }
}

/// Rejects a mesh a glTF writer cannot describe: attribute lists of unequal
/// length, a partial triangle, an index out of range or a non-finite position.
pub(super) fn check_mesh(m: &NamedMesh) -> Result<(), ExportError> {
    let mesh = &m.mesh;
    let n = mesh.positions.len();
    if mesh.normals.len() != n || mesh.colours.len() != n {
        return Err(invalid(&m.name, "normals and colours must have one entry per position"));
    }
    if mesh.indices.len() % 3 != 0 {
        return Err(invalid(&m.name, "index count is not a multiple of 3"));
    }
    // The largest index and one pass over every coordinate, without an
    // early exit, which the compiler vectorises (issue 33: a fresh icon's
    // glTF checked its meshes a value at a time).
    if mesh.indices.iter().copied().max().is_some_and(|i| i as usize >= n) {
        return Err(invalid(&m.name, "index out of range"));
    }
    if !mesh.positions.iter().flatten().fold(true, |finite, c| finite & c.is_finite()) {
        return Err(invalid(&m.name, "non-finite position"));
    }
    Ok(())
}

/// A mesh with its place in the buffer.
pub(super) type Placement<'a> = (&'a NamedMesh, Placed);

/// Checks each mesh and assigns buffer offsets. Meshes without triangles are
/// left out (glTF accessors may not be empty). Returns the placements (paired
/// with their mesh) and the buffer's byte length.
pub(super) fn place(meshes: &[NamedMesh]) -> Result<(Vec<Placement<'_>>, u64), ExportError> {
    let mut placed = Vec::with_capacity(meshes.len());
    let mut offset = 0u64;
    for (index, m) in meshes.iter().enumerate() {
        let mesh = &m.mesh;
        let n = mesh.positions.len();
        if mesh.indices.is_empty() || n == 0 {
            continue;
        }
        check_mesh(m)?;
        let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in &mesh.positions {
            for k in 0..3 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let p = Placed { mesh: index, vertices: n, triangles: mesh.indices.len() / 3, short: n <= MAX_SHORT_VERTICES, offset, min, max };
        offset = align4(p.end());
        let end = p.end();
        placed.push((m, p));
        if end > MAX_BYTES {
            return Err(ExportError::TooLarge { format: "glTF", detail: format!("buffer of {end} bytes exceeds the 4 GiB limit") });
        }
    }
    let len = placed.last().map_or(0, |(_, p)| p.end());
    Ok((placed, len))
}

/// A buffer view of `length` bytes at `offset` of `buffer`.
pub(super) fn view(buffer: Ix, offset: u64, length: u64, target: Option<Target>) -> View {
    View { buffer, byte_length: length, byte_offset: offset, byte_stride: None, name: None, target, meshopt: None }
}

/// An accessor of `count` elements reading `view` from its start.
pub(super) fn accessor(view: Ix, count: usize, component: Component, kind: Kind, normalized: bool) -> Accessor {
    Accessor { view, byte_offset: None, count: count as u64, component, kind, bounds: None, normalized }
}

/// What an animation channel moves.
#[derive(Debug, Clone, Copy)]
pub(super) enum Mover {
    /// Graph node `i`.
    Node(usize),
    /// The camera node.
    Camera,
}

/// Animation samples laid out in the buffer after the meshes.
#[derive(Debug, Default)]
pub(super) struct Tracks {
    /// Buffer offset of the first byte (4-byte aligned).
    pub(super) offset: u64,
    /// Sample times, then each channel's outputs, all little-endian f32.
    pub(super) bytes: Vec<u8>,
    /// Samples per channel.
    pub(super) count: usize,
    /// The last sample time.
    pub(super) end: f32,
    /// Per channel: what it moves, which property, and where its outputs start in `bytes`.
    pub(super) channels: Vec<(Mover, Path, u64)>,
}

impl Tracks {
    /// Lays out the samples of every node (and the camera) that moves;
    /// empty when nothing does. Rotations are sign-aligned sample to sample
    /// so LINEAR interpolation takes the short way.
    fn of(graph: Option<&NodeGraph>, offset: u64) -> Tracks {
        let Some(g) = graph.filter(|g| g.is_animated()) else { return Tracks::default() };
        let count = g.times.len();
        let mut t = Tracks { offset, count, end: g.times.last().copied().unwrap_or(0.0), ..Tracks::default() };
        for time in &g.times {
            t.bytes.extend_from_slice(&time.to_le_bytes());
        }
        let mut movers: Vec<(Mover, &[Trs], bool)> = Vec::new();
        for (i, n) in g.nodes.iter().enumerate() {
            if n.samples.len() == count {
                movers.push((Mover::Node(i), &n.samples, true));
            }
        }
        if let Some(c) = g.camera.as_ref().filter(|c| c.placements.len() == count) {
            movers.push((Mover::Camera, &c.placements, false));
        }
        for (mover, samples, with_scale) in movers {
            t.channels.push((mover, Path::Translation, t.bytes.len() as u64));
            for s in samples {
                for c in s.translation {
                    t.bytes.extend_from_slice(&c.to_le_bytes());
                }
            }
            t.channels.push((mover, Path::Rotation, t.bytes.len() as u64));
            let mut prev = [0.0f32, 0.0, 0.0, 1.0];
            for s in samples {
                let dot: f32 = s.rotation.iter().zip(prev).map(|(a, b)| a * b).sum();
                let q = if dot < 0.0 { s.rotation.map(|c| -c) } else { s.rotation };
                for c in q {
                    t.bytes.extend_from_slice(&c.to_le_bytes());
                }
                prev = q;
            }
            if with_scale {
                t.channels.push((mover, Path::Scale, t.bytes.len() as u64));
                for s in samples {
                    for c in s.scale {
                        t.bytes.extend_from_slice(&c.to_le_bytes());
                    }
                }
            }
        }
        t
    }

    /// The buffer's length with these samples after `meshes_end` bytes of meshes.
    pub(super) fn buffer_len(&self, meshes_end: u64) -> u64 {
        if self.bytes.is_empty() {
            meshes_end
        } else {
            self.offset + self.bytes.len() as u64
        }
    }
}


/// The animation samples of `meta`'s graph, placed after `meshes_end` bytes of
/// meshes and charged to `budget` (they are held until written).
pub(super) fn animation_tracks(meta: &ExportMeta, meshes_end: u64, budget: &mut Budget) -> Result<Tracks, ExportError> {
    let tracks = Tracks::of(meta.graph.as_ref(), align4(meshes_end));
    budget.reserve_memory(tracks.bytes.len() as u64)?;
    if tracks.buffer_len(meshes_end) > MAX_BYTES {
        return Err(ExportError::TooLarge { format: "glTF", detail: "animation samples exceed the 4 GiB buffer limit".to_string() });
    }
    Ok(tracks)
}

/// A destination for the binary buffer's bytes.
pub(super) trait Sink {
    /// Appends `bytes`.
    fn put(&mut self, bytes: &[u8]);
}

impl Sink for Vec<u8> {
    fn put(&mut self, bytes: &[u8]) {
        self.extend_from_slice(bytes);
    }
}

/// Streams bytes as standard base64 (with `=` padding) into a vector.
pub(super) struct Base64<'a> {
    pub(super) out: &'a mut Vec<u8>,
    pub(super) carry: [u8; 3],
    pub(super) held: usize,
}

/// The standard base64 alphabet.
pub(super) const BASE64_ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// Bytes encoded per copy into the output by [`Base64`]'s `put` (in groups of three).
const BASE64_BLOCK: usize = 256;

/// The four base64 characters of three bytes.
fn quad([a, b, c]: [u8; 3]) -> [u8; 4] {
    let sextets = [a >> 2, ((a & 0x03) << 4) | (b >> 4), ((b & 0x0f) << 2) | (c >> 6), c & 0x3f];
    sextets.map(|q| BASE64_ALPHABET[q as usize])
}

impl Base64<'_> {
    /// Writes the carried group: its first `n + 1` characters, then `=`s.
    fn emit(&mut self, n: usize) {
        for (k, &q) in quad(self.carry).iter().enumerate() {
            self.out.push(if k <= n { q } else { b'=' });
        }
    }

    /// Carries one byte, writing the group when it is whole.
    fn carry_byte(&mut self, b: u8) {
        self.carry[self.held] = b;
        self.held += 1;
        if self.held == 3 {
            self.emit(3);
            self.held = 0;
        }
    }

    /// Writes the last, padded quad.
    pub(super) fn finish(mut self) {
        if self.held > 0 {
            for k in self.held..3 {
                self.carry[k] = 0;
            }
            self.emit(self.held);
        }
    }
}

impl Sink for Base64<'_> {
    /// Completes the carried group, then encodes whole groups a block at
    /// a time through a small array (a byte at a time, a `.gltf`'s
    /// base64 cost three times the rest of its export, issue 33), and
    /// carries the last one or two bytes.
    fn put(&mut self, bytes: &[u8]) {
        let mut rest = bytes;
        while self.held > 0 {
            let Some((&b, tail)) = rest.split_first() else { return };
            self.carry_byte(b);
            rest = tail;
        }
        let (groups, tail) = rest.split_at(rest.len() / 3 * 3);
        let mut text = [0u8; 4 * BASE64_BLOCK];
        for block in groups.chunks(3 * BASE64_BLOCK) {
            for (slot, group) in text.chunks_exact_mut(4).zip(block.chunks_exact(3)) {
                if let Ok(group) = <[u8; 3]>::try_from(group) {
                    slot.copy_from_slice(&quad(group));
                }
            }
            self.out.extend_from_slice(&text[..block.len() / 3 * 4]);
        }
        for &b in tail {
            self.carry_byte(b);
        }
    }
}

/// Standard base64 (with `=` padding) of `bytes`, for other glTF writers.
pub(super) fn base64(bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(base64_len(bytes.len() as u64) as usize);
    let mut b = Base64 { out: &mut out, carry: [0; 3], held: 0 };
    b.put(bytes);
    b.finish();
    out
}

/// Length of the base64 encoding of `n` bytes.
pub(super) fn base64_len(n: u64) -> u64 {
    n.div_ceil(3).saturating_mul(4)
}

/// Writes 4-byte words little-endian. On little-endian machines memory
/// already has that layout, so the whole slice goes out in one copy.
fn put_words<T: bytemuck::Pod>(sink: &mut impl Sink, values: &[T], to_le: fn(T) -> [u8; 4]) {
    if cfg!(target_endian = "little") {
        sink.put(bytemuck::cast_slice(values));
    } else {
        for &v in values {
            sink.put(&to_le(v));
        }
    }
}

/// Writes the binary buffer (exactly `buffer_len` bytes, zero padding between
/// meshes), then the animation samples.
pub(super) fn write_buffer(sink: &mut impl Sink, placed: &[Placement<'_>], tracks: &Tracks) {
    let never: Result<(), std::convert::Infallible> = write_buffer_until(sink, placed, tracks, &|| Ok(()));
    let Ok(()) = never;
}

/// [`write_buffer`] that calls `check` between runs of [`STOP_EVERY`] values
/// (a model of millions of triangles takes a noticeable share of a deadline
/// to copy) and gives up with its error, the buffer partly written.
pub(super) fn write_buffer_until<E>(sink: &mut impl Sink, placed: &[Placement<'_>], tracks: &Tracks, check: &dyn Fn() -> Result<(), E>) -> Result<(), E> {
    let mut at = 0u64;
    for (m, p) in placed {
        while at < p.offset {
            sink.put(&[0]);
            at += 1;
        }
        let mesh = &m.mesh;
        for r in runs(mesh.positions.len()) {
            check()?;
            put_words::<f32>(sink, bytemuck::cast_slice(&mesh.positions[r]), f32::to_le_bytes);
        }
        for r in runs(mesh.normals.len()) {
            check()?;
            put_words::<f32>(sink, bytemuck::cast_slice(&mesh.normals[r]), f32::to_le_bytes);
        }
        sink.put(bytemuck::cast_slice(&mesh.colours));
        for r in runs(mesh.indices.len()) {
            check()?;
            if p.short {
                // Through a small array, a run at a time: one `put` per
                // index was most of a small model's buffer write.
                let mut words = [0u8; 2 * SHORT_RUN];
                for run in mesh.indices[r].chunks(SHORT_RUN) {
                    for (word, &i) in words.chunks_exact_mut(2).zip(run) {
                        // Fits: `short` means every index is below 65535.
                        word.copy_from_slice(&(i as u16).to_le_bytes());
                    }
                    sink.put(&words[..2 * run.len()]);
                }
            } else {
                put_words(sink, &mesh.indices[r], u32::to_le_bytes);
            }
        }
        at = p.end();
    }
    if !tracks.bytes.is_empty() {
        while at < tracks.offset {
            sink.put(&[0]);
            at += 1;
        }
        sink.put(&tracks.bytes);
    }
    Ok(())
}

/// Short indices narrowed per `put` by [`write_buffer_until`].
const SHORT_RUN: usize = 512;

/// Consecutive ranges of at most [`STOP_EVERY`] covering `0..len`.
fn runs(len: usize) -> impl Iterator<Item = std::ops::Range<usize>> {
    (0..len).step_by(STOP_EVERY).map(move |start| start..len.min(start + STOP_EVERY))
}

/// Where `needle` (not empty) first occurs in `haystack`. A window is
/// compared whole only when its first two bytes match: comparing every
/// window of a `.gltf`'s JSON for its buffer URI cost more than writing
/// the JSON (issue 33).
pub(super) fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    let (first, second) = (needle.first(), needle.get(1));
    haystack.windows(needle.len().max(1)).position(|w| w.first() == first && w.get(1) == second && w == needle)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_reference_vectors() {
        for (raw, enc) in [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foob", "Zm9vYg=="), ("fooba", "Zm9vYmE="), ("foobar", "Zm9vYmFy")] {
            let mut out = Vec::new();
            let mut b = Base64 { out: &mut out, carry: [0; 3], held: 0 };
            b.put(raw.as_bytes());
            b.finish();
            assert_eq!(out, enc.as_bytes());
            assert_eq!(base64_len(raw.len() as u64) as usize, enc.len());
        }
    }

    /// The URI search finds what comparing every window finds.
    #[test]
    fn find_is_the_first_window_equal_to_the_needle() {
        let hay = b"{\"uri\":1,\"u\":\"uri\",\"uri\":\"data:x\"} \"uri\":\"data:x\"";
        for needle in [&b"\"uri\":\"data:x\""[..], b"\"u", b"}", b"x", b"nothing", b"\"uri\":1"] {
            assert_eq!(find(hay, needle), hay.windows(needle.len()).position(|w| w == needle), "{needle:?}");
        }
    }

    /// Blocks, groups and carried bytes give the text of one byte at a
    /// time, however the input is split between puts.
    #[test]
    fn base64_is_the_same_however_the_bytes_arrive() {
        let bytes: Vec<u8> = (0..2000u32).map(|k| (k * 7919 % 251) as u8).collect();
        let mut one = Vec::new();
        let mut b = Base64 { out: &mut one, carry: [0; 3], held: 0 };
        for &x in &bytes {
            b.carry_byte(x);
        }
        b.finish();
        for len in [0, 1, 2, 3, 4, 5, 767, 768, 769, 1999, 2000] {
            for split in [0, 1, 2, 5, 768, 1000].into_iter().filter(|&s| s <= len) {
                let mut out = Vec::new();
                let mut b = Base64 { out: &mut out, carry: [0; 3], held: 0 };
                b.put(&bytes[..split]);
                b.put(&bytes[split..len]);
                b.finish();
                let mut want = Vec::new();
                let mut w = Base64 { out: &mut want, carry: [0; 3], held: 0 };
                for &x in &bytes[..len] {
                    w.carry_byte(x);
                }
                w.finish();
                assert_eq!(out, want, "{len} split at {split}");
            }
        }
        assert_eq!(base64(&bytes), one);
    }
}
