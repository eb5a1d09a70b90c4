//! Tiled and frieze designs (`CF::Tile`, 2.x `tile { }`) as Context Free 3.4
//! draws them (John Horigan, `cfdgimpl.cpp`: `CFDGImpl::isTiled`,
//! `isFrieze`, the tile offset of `getInitialShape`; `renderimpl.cpp`:
//! `initBounds`, `processPrimShapeSiblings`, `drawShape`; `tiledCanvas.cpp`:
//! `scale`, `tileTransform`, `checkTile`).
//!
//! A tiled design's bounds are its tile, fixed from the start, so the
//! canvas is the tile fitted to the picture size exactly and the minimum
//! size never moves. When drawn, every finished shape is repeated at each
//! lattice offset whose copy of the shape's box meets the canvas, the
//! copies found ring by ring around the one nearest the centre, in cfdg's
//! order. A frieze (one of the tile's scales 0) repeats along one axis
//! only and keeps cfdg's normal framing across it.

use super::frame::Bounds;
use super::state::{Affine, State};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Grammar, Value};
use crate::core::budget::Budget;
use crate::model::EvalError;

/// Which axis a frieze repeats along (`CFDG::frieze_t`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frieze {
    /// A full 2D tiling.
    None,
    /// Repeats along x (the tile's y scale is 0).
    X,
    /// Repeats along y (the tile's x scale is 0).
    Y,
}

/// The tiling of a design: the lattice map (its translation removed) and
/// its kind, the tile's width and height in design units, and the start
/// shape's offset (the tile's translation, `mTileOffset`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tiling {
    /// The tile map without translation (`mTileMod.m_transform`, tx = ty = 0).
    pub transform: Affine,
    /// Tiled in 2D, or a frieze along one axis.
    pub frieze: Frieze,
    /// Width and height of the tile (`isTiled`/`isFrieze`'s x and y).
    pub size: (f64, f64),
    /// The start shape's offset.
    pub offset: (f64, f64),
}

fn bad(span: crate::Span, message: &str) -> EvalError {
    EvalError::BadParam { name: "CF::Tile".into(), message: format!("{}:{}: {message}", span.line, span.column) }
}

/// The design's tiling, if `CF::Tile` is set to an adjustment whose map is
/// a tiling or a frieze (a tile with both scales 0 is neither and is
/// ignored, as cfdg ignores it), with cfdg's checks: a tile must be aligned
/// with the x or y axis and in the positive quadrant.
pub fn tiling(g: &Grammar, scope: &super::expr::Scope) -> Result<Option<Tiling>, EvalError> {
    let Some(d) = g.defines.iter().rev().find(|d| d.name == "CF::Tile") else { return Ok(None) };
    let Value::Adjust(a) = &d.value else { return Ok(None) };
    let mut s = State::initial();
    let mut rand = Rand64::default();
    super::adjust::apply(&super::terms_of(a), &mut s, scope, &mut rand)?;
    let mut t = s.transform;
    let offset = (t.tx, t.ty);
    t.tx = 0.0;
    t.ty = 0.0;
    if !(t.sx.is_finite() && t.sy.is_finite() && t.shx.is_finite() && t.shy.is_finite() && offset.0.is_finite() && offset.1.is_finite()) {
        return Err(bad(d.span, "the tile is not finite"));
    }
    let frieze = match (t.sx == 0.0, t.sy == 0.0) {
        (false, false) => Frieze::None,
        (true, true) => return Ok(None),
        (false, true) => Frieze::X,
        (true, false) => Frieze::Y,
    };
    let (o, u, v) = (t.apply(0.0, 0.0), t.apply(1.0, 0.0), t.apply(0.0, 1.0));
    let (off_u, off_v) = ((u.1 - o.1).abs() >= 0.0001, (v.0 - o.0).abs() >= 0.0001);
    if frieze == Frieze::None && off_u && off_v {
        return Err(bad(d.span, "Tile must be aligned with the X or Y axis."));
    }
    if frieze != Frieze::None && (off_u || off_v) {
        return Err(bad(d.span, "Frieze must be aligned with the X and Y axis."));
    }
    if u.0 - o.0 < 0.0 || v.1 - o.1 < 0.0 {
        return Err(bad(d.span, if frieze == Frieze::None { "Tile must be in the positive X/Y quadrant." } else { "Frieze must be in the positive X/Y quadrant." }));
    }
    Ok(Some(Tiling { transform: t, frieze, size: (u.0 - o.0, v.1 - o.1), offset }))
}

/// The tiling in pixels for a picture drawn at `scale` (`tiledCanvas::scale`):
/// the lattice map in pixels and its inverse, which takes pixels to lattice
/// units (for a frieze, only the repeating axis is inverted).
pub(crate) struct PixelTiling {
    offset: Affine,
    invert: Affine,
    frieze: Frieze,
}

impl PixelTiling {
    /// `mOffset = mTileTransform · scaling(scale)` and `mInvert`.
    pub fn new(t: &Tiling, scale: f64) -> PixelTiling {
        let mut offset = t.transform;
        offset.multiply(&Affine::scaling(scale, scale));
        let invert = if t.frieze != Frieze::None {
            let inv = |v: f64| if v == 0.0 { 0.0 } else { 1.0 / v };
            Affine::scaling(inv(offset.sx), inv(offset.sy))
        } else {
            // agg::trans_affine::invert.
            let d = 1.0 / offset.determinant();
            let (sx, sy, shy, shx) = (offset.sy * d, offset.sx * d, -offset.shy * d, -offset.shx * d);
            Affine { sx, shy, shx, sy, tx: -offset.tx * sx - offset.ty * shx, ty: -offset.tx * shy - offset.ty * sy }
        };
        PixelTiling { offset, invert, frieze: t.frieze }
    }

