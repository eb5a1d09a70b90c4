//! Which parts of a mesh are closed, outward-facing solids, whose back
//! faces the rasteriser may skip (`docs/preview.md`, "Back faces").
//!
//! Lighting is two-sided and open surfaces (an L-system leaf, a UniGrafix
//! polygon, a sheet) must show both sides, so a back face may be skipped
//! only where it can never be seen: on the surface of a solid, seen from
//! outside, a ray meets a face turned towards the camera before any face
//! turned away. The rule, per connected part of a mesh:
//!
//! 1. Corners at bit-identical positions are one vertex (−0 and +0 are
//!    one), so a flat-shaded box, whose faces repeat their corners, is one
//!    piece. Parts are the pieces connected through shared vertices.
//! 2. A part is *closed* when every edge is run through as often in one
//!    direction as in the other by its triangles: no open edge, no
//!    neighbours wound against each other. Two boxes that share a face
//!    (a Menger sponge) stay closed; a T-junction makes a part open.
//! 3. A closed part is *outward* when its signed volume is positive.
//!
//! Only the triangles of closed, outward parts are culled when they face
//! away from the camera; everything else is drawn on both sides, as before.
//! The rule cannot see a surface that passes through itself with a fold
//! turned inside out (a tube swept tighter than its radius); the meshers
//! never make one on purpose (the winding test checks that every
//! triangle's winding agrees with its normals).

use crate::geom::weld::welded_triangles;
use crate::geom::Mesh;
use foldhash::fast::FixedState;
use std::collections::HashMap;

/// Bytes [`cullable`] holds per vertex (weld table, remap, first corners,
/// parts, volumes, flags) and per index (the edge table), for the memory
/// budget.
pub const BYTES_PER_VERTEX: u64 = 64;
/// See [`BYTES_PER_VERTEX`].
pub const BYTES_PER_INDEX: u64 = 16;

