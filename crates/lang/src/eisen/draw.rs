//! Drawing Structure Synth's primitives: each becomes affine instances of
//! rulemesh's prototypes (a box, a sphere, a cylinder; lines, grids and dots
//! as thin solids so the model stays printable) or free triangles
//! (`triangle[…]`, `mesh`), charged to the budget as it is placed: its
//! triangles, the memory the scene keeps and the memory meshing and export
//! will need.

use super::{BuildOptions, Built};
use crate::core::budget::{Budget, LimitExceeded};
use crate::core::PrimitiveKind;
use crate::eisen::syntax::Primitive;
use crate::model::instancing;
use crate::model::scene::{AffineInstance, FreeVertex, AFFINE_INSTANCE_BYTES, FREE_VERTEX_BYTES};
use glam::{DMat3, DMat4, DVec3, Mat3};

/// Where and how a primitive is drawn: the state's frame, the frame before
/// its last loop step (what `mesh` joins to) and its colour as linear RGBA.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Placement {
    pub(super) matrix: DMat4,
    /// `None` when no loop step lies on the state's path: Structure Synth's
    /// `State::previous` is null until `Action::apply` sets it for a loop copy
    /// (State.cpp:10, Action.cpp:38-41).
    pub(super) previous: Option<DMat4>,
    pub(super) colour: [f32; 4],
}

/// What drawing needs from the builder: its options, the budget and the scene so far.
pub(super) struct Canvas<'b> {
    pub(super) opts: &'b BuildOptions,
    pub(super) budget: &'b mut Budget,
    pub(super) built: &'b mut Built,
}

impl Canvas<'_> {
    /// Draws primitive `p` (or the triangle `tri`) in the frame `at`.
    /// Structure Synth counts every drawn primitive and triangle as an object,
    /// but not `template` (`PrimitiveRule::apply`, PrimitiveRule.cpp:44-50,
    /// 125-126).
    pub(super) fn draw(&mut self, p: Primitive, class: u32, at: &Placement, tri: Option<&[DVec3; 3]>) -> Result<(), LimitExceeded> {
        let (colour, m) = (at.colour, at.matrix);
        let r = self.opts.line_radius;
        let mut placed: Vec<(PrimitiveKind, DMat3, DVec3)> = Vec::new();
        let mut faces: Vec<[DVec3; 3]> = Vec::new();
        let lin = DMat3::from_mat4(m);
        let size = lin.determinant().abs().cbrt();
        let size = if size.is_finite() && size > 0.0 { size } else { (lin.x_axis.length() + lin.y_axis.length() + lin.z_axis.length()) / 3.0 };
        let half = DVec3::splat(0.5);
        match (p, tri) {
            (_, Some(pts)) => {
                let [a, b, c] = pts.map(|q| m.transform_point3(q));
                // Both sides, so the triangle shows from either side.
                faces.push([a, b, c]);
                faces.push([a, c, b]);
            }
            (Primitive::Box, _) => placed.push((PrimitiveKind::Box, lin, m.transform_point3(half))),
            (Primitive::Sphere, _) => placed.push((PrimitiveKind::Sphere, lin, m.transform_point3(half))),
            (Primitive::Cylinder, _) => {
                // The prototype's axis is +Y; Structure Synth's is local x.
                let swap = DMat3::from_cols(DVec3::Y, DVec3::X, DVec3::Z);
                let flip = DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0));
                placed.push((PrimitiveKind::Cylinder, lin * swap * flip, m.transform_point3(half)));
            }
            (Primitive::Line, _) => {
                let a = m.transform_point3(DVec3::new(0.0, 0.5, 0.5));
                let b = m.transform_point3(DVec3::new(1.0, 0.5, 0.5));
                placed.extend(bar(a, b, r * size));
            }
            (Primitive::Grid, _) => {
                for (a, b) in cube_edges() {
                    placed.extend(bar(m.transform_point3(a), m.transform_point3(b), r * size));
                }
            }
            (Primitive::Point, _) => {
                placed.push((PrimitiveKind::Icosahedron, DMat3::from_diagonal(DVec3::splat(4.0 * r * size)), m.transform_point3(half)));
            }
            // Without a previous frame Structure Synth counts the object and draws
            // nothing ("No prev", PrimitiveRule.cpp:50, 65-83).
            (Primitive::Mesh, _) => faces.extend(at.previous.map(|from| mesh_solid(&from, &m)).unwrap_or_default()),
            (Primitive::Template, None) => return Ok(()),
        }
        let placed: Vec<AffineInstance> = placed
            .into_iter()
            .map(|(kind, l, t)| AffineInstance {
                kind,
                linear: Mat3::from_cols(l.x_axis.as_vec3(), l.y_axis.as_vec3(), l.z_axis.as_vec3()),
                translation: t.as_vec3(),
                colour,
                class,
            })
            .collect();
        let flat = |a: &AffineInstance| crate::geom::primitives::triangle_count(a.kind, self.opts.detail);
        self.built.objects += 1;
        if placed.iter().map(flat).sum::<u64>() + faces.len() as u64 == 0 {
            return Ok(());
        }
        // Under instanced output a repeated mesh costs a triangle and an
        // instance's bytes after its first placement (`Tally`).
        let (mut triangles, mut downstream) = (faces.len() as u64, 3 * faces.len() as u64 * self.opts.vertex_bytes);
        for a in &placed {
            let key = instancing::Placement::of_affine(a).map(|p| p.key);
            let (t, b) = self.built.tally.cost(key, flat(a), self.opts.downstream_bytes[a.kind as usize]);
            (triangles, downstream) = (triangles + t, downstream.saturating_add(b));
        }
        self.budget.charge_primitive(triangles)?;
        let stored = AFFINE_INSTANCE_BYTES * placed.len() as u64 + 3 * FREE_VERTEX_BYTES * faces.len() as u64;
        self.budget.reserve_memory(stored.saturating_add(downstream))?;
        self.built.promised = self.built.promised.saturating_add(downstream);
        self.built.scene.affine.extend(placed);
        for [a, b, c] in faces {
            let n = (b - a).cross(c - a);
            let Some(n) = n.try_normalize() else { continue };
            for v in [a, b, c] {
                self.built.scene.vertices.push(FreeVertex { position: v, normal: n, colour });
            }
        }
        Ok(())
    }
}

