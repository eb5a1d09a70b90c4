//! Chunk coding for the `strips` format: how a run of at most
//! [`CHUNK_TRIANGLES`] triangles becomes one independently coded chunk
//! (quantise, drop zero-area triangles, weld, optimise and stripify, the two
//! meshoptimizer codecs), how the model is cut into such runs without ever
//! holding more than one of them ([`Chunker`]), and what the first pass over
//! the model learns (bounds, palette, chunk count: [`Survey`]).
//! `docs/strips-format.md` ("Chunks") states the rules; the container
//! (header, body, CRC) is `export::strips`.

use super::format::{oct_encode, quantise_unit, MAX_PALETTE};
use crate::export::ExportError;
use crate::geom::strip;
use crate::geom::Mesh;
use crate::mesh::pieces::{append_piece, Piece};
use std::collections::{BTreeMap, BTreeSet};

/// Triangles per chunk: the model's triangles, in the order of the merged
/// flat mesh, are cut into runs of this many (the last run shorter), and
/// each run with the vertices it uses is coded alone. 2^16: large enough
/// that a chunk loses little to the welding and strips it cannot share with
/// its neighbours (the 3M-triangle box grid is 18 % larger than one
/// whole-model mesh at 2^16, 47 % at 2^14), small enough that the encoder's
/// working set (about 10 MB) stays below the output of a big model; and
/// every model up to 65 536 triangles (icons) is one chunk, written as
/// version 2. docs/strips-format.md ("Chunks") has the measurements.
pub(crate) const CHUNK_TRIANGLES: usize = 1 << 16;

/// Part of a chunk: some triangles of a mesh (indices into its vertices).
pub type Part<'a> = (&'a Mesh, &'a [u32]);

/// Quantised vertex: the format's 16 bytes as eight little-endian `u16`.
type Quantised = [u16; 8];

/// What the first pass learns: the bounding box of the vertices triangles
/// use, the colours they use (while at most 256), and the chunks and
/// triangles the model cuts into.
#[derive(Debug, Clone)]
pub(crate) struct Survey {
    lo: [f32; 3],
    hi: [f32; 3],
    colours: BTreeSet<[u8; 4]>,
    too_many_colours: bool,
    /// Triangles (before zero-area ones are dropped).
    pub triangles: u64,
}

impl Default for Survey {
    fn default() -> Self {
        Survey { lo: [f32::INFINITY; 3], hi: [f32::NEG_INFINITY; 3], colours: BTreeSet::new(), too_many_colours: false, triangles: 0 }
    }
}

impl Survey {
    /// Chunks the model cuts into: every [`CHUNK_TRIANGLES`] triangles one.
    pub fn chunks(&self) -> u64 {
        self.triangles.div_ceil(CHUNK_TRIANGLES as u64)
    }

    /// Takes in one piece without tessellating it: a placed piece's corners
    /// are mapped as the mesher maps them (positions only, with the same
    /// arithmetic), its one colour is its vertices' colour.
    pub(crate) fn add_piece(&mut self, piece: &Piece<'_>) -> Result<(), ExportError> {
        let Piece::Placed { proto, map: (linear, _, translation), colour, .. } = *piece else {
            let Piece::Whole(m) = *piece else { return Ok(()) };
            return self.add(&[(m, &m.indices)]);
        };
        let t = proto.indices.len() / 3;
        if t == 0 {
            return Ok(());
        }
        self.triangles += t as u64;
        for &i in &proto.indices {
            let p = (linear * glam::Vec3::from_array(proto.positions[i as usize]) + translation).to_array();
            self.take_position(p)?;
        }
        self.take_colour(crate::core::quantise::rgba8(colour));
        Ok(())
    }

    fn take_position(&mut self, p: [f32; 3]) -> Result<(), ExportError> {
        if p.iter().any(|c| !c.is_finite()) {
            return Err(ExportError::InvalidMesh { name: "model".into(), detail: "non-finite position".into() });
        }
        for a in 0..3 {
            self.lo[a] = self.lo[a].min(p[a]);
            self.hi[a] = self.hi[a].max(p[a]);
        }
        Ok(())
    }

    fn take_colour(&mut self, c: [u8; 4]) {
        if !self.too_many_colours {
            self.colours.insert(c);
            if self.colours.len() > MAX_PALETTE {
                self.too_many_colours = true;
                self.colours.clear();
            }
        }
    }

