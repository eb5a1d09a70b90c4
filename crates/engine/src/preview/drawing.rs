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
//! A primitive of at most `cells::MOST_PIXELS` mask pixels, most marks
//! of a big design, takes a port of zeno's rasteriser without its setup
//! (`drawing/cells.rs`, zeno's bytes). Big drawings are planned and filled
//! in parallel horizontal bands cut by work ([`render`]), with the same
//! bits as one band.
//!
//! Budget: the canvas is reserved before it is allocated; every mark costs
//! a step plus one per [`PIXELS_PER_STEP`] pixels of its box on the canvas,
//! all charged in drawing order before any is filled (charging checks the
//! deadline), and each band looks at the deadline as it fills.

use super::{Image, PreviewError, PreviewOptions};
use crate::core::budget::{Budget, LimitExceeded};
use crate::core::parallel::Slots;
use crate::model::drawing::{Drawing, Mark, MarkKind};
use zeno::{Command, Fill, Mask, Style, Transform};

mod cells;
mod outline;
mod pixel;
use pixel::{blend, demultiply, mul, premultiply};
use outline::{outline, path_outline};

/// Bounding-box pixels per budget step (the 3D rasteriser charges 64
/// samples per step; a mask pixel is one cell's work or less).
pub(crate) const PIXELS_PER_STEP: u64 = 256;

/// Bytes per pixel: the premultiplied canvas, its straight-alpha copy, and
/// at most one mask byte per band.
const BYTES_PER_PIXEL: u64 = 8;

/// Marks with a coordinate farther than this many pixels from the canvas
/// are not drawn: the rasteriser's cells are 24.8 fixed point.
const FAR: f64 = 4_000_000.0;

/// Drawings with fewer marks are filled on the calling thread: a band
/// thread costs more than it saves.
const BANDS_FROM: usize = 8192;

/// At most this many bands (threads) fill one picture.
const MOST_BANDS: usize = 4;

/// One mark to fill, planned: which mark, and its box on the canvas in
/// whole pixels (left, top, width, height), or the whole canvas for a fill.
/// A small primitive (at most [`cells::MOST_PIXELS`] pixels of box, at
/// most four corners) also carries its colour and corners, so the fill
/// neither reads its mark again nor rebuilds its outline: on a big design
/// of tiny marks, fetching the marks again had been a sixth of the fill.
#[derive(Clone, Copy)]
struct Job {
    mark: u32,
    left: u32,
    top: u32,
    width: u32,
    height: u32,
    /// The budget steps it costs (charged in drawing order by [`plan`]).
    steps: u32,
    /// The corners in `points` (0: read the mark and build its outline).
    corners: u8,
    rgba: [u8; 4],
    points: [(f32, f32); 4],
}

impl Job {
    /// A job that reads its mark when filled.
    fn of_mark(mark: usize, left: u32, top: u32, width: u32, height: u32) -> Job {
        Job { mark: mark as u32, left, top, width, height, steps: 0, corners: 0, rgba: [0; 4], points: [(0.0, 0.0); 4] }
    }
}

/// Bytes accounted per planned mark.
const JOB_BYTES: u64 = std::mem::size_of::<Job>() as u64;

/// Draws `drawing` at the request's `size` (the front end made its canvas
/// that size, `BuildRequest::canvas`; another canvas is scaled to fit), over
/// the request's `background` when it names one, else the drawing's own
/// (`CF::Background`, white by default).
///
/// Two passes. The first, on the calling thread, finds every mark's box
/// and charges its steps in drawing order, as a fill would. The second
/// fills the marks in parallel horizontal bands of the canvas (for a
/// drawing of at least [`BANDS_FROM`] marks): each band takes every mark
/// whose box meets it, in drawing order, rasterises its whole mask exactly
/// as a single band would, and blends only its own rows. Every pixel lies
/// in one band and sees the same blends in the same order with the same
/// coverage, so the picture is the same bits for any number of bands.
pub fn render(drawing: &Drawing, options: &PreviewOptions, budget: &mut Budget) -> Result<Image, PreviewError> {
    let bands = if drawing.marks.len() < BANDS_FROM { 1 } else { std::thread::available_parallelism().map_or(1, |n| n.get()).clamp(1, MOST_BANDS) };
    render_in(drawing, options, budget, bands)
}

