//! Triangle strips (Haglund 2009, §2.1.2): a strip of n triangles needs
//! n + 2 indices instead of 3n, which is what makes the `strips` delivery
//! format small. The heavy lifting is meshoptimizer's (through the `meshopt`
//! crate); this module fixes the order of the passes and the conventions
//! (restart index, winding of odd triangles) that the format and both
//! decoders rely on.
//!
//! Conventions, shared with `docs/strips-format.md` and `clients/js/strips.mjs`:
//! a strip index sequence is split into runs at [`RESTART`]; inside a run,
//! triangle `k` is `(s[k], s[k+1], s[k+2])` for even `k` and
//! `(s[k+1], s[k], s[k+2])` for odd `k` (the OpenGL rule, so the winding of
//! every triangle is the one of the original list); triangles with a repeated
//! index are joins, not geometry, and are skipped.

/// The primitive-restart index: `0xFFFFFFFF`, what WebGL 2 and GLES 3 use
/// for 32-bit indices (`0xFFFF` for 16-bit; decoders map one to the other).
pub const RESTART: u32 = u32::MAX;

/// Welds bitwise-identical vertices: returns the unique vertices (in order of
/// first use by `indices`) and the index list rewritten to them. Vertices no
/// triangle uses are dropped. Exporters call this after quantisation so that
/// vertices which became equal are stored once.
///
/// `T` must be plain bytes without padding (e.g. `[u16; 8]`), since
/// meshoptimizer hashes and compares the raw bytes.
pub fn weld<T: bytemuck::Pod>(vertices: &[T], indices: &[u32]) -> (Vec<T>, Vec<u32>) {
    if indices.is_empty() || vertices.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let (unique, remap) = meshopt::generate_vertex_remap(vertices, Some(indices));
    let mut out = vec![T::zeroed(); unique];
    for (v, &r) in vertices.iter().zip(&remap) {
        // Unused vertices map to !0 and are dropped.
        if let Some(slot) = out.get_mut(r as usize) {
            *slot = *v;
        }
    }
    let indices = indices.iter().map(|&i| remap[i as usize]).collect();
    (out, indices)
}

/// New vertex numbers in order of first use in `list` (`u32::MAX` for unused
/// vertices) and the number used. Written out because the `meshopt` crate's
/// `optimize_vertex_fetch_remap` truncates its table to the used count, which
/// breaks lookups when an unused vertex precedes a used one.
pub fn first_use_remap(list: &[u32], vertex_count: usize) -> (Vec<u32>, usize) {
    let mut remap = vec![u32::MAX; vertex_count];
    let mut used = 0usize;
    for &i in list {
        if let Some(r) = remap.get_mut(i as usize) {
            if *r == u32::MAX {
                // Fits: callers have fewer than u32::MAX vertices.
                *r = used as u32;
                used += 1;
            }
        }
    }
    (remap, used)
}

/// Orders a triangle list for the post-transform vertex cache and for
/// stripification (`meshopt_optimizeVertexCacheStrip`), turns it into one
/// strip index sequence with [`RESTART`] between strips (`meshopt_stripify`),
/// and reorders the vertices by first use in that strip (so the vertex codec
/// sees neighbours together). The set of triangles and the winding of each
/// are preserved (triangles with a repeated index are dropped: they cover no
/// area).
///
/// Every index in `indices` must be below `vertices.len()`, and there must
/// be fewer than `u32::MAX` vertices (the restart index).
pub fn stripify<T: Copy + Default>(vertices: &[T], indices: &[u32]) -> (Vec<T>, Vec<u32>) {
    let list: Vec<u32> = indices.chunks_exact(3).filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]).flatten().copied().collect();
    if list.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let list = meshopt::optimize_vertex_cache_strip(&list, vertices.len());
    // meshopt only fails on bad arguments (it has none here); an empty strip
    // would lose the model, so fall back to one strip per triangle.
    let strip = meshopt::stripify(&list, vertices.len(), RESTART)
        .unwrap_or_else(|_| list.chunks_exact(3).flat_map(|t| [t[0], t[1], t[2], RESTART]).collect());
    // Vertex order = first use in the strip; unused vertices are dropped
    // (the restart index is no vertex, so it stays unmapped).
    let (remap, used) = first_use_remap(&strip, vertices.len());
    let mut out = vec![T::default(); used];
    for (v, &r) in vertices.iter().zip(&remap) {
        if let Some(slot) = out.get_mut(r as usize) {
            *slot = *v;
        }
    }
    let strip = strip.iter().map(|&i| if i == RESTART { RESTART } else { remap.get(i as usize).copied().unwrap_or(0) }).collect();
    (out, strip)
}

