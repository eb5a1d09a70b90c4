//! Per-face extrusion (Haglund 2009 §2.2.2, and the `extrude` call of §4.2).

use super::uniform;
use crate::geom::halfedge::HalfEdgeMesh;
use glam::{DQuat, DVec3};

/// Which faces an extrusion applies to.
#[derive(Debug, Clone, PartialEq)]
pub enum FaceSelect {
    /// Every face.
    All,
    /// Each face independently with this probability (seeded).
    Random(f64),
    /// These face indices (of the mesh as it enters the modifier); others are ignored.
    Faces(Vec<u32>),
}

/// Extrusion parameters. Each selected triangle is pushed out `steps` times;
/// every step copies the top triangle's corners, moves them along its normal
/// (tilted by `tilt` degrees about its first edge) by a length drawn from
/// `length`, scales them about their centroid by `scale`, and joins old and
/// new corners by three quads (six triangles): F′ = F + 6·steps per face.
#[derive(Debug, Clone, PartialEq)]
pub struct Extrude {
    /// Which faces.
    pub select: FaceSelect,
    /// Smallest and largest extrusion length per step (drawn uniformly).
    pub length: (f64, f64),
    /// Tilt of the extrusion direction from the normal, in degrees.
    pub tilt: f64,
    /// Scale of the top face per step (Haglund 2009's `move`), > 0.
    pub scale: f64,
    /// Extrusions stacked on each selected face.
    pub steps: u32,
    /// Random stream seed (lengths and random selection).
    pub seed: u64,
}

impl Default for Extrude {
    fn default() -> Self {
        Extrude { select: FaceSelect::All, length: (0.1, 0.1), tilt: 0.0, scale: 1.0, steps: 1, seed: 0 }
    }
}

impl Extrude {
    /// Checks the ranges; the message names the bad parameter.
    pub fn validate(&self) -> Result<(), String> {
        let (lo, hi) = self.length;
        if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && lo <= hi) {
            return Err(format!("length range must satisfy 0 < min ≤ max, found {lo}..{hi}"));
        }
        if !(self.scale.is_finite() && self.scale > 0.0) {
            return Err(format!("scale must be positive, found {}", self.scale));
        }
        if !(self.tilt.is_finite() && self.tilt.abs() < 90.0) {
            return Err(format!("tilt must be within ±90°, found {}", self.tilt));
        }
        if let FaceSelect::Random(p) = self.select {
            if !(0.0..=1.0).contains(&p) {
                return Err(format!("random fraction must be in [0, 1], found {p}"));
            }
        }
        Ok(())
    }

    fn selected(&self, f: usize) -> bool {
        match &self.select {
            FaceSelect::All => true,
            FaceSelect::Random(p) => uniform(self.seed, f as u64, 0) < *p,
            FaceSelect::Faces(list) => list.contains(&(f as u32)),
        }
    }
}

/// Extrudes the selected faces; unselected faces are copied unchanged.
pub(super) fn extrude(m: &HalfEdgeMesh, x: &Extrude) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut positions = m.positions.clone();
    let mut tris = Vec::with_capacity(m.face_count());
    for (f, t) in m.triangles().iter().enumerate() {
        if !x.selected(f) {
            tris.push(*t);
            continue;
        }
        let mut top = *t;
        for step in 0..x.steps {
            let [a, b, c] = top.map(|i| positions[i as usize]);
            let normal = (b - a).cross(c - a).normalize_or_zero();
            let dir = DQuat::from_axis_angle((b - a).normalize_or_zero(), x.tilt.to_radians()) * normal;
            let (lo, hi) = x.length;
            let len = lo + (hi - lo) * uniform(x.seed, f as u64, 1 + step);
            let centre = (a + b + c) / 3.0;
            let base = positions.len() as u32;
            for p in [a, b, c] {
                positions.push(centre + (p - centre) * x.scale + dir * len);
            }
            let new = [base, base + 1, base + 2];
            for k in 0..3 {
                let (p, q) = (top[k], top[(k + 1) % 3]);
                let (np, nq) = (new[k], new[(k + 1) % 3]);
                tris.push([p, q, nq]);
                tris.push([p, nq, np]);
            }
            top = new;
        }
        tris.push(top);
    }
    (positions, tris)
}
