//! A rendered CFDG [`Picture`] as the model's 2D [`Drawing`]: every shape a
//! mark whose matrix maps the unit primitive to canvas pixels, y down, and
//! whose colour is quantised to 8 bits, exactly as cfdg's SVG canvas
//! (`SVGCanvas.cpp`, Context Free 3.4) and its AGG canvas (`aggCanvas.cpp`)
//! receive them: cfdg's `m_currTrans` (design space to pixels), then the
//! canvas's y flip and the centring of the drawn area on the canvas. The
//! engine's `svg` writer prints it and its preview stage fills it.

use super::eval::agg::{CLOSE, CURVE3, CURVE4, END_POLY, LINE_TO, MOVE_TO, STOP};
use super::eval::frame::Bounds;
use super::eval::tile::PixelTiling;
use super::eval::{state::Affine, Finished, PathDraw, Picture, SHAPE_BYTES};
use crate::cfdg::syntax::path_flags as pf;
use crate::core::budget::Budget;
use crate::model::drawing::{DrawnPath, Drawing, Mark, MarkKind, PathStyle, Segment, MARK_BYTES, SEGMENT_BYTES};
use crate::model::EvalError;

/// Quantises a channel to 8 bits as AGG's `rgba8` does (round to nearest).
pub(crate) fn to_u8(c: f64) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// The background of `p`'s drawing, 8-bit sRGB with straight alpha (what
/// a picture's "foreground" is measured against, without drawing it).
pub fn background(p: &Picture) -> [u8; 4] {
    p.background.map(to_u8)
}

/// The map from design space to canvas pixels of `p` (cfdg's `m_currTrans`
/// followed by the canvas's y flip and centring offset).
pub(crate) fn canvas_transform(p: &Picture) -> Affine {
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
    // A path is not grown (`aggCanvas::path`).
    let grow = GROW.get(kind).copied().unwrap_or(0.0);
    let scale = |size: f64| if size < SMALL { (SMALL + grow) / SMALL } else { (size + grow) / size };
    // `hypot` only where the side may reach SMALL: below 24.9 the sum of
    // squares (a few ulps off) puts the exact length under 5 for certain,
    // so the growth is the same bits; most marks of a big design are that
    // small, and `hypot` was a tenth of turning them into marks.
    let side = |x: f64, y: f64| if x * x + y * y < 24.9 { 0.0 } else { x.hypot(y) };
    let (gx, gy) = (scale(side(t.sx, t.shy)), scale(side(t.shx, t.sy)));
    let off_x = f64::from((p.canvas_width.saturating_sub(p.width)) / 2);
    let off_y = f64::from((p.canvas_height.saturating_sub(p.height)) / 2);
    let h = f64::from(p.canvas_height);
    [t.sx * gx, -t.shy * gx, t.shx * gy, -t.sy * gy, t.tx + off_x, h - (t.ty + off_y)]
}

/// A command's path sequence as drawing segments (AGG's vertices: curve
/// points come in twos and threes, an `end_poly` with the close flag closes).
fn segments(d: &PathDraw) -> Vec<Segment> {
    let v = &d.vertices;
    let mut out = Vec::with_capacity(v.len());
    let mut i = 0;
    while i < v.len() {
        let p = |k: usize| [v[k].x, v[k].y];
        match v[i].cmd {
            MOVE_TO => out.push(Segment::MoveTo(p(i))),
            LINE_TO => out.push(Segment::LineTo(p(i))),
            CURVE3 if i + 1 < v.len() => {
                out.push(Segment::QuadTo(p(i), p(i + 1)));
                i += 1;
            }
            CURVE4 if i + 2 < v.len() => {
                out.push(Segment::CubicTo(p(i), p(i + 1), p(i + 2)));
                i += 2;
            }
            STOP => break,
            c if c & END_POLY == END_POLY && c & CLOSE != 0 => out.push(Segment::Close),
            _ => {}
        }
        i += 1;
    }
    out
}

fn style(d: &PathDraw) -> PathStyle {
    if d.flags & pf::FILL != 0 {
        PathStyle::Fill { even_odd: d.flags & pf::EVEN_ODD != 0 }
    } else {
        PathStyle::Stroke {
            width: d.width,
            iso: d.flags & pf::ISO_WIDTH != 0,
            join: (d.flags & pf::JOIN_MASK) as u8,
            cap: ((d.flags & pf::CAP_MASK) >> pf::CAP_SHIFT) as u8,
            miter_limit: d.miter,
        }
    }
}