/// [`render`] with `bands` bands (at least one).
fn render_in(drawing: &Drawing, options: &PreviewOptions, budget: &mut Budget, bands: usize) -> Result<Image, PreviewError> {
    options.validate().map_err(PreviewError::BadOptions)?;
    let bands = bands.max(1);
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
    let bytes = pixels.saturating_mul(BYTES_PER_PIXEL + bands as u64).saturating_add(JOB_BYTES.saturating_mul(drawing.marks.len() as u64));
    budget.reserve_memory(bytes)?;
    let jobs = &plan(drawing, fit, (width, height), budget, bands)?;
    let bg = match options.background {
        Some([r, g, b]) => [r, g, b, 255],
        None => drawing.background,
    };
    let mut canvas: Vec<[u8; 4]> = vec![premultiply(bg); pixels as usize];
    let budget_ref: &Budget = budget;
    let failed: Option<LimitExceeded> = if bands == 1 {
        fill(drawing, jobs, fit, width, 0, &mut canvas, budget_ref).err()
    } else {
        std::thread::scope(|scope| {
            let mut rest: &mut [[u8; 4]] = &mut canvas;
            let mut handles = Vec::with_capacity(bands);
            for (top, bottom) in band_rows(jobs, height, bands) {
                let (band, after) = rest.split_at_mut((bottom - top) as usize * width as usize);
                rest = after;
                handles.push(scope.spawn(move || fill(drawing, jobs, fit, width, top, band, budget_ref)));
            }
            // A band thread that panicked is a bug; it ends this render with the deadline's error rather than taking the worker down.
            handles.into_iter().map(|h| h.join().unwrap_or_else(|_| Err(budget_ref.deadline_stop().error()))).find_map(Result::err)
        })
    };
    if let Some(e) = failed {
        return Err(e.into());
    }
    let mut rgba: Vec<u8> = Vec::with_capacity(canvas.len() * 4);
    for &p in &canvas {
        rgba.extend_from_slice(&demultiply(p));
    }
    drop(canvas);
    budget.release_memory(bytes);
    Ok(Image { size: width, height, rgba })
}

/// The rows of each band, top to bottom, covering the canvas: cut where
/// the marks' work is shared evenly (a mark costs a fixed amount plus its
/// box's pixels, counted at its top row), since most of a design's marks
/// may lie in a few rows (the bush's crown), and equal heights would leave
/// one thread doing most of the work. Any cut gives the same bits.
fn band_rows(jobs: &[Job], height: u32, bands: usize) -> Vec<(u32, u32)> {
    let mut work = vec![0u64; height as usize];
    for j in jobs.iter().filter(|j| j.width > 0) {
        if let Some(w) = work.get_mut(j.top as usize) {
            *w += 64 + u64::from(j.width) * u64::from(j.height);
        }
    }
    let total: u64 = work.iter().sum();
    let mut cuts = Vec::with_capacity(bands);
    let (mut top, mut sum) = (0u32, 0u64);
    for (row, w) in work.iter().enumerate() {
        sum += w;
        let row = row as u32 + 1;
        let k = cuts.len() as u64 + 1;
        if cuts.len() + 1 < bands && sum * bands as u64 >= total * k && row < height {
            cuts.push((top, row));
            top = row;
        }
    }
    cuts.push((top, height));
    cuts
}

/// The first pass: each mark's box on the canvas, its steps charged in
/// drawing order (a mark costs a step plus one per [`PIXELS_PER_STEP`]
/// pixels of its box; a fill, of the canvas), and the marks to fill: one
/// job per mark, in order, a job of no width filling nothing.
///
/// A big drawing is planned on up to `threads` threads, each writing the
/// jobs of its own stretch of marks in place (a job depends on its mark
/// alone); the steps are then charged on this thread, mark by mark in
/// drawing order, as a single pass would charge them.
fn plan(drawing: &Drawing, fit: f64, canvas: (u32, u32), budget: &mut Budget, threads: usize) -> Result<Vec<Job>, PreviewError> {
    let n = drawing.marks.len();
    let mut jobs: Vec<Job> = Vec::with_capacity(n);
    crate::core::hugepages::advise(&mut jobs);
    let threads = if n < BANDS_FROM { 1 } else { threads.max(1) };
    let shared: &Budget = budget;
    let late = match crate::core::parallel::fill_in_place(&mut jobs, n, threads, |range, out| plan_marks(drawing, range, fit, canvas, out, shared)) {
        Ok(late) => late.into_iter().flatten().next(),
        // A thread that panicked is a bug; it ends this render with the deadline's error rather than taking the worker down.
        Err(_) => Some(shared.deadline_stop().error()),
    };
    if let Some(e) = late {
        return Err(e.into());
    }
    for job in &jobs {
        match job.steps {
            0 => {}
            // Most marks of a big drawing are a pixel or two: their step
            // looks at the clock every 1,024 steps, not every mark (the
            // clock was 3 % of the bush's time).
            1 => budget.charge_step()?,
            n => budget.charge_steps(u64::from(n))?,
        }
    }
    Ok(jobs)
}

