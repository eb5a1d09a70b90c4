//! A rendered CFDG [`Picture`] as the model's 2D [`Drawing`]: every shape a
//! mark whose matrix maps the unit primitive to canvas pixels, y down, and
//! whose colour is quantised to 8 bits, exactly as cfdg's SVG canvas
//! (`SVGCanvas.cpp`, Context Free 3.4) and its AGG canvas (`aggCanvas.cpp`)
//! receive them: cfdg's `m_currTrans` (design space to pixels), then the
//! canvas's y flip and the centring of the drawn area on the canvas. The
//! engine's `svg` writer prints it and its preview stage fills it.

use super::eval::{state::Affine, Picture};
use crate::core::budget::Budget;
use crate::model::drawing::{Drawing, Mark, MarkKind, MARK_BYTES};
use crate::model::EvalError;

/// Quantises a channel to 8 bits as AGG's `rgba8` does (round to nearest).
pub fn to_u8(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// The map from design space to canvas pixels of `p` (cfdg's `m_currTrans`
/// followed by the canvas's y flip and centring offset).
pub fn canvas_transform(p: &Picture) -> Affine {
    let mut off = Affine::translation((f64::from(p.canvas_width) - f64::from(p.width)) / 2.0, (f64::from(p.canvas_height) - f64::from(p.height)) / 2.0);
    off.premultiply(&Affine { sx: 1.0, shy: 0.0, shx: 0.0, sy: -1.0, tx: 0.0, ty: f64::from(p.canvas_height) });
    let mut t = p.to_pixels;
    t.multiply(&off);
    t
}

/// How much cfdg's AGG canvas grows each primitive (CIRCLE, SQUARE,
/// TRIANGLE), in pixels across, and the size below which it grows it as if
/// it were that size (`aggCanvas.cpp`: `ADJ_CIRCLE_SIZE`, `ADJ_SQUARE_SIZE`,
/// `ADJ_TRIANGLE_SIZE`, `ADJ_SMALL_SIZE`).
const GROW: [f64; 3] = [0.30, 0.80, 0.90];
const SMALL: f64 = 5.0;

/// The map of a shape with map `t` (design space to pixels, y up, before
/// the canvas offset: what `aggCanvas::primitive` receives) as cfdg's PNG
/// places it: each axis grown by the primitive's adjustment
/// (`adjustShapeSize`), moved by the canvas's whole-pixel centring
/// (`aggCanvas::start`: `(mWidth − width) / 2` in integers), and flipped
/// to y down (the AGG buffer is attached inverted).
fn raster(kind: usize, t: &Affine, p: &Picture) -> [f64; 6] {
    let grow = GROW.get(kind).copied().unwrap_or(0.5);
    let scale = |size: f64| if size < SMALL { (SMALL + grow) / SMALL } else { (size + grow) / size };
    let (gx, gy) = (scale(t.sx.hypot(t.shy)), scale(t.shx.hypot(t.sy)));
    let off_x = f64::from((p.canvas_width.saturating_sub(p.width)) / 2);
    let off_y = f64::from((p.canvas_height.saturating_sub(p.height)) / 2);
    let h = f64::from(p.canvas_height);
    [t.sx * gx, -t.shy * gx, t.shx * gy, -t.sy * gy, t.tx + off_x, h - (t.ty + off_y)]
}

/// The drawing of `p`, charging the memory its marks take.
pub fn of(p: &Picture, budget: &mut Budget) -> Result<Drawing, EvalError> {
    budget.reserve_memory(MARK_BYTES.saturating_mul(p.shapes.len() as u64))?;
    let base = canvas_transform(p);
    let marks = p
        .shapes
        .iter()
        .map(|s| {
            let mut up = s.transform;
            up.multiply(&p.to_pixels);
            let mut t = s.transform;
            t.multiply(&base);
            let kind = match s.kind {
                0 => MarkKind::Circle,
                1 => MarkKind::Square,
                _ => MarkKind::Triangle,
            };
            Mark { kind, matrix: [t.sx, t.shy, t.shx, t.sy, t.tx, t.ty], raster: raster(s.kind, &up, p), rgba: s.rgba.map(to_u8) }
        })
        .collect();
    Ok(Drawing { width: p.canvas_width, height: p.canvas_height, background: p.background.map(to_u8), marks })
}
