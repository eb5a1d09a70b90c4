//! The preview's camera: the view directions, and framing from the geometry
//! drawn, robust to outliers (`docs/preview.md`, "Framing").
//!
//! The rule: take every vertex's position on the picture plane; per axis,
//! the box from the 1st to the 99th percentile is the *core*. When the whole
//! extent is at most [`OUTLIER_FACTOR`] times the core's, the whole extent
//! is framed (nothing is cut off a tree's tip); when it is more — a backdrop
//! box hundreds of units wide behind a model of ten, two stray parts far
//! apart — the core grown by [`CORE_MARGIN`] is framed, and whatever lies
//! outside is drawn where it falls (a backdrop reads as a ground plane or a
//! wall behind the model). Vertices count one each, whatever the area of
//! their triangles: a backdrop box has 24 vertices however large it is, so
//! it never outweighs the model. The framed box, centred, spans [`FILL`] of
//! the picture's side on its longer axis.

use super::View;
use crate::geom::NamedMesh;

/// The share of the picture's side the framed box spans on its longer axis.
pub const FILL: f32 = 0.8;
/// How much larger than its core (1st–99th percentile) an axis's whole
/// extent may be before the outliers are framed out. A tree whose canopy
/// holds most vertices has a whole extent twice its core; the backdrops of
/// Structure Synth's `RoundTree.es` and `Nabla.es` are 7 and 90 times.
pub(crate) const OUTLIER_FACTOR: f32 = 4.0;
/// The margin added on each side of a core that is framed instead of the
/// whole extent, as a share of the core's extent.
pub(crate) const CORE_MARGIN: f32 = 0.1;
/// The share of vertices on each side of the core (1 %).
pub(crate) const TAIL: usize = 100;

/// Where the camera is and how the picture plane maps to samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Framing {
    /// The picture's right on the world, as a unit vector.
    pub right: [f32; 3],
    /// The picture's up on the world, as a unit vector.
    pub up: [f32; 3],
    /// Towards the camera, as a unit vector (right × up).
    pub back: [f32; 3],
    /// The framed box's centre on the picture plane (along `right`, `up`).
    pub centre: [f32; 2],
    /// Samples per world unit.
    pub scale: f32,
    /// Samples per side of the supersampled picture.
    pub samples: u32,
    /// The nearest and farthest vertex along `back` (the depth range).
    pub depth: [f32; 2],
}