/// What `meshopt::generate_vertex_remap(vertices, Some(indices))` returns —
/// the number of distinct vertices `indices` uses and, for each vertex, its
/// number among them in order of first use (`u32::MAX` for unused ones) —
/// computed faster for millions of vertices: meshoptimizer's table holds
/// vertex numbers only, so every probe that meets another vertex reads that
/// vertex (a cache miss) and compares it through `memcmp`. Here each slot
/// holds the vertex number and 32 bits of its hash, so a probe reads a
/// vertex only when the hashes agree. Open addressing, linear probing, a
/// power of two of at least 1.25 slots per vertex (meshoptimizer's sizing).
fn vertex_remap<T: bytemuck::Pod + PartialEq>(vertices: &[T], indices: &[u32]) -> (usize, Vec<u32>) {
    const EMPTY: u64 = u64::MAX;
    let slots = (vertices.len() + vertices.len() / 4).max(1).next_power_of_two();
    let mask = slots - 1;
    let mut table = vec![EMPTY; slots];
    let hash = |v: &T| {
        let mut h = 0x9e37_79b9_7f4a_7c15u64;
        for chunk in bytemuck::bytes_of(v).chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            h = (h ^ u64::from_le_bytes(word)).wrapping_mul(0xff51_afd7_ed55_8ccd);
            h ^= h >> 32;
        }
        h
    };
    let mut remap = vec![u32::MAX; vertices.len()];
    let mut next = 0u32;
    for &i in indices {
        let i = i as usize;
        if remap[i] != u32::MAX {
            continue;
        }
        let v = &vertices[i];
        let h = hash(v);
        // The slot comes from the high bits, the tag from the low 32.
        let tag = h & 0xffff_ffff;
        let mut slot = (h >> 32) as usize & mask;
        loop {
            let entry = table[slot];
            if entry == EMPTY {
                table[slot] = (tag << 32) | i as u64;
                remap[i] = next;
                next += 1;
                break;
            }
            let other = (entry & 0xffff_ffff) as usize;
            if entry >> 32 == tag && vertices[other] == *v {
                remap[i] = remap[other];
                break;
            }
            slot = (slot + 1) & mask;
        }
    }
    (next as usize, remap)
}

/// [`weld`], then [`stripify`], then [`unstripify`], in one pass that holds
/// as few full-size arrays at a time as it can: the `strips` encoder's
/// geometry step for models of millions of triangles. Returns the welded
/// vertices in order of first use in the strip and the strip's triangles
/// (three indices each, in strip order): exactly what
/// `unstripify(&stripify(&weld(v, i).0, &weld(v, i).1).1)` and its vertices
/// give, without the welded copy of the vertices (a welded vertex is read
/// from the first original that maps to it) or a remapped copy of the strip.
///
/// Takes `indices` by value and reuses it. Every index must be below
/// `vertices.len()`, and there must be fewer than `u32::MAX` vertices.
pub fn weld_stripify<T: bytemuck::Pod + PartialEq>(vertices: &[T], mut indices: Vec<u32>) -> (Vec<T>, Vec<u32>) {
    if indices.is_empty() || vertices.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let (unique, remap) = vertex_remap(vertices, &indices);
    // The first original of each welded vertex (they are bitwise equal).
    let mut first = vec![u32::MAX; unique];
    for (i, &r) in remap.iter().enumerate() {
        if let Some(slot) = first.get_mut(r as usize) {
            if *slot == u32::MAX {
                // Fits: callers have fewer than u32::MAX vertices.
                *slot = i as u32;
            }
        }
    }
    for i in &mut indices {
        *i = remap[*i as usize];
    }
    drop(remap);
    // Triangles with a repeated index cover no area: drop them, in place.
    let mut kept = 0;
    for t in 0..indices.len() / 3 {
        let [a, b, c] = [indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]];
        if a != b && b != c && a != c {
            indices[kept..kept + 3].copy_from_slice(&[a, b, c]);
            kept += 3;
        }
    }
    indices.truncate(kept);
    if indices.is_empty() {
        return (Vec::new(), Vec::new());
    }
    meshopt::optimize_vertex_cache_strip_in_place(&mut indices, unique);
    // As in `stripify`: meshopt only fails on bad arguments, and an empty
    // strip would lose the model, so fall back to one strip per triangle.
    let strip = match meshopt::stripify(&indices, unique, RESTART) {
        Ok(strip) => {
            drop(indices);
            strip
        }
        Err(_) => indices.chunks_exact(3).flat_map(|t| [t[0], t[1], t[2], RESTART]).collect(),
    };
    let (order, used) = first_use_remap(&strip, unique);
    // Renumbering is one-to-one on the vertices the strip uses, so it can
    // follow unstripifying (which only compares indices for equality).
    let mut triangles = unstripify(&strip);
    drop(strip);
    for i in &mut triangles {
        *i = order[*i as usize];
    }
    let mut out = vec![T::zeroed(); used];
    for (&o, &f) in order.iter().zip(&first) {
        if let (Some(slot), Some(v)) = (out.get_mut(o as usize), vertices.get(f as usize)) {
            *slot = *v;
        }
    }
    (out, triangles)
}

