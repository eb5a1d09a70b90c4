//! Archimedean solids by name and geodesic spheres by frequency.
//!
//! Each Archimedean solid is given by its classical vertex coordinates
//! (signed permutations: the "semi-regular polyhedra" of N. Nathan's
//! "Icosahedron Transformation by Rotation-Translation Operation", in
//! Séquin (ed.) 1992) and meshed
//! as their convex hull, so faces come out exactly planar and the topology
//! is checked rather than hand-written. Like the built-in primitives, every
//! solid is centred at the origin and scaled to circumradius 0.5.
//! (The Platonic solids are the built-in primitives `TETRAHEDRON`, `BOX`,
//! `OCTAHEDRON`, `DODECAHEDRON` and `ICOSAHEDRON`.)

use super::halfedge::{HalfEdgeError, HalfEdgeMesh};
use super::hull::convex_hull;
use glam::DVec3;
use std::collections::HashMap;

/// The thirteen Archimedean solids (the snubs in one chirality).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Solid {
    /// 3.6.6: 12 vertices, 4 triangles and 4 hexagons.
    TruncatedTetrahedron,
    /// 3.4.3.4: 12 vertices.
    Cuboctahedron,
    /// 3.8.8: 24 vertices.
    TruncatedCube,
    /// 4.6.6: 24 vertices.
    TruncatedOctahedron,
    /// 3.4.4.4: 24 vertices.
    Rhombicuboctahedron,
    /// 4.6.8: 48 vertices.
    TruncatedCuboctahedron,
    /// 3.3.3.3.4: 24 vertices (one chirality).
    SnubCube,
    /// 3.5.3.5: 30 vertices.
    Icosidodecahedron,
    /// 3.10.10: 60 vertices.
    TruncatedDodecahedron,
    /// 5.6.6: 60 vertices (the football).
    TruncatedIcosahedron,
    /// 3.4.5.4: 60 vertices.
    Rhombicosidodecahedron,
    /// 4.6.10: 120 vertices.
    TruncatedIcosidodecahedron,
    /// 3.3.3.3.5: 60 vertices (one chirality).
    SnubDodecahedron,
}

impl Solid {
    /// Every solid, in a fixed order.
    pub const ALL: [Solid; 13] = [
        Solid::TruncatedTetrahedron,
        Solid::Cuboctahedron,
        Solid::TruncatedCube,
        Solid::TruncatedOctahedron,
        Solid::Rhombicuboctahedron,
        Solid::TruncatedCuboctahedron,
        Solid::SnubCube,
        Solid::Icosidodecahedron,
        Solid::TruncatedDodecahedron,
        Solid::TruncatedIcosahedron,
        Solid::Rhombicosidodecahedron,
        Solid::TruncatedIcosidodecahedron,
        Solid::SnubDodecahedron,
    ];

