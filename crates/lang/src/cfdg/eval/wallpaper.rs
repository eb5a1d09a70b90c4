//! The 17 wallpaper groups of `CF::Symmetry` that need a 2D tiling: `pm`,
//! `pg`, `cm`, `pmm`, `pmg`, `pgg`, `cmm`, `p4`, `p4m`, `p4g`, `p3`,
//! `p3m1`, `p31m`, `p6`, `p6m` (with `p1`, the tiling itself, and `p2`,
//! read in `symmetry.rs`, the 17), ported from Context Free 3.4's
//! `processSymmSpec` (John Horigan, `ast.cpp`, 2018): the same transforms,
//! built with AGG's operations in the same order (so rounding is the same)
//! and added with `addUnique` in the same order, and the same checks of the
//! tile's shape (rectangular, square, square at 45°, rhombic, hexagonal)
//! and of the arguments, as errors naming `CF::Symmetry`.

use super::state::Affine;
use super::symmetry::{bad, flip_x, flip_y, translate, Builder};
use crate::model::EvalError;
use crate::Span;
use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4, PI, SQRT_2};

/// A wallpaper group (`AST::FlagTypes` `CF_PM` … `CF_P6M`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wall {
    /// `CF::pm`: a mirror.
    Pm,
    /// `CF::pg`: a glide.
    Pg,
    /// `CF::cm`: a mirror on a diamond tiling.
    Cm,
    /// `CF::pmm`: two mirrors.
    Pmm,
    /// `CF::pmg`: a mirror and a glide.
    Pmg,
    /// `CF::pgg`: two glides.
    Pgg,
    /// `CF::cmm`: two mirrors on a diamond tiling.
    Cmm,
    /// `CF::p4`: quarter turns.
    P4,
    /// `CF::p4m`: quarter turns and mirrors.
    P4m,
    /// `CF::p4g`: quarter turns and glides.
    P4g,
    /// `CF::p3`: third turns.
    P3,
    /// `CF::p3m1`: third turns and mirrors.
    P3m1,
    /// `CF::p31m`: third turns and mirrors at 30°.
    P31m,
    /// `CF::p6`: sixth turns.
    P6,
    /// `CF::p6m`: sixth turns and mirrors.
    P6m,
}

impl Wall {
    /// The group a `CF::` flag names (`builder.cpp` `FlagNames`).
    pub fn named(name: &str) -> Option<Wall> {
        Some(match name {
            "CF::pm" => Wall::Pm,
            "CF::pg" => Wall::Pg,
            "CF::cm" => Wall::Cm,
            "CF::pmm" => Wall::Pmm,
            "CF::pmg" => Wall::Pmg,
            "CF::pgg" => Wall::Pgg,
            "CF::cmm" => Wall::Cmm,
            "CF::p4" => Wall::P4,
            "CF::p4m" => Wall::P4m,
            "CF::p4g" => Wall::P4g,
            "CF::p3" => Wall::P3,
            "CF::p3m1" => Wall::P3m1,
            "CF::p31m" => Wall::P31m,
            "CF::p6" => Wall::P6,
            "CF::p6m" => Wall::P6m,
            _ => return None,
        })
    }

    fn name(self) -> &'static str {
        match self {
            Wall::Pm => "pm",
            Wall::Pg => "pg",
            Wall::Cm => "cm",
            Wall::Pmm => "pmm",
            Wall::Pmg => "pmg",
            Wall::Pgg => "pgg",
            Wall::Cmm => "cmm",
            Wall::P4 | Wall::P4m => "p4 & p4m",
            Wall::P4g => "p4g",
            Wall::P3 => "p3",
            Wall::P3m1 | Wall::P31m => "p3m1 & p31m",
            Wall::P6 | Wall::P6m => "p6 & p6m",
        }
    }
}

/// The tile's shape as `processSymmSpec` classifies it.
struct Shape {
    rhombic: bool,
    rectangular: bool,
    square: bool,
    hexagonal: bool,
    square45: bool,
    size45: f64,
}

