//! The printability report: what a slicer would want to know first, and
//! what is wrong against the printer profile ([`super::findings`]).

use super::findings::Finding;
use super::profile::PrinterProfile;
use crate::geom::halfedge::HalfEdgeMesh;
use glam::DVec3;
use serde::{Deserialize, Serialize};

/// Measurements of the printable solid, in millimetres.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct PrintReport {
    /// Enclosed volume (mm³).
    pub volume_mm3: f64,
    /// Surface area (mm²).
    pub surface_area_mm2: f64,
    /// Bounding-box size (mm).
    pub bbox_mm: [f64; 3],
    /// Connected shells of the result (1 for one printable piece).
    pub shells: u64,
    /// Every edge has exactly two faces, wound oppositely, and no vertex is pinched.
    pub is_watertight: bool,
    /// Triangles in the result.
    pub triangles: u64,
    /// Closed parts united.
    pub parts: u64,
    /// Parts left out because they are open or not manifold.
    pub skipped_parts: u64,
    /// Open or non-manifold parts (free-vertex surfaces, loose triangles)
    /// thickened into walls of `wall_mm` instead of being left out.
    pub thickened_parts: u64,
    /// Thickness of those walls (mm); 0 when nothing was thickened.
    pub wall_mm: f64,
    /// Gaps narrower than this were closed (mm): 0 when the parts' exact
    /// union was printed; else twice the closing radius of the fused route
    /// (contacts become connections, `fuse`).
    pub fused_gap_mm: f64,
    /// Connections the fused route added between pieces that were apart.
    pub bridges: u64,
    /// Enclosed voids filled (they would trap material): by the fused
    /// route before extraction, or by dropping the inward shells of an exact union.
    pub filled_voids: u64,
    /// The fused route's sample spacing (mm): its surface is within about
    /// this of the parts' (sharp edges are rounded by about as much); 0 when
    /// the exact union was printed.
    pub sample_mm: f64,
    /// Smallest bounding-box side of any part (mm): a rough estimate of the
    /// thinnest feature, kept for older clients; `thinnest_wall_mm` is measured.
    pub min_feature_mm: f64,
    /// The thinnest wall measured (mm, by rays inward from the surface,
    /// [`super::thickness`]); `None` when nothing was measured.
    pub thinnest_wall_mm: Option<f64>,
    /// Where that wall starts on the surface (mm).
    pub thinnest_wall_at_mm: Option<[f64; 3]>,
    /// Rays cast to measure walls (one per triangle, or an even sample of at most 50,000).
    pub wall_rays: u64,
    /// Rays that measured less than the profile's minimum wall.
    pub thin_wall_places: u64,
    /// The surface area those rays left from (mm²).
    pub thin_wall_area_mm2: f64,
    /// The printer profile the findings are judged against.
    pub profile: ProfileReport,
    /// Model units per millimetre applied.
    pub scale: f64,
    /// Edges with other than two faces, or two faces wound the same way: where
    /// parts touch only along an edge or at a point, the union is not a 2-manifold.
    pub nonmanifold_edges: u64,
    /// What is wrong against the profile: codes, messages, places, values.
    pub findings: Vec<Finding>,
    /// The findings' messages (kept for clients that read text).
    pub warnings: Vec<String>,
}

/// The printer profile as the report shows it, in millimetres.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ProfileReport {
    /// Thinnest wall the printer makes (mm).
    pub min_wall_mm: f64,
    /// Build volume x, y, z (mm).
    pub build_volume_mm: [f64; 3],
    /// Most triangles accepted.
    pub triangle_ceiling: u64,
}

impl PrintReport {
    /// Judges the measurements against `profile`: the findings, and the
    /// warnings (their messages).
    pub(super) fn judge(&mut self, profile: &PrinterProfile) {
        self.profile = ProfileReport { min_wall_mm: profile.min_wall_mm(), build_volume_mm: profile.build_mm(), triangle_ceiling: profile.triangle_ceiling.into() };
        self.findings = super::findings::findings(self, profile);
        self.warnings = self.findings.iter().map(|f| f.message.clone()).collect();
    }

    /// The headline figures, stored beside the model's bytes in every
    /// cache tier so that each door serves them without measuring again.
    pub fn summary(&self) -> PrintSummary {
        PrintSummary { volume_mm3: self.volume_mm3, surface_area_mm2: self.surface_area_mm2, bbox_mm: self.bbox_mm, shells: self.shells, watertight: self.is_watertight }
    }
}

