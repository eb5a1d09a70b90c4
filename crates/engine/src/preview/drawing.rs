//! The picture of a 2D [`Drawing`] (a Context Free design): its marks
//! filled in order over its background, antialiased, at the request's
//! `size`, for `format=png`. This replaces the 3D preview for a model that
//! carries a drawing, so a CFDG design's PNG is the picture cfdg draws
//! (John Horigan et al., *Context Free*, cfdg 3.4, `aggCanvas.cpp`: AGG's
//! scanline fill of each shape in drawing order, non-zero rule, no stroke)
//! rather than a shaded view of its tiles.
//!
//! Coverage comes from zeno (Chad Brokaw, the path rasteriser of the swash
//! text stack), a well-kept crate whose rasteriser is FreeType's "gray"
//! cell rasteriser, as AGG's `rasterizer_scanline_aa` is: exact area
//! coverage from integer cells (8 bits of subpixel), so a sliver a tenth
//! of a pixel wide leaves the faint trace it leaves in cfdg's picture (a
//! supersampling filler such as tiny-skia's drops it: it was tried first
//! and covered too few of cfdg's pixels on hair-thin designs). Each mark is
//! rasterised into a mask the size of its box clipped to the canvas, and
//! blended here, by hand, because the blend is four integer lines and must
//! be AGG's: source over, premultiplied 8-bit sRGB without gamma. Every
//! step is integer arithmetic or `f32` adds and multiplies with no SIMD,
//! so the same drawing gives the same bits everywhere.
//!
//! Budget: the canvas is reserved before it is allocated; every mark costs
//! a step plus one per [`PIXELS_PER_STEP`] pixels of its box on the canvas,
//! charged before it is filled (charging checks the deadline).

use super::{Image, PreviewError, PreviewOptions};
use crate::core::budget::Budget;
use crate::geom::curves::{flatten_cubic, flatten_quad};
use crate::model::drawing::{Drawing, DrawnPath, MarkKind, PathStyle, Segment};
use zeno::{Cap, Command, Fill, Join, Mask, Point, Stroke, Style, Transform};

/// Bounding-box pixels per budget step (the 3D rasteriser charges 64
/// samples per step; a mask pixel is one cell's work or less).
pub(crate) const PIXELS_PER_STEP: u64 = 256;

/// Bytes per pixel: the premultiplied canvas, its straight-alpha copy, and
/// at most one mask byte.
const BYTES_PER_PIXEL: u64 = 9;

/// Marks with a coordinate farther than this many pixels from the canvas
/// are not drawn: the rasteriser's cells are 24.8 fixed point.
const FAR: f64 = 4_000_000.0;

/// Draws `drawing` at the request's `size` (the front end made its canvas
/// that size, `BuildRequest::canvas`; another canvas is scaled to fit), over
/// the request's `background` when it names one, else the drawing's own
/// (`CF::Background`, white by default).
pub fn render(drawing: &Drawing, options: &PreviewOptions, budget: &mut Budget) -> Result<Image, PreviewError> {
    options.validate().map_err(PreviewError::BadOptions)?;
    let size = options.size;
    // A square drawing fills the square picture; another (a tiled design's
    // canvas, the shape of its tile) keeps its shape, its longer side `size`.
    let fit = if drawing.width == size && drawing.height == size {
        1.0
    } else {
        f64::from(size) / f64::from(drawing.width.max(drawing.height).max(1))
    };
    let (width, height) = if drawing.width == drawing.height {
        (size, size)
    } else {
        let side = |v: u32| ((f64::from(v) * fit).round() as u32).clamp(1, size);
        (side(drawing.width), side(drawing.height))
    };
    let pixels = u64::from(width) * u64::from(height);
    let bytes = pixels.saturating_mul(BYTES_PER_PIXEL);
    budget.reserve_memory(bytes)?;
    let bg = match options.background {
        Some([r, g, b]) => [r, g, b, 255],
        None => drawing.background,
    };
    let mut canvas: Vec<[u8; 4]> = vec![premultiply(bg); pixels as usize];
    let mut path: Vec<Command> = Vec::with_capacity(16);
    let mut mask: Vec<u8> = Vec::new();
    // zeno's rasteriser without scratch memory builds (and zeroes) a
    // 16 KiB cell array on the stack for every mark; kept scratch memory
    // gives the same coverage without it, which halved the preview of
    // the 262,143-square bush (docs/benchmarks.md).
    let mut scratch = zeno::Scratch::new();
    for mark in &drawing.marks {
        if mark.kind == MarkKind::Fill {
            // AGG's `renderer_base::fill`: the colour blended over every pixel.
            budget.charge_steps(1 + pixels / PIXELS_PER_STEP)?;
            let [r, g, b, a] = mark.rgba;
            for px in canvas.iter_mut() {
                blend(px, [r, g, b], mul(255, a));
            }
            continue;
        }
        let m = mark.raster.map(|v| v * fit);
        let (corners, style, transform) = match (mark.kind, drawing.paths.get(mark.path as usize)) {
            (MarkKind::Path, Some(p)) => path_outline(p, &m, &mut path),
            (MarkKind::Path, None) => continue,
            (kind, _) => (outline(kind, &m, &mut path), Style::Fill(Fill::NonZero), None),
        };
        let Some((x0, y0, x1, y1)) = corners else { continue };
        // The box on the canvas, in whole pixels.
        let (bx0, by0) = (x0.floor().max(0.0), y0.floor().max(0.0));
        let (bx1, by1) = (x1.ceil().min(f64::from(width)), y1.ceil().min(f64::from(height)));
        let (w, h) = (bx1 - bx0, by1 - by0);
        budget.charge_steps(1 + (w.max(0.0) * h.max(0.0)) as u64 / PIXELS_PER_STEP)?;
        if w <= 0.0 || h <= 0.0 || [x0, y0, x1, y1].iter().any(|v| v.abs() > FAR) {
            continue;
        }
        let (w, h) = (w as u32, h as u32);
        mask.clear();
        mask.resize(w as usize * h as usize, 0);
        let mut job = Mask::with_scratch(&path, &mut scratch);
        job.size(w, h).style(style);
        match transform {
            // The box offset goes into the map, applied after the pen.
            Some(t) => job.transform(Some(Transform::new(t.xx, t.xy, t.yx, t.yy, t.x - bx0 as f32, t.y - by0 as f32))),
            None => job.offset(zeno::Vector::new(-bx0 as f32, -by0 as f32)),
        };
        job.render_into(&mut mask, None);
        let [r, g, b, a] = mark.rgba;
        let (left, top) = (bx0 as usize, by0 as usize);
        for (row, covers) in mask.chunks_exact(w as usize).enumerate() {
            let start = (top + row) * width as usize + left;
            for (px, &cover) in canvas[start..start + w as usize].iter_mut().zip(covers) {
                if cover != 0 {
                    blend(px, [r, g, b], mul(cover, a));
                }
            }
        }
    }
    drop(mask);
    let rgba: Vec<u8> = canvas.iter().flat_map(|&p| demultiply(p)).collect();
    drop(canvas);
    budget.release_memory(bytes);
    Ok(Image { size: width, height, rgba })
}

