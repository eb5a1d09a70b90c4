//! Reading scene files back into meshes: the reference decoder of
//! `docs/scene-format.md`, for tests and clients written in Rust.
//!
//! Every record is tessellated with the mesher's own functions
//! ([`crate::mesh::append_instance`], [`crate::mesh::append_affine`],
//! [`crate::geom::primitives::tessellate`], [`LeafShape::prototype`]) from
//! the f32 (hierarchies: f64) numbers the server used, so the meshes are the
//! flat formats' meshes bit for bit. `clients/js/scene.mjs` does the same in
//! JavaScript.

mod read;

pub use read::{scene_provenance, SceneError};
use read::{read_header, read_hierarchy, truncation, Header, Reader};
use crate::export::scene::format::{index_width, FLAG_SCALED, PARITY_BIT, RUN_AFFINE, RUN_HIERARCHY, RUN_MESH, RUN_PLACED, RUN_PRIMITIVES, VERSION_1};
use crate::core::PrimitiveKind;
use crate::geom::primitives::{self, Prototype};
use crate::geom::{Mesh, NamedMesh};
use crate::mesh::{append_affine, append_instance};
use crate::model::hierarchy::Hierarchy;
use crate::model::scene::{AffineInstance, Instance};
use glam::{Mat3, Quat, Vec3};

/// A decoded scene file: the meshes the flat formats write for the same
/// request, and what the header says.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DecodedScene {
    /// The meshes, in the flat glTF's order, named as there.
    pub meshes: Vec<NamedMesh>,
    /// The detail primitives were tessellated at.
    pub detail: u32,
    /// Whether a limit cut the model short.
    pub truncated: bool,
    /// The provenance block, if the file has one.
    pub provenance: Option<serde_json::Value>,
}

/// One placement record (primitive, affine or prototype).
#[derive(Debug, Clone, Copy)]
enum Record {
    /// A primitive kind placed by a similarity.
    Primitive(Instance),
    /// A primitive kind placed by an affine map.
    Affine(AffineInstance),
    /// A prototype placed by a similarity.
    Placed(u32, Instance),
}

/// A run of a mesh as read.
#[derive(Debug, Clone)]
enum Run {
    /// Placement records.
    Records(Vec<Record>),
    /// A mesh written out.
    Mesh(Mesh),
    /// The hierarchy's expansion.
    Hierarchy,
}

/// A version 2 file, read but not tessellated.
struct Parsed {
    /// Prototype meshes.
    protos: Vec<Prototype>,
    /// The hierarchy section (empty when absent).
    hierarchy: Hierarchy,
    /// The meshes: names and runs.
    meshes: Vec<(String, Vec<Run>)>,
}

fn colour_of(palette: &[[u8; 4]], r: &mut Reader<'_>, w: usize, mesh: u32) -> Result<[f32; 4], SceneError> {
    let mut b = [0u8; 4];
    b[..w].copy_from_slice(r.slice(w)?);
    let c = palette.get(u32::from_le_bytes(b) as usize).ok_or(SceneError::Record { mesh, detail: "colour index beyond the palette" })?;
    // The mesher writes round(255·c) of these: exactly the byte again.
    Ok(c.map(|v| f32::from(v) / 255.0))
}

fn finite(v: &[f32], mesh: u32) -> Result<(), SceneError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(SceneError::Record { mesh, detail: "non-finite number" })
    }
}

/// Reads a similarity placement (translation, rotation, scale).
fn similarity(r: &mut Reader<'_>, kind: PrimitiveKind, parity: bool, colour: [f32; 4], mesh: u32) -> Result<Instance, SceneError> {
    let (t, q, s) = (r.f32s::<3>()?, r.f32s::<4>()?, r.f32s::<1>()?);
    finite(&t, mesh)?;
    finite(&q, mesh)?;
    finite(&s, mesh)?;
    Ok(Instance { kind, parity, translation: Vec3::from_array(t), rotation: Quat::from_array(q), scale: s[0], colour })
}

fn kind(code: u8) -> Result<PrimitiveKind, SceneError> {
    PrimitiveKind::ALL.get(usize::from(code & !PARITY_BIT)).copied().ok_or(SceneError::Kind(code))
}

/// Reads a mesh (`with_colours`) or a prototype: counts, then positions,
/// normals, colours, indices, each index checked against the vertex count.
fn read_mesh(r: &mut Reader<'_>, with_colours: bool, mesh: u32) -> Result<Mesh, SceneError> {
    let (v, t) = (r.u32()? as usize, r.u32()? as usize);
    let per_vertex = if with_colours { 28 } else { 24 };
    r.room(v as u64, per_vertex)?;
    r.room(t as u64, 12)?;
    let mut m = Mesh { positions: Vec::with_capacity(v), normals: Vec::with_capacity(v), colours: Vec::new(), indices: Vec::with_capacity(3 * t) };
    for _ in 0..v {
        let p = r.f32s::<3>()?;
        finite(&p, mesh)?;
        m.positions.push(p);
    }
    for _ in 0..v {
        m.normals.push(r.f32s::<3>()?);
    }
    if with_colours {
        m.colours.reserve_exact(v);
        for _ in 0..v {
            m.colours.push(r.take::<4>()?);
        }
    }
    for _ in 0..3 * t {
        let i = r.u32()?;
        if i as usize >= v {
            return Err(SceneError::Record { mesh, detail: "index beyond the vertices" });
        }
        m.indices.push(i);
    }
    Ok(m)
}

