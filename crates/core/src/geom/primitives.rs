//! Tessellation of the built-in primitives.
//!
//! Every primitive is unit-sized and centred at the origin (see
//! [`PrimitiveKind`]). Prototypes are closed, counter-clockwise seen from
//! outside, and free of degenerate triangles, so that a single instance is a
//! valid watertight solid for STL and glTF consumers alike:
//!
//! * BOX and the Platonic solids have flat normals (vertices duplicated per face);
//! * SPHERE and TORUS have smooth normals (vertices shared, the seam closed by
//!   indexing modulo the segment count);
//! * CYLINDER and CONE have smooth sides and flat caps; the cone has one apex
//!   vertex per side segment carrying that segment's side normal.
//!
//! Positions that appear in several places (cap rims, face corners) are
//! computed once and copied, so they are bit-identical and welding by
//! position closes the mesh.
//!
//! [`triangle_count`] and [`vertex_count`] give the exact sizes without
//! tessellating, so budgets can be checked before anything is allocated.

use super::{MAX_DETAIL, MIN_DETAIL};
use crate::core::PrimitiveKind;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// A primitive's tessellated prototype in its unit local space.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Prototype {
    /// Local positions.
    pub positions: Vec<[f32; 3]>,
    /// Unit normals.
    pub normals: Vec<[f32; 3]>,
    /// CCW-outward triangles.
    pub indices: Vec<u32>,
}

/// Major radius of the torus (centre of the tube to the origin).
pub(crate) const TORUS_MAJOR: f64 = 0.375;
/// Minor radius of the torus (radius of the tube).
pub(crate) const TORUS_MINOR: f64 = 0.125;

/// Clamps a detail to the accepted range, so the counting functions and the
/// tessellator agree even when handed an out-of-range value.
fn clamp_detail(detail: u32) -> u64 {
    u64::from(detail.clamp(MIN_DETAIL, MAX_DETAIL))
}

/// Latitude bands of a sphere at detail `d` (the poles are triangle fans).
fn sphere_bands(d: u64) -> u64 {
    (d / 2).max(2)
}

/// Segments around the tube of a torus at detail `d`.
fn torus_tube(d: u64) -> u64 {
    (d / 2).max(3)
}

/// Details up to this are tessellated once per process and kept
/// ([`tessellate`]): every icon render placed the same few unit primitives,
/// and computing their rings (libm's sines and cosines) again each time was
/// a visible share of a fresh render (issue 33). All kinds at every kept
/// detail hold about 3 MB; finer details are made each time.
pub(crate) const KEPT_DETAIL: u32 = 64;

/// The kept prototypes, by kind and detail, made on first use.
static KEPT: [[OnceLock<Prototype>; KEPT_DETAIL as usize + 1]; PrimitiveKind::ALL.len()] = [const { [const { OnceLock::new() }; KEPT_DETAIL as usize + 1] }; PrimitiveKind::ALL.len()];

/// Tessellates `kind` at `detail` (already clamped to MIN_DETAIL..=MAX_DETAIL;
/// out-of-range values are clamped again here). Polyhedra ignore `detail`.
/// A copy of the kept prototype for details up to [`KEPT_DETAIL`]: the same
/// arithmetic ran once, so the numbers are the same.
pub fn tessellate(kind: PrimitiveKind, detail: u32) -> Prototype {
    let d = clamp_detail(detail);
    match KEPT.get(kind as usize).and_then(|by_detail| by_detail.get(d as usize)) {
        Some(slot) => slot.get_or_init(|| make(kind, d)).clone(),
        None => make(kind, d),
    }
}

