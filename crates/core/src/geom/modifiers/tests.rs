//! Done-when counts of issue #7, and counts worked out from Haglund 2009
//! (eq 2.6's β, subdivision, spikeify and extrusion face counts).

use super::syntax::{stack, stage, Word};
use super::*;
use crate::core::budget::Limits;
use crate::geom::primitives::tessellate;

fn base(kind: PrimitiveKind) -> HalfEdgeMesh {
    let p = tessellate(kind, 16);
    HalfEdgeMesh::from_indexed(&p.positions, &p.indices).expect("manifold primitive")
}

fn run(kind: PrimitiveKind, ops: &[Modifier]) -> HalfEdgeMesh {
    let mut budget = Budget::new(Limits::default());
    let m = apply_all(base(kind), ops, &mut budget).expect("modifiers apply");
    assert_eq!(budget.memory(), 0, "every reservation is released");
    m
}

fn vef(m: &HalfEdgeMesh) -> (usize, usize, usize) {
    (m.vertex_count(), m.edge_count(), m.face_count())
}

fn closed_genus0(m: &HalfEdgeMesh) {
    assert!(m.is_closed(), "closed");
    assert!(m.check_invariants(), "pair/next invariants");
    assert!(m.nonmanifold_vertices().is_empty(), "manifold vertices");
    assert_eq!(m.euler_characteristic(), 2, "genus 0");
    assert!(m.signed_volume() > 0.0, "outward orientation");
}

#[test]
fn beta_matches_eq_2_6() {
    assert!((loop_beta(3) - 0.1875).abs() < 1e-15);
    assert!((loop_beta(4) - 31.0 / 256.0).abs() < 1e-15);
    assert!((loop_beta(5) - 0.084_093_2).abs() < 1e-7);
    assert!((loop_beta(6) - 0.0625).abs() < 1e-15);
}

#[test]
fn octahedron_subdivided_twice_has_128_faces() {
    let once = run(PrimitiveKind::Octahedron, &[Modifier::Subdivide { levels: 1, weight: 1.0, smooth: true }]);
    assert_eq!(vef(&once), (18, 48, 32));
    let m = run(PrimitiveKind::Octahedron, &[Modifier::Subdivide { levels: 2, weight: 1.0, smooth: true }]);
    assert_eq!(vef(&m), (66, 192, 128));
    assert_eq!(m.halfedge_count(), 384);
    closed_genus0(&m);
    // Old vertices keep valence 4, new ones have 6.
    let valences: Vec<usize> = (0..m.vertex_count() as u32).map(|v| m.fan(v).len()).collect();
    assert_eq!(valences.iter().filter(|&&n| n == 4).count(), 6);
    assert_eq!(valences.iter().filter(|&&n| n == 6).count(), 60);
    // Smoothing shrinks towards the limit surface; weight 1.4 shrinks more.
    let heavy = run(PrimitiveKind::Octahedron, &[Modifier::Subdivide { levels: 2, weight: 1.4, smooth: true }]);
    assert!(heavy.signed_volume() < m.signed_volume());
}

#[test]
fn split_keeps_old_vertices_and_uses_midpoints() {
    let b = base(PrimitiveKind::Icosahedron);
    let m = run(PrimitiveKind::Icosahedron, &[Modifier::Subdivide { levels: 1, weight: 1.0, smooth: false }]);
    assert_eq!(&m.positions[..12], &b.positions[..]);
    for v in 12..m.vertex_count() as u32 {
        let ring = m.neighbours(v);
        // Each new vertex is the midpoint of two old ones among its neighbours.
        let old: Vec<u32> = ring.into_iter().filter(|&n| n < 12).collect();
        assert_eq!(old.len(), 2);
        let mid = (m.positions[old[0] as usize] + m.positions[old[1] as usize]) / 2.0;
        assert!(mid.distance(m.positions[v as usize]) < 1e-15);
    }
    closed_genus0(&m);
    // The stage syntax agrees.
    assert_eq!(stage("split", &[]).expect("split"), Modifier::Subdivide { levels: 1, weight: 1.0, smooth: false });
}

#[test]
fn spikeify_icosahedron_has_60_faces() {
    let m = run(PrimitiveKind::Icosahedron, &[Modifier::Spikeify { height: 0.1 }]);
    assert_eq!(vef(&m), (32, 90, 60));
    closed_genus0(&m);
    // Each apex is 0.1 above its base face's plane.
    let b = base(PrimitiveKind::Icosahedron);
    for f in 0..20 {
        let [a, _, _] = b.corners(f);
        let apex = m.positions[12 + f];
        assert!(((apex - a).dot(b.face_normal(f)) - 0.1).abs() < 1e-12);
    }
}

