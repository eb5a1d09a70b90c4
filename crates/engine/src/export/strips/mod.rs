//! The `strips` format (`application/vnd.rulemesh.strips`): one quantised,
//! stripified, compressed mesh for phone clients that fetch icons over slow
//! links and decode them on small CPUs. `docs/strips-format.md` specifies it
//! byte by byte; this module is the reference encoder's container (header,
//! body, CRC) and its two ways in: meshes ([`write_strips`]) and the model
//! itself, streamed piece by piece into a [`StreamSink`] (a
//! [`GeometrySink`] the pipeline feeds).
//! `chunk` codes the chunks, `format` holds what the encoder and the
//! decoder share, and `crate::decode::strips` is the reference decoder
//! (`clients/js/strips.mjs` and `clients/c/` its twins).
//!
//! Encoding: a first pass finds the bounding box and palette of the whole
//! model; the second cuts the model's triangles into chunks of
//! [`CHUNK_TRIANGLES`], and each chunk is quantised (16 bytes a vertex:
//! positions relative to the bounding box, octahedral normals, colour or
//! palette index), welded, optimised for the vertex cache and stripified
//! ([`crate::geom::strip`]) and coded with meshoptimizer's vertex and index
//! buffer codecs on its own → optional zstd → header and CRC32. A model of
//! one chunk is written as version 2 (one mesh), anything larger as version 3.

mod chunk;
pub mod format;

pub(crate) use chunk::CHUNK_TRIANGLES;
use chunk::{encode_chunk, weld_chunk, Chunker, EncodedChunk, Part, Quantiser, Survey};
pub use format::*;
use super::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use super::sink::GeometrySink;
use super::{ExportError, ExportMeta, ExportOptions};
use crate::core::budget::Budget;
use crate::geom::strip::RESTART;
use crate::geom::NamedMesh;
use crate::mesh::pieces::Piece;

/// `strips`: the header, CRC and palette, plus meshoptimizer's worst
/// cases: a vertex block costs at most 4164 bytes per 256 16-byte vertices
/// (and one partial block), a strip at most 5 indices per triangle at 5
/// bytes each; zstd's worst-case growth fits in the per-vertex slack.
pub(crate) const STRIPS: FormatInfo = FormatInfo {
    name: "strips",
    extensions: &["strips"],
    mime: "application/vnd.rulemesh.strips",
    caps: Capabilities { streamed: true, ..Capabilities::NONE },
    options: OptionGroup::Strips,
    size: SizeBound { fixed: 16 * 1024, per_vertex: 20, per_triangle: 25, per_instance: 0 },
    writer: Writer::Sink { flat: write_strips_with, model: Some(stream_sink) },
};

/// [`write_strips`] with the request's strips options.
fn write_strips_with(meshes: &[NamedMesh], _: &ExportMeta, options: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_strips(meshes, &options.strips, budget)
}

/// Checks every mesh (in order, so the first bad one is named) before any is read.
fn check_meshes(meshes: &[NamedMesh]) -> Result<(), ExportError> {
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
    }
    Ok(())
}

fn len32(n: usize) -> Result<u32, ExportError> {
    u32::try_from(n).map_err(|_| ExportError::TooLarge { format: STRIPS.name, detail: "stream over 4 GiB".into() })
}

/// The container being written: header space, palette, chunks; the header
/// and CRC are filled in by [`Body::finish`] once the counts are known.
struct Body {
    out: Vec<u8>,
    version: u8,
    count_at: usize,
    chunks: u32,
    vertices: u64,
    triangles: u64,
}

impl Body {
    /// A body of `chunks` chunks (version 2 when there is at most one).
    fn new(chunks: u64, palette: Option<&[[u8; 4]]>) -> Body {
        let version = if chunks <= 1 { VERSION_ONE_MESH } else { VERSION };
        let mut out = vec![0u8; HEADER_LEN];
        for c in palette.into_iter().flatten() {
            out.extend_from_slice(c);
        }
        let count_at = out.len();
        if version == VERSION {
            out.extend_from_slice(&0u32.to_le_bytes());
        }
        Body { out, version, count_at, chunks: 0, vertices: 0, triangles: 0 }
    }

    /// Bytes [`Body::push`] adds for `c`.
    fn growth(c: &EncodedChunk) -> u64 {
        (16 + c.vstream.len() + c.istream.len()) as u64
    }

