//! A bounding-volume hierarchy over triangles and the nearest ray hit, for
//! measuring wall thickness ([`super::thickness`]).
//!
//! Written here rather than taken from a crate: the few Rust BVH crates
//! either use f32 only, threads, or SIMD paths whose results depend on the
//! CPU, and the print stage must give the same report everywhere. It is a
//! plain binary tree split at the median centroid along the longest axis
//! (ties broken by triangle index, so the tree is a function of the input),
//! searched front to back with an explicit stack.

use glam::DVec3;

/// Triangles per leaf at most.
const LEAF: usize = 4;

/// One node: its box and either two children or a run of triangles.
struct Node {
    lo: DVec3,
    hi: DVec3,
    /// Leaf: first index into `order`; inner: index of the first child (the second follows it).
    first: u32,
    /// Leaf: number of triangles; inner: 0.
    count: u32,
}

/// The hierarchy over a triangle list.
pub(super) struct Bvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

/// A triangle the ray may not hit, and what a hit must satisfy.
pub(super) struct RayQuery {
    /// The ray's start.
    pub origin: DVec3,
    /// Its direction (unit length).
    pub dir: DVec3,
    /// Hits closer than this are ignored (the start surface itself).
    pub min_t: f64,
}

/// Bytes the hierarchy holds per triangle (nodes and order), for the budget.
pub(super) const BYTES_PER_TRIANGLE: u64 = 4 + 2 * std::mem::size_of::<Node>() as u64;

impl Bvh {
    /// Builds the hierarchy over `tris` (corner positions).
    pub fn build(tris: &[[DVec3; 3]]) -> Bvh {
        let centres: Vec<DVec3> = tris.iter().map(|t| (t[0] + t[1] + t[2]) / 3.0).collect();
        let mut bvh = Bvh { nodes: Vec::with_capacity(2 * tris.len() / LEAF + 1), order: (0..tris.len() as u32).collect() };
        // (node, start, end) still to split.
        bvh.nodes.push(Node { lo: DVec3::ZERO, hi: DVec3::ZERO, first: 0, count: 0 });
        let mut todo = vec![(0usize, 0usize, tris.len())];
        while let Some((node, start, end)) = todo.pop() {
            let (lo, hi) = bounds(bvh.order[start..end].iter().flat_map(|&k| tris[k as usize]));
            bvh.nodes[node].lo = lo;
            bvh.nodes[node].hi = hi;
            if end - start <= LEAF {
                bvh.nodes[node].first = start as u32;
                bvh.nodes[node].count = (end - start) as u32;
                continue;
            }
            let (clo, chi) = bounds(bvh.order[start..end].iter().map(|&k| centres[k as usize]));
            let axis = (chi - clo).max_position();
            let mid = start + (end - start) / 2;
            bvh.order[start..end].select_nth_unstable_by(mid - start, |&a, &b| centres[a as usize][axis].total_cmp(&centres[b as usize][axis]).then(a.cmp(&b)));
            let left = bvh.nodes.len();
            bvh.nodes.push(Node { lo, hi, first: 0, count: 0 });
            bvh.nodes.push(Node { lo, hi, first: 0, count: 0 });
            bvh.nodes[node].first = left as u32;
            todo.push((left + 1, mid, end));
            todo.push((left, start, mid));
        }
        bvh
    }

    /// The nearest hit of the ray on a triangle that `accept` allows (given
    /// the triangle's index), as (distance, triangle); also counts the nodes
    /// and triangles visited (how well the tree prunes).
    pub fn nearest(&self, tris: &[[DVec3; 3]], ray: &RayQuery, accept: impl Fn(u32) -> bool, visits: &mut u64) -> Option<(f64, u32)> {
        let inv = DVec3::ONE / ray.dir;
        let mut best: Option<(f64, u32)> = None;
        let mut stack = vec![0usize];
        while let Some(n) = stack.pop() {
            *visits += 1;
            let node = &self.nodes[n];
            let limit = best.map_or(f64::INFINITY, |b| b.0);
            if !slab(node.lo, node.hi, ray.origin, inv, limit) {
                continue;
            }
            if node.count > 0 {
                let first = node.first as usize;
                for &k in &self.order[first..first + node.count as usize] {
                    *visits += 1;
                    if let Some(t) = hit(&tris[k as usize], ray) {
                        // Nearest first; on a tie, the lower index (the order is the tree's).
                        if best.is_none_or(|b| (t, k) < b) && accept(k) {
                            best = Some((t, k));
                        }
                    }
                }
            } else {
                stack.push(node.first as usize + 1);
                stack.push(node.first as usize);
            }
        }
        best
    }
}