fn shape(tile: &Affine, tiled: bool) -> Shape {
    let rhombic = tiled && ((tile.shy.abs() <= 0.0000001 && (tile.shx / tile.sx - 0.5).abs() < 0.0000001) || (tile.shx.abs() <= 0.0000001 && (tile.shy / tile.sy - 0.5).abs() < 0.0000001));
    let rectangular = tiled && tile.shx == 0.0 && tile.shy == 0.0;
    let square = rectangular && tile.sx == tile.sy;
    let (mut hexagonal, mut square45, mut size45) = (false, false, tile.sx);
    if rhombic {
        // agg::trans_affine::transform, translation included.
        let (x1, y1) = tile.apply(1.0, 0.0);
        let dist10 = (x1 * x1 + y1 * y1).sqrt();
        let (x2, y2) = tile.apply(0.0, 1.0);
        let dist01 = (x2 * x2 + y2 * y2).sqrt();
        hexagonal = (dist10 / dist01 - 1.0).abs() < 0.0000001;
        square45 = (dist01 / dist10 - SQRT_2).abs() < 0.0000001 || (dist10 / dist01 - SQRT_2).abs() < 0.0000001;
        size45 = dist01.min(dist10);
    }
    Shape { rhombic, rectangular, square, hexagonal, square45, size45 }
}

/// `agg::trans_affine::rotate`.
fn rotate(t: &mut Affine, a: f64) {
    t.multiply(&Affine::rotation(a));
}

/// The nearer of two centres to the origin (`fabs(a) < fabs(b) ? a : b`).
fn nearer(a: f64, b: f64) -> f64 {
    if a.abs() < b.abs() {
        a
    } else {
        b
    }
}