    /// Appends one coded chunk.
    fn push(&mut self, c: &EncodedChunk) -> Result<(), ExportError> {
        if self.version == VERSION {
            self.out.extend_from_slice(&c.vertices.to_le_bytes());
            self.out.extend_from_slice(&c.triangles.to_le_bytes());
        } else if self.chunks > 0 {
            return Err(ExportError::TooLarge { format: STRIPS.name, detail: "a second chunk in a one-mesh file".into() });
        }
        self.out.extend_from_slice(&len32(c.vstream.len())?.to_le_bytes());
        self.out.extend_from_slice(&c.vstream);
        self.out.extend_from_slice(&len32(c.istream.len())?.to_le_bytes());
        self.out.extend_from_slice(&c.istream);
        self.chunks += 1;
        self.vertices += u64::from(c.vertices);
        self.triangles += u64::from(c.triangles);
        Ok(())
    }

    /// Fills in the header, compresses the body if asked, and appends the CRC.
    fn finish(mut self, (lo, hi): ([f32; 3], [f32; 3]), palette: Option<&[[u8; 4]]>, opts: &StripsOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
        if self.version == VERSION_ONE_MESH && self.chunks == 0 {
            // An empty model is one empty chunk.
            self.push(&encode_chunk(&[], &Quantiser::new((lo, hi), opts.position_bits, opts.normal_bits, None))?)?;
        }
        if self.version == VERSION {
            self.out[self.count_at..self.count_at + 4].copy_from_slice(&self.chunks.to_le_bytes());
        }
        if self.vertices >= u64::from(RESTART) {
            return Err(ExportError::TooLarge { format: STRIPS.name, detail: "more than 2^32 - 2 vertices".into() });
        }
        let mut out = self.out;
        let raw_len = len32(out.len() - HEADER_LEN)?;
        let mut flags = if palette.is_some() { FLAG_PALETTE } else { 0 };
        if opts.zstd {
            budget.check_deadline()?;
            budget.reserve_memory(u64::from(raw_len))?;
            flags |= FLAG_ZSTD;
            // Level 19, single-threaded, no checksum or dictionary: deterministic.
            let body = zstd::bulk::compress(&out[HEADER_LEN..], 19).map_err(|e| ExportError::TooLarge { format: STRIPS.name, detail: format!("zstd: {e}") })?;
            out.truncate(HEADER_LEN);
            out.extend_from_slice(&body);
        }
        let body_len = len32(out.len() - HEADER_LEN)?;
        let mut header = Vec::with_capacity(HEADER_LEN);
        header.extend_from_slice(&MAGIC);
        header.extend_from_slice(&[self.version, flags, opts.position_bits, opts.normal_bits]);
        for c in lo.iter().chain(&hi) {
            header.extend_from_slice(&c.to_le_bytes());
        }
        // Fit: below RESTART (checked above), and triangles ≤ vertices·2 for every chunk's mesh.
        header.extend_from_slice(&(self.vertices as u32).to_le_bytes());
        header.extend_from_slice(&len32(self.triangles as usize)?.to_le_bytes());
        header.extend_from_slice(&(palette.map_or(0, <[_]>::len) as u32).to_le_bytes());
        header.extend_from_slice(&body_len.to_le_bytes());
        header.extend_from_slice(&raw_len.to_le_bytes());
        debug_assert_eq!(header.len(), HEADER_LEN);
        out[..HEADER_LEN].copy_from_slice(&header);
        let crc = crc32fast::hash(&out);
        out.extend_from_slice(&crc.to_le_bytes());
        Ok(out)
    }
}

