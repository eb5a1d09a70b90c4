//! SVG (`format=svg`; W3C, *Scalable Vector Graphics (SVG) 1.1*, 2011) of a
//! model's 2D [`Drawing`], laid out as Context Free's `cfdg -V` writes it
//! (John Horigan, `src-common/SVGCanvas.cpp`, Context Free 3.4): the canvas
//! size, the `TRIANGLE` polygon in `<defs>`, then one element per mark in
//! drawing order — `<circle r="0.5">`, a unit `<rect>` or a `<use>` of the
//! triangle — with its fill (8 bits, `fill-opacity` when not opaque) and
//! its transform as `matrix(…)` in pixels, y down, each number printed as
//! C++'s `setprecision(8)` prints it (and, as in cfdg's stream, with the
//! default precision 6 until the first transform is written). A path is a
//! `<g>` carrying its paint and transform around a `<path id="pathN">`, or
//! a `<use>` of an identical path written before (`SVGCanvas::path`); an
//! `iso` stroke has no transform: its points are written transformed. The
//! same drawing gives the bytes cfdg gives, so a client can diff them,
//! except for the stroke cap and join names, which cfdg 3.4 writes wrongly
//! (`miter` for both) and which are written here as SVG names them.
//!
//! Only a model that carries a drawing (a Context Free design) has one:
//! for the 3D languages the pipeline refuses the format with a typed
//! `InvalidOptions` naming the missing capability (docs/cfdg.md says why
//! no projection is made). No provenance is written: it would be the one
//! difference from cfdg's file.

use crate::core::budget::Budget;
use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::{ExportError, Provenance};
use crate::model::drawing::{Drawing, DrawnPath, MarkKind, PathStyle, Segment};
use std::fmt::Write as _;

/// `svg`: text; its size depends on the drawing's marks, which
/// [`write_svg`] reserves itself, so only the fixed part is promised.
pub const SVG: FormatInfo = FormatInfo {
    name: "svg",
    extensions: &["svg"],
    mime: "image/svg+xml",
    caps: Capabilities { text: true, ..Capabilities::NONE },
    options: OptionGroup::None,
    size: SizeBound { fixed: HEADER_BYTES, per_vertex: 0, per_triangle: 0, per_instance: 0 },
    writer: Writer::Drawing(write_with),
};

/// An upper bound on the header and footer.
const HEADER_BYTES: u64 = 1024;

/// An upper bound on one mark's element: its opening, the colour and
/// opacity, and six numbers of at most 14 characters padded to 10.
pub const MARK_BYTES: u64 = 320;

/// Marks written between two looks at the deadline.
const DEADLINE_EVERY: usize = 4096;

/// [`write_svg`] (provenance is not written: see the module comment).
fn write_with(drawing: &Drawing, _: Option<&Provenance>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_svg(drawing, budget)
}

/// Bytes reserved per path segment written (three points of two numbers).
const SEGMENT_BYTES: u64 = 96;

/// Formats `v` as C++'s `setprecision(8)` in default notation (`%.8g`).
pub(crate) fn g8(v: f64) -> String {
    gp(v, 8)
}