#[test]
fn extrude_counts() {
    // Both triangles of one box face, once: +12 faces, +6 vertices, +18 edges.
    let x = Extrude { select: FaceSelect::Faces(vec![0, 1]), length: (0.25, 0.25), ..Extrude::default() };
    let m = run(PrimitiveKind::Box, &[Modifier::Extrude(x)]);
    assert_eq!(vef(&m), (8 + 6, 18 + 18, 12 + 12));
    closed_genus0(&m);
    // Every icosahedron face once: F140 V72 E210; k steps: F = 20 + 120k.
    let all = run(PrimitiveKind::Icosahedron, &[Modifier::Extrude(Extrude::default())]);
    assert_eq!(vef(&all), (72, 210, 140));
    closed_genus0(&all);
    let three = Extrude { steps: 3, scale: 0.8, tilt: 10.0, length: (0.05, 0.2), seed: 7, ..Extrude::default() };
    let m3 = run(PrimitiveKind::Icosahedron, &[Modifier::Extrude(three)]);
    assert_eq!(m3.face_count(), 20 + 120 * 3);
    closed_genus0(&m3);
    // Random selection is seeded and repeatable.
    let r = Extrude { select: FaceSelect::Random(0.5), seed: 3, ..Extrude::default() };
    let a = run(PrimitiveKind::Icosahedron, &[Modifier::Extrude(r.clone())]);
    assert_eq!(a, run(PrimitiveKind::Icosahedron, &[Modifier::Extrude(r)]));
    assert_eq!((a.face_count() - 20) % 6, 0);
}

#[test]
fn randomize_is_bounded_and_seeded() {
    let b = base(PrimitiveKind::Icosahedron);
    let shortest = (0..b.halfedge_count() as u32).map(|h| b.positions[b.tail(h) as usize].distance(b.positions[b.head(h) as usize])).fold(f64::INFINITY, f64::min);
    let m = run(PrimitiveKind::Icosahedron, &[Modifier::Randomize { amount: 0.4, seed: 9 }]);
    let mut moved = 0.0f64;
    for (p, q) in b.positions.iter().zip(&m.positions) {
        moved = moved.max(p.distance(*q));
    }
    assert!(moved > 0.0 && moved <= 0.4 * shortest + 1e-15);
    assert_eq!(m, run(PrimitiveKind::Icosahedron, &[Modifier::Randomize { amount: 0.4, seed: 9 }]));
    assert_ne!(m, run(PrimitiveKind::Icosahedron, &[Modifier::Randomize { amount: 0.4, seed: 10 }]));
    closed_genus0(&m);
    let mut budget = Budget::new(Limits::default());
    assert!(matches!(apply_all(b, &[Modifier::Randomize { amount: 0.6, seed: 0 }], &mut budget), Err(ModifyError::Invalid { .. })));
}

#[test]
fn deformers_keep_topology() {
    for op in [
        Modifier::Displace { amount: 0.05, fraction: 0.5, seed: 1 },
        Modifier::Twist { axis: Axis::Y, degrees_per_unit: 90.0 },
        Modifier::Bend { degrees: 60.0 },
        Modifier::Translate(DVec3::new(1.0, 2.0, 3.0)),
        Modifier::Scale(DVec3::new(1.0, 2.0, 0.5)),
    ] {
        let m = run(PrimitiveKind::Sphere, &[Modifier::Subdivide { levels: 1, weight: 1.0, smooth: false }, op.clone()]);
        closed_genus0(&m);
    }
    // Mirror: a reflected copy, still outward, two shells.
    let m = run(PrimitiveKind::Cone, &[Modifier::Translate(DVec3::X), Modifier::Mirror { axis: Axis::X, offset: 0.0 }]);
    assert!(m.is_closed() && m.check_invariants());
    assert_eq!(m.euler_characteristic(), 4);
    let one = run(PrimitiveKind::Cone, &[]);
    assert!((m.signed_volume() - 2.0 * one.signed_volume()).abs() < 1e-12);
}

