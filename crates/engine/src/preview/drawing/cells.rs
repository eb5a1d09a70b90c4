//! Coverage of a small filled polygon, the very bytes zeno's rasteriser
//! gives it, without zeno's per-shape setup.
//!
//! Why by hand: a big Context Free design is hundreds of thousands of
//! marks a pixel or two across (the bush benchmark: 262,143 squares at
//! 400 px), and for such a mark zeno's `Mask` (builder, path walk through
//! a transform sink, cell lists linked per row) cost several times the
//! coverage arithmetic itself. No crate rasterises a polygon into exact
//! area coverage with less setup, and the picture must keep zeno's bits
//! (the golden table holds the PNGs). So this is a port of zeno 0.3.3's
//! `raster.rs` (Chad Brokaw, after FreeType's "gray" rasteriser by David
//! Turner, Robert Wilhelm and Werner Lemberg) restricted to what a mark
//! needs: straight edges only, the non-zero rule, an alpha mask whose size
//! is the mark's box, and the cells kept in a dense grid (one per pixel
//! of the box, plus the column left of it where zeno gathers everything
//! left of the mask) instead of per-row lists. The grid gives each cell
//! the same wrapping sums in the same order of rows and columns as zeno's
//! sweep, so the coverage is identical: the test at the bottom compares
//! the two on many thousands of random polygons, on and off the mask.

/// Subpixel bits of the fixed-point coordinates (24.8), as zeno's.
const PIXEL_BITS: i32 = 8;
const ONE_PIXEL: i32 = 1 << PIXEL_BITS;

/// Masks up to this many pixels take this path; bigger ones go to zeno,
/// whose per-row lists cost less than a dense grid there.
pub(super) const MOST_PIXELS: u32 = 1024;

/// A dense grid of cells, reused from mark to mark.
#[derive(Default)]
pub(super) struct Cells {
    /// `(area, cover)` per cell, row by row, `width + 1` cells a row (the
    /// first is x = −1).
    grid: Vec<(i32, i32)>,
    width: i32,
    height: i32,
    // The rasteriser's state (zeno's `Rasterizer` fields).
    x: i32,
    y: i32,
    px: i32,
    py: i32,
    cover: i32,
    area: i32,
    invalid: bool,
}

impl Cells {
    /// Writes into every byte of `mask` (`width`×`height`; it need not be zeroed) the
    /// non-zero coverage of the closed polygon `points`, each point moved
    /// by `shift` before it is rounded to fixed point, as zeno's
    /// `Mask::render_into` writes it for a path of `MoveTo`, `LineTo`s and
    /// `Close` with that size and offset.
    pub(super) fn fill(&mut self, points: &[(f32, f32)], shift: (f32, f32), width: u32, height: u32, mask: &mut [u8]) {
        let Some(&first) = points.first() else {
            mask.fill(0);
            return;
        };
        let (w, h) = (width as i32, height as i32);
        self.width = w;
        self.height = h;
        self.grid.clear();
        self.grid.resize(((w + 1) * h) as usize, (0, 0));
        let fixed = |(x, y): (f32, f32)| (to_fixed(x + shift.0), to_fixed(y + shift.1));
        // `rasterize`'s start: no cell yet.
        (self.x, self.y, self.px, self.py, self.cover, self.area, self.invalid) = (0, 0, 0, 0, 0, 0, true);
        let start = fixed(first);
        self.set_cell(trunc(start.0), trunc(start.1));
        (self.px, self.py) = start;
        for &p in &points[1..] {
            self.line_to(fixed(p));
        }
        self.line_to(start);
        if !self.invalid {
            self.store(self.x, self.y, self.area, self.cover);
        }
        // The sweep: running cover along each row, a cell's own area
        // subtracted at its pixel (zeno's `rasterize` with every cell of the
        // row visited; a cell with nothing in it changes nothing).
        let row_cells = (w + 1) as usize;
        for (row, out) in self.grid.chunks_exact(row_cells).zip(mask.chunks_exact_mut(width as usize)) {
            let mut cover: i32 = row[0].1.wrapping_mul(ONE_PIXEL * 2);
            for (&(area, c), px) in row[1..].iter().zip(out.iter_mut()) {
                cover = cover.wrapping_add(c.wrapping_mul(ONE_PIXEL * 2));
                *px = coverage(cover.wrapping_sub(area));
            }
        }
    }

