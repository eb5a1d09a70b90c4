//! Checks of a mesh's solidity for tests, in this crate and the crates above
//! it (a `#[cfg(test)]` module is invisible across crates): exact-position
//! welding, closedness with consistent winding, and signed volume. They
//! assert, so they are for tests only; the engine's own checks return
//! findings (`print::measure`).

use std::collections::{BTreeMap, BTreeSet};

fn key(p: [f32; 3]) -> [u32; 3] {
    p.map(f32::to_bits)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Welds vertices by exact position; returns welded triangle corners.
pub fn welded(positions: &[[f32; 3]], indices: &[u32]) -> (usize, Vec<[u32; 3]>) {
    let mut ids: BTreeMap<[u32; 3], u32> = BTreeMap::new();
    let remap: Vec<u32> = positions
        .iter()
        .map(|&p| {
            let n = ids.len() as u32;
            *ids.entry(key(p)).or_insert(n)
        })
        .collect();
    let tris = indices.chunks_exact(3).map(|t| [remap[t[0] as usize], remap[t[1] as usize], remap[t[2] as usize]]).collect();
    (ids.len(), tris)
}

/// Asserts every undirected edge is used by exactly two triangles in
/// opposite directions, and no triangle is degenerate; returns (V, E, F).
pub fn assert_closed(positions: &[[f32; 3]], indices: &[u32]) -> (usize, usize, usize) {
    let (nv, tris) = welded(positions, indices);
    let mut directed: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    for t in &tris {
        assert!(t[0] != t[1] && t[1] != t[2] && t[0] != t[2], "degenerate triangle {t:?}");
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *directed.entry((a, b)).or_default() += 1;
        }
    }
    let mut undirected = BTreeSet::new();
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "directed edge {a}->{b} used {n} times");
        assert_eq!(directed.get(&(b, a)), Some(&1), "edge {a}->{b} has no opposite");
        undirected.insert((a.min(b), a.max(b)));
    }
    (nv, undirected.len(), tris.len())
}

/// The signed volume of a triangle mesh (positive when it winds outward).
pub fn signed_volume(positions: &[[f32; 3]], indices: &[u32]) -> f64 {
    indices
        .chunks_exact(3)
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|k| positions[t[k] as usize].map(f64::from));
            dot(a, cross(b, c)) / 6.0
        })
        .sum()
}

