//! A fixed-point, supersampled triangle rasteriser with a depth buffer.
//!
//! Written by hand rather than taken from `euc` (the software rasteriser
//! the issue suggests), which was evaluated and does not fit: it decides
//! coverage with `f32` barycentric weights tested against 0..1 at whole
//! pixel centres, so there is no fill rule (pixels on an edge two triangles
//! share are drawn twice or not at all), no supersampling, and no integer
//! path whose bits could be pinned. Here every vertex is snapped to
//! 1/256 of a sample, coverage is decided by exact integer edge functions
//! with the top-left rule (each sample on a shared edge belongs to exactly
//! one triangle), and depth and colour are integer plane equations stepped
//! by addition, so the same triangles give the same bits on every machine.
//!
//! Each pixel is [`samples_per_axis`]² samples (16 up to 128 px, 4 above),
//! averaged in linear light. The samples are drawn in horizontal bands of
//! at most [`BAND_SAMPLES`], so a 2048 px picture needs 32 MiB, not 128.
//!
//! Budget: each triangle costs one step plus one per 64 samples of its
//! bounding box inside the band (pixels × triangles, as tested), charged
//! before it is drawn in batches; charging also checks the deadline.

use super::camera::Framing;
use super::shade::{self, Lights, LINEAR_MAX};
use super::{Image, PreviewOptions};
use crate::core::budget::{Budget, LimitExceeded};
use crate::geom::{Mesh, NamedMesh, STOP_EVERY};

/// Fractional bits of a vertex's snapped sample position.
pub(crate) const SUBPIXEL_BITS: u32 = 8;
const SUB: i64 = 1 << SUBPIXEL_BITS;
/// Snapped coordinates are clamped to ±2^29 (2 million samples): edge
/// functions then stay below 2^62 in `i64`. Only a vertex hundreds of
/// pictures away is moved, which a framed-out backdrop can be.
const COORD_LIMIT: i64 = 1 << 29;
/// The depth of the farthest vertex (the nearest is 0).
pub(crate) const Z_MAX: i64 = (1 << 24) - 1;
/// Fractional bits of the interpolated depth and colour.
const ATTR_BITS: u32 = 16;
/// Samples of colour and depth held at once (4 Mi × 8 bytes = 32 MiB).
pub(crate) const BAND_SAMPLES: u64 = 1 << 22;
/// Bounding-box samples per budget step.
pub(crate) const SAMPLES_PER_STEP: u64 = 64;
/// Steps gathered before they are charged (and the deadline checked); a
/// triangle of this many steps' samples or more is charged on its own.
const CHARGE_EVERY: u64 = 4096;
/// A sample's depth before any triangle covers it.
const EMPTY: u32 = u32::MAX;
/// A backdrop sample's depth once the backdrop is drawn: behind any model
/// depth (at most [`Z_MAX`]), yet covered.
const BEHIND: u32 = u32::MAX - 1;

/// Whether a triangle is part of a backdrop: its extent on the picture is
/// more than twice the picture's side (`width` samples). No triangle of a
/// model framed whole can be (the framed box is 80 % of the side); only
/// geometry the framing left out, such as a backdrop box hundreds of units
/// wide, is. Backdrops are drawn behind the model, as a wall or floor that
/// never hides it (`docs/preview.md`).
fn is_backdrop(a: &ScreenVertex, b: &ScreenVertex, c: &ScreenVertex, width: i64) -> bool {
    let limit = 2 * width * SUB;
    a.x.max(b.x).max(c.x) - a.x.min(b.x).min(c.x) > limit || a.y.max(b.y).max(c.y) - a.y.min(b.y).min(c.y) > limit
}

/// The placed corners of each triangle of `mesh` whose indices are in range.
fn triangles<'a>(mesh: &'a Mesh, verts: &'a [ScreenVertex]) -> impl Iterator<Item = [ScreenVertex; 3]> + 'a {
    mesh.indices.chunks_exact(3).filter_map(|t| Some([*verts.get(t[0] as usize)?, *verts.get(t[1] as usize)?, *verts.get(t[2] as usize)?]))
}

