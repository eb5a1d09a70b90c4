//! The picture of a 2D [`Drawing`] (a Context Free design): its marks
//! filled in order over its background, antialiased, at the request's
//! `size`, for `format=png`. This replaces the 3D preview for a model that
//! carries a drawing, so a CFDG design's PNG is the picture cfdg draws
//! (John Horigan et al., *Context Free*, cfdg 3.4, `aggCanvas.cpp`: AGG's
//! scanline fill of each shape in drawing order, no stroke) rather than a
//! shaded view of its tiles.
//!
//! Filled with tiny-skia (Yevhenii Reizner, a Rust port of a subset of
//! Google's Skia), a well-kept rasteriser, rather than by hand: its
//! analytic-edge, supersampled antialiasing is close to AGG's exact
//! coverage, and both blend 8-bit sRGB without gamma correction, as cfdg
//! does. It is built without its `simd` feature, so every machine takes
//! the same scalar `f32` path and the same drawing gives the same bits.
//!
//! Budget: the canvas is reserved before it is allocated; every mark costs
//! a step plus one per [`PIXELS_PER_STEP`] pixels of its bounding box on
//! the canvas, charged before it is filled (charging checks the deadline).

use super::{Image, PreviewError, PreviewOptions};
use crate::core::budget::Budget;
use crate::model::drawing::{Drawing, MarkKind};
use tiny_skia::{FillRule, Paint, Path, PathBuilder, Pixmap, Rect, Transform};

/// Bounding-box pixels per budget step (the 3D rasteriser charges 64
/// samples per step; a tiny-skia pixel is 16 samples' work or less).
pub const PIXELS_PER_STEP: u64 = 256;

/// Bytes of tiny-skia's canvas per pixel (premultiplied RGBA8) plus the
/// straight-alpha copy the picture is returned in.
const BYTES_PER_PIXEL: u64 = 8;

/// Draws `drawing` at the request's `size` (the front end made its canvas
/// that size, `BuildRequest::canvas`; another canvas is scaled to fit), over the request's `background` when it names one,
/// else the drawing's own (`CF::Background`, white by default).
pub fn render(drawing: &Drawing, options: &PreviewOptions, budget: &mut Budget) -> Result<Image, PreviewError> {
    options.validate().map_err(PreviewError::BadOptions)?;
    let size = options.size;
    let pixels = u64::from(size) * u64::from(size);
    let bytes = pixels.saturating_mul(BYTES_PER_PIXEL);
    budget.reserve_memory(bytes)?;
    let mut pixmap = Pixmap::new(size, size).ok_or_else(|| PreviewError::BadOptions(format!("cannot draw a {size}×{size} picture")))?;
    let [r, g, b, a] = match options.background {
        Some([r, g, b]) => [r, g, b, 255],
        None => drawing.background,
    };
    pixmap.fill(tiny_skia::Color::from_rgba8(r, g, b, a));
    // A canvas made for another size (or not square) is scaled to fit.
    let fit = if drawing.width == size && drawing.height == size {
        1.0
    } else {
        f64::from(size) / f64::from(drawing.width.max(drawing.height).max(1))
    };
    let limit = f64::from(size);
    let mut paint = Paint { anti_alias: true, ..Paint::default() };
    for mark in &drawing.marks {
        let m = mark.raster.map(|v| v * fit);
        if !m.iter().all(|v| v.is_finite()) {
            continue;
        }
        // The box on the canvas, for the charge: a unit shape's half extents.
        let hx = 0.5 * (m[0].abs() + m[2].abs());
        let hy = 0.5 * (m[1].abs() + m[3].abs());
        let w = ((m[4] + hx).min(limit) - (m[4] - hx).max(0.0)).max(0.0);
        let h = ((m[5] + hy).min(limit) - (m[5] - hy).max(0.0)).max(0.0);
        budget.charge_steps(1 + (w * h) as u64 / PIXELS_PER_STEP)?;
        if w == 0.0 || h == 0.0 {
            continue;
        }
        let [r, g, b, a] = mark.rgba;
        paint.set_color_rgba8(r, g, b, a);
        if let Some((path, ts)) = mark_path(mark.kind, &m) {
            pixmap.fill_path(&path, &paint, FillRule::Winding, ts, None);
        }
    }
    let rgba: Vec<u8> = pixmap.pixels().iter().flat_map(|p| {
        let c = p.demultiply();
        [c.red(), c.green(), c.blue(), c.alpha()]
    }).collect();
    drop(pixmap);
    budget.release_memory(bytes);
    Ok(Image { size, rgba })
}

/// The path of a unit mark and the transform that places it. A circle is
/// built at its size on the canvas and the transform shrunk to match,
/// because tiny-skia turns a circle's conics into quadratics at a
/// tolerance in path units: a unit circle scaled up afterwards would show
/// its facets.
fn mark_path(kind: MarkKind, m: &[f64; 6]) -> Option<(Path, Transform)> {
    let ts = |k: f64| Transform::from_row((m[0] / k) as f32, (m[1] / k) as f32, (m[2] / k) as f32, (m[3] / k) as f32, m[4] as f32, m[5] as f32);
    match kind {
        MarkKind::Circle => {
            let k = (m[0].hypot(m[1])).max(m[2].hypot(m[3])).max(1.0);
            Some((PathBuilder::from_circle(0.0, 0.0, (0.5 * k) as f32)?, ts(k)))
        }
        MarkKind::Square => Some((PathBuilder::from_rect(Rect::from_xywh(-0.5, -0.5, 1.0, 1.0)?), ts(1.0))),
        MarkKind::Triangle => {
            let mut pb = PathBuilder::new();
            let [p0, p1, p2] = MarkKind::TRIANGLE;
            pb.move_to(p0.0 as f32, p0.1 as f32);
            pb.line_to(p1.0 as f32, p1.1 as f32);
            pb.line_to(p2.0 as f32, p2.1 as f32);
            pb.close();
            Some((pb.finish()?, ts(1.0)))
        }
    }
}