impl Builder<'_> {
    /// `processSymmSpec` for a wallpaper group, `data` its numeric arguments.
    pub(super) fn wallpaper(&mut self, w: Wall, at: Span, data: &[f64], tile: &Affine, tiled: bool) -> Result<(), EvalError> {
        if !tiled {
            return Err(bad(at, "Wallpaper symmetry only works in tiled designs"));
        }
        let s = shape(tile, tiled);
        let ref45 = Affine::reflection(FRAC_PI_4);
        let ref135 = Affine::reflection(-FRAC_PI_4);
        let name = w.name();
        let needs = |ok: bool, what: &str| if ok { Ok(()) } else { Err(bad(at, format!("{name} symmetry requires {what} tiling"))) };
        // No arguments or a centre (x, y).
        let centre = |what: &str| match data {
            [] => Ok((0.0, 0.0)),
            [x, y] => Ok((*x, *y)),
            _ => Err(bad(at, format!("{name} symmetry takes no arguments or {what}"))),
        };
        // An axis: 0, 1 on a rectangular (or rhombic, for cm) tiling, 2, 3 on a square at 45°.
        let axis = |v: f64, straight: bool, diagonal: bool, word: &str| -> Result<i64, EvalError> {
            let axis = v as i64;
            if straight && !(0..=1).contains(&axis) {
                return Err(bad(at, format!("{name} symmetry {word} axis argument must be 0 or 1")));
            }
            if !straight && diagonal && !(2..=3).contains(&axis) {
                return Err(bad(at, format!("{name} symmetry {word} axis argument must be 2 or 3")));
            }
            if !(0..=3).contains(&axis) {
                return Err(bad(at, format!("{name} symmetry {word} axis argument must be 0, 1, 2, or 3")));
            }
            Ok(axis)
        };
        let r = FRAC_1_SQRT_2;
        match w {
            Wall::Pm | Wall::Pg | Wall::Cm => {
                let (straight, diagonal) = if w == Wall::Cm { (s.rhombic, s.square) } else { (s.rectangular, s.square45) };
                needs(straight || diagonal, if w == Wall::Cm { "diamond" } else { "rectangular" })?;
                let (a, offset) = match data {
                    [a] => (*a, 0.0),
                    [a, o] => (*a, *o),
                    _ => return Err(bad(at, format!("{name} symmetry takes a {} axis argument and an optional axis position argument", if w == Wall::Pg { "glide" } else { "mirror" }))),
                };
                let mut tr = Affine::default();
                self.add(tr)?;
                let glide = w == Wall::Pg;
                match axis(a, straight, diagonal, if glide { "glide" } else { "mirror" })? {
                    0 => {
                        translate(&mut tr, 0.0, -offset);
                        flip_y(&mut tr);
                        translate(&mut tr, if glide { tile.sx * 0.5 } else { 0.0 }, offset);
                    }
                    1 => {
                        translate(&mut tr, -offset, 0.0);
                        flip_x(&mut tr);
                        translate(&mut tr, offset, if glide { tile.sy * 0.5 } else { 0.0 });
                    }
                    2 if w == Wall::Cm => {
                        translate(&mut tr, offset * r, -offset * r);
                        tr.multiply(&ref45);
                        translate(&mut tr, -offset * r, offset * r);
                    }
                    2 => {
                        translate(&mut tr, -offset * r, offset * r);
                        tr.multiply(&ref45);
                        if glide {
                            translate(&mut tr, (offset + s.size45 * 0.5) * r, (-offset + s.size45 * 0.5) * r);
                        } else {
                            translate(&mut tr, offset * r, -offset * r);
                        }
                    }
                    _ => {
                        translate(&mut tr, -offset * r, -offset * r);
                        tr.multiply(&ref135);
                        if glide {
                            translate(&mut tr, (offset - s.size45 * 0.5) * r, (offset + s.size45 * 0.5) * r);
                        } else {
                            translate(&mut tr, offset * r, offset * r);
                        }
                    }
                }
                self.add(tr)
            }
            Wall::Pmm => {
                needs(s.rectangular || s.square45, "rectangular")?;
                let (cx, cy) = centre("a center of reflection")?;
                self.dihedral(2.0, cx, cy, true, if s.square45 { FRAC_PI_4 } else { 0.0 }, at)
            }
            Wall::Cmm => {
                needs(s.rhombic || s.square, "diamond")?;
                let (cx, cy) = centre("a center of reflection")?;
                self.dihedral(2.0, cx, cy, true, if s.square45 { FRAC_PI_4 } else { 0.0 }, at)
            }
            Wall::Pmg => {
                needs(s.rectangular || s.square45, "rectangular")?;
                let (a, cx, cy) = match data {
                    [a] => (*a, 0.0, 0.0),
                    [a, x, y] => (*a, *x, *y),
                    _ => return Err(bad(at, "pmg symmetry takes a mirror axis argument and an optional center of reflection")),
                };
                self.pmg(axis(a, s.rectangular, s.square45, "mirror")?, cx, cy, tile, s.size45, at)
            }
            Wall::Pgg => {
                needs(s.rectangular || s.square45, "rectangular")?;
                let (cx, cy) = centre("a center of glide axis intersection")?;
                self.pgg(cx, cy, tile, &s, at)
            }
            Wall::P4 | Wall::P4m => {
                needs(s.square || s.square45, "square")?;
                let (x, y) = centre("a center of rotation")?;
                self.dihedral(4.0, x, y, w == Wall::P4m, if s.square { FRAC_PI_4 } else { 0.0 }, at)
            }
            Wall::P4g => {
                needs(s.square || s.square45, "square")?;
                let (cx, cy) = centre("a center of rotation")?;
                let reg = Affine::translation(-cx, -cy);
                let mut glide = reg;
                if s.square45 {
                    translate(&mut glide, -s.size45 * 0.25 * r, -s.size45 * 0.25 * r);
                    glide.multiply(&ref135);
                    translate(&mut glide, -s.size45 * 0.25 * r, s.size45 * 0.75 * r);
                } else {
                    translate(&mut glide, tile.sx * 0.25, 0.0);
                    flip_x(&mut glide);
                    translate(&mut glide, -tile.sx * 0.25, tile.sy * 0.5);
                }
                for i in 0..4 {
                    let (mut tr, mut tr2) = (reg, glide);
                    if i != 0 {
                        rotate(&mut tr, f64::from(i) * FRAC_PI_2);
                        rotate(&mut tr2, f64::from(i) * FRAC_PI_2);
                    }
                    translate(&mut tr, cx, cy);
                    translate(&mut tr2, cx, cy);
                    self.add(tr)?;
                    self.add(tr2)?;
                }
                Ok(())
            }
            Wall::P3 | Wall::P3m1 | Wall::P31m | Wall::P6 | Wall::P6m => {
                needs(s.hexagonal, "hexagonal")?;
                let (x, y) = centre("a center of rotation")?;
                match w {
                    Wall::P3 => self.dihedral(3.0, x, y, false, 0.0, at),
                    Wall::P3m1 | Wall::P31m => {
                        let deg30 = (tile.shx.abs() <= 0.000001) != (w == Wall::P3m1);
                        self.dihedral(3.0, x, y, true, PI / if deg30 { 6.0 } else { 3.0 }, at)
                    }
                    _ => self.dihedral(6.0, x, y, w == Wall::P6m, 0.0, at),
                }
            }
        }
    }

    /// `pmg`: a half turn about a point a quarter tile off the centre, a
    /// mirror and a glide, by the mirror's axis.
    fn pmg(&mut self, axis: i64, centerx: f64, centery: f64, tile: &Affine, size45: f64, at: Span) -> Result<(), EvalError> {
        let r = FRAC_1_SQRT_2;
        let (mut tr, mut tr2) = (Affine::default(), Affine::default());
        match axis {
            0 => {
                let cy = nearer(centery + 0.25 * tile.sy, centery - 0.25 * tile.sy);
                self.dihedral(2.0, centerx, cy, false, 0.0, at)?;
                translate(&mut tr, -centerx, 0.0);
                flip_x(&mut tr);
                translate(&mut tr, centerx, 0.5 * tile.sy);
                self.add(tr)?;
                translate(&mut tr2, 0.0, -centery);
                flip_y(&mut tr2);
                translate(&mut tr2, 0.0, centery);
                self.add(tr2)
            }
            1 => {
                let cx = nearer(centerx + 0.25 * tile.sx, centerx - 0.25 * tile.sx);
                self.dihedral(2.0, cx, centery, false, 0.0, at)?;
                translate(&mut tr, -centerx, 0.0);
                flip_x(&mut tr);
                translate(&mut tr, centerx, 0.0);
                self.add(tr)?;
                translate(&mut tr2, 0.0, -centery);
                flip_y(&mut tr2);
                translate(&mut tr2, 0.5 * tile.sx, centery);
                self.add(tr2)
            }
            _ => {
                let diag = axis == 2;
                let (mut cx, mut cy) = if diag { (centerx - 0.25 * r * size45, centery + 0.25 * r * size45) } else { (centerx + 0.25 * r * size45, centery + 0.25 * r * size45) };
                let (cx2, cy2) = if diag { (centerx + 0.25 * r * size45, centery - 0.25 * r * size45) } else { (centerx - 0.25 * r * size45, centery - 0.25 * r * size45) };
                if cx2 * cx2 + cy2 * cy2 < cx * cx + cy * cy {
                    (cx, cy) = (cx2, cy2);
                }
                self.dihedral(2.0, cx, cy, false, 0.0, at)?;
                let (mirror, glide) = if diag { (Affine::reflection(FRAC_PI_4), Affine::reflection(-FRAC_PI_4)) } else { (Affine::reflection(-FRAC_PI_4), Affine::reflection(FRAC_PI_4)) };
                translate(&mut tr, -centerx, -centery);
                tr.multiply(&mirror);
                translate(&mut tr, centerx, centery);
                self.add(tr)?;
                translate(&mut tr2, -centerx, -centery);
                tr2.multiply(&glide);
                if diag {
                    translate(&mut tr2, centerx - size45 * r * 0.5, centery + size45 * r * 0.5);
                } else {
                    translate(&mut tr2, centerx + size45 * r * 0.5, centery + size45 * r * 0.5);
                }
                self.add(tr2)
            }
        }
    }

    /// `pgg`: a half turn about the nearest glide-axis crossing and two glides.
    fn pgg(&mut self, centerx: f64, centery: f64, tile: &Affine, s: &Shape, at: Span) -> Result<(), EvalError> {
        let r = FRAC_1_SQRT_2;
        if s.square45 {
            let q = 0.25 * SQRT_2 * s.size45;
            let (mut cx, mut cy) = (centerx + q, centery);
            for (cx2, cy2) in [(centerx - q, centery), (centerx, centery + q), (centerx, centery - q)] {
                if cx2 * cx2 + cy2 * cy2 < cx * cx + cy * cy {
                    (cx, cy) = (cx2, cy2);
                }
            }
            self.dihedral(2.0, cx, cy, false, 0.0, at)?;
            let (mut tr, mut tr2) = (Affine::default(), Affine::default());
            translate(&mut tr, -centerx, -centery);
            tr.multiply(&Affine::reflection(FRAC_PI_4));
            translate(&mut tr, centerx + s.size45 * r * 0.5, centery + s.size45 * r * 0.5);
            self.add(tr)?;
            translate(&mut tr2, -centerx, -centery);
            tr2.multiply(&Affine::reflection(-FRAC_PI_4));
            translate(&mut tr2, centerx - s.size45 * r * 0.5, centery + s.size45 * r * 0.5);
            return self.add(tr2);
        }
        let cx = nearer(centerx + 0.25 * tile.sx, centerx - 0.25 * tile.sx);
        let cy = nearer(centery + 0.25 * tile.sy, centery - 0.25 * tile.sy);
        self.dihedral(2.0, cx, cy, false, 0.0, at)?;
        let (mut tr, mut tr2) = (Affine::default(), Affine::default());
        translate(&mut tr, -centerx, 0.0);
        flip_x(&mut tr);
        translate(&mut tr, centerx, 0.5 * tile.sy);
        self.add(tr)?;
        translate(&mut tr2, 0.0, -centery);
        flip_y(&mut tr2);
        translate(&mut tr2, 0.5 * tile.sx, centery);
        self.add(tr2)
    }
}