/// Samples per pixel side: 4×4 up to 128 px (icons, where edges matter
/// most), 2×2 above; both at least 4 samples a pixel, and at most 512² samples
/// up to 256 px, which keeps a 100k-triangle preview within its time.
pub(crate) fn samples_per_axis(size: u32) -> u32 {
    if size <= 128 {
        4
    } else {
        2
    }
}

/// A vertex placed in the supersampled picture and lit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ScreenVertex {
    /// x in 1/256 samples from the left.
    pub x: i64,
    /// y in 1/256 samples from the top.
    pub y: i64,
    /// Depth, 0 (nearest vertex) to [`Z_MAX`] (farthest).
    pub z: i64,
    /// Lit linear colour, `0..=LINEAR_MAX` per channel.
    pub rgb: [i64; 3],
}

/// Bytes the stage holds per vertex: the placed vertex and the framing's two coordinates.
pub const VERTEX_BYTES: u64 = std::mem::size_of::<ScreenVertex>() as u64 + 8;

/// Places and lights every vertex of `mesh` (normals and colours missing
/// from a mesh made by hand count as facing the camera and white). `None`
/// when `stop`, asked every [`STOP_EVERY`] vertices, said to give up.
pub fn project(mesh: &Mesh, frame: &Framing, lights: &Lights, stop: &dyn Fn() -> bool) -> Option<Vec<ScreenVertex>> {
    let [near, far] = frame.depth;
    let range = near - far;
    let snap = |v: f32| round(v * SUB as f32).clamp(-COORD_LIMIT, COORD_LIMIT);
    // Neighbouring vertices often share a normal and a colour (a face's corners): lit once.
    let mut last: Option<(([f32; 3], [u8; 4]), [i64; 3])> = None;
    mesh.positions
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            if i % STOP_EVERY == STOP_EVERY - 1 && stop() {
                return None;
            }
            let [x, y, d] = frame.place(p);
            let z = if range > 0.0 { round(((near - d) / range) * Z_MAX as f32) } else { 0 };
            let key = (mesh.normals.get(i).copied().unwrap_or([0.0, 0.0, 0.0]), mesh.colours.get(i).copied().unwrap_or([255; 4]));
            let rgb = match last {
                Some((k, rgb)) if k == key => rgb,
                _ => {
                    let n = key.0;
                    let n = [super::camera::dot(n, frame.right), super::camera::dot(n, frame.up), super::camera::dot(n, frame.back)];
                    let albedo = [key.1[0], key.1[1], key.1[2]].map(|v| f32::from(v) / 255.0);
                    let rgb = lights.shade(albedo, n).map(|c| round(c * LINEAR_MAX as f32));
                    last = Some((key, rgb));
                    rgb
                }
            };
            Some(ScreenVertex { x: snap(x), y: snap(y), z: z.clamp(0, Z_MAX), rgb })
        })
        .collect()
}

/// `v` rounded half away from zero, as `f32::round` (which compiles to a
/// call of C's `roundf` on x86-64's baseline; this is a few instructions),
/// exact for |v| < 2^23 and saturating beyond.
fn round(v: f32) -> i64 {
    let t = v as i64;
    let frac = v - t as f32;
    if frac >= 0.5 {
        t + 1
    } else if frac <= -0.5 {
        t - 1
    } else {
        t
    }
}

/// `v` (|v| ≤ 2^52) rounded half away from zero, like `f64::round`, which
/// is a libm call on x86-64's baseline and was a tenth of a preview's time.
fn round_f64(v: f64) -> i64 {
    let t = v as i64;
    let frac = v - t as f64;
    t + i64::from(frac >= 0.5) - i64::from(frac <= -0.5)
}

/// One band of supersampled colour (10 bits a channel) and depth.
struct Band {
    /// Samples per row.
    width: i64,
    /// The first sample row and one past the last.
    rows: (i64, i64),
    depth: Vec<u32>,
    colour: Vec<u32>,
}