    /// zeno's `RasterStorage::set`: adds to cell (x, y), x already at least −1.
    fn store(&mut self, x: i32, y: i32, area: i32, cover: i32) {
        let i = (y * (self.width + 1) + x + 1) as usize;
        if let Some(cell) = self.grid.get_mut(i) {
            cell.0 = cell.0.wrapping_add(area);
            cell.1 = cell.1.wrapping_add(cover);
        }
    }

    fn set_cell(&mut self, x: i32, y: i32) {
        if !self.invalid && (self.area != 0 || self.cover != 0) {
            self.store(self.x, self.y, self.area, self.cover);
        }
        self.area = 0;
        self.cover = 0;
        self.x = x.max(-1);
        self.y = y;
        self.invalid = y >= self.height || y < 0 || x >= self.width;
    }

    /// zeno's `line_to`, line for line.
    fn line_to(&mut self, (to_x, to_y): (i32, i32)) {
        let mut ey1 = trunc(self.py);
        let ey2 = trunc(to_y);
        if (ey1 >= self.height && ey2 >= self.height) || (ey1 < 0 && ey2 < 0) {
            (self.px, self.py) = (to_x, to_y);
            return;
        }
        let mut ex1 = trunc(self.px);
        let ex2 = trunc(to_x);
        let mut fx1 = fract(self.px);
        let mut fy1 = fract(self.py);
        let dx = to_x - self.px;
        let dy = to_y - self.py;
        if ex1 == ex2 && ey1 == ey2 {
            // In one cell.
        } else if dy == 0 {
            self.set_cell(ex2, ey2);
            (self.px, self.py) = (to_x, to_y);
            return;
        } else if dx == 0 {
            if dy > 0 {
                loop {
                    let fy2 = ONE_PIXEL;
                    self.cover += fy2 - fy1;
                    self.area += (fy2 - fy1) * fx1 * 2;
                    fy1 = 0;
                    ey1 += 1;
                    self.set_cell(ex1, ey1);
                    if ey1 == ey2 {
                        break;
                    }
                }
            } else {
                loop {
                    let fy2 = 0;
                    self.cover += fy2 - fy1;
                    self.area += (fy2 - fy1) * fx1 * 2;
                    fy1 = ONE_PIXEL;
                    ey1 -= 1;
                    self.set_cell(ex1, ey1);
                    if ey1 == ey2 {
                        break;
                    }
                }
            }
        } else {
            let mut prod = dx * fy1 - dy * fx1;
            let dx_r = if ex1 != ex2 { 0x00FF_FFFF / dx } else { 0 };
            let dy_r = if ey1 != ey2 { 0x00FF_FFFF / dy } else { 0 };
            let udiv = |a: i32, b: i32| ((a as u64 * b as u64) >> (4 * 8 - PIXEL_BITS)) as i32;
            loop {
                if prod <= 0 && prod - dx * ONE_PIXEL > 0 {
                    let fx2 = 0;
                    let fy2 = udiv(-prod, -dx_r);
                    prod -= dy * ONE_PIXEL;
                    self.cover += fy2 - fy1;
                    self.area += (fy2 - fy1) * (fx1 + fx2);
                    fx1 = ONE_PIXEL;
                    fy1 = fy2;
                    ex1 -= 1;
                } else if prod - dx * ONE_PIXEL <= 0 && prod - dx * ONE_PIXEL + dy * ONE_PIXEL > 0 {
                    prod -= dx * ONE_PIXEL;
                    let fx2 = udiv(-prod, dy_r);
                    let fy2 = ONE_PIXEL;
                    self.cover += fy2 - fy1;
                    self.area += (fy2 - fy1) * (fx1 + fx2);
                    fx1 = fx2;
                    fy1 = 0;
                    ey1 += 1;
                } else if prod - dx * ONE_PIXEL + dy * ONE_PIXEL <= 0 && prod + dy * ONE_PIXEL >= 0 {
                    prod += dy * ONE_PIXEL;
                    let fx2 = ONE_PIXEL;
                    let fy2 = udiv(prod, dx_r);
                    self.cover += fy2 - fy1;
                    self.area += (fy2 - fy1) * (fx1 + fx2);
                    fx1 = 0;
                    fy1 = fy2;
                    ex1 += 1;
                } else {
                    let fx2 = udiv(prod, -dy_r);
                    let fy2 = 0;
                    prod += dx * ONE_PIXEL;
                    self.cover += fy2 - fy1;
                    self.area += (fy2 - fy1) * (fx1 + fx2);
                    fx1 = fx2;
                    fy1 = ONE_PIXEL;
                    ey1 -= 1;
                }
                self.set_cell(ex1, ey1);
                if ex1 == ex2 && ey1 == ey2 {
                    break;
                }
            }
        }
        let fx2 = fract(to_x);
        let fy2 = fract(to_y);
        self.cover += fy2 - fy1;
        self.area += (fy2 - fy1) * (fx1 + fx2);
        (self.px, self.py) = (to_x, to_y);
    }
}