/// Formats `v` as C++'s `setprecision(p)` in default notation (`%.{p}g`).
pub(crate) fn gp(v: f64, p: i32) -> String {
    if v == 0.0 {
        // iostream keeps the sign of a negative zero.
        return if v.is_sign_negative() { "-0".into() } else { "0".into() };
    }
    if !v.is_finite() {
        return if v.is_nan() { "nan".into() } else if v > 0.0 { "inf".into() } else { "-inf".into() };
    }
    let p = p.max(1);
    // The exponent after rounding to p digits, as printf decides the notation.
    let e = format!("{:.*e}", (p - 1) as usize, v);
    let exp: i32 = e.split_once('e').and_then(|(_, x)| x.parse().ok()).unwrap_or(0);
    if !(-5..p).contains(&exp) {
        let s = e;
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = if m.contains('.') { m.trim_end_matches('0').trim_end_matches('.') } else { m };
        let e: i32 = e.parse().unwrap_or(0);
        return format!("{m}e{}{:02}", if e < 0 { '-' } else { '+' }, e.abs());
    }
    let decimals = (p - 1 - exp).max(0) as usize;
    let s = format!("{:.*}", decimals, v);
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// Writes `drawing` as SVG in cfdg `-V`'s layout, reserving its size first.
pub fn write_svg(drawing: &Drawing, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let bytes = HEADER_BYTES.saturating_add(MARK_BYTES.saturating_mul(drawing.marks.len() as u64));
    budget.reserve_memory(bytes)?;
    let mut o = String::with_capacity(usize::try_from(bytes).unwrap_or(0));
    let _ = write!(
        o,
        "<?xml version=\"1.0\" standalone=\"no\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \n\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n<svg width=\"{}px\" height=\"{}px\" version=\"1.1\"\n     xmlns=\"http://www.w3.org/2000/svg\"  xmlns:xlink=\"http://www.w3.org/1999/xlink\">\n  <defs>\n    <polygon id=\"TRIANGLE\" points=\"0,0.57735 -0.5,-0.288675 0.5,-0.288675\"/>\n  </defs>",
        drawing.width, drawing.height
    );
    // cfdg's stream prints with precision 6 until its first transform sets 8.
    let mut prec = 6;
    let mut written = vec![false; drawing.paths.len()];
    let mut extra = 0u64;
    for (k, mark) in drawing.marks.iter().enumerate() {
        if k % DEADLINE_EVERY == 0 {
            budget.check_deadline()?;
        }
        let (open, pad) = match mark.kind {
            MarkKind::Circle => ("<circle r=\"0.5\"", 8),
            MarkKind::Square => ("<rect x=\"-0.5\" y=\"-0.5\" width=\"1\" height=\"1\" ", 6),
            MarkKind::Triangle => ("<use xlink:href=\"#TRIANGLE\"", 5),
            // cfdg's SVG canvas writes nothing for a whole-canvas fill.
            MarkKind::Fill => continue,
            MarkKind::Path => {
                let Some(path) = drawing.paths.get(mark.path as usize) else { continue };
                let first = !std::mem::replace(&mut written[mark.path as usize], true);
                if first {
                    let more = SEGMENT_BYTES.saturating_mul(path.segments.len() as u64);
                    budget.reserve_memory(more)?;
                    extra = extra.saturating_add(more);
                }
                write_path(&mut o, mark.path, path, first.then_some(()), &mark.matrix, mark.rgba, &mut prec);
                continue;
            }
        };
        let ind = " ".repeat(2 + pad);
        let [r, g, b, a] = mark.rgba;
        let _ = write!(o, "\n  {open}\n{ind}stroke=\"none\" fill=\"#{r:02x}{g:02x}{b:02x}\"");
        if a < 255 {
            let _ = write!(o, " fill-opacity=\"{}\"", gp(f64::from(a) / 255.0, prec));
        }
        prec = 8;
        let [m0, m1, m2, m3, m4, m5] = mark.matrix.map(g8);
        let _ = write!(o, " fill-rule=\"nonzero\"\n{ind}transform=\"matrix({m0:>10} {m1:>10} {m2:>10} {m3:>10} {m4:>10} {m5:>10})\"/>");
    }
    let bytes = bytes.saturating_add(extra);
    o.push_str("\n</svg>\n");
    budget.release_memory(bytes.saturating_sub(o.len() as u64));
    Ok(o.into_bytes())
}

/// One path mark as `SVGCanvas::path` writes it: a `<g>` with the paint
/// and transform (`SVGCanvas::complete`), holding the path's outline the
/// first time (`first`), a `<use>` of it after.
fn write_path(o: &mut String, id: u32, path: &DrawnPath, first: Option<()>, m: &[f64; 6], rgba: [u8; 4], prec: &mut i32) {
    let [r, g, b, a] = rgba;
    let iso = matches!(path.style, PathStyle::Stroke { iso: true, .. });
    let opacity = |o: &mut String, what: &str, prec: i32| {
        if a < 255 {
            let _ = write!(o, " {what}-opacity=\"{}\"", gp(f64::from(a) / 255.0, prec));
        }
    };
    match path.style {
        PathStyle::Fill { even_odd } => {
            let _ = write!(o, "\n  <g stroke=\"none\" fill=\"#{r:02x}{g:02x}{b:02x}\"");
            opacity(o, "fill", *prec);
            let _ = write!(o, " fill-rule=\"{}\"", if even_odd { "evenodd" } else { "nonzero" });
        }
        PathStyle::Stroke { width, join, cap, miter_limit, .. } => {
            let _ = write!(o, "\n  <g fill=\"none\" stroke=\"#{r:02x}{g:02x}{b:02x}\"");
            opacity(o, "stroke", *prec);
            let w = if iso { width * (m[0] * m[3] - m[1] * m[2]).abs().sqrt() } else { width };
            let cap = match cap {
                1 => "square",
                2 => "round",
                _ => "butt",
            };
            let join = match join {
                2 => "round",
                3 => "bevel",
                _ => "miter",
            };
            let _ = write!(o, "\n     stroke-width=\"{}\" stroke-linecap=\"{cap}\" stroke-linejoin=\"{join}\" stroke-miterlimit=\"{}\"", gp(w, *prec), gp(miter_limit, *prec));
        }
    }
    if iso {
        o.push_str(" >");
    } else {
        *prec = 8;
        let [m0, m1, m2, m3, m4, m5] = m.map(g8);
        let _ = write!(o, "\n     transform=\"matrix({m0:>10} {m1:>10} {m2:>10} {m3:>10} {m4:>10} {m5:>10})\">");
    }
    let n = id + 1;
    if first.is_none() {
        let _ = write!(o, "\n    <use xlink:href=\"#path{n}\" />\n  </g>");
        return;
    }
    let _ = write!(o, "\n    <path id=\"path{n}\" d=");
    let mut sep = '"';
    let pt = |(x, y): (f64, f64)| if iso { (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]) } else { (x, y) };
    let num = |[x, y]: [f64; 2], p: i32| {
        let (x, y) = pt((x, y));
        format!("{},{}", gp(x, p), gp(y, p))
    };
    for s in &path.segments {
        match s {
            Segment::MoveTo(a) => {
                let _ = write!(o, "{sep}M {}", num(*a, *prec));
            }
            Segment::LineTo(a) => {
                let _ = write!(o, "{sep}L {}", num(*a, *prec));
            }
            Segment::QuadTo(c, e) => {
                let _ = write!(o, "{sep}Q {} {}", num(*c, *prec), num(*e, *prec));
            }
            Segment::CubicTo(c1, c2, e) => {
                let _ = write!(o, "{sep}C {} {} {}", num(*c1, *prec), num(*c2, *prec), num(*e, *prec));
            }
            Segment::Close => {
                let _ = write!(o, "{sep}Z");
            }
        }
        sep = ' ';
    }
    if sep == '"' {
        o.push('"');
    }
    o.push_str("\"/>\n  </g>");
}

#[cfg(test)]
mod tests;