/// `a·b/255`, rounded as AGG's `int8u` multiply (`agg::rgba8::multiply`).
fn mul(a: u8, b: u8) -> u8 {
    let t = u32::from(a) * u32::from(b) + 128;
    (((t >> 8) + t) >> 8) as u8
}

/// A straight-alpha colour premultiplied.
fn premultiply([r, g, b, a]: [u8; 4]) -> [u8; 4] {
    [mul(r, a), mul(g, a), mul(b, a), a]
}

/// A premultiplied colour back to straight alpha (PNG's).
fn demultiply([r, g, b, a]: [u8; 4]) -> [u8; 4] {
    if a == 0 {
        return [0; 4];
    }
    let d = |c: u8| ((u32::from(c) * 255 + u32::from(a) / 2) / u32::from(a)).min(255) as u8;
    [d(r), d(g), d(b), a]
}

/// Source over a premultiplied pixel: colour `rgb` at coverage-scaled alpha `alpha`.
fn blend(px: &mut [u8; 4], rgb: [u8; 3], alpha: u8) {
    let keep = 255 - alpha;
    for k in 0..3 {
        px[k] = mul(rgb[k], alpha).saturating_add(mul(px[k], keep));
    }
    px[3] = alpha.saturating_add(mul(px[3], keep));
}

