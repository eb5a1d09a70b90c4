//! Whether a mesh is a closed, outward-facing surface, whose back faces the
//! rasteriser may skip (`docs/preview.md`, "Back faces").
//!
//! Lighting is two-sided and open surfaces (an L-system leaf, a UniGrafix
//! polygon, a sheet) must show both sides, so a back face may be skipped
//! only where it can never be seen: on the surface of a solid seen from
//! outside, a ray meets a face turned towards the camera before any face
//! turned away. The rule, for each mesh the pipeline hands over (the whole
//! model, or one per primitive kind):
//!
//! 1. Corners at bit-identical positions are one point (−0 and +0 are
//!    one), so a flat-shaded box, whose faces repeat their corners, counts
//!    as one surface.
//! 2. The mesh is *closed* when every edge between two points is run
//!    through as often in one direction as in the other by its triangles:
//!    no open edge anywhere, no neighbours wound against each other. Boxes
//!    sharing a face (a Menger sponge) stay closed; one leaf, one missing
//!    triangle or a T-junction makes the whole mesh open.
//! 3. A closed mesh is *outward* when its signed volume is positive.
//!
//! Step 2 is checked without tables: each directed edge adds a 128-bit hash
//! of its two points and subtracts the hash of the reversed edge; the sum
//! is zero exactly when the edges balance, up to a hash collision (about
//! 2⁻¹²⁸ for any mesh not built to collide). A linear pass over the
//! triangles in their own order: the exact check with a weld and an edge
//! table was measured to cost more time than culling saved (random access
//! into megabytes of tables).
//!
//! What the rule cannot see: a closed mesh whose total volume is positive
//! but which holds an inward-wound closed part, or a surface that passes
//! through itself with a fold turned inside out; there the picture would
//! show what lies behind the inward part. The meshers wind every solid
//! outward (the winding test checks every grammar's triangles against their
//! normals), so only a hand-made inward solid among outward ones could.

use crate::geom::{Mesh, STOP_EVERY};

/// Whether `mesh` is closed and outward, so its triangles facing away from
/// the camera can never be seen. A mesh with no triangles, or with an index
/// out of range, is not. `None` when `stop`, asked every
/// [`STOP_EVERY`] triangles, said to give up (the deadline: one pass over
/// millions of triangles is a quarter of a second).
pub(crate) fn closed_outward_until(mesh: &Mesh, stop: &dyn Fn() -> bool) -> Option<bool> {
    let key = |i: u32| mesh.positions.get(i as usize).map(|p| p.map(|c| (c + 0.0).to_bits()));
    let Some(origin) = mesh.positions.first().map(|p| p.map(f64::from)) else {
        return Some(false);
    };
    let (mut balance, mut volume) = ([0u64; 2], 0.0f64);
    for (n, t) in mesh.indices.chunks_exact(3).enumerate() {
        if n % STOP_EVERY == STOP_EVERY - 1 && stop() {
            return None;
        }
        let (Some(a), Some(b), Some(c)) = (key(t[0]), key(t[1]), key(t[2])) else {
            return Some(false);
        };
        for (p, q) in [(a, b), (b, c), (c, a)] {
            let (there, back) = (edge_hash(p, q), edge_hash(q, p));
            for k in 0..2 {
                balance[k] = balance[k].wrapping_add(there[k]).wrapping_sub(back[k]);
            }
        }
        // Six times the signed volume of the tetrahedron (origin, a, b, c),
        // about the first vertex so a model far from 0 keeps its precision.
        let [p, q, r] = [a, b, c].map(|k| k.map(|bits| f64::from(f32::from_bits(bits))));
        let [p, q, r] = [p, q, r].map(|v| [v[0] - origin[0], v[1] - origin[1], v[2] - origin[2]]);
        volume += p[0] * (q[1] * r[2] - q[2] * r[1]) + p[1] * (q[2] * r[0] - q[0] * r[2]) + p[2] * (q[0] * r[1] - q[1] * r[0]);
    }
    Some(balance == [0, 0] && volume > 0.0)
}