/// Plans the marks of `range`, pushing one job per mark into `out`; looks
/// at the deadline every 1,024 marks and, past it, pushes empty jobs for
/// the rest and returns the deadline's error.
fn plan_marks(drawing: &Drawing, range: std::ops::Range<usize>, fit: f64, (width, height): (u32, u32), out: &mut Slots<'_, Job>, budget: &Budget) -> Option<LimitExceeded> {
    let pixels = u64::from(width) * u64::from(height);
    let (mut path, mut points) = (Vec::with_capacity(16), Vec::with_capacity(16));
    let mut late = None;
    for (k, i) in range.enumerate() {
        if k % 1024 == 1023 && late.is_none() {
            late = budget.check_deadline().err();
        }
        let job = match (&late, drawing.marks.get(i)) {
            (None, Some(mark)) => plan_mark(drawing, i, mark, fit, (width, height), pixels, &mut path, &mut points),
            _ => Job::of_mark(i, 0, 0, 0, 0),
        };
        out.push(job);
    }
    late
}

/// One mark's job: its box, its steps, and for a small primitive its corners.
#[allow(clippy::too_many_arguments)]
fn plan_mark(drawing: &Drawing, i: usize, mark: &Mark, fit: f64, (width, height): (u32, u32), pixels: u64, path: &mut Vec<Command>, points: &mut Vec<(f64, f64)>) -> Job {
    let none = Job::of_mark(i, 0, 0, 0, 0);
    if mark.kind == MarkKind::Fill {
        return Job { steps: u32::try_from(1 + pixels / PIXELS_PER_STEP).unwrap_or(u32::MAX), ..Job::of_mark(i, 0, 0, width, height) };
    }
    let Some((corners, ..)) = shape(drawing, mark, fit, path, points) else { return none };
    let Some((x0, y0, x1, y1)) = corners else { return none };
    // The box on the canvas, in whole pixels.
    let (bx0, by0) = (x0.floor().max(0.0), y0.floor().max(0.0));
    let (bx1, by1) = (x1.ceil().min(f64::from(width)), y1.ceil().min(f64::from(height)));
    let (w, h) = (bx1 - bx0, by1 - by0);
    let steps = u32::try_from(1 + (w.max(0.0) * h.max(0.0)) as u64 / PIXELS_PER_STEP).unwrap_or(u32::MAX);
    if w <= 0.0 || h <= 0.0 || [x0, y0, x1, y1].iter().any(|v| v.abs() > FAR) {
        return Job { steps, ..none };
    }
    let mut job = Job { steps, ..Job::of_mark(i, bx0 as u32, by0 as u32, w as u32, h as u32) };
    if mark.kind != MarkKind::Path && points.len() <= 4 && job.width * job.height <= cells::MOST_PIXELS {
        job.corners = points.len() as u8;
        job.rgba = mark.rgba;
        for (c, &(x, y)) in job.points.iter_mut().zip(points.iter()) {
            *c = (x as f32, y as f32);
        }
    }
    job
}

/// A mark's outline (into `path`), style and pen map at the picture's
/// fit; `None` for a path mark whose path is missing.
fn shape(drawing: &Drawing, mark: &Mark, fit: f64, path: &mut Vec<Command>, points: &mut Vec<(f64, f64)>) -> Option<outline::Outline> {
    let m = mark.raster.map(|v| v * fit);
    match (mark.kind, drawing.paths.get(mark.path as usize)) {
        (MarkKind::Path, Some(p)) => Some(path_outline(p, &m, path)),
        (MarkKind::Path, None) => None,
        (kind, _) => Some((outline(kind, &m, path, points), Style::Fill(Fill::NonZero), None)),
    }
}