    /// Takes in some triangles of meshes.
    pub fn add(&mut self, parts: &[Part<'_>]) -> Result<(), ExportError> {
        for &(mesh, tris) in parts {
            self.triangles += (tris.len() / 3) as u64;
            let mut last = None;
            for &i in tris {
                self.take_position(mesh.positions[i as usize])?;
                let c = mesh.colours[i as usize];
                // Neighbouring corners mostly share a colour: skip the set then.
                if last != Some(c) {
                    last = Some(c);
                    self.take_colour(c);
                }
            }
        }
        Ok(())
    }

    /// The bounding box of the used vertices (zero when there are none).
    pub fn bounds(&self) -> ([f32; 3], [f32; 3]) {
        if self.triangles == 0 {
            ([0.0; 3], [0.0; 3])
        } else {
            (self.lo, self.hi)
        }
    }

    /// The palette (sorted colours) when there are triangles and at most 256 colours.
    pub fn palette(&self) -> Option<Vec<[u8; 4]>> {
        (self.triangles > 0 && !self.too_many_colours).then(|| self.colours.iter().copied().collect())
    }
}

/// Quantisation shared by every chunk: the model's bounding box, the bit
/// counts and the palette.
pub(crate) struct Quantiser {
    lo: [f32; 3],
    ext: [f64; 3],
    pmax: u32,
    nmax: u32,
    palette: Option<BTreeMap<[u8; 4], u8>>,
}

impl Quantiser {
    /// The quantiser for a model with these bounds and palette.
    pub fn new((lo, hi): ([f32; 3], [f32; 3]), position_bits: u8, normal_bits: u8, palette: Option<&[[u8; 4]]>) -> Quantiser {
        Quantiser {
            lo,
            ext: [0, 1, 2].map(|a| f64::from(hi[a]) - f64::from(lo[a])),
            pmax: (1u32 << position_bits) - 1,
            nmax: (1u32 << normal_bits) - 1,
            palette: palette.map(|p| p.iter().enumerate().map(|(k, &c)| (c, k as u8)).collect()),
        }
    }