/// The outline of path `p` placed by `m` into `cmds`, with its style and
/// the map zeno applies after its pen (a stroke not `iso` is drawn with a
/// pen in the path's own units, then mapped, as AGG's
/// `conv_transform<conv_stroke<…>>` in `pathIterator`), and its box on the
/// canvas. Curves are flattened here as AGG flattens them for drawing
/// (approximation scale: pixels per unit), so zeno gets cfdg's polygons.
type Outline = (Option<(f64, f64, f64, f64)>, Style<'static>, Option<Transform>);

fn path_outline(p: &DrawnPath, m: &[f64; 6], cmds: &mut Vec<Command>) -> Outline {
    cmds.clear();
    let none = (None, Style::Fill(Fill::NonZero), None);
    if !m.iter().all(|v| v.is_finite()) {
        return none;
    }
    let at = |(x, y): (f64, f64)| (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]);
    let det = (m[0] * m[3] - m[1] * m[2]).abs();
    let scale = det.sqrt();
    let (local, half, style) = match p.style {
        PathStyle::Fill { even_odd } => (false, 0.0, Style::Fill(if even_odd { Fill::EvenOdd } else { Fill::NonZero })),
        PathStyle::Stroke { width, iso, join, cap, miter_limit } => {
            let w = if iso { width * scale } else { width };
            let mut s = Stroke::new(w as f32);
            s.join(match join {
                2 => Join::Round,
                3 => Join::Bevel,
                _ => Join::Miter,
            })
            .cap(match cap {
                1 => Cap::Square,
                2 => Cap::Round,
                _ => Cap::Butt,
            })
            .miter_limit(miter_limit as f32);
            (!iso, w / 2.0 * miter_limit.max(1.0) * if iso { 1.0 } else { m[0].hypot(m[1]).max(m[2].hypot(m[3])) }, Style::Stroke(s))
        }
    };
    // Points in the frame the pen works in: the path's units, or pixels.
    let frame = |q: (f64, f64)| if local { q } else { at(q) };
    let approx = if local { scale.max(1e-9) } else { 1.0 };
    let mut pts: Vec<(f64, f64)> = Vec::new();
    let (mut x0, mut y0, mut x1, mut y1) = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut last = (0.0, 0.0);
    let pt = |(x, y): (f64, f64)| Point::new(x as f32, y as f32);
    for s in &p.segments {
        pts.clear();
        match *s {
            Segment::MoveTo([x, y]) => {
                last = frame((x, y));
                cmds.push(Command::MoveTo(pt(last)));
                pts.push(last);
            }
            Segment::LineTo([x, y]) => pts.push(frame((x, y))),
            Segment::QuadTo([cx, cy], [x, y]) => flatten_quad(last, frame((cx, cy)), frame((x, y)), approx, &mut pts),
            Segment::CubicTo([ax, ay], [bx, by], [x, y]) => flatten_cubic(last, frame((ax, ay)), frame((bx, by)), frame((x, y)), approx, &mut pts),
            Segment::Close => cmds.push(Command::Close),
        }
        if !matches!(s, Segment::MoveTo(_) | Segment::Close) {
            cmds.extend(pts.iter().map(|&q| Command::LineTo(pt(q))));
        }
        if let Some(&q) = pts.last() {
            last = q;
        }
        for &q in &pts {
            let (x, y) = if local { at(q) } else { q };
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
        }
    }
    if cmds.is_empty() || !(x0 <= x1 && y0 <= y1) {
        return none;
    }
    let transform = local.then(|| Transform::new(m[0] as f32, m[1] as f32, m[2] as f32, m[3] as f32, m[4] as f32, m[5] as f32));
    (Some((x0 - half, y0 - half, x1 + half, y1 + half)), style, transform)
}

/// Writes the outline of a unit mark placed by `m` (canvas pixels, y down)
/// into `path` and returns its box, or `None` when the map is not finite.
/// A circle is flattened as AGG flattens it (`fast_ellipse`), with
/// `libm`'s sine and cosine so every machine gets the same vertices.
fn outline(kind: MarkKind, m: &[f64; 6], path: &mut Vec<Command>) -> Option<(f64, f64, f64, f64)> {
    if !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    let at = |x: f64, y: f64| (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]);
    let pt = |(x, y): (f64, f64)| Point::new(x as f32, y as f32);
    path.clear();
    let mut points: Vec<(f64, f64)> = Vec::with_capacity(16);
    match kind {
        MarkKind::Square => {
            points.extend([at(-0.5, -0.5), at(0.5, -0.5), at(0.5, 0.5), at(-0.5, 0.5)]);
            path.push(Command::MoveTo(pt(points[0])));
            path.extend(points[1..].iter().map(|&p| Command::LineTo(pt(p))));
        }
        // Drawn by `path_outline`, and over the whole canvas.
        MarkKind::Path | MarkKind::Fill => return None,
        MarkKind::Triangle => {
            points.extend(MarkKind::TRIANGLE.iter().map(|&(x, y)| at(x, y)));
            path.push(Command::MoveTo(pt(points[0])));
            path.extend(points[1..].iter().map(|&p| Command::LineTo(pt(p))));
        }
        MarkKind::Circle => {
            // AGG's `fast_ellipse` as cfdg sets it up (`aggCanvas::primitive`):
            // int(mean radius in pixels) + 8 segments, rounded up to a multiple
            // of 8, the vertices half a step off the axes. An inscribed
            // polygon, not the true circle: where a design overlaps hundreds
            // of small circles (`underground`), their edges add up. Above a
            // radius of 4096 px the count stops growing (0.03 px off at 10⁵ px).
            let radius = 0.25 * (m[0].hypot(m[1]) + m[2].hypot(m[3]));
            let steps = (radius.min(4096.0) as u32).saturating_add(8).next_multiple_of(8);
            let step = 2.0 * std::f64::consts::PI / f64::from(steps);
            for k in 0..steps {
                let angle = (f64::from(k) + 0.5) * step;
                points.push(at(0.5 * libm::cos(angle), 0.5 * libm::sin(angle)));
            }
            path.push(Command::MoveTo(pt(points[0])));
            path.extend(points[1..].iter().map(|&p| Command::LineTo(pt(p))));
        }
    }
    path.push(Command::Close);
    let (mut x0, mut y0, mut x1, mut y1) = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for (x, y) in points {
        (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
    }
    Some((x0, y0, x1, y1))
}
