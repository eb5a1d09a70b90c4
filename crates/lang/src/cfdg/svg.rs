//! SVG of a rendered CFDG picture with the structure of cfdg's `-V` output
//! (`SVGCanvas.cpp`, Context Free 3.4): the canvas size, a `TRIANGLE`
//! polygon in `<defs>`, then one element per shape in drawing order — a
//! `<circle r="0.5">`, a unit `<rect>` or a `<use>` of the triangle — with
//! its fill colour (8 bits, `fill-opacity` when not opaque) and its
//! transform as a `matrix(…)` in pixels, y down.
//!
//! Written here rather than in the engine's export registry: the 2D picture
//! is what the front end renders, and the format registry is being rebuilt
//! (docs/cfdg.md says what registration the `svg` format needs).

use super::eval::{state::Affine, Picture};
use std::fmt::Write;

/// Quantises a channel to 8 bits as AGG's `rgba8` does (round to nearest).
pub fn to_u8(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// The map from design space to SVG pixels of `p` (cfdg's `m_currTrans`
/// followed by the canvas's y flip and centring offset).
pub fn svg_transform(p: &Picture) -> Affine {
    let mut off = Affine::translation((f64::from(p.canvas_width) - f64::from(p.width)) / 2.0, (f64::from(p.canvas_height) - f64::from(p.height)) / 2.0);
    off.premultiply(&Affine { sx: 1.0, shy: 0.0, shx: 0.0, sy: -1.0, tx: 0.0, ty: f64::from(p.canvas_height) });
    let mut t = p.to_pixels;
    t.multiply(&off);
    t
}

/// Formats like C++'s `setprecision(8)` in default notation (`%.8g`).
fn g8(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
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

/// Writes `p` as SVG in cfdg `-V`'s layout.
pub fn write(p: &Picture) -> String {
    let mut o = String::with_capacity(200 + 180 * p.shapes.len());
    let _ = write!(
        o,
        "<?xml version=\"1.0\" standalone=\"no\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \n\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n<svg width=\"{}px\" height=\"{}px\" version=\"1.1\"\n     xmlns=\"http://www.w3.org/2000/svg\"  xmlns:xlink=\"http://www.w3.org/1999/xlink\">\n  <defs>\n    <polygon id=\"TRIANGLE\" points=\"0,0.57735 -0.5,-0.288675 0.5,-0.288675\"/>\n  </defs>",
        p.canvas_width, p.canvas_height
    );
    let base = svg_transform(p);
    for s in &p.shapes {
        let mut t = s.transform;
        t.multiply(&base);
        let (open, pad) = match s.kind {
            0 => ("<circle r=\"0.5\"", 8),
            1 => ("<rect x=\"-0.5\" y=\"-0.5\" width=\"1\" height=\"1\" ", 6),
            _ => ("<use xlink:href=\"#TRIANGLE\"", 5),
        };
        let ind = " ".repeat(2 + pad);
        let [r, g, b, a] = s.rgba.map(to_u8);
        let _ = write!(o, "\n  {open}\n{ind}stroke=\"none\" fill=\"#{r:02x}{g:02x}{b:02x}\"");
        if a < 255 {
            let _ = write!(o, " fill-opacity=\"{}\"", g8(f64::from(a) / 255.0));
        }
        let _ = write!(
            o,
            " fill-rule=\"nonzero\"\n{ind}transform=\"matrix({:>10} {:>10} {:>10} {:>10} {:>10} {:>10})\"/>",
            g8(t.sx),
            g8(t.shy),
            g8(t.shx),
            g8(t.sy),
            g8(t.tx),
            g8(t.ty)
        );
    }
    o.push_str("\n</svg>\n");
    o
}