/// Whether the ray enters the box before `limit` (slab test; a zero
/// direction component gives infinite slabs, which IEEE handles).
fn slab(lo: DVec3, hi: DVec3, origin: DVec3, inv: DVec3, limit: f64) -> bool {
    let a = (lo - origin) * inv;
    let b = (hi - origin) * inv;
    // NaN (0 × ∞ on a box face) is dropped by min/max: the test stays conservative.
    let near = a.min(b).max_element().max(0.0);
    let far = a.max(b).min_element();
    near <= far && near <= limit
}

/// The distance along the ray to triangle `t` (Möller–Trumbore, edges
/// included), if it is at least `min_t`.
pub(super) fn hit(t: &[DVec3; 3], ray: &RayQuery) -> Option<f64> {
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let p = ray.dir.cross(e2);
    let det = e1.dot(p);
    if det.abs() <= f64::EPSILON * e1.length_squared().max(e2.length_squared()) {
        // The ray runs along the triangle's plane.
        return None;
    }
    let s = ray.origin - t[0];
    let u = s.dot(p) / det;
    const EDGE: f64 = 1e-9;
    if !(-EDGE..=1.0 + EDGE).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = ray.dir.dot(q) / det;
    if v < -EDGE || u + v > 1.0 + EDGE {
        return None;
    }
    let d = e2.dot(q) / det;
    (d >= ray.min_t).then_some(d)
}

/// The bounding box of `points`.
fn bounds(points: impl IntoIterator<Item = DVec3>) -> (DVec3, DVec3) {
    points.into_iter().fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), q| (lo.min(q), hi.max(q)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad(z: f64, k: f64) -> [[DVec3; 3]; 2] {
        let c = |x: f64, y: f64| DVec3::new(x + k, y, z);
        [[c(0.0, 0.0), c(1.0, 0.0), c(1.0, 1.0)], [c(0.0, 0.0), c(1.0, 1.0), c(0.0, 1.0)]]
    }

    #[test]
    fn a_ray_hits_a_triangle_inside_and_on_an_edge_only() {
        let t = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let down = |x: f64, y: f64| RayQuery { origin: DVec3::new(x, y, 2.0), dir: DVec3::NEG_Z, min_t: 1e-6 };
        assert_eq!(hit(&t, &down(0.25, 0.25)), Some(2.0));
        assert_eq!(hit(&t, &down(0.5, 0.5)), Some(2.0));
        assert_eq!(hit(&t, &down(0.6, 0.6)), None);
        // Behind the start, or closer than min_t: no hit.
        assert_eq!(hit(&t, &RayQuery { origin: DVec3::new(0.2, 0.2, -1.0), dir: DVec3::NEG_Z, min_t: 1e-6 }), None);
        assert_eq!(hit(&t, &RayQuery { origin: DVec3::new(0.2, 0.2, 0.0), dir: DVec3::NEG_Z, min_t: 1e-6 }), None);
        // Along the plane: no hit.
        assert_eq!(hit(&t, &RayQuery { origin: DVec3::new(-1.0, 0.2, 0.0), dir: DVec3::X, min_t: 1e-6 }), None);
    }

    #[test]
    fn the_nearest_accepted_hit_among_many() {
        // 40 stacked unit squares at z = 0, 1, ..., 19, each shifted in x.
        let tris: Vec<[DVec3; 3]> = (0..20).flat_map(|i| quad(f64::from(i), f64::from(i % 3) * 0.1)).collect();
        let bvh = Bvh::build(&tris);
        let ray = RayQuery { origin: DVec3::new(0.5, 0.3, 30.0), dir: DVec3::NEG_Z, min_t: 1e-6 };
        let mut visits = 0;
        let (t, k) = bvh.nearest(&tris, &ray, |_| true, &mut visits).expect("hit");
        assert_eq!((t, k / 2), (11.0, 19));
        assert!(visits > 0 && visits < 200, "{visits}");
        // Refusing the top square's triangles finds the next one down.
        let (t, k) = bvh.nearest(&tris, &ray, |k| k / 2 != 19, &mut visits).expect("hit");
        assert_eq!((t, k / 2), (12.0, 18));
        // A ray that misses everything.
        let away = RayQuery { origin: DVec3::new(5.0, 5.0, 30.0), dir: DVec3::NEG_Z, min_t: 1e-6 };
        assert_eq!(bvh.nearest(&tris, &away, |_| true, &mut visits), None);
        // Against a brute-force search, from many starts.
        for i in 0..50 {
            let f = f64::from(i);
            let ray = RayQuery { origin: DVec3::new(0.02 * f, (0.37 * f) % 1.0, 25.0 - 0.3 * f), dir: DVec3::new(0.01 * f, -0.02, -1.0).normalize(), min_t: 1e-6 };
            let brute = tris.iter().enumerate().filter_map(|(k, t)| hit(t, &ray).map(|d| (d, k as u32))).fold(None, |b: Option<(f64, u32)>, h| if b.is_none_or(|b| h < b) { Some(h) } else { b });
            assert_eq!(bvh.nearest(&tris, &ray, |_| true, &mut visits), brute, "ray {i}");
        }
    }
}