/// The drawing of `p`, charging the memory its marks and paths take: one
/// mark per primitive, one per path command (as cfdg's canvases get one
/// `path` call per command).
pub fn of(p: &Picture, budget: &mut Budget) -> Result<Drawing, EvalError> {
    let commands = commands_of(&p.shapes, p);
    budget.reserve_memory(MARK_BYTES.saturating_mul((p.shapes.len() + commands) as u64))?;
    let mut m = Marker::new(p, p.shapes.len() + commands);
    if commands > 0 || m.tiles.is_some() || !m.add_in_parallel(&p.shapes) {
        for s in &p.shapes {
            m.add(s, budget)?;
        }
    }
    Ok(m.finish())
}

/// Pictures with fewer shapes are marked on the calling thread.
const PARALLEL_FROM: usize = 1 << 16;

/// Shapes drawn per step of [`into_drawing`]: the memory it holds beyond
/// the picture's is one step's marks.
const STEP: usize = 1 << 16;

/// The drawing of `p`, as [`of`] draws it, consuming the picture. When
/// the picture and its whole drawing would not fit the memory limit
/// together, it takes the picture's shapes as it goes: each step of
/// [`STEP`] shapes is drawn, then the memory those shapes held is handed
/// back (to the allocator and to the budget). So a design of a million
/// squares (Context Free's `tests/perftest.cfdg`) is drawn under the
/// default memory limit, where holding both took 272 MB. The marks are the
/// same, in the same order, either way.
pub fn into_drawing(mut p: Picture, budget: &mut Budget) -> Result<Drawing, EvalError> {
    let commands = commands_of(&p.shapes, &p);
    // When the whole drawing fits beside the picture, it is drawn in one
    // go, as `of` draws it: handing shapes back costs a reversal and a
    // shrink per step, a tenth of the bush's drawing time.
    let all = MARK_BYTES.saturating_mul((p.shapes.len() + commands) as u64);
    if budget.check_memory(all).is_ok() {
        let d = of(&p, budget)?;
        budget.release_memory(SHAPE_BYTES.saturating_mul(p.shapes.len() as u64));
        return Ok(d);
    }
    let mut shapes = std::mem::take(&mut p.shapes);
    // Drawn from the back: popping is what lets the vector shrink.
    shapes.reverse();
    let mut m = Marker::new(&p, shapes.len() + commands);
    while !shapes.is_empty() {
        let n = STEP.min(shapes.len());
        let tail = &shapes[shapes.len() - n..];
        budget.reserve_memory(MARK_BYTES.saturating_mul((n + commands_of(tail, &p)) as u64))?;
        for _ in 0..n {
            if let Some(s) = shapes.pop() {
                m.add(&s, budget)?;
            }
        }
        shapes.shrink_to_fit();
        budget.release_memory(SHAPE_BYTES.saturating_mul(n as u64));
    }
    Ok(m.finish())
}

/// The mark kind of a finished shape that is not a path.
fn primitive_kind(kind: usize) -> MarkKind {
    match kind {
        0 => MarkKind::Circle,
        1 => MarkKind::Square,
        2 => MarkKind::Triangle,
        _ => MarkKind::Fill,
    }
}

/// Path commands among `shapes`: each is a mark of its own. None without
/// a path shape, and then no pass over the shapes (tens of megabytes for
/// a big design, read three times before).
fn commands_of(shapes: &[Finished], p: &Picture) -> usize {
    if !p.has_paths {
        return 0;
    }
    shapes.iter().filter(|s| s.kind == 3).map(|s| p.paths.get(s.path).map_or(0, Vec::len)).sum()
}

/// Builds a drawing's marks shape by shape, in drawing order.
struct Marker<'p> {
    p: &'p Picture,
    /// Design space to canvas pixels ([`canvas_transform`]).
    base: Affine,
    /// The canvas's own part of `base`: its centring and y flip (SVGCanvas's `mOffset`).
    flip: Affine,
    /// A tiled design's shapes are drawn once per copy touching the canvas,
    /// each copy's pixel map moved by its lattice offset before the canvas
    /// flips it (`tiledCanvas::primitive`, `tiledCanvas::path`).
    tiles: Option<PixelTiling>,
    marks: Vec<Mark>,
    paths: Vec<DrawnPath>,
    /// Identical outlines are kept once (cfdg writes a `<use>` of a cached path).
    seen: std::collections::HashMap<String, u32>,
}

