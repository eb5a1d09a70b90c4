//! The exact-position vertex weld every caller shares: exporters that name
//! shared vertices (3MF, UniGrafix), the UniGrafix reader, the half-edge
//! mesh and the print stage. Two corners are one vertex exactly when their
//! keys are equal (bit-identical coordinates); nothing is snapped, so
//! welding never moves a point and the same input always welds the same way.
//!
//! Written by hand: it is a first-use-ordered dedup over a hash map, which
//! mesh crates offer only with tolerance or reordering (meshopt's remap
//! tables reorder by first occurrence too, but on whole vertices, not
//! positions), and the order is part of the output bytes.

use super::STOP_EVERY;
use std::collections::HashMap;
use std::hash::Hash;

/// The distinct points of `points` in first-use order, and for every input
/// point the index of its distinct point. `key` decides which points are the
/// same (see [`f32_key`], [`f64_key`]).
pub fn weld_by<P: Copy, K: Hash + Eq>(points: impl IntoIterator<Item = P>, key: impl Fn(&P) -> K) -> (Vec<P>, Vec<u32>) {
    let never = || false;
    let (distinct, remap, _) = weld_while(points, key, &never);
    (distinct, remap)
}

/// [`weld_by`] that asks `stop` every [`STOP_EVERY`] points whether to give
/// up (`None`): welding millions of corners takes longer than a request's
/// deadline may allow.
pub fn weld_by_until<P: Copy, K: Hash + Eq>(points: impl IntoIterator<Item = P>, key: impl Fn(&P) -> K, stop: &dyn Fn() -> bool) -> Option<(Vec<P>, Vec<u32>)> {
    let (distinct, remap, stopped) = weld_while(points, key, stop);
    (!stopped).then_some((distinct, remap))
}

/// The weld itself; the flag says whether `stop` ended it early.
fn weld_while<P: Copy, K: Hash + Eq>(points: impl IntoIterator<Item = P>, key: impl Fn(&P) -> K, stop: &dyn Fn() -> bool) -> (Vec<P>, Vec<u32>, bool) {
    let points = points.into_iter();
    // foldhash: the ids come from the order of first occurrence, not the map's.
    let mut ids: HashMap<K, u32, foldhash::fast::FixedState> = HashMap::with_capacity_and_hasher(points.size_hint().0, foldhash::fast::FixedState::default());
    let mut distinct = Vec::new();
    let mut remap = Vec::with_capacity(points.size_hint().0);
    for (i, p) in points.enumerate() {
        if i % STOP_EVERY == STOP_EVERY - 1 && stop() {
            return (distinct, remap, true);
        }
        let id = *ids.entry(key(&p)).or_insert_with(|| {
            distinct.push(p);
            // Fits: callers weld meshes whose vertex counts are u32 indices.
            (distinct.len() - 1) as u32
        });
        remap.push(id);
    }
    (distinct, remap, false)
}

/// The exact key of an f32 point: its coordinates' bit patterns.
pub fn f32_key(p: &[f32; 3]) -> [u32; 3] {
    p.map(f32::to_bits)
}

/// The exact key of an f64 point, with −0 taken as +0 (so a coordinate
/// computed as −0.0 welds with 0.0).
pub(crate) fn f64_key(p: &[f64; 3]) -> [u64; 3] {
    p.map(|c| (c + 0.0).to_bits())
}

/// The triangles of `indices` (three per triangle) through `remap`, with
/// their index in `indices`, leaving out those that welding made degenerate
/// (two corners on one vertex). An index past `remap` reads as vertex 0.
pub fn welded_triangles<'a>(indices: &'a [u32], remap: &'a [u32]) -> impl Iterator<Item = (usize, [u32; 3])> + 'a {
    indices
        .chunks_exact(3)
        .map(move |t| [0, 1, 2].map(|k| remap.get(t[k] as usize).copied().unwrap_or(0)))
        .enumerate()
        .filter(|(_, [a, b, c])| a != b && b != c && a != c)
}