    /// The upper-case name used in grammars.
    pub fn name(self) -> &'static str {
        match self {
            Solid::TruncatedTetrahedron => "TRUNCATED_TETRAHEDRON",
            Solid::Cuboctahedron => "CUBOCTAHEDRON",
            Solid::TruncatedCube => "TRUNCATED_CUBE",
            Solid::TruncatedOctahedron => "TRUNCATED_OCTAHEDRON",
            Solid::Rhombicuboctahedron => "RHOMBICUBOCTAHEDRON",
            Solid::TruncatedCuboctahedron => "TRUNCATED_CUBOCTAHEDRON",
            Solid::SnubCube => "SNUB_CUBE",
            Solid::Icosidodecahedron => "ICOSIDODECAHEDRON",
            Solid::TruncatedDodecahedron => "TRUNCATED_DODECAHEDRON",
            Solid::TruncatedIcosahedron => "TRUNCATED_ICOSAHEDRON",
            Solid::Rhombicosidodecahedron => "RHOMBICOSIDODECAHEDRON",
            Solid::TruncatedIcosidodecahedron => "TRUNCATED_ICOSIDODECAHEDRON",
            Solid::SnubDodecahedron => "SNUB_DODECAHEDRON",
        }
    }

    /// The solid with this name (case-insensitive).
    pub fn by_name(name: &str) -> Option<Solid> {
        Solid::ALL.into_iter().find(|s| s.name().eq_ignore_ascii_case(name))
    }

    /// Vertex and face counts of the polygon faces: (V, F).
    pub(crate) fn polygon_counts(self) -> (u64, u64) {
        match self {
            Solid::TruncatedTetrahedron => (12, 8),
            Solid::Cuboctahedron => (12, 14),
            Solid::TruncatedCube | Solid::TruncatedOctahedron => (24, 14),
            Solid::Rhombicuboctahedron => (24, 26),
            Solid::TruncatedCuboctahedron => (48, 26),
            Solid::SnubCube => (24, 38),
            Solid::Icosidodecahedron => (30, 32),
            Solid::TruncatedDodecahedron | Solid::TruncatedIcosahedron => (60, 32),
            Solid::Rhombicosidodecahedron => (60, 62),
            Solid::TruncatedIcosidodecahedron => (120, 62),
            Solid::SnubDodecahedron => (60, 92),
        }
    }

    /// Vertex and triangle counts of the mesh (a triangulated sphere: F = 2V − 4).
    pub fn size(self) -> (u64, u64) {
        let v = self.polygon_counts().0;
        (v, 2 * v - 4)
    }

    /// The solid's vertices at circumradius 0.5.
    pub fn vertices(self) -> Vec<DVec3> {
        let g = (1.0 + 5f64.sqrt()) / 2.0;
        let r2 = 2f64.sqrt();
        let sets: Vec<(DVec3, Perm)> = match self {
            Solid::TruncatedTetrahedron => {
                // Permutations of (3, 1, 1) with an even number of minus signs.
                let all = signed(&[DVec3::new(3.0, 1.0, 1.0)], Perm::All);
                return unit(all.into_iter().filter(|p| p.to_array().iter().filter(|&&c| c < 0.0).count() % 2 == 0).collect());
            }
            Solid::Cuboctahedron => vec![(DVec3::new(1.0, 1.0, 0.0), Perm::All)],
            Solid::TruncatedCube => vec![(DVec3::new(r2 - 1.0, 1.0, 1.0), Perm::All)],
            Solid::TruncatedOctahedron => vec![(DVec3::new(0.0, 1.0, 2.0), Perm::All)],
            Solid::Rhombicuboctahedron => vec![(DVec3::new(1.0, 1.0, 1.0 + r2), Perm::All)],
            Solid::TruncatedCuboctahedron => vec![(DVec3::new(1.0, 1.0 + r2, 1.0 + 2.0 * r2), Perm::All)],
            Solid::SnubCube => return unit(snub_cube()),
            Solid::SnubDodecahedron => return unit(snub_dodecahedron()),
            Solid::Icosidodecahedron => vec![(DVec3::new(0.0, 0.0, g), Perm::Cyclic), (DVec3::new(0.5, g / 2.0, g * g / 2.0), Perm::Cyclic)],
            Solid::TruncatedDodecahedron => vec![
                (DVec3::new(0.0, 1.0 / g, 2.0 + g), Perm::Cyclic),
                (DVec3::new(1.0 / g, g, 2.0 * g), Perm::Cyclic),
                (DVec3::new(g, 2.0, g + 1.0), Perm::Cyclic),
            ],
            Solid::TruncatedIcosahedron => vec![
                (DVec3::new(0.0, 1.0, 3.0 * g), Perm::Cyclic),
                (DVec3::new(1.0, 2.0 + g, 2.0 * g), Perm::Cyclic),
                (DVec3::new(g, 2.0, g * g * g), Perm::Cyclic),
            ],
            Solid::Rhombicosidodecahedron => vec![
                (DVec3::new(1.0, 1.0, g * g * g), Perm::Cyclic),
                (DVec3::new(g * g, g, 2.0 * g), Perm::Cyclic),
                (DVec3::new(2.0 + g, 0.0, g * g), Perm::Cyclic),
            ],
            Solid::TruncatedIcosidodecahedron => vec![
                (DVec3::new(1.0 / g, 1.0 / g, 3.0 + g), Perm::Cyclic),
                (DVec3::new(2.0 / g, g, 1.0 + 2.0 * g), Perm::Cyclic),
                (DVec3::new(1.0 / g, g * g, 3.0 * g - 1.0), Perm::Cyclic),
                (DVec3::new(2.0 * g - 1.0, 2.0, 2.0 + g), Perm::Cyclic),
                (DVec3::new(g, 3.0, 2.0 * g), Perm::Cyclic),
            ],
        };
        let mut all = Vec::new();
        for (v, perm) in sets {
            all.extend(signed(&[v], perm));
        }
        unit(all)
    }

    /// The solid as a closed half-edge mesh (its convex hull).
    pub fn mesh(self) -> Result<HalfEdgeMesh, HalfEdgeError> {
        convex_hull(&self.vertices()).map_err(|e| match e {
            super::hull::HullError::Mesh(m) => m,
            // The vertex sets are fixed and full-dimensional; keep a typed error anyway.
            _ => HalfEdgeError::TooLarge { triangles: 0 },
        })
    }
}