    /// The offsets, in pixels (y up), of every copy of a shape whose box in
    /// pixels is `b` that may touch a canvas of `width`×`height`, in cfdg's
    /// order (`tiledCanvas::tileTransform`): first the copy nearest the
    /// centre, then ring after ring until a ring adds none. Each copy
    /// examined is a step of `budget`, so a shape many tiles wide ends at
    /// the step limit, not in a hang.
    pub fn offsets(&self, b: &Bounds, width: u32, height: u32, budget: &mut Budget) -> Result<Vec<(f64, f64)>, EvalError> {
        let (cx, cy) = self.invert.apply((b.min_x + b.max_x) * 0.5, (b.min_y + b.max_y) * 0.5);
        let (mut cx, mut cy) = ((cx + 0.5).floor(), (cy + 0.5).floor());
        let mut out = vec![self.offset.apply(-cx, -cy)];
        let canvas = Bounds { min_x: -5.0, min_y: -5.0, max_x: f64::from(width) + 9.0, max_y: f64::from(height) + 9.0 };
        if self.frieze != Frieze::None {
            // One of the two is zero; both take the other.
            cx += cy;
            cy = cx;
        }
        let mut check = |dx: f64, dy: f64, out: &mut Vec<(f64, f64)>| -> Result<bool, EvalError> {
            budget.charge_step()?;
            let (dx, dy) = self.offset.apply(dx, dy);
            let hit = !(b.min_x + dx > canvas.max_x || b.max_x + dx < canvas.min_x || b.min_y + dy > canvas.max_y || b.max_y + dy < canvas.min_y);
            if hit {
                budget.reserve_memory(16)?;
                out.push((dx, dy));
            }
            Ok(hit)
        };
        let mut ring = 1.0f64;
        loop {
            let mut hit = false;
            if self.frieze != Frieze::None {
                hit |= check(ring - cx, ring - cy, &mut out)?;
                hit |= check(-ring - cx, -ring - cy, &mut out)?;
            } else {
                let mut pos = -ring;
                while pos < ring {
                    hit |= check(pos - cx, -ring - cy, &mut out)?;
                    hit |= check(ring - cx, pos - cy, &mut out)?;
                    hit |= check(-pos - cx, ring - cy, &mut out)?;
                    hit |= check(-ring - cx, -pos - cy, &mut out)?;
                    pos += 1.0;
                }
            }
            if !hit {
                return Ok(out);
            }
            ring += 1.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cfdg::eval::expr::Scope;
    use crate::cfdg::syntax::parse;
    use crate::core::budget::Limits;

    fn tiling_of(src: &str) -> Result<Option<Tiling>, EvalError> {
        tiling(&parse(src.as_bytes()).expect("parses"), &Scope::default())
    }

    #[test]
    fn cfdg_tiles_and_friezes_are_read_as_cfdg_reads_them() {
        let t = tiling_of("startshape A\nCF::Tile = [s 3 4 x 1]\nshape A { SQUARE [] }\n").expect("ok").expect("tiled");
        assert_eq!((t.frieze, t.size, t.offset), (Frieze::None, (3.0, 4.0), (1.0, 0.0)));
        let f = tiling_of("startshape A\ntile {s 2 0}\nrule A { SQUARE {} }\n").expect("ok").expect("frieze");
        assert_eq!(f.frieze, Frieze::X);
        assert!(tiling_of("startshape A\nCF::Tile = [s 0]\nshape A { SQUARE [] }\n").expect("ok").is_none());
        assert!(tiling_of("startshape A\nCF::Tile = [r 30]\nshape A { SQUARE [] }\n").is_err());
        assert!(tiling_of("startshape A\nCF::Tile = [s -2 2]\nshape A { SQUARE [] }\n").is_err());
    }

    #[test]
    fn cfdg_tile_copies_ring_out_from_the_centre() {
        // A 2×2 tile on a 500 px canvas: 250 px to the unit; a unit square
        // at the centre and one at a corner.
        let t = tiling_of("startshape A\nCF::Tile = [s 2]\nshape A { SQUARE [] }\n").expect("ok").expect("tiled");
        let p = PixelTiling::new(&t, 250.0);
        let mut budget = Budget::new(Limits::default());
        let centre = Bounds { min_x: 112.5, min_y: 112.5, max_x: 387.5, max_y: 387.5 };
        let offsets = p.offsets(&centre, 500, 500, &mut budget).expect("offsets");
        assert_eq!(offsets[0], (-500.0, -500.0));
        assert!(offsets.contains(&(0.0, 0.0)));
        let huge = Bounds { min_x: -1e9, min_y: -1e9, max_x: 1e9, max_y: 1e9 };
        let mut small = Budget::new(Limits { max_steps: 10_000, ..Limits::default() });
        assert!(p.offsets(&huge, 500, 500, &mut small).is_err());
    }
}
