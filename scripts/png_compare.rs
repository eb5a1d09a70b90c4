//! Pixel comparison of two pictures of one design, as issue 34 measures it:
//! the foreground (every pixel not the background colour) of each, their
//! intersection over union, and the mean absolute difference per channel
//! over the union, as a fraction of 255. Shared by `scripts/cfdg_svg.rs`
//! (the compatibility table) and `tests/it/cfdg.rs` (the named examples),
//! which include it with `#[path]`.

/// A decoded picture: width, height and RGBA8 pixels.
pub struct Rgba {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height × 4` bytes, straight alpha.
    pub pixels: Vec<u8>,
}

/// Reads a PNG of any 8-bit colour type (cfdg writes grey, grey with
/// alpha, RGB or RGBA as the design needs) as RGBA8.
pub fn decode(bytes: &[u8]) -> Result<Rgba, String> {
    let mut dec = png::Decoder::new(std::io::Cursor::new(bytes));
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().map_err(|e| e.to_string())?;
    let mut buf = vec![0; reader.output_buffer_size().ok_or("PNG too large")?];
    let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let channels = match info.color_type {
        png::ColorType::Grayscale => 1,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        png::ColorType::Indexed => return Err("indexed PNG after expansion".into()),
    };
    let mut pixels = Vec::with_capacity(info.width as usize * info.height as usize * 4);
    for px in buf[..info.buffer_size()].chunks_exact(channels) {
        pixels.extend_from_slice(&match px {
            [g] => [*g, *g, *g, 255],
            [g, a] => [*g, *g, *g, *a],
            [r, g, b] => [*r, *g, *b, 255],
            [r, g, b, a] => [*r, *g, *b, *a],
            _ => [0; 4],
        });
    }
    Ok(Rgba { width: info.width, height: info.height, pixels })
}

/// How closely two pictures agree.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Score {
    /// Foreground intersection over union (1 when both are empty).
    pub iou: f64,
    /// Mean absolute difference per channel (R, G, B, A) over the union of
    /// the foregrounds, as a fraction of 255.
    pub diff: [f64; 4],
}

impl Score {
    /// The bar: IoU ≥ 0.9 and every channel's mean difference ≤ 6 %.
    pub fn passes(&self) -> bool {
        self.iou >= 0.9 && self.diff.iter().all(|d| *d <= 0.06)
    }
}

/// Compares `a` (the oracle's) and `b` of the same size over the
/// foreground of `bg`; `None` when the sizes differ.
pub fn compare(a: &Rgba, b: &Rgba, bg: [u8; 4]) -> Option<Score> {
    if (a.width, a.height) != (b.width, b.height) || a.pixels.len() != b.pixels.len() {
        return None;
    }
    let (mut inter, mut union) = (0u64, 0u64);
    let mut sum = [0u64; 4];
    for (p, q) in a.pixels.chunks_exact(4).zip(b.pixels.chunks_exact(4)) {
        let (fa, fb) = (p != bg, q != bg);
        inter += u64::from(fa && fb);
        if fa || fb {
            union += 1;
            for k in 0..4 {
                sum[k] += u64::from(p[k].abs_diff(q[k]));
            }
        }
    }
    let iou = if union == 0 { 1.0 } else { inter as f64 / union as f64 };
    let diff = sum.map(|s| if union == 0 { 0.0 } else { s as f64 / union as f64 / 255.0 });
    Some(Score { iou, diff })
}