/// Which coordinate permutations a vertex set includes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Perm {
    /// All six.
    All,
    /// The three cyclic ones (even permutations).
    Cyclic,
}

/// Every sign change and the chosen permutations of each seed vertex, deduplicated in first-seen order.
fn signed(seeds: &[DVec3], perm: Perm) -> Vec<DVec3> {
    let mut out: Vec<DVec3> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for s in seeds {
        let [x, y, z] = s.to_array();
        let mut perms = vec![[x, y, z], [y, z, x], [z, x, y]];
        if perm == Perm::All {
            perms.extend([[y, x, z], [x, z, y], [z, y, x]]);
        }
        for p in perms {
            for signs in 0..8 {
                let q = DVec3::new(
                    if signs & 1 != 0 { -p[0] } else { p[0] },
                    if signs & 2 != 0 { -p[1] } else { p[1] },
                    if signs & 4 != 0 { -p[2] } else { p[2] },
                );
                // +0 and −0 are one point.
                let key = (q + DVec3::ZERO).to_array().map(|c| (c + 0.0).to_bits());
                if seen.insert(key) {
                    out.push(q + DVec3::ZERO);
                }
            }
        }
    }
    out
}

/// Snub cube: even permutations of (±1, ±1/t, ±t) with an even number of
/// plus signs, and odd permutations with an odd number; t is the tribonacci constant.
fn snub_cube() -> Vec<DVec3> {
    let s = 33f64.sqrt();
    let t = (1.0 + libm::cbrt(19.0 + 3.0 * s) + libm::cbrt(19.0 - 3.0 * s)) / 3.0;
    let (a, b, c) = (1.0, 1.0 / t, t);
    let even = [[a, b, c], [b, c, a], [c, a, b]];
    let odd = [[b, a, c], [a, c, b], [c, b, a]];
    let mut out = Vec::new();
    for (perms, parity) in [(even, 0), (odd, 1)] {
        for p in perms {
            for signs in 0u32..8 {
                let plus = 3 - signs.count_ones();
                if plus % 2 == parity {
                    out.push(DVec3::new(
                        if signs & 1 != 0 { -p[0] } else { p[0] },
                        if signs & 2 != 0 { -p[1] } else { p[1] },
                        if signs & 4 != 0 { -p[2] } else { p[2] },
                    ));
                }
            }
        }
    }
    out
}

/// Snub dodecahedron: even (cyclic) permutations with an even number of plus
/// signs of five seed points in α = ξ − 1/ξ and β = ξφ + φ² + φ/ξ, where ξ is
/// the real root of ξ³ − 2ξ = φ.
fn snub_dodecahedron() -> Vec<DVec3> {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut x = 1.7f64;
    for _ in 0..60 {
        x -= (x * x * x - 2.0 * x - g) / (3.0 * x * x - 2.0);
    }
    let (a, b) = (x - 1.0 / x, x * g + g * g + g / x);
    let seeds = [
        [2.0 * a, 2.0, 2.0 * b],
        [a + b / g + g, -a * g + b + 1.0 / g, a / g + b * g - 1.0],
        [-a / g + b * g + 1.0, -a + b / g - g, a * g + b - 1.0 / g],
        [-a / g + b * g - 1.0, a - b / g - g, a * g + b + 1.0 / g],
        [a + b / g - g, a * g - b + 1.0 / g, a / g + b * g + 1.0],
    ];
    let mut out = Vec::with_capacity(60);
    for s in seeds {
        for p in [[s[0], s[1], s[2]], [s[1], s[2], s[0]], [s[2], s[0], s[1]]] {
            for signs in 0u32..8 {
                if (3 - signs.count_ones()) % 2 == 0 {
                    out.push(DVec3::new(
                        if signs & 1 != 0 { -p[0] } else { p[0] },
                        if signs & 2 != 0 { -p[1] } else { p[1] },
                        if signs & 4 != 0 { -p[2] } else { p[2] },
                    ));
                }
            }
        }
    }
    out
}

