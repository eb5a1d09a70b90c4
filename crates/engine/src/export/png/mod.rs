//! PNG: a preview picture ([`crate::preview::Image`]) → bytes, with the
//! `png` crate (image-rs), and a few `tEXt` chunks saying what made it.
//!
//! The encoder's settings are pinned (8-bit RGBA, Paeth filtering, zlib
//! level 2; the crate versions are pinned by `Cargo.lock`) and it runs on one thread, so the same picture gives
//! the same bytes everywhere; nothing time-dependent is written.

use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::{ExportError, Provenance};
use crate::core::budget::Budget;
use crate::preview::Image;

/// `png`: the picture's size depends on the preview options, not the
/// model; the preview stage reserves its framebuffer and [`write_png`] its
/// output itself, so only a fixed overhead is promised up front.
pub const PNG: FormatInfo = FormatInfo {
    name: "png",
    extensions: &["png"],
    mime: "image/png",
    caps: Capabilities::NONE,
    options: OptionGroup::Preview,
    size: SizeBound { fixed: 1024, per_vertex: 0, per_triangle: 0, per_instance: 0 },
    writer: Writer::Picture(encode),
};

/// Encodes the preview stage's picture with the model's provenance as text chunks.
fn encode(image: &Image, provenance: Option<&Provenance>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_png(image, &text_chunks(provenance), budget)
}

/// `tEXt` keywords and values to write (each under 80 Latin-1 bytes; a
/// handful, so a phone icon stays small).
pub(crate) type TextChunks = Vec<(&'static str, String)>;

/// The text chunks of a picture: `Software` (the engine, PNG's registered
/// keyword) and, for a rendered model, its provenance (`rulemesh:seed`, …),
/// so a picture found on its own can be traced to its request. All values
/// are ASCII ([`Provenance::params_json`] escapes the rest), as `tEXt` needs.
pub(crate) fn text_chunks(provenance: Option<&Provenance>) -> TextChunks {
    let mut text = vec![("Software", Provenance::engine())];
    text.extend(provenance.map(Provenance::pairs).unwrap_or_default());
    text
}

/// An upper bound on the PNG of a `width`×`height` picture with `text`
/// chunks: the raw rows (a filter byte each) plus deflate's worst-case
/// growth of 5 bytes per 16 KiB block, the chunk framing and the text.
pub(crate) fn max_png_bytes(width: u32, height: u32, text: &TextChunks) -> u64 {
    let raw = u64::from(height) * (u64::from(width) * 4 + 1);
    let text: u64 = text.iter().map(|(k, v)| 12 + k.len() as u64 + 1 + v.len() as u64).sum();
    raw + (raw / 16_384 + 1) * 5 + 1024 + text
}

/// Encodes `image` as an RGBA PNG with `text`, reserving the output's
/// worst-case size in `budget` first.
pub(crate) fn write_png(image: &Image, text: &TextChunks, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_rgba(image.size, image.height, &image.rgba, text, budget)
}

/// Encodes `width`×`height` RGBA8 pixels (a preview, or a contact sheet,
/// which is not square) the same pinned way as [`write_png`].
pub(crate) fn write_rgba(width: u32, height: u32, rgba: &[u8], text: &TextChunks, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    budget.reserve_memory(max_png_bytes(width, height, text))?;
    let bad = |e: ::png::EncodingError| ExportError::Png(e.to_string());
    let mut out = Vec::new();
    {
        let mut enc = ::png::Encoder::new(&mut out, width, height);
        enc.set_color(::png::ColorType::Rgba);
        enc.set_depth(::png::BitDepth::Eight);
        // zlib level 2 over Paeth-filtered rows: 40–60 % of the balanced
        // setting's (level 6, adaptive filters) instructions on a 256 px
        // preview, for PNGs 4 % (knot) to 33 % (menger) larger; fdeflate's fast mode
        // would be faster still but made menger's icon nearly three times
        // the size (docs/benchmarks.md, "PNG previews").
        enc.set_deflate_compression(::png::DeflateCompression::Level(2));
        enc.set_filter(::png::Filter::Paeth);
        for (k, v) in text {
            enc.add_text_chunk((*k).to_string(), v.clone()).map_err(bad)?;
        }
        let mut w = enc.write_header().map_err(bad)?;
        w.write_image_data(rgba).map_err(bad)?;
        w.finish().map_err(bad)?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;

    #[test]
    fn decodes_to_the_same_pixels_and_text() {
        let rgba: Vec<u8> = (0..16 * 16 * 4).map(|i| (i * 7 % 251) as u8).collect();
        let image = Image { size: 16, height: 16, rgba: rgba.clone() };
        let text: TextChunks = vec![("Software", "rulemesh test".into()), ("rulemesh-seed", "7".into())];
        let bytes = write_png(&image, &text, &mut Budget::new(Limits::default())).expect("encodes");
        assert!(bytes.len() as u64 <= max_png_bytes(16, 16, &text));
        let mut reader = ::png::Decoder::new(std::io::Cursor::new(&bytes)).read_info().expect("header");
        let mut buf = vec![0; reader.output_buffer_size().expect("size")];
        let frame = reader.next_frame(&mut buf).expect("frame");
        assert_eq!((frame.width, frame.height, frame.color_type), (16, 16, ::png::ColorType::Rgba));
        assert_eq!(&buf[..frame.buffer_size()], &rgba[..]);
        let chunks: Vec<(String, String)> = reader.info().uncompressed_latin1_text.iter().map(|t| (t.keyword.clone(), t.text.clone())).collect();
        assert_eq!(chunks, [("Software".to_string(), "rulemesh test".to_string()), ("rulemesh-seed".to_string(), "7".to_string())]);
        assert_eq!(bytes, write_png(&image, &text, &mut Budget::new(Limits::default())).expect("again"));
    }
}