/// [`tessellate`]'s work, at a clamped detail.
fn make(kind: PrimitiveKind, detail: u64) -> Prototype {
    let d = detail as usize;
    let proto = match kind {
        PrimitiveKind::Box => box_proto(),
        PrimitiveKind::Sphere => sphere(d),
        PrimitiveKind::Cylinder => cylinder(d),
        PrimitiveKind::Cone => cone(d),
        PrimitiveKind::Torus => torus(d),
        PrimitiveKind::Tetrahedron => flat_polyhedron(&tetrahedron_vertices(), &triangle_faces(&tetrahedron_vertices())),
        PrimitiveKind::Octahedron => flat_polyhedron(&octahedron_vertices(), &triangle_faces(&octahedron_vertices())),
        PrimitiveKind::Icosahedron => flat_polyhedron(&icosahedron_vertices(), &triangle_faces(&icosahedron_vertices())),
        PrimitiveKind::Dodecahedron => {
            let v = dodecahedron_vertices();
            let faces = dodecahedron_faces(&v);
            flat_polyhedron(&v, &faces)
        }
    };
    debug_assert_eq!(proto.positions.len() as u64, vertex_count(kind, detail as u32));
    debug_assert_eq!(proto.indices.len() as u64, 3 * triangle_count(kind, detail as u32));
    proto
}

/// Triangle count of `tessellate(kind, detail)`, computed without allocating.
pub fn triangle_count(kind: PrimitiveKind, detail: u32) -> u64 {
    let d = clamp_detail(detail);
    match kind {
        PrimitiveKind::Box => 12,
        PrimitiveKind::Sphere => 2 * d * (sphere_bands(d) - 1),
        PrimitiveKind::Cylinder => 4 * d,
        PrimitiveKind::Cone => 2 * d,
        PrimitiveKind::Torus => 2 * d * torus_tube(d),
        PrimitiveKind::Tetrahedron => 4,
        PrimitiveKind::Octahedron => 8,
        PrimitiveKind::Icosahedron => 20,
        PrimitiveKind::Dodecahedron => 36,
    }
}

/// Vertex count of `tessellate(kind, detail)`, computed without allocating.
pub fn vertex_count(kind: PrimitiveKind, detail: u32) -> u64 {
    let d = clamp_detail(detail);
    match kind {
        PrimitiveKind::Box => 24,
        PrimitiveKind::Sphere => 2 + d * (sphere_bands(d) - 1),
        PrimitiveKind::Cylinder => 4 * d + 2,
        PrimitiveKind::Cone => 3 * d + 1,
        PrimitiveKind::Torus => d * torus_tube(d),
        PrimitiveKind::Tetrahedron => 12,
        PrimitiveKind::Octahedron => 24,
        PrimitiveKind::Icosahedron => 60,
        PrimitiveKind::Dodecahedron => 60,
    }
}

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalize(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    if l > 0.0 {
        [a[0] / l, a[1] / l, a[2] / l]
    } else {
        a
    }
}

fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn to_f32(a: V3) -> [f32; 3] {
    [a[0] as f32, a[1] as f32, a[2] as f32]
}

/// A unit normal in f32: normalised in f64 then rounded, which keeps the
/// length within one ulp of 1.
fn unit_f32(a: V3) -> [f32; 3] {
    to_f32(normalize(a))
}

/// `(cos φ, sin φ)` for φ = 2πj/d, j in 0..d. Every ring of a round primitive
/// reads this one table, so vertices at the same angle are bit-identical.
fn circle(d: usize) -> Vec<(f64, f64)> {
    (0..d)
        .map(|j| {
            let phi = 2.0 * PI * j as f64 / d as f64;
            (libm::cos(phi), libm::sin(phi))
        })
        .collect()
}

/// The point at angle index j on a circle of radius `r` at height `y`,
/// turning counter-clockwise about +Y as j grows (x = r cos φ, z = −r sin φ).
fn ring_point((c, s): (f64, f64), r: f64, y: f64) -> V3 {
    [r * c, y, -r * s]
}

/// Builder shared by the tessellators.
struct Builder {
    p: Prototype,
}