/// Reads a version 2 file after its header.
fn parse_v2(r: &mut Reader<'_>, header: &Header) -> Result<Parsed, SceneError> {
    let (ncolours, nprotos) = header.counts;
    r.room(u64::from(ncolours), 4)?;
    let palette: Vec<[u8; 4]> = (0..ncolours).map(|_| r.take::<4>()).collect::<Result<_, _>>()?;
    r.room(u64::from(nprotos), 8)?;
    let mut protos = Vec::with_capacity(nprotos as usize);
    for _ in 0..nprotos {
        let m = read_mesh(r, false, u32::MAX)?;
        protos.push(Prototype { positions: m.positions, normals: m.normals, indices: m.indices });
    }
    let (nshapes, nobjects) = (r.u32()?, r.u32()?);
    let hierarchy = read_hierarchy(r, nshapes, nobjects, true, header.flags & FLAG_SCALED != 0)?;
    let w = index_width(palette.len());
    let nmeshes = r.u32()?;
    r.room(u64::from(nmeshes), 6)?;
    let mut meshes = Vec::with_capacity(nmeshes as usize);
    for mi in 0..nmeshes {
        let len = r.u16()?;
        let name = std::str::from_utf8(r.slice(usize::from(len))?).map_err(|_| SceneError::Record { mesh: mi, detail: "name is not UTF-8" })?.to_string();
        let nruns = r.u32()?;
        r.room(u64::from(nruns), 5)?;
        let mut runs = Vec::with_capacity(nruns as usize);
        for _ in 0..nruns {
            let (ty, n) = (r.u8()?, r.u32()?);
            let run = match ty {
                RUN_PRIMITIVES | RUN_AFFINE | RUN_PLACED => {
                    r.room(u64::from(n), 33)?;
                    let mut records = Vec::with_capacity(n as usize);
                    for _ in 0..n {
                        records.push(match ty {
                            RUN_PRIMITIVES => {
                                let code = r.u8()?;
                                let c = colour_of(&palette, r, w, mi)?;
                                Record::Primitive(similarity(r, kind(code)?, code & PARITY_BIT != 0, c, mi)?)
                            }
                            RUN_AFFINE => {
                                let k = kind(r.u8()?)?;
                                let colour = colour_of(&palette, r, w, mi)?;
                                let (m, t) = (r.f32s::<9>()?, r.f32s::<3>()?);
                                finite(&m, mi)?;
                                finite(&t, mi)?;
                                Record::Affine(AffineInstance { kind: k, linear: Mat3::from_cols_array(&m), translation: Vec3::from_array(t), colour, class: 0 })
                            }
                            _ => {
                                let shape = r.u32()?;
                                if shape >= nprotos {
                                    return Err(SceneError::Record { mesh: mi, detail: "placement of a prototype that does not exist" });
                                }
                                let parity = r.u8()? != 0;
                                let c = colour_of(&palette, r, w, mi)?;
                                Record::Placed(shape, similarity(r, PrimitiveKind::Box, parity, c, mi)?)
                            }
                        });
                    }
                    Run::Records(records)
                }
                RUN_MESH if n == 1 => Run::Mesh(read_mesh(r, true, mi)?),
                RUN_HIERARCHY if n == 1 => Run::Hierarchy,
                _ => return Err(SceneError::Record { mesh: mi, detail: "unknown run type or count" }),
            };
            runs.push(run);
        }
        meshes.push((name, runs));
    }
    if r.at != r.bytes.len() {
        return Err(SceneError::Length("followed by trailing bytes"));
    }
    Ok(Parsed { protos, hierarchy, meshes })
}

/// Reads the object hierarchy of a scene file of either version (leaf counts
/// recomputed; the truncation flag becomes a placeholder
/// [`Hierarchy::truncated`] of the memory limit). A version 2 file without a
/// hierarchy gives an empty one; [`decode_scene_meshes`] reads everything.
pub fn decode_scene(bytes: &[u8]) -> Result<Hierarchy, SceneError> {
    let mut r = Reader { bytes, at: 0 };
    let header = read_header(&mut r)?;
    let mut h = if header.version == VERSION_1 {
        let (nshapes, nobjects) = header.counts;
        let h = read_hierarchy(&mut r, nshapes, nobjects, false, false)?;
        if r.at != r.bytes.len() {
            return Err(SceneError::Length("followed by trailing bytes"));
        }
        h
    } else {
        parse_v2(&mut r, &header)?.hierarchy
    };
    h.truncated = truncation(header.flags);
    Ok(h)
}