    /// Appends the vertices `range` of `mesh`, quantised, to `out`.
    fn quantise(&self, mesh: &Mesh, range: std::ops::Range<usize>, out: &mut Vec<Quantised>) {
        let mut last: Option<([u8; 4], [u8; 4])> = None;
        let mut last_normal: Option<([f32; 3], [u16; 2])> = None;
        for k in range {
            let (p, n, c) = (mesh.positions[k], mesh.normals[k], mesh.colours[k]);
            let q = |a: usize| if self.ext[a] > 0.0 { quantise_unit((f64::from(p[a]) - f64::from(self.lo[a])) / self.ext[a], self.pmax) } else { 0 };
            // Neighbouring vertices mostly share a normal (flat faces): encode it once.
            let n = match last_normal {
                Some((from, to)) if from.map(f32::to_bits) == n.map(f32::to_bits) => to,
                _ => {
                    let to = oct_encode(n, self.nmax);
                    last_normal = Some((n, to));
                    to
                }
            };
            let c = match &self.palette {
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
            out.push([q(0), q(1), q(2), 0, n[0], n[1], u16::from_le_bytes([c[0], c[1]]), u16::from_le_bytes([c[2], c[3]])].map(u16::to_le));
        }
    }
}

/// One coded chunk.
pub(crate) struct EncodedChunk {
    /// Vertices after welding.
    pub vertices: u32,
    /// Triangles kept (zero-area ones dropped).
    pub triangles: u32,
    /// The vertex stream (meshoptimizer vertex codec, version 1).
    pub vstream: Vec<u8>,
    /// The strip's triangles (meshoptimizer index buffer codec, version 1).
    pub istream: Vec<u8>,
}

/// A chunk welded and stripified, ready for the codecs ([`WeldedChunk::code`]).
pub(crate) struct WeldedChunk {
    vertices: Vec<Quantised>,
    triangles: Vec<u32>,
}

/// Codes one chunk: the parts' triangles with the vertices they use. The
/// result does not depend on how the parts number their vertices (welding
/// numbers them by first use), only on the triangles' corners, in order.
pub(crate) fn encode_chunk(parts: &[Part<'_>], q: &Quantiser) -> Result<EncodedChunk, ExportError> {
    weld_chunk(parts, q).code()
}

/// The first half of [`encode_chunk`]: quantise, weld and stripify.
pub(crate) fn weld_chunk(parts: &[Part<'_>], q: &Quantiser) -> WeldedChunk {
    let mut quantised: Vec<Quantised> = Vec::new();
    let mut indices: Vec<u32> = Vec::with_capacity(parts.iter().map(|p| p.1.len()).sum());
    for &(mesh, tris) in parts {
        let (Some(&lo), Some(&hi)) = (tris.iter().min(), tris.iter().max()) else { continue };
        // Fits: a chunk has at most 3·CHUNK_TRIANGLES corners per part window
        // in practice, and never more vertices than its meshes.
        let base = quantised.len() as u32;
        q.quantise(mesh, lo as usize..hi as usize + 1, &mut quantised);
        for t in tris.chunks_exact(3) {
            let t = [t[0] - lo + base, t[1] - lo + base, t[2] - lo + base];
            let p = |k: usize| &quantised[t[k] as usize][..3];
            // Corners that quantise to one position make a triangle of no area.
            if p(0) != p(1) && p(1) != p(2) && p(0) != p(2) {
                indices.extend_from_slice(&t);
            }
        }
    }
    // The strip travels as its triangles, in strip order: the index buffer
    // codec stores them in fewer bytes than the sequence codec stores the
    // strip, and the decoder rebuilds the strip with `strip::restrip`.
    let (vertices, triangles) = strip::weld_stripify(&quantised, indices);
    WeldedChunk { vertices, triangles }
}

impl WeldedChunk {
    /// The second half of [`encode_chunk`]: meshoptimizer's vertex and index
    /// codecs. It needs nothing but the chunk, so the streamed writer runs it
    /// on a second thread while the next chunk is welded.
    pub fn code(self) -> Result<EncodedChunk, ExportError> {
        let WeldedChunk { vertices, triangles } = self;
        let codec = |what: &str, e: meshopt::Error| ExportError::TooLarge { format: super::STRIPS.name, detail: format!("{what} codec: {e:?}") };
        let vstream = meshopt::encode_vertex_buffer_level(&vertices, 3, Some(1)).map_err(|e| codec("vertex", e))?;
        let istream = meshopt::encode_index_buffer(&triangles, vertices.len()).map_err(|e| codec("index", e))?;
        // Fits: at most 3·CHUNK_TRIANGLES of each.
        Ok(EncodedChunk { vertices: vertices.len() as u32, triangles: (triangles.len() / 3) as u32, vstream, istream })
    }
}

/// Cuts a stream of pieces into chunks of [`CHUNK_TRIANGLES`] triangles,
/// holding at most one chunk's triangles (plus the rest of the piece that
/// completed it) at a time: placed pieces are tessellated into a buffer,
/// whole meshes are copied a chunk's window at a time.
#[derive(Default)]
pub(crate) struct Chunker {
    buf: Mesh,
    /// Pieces taken so far.
    pub pieces: u64,
}

impl Chunker {
    /// Bytes the buffer holds now.
    pub(crate) fn buffer_bytes(&self) -> u64 {
        let m = &self.buf;
        (m.positions.capacity() * 12 + m.normals.capacity() * 12 + m.colours.capacity() * 4 + m.indices.capacity() * 4) as u64
    }

    /// Takes one piece; `chunk` is called with every chunk it completes.
    pub fn push(&mut self, piece: &Piece<'_>, chunk: &mut dyn FnMut(&[Part<'_>]) -> Result<(), ExportError>) -> Result<(), ExportError> {
        self.pieces += 1;
        match piece {
            Piece::Placed { .. } => append_piece(&mut self.buf, piece),
            Piece::Whole(m) => {
                let mut at = 0;
                while at < m.indices.len() {
                    let room = 3 * CHUNK_TRIANGLES.saturating_sub(self.buf.indices.len() / 3).max(1);
                    let window = &m.indices[at..(at + room).min(m.indices.len())];
                    at += window.len();
                    let (Some(&lo), Some(&hi)) = (window.iter().min(), window.iter().max()) else { continue };
                    let (lo, hi) = (lo as usize, hi as usize + 1);
                    // Fits: the buffer stays far below u32::MAX vertices.
                    let base = self.buf.positions.len() as u32;
                    self.buf.positions.extend_from_slice(&m.positions[lo..hi]);
                    self.buf.normals.extend_from_slice(&m.normals[lo..hi]);
                    self.buf.colours.extend_from_slice(&m.colours[lo..hi]);
                    self.buf.indices.extend(window.iter().map(|&i| i - lo as u32 + base));
                    self.emit_full(chunk)?;
                }
            }
        }
        self.emit_full(chunk)
    }

    /// Emits every full chunk in the buffer and drops what no later triangle uses.
    fn emit_full(&mut self, chunk: &mut dyn FnMut(&[Part<'_>]) -> Result<(), ExportError>) -> Result<(), ExportError> {
        let n = 3 * CHUNK_TRIANGLES;
        if self.buf.indices.len() < n {
            return Ok(());
        }
        let mut from = 0;
        while self.buf.indices.len() - from >= n {
            chunk(&[(&self.buf, &self.buf.indices[from..from + n])])?;
            from += n;
        }
        self.buf.indices.drain(..from);
        // Pieces append their vertices in order, so the vertices below the
        // lowest one still used belong to emitted triangles only.
        let keep = self.buf.indices.iter().min().map_or(self.buf.positions.len(), |&i| i as usize);
        self.buf.positions.drain(..keep);
        self.buf.normals.drain(..keep);
        self.buf.colours.drain(..keep);
        for i in &mut self.buf.indices {
            *i -= keep as u32;
        }
        Ok(())
    }

    /// Emits the last, partial chunk (if any triangles are left).
    pub fn finish(mut self, chunk: &mut dyn FnMut(&[Part<'_>]) -> Result<(), ExportError>) -> Result<(), ExportError> {
        if !self.buf.indices.is_empty() {
            let buf = std::mem::take(&mut self.buf);
            chunk(&[(&buf, &buf.indices)])?;
        }
        Ok(())
    }
}