/// A printed model's headline figures: what HTTP sends as `X-Print-…`
/// headers (STL and 3MF alike) and gRPC as `RenderMeta.print`. The print
/// stage measures them once; the cache keeps them with the bytes (issue 32,
/// "artifacts travel with the bytes"), so no door re-reads served bytes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct PrintSummary {
    /// Enclosed volume (mm³).
    pub volume_mm3: f64,
    /// Surface area (mm²).
    pub surface_area_mm2: f64,
    /// Bounding-box size (mm).
    pub bbox_mm: [f64; 3],
    /// Connected shells (1 for one printable piece).
    pub shells: u64,
    /// Every edge has exactly two faces, wound oppositely, and no vertex is pinched.
    pub watertight: bool,
}

impl PrintSummary {
    /// The figures as HTTP header pairs (`X-Print-…`), for responses that carry the model.
    pub fn headers(&self) -> Vec<(&'static str, String)> {
        vec![
            ("x-print-volume-mm3", format!("{:.3}", self.volume_mm3)),
            ("x-print-surface-area-mm2", format!("{:.3}", self.surface_area_mm2)),
            ("x-print-bbox-mm", format!("{:.3} {:.3} {:.3}", self.bbox_mm[0], self.bbox_mm[1], self.bbox_mm[2])),
            ("x-print-shells", self.shells.to_string()),
            ("x-print-watertight", self.watertight.to_string()),
        ]
    }
}

/// Measures a solid given as shared positions and CCW triangles.
pub fn measure(positions: &[[f32; 3]], indices: &[u32]) -> PrintReport {
    let p: Vec<DVec3> = positions.iter().map(|q| DVec3::from_array(q.map(f64::from))).collect();
    let tris: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let (mut volume, mut area) = (0.0, 0.0);
    for t in &tris {
        let [a, b, c] = t.map(|i| p[i as usize]);
        volume += a.dot(b.cross(c)) / 6.0;
        area += (b - a).cross(c - a).length() / 2.0;
    }
    let (lo, hi) = super::bounds(p.iter().copied());
    let bbox = if p.is_empty() { [0.0; 3] } else { (hi - lo).to_array() };
    let (watertight, shells) = match HalfEdgeMesh::from_indexed(positions, indices) {
        Ok(m) => (m.is_closed() && m.nonmanifold_vertices().is_empty(), shell_count(&m)),
        Err(_) => (false, 0),
    };
    let nonmanifold_edges = if watertight { 0 } else { bad_edges(positions, indices) };
    PrintReport {
        volume_mm3: volume,
        surface_area_mm2: area,
        bbox_mm: bbox,
        shells,
        is_watertight: watertight,
        triangles: tris.len() as u64,
        nonmanifold_edges,
        ..PrintReport::default()
    }
}

/// Undirected edges (vertices welded by position) not used exactly once in each direction.
pub(super) fn bad_edges(positions: &[[f32; 3]], indices: &[u32]) -> u64 {
    let key = |i: u32| positions.get(i as usize).map_or([0; 3], |p| p.map(f32::to_bits));
    let mut uses: std::collections::HashMap<([u32; 3], [u32; 3]), (u32, u32), foldhash::fast::FixedState> = std::collections::HashMap::default();
    for t in indices.chunks_exact(3) {
        for k in 0..3 {
            let (a, b) = (key(t[k]), key(t[(k + 1) % 3]));
            let e = uses.entry((a.min(b), a.max(b))).or_default();
            if a < b {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
    }
    uses.values().filter(|&&(f, r)| (f, r) != (1, 1)).count() as u64
}

/// Connected components of the faces (through shared edges).
fn shell_count(m: &HalfEdgeMesh) -> u64 {
    let mut seen = vec![false; m.face_count()];
    let mut shells = 0;
    for start in 0..m.face_count() {
        if seen[start] {
            continue;
        }
        shells += 1;
        seen[start] = true;
        let mut stack = vec![start];
        while let Some(f) = stack.pop() {
            for k in 0..3 {
                let p = m.pair((3 * f + k) as u32);
                if p != crate::geom::halfedge::NO_PAIR {
                    let g = HalfEdgeMesh::face(p) as usize;
                    if !seen[g] {
                        seen[g] = true;
                        stack.push(g);
                    }
                }
            }
        }
    }
    shells
}
