//! Framing as cfdg frames a picture: each finished primitive's bounding box
//! (of its polygon, `primShape.cpp`, transformed) dilated by the shape
//! border, the scale that fits the bounds into the canvas less a fixed
//! border (`Bounds::computeScale`, `bounds.cpp`), and the heap that always
//! expands the largest unfinished shape first — a port of libstdc++'s
//! `push_heap`/`pop_heap` (GNU ISO C++ Library, `bits/stl_heap.h`), because
//! the order in which cfdg expands shapes decides both which shapes pass
//! the minimum size (the scale shrinks as the bounds grow) and the drawing
//! order of shapes at the same z.

/// An axis-aligned box; invalid until the first point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Least x.
    pub min_x: f64,
    /// Least y.
    pub min_y: f64,
    /// Greatest x.
    pub max_x: f64,
    /// Greatest y.
    pub max_y: f64,
}

impl Default for Bounds {
    fn default() -> Self {
        Bounds { min_x: f64::INFINITY, min_y: f64::INFINITY, max_x: f64::INFINITY, max_y: f64::INFINITY }
    }
}

impl Bounds {
    /// Whether all four are finite.
    pub fn valid(&self) -> bool {
        self.min_x.is_finite() && self.max_x.is_finite() && self.min_y.is_finite() && self.max_y.is_finite()
    }
    /// Grows to hold `b` (`Bounds::merge`).
    pub fn merge(&mut self, b: &Bounds) {
        if self.valid() && b.valid() {
            self.min_x = self.min_x.min(b.min_x);
            self.max_x = self.max_x.max(b.max_x);
            self.min_y = self.min_y.min(b.min_y);
            self.max_y = self.max_y.max(b.max_y);
        } else if b.valid() {
            *self = *b;
        }
    }
    /// Scaled by `d` about its centre (`Bounds::dilate`).
    pub(crate) fn dilate(&self, d: f64) -> Bounds {
        let (cx, cy) = ((self.min_x + self.max_x) * 0.5, (self.min_y + self.max_y) * 0.5);
        Bounds { min_x: d * (self.min_x - cx) + cx, max_x: d * (self.max_x - cx) + cx, min_y: d * (self.min_y - cy) + cy, max_y: d * (self.max_y - cy) + cy }
    }
    /// The box of `points` under `t`.
    pub(crate) fn of_polygon(t: &super::state::Affine, points: &[(f64, f64)]) -> Bounds {
        let mut b = Bounds::default();
        for &(x, y) in points {
            let (px, py) = t.apply(x, y);
            if b.valid() {
                b.min_x = b.min_x.min(px);
                b.max_x = b.max_x.max(px);
                b.min_y = b.min_y.min(py);
                b.max_y = b.max_y.max(py);
            } else {
                b = Bounds { min_x: px, max_x: px, min_y: py, max_y: py };
            }
        }
        b
    }
    /// The scale fitting the box into `width`×`height` less the borders, the
    /// canvas size it implies, and the map from design to pixels
    /// (`Bounds::computeScale` with `modify` and a transform; `exact` off).
    pub(crate) fn compute_scale(&self, width: i64, height: i64, border_x: f64, border_y: f64) -> (f64, i64, i64, super::state::Affine) {
        self.compute_scale_exact(width, height, border_x, border_y, false)
    }

    /// [`Bounds::compute_scale`], with `exact` as cfdg passes it for sized
    /// and tiled designs (the implied size is not rounded to the canvas's parity).
    pub(crate) fn compute_scale_exact(&self, width: i64, height: i64, border_x: f64, border_y: f64, exact: bool) -> (f64, i64, i64, super::state::Affine) {
        let (mut vw, mut vh) = (self.max_x - self.min_x, self.max_y - self.min_y);
        if !self.valid() {
            vw = 1.0;
            vh = 1.0;
        }
        let (tw, th) = (width as f64 - 2.0 * border_x, height as f64 - 2.0 * border_y);
        let (mut nw, mut nh) = (width, height);
        let scale;
        if vw / tw > vh / th {
            scale = tw / vw;
            nh = (scale * vh + 2.0 * border_y + 0.5).floor() as i64;
            if !exact {
                nh += (nh ^ height) & 1;
            }
        } else {
            scale = th / vh;
            nw = (scale * vw + 2.0 * border_x + 0.5).floor() as i64;
            if !exact {
                nw += (nw ^ width) & 1;
            }
        }
        let ox = scale * (self.max_x + self.min_x) / 2.0 - nw as f64 / 2.0;
        let oy = scale * (self.max_y + self.min_y) / 2.0 - nh as f64 / 2.0;
        let mut t = super::state::Affine::scaling(scale, scale);
        t.multiply(&super::state::Affine::translation(-ox, -oy));
        (scale, nw, nh, t)
    }
}