/// Budget steps drawn but not yet charged.
struct Meter<'b> {
    budget: &'b mut Budget,
    pending: u64,
}

impl Meter<'_> {
    fn add(&mut self, steps: u64) -> Result<(), LimitExceeded> {
        self.pending = self.pending.saturating_add(steps);
        // A large triangle is charged at once, before it is drawn.
        if self.pending >= CHARGE_EVERY || steps >= CHARGE_EVERY / SAMPLES_PER_STEP {
            self.flush()?;
        }
        Ok(())
    }

    fn flush(&mut self) -> Result<(), LimitExceeded> {
        let n = std::mem::take(&mut self.pending);
        self.budget.charge_steps(n)
    }
}

/// Draws every triangle of `meshes` (placed as `vertices`, one list per
/// mesh) into a picture, band by band, and resolves it to sRGB pixels.
/// `cull` (one flag per mesh) marks the meshes whose triangles are skipped
/// when they face away from the camera (closed, outward ones: [`super::closed`]).
pub fn draw(meshes: &[NamedMesh], vertices: &[Vec<ScreenVertex>], cull: &[bool], options: &PreviewOptions, budget: &mut Budget) -> Result<Image, LimitExceeded> {
    let ss = i64::from(samples_per_axis(options.size));
    let width = i64::from(options.size) * ss;
    let band_rows = ((BAND_SAMPLES as i64 / width) / ss * ss).clamp(ss, width);
    let band_bytes = (band_rows * width) as u64 * 8;
    let image_bytes = u64::from(options.size) * u64::from(options.size) * 4;
    budget.reserve_memory(band_bytes.saturating_add(image_bytes))?;
    let mut rgba = vec![0u8; image_bytes as usize];
    let cells = (band_rows * width) as usize;
    let (depth, colour) = BandBuffers::take(cells);
    let mut band = Band { width, rows: (0, 0), depth, colour };
    let mut meter = Meter { budget, pending: 0 };
    let mut top = 0;
    // Backdrop triangles (see `is_backdrop`), if any, are drawn first and
    // then pushed behind everything, so they never hide the model.
    // When every vertex lies within the picture's side of it, no triangle can be one.
    let reach = width * SUB;
    let any_backdrop = vertices.iter().flatten().any(|v| v.x < -reach || v.x > 2 * reach || v.y < -reach || v.y > 2 * reach);
    let backdrop = |a: &ScreenVertex, b: &ScreenVertex, c: &ScreenVertex| any_backdrop && is_backdrop(a, b, c, width);
    while top < width {
        band.rows = (top, (top + band_rows).min(width));
        band.depth.fill(EMPTY);
        for pass in [true, false] {
            if pass && !any_backdrop {
                continue;
            }
            for ((mesh, verts), &cull) in meshes.iter().zip(vertices).zip(cull) {
                for [a, b, c] in triangles(&mesh.mesh, verts) {
                    if backdrop(&a, &b, &c) == pass {
                        band.triangle(a, b, c, cull, &mut meter)?;
                    }
                }
            }
            if pass {
                band.depth.iter_mut().filter(|d| **d != EMPTY).for_each(|d| *d = BEHIND);
            }
        }
        meter.flush()?;
        band.resolve(ss, options.background, &mut rgba);
        top += band_rows;
    }
    meter.budget.release_memory(band_bytes);
    BandBuffers::keep(band.depth, band.colour);
    Ok(Image { size: options.size, height: options.size, rgba })
}

/// The largest band, in samples, whose buffers a thread keeps for its next
/// preview: a 256 px icon's whole picture (512² samples, 2 MiB of depth and
/// colour). Larger previews allocate theirs each time.
const KEPT_CELLS: usize = 512 * 512;

thread_local! {
    /// The band buffers of this thread's last preview (at most [`KEPT_CELLS`]).
    static KEPT: std::cell::RefCell<(Vec<u32>, Vec<u32>)> = const { std::cell::RefCell::new((Vec::new(), Vec::new())) };
}

