//! Wall thickness of the printed solid, measured by rays: from the centre of
//! a surface triangle straight inward (against its outward normal) to where
//! the ray leaves the solid again. That distance is the wall's thickness
//! there; the thinnest over the triangles is the report's thinnest wall.
//!
//! A hit counts only on a triangle that faces along the ray (the far side of
//! the wall seen from inside: its outward normal has a positive dot with the
//! ray), that shares no corner with the start triangle (its neighbours,
//! which a ray leaving near a crease grazes at distance ≈ 0), and that is
//! further than a hair (10⁻⁶ of the model, at least 0.1 µm).
//!
//! A sharp edge or a corner poking out (where thickened surfaces meet, say)
//! is thin right at its tip, and the union leaves sliver triangles there
//! whose rays measure a fraction of the wall. A printer cannot fail on a
//! spot smaller than its own feature, so the thinnest wall reported is the
//! thinnest that covers at least `min_wall²` of surface: the measurements
//! are sorted by thickness and their start triangles' areas summed, and the
//! thickness at which the sum reaches that area is the thinnest wall (a
//! 0.5 mm plate's first triangle is already hundreds of mm²; the slivers at
//! the corners of the thickened icosahedron add up to 0.003 mm²). What this
//! does not see: walls between triangles that share a corner (a wedge's
//! very tip), and, above [`MAX_RAYS`] triangles, the ones between samples.

use super::bvh::{Bvh, RayQuery, BYTES_PER_TRIANGLE};
use crate::core::budget::{Budget, LimitExceeded};
use glam::DVec3;

/// Most rays cast: above this many triangles, an evenly spaced sample of
/// them (every k-th, deterministic) is measured, each standing for k
/// triangles' area. 20,000 rays take a few hundredths of a second.
pub(crate) const MAX_RAYS: usize = 20_000;

/// The thinnest place found and how the measurement went.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Walls {
    /// The thinnest wall over at least `min_wall²` of surface (mm, see the
    /// module's comment) and where it starts on the surface (the centre of
    /// the triangle the ray left from, mm); `None` when no ray found the
    /// other side (no triangles, or an open surface).
    pub thinnest: Option<(f64, [f64; 3])>,
    /// Rays cast.
    pub rays: u64,
    /// Rays that measured less than the minimum wall.
    pub thin: u64,
    /// The area of the triangles those rays left from (mm²).
    pub thin_area: f64,
}