/// The primitives' polygons (`primShape::shapeMap`): CIRCLE's eight
/// pseudo-vertices, SQUARE, TRIANGLE.
pub fn polygon(kind: usize) -> &'static [(f64, f64)] {
    const T: f64 = std::f64::consts::SQRT_2 / 4.0;
    // h = 0.5 / cos(30°)
    const H: f64 = 0.577_350_269_189_625_8;
    static CIRCLE: [(f64, f64); 8] = [(0.5, 0.0), (T, T), (0.0, 0.5), (-T, T), (-0.5, 0.0), (-T, -T), (0.0, -0.5), (T, -T)];
    static SQUARE: [(f64, f64); 4] = [(0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5), (0.5, -0.5)];
    static TRIANGLE: [(f64, f64); 3] = [(0.0, H), (-0.5, -H / 2.0), (0.5, -H / 2.0)];
    match kind {
        0 => &CIRCLE,
        1 => &SQUARE,
        _ => &TRIANGLE,
    }
}

/// The polygon cfdg measures a primitive's bounds by: its outline stroked
/// with cfdg's default width 0.1 and miter joins (the primitives'
/// `CommandInfo` has no fill flag at bounds time, `pathIterator::boundingRect`
/// strokes it, `agg_vcgen_stroke`), which for these regular polygons moves
/// each vertex out along its bisector by `0.05 / sin(half angle)`.
pub(crate) fn bounds_polygon(kind: usize) -> Vec<(f64, f64)> {
    let (r, half_angle) = match kind {
        0 => (0.5, 67.5f64),
        1 => (std::f64::consts::FRAC_1_SQRT_2, 45.0),
        _ => (0.577_350_269_189_625_8, 30.0),
    };
    let k = (r + 0.05 / half_angle.to_radians().sin()) / r;
    polygon(kind).iter().map(|&(x, y)| (x * k, y * k)).collect()
}

/// libstdc++'s `__push_heap`: sifts `value` up from `hole` to no higher than `top`.
fn push_up<T>(v: &mut [T], mut hole: usize, top: usize, value: T, less: &impl Fn(&T, &T) -> bool)
where
    T: Clone,
{
    let mut parent = hole.wrapping_sub(1) / 2;
    while hole > top && less(&v[parent], &value) {
        v[hole] = v[parent].clone();
        hole = parent;
        parent = hole.wrapping_sub(1) / 2;
    }
    v[hole] = value;
}

/// `std::push_heap` after a push: restores the max-heap with the last element added.
pub(crate) fn push_heap<T: Clone>(v: &mut [T], less: &impl Fn(&T, &T) -> bool) {
    if v.is_empty() {
        return;
    }
    let last = v.len() - 1;
    let value = v[last].clone();
    push_up(v, last, 0, value, less);
}

/// `std::pop_heap`: moves the greatest element to the end and restores the
/// heap over the rest (`__pop_heap` and `__adjust_heap`).
pub(crate) fn pop_heap<T: Clone>(v: &mut [T], less: &impl Fn(&T, &T) -> bool) {
    let n = v.len();
    if n < 2 {
        return;
    }
    let len = n - 1;
    let value = v[len].clone();
    v[len] = v[0].clone();
    let mut hole = 0usize;
    let top = 0usize;
    let mut second = hole;
    while len > 2 && second < (len - 1) / 2 {
        second = 2 * (second + 1);
        if less(&v[second], &v[second - 1]) {
            second -= 1;
        }
        // The sift goes down a level per turn: asking now for the
        // grandchildren of the hole's new place hides a level of cache
        // misses of a heap larger than the cache (the bush's waits
        // 131,072 shapes, 2 MiB).
        prefetch(v, 4 * second + 3);
        prefetch(v, 4 * second + 6);
        v[hole] = v[second].clone();
        hole = second;
    }
    if len & 1 == 0 && len >= 2 && second == (len - 2) / 2 {
        second = 2 * (second + 1);
        v[hole] = v[second - 1].clone();
        hole = second - 1;
    }
    push_up(&mut v[..len], hole, top, value, less);
}

/// Asks the cache for `v[i]` when it exists: a hint, which changes no value.
#[inline(always)]
fn prefetch<T>(v: &[T], i: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(e) = v.get(i) {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        // SAFETY: `_mm_prefetch` needs SSE, which every x86_64 target has
        // (it is in the baseline), and is a hint that never reads or
        // faults; the pointer comes from a live reference anyway.
        unsafe { _mm_prefetch::<_MM_HINT_T0>((e as *const T).cast::<i8>()) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (v, i);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heap_pops_in_descending_order() {
        let mut v: Vec<u32> = Vec::new();
        for x in [5, 1, 9, 3, 7, 7, 2, 8, 0, 6] {
            v.push(x);
            push_heap(&mut v, &|a, b| a < b);
        }
        let mut out = Vec::new();
        while !v.is_empty() {
            pop_heap(&mut v, &|a, b| a < b);
            out.push(v.pop().unwrap_or(0));
        }
        assert_eq!(out, vec![9, 8, 7, 7, 6, 5, 3, 2, 1, 0]);
    }
}