/// Rebuilds a strip from a triangle list whose triangles come in strip order
/// (what [`unstripify`] of a [`stripify`] strip gives, possibly with each
/// triangle rotated, as meshoptimizer's index buffer codec does). This is how
/// the `strips` format (version 2) carries its strip: as the strip's
/// triangles, which the index buffer codec stores in fewer bytes than the
/// index sequence codec stores the strip. Deterministic and shared with
/// `clients/js/strips.mjs` and `docs/strips-format.md`:
///
/// A run starts at a triangle `(a, b, c)` written in the first of the
/// rotations `(a, b, c)`, `(b, c, a)`, `(c, a, b)` after which the next
/// triangle can continue the run (or `(a, b, c)` if none can). With `x, y` the
/// last two indices of the run and `k` the number of the next triangle inside
/// the run, the next list triangle continues the run if it holds the directed
/// edge `x → y` (k even) or `y → x` (k odd): its third corner `z` is
/// appended. Otherwise [`RESTART`] is written and a new run starts.
///
/// [`unstripify`] of the result gives the input triangles in order (each
/// possibly rotated, so with the same winding). Triangles with a repeated
/// index are the caller's business: the decoders refuse them first.
pub fn restrip(list: &[u32]) -> Vec<u32> {
    let tris: Vec<[u32; 3]> = list.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    // The third corner of `t` if `t` holds the directed edge p → q.
    let third = |t: &[u32; 3], p: u32, q: u32| (0..3).find(|&r| t[r] == p && t[(r + 1) % 3] == q).map(|r| t[(r + 2) % 3]);
    let mut out = Vec::with_capacity(tris.len() + 2);
    let mut i = 0;
    while i < tris.len() {
        if i > 0 {
            out.push(RESTART);
        }
        let [a, b, c] = tris[i];
        let rots = [[a, b, c], [b, c, a], [c, a, b]];
        // The second triangle of a run is odd: it needs the edge (last → second last).
        let start = tris.get(i + 1).and_then(|n| rots.iter().find(|r| third(n, r[2], r[1]).is_some())).unwrap_or(&rots[0]);
        out.extend_from_slice(start);
        i += 1;
        let mut k = 1usize;
        while let Some(t) = tris.get(i) {
            let (x, y) = (out[out.len() - 2], out[out.len() - 1]);
            let z = if k % 2 == 0 { third(t, x, y) } else { third(t, y, x) };
            match z {
                Some(z) => out.push(z),
                None => break,
            }
            i += 1;
            k += 1;
        }
    }
    out
}

