//! Wall thickness of the printed solid, measured by rays: from the centre of
//! a surface triangle straight inward (against its outward normal) to where
//! the ray leaves the solid again. That distance is the wall's thickness
//! there; the thinnest over the triangles is the report's thinnest wall.
//!
//! A hit counts only on a triangle that faces along the ray (the far side of
//! the wall seen from inside: its outward normal has a positive dot with the
//! ray), that shares no corner with the start triangle (its neighbours,
//! which a ray leaving near a crease grazes at distance ≈ 0), and that is
//! further than a hair (10⁻⁶ of the model, at least 0.1 µm). What this does
//! not see: a wall measured at a slant (a ray inward along one face's normal
//! crosses a wedge's other face sooner than the wedge is thick, so knife
//! edges report their real, thin, thickness near the edge) and walls
//! between triangles that share a corner (a wedge's very tip).

use super::bvh::{Bvh, RayQuery, BYTES_PER_TRIANGLE};
use crate::core::budget::{Budget, LimitExceeded};
use glam::DVec3;

/// Most rays cast: above this many triangles, an evenly spaced sample of
/// them (every k-th, deterministic) is measured. 50,000 rays take well under
/// a tenth of a second.
pub const MAX_RAYS: usize = 50_000;

/// The thinnest place found and how the measurement went.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Walls {
    /// The thinnest wall (mm) and where it starts on the surface (the centre
    /// of the triangle the ray left from, mm); `None` when no ray found the
    /// other side (no triangles, or an open surface).
    pub thinnest: Option<(f64, [f64; 3])>,
    /// Rays cast.
    pub rays: u64,
    /// Rays that measured less than the minimum wall.
    pub thin: u64,
}

/// Measures the walls of the solid (`positions` in mm, CCW `indices` wound
/// outward), counting those thinner than `min_wall` (less a micrometre, the
/// profile's resolution). Charges a step per node and triangle visited, and
/// reserves the hierarchy's memory while it works.
pub fn measure_walls(positions: &[[f32; 3]], indices: &[u32], min_wall: f64, budget: &mut Budget) -> Result<Walls, LimitExceeded> {
    let at = |i: u32| positions.get(i as usize).map_or(DVec3::ZERO, |p| DVec3::from_array(p.map(f64::from)));
    let corners: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let tris: Vec<[DVec3; 3]> = corners.iter().map(|t| t.map(at)).collect();
    let mut walls = Walls { thinnest: None, rays: 0, thin: 0 };
    if tris.is_empty() {
        return Ok(walls);
    }
    let bytes = (tris.len() as u64).saturating_mul(BYTES_PER_TRIANGLE + 80);
    budget.reserve_memory(bytes)?;
    let (bvh, work) = Bvh::build(&tris);
    budget.charge_steps(work)?;
    let (lo, hi) = tris.iter().flatten().fold((DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
    let min_t = ((hi - lo).max_element() * 1e-6).max(1e-4);
    let stride = tris.len().div_ceil(MAX_RAYS);
    let mut visits = 0u64;
    for (i, t) in tris.iter().enumerate().step_by(stride) {
        let Some(normal) = (t[1] - t[0]).cross(t[2] - t[0]).try_normalize() else {
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
            if d < min_wall - 1e-3 {
                walls.thin += 1;
            }
            // The first thinnest in triangle order on a tie (deterministic).
            if walls.thinnest.is_none_or(|(best, _)| d < best) {
                walls.thinnest = Some((d, ray.origin.to_array()));
            }
        }
        if walls.rays % 1024 == 0 {
            budget.charge_steps(std::mem::take(&mut visits))?;
        }
    }
    budget.charge_steps(visits)?;
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
        assert_eq!((w.rays, w.thin), (12, 4));
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
    fn rays_are_charged_and_bounded_by_the_budget() {
        let (p, idx) = cuboid([0.0; 3], [1.0; 3]);
        let mut b = Budget::new(Limits { max_steps: 10, ..Limits::default() });
        assert!(measure_walls(&p, &idx, 0.8, &mut b).is_err());
        let mut b = budget();
        measure_walls(&p, &idx, 0.8, &mut b).expect("ok");
        assert!(b.steps() > 12, "{}", b.steps());
        assert_eq!(b.memory(), 0);
        assert_eq!(measure_walls(&[], &[], 0.8, &mut b).expect("ok"), Walls { thinnest: None, rays: 0, thin: 0 });
    }
}