impl Builder {
    fn with_capacity(v: usize, t: usize) -> Builder {
        Builder {
            p: Prototype { positions: Vec::with_capacity(v), normals: Vec::with_capacity(v), indices: Vec::with_capacity(3 * t) },
        }
    }

    fn vertex(&mut self, pos: [f32; 3], normal: [f32; 3]) -> u32 {
        self.p.positions.push(pos);
        self.p.normals.push(normal);
        (self.p.positions.len() - 1) as u32
    }

    fn tri(&mut self, a: u32, b: u32, c: u32) {
        self.p.indices.extend_from_slice(&[a, b, c]);
    }
}

fn box_proto() -> Prototype {
    let mut b = Builder::with_capacity(24, 12);
    // For each face: outward normal and two in-plane axes u, v with u × v = normal,
    // so corners (−u−v, +u−v, +u+v, −u+v) run counter-clockwise seen from outside.
    let faces: [(V3, V3, V3); 6] = [
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
    ];
    for (n, u, v) in faces {
        debug_assert_eq!(cross(u, v), n);
        let base = b.p.positions.len() as u32;
        for (su, sv) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let p = [
                0.5 * (n[0] + su * u[0] + sv * v[0]),
                0.5 * (n[1] + su * u[1] + sv * v[1]),
                0.5 * (n[2] + su * u[2] + sv * v[2]),
            ];
            b.vertex(to_f32(p), to_f32(n));
        }
        b.tri(base, base + 1, base + 2);
        b.tri(base, base + 2, base + 3);
    }
    b.p
}

/// Sphere: a pole vertex at each end (fans, no degenerate triangles), then
/// `bands − 1` rings of `d` shared vertices.
fn sphere(d: usize) -> Prototype {
    let bands = sphere_bands(d as u64) as usize;
    let rings = bands - 1;
    let mut b = Builder::with_capacity(2 + d * rings, 2 * d * rings);
    let around = circle(d);
    let north = b.vertex([0.0, 0.5, 0.0], [0.0, 1.0, 0.0]);
    for i in 1..bands {
        let theta = PI * i as f64 / bands as f64;
        let (rho, y) = (libm::sin(theta), libm::cos(theta));
        for &cs in &around {
            let n = ring_point(cs, rho, y);
            b.vertex(to_f32(scale(n, 0.5)), unit_f32(n));
        }
    }
    let south = b.vertex([0.0, -0.5, 0.0], [0.0, -1.0, 0.0]);
    let ring = |i: usize, j: usize| (1 + i * d + j % d) as u32;
    for j in 0..d {
        b.tri(north, ring(0, j), ring(0, j + 1));
    }
    for i in 0..rings - 1 {
        for j in 0..d {
            let (a0, a1, b0, b1) = (ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1));
            b.tri(a0, b0, b1);
            b.tri(a0, b1, a1);
        }
    }
    for j in 0..d {
        b.tri(ring(rings - 1, j), south, ring(rings - 1, j + 1));
    }
    b.p
}

/// Cylinder: smooth side (2d vertices), flat caps as centre fans (d + 1 each).
fn cylinder(d: usize) -> Prototype {
    let mut b = Builder::with_capacity(4 * d + 2, 4 * d);
    let around = circle(d);
    let top: Vec<[f32; 3]> = around.iter().map(|&cs| to_f32(ring_point(cs, 0.5, 0.5))).collect();
    let bottom: Vec<[f32; 3]> = around.iter().map(|&cs| to_f32(ring_point(cs, 0.5, -0.5))).collect();
    // Side: top ring then bottom ring, normals radial.
    for (j, &cs) in around.iter().enumerate() {
        b.vertex(top[j], unit_f32(ring_point(cs, 1.0, 0.0)));
    }
    for (j, &cs) in around.iter().enumerate() {
        b.vertex(bottom[j], unit_f32(ring_point(cs, 1.0, 0.0)));
    }
    let t = |j: usize| (j % d) as u32;
    let bo = |j: usize| (d + j % d) as u32;
    for j in 0..d {
        b.tri(t(j), bo(j), bo(j + 1));
        b.tri(t(j), bo(j + 1), t(j + 1));
    }
    // Top cap.
    let c = b.vertex([0.0, 0.5, 0.0], [0.0, 1.0, 0.0]);
    for p in &top {
        b.vertex(*p, [0.0, 1.0, 0.0]);
    }
    for j in 0..d {
        b.tri(c, c + 1 + (j % d) as u32, c + 1 + ((j + 1) % d) as u32);
    }
    bottom_cap(&mut b, &bottom);
    b.p
}