/// Band buffers kept from one preview to the next on the same thread. A
/// fresh 2 MiB pair for every icon cost a third of a 256 px preview's CPU
/// (page faults, zeroing, and returning the pages: issue 33's profile);
/// kept, a buffer is only sized. Its old contents are never read: every
/// band fills its depth with [`EMPTY`] first, and a colour is read only
/// where a triangle of this band set the depth, so the pixels do not
/// depend on what the last preview left. The service renders on its
/// blocking pool (at most `--max-concurrency` + 4 threads), so at most that
/// many pairs are kept.
struct BandBuffers;

impl BandBuffers {
    /// A depth and a colour buffer of `cells` samples, the kept ones when they fit.
    fn take(cells: usize) -> (Vec<u32>, Vec<u32>) {
        let (mut depth, mut colour) = if cells <= KEPT_CELLS { KEPT.with(|k| std::mem::take(&mut *k.borrow_mut())) } else { (Vec::new(), Vec::new()) };
        depth.resize(cells, EMPTY);
        depth.truncate(cells);
        colour.resize(cells, 0);
        colour.truncate(cells);
        (depth, colour)
    }

    /// Keeps the buffers for the thread's next preview, when small enough.
    fn keep(depth: Vec<u32>, colour: Vec<u32>) {
        if depth.capacity() <= KEPT_CELLS && colour.capacity() <= KEPT_CELLS {
            KEPT.with(|k| *k.borrow_mut() = (depth, colour));
        }
    }
}

/// One attribute's plane over the triangle's samples, in 1/2^16 units:
/// its value at the box's first sample and its steps along x and y.
#[derive(Clone, Copy)]
struct Plane {
    start: i64,
    dx: i64,
    dy: i64,
}

impl Plane {
    /// The plane through values `a` at the corners, from the edge functions
    /// at the first sample (`e`, opposite each corner), their steps, and
    /// `1 / area`. Set up in `f64` (IEEE operations in a fixed order, so the
    /// same bits everywhere), then stepped in integers.
    fn new(a: [i64; 3], e: [i64; 3], ex: [i64; 3], ey: [i64; 3], inv_area: f64) -> Plane {
        let scale = inv_area * f64::from(1u32 << ATTR_BITS);
        let at = |w: [i64; 3]| -> i64 {
            let sum = w[0] as f64 * a[0] as f64 + w[1] as f64 * a[1] as f64 + w[2] as f64 * a[2] as f64;
            // Saturating: only a sample far outside a sliver could be this far off.
            round_f64((sum * scale).clamp(-ATTR_LIMIT, ATTR_LIMIT))
        };
        Plane { start: at(e), dx: at(ex), dy: at(ey) }
    }
}

/// The largest interpolated value kept (far beyond any real depth or colour),
/// so stepping it across a picture cannot overflow.
const ATTR_LIMIT: f64 = (1u64 << 48) as f64;

/// The first and last x (`x0 + t`) of a row where `w + step * t + bias >= 0`,
/// within `0..=len`; `None` when there is none. `recip` is `1 / step`: the
/// end is estimated in `f64`, then moved to the exact integer answer.
fn span(w: i64, step: i64, bias: i64, recip: f64, len: i64) -> Option<(i64, i64)> {
    let w = w + bias;
    let inside = |t: i64| w + step * t >= 0;
    let guess = |t: f64| t.clamp(-1.0, (len + 1) as f64) as i64;
    match step {
        0 if w >= 0 => Some((0, len)),
        0 => None,
        s if s > 0 => {
            if w >= 0 {
                return Some((0, len));
            }
            let mut t = guess(-(w as f64) * recip).max(0);
            while t > 0 && inside(t - 1) {
                t -= 1;
            }
            while t <= len && !inside(t) {
                t += 1;
            }
            (t <= len).then_some((t, len))
        }
        _ => {
            if w < 0 {
                return None;
            }
            let mut t = guess(-(w as f64) * recip).min(len);
            while t < len && inside(t + 1) {
                t += 1;
            }
            while t >= 0 && !inside(t) {
                t -= 1;
            }
            (t >= 0).then_some((0, t))
        }
    }
}

