//! Isosurfaces: the surface f(x, y, z) = 0 of a scalar field, inside where
//! f > 0 (Andersson 2015 §4.1 fixes neither the level nor the side; this
//! is rulemesh's choice, docs/mdg.md), meshed with naive
//! surface nets (the `fast-surface-nets` crate: watertight output, no
//! ambiguous cases to tabulate, so no hand-written marching-cubes tables).
//!
//! The field is sampled at (cells + 1) points per axis across the bounding
//! box, inside a one-sample border that is forced to "outside", so a surface
//! cut by the box is closed against it instead of left open.

use super::primitives::Prototype;
use fast_surface_nets::ndshape::{RuntimeShape, Shape};
use fast_surface_nets::{surface_nets, SurfaceNetsBuffer};

/// Forced-outside samples on each side of the grid.
const BORDER: u32 = 2;

/// Samples the grid of an isosurface takes, border included, for the budget.
pub fn sample_count(axes: &[(f64, f64, u32); 3]) -> u64 {
    axes.iter().fold(1u64, |acc, &(_, _, cells)| acc.saturating_mul(u64::from(cells) + 1 + 2 * BORDER as u64))
}

/// Meshes the zero set of `field` over `axes` ((min, max, cells) per axis).
/// `field` returns f at a point; NaN counts as outside. The caller has
/// already charged [`sample_count`] samples to the budget.
pub fn mesh_isosurface(axes: &[(f64, f64, u32); 3], mut field: impl FnMut([f64; 3]) -> f64) -> Prototype {
    // Samples per axis: cells + 1, plus a border each side (surface nets makes
    // no faces in the outermost layer, so the forced-outside border is two deep).
    let dims = axes.map(|(_, _, c)| c.saturating_add(1 + 2 * BORDER));
    let shape = RuntimeShape::<u32, 3>::new(dims);
    let step = axes.map(|(lo, hi, c)| (hi - lo) / f64::from(c.max(1)));
    let mut sdf = vec![1.0f32; shape.usize()];
    for (i, v) in sdf.iter_mut().enumerate() {
        let [x, y, z] = shape.delinearize(i as u32);
        let border = [x, y, z].iter().zip(&dims).any(|(&c, &d)| c < BORDER || c + BORDER >= d);
        if border {
            continue;
        }
        let p = [0usize, 1, 2].map(|a| axes[a].0 + step[a] * f64::from([x, y, z][a] - BORDER));
        let f = field(p);
        // Surface nets expects negative inside; the seed's convention is f > 0 inside.
        *v = if f.is_finite() { (-f) as f32 } else { 1.0 };
    }
    let mut buffer = SurfaceNetsBuffer::default();
    surface_nets(&sdf, &shape, [0; 3], dims.map(|d| d - 1), &mut buffer);
    let positions: Vec<[f32; 3]> = buffer
        .positions
        .iter()
        .map(|p| [0usize, 1, 2].map(|a| (axes[a].0 + step[a] * (f64::from(p[a]) - f64::from(BORDER))) as f32))
        .collect();
    // The crate's normals are SDF gradients (pointing outward); scale them to
    // world units per axis and normalise.
    let normals: Vec<[f32; 3]> = buffer
        .normals
        .iter()
        .map(|n| {
            let v = glam::DVec3::new(f64::from(n[0]) / step[0], f64::from(n[1]) / step[1], f64::from(n[2]) / step[2]);
            v.try_normalize().unwrap_or(glam::DVec3::Z).as_vec3().to_array()
        })
        .collect();
    let mut indices = buffer.indices;
    // Make the winding agree with the outward normals: flip if the enclosed volume is negative.
    let volume: f64 = indices
        .chunks_exact(3)
        .map(|t| {
            let p = |i: u32| glam::DVec3::from_array(positions[i as usize].map(f64::from));
            p(t[0]).dot(p(t[1]).cross(p(t[2])))
        })
        .sum();
    if volume < 0.0 {
        for t in indices.chunks_exact_mut(3) {
            t.swap(1, 2);
        }
    }
    Prototype { positions, normals, indices }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sphere_field_gives_a_closed_outward_surface() {
        let axes = [(-1.0, 1.0, 16); 3];
        let p = mesh_isosurface(&axes, |[x, y, z]| 0.64 - (x * x + y * y + z * z));
        assert!(!p.indices.is_empty());
        // Every directed edge has its reverse: closed and consistently wound.
        let mut edges = std::collections::HashMap::new();
        for t in p.indices.chunks_exact(3) {
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                *edges.entry((a, b)).or_insert(0) += 1;
            }
        }
        for (&(a, b), &n) in &edges {
            assert_eq!(n, 1, "edge {a}-{b} used twice in one direction");
            assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}-{b} has no twin");
        }
        // Volume close to 4/3 π 0.8³ and positive.
        let v: f64 = p
            .indices
            .chunks_exact(3)
            .map(|t| {
                let q = |i: u32| glam::DVec3::from_array(p.positions[i as usize].map(f64::from));
                q(t[0]).dot(q(t[1]).cross(q(t[2]))) / 6.0
            })
            .sum();
        let exact = 4.0 / 3.0 * std::f64::consts::PI * 0.512;
        assert!((v - exact).abs() / exact < 0.05, "volume {v} vs {exact}");
    }

    #[test]
    fn a_field_cut_by_the_box_is_closed_against_it() {
        // Inside everywhere: the surface is the box itself.
        let axes = [(0.0, 1.0, 4); 3];
        let p = mesh_isosurface(&axes, |_| 1.0);
        assert!(!p.indices.is_empty());
        let mut edges = std::collections::HashSet::new();
        for t in p.indices.chunks_exact(3) {
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                edges.insert((a, b));
            }
        }
        assert!(edges.iter().all(|&(a, b)| edges.contains(&(b, a))));
    }
}