/// Scales a centred vertex set to circumradius 0.5.
fn unit(v: Vec<DVec3>) -> Vec<DVec3> {
    let r = v.iter().fold(0.0f64, |m, p| m.max(p.length()));
    v.into_iter().map(|p| p * (0.5 / r)).collect()
}

/// Vertex and triangle counts of the geodesic sphere of frequency `n`: (10n² + 2, 20n²).
pub(crate) fn geodesic_size(n: u32) -> (u64, u64) {
    let n = u64::from(n);
    (10u64.saturating_mul(n).saturating_mul(n).saturating_add(2), 20u64.saturating_mul(n).saturating_mul(n))
}

/// A geodesic sphere (class I) of diameter 1: each icosahedron face is cut
/// into n² triangles whose corners are pushed onto the sphere. Shared corners
/// on face edges are welded by position rounded to 1e-9 of the radius.
pub fn geodesic(n: u32) -> Result<HalfEdgeMesh, HalfEdgeError> {
    let n = n.max(1);
    let ico = super::primitives::tessellate(crate::core::PrimitiveKind::Icosahedron, 3);
    let ico = HalfEdgeMesh::from_indexed(&ico.positions, &ico.indices)?;
    let mut ids: HashMap<[i64; 3], u32> = HashMap::new();
    let mut positions = Vec::new();
    let mut id = |p: DVec3, positions: &mut Vec<DVec3>| -> u32 {
        let q = p.normalize() * 0.5;
        let key = (q * 2e9).round().to_array().map(|c| c as i64);
        *ids.entry(key).or_insert_with(|| {
            positions.push(q);
            (positions.len() - 1) as u32
        })
    };
    let mut tris = Vec::with_capacity(20 * (n * n) as usize);
    let nf = f64::from(n);
    for f in 0..ico.face_count() {
        let [a, b, c] = ico.corners(f);
        let at = |i: u32, j: u32| a + (b - a) * (f64::from(i) / nf) + (c - a) * (f64::from(j) / nf);
        for i in 0..n {
            for j in 0..n - i {
                let p0 = id(at(i, j), &mut positions);
                let p1 = id(at(i + 1, j), &mut positions);
                let p2 = id(at(i, j + 1), &mut positions);
                tris.push([p0, p1, p2]);
                if i + j + 1 < n {
                    let p3 = id(at(i + 1, j + 1), &mut positions);
                    tris.push([p1, p3, p2]);
                }
            }
        }
    }
    HalfEdgeMesh::new(positions, tris)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solids_have_their_counts_and_are_closed() {
        for s in Solid::ALL {
            let m = s.mesh().unwrap_or_else(|e| panic!("{s:?}: {e}"));
            let (v, f) = s.size();
            assert_eq!((m.vertex_count() as u64, m.face_count() as u64), (v, f), "{s:?}");
            assert!(m.is_closed() && m.check_invariants(), "{s:?}");
            assert_eq!(m.euler_characteristic(), 2, "{s:?}");
            assert!(m.signed_volume() > 0.0);
            // Every vertex on the circumsphere; every edge of the hull's
            // polygon faces has one length (only polygon edges are that short).
            assert!(m.positions.iter().all(|p| (p.length() - 0.5).abs() < 1e-12), "{s:?}");
            let shortest = (0..m.halfedge_count() as u32).map(|h| m.positions[m.tail(h) as usize].distance(m.positions[m.head(h) as usize])).fold(f64::INFINITY, f64::min);
            let polygon_edges = (0..m.halfedge_count() as u32)
                .filter(|&h| (m.positions[m.tail(h) as usize].distance(m.positions[m.head(h) as usize]) - shortest).abs() < 1e-9)
                .count()
                / 2;
            let (pv, pf) = s.polygon_counts();
            assert_eq!(polygon_edges as u64, pv + pf - 2, "{s:?}: polygon edges");
            assert_eq!(Solid::by_name(&s.name().to_ascii_lowercase()), Some(s));
        }
    }

    #[test]
    fn geodesic_counts() {
        for n in [1, 2, 3, 5] {
            let m = geodesic(n).expect("geodesic");
            let (v, f) = geodesic_size(n);
            assert_eq!((m.vertex_count() as u64, m.face_count() as u64), (v, f));
            assert!(m.is_closed() && m.euler_characteristic() == 2 && m.signed_volume() > 0.0);
        }
    }
}
