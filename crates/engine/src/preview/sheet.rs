//! Contact sheets: many previews on one labelled picture, so a person can
//! look over a whole grammar library at once (`rulemesh gallery`,
//! `docs/gallery.md`). The compositor only places finished pictures and
//! draws labels; rendering each grammar is the caller's job, so a grammar
//! that fails becomes a tile saying so instead of failing the sheet.
//!
//! Labels are drawn with `font8x8`'s public-domain 8×8 bitmap glyphs (a
//! small, dependency-free crate), one pixel per font pixel, so the bytes
//! depend on nothing but the inputs.

use super::Image;

/// Height of a tile's label band, in pixels: an 8-pixel glyph row plus a
/// 2-pixel margin above and below.
pub const LABEL_HEIGHT: u32 = 12;
/// The smallest tile side: the picture above the label must be at least
/// [`super::MIN_SIZE`] pixels.
pub const MIN_TILE: u32 = super::MIN_SIZE + LABEL_HEIGHT;

/// One tile's content: a rendered picture, or the reason there is none.
#[derive(Debug, Clone)]
pub enum TileContent {
    /// The preview, `tile - LABEL_HEIGHT` pixels square.
    Picture(Image),
    /// Rendering failed; the message is written into the tile.
    Failed(String),
}

/// One labelled tile of a sheet.
#[derive(Debug, Clone)]
pub struct Tile {
    /// The text under the picture (a file name).
    pub label: String,
    /// What the tile shows.
    pub content: TileContent,
}

/// A finished sheet: RGBA8, opaque, rows top to bottom.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sheet {
    /// Width in pixels (`columns * tile`).
    pub width: u32,
    /// Height in pixels (`rows * tile`).
    pub height: u32,
    /// `width * height * 4` bytes.
    pub rgba: Vec<u8>,
}

/// The picture side a tile of side `tile` holds.
pub fn picture_size(tile: u32) -> u32 {
    tile.saturating_sub(LABEL_HEIGHT)
}

const LABEL_BG: [u8; 4] = [232, 232, 232, 255];
const TEXT: [u8; 4] = [20, 20, 20, 255];
const FAILED_BG: [u8; 4] = [250, 214, 214, 255];
const FAILED_TEXT: [u8; 4] = [150, 0, 0, 255];

/// Lays `tiles` out in rows of `columns` (fewer when there are fewer tiles),
/// each `tile` pixels square, on an opaque `background`. A picture of the
/// wrong size is drawn clipped to its tile, never out of it.
pub fn compose(tiles: &[Tile], columns: u32, tile: u32, background: [u8; 3]) -> Sheet {
    let n = tiles.len() as u32;
    let columns = columns.clamp(1, n.max(1));
    let rows = n.div_ceil(columns).max(1);
    let (width, height) = (columns * tile, rows * tile);
    let bg = [background[0], background[1], background[2], 255];
    let mut sheet = Sheet { width, height, rgba: bg.repeat((width * height) as usize) };
    let pic = picture_size(tile);
    for (i, t) in tiles.iter().enumerate() {
        let (x0, y0) = ((i as u32 % columns) * tile, (i as u32 / columns) * tile);
        match &t.content {
            TileContent::Picture(img) => {
                let off = (pic.saturating_sub(img.size)) / 2;
                for y in 0..img.height.min(pic) {
                    for x in 0..img.size.min(pic) {
                        let at = ((y * img.size + x) * 4) as usize;
                        if let Some(p) = img.rgba.get(at..at + 4) {
                            let a = u32::from(p[3]);
                            let px = [0, 1, 2].map(|k| ((u32::from(p[k]) * a + u32::from(bg[k]) * (255 - a) + 127) / 255) as u8);
                            sheet.put(x0 + off + x, y0 + off + y, [px[0], px[1], px[2], 255]);
                        }
                    }
                }
            }
            TileContent::Failed(msg) => {
                sheet.fill(x0, y0, tile, pic, FAILED_BG);
                let per_line = (tile / 8).saturating_sub(1).max(1) as usize;
                let text = format!("FAILED: {msg}");
                let chars: Vec<char> = text.chars().collect();
                for (row, line) in chars.chunks(per_line).take((pic / 10).saturating_sub(1) as usize).enumerate() {
                    let line: String = line.iter().collect();
                    sheet.text(x0 + 4, y0 + 4 + row as u32 * 10, &line, FAILED_TEXT);
                }
            }
        }
        sheet.fill(x0, y0 + pic, tile, LABEL_HEIGHT, LABEL_BG);
        let fits = (tile / 8).saturating_sub(1) as usize;
        let label = fit(&t.label, fits);
        let tw = label.chars().count() as u32 * 8;
        sheet.text(x0 + (tile.saturating_sub(tw)) / 2, y0 + pic + 2, &label, TEXT);
    }
    sheet
}

/// `s` cut to `n` characters, its end replaced by `~` when cut.
fn fit(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        return s.to_string();
    }
    let mut out: String = s.chars().take(n.saturating_sub(1)).collect();
    out.push('~');
    out
}

impl Sheet {
    fn put(&mut self, x: u32, y: u32, px: [u8; 4]) {
        if x < self.width && y < self.height {
            let at = ((y * self.width + x) * 4) as usize;
            if let Some(dst) = self.rgba.get_mut(at..at + 4) {
                dst.copy_from_slice(&px);
            }
        }
    }

    fn fill(&mut self, x0: u32, y0: u32, w: u32, h: u32, px: [u8; 4]) {
        for y in y0..y0 + h {
            for x in x0..x0 + w {
                self.put(x, y, px);
            }
        }
    }

    /// Draws `s` from (`x0`, `y0`), one 8×8 glyph per character; characters
    /// outside ASCII are drawn as `?`.
    fn text(&mut self, x0: u32, y0: u32, s: &str, colour: [u8; 4]) {
        for (i, ch) in s.chars().enumerate() {
            let code = if ch.is_ascii() { ch as usize } else { '?' as usize };
            let glyph = font8x8::legacy::BASIC_LEGACY.get(code).copied().unwrap_or([0; 8]);
            for (gy, bits) in glyph.iter().enumerate() {
                for gx in 0..8u32 {
                    if bits & (1 << gx) != 0 {
                        self.put(x0 + i as u32 * 8 + gx, y0 + gy as u32, colour);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lays_out_columns_by_rows_with_labels_and_failures() {
        let img = Image { size: 20, height: 20, rgba: [255, 0, 0, 255].repeat(400) };
        let tiles = vec![
            Tile { label: "a.mdg".into(), content: TileContent::Picture(img.clone()) },
            Tile { label: "b.mdg".into(), content: TileContent::Failed("boom".into()) },
            Tile { label: "c.mdg".into(), content: TileContent::Picture(img) },
        ];
        let s = compose(&tiles, 2, 32, [255, 255, 255]);
        assert_eq!((s.width, s.height, s.rgba.len()), (64, 64, 64 * 64 * 4));
        let px = |x: u32, y: u32| s.rgba[((y * 64 + x) * 4) as usize..][..4].to_vec();
        assert_eq!(px(10, 10), [255, 0, 0, 255]);
        assert_eq!(px(33, 1), FAILED_BG);
        assert_eq!(px(10, 42), [255, 0, 0, 255]);
        assert_eq!(px(33, 33), [255, 255, 255, 255], "the empty fourth tile is background");
        assert!((0..64).any(|x| (20..32).any(|y| px(x, y) == TEXT)), "a label is drawn");
        assert_eq!(s, compose(&tiles, 2, 32, [255, 255, 255]));
    }
}