/// The three view axes (right, up, back) of `view`: an orthographic camera
/// at azimuth `a` round +Y from +Z and elevation `e`, computed in `f64` with
/// `libm` so they are the same bits everywhere.
pub fn axes(view: View) -> [[f32; 3]; 3] {
    if view == View::Top {
        // Looking down, the model's front (+Z) at the bottom of the picture.
        return [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    }
    let (a, e): (f64, f64) = match view {
        View::Front => (0.0, 0.0),
        View::ThreeQuarter => (30.0, 20.0),
        // atan(1/√2): the isometric elevation.
        View::Iso => (45.0, libm::atan(libm::sqrt(0.5)).to_degrees()),
        View::Top => (0.0, 90.0),
    };
    let (a, e) = (a.to_radians(), e.to_radians());
    let back = [libm::sin(a) * libm::cos(e), libm::sin(e), libm::cos(a) * libm::cos(e)];
    // right = normalise(Y × back), up = back × right.
    let len = libm::sqrt(back[2] * back[2] + back[0] * back[0]);
    let right = [back[2] / len, 0.0, -back[0] / len];
    let up = [
        back[1] * right[2] - back[2] * right[1],
        back[2] * right[0] - back[0] * right[2],
        back[0] * right[1] - back[1] * right[0],
    ];
    [right, up, back].map(|v| v.map(|c| c as f32))
}

/// `a · b` in a fixed order.
pub fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// An integer whose order is `f32::total_cmp`'s order of `v`.
fn total_key(v: f32) -> i32 {
    let bits = v.to_bits() as i32;
    bits ^ (((bits >> 31) as u32) >> 1) as i32
}

/// The float whose [`total_key`] is `key`.
fn float_of_key(key: i32) -> f32 {
    f32::from_bits((key ^ (((key >> 31) as u32) >> 1) as i32) as u32)
}

/// The framed interval of one picture axis from its coordinates: the whole extent, or the core with a margin when outliers
/// stretch the whole extent past [`OUTLIER_FACTOR`] times the core's.
fn framed_interval(values: &[f32]) -> (f32, f32) {
    let n = values.len();
    let (min, max) = values.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    let k = n / TAIL;
    if k == 0 {
        return (min, max);
    }
    // The k-th smallest and largest values are the same whatever order
    // select_nth leaves the rest in, so the result is deterministic. They
    // are selected as integers ordered as `f32::total_cmp` orders the
    // floats (a third of the comparisons' cost), the largest among those
    // above the smallest.
    let mut keys: Vec<i32> = values.iter().map(|v| total_key(*v)).collect();
    let (_, lo, above) = keys.select_nth_unstable(k);
    let lo = *lo;
    let hi = *above.select_nth_unstable(n - 2 - 2 * k).1;
    let (lo, hi) = (float_of_key(lo), float_of_key(hi));
    let core = hi - lo;
    if max - min <= OUTLIER_FACTOR * core {
        (min, max)
    } else {
        (lo - CORE_MARGIN * core, hi + CORE_MARGIN * core)
    }
}

impl Framing {
    /// Frames the vertices of `meshes` seen from `view` in a picture of
    /// `size` pixels of `ss`×`ss` samples each. Non-finite positions (which
    /// meshing never makes) are left out.
    pub fn of(meshes: &[NamedMesh], view: View, size: u32, ss: u32) -> Framing {
        let [right, up, back] = axes(view);
        let samples = size * ss;
        let points = meshes.iter().flat_map(|m| m.mesh.positions.iter()).filter(|p| p.iter().all(|c| c.is_finite()));
        let count = points.clone().count();
        let (mut xs, mut ys) = (Vec::with_capacity(count), Vec::with_capacity(count));
        let mut depth = [f32::NEG_INFINITY, f32::INFINITY];
        for &p in points {
            xs.push(dot(p, right));
            ys.push(dot(p, up));
            let d = dot(p, back);
            depth = [depth[0].max(d), depth[1].min(d)];
        }
        if count == 0 {
            return Framing { right, up, back, centre: [0.0, 0.0], scale: 1.0, samples, depth: [0.0, 0.0] };
        }
        let (x0, x1) = framed_interval(&xs);
        let (y0, y1) = framed_interval(&ys);
        let extent = (x1 - x0).max(y1 - y0);
        // A point or a line seen end-on: any scale centres it.
        let extent = if extent > 0.0 && extent.is_finite() { extent } else { 1.0 };
        let scale = FILL * samples as f32 / extent;
        Framing { right, up, back, centre: [0.5 * (x0 + x1), 0.5 * (y0 + y1)], scale, samples, depth }
    }

    /// Where `p` falls in the supersampled picture, in samples from the top
    /// left (x right, y down), and its depth along `back` (larger is nearer).
    pub fn place(&self, p: [f32; 3]) -> [f32; 3] {
        let half = 0.5 * self.samples as f32;
        let x = (dot(p, self.right) - self.centre[0]) * self.scale + half;
        let y = half - (dot(p, self.up) - self.centre[1]) * self.scale;
        [x, y, dot(p, self.back)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Mesh;

    fn cloud(points: Vec<[f32; 3]>) -> Vec<NamedMesh> {
        vec![NamedMesh { name: "model".into(), mesh: Mesh { positions: points, ..Mesh::default() } }]
    }

    #[test]
    fn axes_are_orthonormal_and_right_handed() {
        for view in View::ALL {
            let [r, u, b] = axes(view);
            for (a, c) in [(r, u), (u, b), (b, r)] {
                assert!(dot(a, c).abs() < 1e-6, "{view:?}");
            }
            for v in [r, u, b] {
                assert!((dot(v, v) - 1.0).abs() < 1e-6, "{view:?}");
            }
            // right × up = back.
            let cross = [r[1] * u[2] - r[2] * u[1], r[2] * u[0] - r[0] * u[2], r[0] * u[1] - r[1] * u[0]];
            assert!(dot(cross, b) > 0.999, "{view:?}");
        }
        assert_eq!(axes(View::Front), [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    }

    #[test]
    fn a_model_is_centred_and_spans_the_fill() {
        let f = Framing::of(&cloud(vec![[2.0, 3.0, 0.0], [6.0, 5.0, 0.0]]), View::Front, 100, 4);
        assert_eq!(f.centre, [4.0, 4.0]);
        // 4 units wide (the longer side) over 80 % of 400 samples.
        assert_eq!(f.scale, 80.0);
        assert_eq!(f.place([2.0, 4.0, 0.0]), [40.0, 200.0, 0.0]);
        assert_eq!(f.place([6.0, 5.0, 0.0]), [360.0, 120.0, 0.0]);
    }

    #[test]
    fn a_far_backdrop_is_framed_out_and_a_normal_spread_is_not() {
        // 400 points in a 10-unit square and 4 backdrop corners 500 units out.
        let mut pts: Vec<[f32; 3]> = (0..400).map(|i| [(i % 20) as f32 * 0.5, (i / 20) as f32 * 0.5, 0.0]).collect();
        pts.extend([[-500.0, -500.0, -10.0], [500.0, -500.0, -10.0], [-500.0, 500.0, -10.0], [500.0, 500.0, -10.0]]);
        let f = Framing::of(&cloud(pts.clone()), View::Front, 64, 4);
        assert!(f.centre.iter().all(|c| (c - 4.75).abs() < 0.5), "{:?}", f.centre);
        assert!(f.scale > 15.0, "the core is framed: {}", f.scale);
        // Without the backdrop the same points frame their whole extent (9.5 units).
        let f = Framing::of(&cloud(pts[..400].to_vec()), View::Front, 64, 4);
        assert_eq!(f.centre, [4.75, 4.75]);
        assert_eq!(f.scale, FILL * 256.0 / 9.5);
    }
}
