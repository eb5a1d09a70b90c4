//! A shape's world state as Context Free keeps it (`Modification`,
//! `shape.h`): a 2D affine map in AGG's layout (`agg::trans_affine`, Maxim
//! Shemanarev, Anti-Grain Geometry 2.4, 2006), a 1D z map, the colour and
//! target colour in HSBA, and the shape's random stream. Colour arithmetic
//! is `HSBColor.cpp`/`HSBColor.h` (Context Free 3.4).

use crate::cfdg::rand64::Rand64;

/// An affine map `x' = sx·x + shx·y + tx`, `y' = shy·x + sy·y + ty`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine {
    /// xx.
    pub sx: f64,
    /// yx.
    pub shy: f64,
    /// xy.
    pub shx: f64,
    /// yy.
    pub sy: f64,
    /// x offset.
    pub tx: f64,
    /// y offset.
    pub ty: f64,
}

impl Default for Affine {
    fn default() -> Self {
        Affine { sx: 1.0, shy: 0.0, shx: 0.0, sy: 1.0, tx: 0.0, ty: 0.0 }
    }
}

impl Affine {
    /// `this = this · m`: apply `self` first, then `m` (`multiply`).
    pub fn multiply(&mut self, m: &Affine) {
        let t0 = self.sx * m.sx + self.shy * m.shx;
        let t2 = self.shx * m.sx + self.sy * m.shx;
        let t4 = self.tx * m.sx + self.ty * m.shx + m.tx;
        self.shy = self.sx * m.shy + self.shy * m.sy;
        self.sy = self.shx * m.shy + self.sy * m.sy;
        self.ty = self.tx * m.shy + self.ty * m.sy + m.ty;
        self.sx = t0;
        self.shx = t2;
        self.tx = t4;
    }
    /// `this = m · this`: apply `m` first, then `self` (`premultiply`).
    pub fn premultiply(&mut self, m: &Affine) {
        let mut t = *m;
        t.multiply(self);
        *self = t;
    }
    /// A translation.
    pub fn translation(x: f64, y: f64) -> Affine {
        Affine { tx: x, ty: y, ..Affine::default() }
    }
    /// A scaling.
    pub fn scaling(x: f64, y: f64) -> Affine {
        Affine { sx: x, sy: y, ..Affine::default() }
    }
    /// A rotation by `a` radians.
    pub fn rotation(a: f64) -> Affine {
        let (s, c) = a.sin_cos();
        Affine { sx: c, shy: s, shx: -s, sy: c, tx: 0.0, ty: 0.0 }
    }
    /// A skew by angles `x`, `y` radians.
    pub(crate) fn skewing(x: f64, y: f64) -> Affine {
        Affine { sx: 1.0, shy: y.tan(), shx: x.tan(), sy: 1.0, tx: 0.0, ty: 0.0 }
    }
    /// A reflection across the line through the origin at angle `a` radians.
    pub fn reflection(a: f64) -> Affine {
        let (uy, ux) = a.sin_cos();
        let y2 = 2.0 * ux * uy;
        Affine { sx: 2.0 * ux * ux - 1.0, shy: y2, shx: y2, sy: 2.0 * uy * uy - 1.0, tx: 0.0, ty: 0.0 }
    }
    /// The map taking the unit square to the parallelogram `p` (three
    /// corners: (0,0) → p0, (1,0) → p1, (1,1) → p2, AGG's `rect_to_parl`).
    pub fn parallelogram(p: &[f64; 6]) -> Affine {
        Affine { sx: p[2] - p[0], shy: p[3] - p[1], shx: p[4] - p[2], sy: p[5] - p[3], tx: p[0], ty: p[1] }
    }
    /// The determinant of the linear part.
    pub fn determinant(&self) -> f64 {
        self.sx * self.sy - self.shy * self.shx
    }
    /// Applies the map to a point.
    pub fn apply(&self, x: f64, y: f64) -> (f64, f64) {
        (x * self.sx + y * self.shx + self.tx, x * self.shy + y * self.sy + self.ty)
    }
}

/// A colour in hue (degrees), saturation, brightness and alpha.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Hsba {
    /// Hue in degrees.
    pub h: f64,
    /// Saturation.
    pub s: f64,
    /// Brightness.
    pub b: f64,
    /// Alpha.
    pub a: f64,
}

impl Hsba {
    /// The component by index (0 h, 1 s, 2 b, 3 a), as cfdg's pointer walk.
    pub fn get_mut(&mut self, i: usize) -> &mut f64 {
        match i {
            0 => &mut self.h,
            1 => &mut self.s,
            2 => &mut self.b,
            _ => &mut self.a,
        }
    }

