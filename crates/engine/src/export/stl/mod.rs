//! STL export, binary and ASCII.
//!
//! STL stores unindexed triangles with one facet normal each; all meshes are
//! concatenated into one solid. Facet normals are recomputed from the
//! triangle's winding (which already accounts for reflected instances), since
//! STL readers take the winding and the facet normal to agree. Output bytes
//! are accounted in the [`Budget`] before they are allocated.

use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::{ExportError, ExportMeta, ExportOptions};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use std::fmt::Write as _;

/// Binary STL header size.
const HEADER: usize = 80;
/// Bytes per binary STL triangle: normal, three vertices (12 f32), attribute u16.
const TRIANGLE_BYTES: u64 = 50;
/// Upper bound on one ASCII facet's length (see [`write_ascii`]), the
/// per-triangle size bound of [`STL_ASCII`].
const ASCII_FACET_MAX: u64 = 300;

/// `stl`: binary STL, 84 bytes of header and count and 50 a triangle.
pub const STL: FormatInfo = FormatInfo {
    name: "stl",
    extensions: &["stl"],
    mime: "model/stl",
    caps: Capabilities { positions_only: true, ..Capabilities::NONE },
    options: OptionGroup::None,
    size: SizeBound { fixed: 84, per_vertex: 0, per_triangle: TRIANGLE_BYTES, per_instance: 0 },
    writer: Writer::Sink { flat: write_binary_with, model: None },
};

/// `stl-ascii`: ASCII STL, at most [`ASCII_FACET_MAX`] bytes a facet. It
/// shares `.stl` with binary STL, which claims it first: an `.stl` file is
/// binary unless the format is named.
pub(crate) const STL_ASCII: FormatInfo = FormatInfo {
    name: "stl-ascii",
    extensions: &["stl"],
    mime: "model/stl",
    caps: Capabilities { text: true, positions_only: true, ..Capabilities::NONE },
    options: OptionGroup::None,
    size: SizeBound { fixed: 1024, per_vertex: 0, per_triangle: ASCII_FACET_MAX, per_instance: 0 },
    writer: Writer::Sink { flat: write_ascii_with, model: None },
};

/// Binary STL titled with the model's provenance.
fn write_binary_with(meshes: &[NamedMesh], meta: &ExportMeta, _: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_binary_titled(meshes, &title(meta.provenance.as_ref()), budget)
}

/// ASCII STL (it has no room for metadata).
fn write_ascii_with(meshes: &[NamedMesh], _: &ExportMeta, _: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_ascii(meshes, budget)
}

/// Total triangles, rejecting meshes with indices out of range (which would
/// otherwise make the writer panic).
fn triangle_total(meshes: &[NamedMesh]) -> Result<u64, ExportError> {
    let mut total = 0u64;
    for m in meshes {
        let n = m.mesh.positions.len();
        if m.mesh.indices.iter().any(|&i| i as usize >= n) {
            return Err(ExportError::InvalidMesh { name: m.name.clone(), detail: "index out of range".into() });
        }
        total = total.saturating_add(m.mesh.triangle_count() as u64);
    }
    Ok(total)
}

/// Every triangle as (facet normal, three corners), in mesh order.
fn triangles(meshes: &[NamedMesh]) -> impl Iterator<Item = ([f32; 3], [[f32; 3]; 3])> + '_ {
    meshes.iter().flat_map(|m| {
        m.mesh.indices.chunks_exact(3).map(move |t| {
            let c = [0, 1, 2].map(|k| m.mesh.positions[t[k] as usize]);
            (facet_normal(&c), c)
        })
    })
}

/// The unit normal of a counter-clockwise triangle, computed in f64 so thin
/// triangles still get an accurate direction; zero for a degenerate one.
fn facet_normal(c: &[[f32; 3]; 3]) -> [f32; 3] {
    let [a, b, d] = c.map(|p| p.map(f64::from));
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
    let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 && len.is_finite() {
        n.map(|x| (x / len) as f32)
    } else {
        [0.0; 3]
    }
}