/// The covered samples `x0 + lo ..= x0 + hi` of one row of a triangle,
/// from its edge functions `w` at the row's first sample, their steps and
/// the steps' reciprocals. A row crosses a triangle in one piece.
fn row_span(w: [i64; 3], ex: [i64; 3], bias: [i64; 3], recip: [f64; 3], len: i64) -> Option<(i64, i64)> {
    let (mut lo, mut hi) = (0, len);
    for k in 0..3 {
        let (f, l) = span(w[k], ex[k], bias[k], recip[k], len)?;
        lo = lo.max(f);
        hi = hi.min(l);
    }
    (lo <= hi).then_some((lo, hi))
}

impl Band {
    /// Draws one triangle: samples whose centres it covers (top-left rule)
    /// and that are nearer than what is there take its depth and colour.
    /// Each row is walked only over its covered span, found exactly from
    /// the edge functions, so a long sliver costs its samples, not its box.
    /// With `cull`, a triangle facing away from the camera is skipped.
    fn triangle(&mut self, a: ScreenVertex, b: ScreenVertex, c: ScreenVertex, cull: bool, meter: &mut Meter<'_>) -> Result<(), LimitExceeded> {
        let cross = |p: &ScreenVertex, q: &ScreenVertex, r: &ScreenVertex| (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
        let area = cross(&a, &b, &c);
        // y runs down the picture, so a triangle wound counter-clockwise as
        // the camera sees it (facing it) has a negative area here.
        if area == 0 {
            return Ok(());
        }
        if cull && area > 0 {
            return meter.add(1);
        }
        // Otherwise both windings are drawn (lighting is two-sided); order the corners so the area is positive.
        let (b, c, area) = if area < 0 { (c, b, -area) } else { (b, c, area) };
        let v = [a, b, c];
        // Sample centres are at (i + ½) samples; the box holds those inside the corners' extent.
        let first = |lo: i64| (lo - SUB / 2 + SUB - 1).div_euclid(SUB);
        let last = |hi: i64| (hi - SUB / 2).div_euclid(SUB);
        let x0 = first(a.x.min(b.x).min(c.x)).max(0);
        let x1 = last(a.x.max(b.x).max(c.x)).min(self.width - 1);
        let y0 = first(a.y.min(b.y).min(c.y)).max(self.rows.0);
        let y1 = last(a.y.max(b.y).max(c.y)).min(self.rows.1 - 1);
        if x0 > x1 || y0 > y1 {
            return meter.add(1);
        }
        // The work: a span per row, and the samples covered (the area, at
        // most the box's): charged before any is drawn.
        let covered = ((area / (2 * SUB * SUB)) as u64).min(((x1 - x0 + 1) * (y1 - y0 + 1)) as u64);
        meter.add(1 + (y1 - y0 + 1) as u64 / 8 + covered / SAMPLES_PER_STEP)?;
        // Edge k runs from corner k+1 to k+2 (opposite corner k); inside is
        // where all three are positive, or zero on a top or left edge.
        let (px, py) = (x0 * SUB + SUB / 2, y0 * SUB + SUB / 2);
        let mut e = [0i64; 3];
        let mut ex = [0i64; 3];
        let mut ey = [0i64; 3];
        let mut bias = [0i64; 3];
        for k in 0..3 {
            let (p, q) = (v[(k + 1) % 3], v[(k + 2) % 3]);
            let (dx, dy) = (q.x - p.x, q.y - p.y);
            e[k] = dx * (py - p.y) - dy * (px - p.x);
            ex[k] = -dy * SUB;
            ey[k] = dx * SUB;
            let top_left = dy < 0 || (dy == 0 && dx > 0);
            bias[k] = if top_left { 0 } else { -1 };
        }
        let inv_area = 1.0 / area as f64;
        let z = Plane::new(v.map(|s| s.z), e, ex, ey, inv_area);
        let flat = (a.rgb == b.rgb && b.rgb == c.rgb).then(|| {
            let ch = |k: usize| a.rgb[k].clamp(0, LINEAR_MAX) as u32;
            ch(0) << 20 | ch(1) << 10 | ch(2)
        });
        let rgb: [Plane; 3] = match flat {
            Some(_) => [Plane { start: 0, dx: 0, dy: 0 }; 3],
            None => [0, 1, 2].map(|ch| Plane::new(v.map(|s| s.rgb[ch]), e, ex, ey, inv_area)),
        };
        let len = x1 - x0;
        let recip = ex.map(|s| if s == 0 { 0.0 } else { 1.0 / s as f64 });
        for y in y0..=y1 {
            let j = y - y0;
            let w = [0, 1, 2].map(|k| e[k] + ey[k] * j);
            let Some((lo, hi)) = row_span(w, ex, bias, recip, len) else {
                continue;
            };
            let base = ((y - self.rows.0) * self.width + x0) as usize;
            let at = |p: &Plane| p.start + p.dy * j + p.dx * lo;
            let (mut zz, mut cc) = (at(&z), [at(&rgb[0]), at(&rgb[1]), at(&rgb[2])]);
            let (Some(depths), Some(colours)) = (self.depth.get_mut(base + lo as usize..=base + hi as usize), self.colour.get_mut(base + lo as usize..=base + hi as usize)) else {
                continue;
            };
            if let Some(packed) = flat {
                // One colour (a flat face, lit alike at its corners): only depth varies.
                for (d, slot) in depths.iter_mut().zip(colours.iter_mut()) {
                    let depth = (zz >> ATTR_BITS).clamp(0, Z_MAX) as u32;
                    if depth < *d {
                        *d = depth;
                        *slot = packed;
                    }
                    zz += z.dx;
                }
                continue;
            }
            for (d, slot) in depths.iter_mut().zip(colours.iter_mut()) {
                let depth = (zz >> ATTR_BITS).clamp(0, Z_MAX) as u32;
                if depth < *d {
                    *d = depth;
                    let ch = |k: usize| (cc[k] >> ATTR_BITS).clamp(0, LINEAR_MAX) as u32;
                    *slot = ch(0) << 20 | ch(1) << 10 | ch(2);
                }
                zz += z.dx;
                cc = [cc[0] + rgb[0].dx, cc[1] + rgb[1].dx, cc[2] + rgb[2].dx];
            }
        }
        Ok(())
    }

    /// Averages each pixel's samples (in linear light) into `rgba`'s rows of
    /// this band: alpha is the covered share, or opaque over `background`.
    fn resolve(&self, ss: i64, background: Option<[u8; 3]>, rgba: &mut [u8]) {
        let size = (self.width / ss) as usize;
        let per_pixel = ss * ss;
        let bg = background.map(|c| c.map(shade::linear_of_srgb));
        let to_srgb = |sum: i64, n: i64| shade::srgb_of_linear(((sum * 4 + n / 2) / n) as usize);
        let width = self.width as usize;
        let mut covered = vec![0i64; size];
        let mut sums = vec![[0i64; 3]; size];
        for py in self.rows.0 / ss..self.rows.1 / ss {
            covered.fill(0);
            sums.fill([0; 3]);
            for sy in 0..ss {
                let row = ((py * ss + sy - self.rows.0) * self.width) as usize;
                let (Some(depths), Some(colours)) = (self.depth.get(row..row + width), self.colour.get(row..row + width)) else {
                    continue;
                };
                // A pixel's samples of this row side by side: no division per sample.
                let pixels = depths.chunks_exact(ss as usize).zip(colours.chunks_exact(ss as usize));
                for ((d, c), (n, s)) in pixels.zip(covered.iter_mut().zip(sums.iter_mut())) {
                    for (&d, &c) in d.iter().zip(c) {
                        if d != EMPTY {
                            let c = i64::from(c);
                            *n += 1;
                            *s = [s[0] + (c >> 20 & 0x3ff), s[1] + (c >> 10 & 0x3ff), s[2] + (c & 0x3ff)];
                        }
                    }
                }
            }
            for px in 0..size {
                let (n, sum) = (covered[px], sums[px]);
                let out = match bg {
                    None if n == 0 => [0, 0, 0, 0],
                    None => {
                        let alpha = ((n * 255 + per_pixel / 2) / per_pixel) as u8;
                        [to_srgb(sum[0], n), to_srgb(sum[1], n), to_srgb(sum[2], n), alpha]
                    }
                    Some(bg) => {
                        let blend = |k: usize| to_srgb(sum[k] + (per_pixel - n) * bg[k], per_pixel);
                        [blend(0), blend(1), blend(2), 255]
                    }
                };
                let at = (py as usize * size + px) * 4;
                if let Some(dst) = rgba.get_mut(at..at + 4) {
                    dst.copy_from_slice(&out);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;

    fn vertex(x: i64, y: i64) -> ScreenVertex {
        ScreenVertex { x: x * SUB, y: y * SUB, z: 0, rgb: [LINEAR_MAX, 0, 0] }
    }

    fn band(width: i64) -> Band {
        let n = (width * width) as usize;
        Band { width, rows: (0, width), depth: vec![EMPTY; n], colour: vec![0; n] }
    }

    fn covered(b: &Band) -> usize {
        b.depth.iter().filter(|&&d| d != EMPTY).count()
    }

    #[test]
    fn two_triangles_sharing_an_edge_cover_each_sample_once() {
        let mut budget = Budget::new(Limits::default());
        let mut meter = Meter { budget: &mut budget, pending: 0 };
        // A 16×16 square split on its diagonal covers exactly its 256 sample centres.
        let mut b = band(32);
        let (p, q, r, s) = (vertex(4, 4), vertex(20, 4), vertex(20, 20), vertex(4, 20));
        b.triangle(p, q, r, false, &mut meter).expect("budget");
        let first = covered(&b);
        b.triangle(p, r, s, false, &mut meter).expect("budget");
        assert_eq!(covered(&b), 256);
        // The diagonal's 16 samples belong to one of the two: 120 + 136.
        assert_eq!((first, 256 - first), (136, 120));
        // Drawn alone, the second still leaves the diagonal to the first.
        let mut alone = band(32);
        alone.triangle(s, r, p, false, &mut meter).expect("budget");
        assert_eq!(covered(&alone), 120);
        assert!(b.colour.iter().all(|&c| c == 0 || c == 0x3ff << 20));
    }

    #[test]
    fn the_nearer_triangle_wins_whatever_the_order() {
        let mut budget = Budget::new(Limits::default());
        let mut meter = Meter { budget: &mut budget, pending: 0 };
        let near = |x: i64, y: i64| ScreenVertex { z: 10, rgb: [0, LINEAR_MAX, 0], ..vertex(x, y) };
        let far = |x: i64, y: i64| ScreenVertex { z: 1000, rgb: [0, 0, LINEAR_MAX], ..vertex(x, y) };
        for near_first in [true, false] {
            let mut b = band(16);
            let tris = [[near(0, 0), near(16, 0), near(0, 16)], [far(0, 0), far(16, 0), far(0, 16)]];
            let order = if near_first { [0, 1] } else { [1, 0] };
            for i in order {
                let [a, bb, c] = tris[i];
                b.triangle(a, bb, c, false, &mut meter).expect("budget");
            }
            assert!(b.colour.iter().zip(&b.depth).all(|(&c, &d)| d == EMPTY || c == 0x3ff << 10), "near_first {near_first}");
        }
    }

    #[test]
    fn a_steps_limit_stops_a_huge_triangle_before_it_is_drawn() {
        let mut budget = Budget::new(Limits { max_steps: 100, ..Limits::default() });
        let mut meter = Meter { budget: &mut budget, pending: 0 };
        let mut b = band(256);
        let err = b.triangle(vertex(0, 0), vertex(256, 0), vertex(0, 256), false, &mut meter).expect_err("65536 samples cost 1025 steps");
        assert_eq!(err.limit, crate::core::budget::Limit::Steps);
        assert_eq!(covered(&b), 0);
    }
}