/// The second pass over one band: the canvas rows `top..` in `band`
/// (whole rows of `width` pixels), every planned mark meeting them filled
/// in order. The deadline is looked at every 1,024 marks.
fn fill(drawing: &Drawing, jobs: &[Job], fit: f64, width: u32, top: u32, band: &mut [[u8; 4]], budget: &Budget) -> Result<(), LimitExceeded> {
    let bottom = top + (band.len() / width.max(1) as usize) as u32;
    let (mut path, mut points, mut mask) = (Vec::with_capacity(16), Vec::with_capacity(16), Vec::new());
    // zeno's rasteriser without scratch memory builds (and zeroes) a
    // 16 KiB cell array on the stack for every mark; kept scratch memory
    // gives the same coverage without it, which halved the preview of
    // the 262,143-square bush (docs/benchmarks.md).
    let mut scratch = zeno::Scratch::new();
    let (mut small, mut corners) = (cells::Cells::default(), Vec::with_capacity(16));
    for (n, job) in jobs.iter().enumerate() {
        if n % 1024 == 1023 {
            budget.check_deadline()?;
        }
        if job.width == 0 || job.top >= bottom || job.top + job.height <= top {
            continue;
        }
        let (w, h) = (job.width, job.height);
        let (bx0, by0) = (f64::from(job.left), f64::from(job.top));
        if job.corners > 0 {
            // A primitive a few pixels across: zeno's coverage, without zeno's setup (cells.rs).
            // `Cells::fill` writes every byte of the mask: no zeroing first.
            let n = w as usize * h as usize;
            if mask.len() < n {
                mask.resize(n, 0);
            }
            small.fill(&job.points[..usize::from(job.corners)], (-bx0 as f32, -by0 as f32), w, h, &mut mask[..n]);
            blend_mask(band, width, top, bottom, job, &mask[..n]);
            continue;
        }
        let Some(mark) = drawing.marks.get(job.mark as usize) else { continue };
        let [r, g, b, a] = mark.rgba;
        if mark.kind == MarkKind::Fill {
            // AGG's `renderer_base::fill`: the colour blended over every pixel.
            for px in band.iter_mut() {
                blend(px, [r, g, b], mul(255, a));
            }
            continue;
        }
        let Some((_, style, transform)) = shape(drawing, mark, fit, &mut path, &mut points) else { continue };
        mask.clear();
        mask.resize(w as usize * h as usize, 0);
        if mark.kind != MarkKind::Path && w * h <= cells::MOST_PIXELS {
            // A primitive a few pixels across: zeno's coverage, without zeno's setup (cells.rs).
            corners.clear();
            corners.extend(points.iter().map(|&(x, y)| (x as f32, y as f32)));
            small.fill(&corners, (-bx0 as f32, -by0 as f32), w, h, &mut mask);
        } else {
            let mut fill = Mask::with_scratch(&path, &mut scratch);
            fill.size(w, h).style(style);
            match transform {
                // The box offset goes into the map, applied after the pen.
                Some(t) => fill.transform(Some(Transform::new(t.xx, t.xy, t.yx, t.yy, t.x - bx0 as f32, t.y - by0 as f32))),
                None => fill.offset(zeno::Vector::new(-bx0 as f32, -by0 as f32)),
            };
            fill.render_into(&mut mask, None);
        }
        blend_mask(band, width, top, bottom, &Job { rgba: [r, g, b, a], ..*job }, &mask);
    }
    Ok(())
}

/// Blends `job`'s colour through its coverage `mask` (its box) into the
/// band's rows `top..bottom`.
fn blend_mask(band: &mut [[u8; 4]], width: u32, top: u32, bottom: u32, job: &Job, mask: &[u8]) {
    let [r, g, b, a] = job.rgba;
    let (left, w) = (job.left as usize, job.width as usize);
    for (row, covers) in mask.chunks_exact(w.max(1)).enumerate() {
        let y = job.top + row as u32;
        if y < top || y >= bottom {
            continue;
        }
        let start = (y - top) as usize * width as usize + left;
        let Some(pixels) = band.get_mut(start..start + w) else { continue };
        for (px, &cover) in pixels.iter_mut().zip(covers) {
            if cover != 0 {
                blend(px, [r, g, b], mul(cover, a));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 9,000 marks of every kind but paths, large and small, overlapping
    /// and translucent, some off the canvas: bands of 2, 3 and 4 give the
    /// single band's bits.
    #[test]
    fn bands_give_the_same_bits_as_one() {
        let kinds = [MarkKind::Square, MarkKind::Circle, MarkKind::Triangle];
        let mut marks = Vec::new();
        let mut x = 12345u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % 10_000) as f64 / 10_000.0
        };
        for i in 0..9_000 {
            let (s, r) = (1.0 + 60.0 * next().powi(3), 6.3 * next());
            let m = [s * r.cos(), s * r.sin(), -s * r.sin(), s * r.cos(), 220.0 * next() - 10.0, 220.0 * next() - 10.0];
            let rgba = [(255.0 * next()) as u8, (255.0 * next()) as u8, (255.0 * next()) as u8, 40 + (200.0 * next()) as u8];
            let kind = if i == 4_000 { MarkKind::Fill } else { kinds[i % 3] };
            marks.push(Mark { kind, matrix: m, raster: m, rgba, path: 0 });
        }
        let d = Drawing { width: 200, height: 200, background: [255, 255, 255, 255], marks, paths: Vec::new() };
        let opts = PreviewOptions { size: 200, ..PreviewOptions::default() };
        let draw = |bands| render_in(&d, &opts, &mut Budget::new(crate::core::Limits::default()), bands).expect("draws").rgba;
        let one = draw(1);
        assert!(one.chunks(4).filter(|p| p != &[255, 255, 255, 255]).count() > 30_000, "the marks cover the canvas");
        for bands in [2, 3, 4] {
            assert!(draw(bands) == one, "{bands} bands differ from one");
        }
    }
}