/// Writes binary STL: an 80-byte header starting with `rulemesh`, the u32
/// triangle count, then per triangle the facet normal, three vertices (f32
/// little-endian) and a zero attribute word. The exact size, 84 + 50·T bytes,
/// is reserved in `budget` first.
#[cfg(test)]
pub(crate) fn write_binary(meshes: &[NamedMesh], budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_binary_titled(meshes, &title(None), budget)
}

/// The binary header's text: `rulemesh <version> binary STL`, and with a
/// provenance the language and seed instead (`rulemesh 0.1.0 mdg seed=7`).
/// The 80-byte header has no room for the parameters and the model key;
/// the formats with metadata (glTF, 3MF, PNG, scene) carry those. Never starts with `solid`, which
/// would make readers take the file for ASCII STL.
pub fn title(provenance: Option<&crate::export::Provenance>) -> String {
    match provenance {
        Some(p) => format!("{} {} seed={}", crate::export::Provenance::engine(), p.language.name(), p.seed),
        None => format!("rulemesh {} binary STL", crate::ENGINE_VERSION),
    }
}

/// [`write_binary`] with `title` in the header (cut at 80 bytes).
pub(crate) fn write_binary_titled(meshes: &[NamedMesh], title: &str, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let count = triangle_total(meshes)?;
    let count32 = u32::try_from(count)
        .map_err(|_| ExportError::TooLarge { format: STL.name, detail: format!("{count} triangles exceed the u32 triangle count") })?;
    let total = 84u64.saturating_add(count.saturating_mul(TRIANGLE_BYTES));
    budget.reserve_memory(total)?;
    let mut out = Vec::with_capacity(usize::try_from(total).map_err(|_| ExportError::TooLarge { format: STL.name, detail: "output exceeds the address space".into() })?);
    let mut header = [0u8; HEADER];
    let n = title.len().min(HEADER);
    header[..n].copy_from_slice(&title.as_bytes()[..n]);
    out.extend_from_slice(&header);
    out.extend_from_slice(&count32.to_le_bytes());
    for (k, (normal, corners)) in triangles(meshes).enumerate() {
        if k % crate::export::DEADLINE_EVERY == 0 {
            budget.check_deadline()?;
        }
        for v in std::iter::once(normal).chain(corners) {
            for c in v {
                out.extend_from_slice(&c.to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    debug_assert_eq!(out.len() as u64, total);
    Ok(out)
}

/// Writes ASCII STL (`solid rulemesh` … `endsolid rulemesh`).
///
/// Numbers use Rust's `{:e}` for f32: the shortest text that reads back to
/// the same f32, so positions shared by neighbouring triangles stay
/// identical and the output is deterministic. A facet is at most 284 bytes
/// (each number at most 15 characters); [`ASCII_FACET_MAX`] per facet is
/// reserved first and the unused part released once the text is written.
pub(crate) fn write_ascii(meshes: &[NamedMesh], budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    const HEAD: &str = "solid rulemesh\n";
    const TAIL: &str = "endsolid rulemesh\n";
    let count = triangle_total(meshes)?;
    let bound = ((HEAD.len() + TAIL.len()) as u64).saturating_add(count.saturating_mul(ASCII_FACET_MAX));
    let cap = usize::try_from(bound).map_err(|_| ExportError::TooLarge { format: STL.name, detail: "output exceeds the address space".into() })?;
    budget.reserve_memory(bound)?;
    let mut out = String::with_capacity(cap);
    out.push_str(HEAD);
    for (k, (n, [a, b, c])) in triangles(meshes).enumerate() {
        if k % crate::export::DEADLINE_EVERY == 0 {
            budget.check_deadline()?;
        }
        // Writing into a String cannot fail.
        let _ = write!(
            out,
            "facet normal {:e} {:e} {:e}\n outer loop\n  vertex {:e} {:e} {:e}\n  vertex {:e} {:e} {:e}\n  vertex {:e} {:e} {:e}\n endloop\nendfacet\n",
            n[0], n[1], n[2], a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]
        );
    }
    out.push_str(TAIL);
    debug_assert!(out.len() as u64 <= bound);
    budget.release_memory(bound - out.len() as u64);
    let mut bytes = out.into_bytes();
    bytes.shrink_to_fit();
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::{Limit, Limits};
    use crate::export::gltf::tests::{all_nine, meshes_of};
    use crate::export::{estimated_size, Format};
    use crate::mesh::tests::{inst, scene};
    use crate::geom::testing::{assert_closed, signed_volume};
    use crate::mesh::MeshLayout;
    use crate::core::PrimitiveKind;

    fn f32_at(b: &[u8], at: usize) -> f32 {
        f32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
    }

    /// Reads binary STL back to (normals, flat corner list).
    fn parse_binary(b: &[u8]) -> (Vec<[f32; 3]>, Vec<[f32; 3]>) {
        let n = u32::from_le_bytes([b[80], b[81], b[82], b[83]]) as usize;
        assert_eq!(b.len(), 84 + 50 * n);
        let mut normals = Vec::new();
        let mut corners = Vec::new();
        for t in 0..n {
            let at = 84 + 50 * t;
            let v = |k: usize| [0, 1, 2].map(|c| f32_at(b, at + 12 * k + 4 * c));
            normals.push(v(0));
            corners.extend([v(1), v(2), v(3)]);
            assert_eq!(&b[at + 48..at + 50], &[0, 0]);
        }
        (normals, corners)
    }

    /// Reads ASCII STL back to a flat corner list, checking the grammar.
    fn parse_ascii(text: &str) -> Vec<[f32; 3]> {
        let mut lines = text.lines().map(str::trim);
        assert_eq!(lines.next(), Some("solid rulemesh"));
        let mut corners = Vec::new();
        let nums = |s: &str| -> [f32; 3] {
            let v: Vec<f32> = s.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        };
        loop {
            let l = lines.next().unwrap();
            if l == "endsolid rulemesh" {
                break;
            }
            nums(l.strip_prefix("facet normal ").unwrap());
            assert_eq!(lines.next(), Some("outer loop"));
            for _ in 0..3 {
                corners.push(nums(lines.next().unwrap().strip_prefix("vertex ").unwrap()));
            }
            assert_eq!(lines.next(), Some("endloop"));
            assert_eq!(lines.next(), Some("endfacet"));
        }
        assert_eq!(lines.next(), None);
        corners
    }

    fn counts(meshes: &[NamedMesh]) -> (u64, u64) {
        meshes.iter().fold((0, 0), |(v, t), m| (v + m.mesh.positions.len() as u64, t + m.mesh.triangle_count() as u64))
    }

    #[test]
    fn binary_layout_and_closed_solids() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::PerKind);
        let (_, t) = counts(&meshes);
        let mut b = Budget::new(Limits::default());
        let out = write_binary(&meshes, &mut b).unwrap();
        assert!(out.starts_with(b"rulemesh"));
        assert_eq!(out.len() as u64, 84 + 50 * t);
        assert_eq!(b.memory(), out.len() as u64);
        assert!(out.len() as u64 <= estimated_size(Format::Stl, 0, t));
        let (normals, corners) = parse_binary(&out);
        let idx: Vec<u32> = (0..corners.len() as u32).collect();
        assert_closed(&corners, &idx);
        assert!(signed_volume(&corners, &idx) > 0.0);
        for (n, c) in normals.iter().zip(corners.chunks_exact(3)) {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-5);
            assert_eq!(*n, facet_normal(&[c[0], c[1], c[2]]));
        }
    }

    #[test]
    fn ascii_round_trips_exactly() {
        let meshes = meshes_of(&all_nine(), 9, MeshLayout::Merged);
        let (_, t) = counts(&meshes);
        let mut b = Budget::new(Limits::default());
        let out = write_ascii(&meshes, &mut b).unwrap();
        assert_eq!(b.memory(), out.len() as u64);
        assert!(out.len() as u64 <= estimated_size(Format::StlAscii, 0, t));
        let corners = parse_ascii(std::str::from_utf8(&out).unwrap());
        assert_eq!(corners.len() as u64, 3 * t);
        let (_, bin) = parse_binary(&write_binary(&meshes, &mut Budget::new(Limits::default())).unwrap());
        assert_eq!(corners, bin);
    }

    #[test]
    fn positions_only_meshes_write_the_same_bytes() {
        let meshes = meshes_of(&all_nine(), 12, MeshLayout::Merged);
        let mut lean = meshes.clone();
        crate::export::keep_positions_only(&mut lean);
        assert!(lean.iter().all(|m| m.mesh.normals.is_empty() && m.mesh.colours.is_empty()));
        let write = |m: &[NamedMesh], ascii: bool| if ascii { write_ascii(m, &mut Budget::new(Limits::default())) } else { write_binary(m, &mut Budget::new(Limits::default())) }.unwrap();
        for ascii in [false, true] {
            assert_eq!(write(&lean, ascii), write(&meshes, ascii));
        }
    }

    #[test]
    fn mirrored_solids_stay_outward() {
        let meshes = meshes_of(&scene(vec![inst(PrimitiveKind::Cone, [1.0, 2.0, 3.0], 1.5, true)]), 16, MeshLayout::Merged);
        let (_, corners) = parse_binary(&write_binary(&meshes, &mut Budget::new(Limits::default())).unwrap());
        let idx: Vec<u32> = (0..corners.len() as u32).collect();
        assert!(signed_volume(&corners, &idx) > 0.0);
    }

    #[test]
    fn ascii_facet_bound_holds_for_long_numbers() {
        let p = [-1.1754944e-38f32, -3.4028235e38, -1.2345679e-12];
        let mesh = crate::geom::Mesh { positions: vec![p; 3], normals: vec![[0.0; 3]; 3], colours: vec![[0; 4]; 3], indices: vec![0, 1, 2] };
        let out = write_ascii(&[NamedMesh { name: "x".into(), mesh }], &mut Budget::new(Limits::default())).unwrap();
        assert!(out.len() as u64 - 33 <= ASCII_FACET_MAX, "{}", out.len());
    }

    #[test]
    fn empty_and_deterministic() {
        let out = write_binary(&[], &mut Budget::new(Limits::default())).unwrap();
        assert_eq!(out.len(), 84);
        let out = write_ascii(&[], &mut Budget::new(Limits::default())).unwrap();
        assert_eq!(out, b"solid rulemesh\nendsolid rulemesh\n");
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::Merged);
        let lim = Limits::default();
        assert_eq!(write_binary(&meshes, &mut Budget::new(lim)).unwrap(), write_binary(&meshes, &mut Budget::new(lim)).unwrap());
        assert_eq!(write_ascii(&meshes, &mut Budget::new(lim)).unwrap(), write_ascii(&meshes, &mut Budget::new(lim)).unwrap());
    }

    #[test]
    fn budget_refusal() {
        let meshes = meshes_of(&all_nine(), 16, MeshLayout::Merged);
        for f in [write_binary, write_ascii] {
            let mut b = Budget::new(Limits { max_memory: 1000, ..Limits::default() });
            match f(&meshes, &mut b) {
                Err(ExportError::Limit(e)) => assert_eq!(e.limit, Limit::Memory),
                other => panic!("expected a memory limit, got {other:?}"),
            }
            assert_eq!(b.memory(), 0);
        }
    }
}
