//! A CFDG path made solid for the 3D formats: each command's fill or
//! stroke tessellated into triangles by lyon (Nicolas Silva, *lyon*, the
//! reference Rust tessellator for 2D fills and strokes: `FillTessellator`
//! with the non-zero or even-odd rule, `StrokeTessellator` with cfdg's
//! width, joins, caps and miter limit), then extruded into a thin slab of
//! the same thickness and at the same height as the primitives' tiles
//! ([`super::tiles`]): the triangles on top and below, a wall along every
//! edge of the outline. Seen from above, the model shows what cfdg draws.
//!
//! lyon rather than the AGG port the picture uses: a fill has to become
//! triangles here (AGG only rasterises), and lyon's tessellators handle
//! self-intersecting outlines and both fill rules.

use super::eval::agg::{CLOSE, CURVE3, CURVE4, END_POLY, LINE_TO, MOVE_TO, STOP};
use super::eval::{state::Affine, PathDraw};
use crate::cfdg::syntax::path_flags as pf;
use crate::core::budget::Budget;
use crate::model::scene::{FreeVertex, Scene, FREE_VERTEX_BYTES};
use crate::model::EvalError;
use glam::DVec3;
use lyon_tessellation::math::point;
use lyon_tessellation::path::Path;
use lyon_tessellation::{BuffersBuilder, FillOptions, FillRule, FillTessellator, FillVertex, LineCap, LineJoin, StrokeOptions, StrokeTessellator, StrokeVertex, VertexBuffers};
use std::collections::HashMap;

/// The command's outline in design space (an `iso` stroke's too) or in the path's units.
fn outline(d: &PathDraw, t: &Affine) -> Path {
    let mut b = Path::builder();
    let mut open = false;
    let v = &d.vertices;
    let p = |k: usize| {
        let (x, y) = t.apply(v[k].x, v[k].y);
        point(x as f32, y as f32)
    };
    let mut i = 0;
    while i < v.len() {
        match v[i].cmd {
            MOVE_TO => {
                if open {
                    b.end(false);
                }
                b.begin(p(i));
                open = true;
            }
            LINE_TO if open => {
                b.line_to(p(i));
            }
            CURVE3 if open && i + 1 < v.len() => {
                b.quadratic_bezier_to(p(i), p(i + 1));
                i += 1;
            }
            CURVE4 if open && i + 2 < v.len() => {
                b.cubic_bezier_to(p(i), p(i + 1), p(i + 2));
                i += 2;
            }
            STOP => break,
            c if open && c & END_POLY == END_POLY => {
                b.end(c & CLOSE != 0);
                open = false;
            }
            _ => {}
        }
        i += 1;
    }
    if open {
        b.end(false);
    }
    b.build()
}

/// Adds the slab of command `d` between heights `z` and `z + h` to
/// `scene`, in colour `colour`; `px` is pixels per design unit (the
/// tessellation tolerance is half a pixel of the picture).
pub fn slab(d: &PathDraw, z: f64, h: f64, px: f64, colour: [f32; 4], scene: &mut Scene, budget: &mut Budget) -> Result<(), EvalError> {
    let t = &d.transform;
    let scale = t.determinant().abs().sqrt();
    let fill = d.flags & pf::FILL != 0;
    let iso = d.flags & pf::ISO_WIDTH != 0;
    // Fills and iso strokes in design space; other strokes in the path's units, mapped after.
    let local = !fill && !iso;
    let identity = Affine::default();
    let path = outline(d, if local { &identity } else { t });
    let tolerance = (0.5 / (px * if local { scale } else { 1.0 })).max(1e-6) as f32;
    let mut buf: VertexBuffers<[f32; 2], u32> = VertexBuffers::new();
    let done = if fill {
        let rule = if d.flags & pf::EVEN_ODD != 0 { FillRule::EvenOdd } else { FillRule::NonZero };
        let opts = FillOptions::tolerance(tolerance).with_fill_rule(rule);
        FillTessellator::new().tessellate_path(&path, &opts, &mut BuffersBuilder::new(&mut buf, |v: FillVertex| v.position().to_array())).is_ok()
    } else {
        let join = match d.flags & pf::JOIN_MASK {
            2 => LineJoin::Round,
            3 => LineJoin::Bevel,
            _ => LineJoin::MiterClip,
        };
        let cap = match (d.flags & pf::CAP_MASK) >> pf::CAP_SHIFT {
            1 => LineCap::Square,
            2 => LineCap::Round,
            _ => LineCap::Butt,
        };
        let width = if iso { d.width * scale } else { d.width };
        let opts = StrokeOptions::tolerance(tolerance).with_line_width(width as f32).with_line_join(join).with_line_cap(cap).with_miter_limit(d.miter.max(1.0) as f32);
        StrokeTessellator::new().tessellate_path(&path, &opts, &mut BuffersBuilder::new(&mut buf, |v: StrokeVertex| v.position().to_array())).is_ok()
    };
    if !done {
        // lyon refuses some degenerate outlines (NaN-free by construction): nothing is drawn.
        return Ok(());
    }
    let at = |k: u32| {
        let [x, y] = buf.vertices[k as usize];
        let (x, y) = if local { t.apply(f64::from(x), f64::from(y)) } else { (f64::from(x), f64::from(y)) };
        DVec3::new(x, y, z)
    };
    // lyon may emit one point under several indices: weld them by exact
    // position, so the outline is found by shared edges.
    let mut weld: HashMap<(u32, u32), u32> = HashMap::new();
    let canon: Vec<u32> = (0..buf.vertices.len() as u32).map(|k| *weld.entry((buf.vertices[k as usize][0].to_bits(), buf.vertices[k as usize][1].to_bits())).or_insert(k)).collect();
    // Triangles turned counter-clockwise seen from above; edges counted to find the outline.
    let mut tris = Vec::with_capacity(buf.indices.len() / 3);
    let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
    for c in buf.indices.chunks_exact(3) {
        let c = [canon[c[0] as usize], canon[c[1] as usize], canon[c[2] as usize]];
        if c[0] == c[1] || c[1] == c[2] || c[0] == c[2] {
            continue;
        }
        let (a, b, e) = (at(c[0]), at(c[1]), at(c[2]));
        let ccw = (b - a).cross(e - a).z >= 0.0;
        let tri = if ccw { [c[0], c[1], c[2]] } else { [c[0], c[2], c[1]] };
        for k in 0..3 {
            let (p, q) = (tri[k], tri[(k + 1) % 3]);
            *edges.entry((p.min(q), p.max(q))).or_insert(0) += 1;
        }
        tris.push(tri);
    }
    let walls: Vec<(u32, u32)> = tris.iter().flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]).filter(|&(p, q)| edges.get(&(p.min(q), p.max(q))) == Some(&1)).collect();
    let count = 6 * tris.len() + 6 * walls.len();
    budget.reserve_memory(FREE_VERTEX_BYTES.saturating_mul(count as u64))?;
    let up = DVec3::new(0.0, 0.0, h);
    let mut push = |p: [DVec3; 3]| {
        let nrm = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
        for q in p {
            scene.vertices.push(FreeVertex { position: q, normal: nrm, colour });
        }
    };
    for t in &tris {
        let (a, b, c) = (at(t[0]), at(t[1]), at(t[2]));
        push([a + up, b + up, c + up]);
        push([a, c, b]);
    }
    for &(p, q) in &walls {
        let (a, b) = (at(p), at(q));
        push([a, b, b + up]);
        push([a, b + up, a + up]);
    }
    Ok(())
}