    /// RGBA in [0, 1] (`HSBColor::getRGBA`).
    pub fn rgba(&self) -> [f64; 4] {
        let mut hue = self.h / 60.0;
        let (mut hex, mut rem) = (hue.trunc(), hue.fract());
        for _ in 0..2 {
            hex = hue.trunc();
            rem = hue - hex;
            if hex > -0.1 && hex < 5.1 && rem >= 0.0 {
                break;
            }
            hue %= 6.0;
            if hue < 0.0 {
                hue += 6.0;
            }
        }
        let (b, s) = (self.b, self.s);
        let p = b * (1.0 - s);
        let q = b * (1.0 - s * rem);
        let t = b * (1.0 - s * (1.0 - rem));
        let rgb = match (hex + 0.5) as i64 {
            0 => [b, t, p],
            1 => [q, b, p],
            2 => [p, b, t],
            3 => [p, q, b],
            4 => [t, p, b],
            5 => [b, p, q],
            _ => return [0.0, 0.0, 0.0, 1.0],
        };
        [rgb[0], rgb[1], rgb[2], self.a]
    }
}

/// cfdg's threshold for equal colour values.
const EQ: f64 = 0.00001;

/// `HSBColor::adjust`: moves `base` by `adj` towards 0 or 1, or towards `target`.
pub(crate) fn adjust(base: f64, adj: f64, use_target: bool, target: f64) -> f64 {
    if adj == 0.0 {
        return base;
    }
    if use_target {
        if adj > 0.0 && (base - target).abs() < EQ {
            return base;
        }
        let edge = if base < target { 0.0 } else { 1.0 };
        if adj < 0.0 {
            base + (base - edge) * adj
        } else {
            base + (target - base) * adj
        }
    } else if adj < 0.0 {
        base + base * adj
    } else {
        base + (1.0 - base) * adj
    }
}

/// `HSBColor::adjustHue`: adds degrees, or moves towards `target`.
pub(crate) fn adjust_hue(base: f64, adj: f64, use_target: bool, target: f64) -> f64 {
    if adj == 0.0 {
        return base;
    }
    let h = if use_target {
        let mut t = target;
        if adj < 0.0 {
            if t > base {
                t -= 360.0;
            }
            base + (base - t) * adj
        } else {
            if t < base {
                t += 360.0;
            }
            base + (t - base) * adj
        }
    } else {
        base + adj
    };
    if h < 0.0 {
        (h + 360.0) % 360.0
    } else {
        h % 360.0
    }
}

/// A shape's world state (`Modification`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    /// The 2D map.
    pub transform: Affine,
    /// z scale.
    pub sz: f64,
    /// z offset (drawing order: lower first).
    pub tz: f64,
    /// The colour.
    pub color: Hsba,
    /// The target colour.
    pub target: Hsba,
    /// The random stream.
    pub seed: Rand64,
    /// The time map (`agg::trans_affine_time`: scale, begin, end), moved
    /// by `time` and `timescale` terms ([`super::anim`]).
    pub time: [f64; 3],
}

impl State {
    /// The start state (`CFDGImpl::getInitialShape`): black, opaque targets.
    pub fn initial() -> State {
        let black = Hsba { h: 0.0, s: 0.0, b: 0.0, a: 1.0 };
        State { transform: Affine::default(), sz: 1.0, tz: 0.0, color: black, target: black, seed: Rand64::default(), time: [1.0, 0.0, 0.0] }
    }
    /// Whether every number is finite (`Modification::isFinite`).
    pub fn is_finite(&self) -> bool {
        let t = &self.transform;
        all_finite(&[t.sx, t.shy, t.shx, t.sy, t.tx, t.ty, self.sz, self.tz, self.color.h, self.color.s, self.color.b, self.color.a, self.target.h, self.target.s, self.target.b, self.target.a, self.time[0]])
    }
    /// `|det|`, the area scale (what orders expansion).
    pub fn area(&self) -> f64 {
        self.transform.determinant().abs()
    }
}

/// Whether every value is finite, without a branch per value (`&`, not
/// `&&`: the tests are bit masks the compiler can do side by side).
/// Checking every shape's state with a test and branch per value had been
/// a tenth of a memoised design's expansion (the bush benchmark).
pub(crate) fn all_finite(values: &[f64]) -> bool {
    values.iter().fold(true, |ok, v| ok & v.is_finite())
}