impl<'p> Marker<'p> {
    fn new(p: &'p Picture, marks: usize) -> Marker<'p> {
        let mut flip = Affine::translation((f64::from(p.canvas_width) - f64::from(p.width)) / 2.0, (f64::from(p.canvas_height) - f64::from(p.height)) / 2.0);
        flip.premultiply(&Affine { sx: 1.0, shy: 0.0, shx: 0.0, sy: -1.0, tx: 0.0, ty: f64::from(p.canvas_height) });
        let tiles = p.tiling.as_ref().map(|(t, scale)| PixelTiling::new(t, *scale));
        let mut list = Vec::with_capacity(marks);
        crate::core::hugepages::advise(&mut list);
        Marker { p, base: canvas_transform(p), flip, tiles, marks: list, paths: Vec::new(), seen: Default::default() }
    }

    fn mark(&self, kind: MarkKind, k: usize, transform: &Affine, rgba: [f64; 4], path: u32, shift: Option<(f64, f64)>) -> Mark {
        let p = self.p;
        let mut up = *transform;
        up.multiply(&p.to_pixels);
        let t = match shift {
            None => {
                let mut t = *transform;
                t.multiply(&self.base);
                t
            }
            Some((dx, dy)) => {
                up.tx += dx;
                up.ty += dy;
                let mut t = up;
                t.multiply(&self.flip);
                t
            }
        };
        Mark { kind, matrix: [t.sx, t.shy, t.shx, t.sy, t.tx, t.ty], raster: raster(k, &up, p), rgba: rgba.map(to_u8), path }
    }

    /// Adds the marks of `shapes` (no path among them, no tiling: one mark
    /// each, a pure function of the shape and the framing) on up to four
    /// threads, each writing its own stretch of the marks in place; false,
    /// having added nothing, for fewer than [`PARALLEL_FROM`] shapes or
    /// marks already made. The marks are the ones [`Marker::add`] makes,
    /// in the same order.
    fn add_in_parallel(&mut self, shapes: &[Finished]) -> bool {
        let n = shapes.len();
        if n < PARALLEL_FROM || !self.marks.is_empty() || self.p.has_paths {
            return false;
        }
        let threads = std::thread::available_parallelism().map_or(1, |t| t.get()).clamp(1, 4);
        let mut room = std::mem::take(&mut self.marks);
        let this = &*self;
        let filled = crate::core::parallel::fill_in_place(&mut room, n, threads, |range, marks| {
            for s in &shapes[range] {
                marks.push(this.mark(primitive_kind(s.kind), s.kind, &s.transform, s.rgba, 0, None));
            }
        });
        if filled.is_err() {
            // A bug in `mark`; the one-thread path meets it again.
            return false;
        }
        self.marks = room;
        true
    }

    /// Adds the marks of `s`: one per tile copy touching the canvas, and a
    /// path's one per command.
    fn add(&mut self, s: &Finished, budget: &mut Budget) -> Result<(), EvalError> {
        let p = self.p;
        let shifts: Vec<Option<(f64, f64)>> = match &self.tiles {
            None => vec![None],
            // A fill covers the canvas once (`tiledCanvas::primitive`).
            Some(_) if s.kind == 4 => vec![None],
            Some(t) => {
                let (x0, y0) = p.to_pixels.apply(s.bounds.min_x, s.bounds.min_y);
                let (x1, y1) = p.to_pixels.apply(s.bounds.max_x, s.bounds.max_y);
                let b = Bounds { min_x: x0, min_y: y0, max_x: x1, max_y: y1 };
                let offsets = t.offsets(&b, p.canvas_width, p.canvas_height, budget)?;
                let per_shape = if s.kind == 3 { p.paths.get(s.path).map_or(0, Vec::len) } else { 1 };
                budget.reserve_memory(MARK_BYTES.saturating_mul((offsets.len().saturating_sub(1) * per_shape) as u64))?;
                offsets.into_iter().map(Some).collect()
            }
        };
        if self.tiles.is_none() && s.kind != 3 {
            // One mark, at no offset: no list of offsets to build.
            let m = self.mark(primitive_kind(s.kind), s.kind, &s.transform, s.rgba, 0, None);
            self.marks.push(m);
            return Ok(());
        }
        let kind = match s.kind {
            0 | 1 | 2 | 4 => primitive_kind(s.kind),
            _ => {
                for d in p.paths.get(s.path).map_or(&[][..], Vec::as_slice) {
                    let drawn = DrawnPath { segments: segments(d), style: style(d) };
                    let key = format!("{drawn:?}");
                    let index = match self.seen.get(&key) {
                        Some(&i) => i,
                        None => {
                            budget.reserve_memory(SEGMENT_BYTES.saturating_mul(drawn.segments.len() as u64).saturating_add(key.len() as u64))?;
                            self.seen.insert(key, self.paths.len() as u32);
                            self.paths.push(drawn);
                            self.paths.len() as u32 - 1
                        }
                    };
                    for &shift in &shifts {
                        let m = self.mark(MarkKind::Path, 3, &d.transform, d.rgba, index, shift);
                        self.marks.push(m);
                    }
                }
                return Ok(());
            }
        };
        for &shift in &shifts {
            let m = self.mark(kind, s.kind, &s.transform, s.rgba, 0, shift);
            self.marks.push(m);
        }
        Ok(())
    }

    fn finish(self) -> Drawing {
        let p = self.p;
        Drawing { width: p.canvas_width, height: p.canvas_height, background: background(p), marks: self.marks, paths: self.paths }
    }
}
