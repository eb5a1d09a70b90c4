//! SVG (`format=svg`; W3C, *Scalable Vector Graphics (SVG) 1.1*, 2011) of a
//! model's 2D [`Drawing`], laid out as Context Free's `cfdg -V` writes it
//! (John Horigan, `src-common/SVGCanvas.cpp`, Context Free 3.4): the canvas
//! size, the `TRIANGLE` polygon in `<defs>`, then one element per mark in
//! drawing order — `<circle r="0.5">`, a unit `<rect>` or a `<use>` of the
//! triangle — with its fill (8 bits, `fill-opacity` when not opaque) and
//! its transform as `matrix(…)` in pixels, y down, each number printed as
//! C++'s `setprecision(8)` prints it. The same drawing gives the bytes
//! cfdg gives, so a client can diff them.
//!
//! Only a model that carries a drawing (a Context Free design) has one:
//! for the 3D languages the pipeline refuses the format with a typed
//! `InvalidOptions` naming the missing capability (docs/cfdg.md says why
//! no projection is made). No provenance is written: it would be the one
//! difference from cfdg's file.

use crate::core::budget::Budget;
use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::{ExportError, Provenance};
use crate::model::drawing::{Drawing, MarkKind};
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

/// Formats `v` as C++'s `setprecision(8)` in default notation (`%.8g`).
pub(crate) fn g8(v: f64) -> String {
    if v == 0.0 {
        // iostream keeps the sign of a negative zero.
        return if v.is_sign_negative() { "-0".into() } else { "0".into() };
    }
    if !v.is_finite() {
        return if v.is_nan() { "nan".into() } else if v > 0.0 { "inf".into() } else { "-inf".into() };
    }
    let exp = v.abs().log10().floor() as i32;
    if !(-5..8).contains(&exp) {
        let s = format!("{:.7e}", v);
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = if m.contains('.') { m.trim_end_matches('0').trim_end_matches('.') } else { m };
        let e: i32 = e.parse().unwrap_or(0);
        return format!("{m}e{}{:02}", if e < 0 { '-' } else { '+' }, e.abs());
    }
    let decimals = (7 - exp).max(0) as usize;
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
    for (k, mark) in drawing.marks.iter().enumerate() {
        if k % DEADLINE_EVERY == 0 {
            budget.check_deadline()?;
        }
        let (open, pad) = match mark.kind {
            MarkKind::Circle => ("<circle r=\"0.5\"", 8),
            MarkKind::Square => ("<rect x=\"-0.5\" y=\"-0.5\" width=\"1\" height=\"1\" ", 6),
            MarkKind::Triangle => ("<use xlink:href=\"#TRIANGLE\"", 5),
        };
        let ind = " ".repeat(2 + pad);
        let [r, g, b, a] = mark.rgba;
        let _ = write!(o, "\n  {open}\n{ind}stroke=\"none\" fill=\"#{r:02x}{g:02x}{b:02x}\"");
        if a < 255 {
            let _ = write!(o, " fill-opacity=\"{}\"", g8(f64::from(a) / 255.0));
        }
        let [m0, m1, m2, m3, m4, m5] = mark.matrix.map(g8);
        let _ = write!(o, " fill-rule=\"nonzero\"\n{ind}transform=\"matrix({m0:>10} {m1:>10} {m2:>10} {m3:>10} {m4:>10} {m5:>10})\"/>");
    }
    o.push_str("\n</svg>\n");
    budget.release_memory(bytes.saturating_sub(o.len() as u64));
    Ok(o.into_bytes())
}

#[cfg(test)]
mod tests;