/// Calls `chunk` with every chunk of `meshes` (merged into one, in order),
/// a chunk's window of each mesh at a time: nothing is copied.
fn mesh_chunks(meshes: &[NamedMesh], chunk: &mut dyn FnMut(&[Part<'_>]) -> Result<(), ExportError>) -> Result<(), ExportError> {
    let mut parts: Vec<Part<'_>> = Vec::new();
    let mut pending = 0usize;
    for nm in meshes {
        let mut at = 0;
        while at < nm.mesh.indices.len() {
            let take = (3 * (CHUNK_TRIANGLES - pending)).min(nm.mesh.indices.len() - at);
            parts.push((&nm.mesh, &nm.mesh.indices[at..at + take]));
            at += take;
            pending += take / 3;
            if pending == CHUNK_TRIANGLES {
                chunk(&parts)?;
                parts.clear();
                pending = 0;
            }
        }
    }
    if pending > 0 {
        chunk(&parts)?;
    }
    Ok(())
}

/// Encodes `meshes` (merged into one) as a strips file. Deterministic: the
/// same meshes and options give the same bytes, and the same bytes as
/// a [`StreamSink`] fed the model they were meshed from.
pub(crate) fn write_strips(meshes: &[NamedMesh], opts: &StripsOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    opts.validate().map_err(|detail| ExportError::InvalidOptions { format: STRIPS.name, detail })?;
    let (v, t) = meshes.iter().fold((0u64, 0u64), |(v, t), m| (v + m.mesh.positions.len() as u64, t + m.mesh.triangle_count() as u64));
    budget.reserve_memory(STRIPS.size.of(v, t))?;
    check_meshes(meshes)?;
    let mut survey = Survey::default();
    mesh_chunks(meshes, &mut |parts| survey.add(parts))?;
    budget.check_deadline()?;
    let palette = survey.palette();
    let q = Quantiser::new(survey.bounds(), opts.position_bits, opts.normal_bits, palette.as_deref());
    let mut body = Body::new(survey.chunks(), palette.as_deref());
    mesh_chunks(meshes, &mut |parts| {
        budget.check_deadline()?;
        body.push(&encode_chunk(parts, &q)?)
    })?;
    body.finish(survey.bounds(), palette.as_deref(), opts, budget)
}

/// Bytes one chunk's coding needs at most besides its output: quantised
/// vertices, weld tables, the strip and meshoptimizer's own arrays for up to
/// three vertices per triangle.
pub(crate) const CHUNK_WORKING_SET: u64 = 3 * CHUNK_TRIANGLES as u64 * 128;

/// A chunk's codecs, running on a second thread.
type Coding = std::thread::JoinHandle<Result<EncodedChunk, ExportError>>;

/// The streamed strips writer as a [`GeometrySink`]: the model's pieces,
/// surveyed once for the bounding box, palette and chunk count, then fed
/// again and written a chunk at a time, never holding a model-sized mesh:
/// the same bytes as [`write_strips`] of the merged meshes of the same
/// model (docs/strips-format.md).
pub(crate) struct StreamSink {
    opts: StripsOptions,
    survey: Survey,
    writing: Option<Streaming>,
}

/// What a [`StreamSink`] holds while writing.
struct Streaming {
    q: Quantiser,
    body: Body,
    chunker: Chunker,
    /// Bytes reserved for the chunker's buffer.
    reserved: u64,
    /// Bytes reserved for the chunks being coded.
    working_set: u64,
    /// The previous chunk's codecs, while this thread welds the next.
    coding: Option<Coding>,
    /// One chunk in all: its codecs run on this thread.
    single: bool,
}

impl StreamSink {
    /// A sink writing strips with the request's strips options.
    pub(crate) fn new(opts: StripsOptions) -> StreamSink {
        StreamSink { opts, survey: Survey::default(), writing: None }
    }
}

/// The streamed sink of the strips descriptor, with the request's options.
fn stream_sink(options: &ExportOptions) -> Box<dyn GeometrySink> {
    Box::new(StreamSink::new(options.strips))
}

/// Appends a coded chunk to `body`; the output grows by what the chunk
/// adds (its capacity may double: that is reserved too).
fn append(body: &mut Body, c: EncodedChunk, budget: &mut Budget) -> Result<(), ExportError> {
    let grown = Body::growth(&c);
    if body.out.len() as u64 + grown > body.out.capacity() as u64 {
        budget.reserve_memory((body.out.capacity() as u64).max(grown))?;
    }
    body.push(&c)
}

/// The coded chunk of a codec thread.
fn joined(h: Coding) -> Result<EncodedChunk, ExportError> {
    h.join().unwrap_or_else(|_| Err(ExportError::TooLarge { format: STRIPS.name, detail: "a chunk's codec thread panicked".into() }))
}

/// Feeds every chunk the chunker completes while taking `piece` (or, with
/// no piece, its last partial chunk) to the codecs and the body. Each
/// chunk is welded here; its codecs (meshoptimizer's vertex and index
/// codecs, about a third of the encoder's time) run on a second thread
/// while this one tessellates, quantises and welds the next chunk, and
/// chunks are appended in order, so the bytes are those of one thread. A
/// model of one chunk (every icon) has nothing to overlap its codecs with:
/// they run here, since starting a thread cost a tenth of a fresh gem's
/// strips (issue 33).
fn chunks(w: &mut Streaming, piece: Option<&Piece<'_>>, budget: &mut Budget) -> Result<(), ExportError> {
    let Streaming { q, body, chunker, coding, single, .. } = w;
    let mut take = |parts: &[Part<'_>]| -> Result<(), ExportError> {
        let welded = weld_chunk(parts, q);
        if let Some(h) = coding.take() {
            append(body, joined(h)?, budget)?;
        }
        if *single {
            return append(body, welded.code()?, budget);
        }
        *coding = Some(std::thread::spawn(move || welded.code()));
        Ok(())
    };
    match piece {
        Some(piece) => chunker.push(piece, &mut take),
        None => std::mem::take(chunker).finish(&mut take),
    }
}

impl GeometrySink for StreamSink {
    fn format(&self) -> &'static str {
        STRIPS.name
    }

    fn surveys(&self) -> bool {
        true
    }

    /// A placed piece's corners are mapped as the mesher maps them
    /// (positions only); nothing is tessellated.
    fn survey(&mut self, piece: &Piece<'_>) -> Result<(), ExportError> {
        self.survey.add_piece(piece)
    }

    /// Strips carry no metadata: only the geometry is written.
    fn begin(&mut self, _meta: &ExportMeta, budget: &mut Budget) -> Result<(), ExportError> {
        let opts = &self.opts;
        opts.validate().map_err(|detail| ExportError::InvalidOptions { format: STRIPS.name, detail })?;
        budget.check_deadline()?;
        let palette = self.survey.palette();
        let q = Quantiser::new(self.survey.bounds(), opts.position_bits, opts.normal_bits, palette.as_deref());
        // A second chunk is in flight while its codecs run: its welded
        // vertices and triangles, at most half a working set.
        let working_set = CHUNK_WORKING_SET + CHUNK_WORKING_SET / 2;
        budget.reserve_memory(working_set + STRIPS.size.fixed)?;
        let body = Body::new(self.survey.chunks(), palette.as_deref());
        let single = self.survey.chunks() <= 1;
        self.writing = Some(Streaming { q, body, chunker: Chunker::default(), reserved: 0, working_set, coding: None, single });
        Ok(())
    }

    /// Tessellates the piece into the chunk buffer (reserving the buffer as
    /// it grows) and codes every chunk it completes.
    fn piece(&mut self, piece: &Piece<'_>, budget: &mut Budget) -> Result<(), ExportError> {
        let Some(w) = self.writing.as_mut() else { return Err(super::sink::not_begun(STRIPS.name)) };
        let (v, t) = piece.counts();
        let need = w.chunker.buffer_bytes().max(crate::geom::mesh::mesh_bytes((v + 3 * CHUNK_TRIANGLES) as u64, (t + CHUNK_TRIANGLES) as u64));
        if need > w.reserved {
            budget.reserve_memory(need - w.reserved)?;
            w.reserved = need;
        }
        chunks(w, Some(piece), budget)
    }

    fn end(self: Box<Self>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
        let StreamSink { opts, survey, writing } = *self;
        let Some(mut w) = writing else { return Err(super::sink::not_begun(STRIPS.name)) };
        chunks(&mut w, None, budget)?;
        budget.release_memory(w.reserved);
        if let Some(h) = w.coding.take() {
            append(&mut w.body, joined(h)?, budget)?;
        }
        budget.release_memory(w.working_set);
        let palette = survey.palette();
        w.body.finish(survey.bounds(), palette.as_deref(), &opts, budget)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::{Limits, OnLimit};
    use crate::mesh::pieces::for_each_piece;
    use crate::mesh::MeshLayout;
    use crate::model::Scene;
    use crate::geom::strip::RESTART;
    use crate::decode::strips::{decode_strips, decode_strips_full, oct_decode, StripsError};

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

    /// A grid of boxes of `n`² · 12 triangles (two chunks at n = 80), and its strips file.
    fn grid(n: u32) -> (Scene, Vec<u8>) {
        use crate::mesh::tests::{inst, scene};
        let s = scene((0..n * n).map(|k| inst(crate::core::PrimitiveKind::Box, [(k / n) as f32, (k % n) as f32, 0.0], 0.5, k % 7 == 0)).collect());
        // As the pipeline's streamed route feeds the sink: a survey, then the pieces.
        let mut b = Budget::new(Limits::default());
        let mut sink = StreamSink::new(StripsOptions::default());
        let walk = |b: &mut Budget, f: &mut dyn FnMut(Piece<'_>, &mut Budget) -> Result<bool, ExportError>| {
            for_each_piece::<ExportError>(&s, None, 8, MeshLayout::Merged, OnLimit::Error, b, f).unwrap();
        };
        walk(&mut b, &mut |p, _| sink.survey(&p).map(|()| true));
        sink.begin(&ExportMeta::default(), &mut b).unwrap();
        walk(&mut b, &mut |p, b| sink.piece(&p, b).map(|()| true));
        let bytes = Box::new(sink).end(&mut b).unwrap();
        (s, bytes)
    }

    #[test]
    fn streamed_chunks_equal_the_meshed_model_and_decode() {
        let (s, bytes) = grid(80);
        assert_eq!(bytes[4], VERSION, "76 800 triangles are two chunks");
        let mut b = Budget::new(Limits::default());
        let meshes = crate::mesh::build_meshes(&s, 8, MeshLayout::Merged, &mut b).unwrap();
        assert_eq!(write_strips(&meshes, &StripsOptions::default(), &mut b).unwrap(), bytes, "streamed = meshed");
        assert_eq!(grid(80).1, bytes, "deterministic");
        let d = decode_strips_full(&bytes).unwrap();
        assert_eq!(d.mesh.triangle_count(), 80 * 80 * 12);
        // The two chunks' strips are separate runs, and their vertices disjoint.
        assert_eq!(u32_le(&bytes, HEADER_LEN + d.palette.as_ref().map_or(0, |p| 4 * p.len())), 2);
        assert!(d.strip.iter().filter(|&&i| i == RESTART).count() >= 1);
        // One chunk stays version 2.
        assert_eq!(grid(10).1[4], VERSION_ONE_MESH);
    }

    fn u32_le(b: &[u8], at: usize) -> u32 {
        u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
    }

    /// Rewrites the CRC after `b` was edited, so the edit reaches the body checks.
    fn recrc(b: &mut [u8]) {
        let end = b.len() - 4;
        let crc = crc32fast::hash(&b[..end]);
        b[end..].copy_from_slice(&crc.to_le_bytes());
    }

    #[test]
    fn damaged_chunks_are_refused() {
        let (_, bytes) = grid(80);
        for n in (0..bytes.len()).step_by(997) {
            assert!(decode_strips(&bytes[..n]).is_err(), "truncated to {n}");
        }
        let at = HEADER_LEN + 4 * u32_le(&bytes, 40) as usize;
        // Chunk count, first chunk's vertex and triangle counts and stream lengths.
        for (off, val) in [(at, 3u32), (at, u32::MAX), (at + 4, u32::MAX), (at + 4, 0), (at + 8, u32::MAX), (at + 8, 1), (at + 12, u32::MAX), (at + 12, 5)] {
            let mut b = bytes.clone();
            b[off..off + 4].copy_from_slice(&val.to_le_bytes());
            recrc(&mut b);
            assert!(decode_strips(&b).is_err(), "offset {off} = {val}");
        }
        // A byte inside the first chunk's streams, with a valid CRC.
        for k in (at + 20..at + 2000).step_by(37) {
            let mut b = bytes.clone();
            b[k] ^= 0x5a;
            recrc(&mut b);
            // Either refused or decoded to valid indices (the codecs cannot tell every change).
            if let Ok(m) = decode_strips(&b) {
                assert!(m.indices.iter().all(|&i| (i as usize) < m.positions.len()));
            }
        }
        // Version 2 with a chunk list is refused (the body does not parse as one mesh).
        let mut b = bytes.clone();
        b[4] = VERSION_ONE_MESH;
        recrc(&mut b);
        assert!(decode_strips(&b).is_err());
    }

    #[test]
    fn empty_model_round_trips() {
        let bytes = write_strips(&[], &StripsOptions::default(), &mut Budget::new(Limits::default())).unwrap();
        let d = decode_strips(&bytes).unwrap();
        assert!(d.positions.is_empty() && d.indices.is_empty());
    }
}
