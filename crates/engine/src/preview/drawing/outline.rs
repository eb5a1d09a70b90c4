//! The outlines of a drawing's marks as zeno paths: a unit primitive or a
//! path placed on the canvas, with its style and its box in pixels
//! ([`super::render`] fills them).

use crate::geom::curves::{flatten_cubic, flatten_quad};
use crate::model::drawing::{DrawnPath, MarkKind, PathStyle, Segment};
use zeno::{Cap, Command, Fill, Join, Point, Stroke, Style, Transform};

/// The outline of path `p` placed by `m` into `cmds`, with its style and
/// the map zeno applies after its pen (a stroke not `iso` is drawn with a
/// pen in the path's own units, then mapped, as AGG's
/// `conv_transform<conv_stroke<…>>` in `pathIterator`), and its box on the
/// canvas. Curves are flattened here as AGG flattens them for drawing
/// (approximation scale: pixels per unit), so zeno gets cfdg's polygons.
pub(super) type Outline = (Option<(f64, f64, f64, f64)>, Style<'static>, Option<Transform>);

pub(super) fn path_outline(p: &DrawnPath, m: &[f64; 6], cmds: &mut Vec<Command>) -> Outline {
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
pub(super) fn outline(kind: MarkKind, m: &[f64; 6], path: &mut Vec<Command>, points: &mut Vec<(f64, f64)>) -> Option<(f64, f64, f64, f64)> {
    if !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    let at = |x: f64, y: f64| (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]);
    let pt = |(x, y): (f64, f64)| Point::new(x as f32, y as f32);
    path.clear();
    points.clear();
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
    for &(x, y) in points.iter() {
        (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
    }
    Some((x0, y0, x1, y1))
}