/// zeno's `coverage` for the non-zero rule.
fn coverage(c: i32) -> u8 {
    let mut c = c >> (PIXEL_BITS * 2 + 1 - 8);
    if c < 0 {
        c = !c;
    }
    c.min(255) as u8
}

/// zeno's `to_fixed`: 24.8 fixed point, truncated toward zero (`as`
/// saturates where zeno's unchecked conversion would be undefined; the
/// caller keeps marks within a few million pixels of the canvas).
fn to_fixed(v: f32) -> i32 {
    (v * 256.0) as i32
}

fn trunc(x: i32) -> i32 {
    x >> PIXEL_BITS
}

fn fract(x: i32) -> i32 {
    x & (ONE_PIXEL - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use zeno::{Command, Fill, Mask, Point, Style};

    /// Random squares, triangles and octagons, a fraction of a pixel to
    /// many pixels across, some reaching past every side of the mask and
    /// some wound backwards: every mask byte equals zeno's.
    #[test]
    fn coverage_is_zenos() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut cells, mut scratch) = (Cells::default(), zeno::Scratch::new());
        let (mut ours, mut theirs) = (Vec::new(), Vec::new());
        for case in 0..40_000 {
            let n = [3, 4, 8][case % 3];
            let size = 0.05 + 12.0 * next().powi(3);
            let (cx, cy, turn) = (8.0 * next(), 8.0 * next(), 6.3 * next());
            let sign = if case % 7 == 0 { -1.0 } else { 1.0 };
            let points: Vec<(f32, f32)> = (0..n)
                .map(|k| {
                    let a = turn + sign * k as f64 * std::f64::consts::TAU / n as f64;
                    ((cx + size * a.cos()) as f32, (cy + size * (1.0 + 0.3 * next()) * a.sin()) as f32)
                })
                .collect();
            let (w, h) = (1 + (next() * 14.0) as u32, 1 + (next() * 14.0) as u32);
            let shift = ((-3.0 * next()) as f32, (-3.0 * next()) as f32);
            ours.clear();
            ours.resize((w * h) as usize, 0);
            cells.fill(&points, shift, w, h, &mut ours);
            let mut path = vec![Command::MoveTo(Point::new(points[0].0, points[0].1))];
            path.extend(points[1..].iter().map(|&(x, y)| Command::LineTo(Point::new(x, y))));
            path.push(Command::Close);
            theirs.clear();
            theirs.resize((w * h) as usize, 0);
            let mut mask = Mask::with_scratch(&path, &mut scratch);
            mask.size(w, h).style(Style::Fill(Fill::NonZero)).offset(zeno::Vector::new(shift.0, shift.1));
            mask.render_into(&mut theirs, None);
            assert_eq!(ours, theirs, "case {case}: {points:?} shift {shift:?} in {w}x{h}");
        }
    }
}