/// Measures the walls of the solid (`positions` in mm, CCW `indices` wound
/// outward), counting those thinner than `min_wall` (less a micrometre, the
/// profile's resolution). Charges a step per triangle for the hierarchy and
/// one per ray (the search is a few microseconds a ray, far cheaper per
/// step than the union it follows), checks the deadline every 1,024 rays,
/// and reserves the hierarchy's memory while it works.
pub(crate) fn measure_walls(positions: &[[f32; 3]], indices: &[u32], min_wall: f64, budget: &mut Budget) -> Result<Walls, LimitExceeded> {
    let at = |i: u32| positions.get(i as usize).map_or(DVec3::ZERO, |p| DVec3::from_array(p.map(f64::from)));
    let corners: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let tris: Vec<[DVec3; 3]> = corners.iter().map(|t| t.map(at)).collect();
    let mut walls = Walls { thinnest: None, rays: 0, thin: 0, thin_area: 0.0 };
    if tris.is_empty() {
        return Ok(walls);
    }
    let bytes = (tris.len() as u64).saturating_mul(BYTES_PER_TRIANGLE + 80);
    budget.reserve_memory(bytes)?;
    budget.charge_steps(tris.len() as u64)?;
    let bvh = Bvh::build(&tris);
    let (lo, hi) = tris.iter().flatten().fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
    let min_t = ((hi - lo).max_element() * 1e-6).max(1e-4);
    let stride = tris.len().div_ceil(MAX_RAYS);
    let mut visits = 0u64;
    // (thickness, start triangle's area, start point) of every ray that hit.
    let mut hits: Vec<(f64, f64, DVec3)> = Vec::new();
    for (i, t) in tris.iter().enumerate().step_by(stride) {
        let cross = (t[1] - t[0]).cross(t[2] - t[0]);
        let Some(normal) = cross.try_normalize() else {
            continue;
        };
        let ray = RayQuery { origin: (t[0] + t[1] + t[2]) / 3.0, dir: -normal, min_t };
        let start = corners[i];
        let accept = |k: u32| {
            let other = &tris[k as usize];
            let faces_along = (other[1] - other[0]).cross(other[2] - other[0]).dot(ray.dir) > 0.0;
            faces_along && !corners[k as usize].iter().any(|v| start.contains(v))
        };
        walls.rays += 1;
        if let Some((d, _)) = bvh.nearest(&tris, &ray, accept, &mut visits) {
            // A sampled triangle stands for `stride` of them.
            let area = cross.length() / 2.0 * stride as f64;
            if d < min_wall - 1e-3 {
                walls.thin += 1;
                walls.thin_area += area;
            }
            hits.push((d, area, ray.origin));
        }
        if walls.rays % 1024 == 0 {
            budget.charge_steps(1024)?;
        }
    }
    budget.charge_steps(walls.rays % 1024)?;
    // Stable: the first in triangle order on a tie (deterministic).
    hits.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut covered = 0.0;
    for &(d, area, at) in &hits {
        covered += area;
        walls.thinnest = Some((d, at.to_array()));
        if covered >= min_wall * min_wall {
            break;
        }
    }
    budget.release_memory(bytes);
    Ok(walls)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;

    /// A closed box from `lo` to `hi`, outward CCW (12 triangles).
    fn cuboid(lo: [f32; 3], hi: [f32; 3]) -> (Vec<[f32; 3]>, Vec<u32>) {
        let p: Vec<[f32; 3]> = (0..8).map(|i| [if i & 1 == 0 { lo[0] } else { hi[0] }, if i & 2 == 0 { lo[1] } else { hi[1] }, if i & 4 == 0 { lo[2] } else { hi[2] }]).collect();
        let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        let idx = quads.iter().flat_map(|q: &[u32; 4]| [q[0], q[1], q[2], q[0], q[2], q[3]]).collect();
        (p, idx)
    }

    fn budget() -> Budget {
        Budget::new(Limits::default())
    }

    #[test]
    fn a_plate_is_as_thick_as_it_is() {
        let (p, idx) = cuboid([0.0, 0.0, 0.0], [20.0, 20.0, 0.5]);
        let w = measure_walls(&p, &idx, 0.8, &mut budget()).expect("within budget");
        let (t, at) = w.thinnest.expect("measured");
        assert!((t - 0.5).abs() < 1e-6, "{t}");
        assert!((at[2] - 0.5).abs() < 1e-6 || at[2].abs() < 1e-6, "{at:?}");
        assert_eq!((w.rays, w.thin, w.thin_area), (12, 4, 800.0));
        // Against a thinner minimum nothing is thin.
        assert_eq!(measure_walls(&p, &idx, 0.4, &mut budget()).expect("ok").thin, 0);
    }

    #[test]
    fn a_hollow_box_measures_its_wall_not_its_size() {
        // A 10 mm cube with a 1 mm wall: the cavity is a second, inward shell.
        let (mut p, mut idx) = cuboid([0.0; 3], [10.0; 3]);
        let (q, inner) = cuboid([1.0; 3], [9.0; 3]);
        let base = p.len() as u32;
        p.extend(q);
        idx.extend(inner.chunks_exact(3).flat_map(|t| [t[0] + base, t[2] + base, t[1] + base]));
        let w = measure_walls(&p, &idx, 0.8, &mut budget()).expect("ok");
        assert!((w.thinnest.expect("measured").0 - 1.0).abs() < 1e-6, "{w:?}");
        assert_eq!(w.thin, 0);
    }

    #[test]
    fn a_thin_spot_smaller_than_the_minimum_squared_is_not_the_thinnest_wall() {
        // A 10 mm cube and a 0.3 mm one: the small one's 0.54 mm² of surface
        // is thin, but less than 0.8², so the thinnest wall is the big cube's.
        let (mut p, mut idx) = cuboid([0.0; 3], [10.0; 3]);
        let (q, small) = cuboid([20.0; 3], [20.3; 3]);
        let base = p.len() as u32;
        p.extend(q);
        idx.extend(small.iter().map(|v| v + base));
        let w = measure_walls(&p, &idx, 0.8, &mut budget()).expect("ok");
        assert!((w.thinnest.expect("measured").0 - 10.0).abs() < 1e-6, "{w:?}");
        assert_eq!(w.thin, 12);
        assert!((w.thin_area - 0.54).abs() < 1e-5, "{w:?}");
        // Against a 0.5 mm minimum (0.25 mm² is enough) the small cube is the thinnest.
        let w = measure_walls(&p, &idx, 0.5, &mut budget()).expect("ok");
        assert!((w.thinnest.expect("measured").0 - 0.3).abs() < 1e-5, "{w:?}");
    }

    #[test]
    fn rays_are_charged_and_bounded_by_the_budget() {
        let (p, idx) = cuboid([0.0; 3], [1.0; 3]);
        let mut b = Budget::new(Limits { max_steps: 10, ..Limits::default() });
        assert!(measure_walls(&p, &idx, 0.8, &mut b).is_err());
        let mut b = budget();
        measure_walls(&p, &idx, 0.8, &mut b).expect("ok");
        // A step per triangle and one per ray.
        assert_eq!(b.steps(), 24);
        assert_eq!(b.memory(), 0);
        assert_eq!(measure_walls(&[], &[], 0.8, &mut b).expect("ok"), Walls { thinnest: None, rays: 0, thin: 0, thin_area: 0.0 });
    }
}
