//! Normalising a model's placement for icons: [`fit_unit_box`] scales and
//! moves every mesh so the whole model fits a unit box centred at the origin.
//! An export option, applied after meshing: the parser and evaluator never
//! see it.

use crate::core::budget::{Budget, LimitExceeded};
use crate::geom::NamedMesh;

/// The bounding box of the vertices that triangles use, over all meshes
/// (`None` for a model without triangles).
pub fn bounds(meshes: &[NamedMesh]) -> Option<([f64; 3], [f64; 3])> {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for m in meshes {
        for &i in &m.mesh.indices {
            if let Some(p) = m.mesh.positions.get(i as usize) {
                for a in 0..3 {
                    lo[a] = lo[a].min(f64::from(p[a]));
                    hi[a] = hi[a].max(f64::from(p[a]));
                }
            }
        }
    }
    (lo.iter().chain(&hi).all(|c| c.is_finite())).then_some((lo, hi))
}

/// The map `p ↦ (p − centre) · scale` that [`fit_unit_box`] applies:
/// the bounding box's centre and the inverse of its longest side (1 for a
/// flat or empty model). `None` when the meshes have no finite bounds.
pub(crate) fn unit_box_map(meshes: &[NamedMesh]) -> Option<([f64; 3], f64)> {
    let (lo, hi) = bounds(meshes)?;
    let centre = [0, 1, 2].map(|a| (lo[a] + hi[a]) * 0.5);
    let ext = (0..3).map(|a| hi[a] - lo[a]).fold(0.0f64, f64::max);
    Some((centre, if ext > 0.0 { 1.0 / ext } else { 1.0 }))
}

/// A copy of `meshes` scaled uniformly so the longest side of the bounding
/// box is 1 and moved so its centre is the origin: every position ends up in
/// `[-0.5, 0.5]³`. Normals are unchanged (the scale is uniform and positive,
/// so winding too). A model without triangles, or of zero extent, is only
/// moved. The copy's bytes are reserved in `budget` first. Also returns the
/// map it applied ([`unit_box_map`]), so whatever is placed with the model
/// (a camera) can be moved alike without measuring the bounds again.
pub fn fit_unit_box(meshes: &[NamedMesh], budget: &mut Budget) -> Result<(Vec<NamedMesh>, Option<([f64; 3], f64)>), LimitExceeded> {
    budget.reserve_memory(meshes.iter().map(|m| m.mesh.byte_size()).sum())?;
    let map = unit_box_map(meshes);
    let Some((centre, scale)) = map else {
        return Ok((meshes.to_vec(), None));
    };
    let fitted = meshes
        .iter()
        .map(|m| {
            let mut m = m.clone();
            for p in &mut m.mesh.positions {
                *p = [0, 1, 2].map(|a| (((f64::from(p[a]) - centre[a]) * scale) as f32).clamp(-0.5, 0.5));
            }
            m
        })
        .collect();
    Ok((fitted, map))
}