/// A flat cap at y = −0.5 facing −Y: a centre vertex fanned to `ring`
/// (its own vertices, so the cap's normals stay flat).
fn bottom_cap(b: &mut Builder, ring: &[[f32; 3]]) {
    let d = ring.len();
    let c = b.vertex([0.0, -0.5, 0.0], [0.0, -1.0, 0.0]);
    for p in ring {
        b.vertex(*p, [0.0, -1.0, 0.0]);
    }
    for j in 0..d {
        b.tri(c, c + 1 + ((j + 1) % d) as u32, c + 1 + (j % d) as u32);
    }
}

/// Cone: base ring (d, smooth side normals), one apex per side segment (d,
/// with the normal at the segment's middle angle), flat base cap (d + 1).
fn cone(d: usize) -> Prototype {
    let mut b = Builder::with_capacity(3 * d + 1, 2 * d);
    let around = circle(d);
    let base: Vec<[f32; 3]> = around.iter().map(|&cs| to_f32(ring_point(cs, 0.5, -0.5))).collect();
    // Side normal at angle φ for radius 0.5, height 1: (cos φ, 0.5, −sin φ), normalised.
    for (j, &cs) in around.iter().enumerate() {
        b.vertex(base[j], unit_f32(ring_point(cs, 1.0, 0.5)));
    }
    for j in 0..d {
        let mid = 2.0 * PI * (j as f64 + 0.5) / d as f64;
        b.vertex([0.0, 0.5, 0.0], unit_f32(ring_point((libm::cos(mid), libm::sin(mid)), 1.0, 0.5)));
    }
    for j in 0..d {
        b.tri((d + j) as u32, j as u32, ((j + 1) % d) as u32);
    }
    bottom_cap(&mut b, &base);
    b.p
}

/// Torus in the XZ plane: d segments around the major circle, m around the tube.
fn torus(d: usize) -> Prototype {
    let m = torus_tube(d as u64) as usize;
    let mut b = Builder::with_capacity(d * m, 2 * d * m);
    let around = circle(d);
    let tube = circle(m);
    for &(cp, sp) in &around {
        for &(ct, st) in &tube {
            let n = [ct * cp, st, -ct * sp];
            let p = [(TORUS_MAJOR + TORUS_MINOR * ct) * cp, TORUS_MINOR * st, -(TORUS_MAJOR + TORUS_MINOR * ct) * sp];
            b.vertex(to_f32(p), unit_f32(n));
        }
    }
    let v = |i: usize, k: usize| ((i % d) * m + k % m) as u32;
    for i in 0..d {
        for k in 0..m {
            b.tri(v(i, k), v(i + 1, k), v(i + 1, k + 1));
            b.tri(v(i, k), v(i + 1, k + 1), v(i, k + 1));
        }
    }
    b.p
}

/// Scales `v` to circumradius 0.5.
fn to_circumradius(v: Vec<V3>) -> Vec<V3> {
    v.into_iter().map(|p| scale(normalize(p), 0.5)).collect()
}

fn tetrahedron_vertices() -> Vec<V3> {
    to_circumradius(vec![[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]])
}

fn octahedron_vertices() -> Vec<V3> {
    to_circumradius(vec![
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ])
}