/// [`closed_outward_until`] to the end.
#[cfg(test)]
fn closed_outward(mesh: &Mesh) -> bool {
    closed_outward_until(mesh, &|| false).unwrap_or(false)
}

/// Two independent 64-bit hashes of the directed edge `p → q` (each point
/// as its coordinates' bits): multiply–xorshift rounds (SplitMix64's
/// constants), order-sensitive, so `p → q` and `q → p` differ.
fn edge_hash(p: [u32; 3], q: [u32; 3]) -> [u64; 2] {
    let words = [p[0], p[1], p[2], q[0], q[1], q[2]];
    [(0x9e37_79b9_7f4a_7c15u64, 0xbf58_476d_1ce4_e5b9u64), (0x94d0_49bb_1331_11ebu64, 0x2545_f491_4f6c_dd1du64)].map(|(seed, mul)| {
        let mut h = seed;
        for w in words {
            h = (h ^ u64::from(w)).wrapping_mul(mul);
            h ^= h >> 29;
        }
        h
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit cube, flat-shaded (4 corners per face, 24 in all), wound outward or inward.
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

    #[test]
    fn an_outward_cube_is_closed_outward_an_inward_or_open_one_is_not() {
        assert!(closed_outward(&cube([0.0; 3], false)));
        assert!(!closed_outward(&cube([0.0; 3], true)));
        let mut open = cube([0.0; 3], false);
        open.indices.truncate(30);
        assert!(!closed_outward(&open));
        // A corner at −0 is the same point as one at +0.
        let mut signed = cube([0.0; 3], false);
        signed.positions[0] = [-0.0, 0.0, 1.0];
        assert!(closed_outward(&signed));
        assert!(!closed_outward(&Mesh::default()));
        let mut bad = cube([0.0; 3], false);
        bad.indices[0] = 99;
        assert!(!closed_outward(&bad));
    }

    #[test]
    fn shared_faces_stay_closed_and_one_open_part_opens_the_mesh() {
        // Two cubes sharing a face (a Menger sponge's neighbours), far from the origin.
        assert!(closed_outward(&joined(cube([1000.0; 3], false), cube([1001.0, 1000.0, 1000.0], false))));
        let mut open = cube([5.0, 0.0, 0.0], false);
        open.indices.truncate(30);
        assert!(!closed_outward(&joined(cube([0.0; 3], false), open)));
        // An inward cube with an outward one of the same size: no volume, not culled.
        assert!(!closed_outward(&joined(cube([0.0; 3], false), cube([9.0, 0.0, 0.0], true))));
    }

    #[test]
    fn culling_an_outward_cube_changes_no_pixel_and_costs_fewer_steps() {
        use super::super::{camera::Framing, raster, shade::Lights, PreviewOptions, View};
        use crate::core::budget::{Budget, Limits};
        use crate::geom::NamedMesh;
        let meshes = vec![NamedMesh { name: "model".into(), mesh: cube([0.0; 3], false) }];
        for view in View::ALL {
            let options = PreviewOptions { size: 64, view, background: None };
            let frame = Framing::of(&meshes, view, 64, raster::samples_per_axis(64));
            let verts = vec![raster::project(&meshes[0].mesh, &frame, &Lights::default(), &|| false).unwrap_or_default()];
            let draw = |cull: bool| {
                let mut budget = Budget::new(Limits::default());
                let image = raster::draw(&meshes, &verts, &[cull], &options, &mut budget).expect("drawn");
                (image, budget.steps())
            };
            let ((culled, culled_steps), (both, both_steps)) = (draw(true), draw(false));
            assert_eq!(culled, both, "{view:?}");
            assert!(culled_steps < both_steps, "{view:?}: {culled_steps} vs {both_steps}");
            assert!(culled.rgba.chunks(4).filter(|p| p[3] == 255).count() > 64 * 64 / 4, "{view:?}");
        }
    }
}
