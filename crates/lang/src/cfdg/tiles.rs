//! A rendered CFDG picture as a flat 3D model: every primitive a thin tile
//! (SQUARE a box, CIRCLE a cylinder on its side, TRIANGLE a prism of free
//! triangles, since the Model has no triangular prototype; a path a slab
//! of its tessellated fill or stroke, [`super::solid`]), all of one
//! thickness, each lifted a little above the one drawn before it, so that
//! seen from above the model shows what cfdg draws and every 3D format
//! (glb, stl, 3mf, scene) can write it.

use super::eval::Picture;
use crate::core::budget::Budget;
use crate::core::PrimitiveKind;
use crate::model::scene::{AffineInstance, FreeVertex, Scene, AFFINE_INSTANCE_BYTES, FREE_VERTEX_BYTES};
use crate::model::{BuildRequest, EvalError};
use glam::{DVec3, Mat3, Vec3};

/// Tile thickness as a fraction of the picture's larger side.
pub(crate) const THICKNESS: f64 = 0.002;

/// sRGB to linear (the Model's colours are linear; cfdg's are sRGB).
fn linear(c: f64) -> f32 {
    let c = c.clamp(0.0, 1.0);
    (if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }) as f32
}

/// The picture's background as the Model's linear colour.
pub(crate) fn background(p: &Picture) -> Option<[f32; 4]> {
    Some([linear(p.background[0]), linear(p.background[1]), linear(p.background[2]), p.background[3] as f32])
}

/// Builds the tiles of `p`, charging the memory the scene keeps.
pub fn scene(p: &Picture, _req: &BuildRequest<'_>, budget: &mut Budget) -> Result<Scene, EvalError> {
    let mut scene = Scene::default();
    let scale = p.to_pixels.sx.abs().max(1e-300);
    let extent = f64::from(p.width.max(p.height)) / scale;
    let h = (extent * THICKNESS).max(f64::MIN_POSITIVE);
    let n = p.shapes.len().max(1) as f64;
    scene.background = background(p);
    for (i, s) in p.shapes.iter().enumerate() {
        let t = &s.transform;
        let z = h * i as f64 / n;
        let colour = [linear(s.rgba[0]), linear(s.rgba[1]), linear(s.rgba[2]), s.rgba[3].clamp(0.0, 1.0) as f32];
        let u = Vec3::new(t.sx as f32, t.shy as f32, 0.0);
        let v = Vec3::new(t.shx as f32, t.sy as f32, 0.0);
        let w = Vec3::new(0.0, 0.0, h as f32);
        let centre = Vec3::new(t.tx as f32, t.ty as f32, (z + h / 2.0) as f32);
        match s.kind {
            1 => {
                budget.reserve_memory(AFFINE_INSTANCE_BYTES)?;
                scene.affine.push(AffineInstance { kind: PrimitiveKind::Box, linear: Mat3::from_cols(u, v, w), translation: centre, colour, class: 0 });
            }
            0 => {
                budget.reserve_memory(AFFINE_INSTANCE_BYTES)?;
                // The cylinder's axis is +Y: send it to +Z.
                scene.affine.push(AffineInstance { kind: PrimitiveKind::Cylinder, linear: Mat3::from_cols(u, w, v), translation: centre, colour, class: 0 });
            }
            // A path: each command's fill or stroke a slab of the same thickness (solid.rs).
            // A whole-canvas fill has no solid form.
            4.. => {}
            3 => {
                for d in p.paths.get(s.path).map_or(&[][..], Vec::as_slice) {
                    let c = [linear(d.rgba[0]), linear(d.rgba[1]), linear(d.rgba[2]), d.rgba[3].clamp(0.0, 1.0) as f32];
                    super::solid::slab(d, z, h, scale, c, &mut scene, budget)?;
                }
            }
            _ => {
                budget.reserve_memory(24 * FREE_VERTEX_BYTES)?;
                let pts: Vec<DVec3> = super::eval::frame::polygon(2)
                    .iter()
                    .map(|&(x, y)| {
                        let (px, py) = t.apply(x, y);
                        DVec3::new(px, py, z)
                    })
                    .collect();
                let up = DVec3::new(0.0, 0.0, h);
                let flip = t.determinant() < 0.0;
                let [a, b, c] = if flip { [pts[0], pts[2], pts[1]] } else { [pts[0], pts[1], pts[2]] };
                let mut tri = |p: [DVec3; 3]| {
                    let nrm = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
                    for q in p {
                        scene.vertices.push(FreeVertex { position: q, normal: nrm, colour });
                    }
                };
                tri([a + up, b + up, c + up]);
                tri([a, c, b]);
                for (p0, p1) in [(a, b), (b, c), (c, a)] {
                    tri([p0, p1, p1 + up]);
                    tri([p0, p1 + up, p0 + up]);
                }
            }
        }
    }
    Ok(scene)
}