fn golden() -> f64 {
    (1.0 + 5f64.sqrt()) / 2.0
}

fn icosahedron_vertices() -> Vec<V3> {
    let g = golden();
    let mut v = Vec::with_capacity(12);
    for a in [-1.0, 1.0] {
        for b in [-g, g] {
            v.push([0.0, a, b]);
            v.push([a, b, 0.0]);
            v.push([b, 0.0, a]);
        }
    }
    to_circumradius(v)
}

fn dodecahedron_vertices() -> Vec<V3> {
    let g = golden();
    let ig = 1.0 / g;
    let mut v = Vec::with_capacity(20);
    for x in [-1.0, 1.0] {
        for y in [-1.0, 1.0] {
            for z in [-1.0, 1.0] {
                v.push([x, y, z]);
            }
        }
    }
    for a in [-ig, ig] {
        for b in [-g, g] {
            v.push([0.0, a, b]);
            v.push([a, b, 0.0]);
            v.push([b, 0.0, a]);
        }
    }
    to_circumradius(v)
}

/// The triangular faces of a convex deltahedron: triples of mutually adjacent
/// vertices (pairwise at the shortest distance).
fn triangle_faces(v: &[V3]) -> Vec<Vec<usize>> {
    let mut edge = f64::INFINITY;
    for i in 0..v.len() {
        for j in i + 1..v.len() {
            let d = sub(v[i], v[j]);
            edge = edge.min(dot(d, d));
        }
    }
    let adjacent = |i: usize, j: usize| {
        let d = sub(v[i], v[j]);
        (dot(d, d) - edge).abs() < 1e-9
    };
    let mut faces = Vec::new();
    for i in 0..v.len() {
        for j in i + 1..v.len() {
            for k in j + 1..v.len() {
                if adjacent(i, j) && adjacent(j, k) && adjacent(i, k) {
                    faces.push(vec![i, j, k]);
                }
            }
        }
    }
    faces
}

/// The 12 pentagons of the dodecahedron: for each face direction (a vertex of
/// the dual icosahedron), the five dodecahedron vertices farthest along it.
fn dodecahedron_faces(v: &[V3]) -> Vec<Vec<usize>> {
    // Face directions of this dodecahedron: cyclic permutations of (0, ±φ, ±1).
    let g = golden();
    let mut axes = Vec::with_capacity(12);
    for a in [-1.0, 1.0] {
        for b in [-g, g] {
            axes.push([0.0, b, a]);
            axes.push([b, a, 0.0]);
            axes.push([a, 0.0, b]);
        }
    }
    axes.into_iter()
        .map(|axis| {
            let best = v.iter().map(|&p| dot(p, axis)).fold(f64::NEG_INFINITY, f64::max);
            (0..v.len()).filter(|&i| dot(v[i], axis) > best - 1e-9).collect()
        })
        .collect()
}