/// Triangles the runs make at `detail` (saturating).
fn triangles(p: &Parsed, detail: u32) -> u64 {
    let run = |run: &Run| match run {
        Run::Records(records) => records
            .iter()
            .map(|rec| match rec {
                Record::Primitive(i) => primitives::triangle_count(i.kind, detail),
                Record::Affine(a) => primitives::triangle_count(a.kind, detail),
                Record::Placed(s, _) => p.protos.get(*s as usize).map_or(0, |q| q.indices.len() as u64 / 3),
            })
            .fold(0u64, u64::saturating_add),
        Run::Mesh(m) => m.indices.len() as u64 / 3,
        Run::Hierarchy => p.hierarchy.triangles(detail),
    };
    p.meshes.iter().flat_map(|(_, runs)| runs).map(run).fold(0, u64::saturating_add)
}

/// Appends the hierarchy's expansion to `mesh`, as the flat path does: each
/// leaf placed by its world frame (walked in f64, then rounded as the mesher
/// rounds) over its leaf shape's prototype.
fn append_hierarchy(mesh: &mut Mesh, h: &Hierarchy, detail: u32) {
    let protos: Vec<Prototype> = h.shapes.iter().map(|s| s.prototype(detail)).collect();
    h.walk(&mut |leaf| {
        let frame = leaf.frame();
        let colour = leaf.colour.map(|c| f64::from(f32::from(c) / 255.0));
        let inst = Instance::new(PrimitiveKind::Box, &frame, colour);
        if let Some(p) = protos.get(leaf.shape as usize) {
            if crate::mesh::is_drawable(&inst) {
                append_instance(mesh, p, &inst);
            }
        }
    });
}

/// Decodes a scene file of either version into the meshes the flat formats
/// write for the same request, refusing (before tessellating) a file that
/// would make more than `max_triangles`. A version 1 file does not record
/// its detail; it is tessellated at `v1_detail` (the request's, 16 by default).
pub fn decode_scene_meshes(bytes: &[u8], v1_detail: u32, max_triangles: u64) -> Result<DecodedScene, SceneError> {
    let mut r = Reader { bytes, at: 0 };
    let header = read_header(&mut r)?;
    let (parsed, detail) = if header.version == VERSION_1 {
        let (nshapes, nobjects) = header.counts;
        let hierarchy = read_hierarchy(&mut r, nshapes, nobjects, false, false)?;
        if r.at != r.bytes.len() {
            return Err(SceneError::Length("followed by trailing bytes"));
        }
        let meshes = if hierarchy.leaves() > 0 { vec![("isosurfaces".to_string(), vec![Run::Hierarchy])] } else { Vec::new() };
        (Parsed { protos: Vec::new(), hierarchy, meshes }, v1_detail.clamp(crate::geom::MIN_DETAIL, crate::geom::MAX_DETAIL))
    } else {
        (parse_v2(&mut r, &header)?, header.detail.unwrap_or(16))
    };
    let t = triangles(&parsed, detail);
    if t > max_triangles {
        return Err(SceneError::TooLarge(t));
    }
    let mut kinds: [Option<Prototype>; PrimitiveKind::ALL.len()] = Default::default();
    let mut out = DecodedScene { meshes: Vec::with_capacity(parsed.meshes.len()), detail, truncated: truncation(header.flags).is_some(), provenance: header.provenance };
    for (name, runs) in &parsed.meshes {
        let mut mesh = Mesh::default();
        for run in runs {
            match run {
                Run::Records(records) => {
                    for rec in records {
                        match rec {
                            Record::Primitive(i) => append_instance(&mut mesh, kinds[i.kind as usize].get_or_insert_with(|| primitives::tessellate(i.kind, detail)), i),
                            Record::Affine(a) => append_affine(&mut mesh, kinds[a.kind as usize].get_or_insert_with(|| primitives::tessellate(a.kind, detail)), a),
                            // The index was checked when read.
                            Record::Placed(s, i) => append_instance(&mut mesh, &parsed.protos[*s as usize], i),
                        }
                    }
                }
                Run::Mesh(m) => {
                    // Fits: the triangle limit above bounds the vertex count.
                    let base = mesh.positions.len() as u32;
                    mesh.positions.extend_from_slice(&m.positions);
                    mesh.normals.extend_from_slice(&m.normals);
                    mesh.colours.extend_from_slice(&m.colours);
                    mesh.indices.extend(m.indices.iter().map(|i| i + base));
                }
                Run::Hierarchy => append_hierarchy(&mut mesh, &parsed.hierarchy, detail),
            }
        }
        out.meshes.push(NamedMesh { name: name.clone(), mesh });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    /// The decoder hands the mesher colour bytes as `b / 255`; the mesher
    /// writes `round(255 c)`: every byte must survive the trip.
    #[test]
    fn colour_bytes_survive_the_mesher() {
        for b in 0..=255u8 {
            let c = f32::from(b) / 255.0;
            assert_eq!((c.clamp(0.0, 1.0) * 255.0).round() as u8, b);
            let via_f64 = (f64::from(c).clamp(0.0, 1.0) as f32 * 255.0).round() as u8;
            assert_eq!(via_f64, b);
        }
    }
}