/// Turns a strip index sequence back into a triangle list (three indices per
/// triangle), by the conventions in the module documentation. Works on any
/// input (untrusted data included): it never indexes anything.
pub fn unstripify(strip: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(strip.len().saturating_mul(3));
    let mut start = 0usize;
    for i in 0..strip.len() {
        if strip[i] == RESTART {
            start = i + 1;
        } else if i - start >= 2 {
            let (mut a, mut b, c) = (strip[i - 2], strip[i - 1], strip[i]);
            if (i - start) & 1 == 1 {
                std::mem::swap(&mut a, &mut b);
            }
            if a != b && a != c && b != c {
                out.extend_from_slice(&[a, b, c]);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each triangle rotated so its smallest vertex key comes first: the same
    /// triangle with the same orientation has the same key, a flipped one not.
    fn canonical<K: Ord + Copy>(tris: impl Iterator<Item = [K; 3]>) -> Vec<[K; 3]> {
        let mut v: Vec<[K; 3]> = tris
            .map(|[a, b, c]| {
                if a <= b && a <= c {
                    [a, b, c]
                } else if b <= a && b <= c {
                    [b, c, a]
                } else {
                    [c, a, b]
                }
            })
            .collect();
        v.sort();
        v
    }

    fn tri_keys<T: Copy + Ord>(verts: &[T], idx: &[u32]) -> Vec<[T; 3]> {
        canonical(idx.chunks_exact(3).map(|t| [verts[t[0] as usize], verts[t[1] as usize], verts[t[2] as usize]]))
    }

    /// A grid of quads plus a separate fan, with vertex ids as "positions".
    fn sample() -> (Vec<u32>, Vec<u32>) {
        let n = 9u32;
        let mut idx = Vec::new();
        for y in 0..n - 1 {
            for x in 0..n - 1 {
                let (a, b, c, d) = (y * n + x, y * n + x + 1, (y + 1) * n + x + 1, (y + 1) * n + x);
                idx.extend_from_slice(&[a, b, c, a, c, d]);
            }
        }
        let base = n * n;
        for k in 1..7 {
            idx.extend_from_slice(&[base, base + k, base + k + 1]);
        }
        idx.extend_from_slice(&[3, 3, 4]); // degenerate: must disappear
        let verts: Vec<u32> = (0..base + 8).map(|v| v * 10).collect();
        (verts, idx)
    }

    #[test]
    fn strips_keep_triangles_and_winding() {
        let (verts, idx) = sample();
        let (sv, strip) = stripify(&verts, &idx);
        assert!(strip.len() < idx.len(), "strip {} vs list {}", strip.len(), idx.len());
        let back = unstripify(&strip);
        // The strip comes back from its triangles, even rotated ones.
        let rebuilt = restrip(&back);
        // Same triangles in the same order, each up to rotation.
        let rot = |l: &[u32]| -> Vec<[u32; 3]> { l.chunks_exact(3).map(|t| canonical(std::iter::once([t[0], t[1], t[2]]))[0]).collect() };
        assert_eq!(rot(&unstripify(&rebuilt)), rot(&back));
        assert!(rebuilt.len() <= strip.len() + strip.len() / 4, "rebuilt {} vs {}", rebuilt.len(), strip.len());
        let rotated: Vec<u32> = back.chunks_exact(3).enumerate().flat_map(|(k, t)| match k % 3 { 0 => [t[0], t[1], t[2]], 1 => [t[1], t[2], t[0]], _ => [t[2], t[0], t[1]] }).collect();
        assert_eq!(tri_keys(&sv, &unstripify(&restrip(&rotated))), tri_keys(&sv, &back));
        let nondegenerate: Vec<u32> =
            idx.chunks_exact(3).filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]).flatten().copied().collect();
        assert_eq!(tri_keys(&sv, &back), tri_keys(&verts, &nondegenerate));
        // And a flipped mesh would not compare equal (the check can fail).
        let flipped: Vec<u32> = nondegenerate.chunks_exact(3).flat_map(|t| [t[0], t[2], t[1]]).collect();
        assert_ne!(tri_keys(&verts, &flipped), tri_keys(&sv, &back));
    }

    #[test]
    fn weld_stripify_equals_the_three_passes() {
        let (verts, idx) = sample();
        // Duplicate some vertices so welding has work to do.
        let mut dup = verts.clone();
        dup.extend_from_slice(&verts[..20]);
        let n = verts.len() as u32;
        let idx2: Vec<u32> = idx.iter().enumerate().map(|(k, &i)| if k % 5 == 0 && i < 20 { i + n } else { i }).collect();
        let (wv, wi) = weld(&dup, &idx2);
        let (sv, strip) = stripify(&wv, &wi);
        assert_eq!(weld_stripify(&dup, idx2.clone()), (sv, unstripify(&strip)));
        assert_eq!(weld_stripify::<u32>(&[], vec![]), (vec![], vec![]));
    }

    #[test]
    fn vertex_remap_is_meshopts() {
        let verts: Vec<[u16; 8]> = (0..500u16).map(|k| [k % 37, k % 11, 0, 0, k % 3, 0, 0, 0]).collect();
        let idx: Vec<u32> = (0..300u32).map(|k| (k * 7919) % 450).collect();
        assert_eq!(vertex_remap(&verts, &idx), meshopt::generate_vertex_remap(&verts, Some(&idx)));
    }

    #[test]
    fn unstripify_follows_the_gl_rule() {
        // ABCDEF → ABC, CBD (odd flipped), CDE, EDF; restart; GHI.
        let s = [0, 1, 2, 3, 4, 5, RESTART, 6, 7, 8];
        assert_eq!(unstripify(&s), vec![0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5, 6, 7, 8]);
        assert!(unstripify(&[RESTART, 1, RESTART, 2, 3]).is_empty());
    }

    #[test]
    fn weld_merges_identical_vertices() {
        let verts = [[1u16, 2], [3, 4], [1, 2], [9, 9], [3, 4]];
        let (v, i) = weld(&verts, &[0, 1, 2, 2, 4, 0]);
        assert_eq!(v, vec![[1, 2], [3, 4]]);
        assert_eq!(i, vec![0, 1, 0, 0, 1, 0]);
    }

    #[test]
    fn deterministic_and_empty() {
        let (verts, idx) = sample();
        assert_eq!(stripify(&verts, &idx), stripify(&verts, &idx));
        assert_eq!(stripify::<u32>(&[], &[]), (vec![], vec![]));
    }
}