/// Flat-shaded convex polyhedron: each face (a convex polygon, vertices in any
/// order) is sorted counter-clockwise about its outward normal and fanned from
/// its first corner.
fn flat_polyhedron(v: &[V3], faces: &[Vec<usize>]) -> Prototype {
    let nv: usize = faces.iter().map(Vec::len).sum();
    let nt: usize = faces.iter().map(|f| f.len() - 2).sum();
    let mut b = Builder::with_capacity(nv, nt);
    let pts: Vec<[f32; 3]> = v.iter().map(|&p| to_f32(p)).collect();
    for face in faces {
        let k = face.len() as f64;
        let centre = face.iter().fold([0.0; 3], |acc, &i| [acc[0] + v[i][0] / k, acc[1] + v[i][1] / k, acc[2] + v[i][2] / k]);
        // A convex polyhedron centred at the origin: the face centre points outward.
        let n = normalize(centre);
        let u = normalize(sub(v[face[0]], centre));
        let w = cross(n, u);
        let mut order: Vec<(f64, usize)> = face
            .iter()
            .map(|&i| {
                let r = sub(v[i], centre);
                (libm::atan2(dot(r, w), dot(r, u)), i)
            })
            .collect();
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
        let normal = unit_f32(n);
        let base = b.p.positions.len() as u32;
        for &(_, i) in &order {
            b.vertex(pts[i], normal);
        }
        for t in 1..order.len() as u32 - 1 {
            b.tri(base, base + t, base + t + 1);
        }
    }
    b.p
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::geom::testing::{assert_closed, signed_volume};

    const DETAILS: [u32; 7] = [3, 4, 5, 7, 16, 33, 256];

    fn analytic_volume(kind: PrimitiveKind) -> f64 {
        let g = golden();
        match kind {
            PrimitiveKind::Box => 1.0,
            PrimitiveKind::Sphere => PI / 6.0,
            PrimitiveKind::Cylinder => PI * 0.25,
            PrimitiveKind::Cone => PI * 0.25 / 3.0,
            PrimitiveKind::Torus => 2.0 * PI * PI * TORUS_MAJOR * TORUS_MINOR * TORUS_MINOR,
            // Edge a from circumradius R = 0.5.
            PrimitiveKind::Tetrahedron => {
                let a = 0.5 * 4.0 / 6f64.sqrt();
                a.powi(3) / (6.0 * 2f64.sqrt())
            }
            PrimitiveKind::Octahedron => {
                let a = 0.5 * 2f64.sqrt();
                2f64.sqrt() / 3.0 * a.powi(3)
            }
            PrimitiveKind::Icosahedron => {
                let a = 0.5 / (g * g + 1.0).sqrt() * 2.0;
                5.0 / 12.0 * (3.0 + 5f64.sqrt()) * a.powi(3)
            }
            PrimitiveKind::Dodecahedron => {
                let a = 0.5 * 2.0 / (3f64.sqrt() * g);
                (15.0 + 7.0 * 5f64.sqrt()) / 4.0 * a.powi(3)
            }
        }
    }

    fn is_round(kind: PrimitiveKind) -> bool {
        matches!(kind, PrimitiveKind::Sphere | PrimitiveKind::Cylinder | PrimitiveKind::Cone | PrimitiveKind::Torus)
    }

    #[test]
    fn counts_match_tessellation() {
        for kind in PrimitiveKind::ALL {
            for d in DETAILS {
                let p = tessellate(kind, d);
                assert_eq!(p.positions.len() as u64, vertex_count(kind, d), "{kind:?} d={d}");
                assert_eq!(p.normals.len(), p.positions.len());
                assert_eq!(p.indices.len() as u64, 3 * triangle_count(kind, d), "{kind:?} d={d}");
                assert!(p.indices.iter().all(|&i| (i as usize) < p.positions.len()));
            }
        }
        // Out-of-range details are clamped consistently.
        assert_eq!(triangle_count(PrimitiveKind::Sphere, 0), triangle_count(PrimitiveKind::Sphere, MIN_DETAIL));
        assert_eq!(tessellate(PrimitiveKind::Torus, 10_000).indices.len() as u64, 3 * triangle_count(PrimitiveKind::Torus, MAX_DETAIL));
    }

    #[test]
    fn closed_with_expected_euler_characteristic() {
        for kind in PrimitiveKind::ALL {
            for d in DETAILS {
                let p = tessellate(kind, d);
                let (v, e, f) = assert_closed(&p.positions, &p.indices);
                let chi = v as i64 - e as i64 + f as i64;
                let want = if kind == PrimitiveKind::Torus { 0 } else { 2 };
                assert_eq!(chi, want, "{kind:?} d={d}: V={v} E={e} F={f}");
            }
        }
    }

    #[test]
    fn volume_positive_and_close_to_analytic() {
        for kind in PrimitiveKind::ALL {
            for d in DETAILS {
                let p = tessellate(kind, d);
                let vol = signed_volume(&p.positions, &p.indices);
                let want = analytic_volume(kind);
                assert!(vol > 0.0, "{kind:?} d={d}: volume {vol}");
                if is_round(kind) {
                    // Inscribed polygons lose area ∝ 1/d²; at d=3 a lot.
                    let tol = if d >= 32 { 0.04 } else if d >= 16 { 0.15 } else { 0.85 };
                    assert!(vol <= want * 1.0001 && vol > want * (1.0 - tol), "{kind:?} d={d}: {vol} vs {want}");
                } else {
                    assert!((vol - want).abs() < want * 1e-5, "{kind:?}: {vol} vs {want}");
                }
            }
            if is_round(kind) {
                let vol = signed_volume(&tessellate(kind, 256).positions, &tessellate(kind, 256).indices);
                assert!((vol - analytic_volume(kind)).abs() < analytic_volume(kind) * 1e-3, "{kind:?} at 256: {vol}");
            }
        }
    }

    #[test]
    fn extents_are_unit() {
        for kind in PrimitiveKind::ALL {
            let p = tessellate(kind, 64);
            let mut max_r: f64 = 0.0;
            let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
            for q in &p.positions {
                max_r = max_r.max(dot(q.map(f64::from), q.map(f64::from)).sqrt());
                for k in 0..3 {
                    lo[k] = lo[k].min(q[k]);
                    hi[k] = hi[k].max(q[k]);
                }
            }
            match kind {
                PrimitiveKind::Box => assert_eq!((lo, hi), ([-0.5; 3], [0.5; 3])),
                PrimitiveKind::Cylinder | PrimitiveKind::Cone => assert_eq!((lo[1], hi[1]), (-0.5, 0.5)),
                PrimitiveKind::Torus => assert!((max_r - 0.5).abs() < 1e-6 && (hi[1] - 0.125).abs() < 1e-6),
                _ => assert!((max_r - 0.5).abs() < 1e-6, "{kind:?}: {max_r}"),
            }
        }
    }

    #[test]
    fn normals_unit_and_agree_with_winding() {
        for kind in PrimitiveKind::ALL {
            for d in DETAILS {
                let p = tessellate(kind, d);
                for n in &p.normals {
                    let l = dot(n.map(f64::from), n.map(f64::from)).sqrt();
                    assert!((l - 1.0).abs() < 1e-6, "{kind:?}: |n| = {l}");
                }
                for t in p.indices.chunks_exact(3) {
                    let [a, b, c] = [0, 1, 2].map(|k| p.positions[t[k] as usize].map(f64::from));
                    let face = normalize(cross(sub(b, a), sub(c, a)));
                    for &i in t {
                        let n = p.normals[i as usize].map(f64::from);
                        // Smooth normals deviate from the facet by at most about one segment angle.
                        assert!(dot(face, n) > 0.2, "{kind:?} d={d}: facet {face:?} vs normal {n:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn flat_kinds_have_flat_normals() {
        for kind in [
            PrimitiveKind::Box,
            PrimitiveKind::Tetrahedron,
            PrimitiveKind::Octahedron,
            PrimitiveKind::Icosahedron,
            PrimitiveKind::Dodecahedron,
        ] {
            let p = tessellate(kind, 16);
            for t in p.indices.chunks_exact(3) {
                let [a, b, c] = [0, 1, 2].map(|k| p.positions[t[k] as usize].map(f64::from));
                let face = normalize(cross(sub(b, a), sub(c, a)));
                for &i in t {
                    assert!(dot(face, p.normals[i as usize].map(f64::from)) > 1.0 - 1e-6);
                }
            }
        }
    }

    #[test]
    fn deterministic() {
        for kind in PrimitiveKind::ALL {
            assert_eq!(tessellate(kind, 17), tessellate(kind, 17));
        }
    }
}