#[cfg(test)]
mod tests {
    use crate::cfdg::eval::expr::Scope;
    use crate::cfdg::syntax::parse;
    use crate::core::budget::{Budget, Limits};

    fn transforms(tile: &str, group: &str) -> Result<usize, String> {
        let src = format!("startshape A\nCF::Tile = {tile}\nCF::Symmetry = {group}\nshape A {{ SQUARE [] }}\n");
        let g = parse(src.as_bytes()).map_err(|e| e.to_string())?;
        let tiling = super::super::tile::tiling(&g, &Scope::default()).map_err(|e| e.to_string())?;
        super::super::symmetry::symmetry(&g, &Scope::default(), tiling.as_ref(), &mut Budget::new(Limits::default())).map(|v| v.len()).map_err(|e| e.to_string())
    }

    #[test]
    fn every_wallpaper_group_has_its_order() {
        let rect = "[s 2 3]";
        let diamond = "[[skew atan2(1.5, 2) 0 s 3 2]]";
        let hex = "[s 3 skew 15 15 r 15]";
        let cases = [
            (rect, "CF::pm, 1, 0.5", 2),
            (rect, "CF::pg, 0", 2),
            (diamond, "CF::cm, 1", 2),
            (rect, "CF::pmm", 4),
            (rect, "CF::pmg, 0", 4),
            (rect, "CF::pgg, 1.25, 0.75", 4),
            (diamond, "CF::cmm", 4),
            ("[s 3]", "CF::p4", 4),
            ("[s 3]", "CF::p4m, 0.5, 0", 8),
            ("[s 4]", "CF::p4g", 8),
            (hex, "CF::p3", 3),
            (hex, "CF::p3m1", 6),
            (hex, "CF::p31m", 6),
            (hex, "CF::p6", 6),
            (hex, "CF::p6m", 12),
            // A square tile turned 45° (cfdg's `square45`).
            ("[trans 0 0 sqrt(2) 0 sqrt(4.5) sqrt(0.5)]", "CF::pm, 3, 0.2", 2),
            ("[trans 0 0 sqrt(2) 0 sqrt(4.5) sqrt(0.5)]", "CF::p4g, 0.1, 0.2", 8),
        ];
        for (tile, group, n) in cases {
            assert_eq!(transforms(tile, group), Ok(n), "{group} on {tile}");
        }
    }