/// A thin square bar from `a` to `b` with half-thickness `r`, as a box.
fn bar(a: DVec3, b: DVec3, r: f64) -> Option<(PrimitiveKind, DMat3, DVec3)> {
    let d = b - a;
    if !(d.length() > 0.0) || !(r > 0.0) {
        return None;
    }
    // `any_orthonormal_vector` needs a unit input: given `d` itself it gave a
    // vector neither unit nor perpendicular, so bars were sheared and of
    // uneven thickness (and had no TRS form for instancing).
    let axis = d.normalize();
    let u = axis.any_orthonormal_vector();
    let v = axis.cross(u);
    let (u, v) = (u * (2.0 * r), v * (2.0 * r));
    Some((PrimitiveKind::Box, DMat3::from_cols(d, u, v), (a + b) * 0.5))
}

/// The twelve edges of the unit cube: along each axis, from each corner of the opposite face.
fn cube_edges() -> impl Iterator<Item = (DVec3, DVec3)> {
    (0..3).flat_map(|axis: usize| {
        (0..4).map(move |k: u32| {
            let mut a = DVec3::ZERO;
            a[(axis + 1) % 3] = f64::from(k & 1);
            a[(axis + 2) % 3] = f64::from(k >> 1);
            let mut b = a;
            b[axis] = 1.0;
            (a, b)
        })
    })
}

/// The closed solid between the x = 0 unit squares of two frames, as
/// outward-facing triangles (12; degenerate ones are dropped by the caller).
fn mesh_solid(from: &DMat4, to: &DMat4) -> Vec<[DVec3; 3]> {
    let square = |m: &DMat4| [(0., 0.), (1., 0.), (1., 1.), (0., 1.)].map(|(y, z)| m.transform_point3(DVec3::new(0.0, y, z)));
    let (a, b) = (square(from), square(to));
    let centre = (a.iter().chain(b.iter()).copied().sum::<DVec3>()) / 8.0;
    let quads = [[a[0], a[1], a[2], a[3]], [b[0], b[3], b[2], b[1]], [a[0], b[0], b[1], a[1]], [a[1], b[1], b[2], a[2]], [a[2], b[2], b[3], a[3]], [a[3], b[3], b[0], a[0]]];
    let mut out = Vec::with_capacity(12);
    for q in quads {
        for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            let n = (t[1] - t[0]).cross(t[2] - t[0]);
            let mid = (t[0] + t[1] + t[2]) / 3.0;
            out.push(if n.dot(mid - centre) < 0.0 { [t[0], t[2], t[1]] } else { t });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_edges_are_the_twelve_unit_edges() {
        let edges: Vec<(DVec3, DVec3)> = cube_edges().collect();
        assert_eq!(edges.len(), 12);
        for (i, (a, b)) in edges.iter().enumerate() {
            assert_eq!((*b - *a).length(), 1.0);
            assert!(edges[..i].iter().all(|e| e != &(*a, *b)));
        }
    }

    #[test]
    fn bars_are_square_and_perpendicular_to_their_edge() {
        for (a, b) in [(DVec3::ZERO, DVec3::new(3.0, 0.5, -2.0)), (DVec3::ONE, DVec3::new(1.0, 1.0, 0.2)), (DVec3::ZERO, DVec3::new(0.0, 0.0, -4.0))] {
            let (_, m, centre) = bar(a, b, 0.25).expect("a bar");
            assert_eq!(centre, (a + b) * 0.5);
            assert!((m.x_axis - (b - a)).length() < 1e-12);
            for axis in [m.y_axis, m.z_axis] {
                assert!((axis.length() - 0.5).abs() < 1e-12, "{axis}");
                assert!(axis.dot(m.x_axis).abs() < 1e-12);
            }
            assert!(m.y_axis.dot(m.z_axis).abs() < 1e-12);
            // Right-handed, so the box keeps its outward winding.
            assert!(m.determinant() > 0.0);
        }
    }

    #[test]
    fn mesh_solid_is_closed_and_outward() {
        let from = DMat4::IDENTITY;
        for to in [DMat4::from_translation(DVec3::X), DMat4::from_translation(-2.0 * DVec3::X), DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::new(1.0, -1.0, 1.0))] {
            let tris = mesh_solid(&from, &to);
            assert_eq!(tris.len(), 12);
            // Signed volume by the divergence theorem: positive when every face points outward.
            let v: f64 = tris.iter().map(|[a, b, c]| a.dot(b.cross(*c)) / 6.0).sum();
            assert!(v > 0.0, "{v}");
        }
    }

    #[test]
    fn bars_span_their_segment() {
        let Some((kind, m, t)) = bar(DVec3::ZERO, DVec3::new(0.0, 0.0, 2.0), 0.1) else { panic!("no bar") };
        assert_eq!(kind, PrimitiveKind::Box);
        assert_eq!(t, DVec3::new(0.0, 0.0, 1.0));
        assert!((m.determinant().abs() - 2.0 * 0.2 * 0.2).abs() < 1e-12);
        assert!(bar(DVec3::ONE, DVec3::ONE, 0.1).is_none());
    }
}