/// For every vertex of `mesh`, whether it belongs to a closed, outward
/// part (so its triangles may have their back faces culled). `None` when
/// `stop` asked to give up (the deadline passed). A mesh with an index out
/// of range culls nothing.
pub fn cullable(mesh: &Mesh, stop: &dyn Fn() -> bool) -> Option<Vec<bool>> {
    let n = mesh.positions.len();
    if mesh.indices.iter().any(|&i| i as usize >= n) {
        return Some(vec![false; n]);
    }
    // Weld: every corner's vertex, and each vertex's first corner. foldhash,
    // not std's SipHash, which was two thirds of this function's time.
    let mut ids: HashMap<[u32; 3], u32, FixedState> = HashMap::with_capacity_and_hasher(n, FixedState::default());
    let mut first: Vec<u32> = Vec::new();
    let remap: Vec<u32> = (0..n as u32)
        .map(|i| {
            let key = mesh.positions[i as usize].map(|c| (c + 0.0).to_bits());
            *ids.entry(key).or_insert_with(|| {
                first.push(i);
                first.len() as u32 - 1
            })
        })
        .collect();
    drop(ids);
    if stop() {
        return None;
    }
    let mut parts = Parts::new(first.len());
    // Each edge once, as (low, high), counting +1 one way and −1 the other.
    let mut balance: HashMap<u64, i32, FixedState> = HashMap::with_capacity_and_hasher(mesh.indices.len() / 2, FixedState::default());
    for (_, t) in welded_triangles(&mesh.indices, &remap) {
        parts.join(t[0], t[1]);
        parts.join(t[1], t[2]);
        for k in 0..3 {
            let (p, q) = (t[k], t[(k + 1) % 3]);
            let (key, step) = if p < q { (u64::from(p) << 32 | u64::from(q), 1) } else { (u64::from(q) << 32 | u64::from(p), -1) };
            *balance.entry(key).or_insert(0) += step;
        }
    }
    if stop() {
        return None;
    }
    let mut closed = vec![true; first.len()];
    for (&key, &count) in &balance {
        if count != 0 {
            let part = parts.find((key >> 32) as u32);
            closed[part as usize] = false;
        }
    }
    drop(balance);
    // Signed volume per part, about the part's own first vertex so a small
    // part far from the origin keeps its precision.
    let at = |v: u32| mesh.positions[first[v as usize] as usize].map(f64::from);
    let mut volume = vec![0.0f64; first.len()];
    for (_, t) in welded_triangles(&mesh.indices, &remap) {
        let part = parts.find(t[0]);
        let o = at(part);
        let [a, b, c] = t.map(|v| {
            let p = at(v);
            [p[0] - o[0], p[1] - o[1], p[2] - o[2]]
        });
        volume[part as usize] += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    let keep: Vec<bool> = (0..first.len() as u32)
        .map(|v| {
            let part = parts.find(v) as usize;
            closed[part] && volume[part] > 0.0
        })
        .collect();
    Some(remap.iter().map(|&v| keep[v as usize]).collect())
}

/// Connected parts: a union-find over welded vertices whose root is each
/// part's first-joined representative.
struct Parts {
    parent: Vec<u32>,
}

impl Parts {
    fn new(n: usize) -> Parts {
        Parts { parent: (0..n as u32).collect() }
    }

    /// The part of vertex `v`, halving the path to it on the way.
    #[inline]
    fn find(&mut self, mut v: u32) -> u32 {
        while self.parent[v as usize] != v {
            let up = self.parent[self.parent[v as usize] as usize];
            self.parent[v as usize] = up;
            v = up;
        }
        v
    }

    /// Puts `a` and `b` in one part (the smaller root stays the root).
    #[inline]
    fn join(&mut self, a: u32, b: u32) {
        let (a, b) = (self.find(a), self.find(b));
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        self.parent[hi as usize] = lo;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit cube, flat-shaded (4 corners per face, 24 in all), outward.
    fn cube(at: [f32; 3], inward: bool) -> Mesh {
        let faces: [[[f32; 3]; 4]; 6] = [
            [[0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.]],
            [[1., 0., 0.], [0., 0., 0.], [0., 1., 0.], [1., 1., 0.]],
            [[1., 0., 1.], [1., 0., 0.], [1., 1., 0.], [1., 1., 1.]],
            [[0., 0., 0.], [0., 0., 1.], [0., 1., 1.], [0., 1., 0.]],
            [[0., 1., 1.], [1., 1., 1.], [1., 1., 0.], [0., 1., 0.]],
            [[0., 0., 0.], [1., 0., 0.], [1., 0., 1.], [0., 0., 1.]],
        ];
        let mut m = Mesh::default();
        for f in faces {
            let base = m.positions.len() as u32;
            m.positions.extend(f.map(|p| [p[0] + at[0], p[1] + at[1], p[2] + at[2]]));
            let tri = if inward { [0, 2, 1, 0, 3, 2] } else { [0, 1, 2, 0, 2, 3] };
            m.indices.extend(tri.map(|i| base + i));
        }
        m
    }

    fn joined(a: Mesh, b: Mesh) -> Mesh {
        let mut m = a;
        let base = m.positions.len() as u32;
        m.positions.extend(b.positions);
        m.indices.extend(b.indices.iter().map(|i| i + base));
        m
    }

    fn all(mesh: &Mesh) -> Vec<bool> {
        cullable(mesh, &|| false).expect("not stopped")
    }

    #[test]
    fn an_outward_cube_is_cullable_an_inward_or_open_one_is_not() {
        assert_eq!(all(&cube([0.0; 3], false)), vec![true; 24]);
        assert_eq!(all(&cube([0.0; 3], true)), vec![false; 24]);
        let mut open = cube([0.0; 3], false);
        open.indices.truncate(30);
        assert_eq!(all(&open), vec![false; 24]);
    }

    #[test]
    fn parts_are_judged_apart_and_a_shared_face_stays_closed() {
        // Two cubes sharing a face (a Menger sponge's neighbours) are one closed part.
        assert_eq!(all(&joined(cube([0.0; 3], false), cube([1.0, 0.0, 0.0], false))), vec![true; 48]);
        // An open cube next to a closed one: only the closed one culls.
        let mut open = cube([5.0, 0.0, 0.0], false);
        open.indices.truncate(30);
        let got = all(&joined(cube([0.0; 3], false), open));
        assert_eq!(got, [vec![true; 24], vec![false; 24]].concat());
        // An inward cube far away does not borrow the other's volume.
        let got = all(&joined(cube([0.0; 3], false), cube([9.0, 0.0, 0.0], true)));
        assert_eq!(got, [vec![true; 24], vec![false; 24]].concat());
    }

    #[test]
    fn culling_an_outward_cube_changes_no_pixel_and_costs_fewer_steps() {
        use super::super::{camera::Framing, raster, shade::Lights, PreviewOptions, View};
        use crate::core::budget::{Budget, Limits};
        use crate::geom::NamedMesh;
        let mesh = cube([0.0; 3], false);
        let flags = all(&mesh);
        let meshes = vec![NamedMesh { name: "model".into(), mesh }];
        for view in View::ALL {
            let options = PreviewOptions { size: 64, view, background: None };
            let frame = Framing::of(&meshes, view, 64, raster::samples_per_axis(64));
            let verts = vec![raster::project(&meshes[0].mesh, &frame, &Lights::default())];
            let draw = |cull: Vec<bool>| {
                let mut budget = Budget::new(Limits::default());
                let image = raster::draw(&meshes, &verts, &[cull], &options, &mut budget).expect("drawn");
                (image, budget.steps())
            };
            let (culled, culled_steps) = draw(flags.clone());
            let (both, both_steps) = draw(vec![false; 24]);
            assert_eq!(culled, both, "{view:?}");
            assert!(culled_steps < both_steps, "{view:?}: {culled_steps} vs {both_steps}");
            assert!(culled.rgba.chunks(4).filter(|p| p[3] == 255).count() > 64 * 64 / 4, "{view:?}");
        }
    }
}