#[test]
fn budget_is_checked_before_allocating() {
    let mut budget = Budget::new(Limits { max_triangles: 1000, ..Limits::default() });
    let e = apply_all(base(PrimitiveKind::Icosahedron), &[Modifier::Subdivide { levels: 12, weight: 1.0, smooth: true }], &mut budget);
    assert!(matches!(e, Err(ModifyError::Limit(LimitExceeded { limit: Limit::Triangles, configured: 1000, reached: 335_544_320 }))), "{e:?}");
    let mut budget = Budget::new(Limits { max_memory: 10_000, ..Limits::default() });
    let e = apply_all(base(PrimitiveKind::Icosahedron), &[Modifier::Subdivide { levels: 6, weight: 1.0, smooth: true }], &mut budget);
    assert!(matches!(e, Err(ModifyError::Limit(LimitExceeded { limit: Limit::Memory, .. }))), "{e:?}");
}

#[test]
fn stage_syntax() {
    let w = |s: &str| -> Vec<Word> {
        s.split_whitespace().map(|t| t.parse::<f64>().map(Word::Num).unwrap_or_else(|_| Word::Key(t.to_string()))).collect()
    };
    assert_eq!(stage("subdivide", &w("2 weight 1.4")), Ok(Modifier::Subdivide { levels: 2, weight: 1.4, smooth: true }));
    assert_eq!(stage("SPIKEIFY", &w("0.1")), Ok(Modifier::Spikeify { height: 0.1 }));
    assert_eq!(stage("mirror", &w("z 0.5")), Ok(Modifier::Mirror { axis: Axis::Z, offset: 0.5 }));
    let x = stage("extrude", &w("faces 0 1 length 0.1 0.3 tilt 5 scale 0.9 steps 2 seed 4")).expect("extrude");
    assert_eq!(
        x,
        Modifier::Extrude(Extrude { select: FaceSelect::Faces(vec![0, 1]), length: (0.1, 0.3), tilt: 5.0, scale: 0.9, steps: 2, seed: 4 })
    );
    assert!(stage("subdivide", &w("2.5")).is_err());
    assert!(stage("subdivide", &w("13")).is_err());
    assert!(stage("spikeify", &[]).unwrap_err().contains("needs a number"));
    assert!(stage("frobnicate", &[]).unwrap_err().contains("unknown modifier"));
    assert!(stage("extrude", &w("length 0.3 0.1")).is_err());
    assert!(stage("bend", &w("30 40")).unwrap_err().contains("unexpected number"));
}

#[test]
fn stacking_string() {
    let s = stack("b1.5s1.4w0.1").expect("stack");
    assert_eq!(s.base, MeshBase::Primitive(PrimitiveKind::Box));
    assert_eq!(
        s.modifiers,
        vec![Modifier::Scale(DVec3::splat(1.5)), Modifier::Subdivide { levels: 1, weight: 1.4, smooth: true }, Modifier::Spikeify { height: 0.1 }]
    );
    let s = stack("o x7 r0.4 s s").expect("defaults");
    assert_eq!(s.modifiers.len(), 4);
    assert!(matches!(s.modifiers[1], Modifier::Randomize { amount: 0.4, .. }));
    assert_eq!(s.modifiers[3], Modifier::Subdivide { levels: 1, weight: 1.0, smooth: true });
    assert!(stack("").is_err());
    assert!(stack("s1.4").unwrap_err().contains("starts with a primitive"));
    assert!(stack("bb").unwrap_err().contains("second"));
    assert!(stack("bq").unwrap_err().contains("unknown stacking letter"));
    assert!(stack("b1.2.3").unwrap_err().contains("not a number"));
    // Built under a budget: two smooth subdivisions of a box.
    let mut budget = Budget::new(Limits::default());
    let s = stack("b2s1s1").expect("stack");
    let p = build(&s.base, &s.modifiers, 16, &mut budget).expect("builds");
    assert_eq!(p.indices.len() / 3, 12 * 16);
}

#[test]
fn solids_and_geodesics_as_bases() {
    let mut budget = Budget::new(Limits::default());
    let p = build(&MeshBase::Solid(Solid::TruncatedIcosahedron), &[], 16, &mut budget).expect("solid");
    assert_eq!(p.indices.len() / 3, 116);
    let p = build(&MeshBase::Geodesic(4), &[Modifier::Spikeify { height: 0.05 }], 16, &mut budget).expect("geodesic");
    assert_eq!(p.indices.len() / 3, 3 * 320);
    assert_eq!(budget.memory(), 0);
}