    #[test]
    fn wallpaper_groups_check_the_tiling_as_cfdg_does() {
        let cases = [
            ("[s 2 0]", "CF::p4", "only works in tiled designs"),
            ("[s 2 3]", "CF::p4", "p4 & p4m symmetry requires square tiling"),
            ("[s 2 3]", "CF::p6m", "requires hexagonal tiling"),
            ("[s 2 3]", "CF::cmm", "cmm symmetry requires diamond tiling"),
            ("[s 2 3]", "CF::pm, 2", "pm symmetry mirror axis argument must be 0 or 1"),
            ("[s 2 3]", "CF::pm", "takes a mirror axis argument"),
            ("[s 2 3]", "CF::pmm, 1", "pmm symmetry takes no arguments or a center of reflection"),
        ];
        for (tile, group, message) in cases {
            let e = transforms(tile, group).expect_err(group);
            assert!(e.contains("CF::Symmetry") && e.contains(message), "{group}: {e}");
        }
        let untiled = parse(b"startshape A\nCF::Symmetry = CF::p4\nshape A { SQUARE [] }\n").expect("parses");
        let e = super::super::symmetry::symmetry(&untiled, &Scope::default(), None, &mut Budget::new(Limits::default())).expect_err("untiled");
        assert!(e.to_string().contains("Wallpaper symmetry only works in tiled designs"), "{e}");
    }
}
