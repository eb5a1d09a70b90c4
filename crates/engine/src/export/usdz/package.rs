//! The USDZ package: an uncompressed zip whose entries' data each start at
//! a multiple of 64 bytes, the default layer first (Pixar Animation
//! Studios, *Universal Scene Description: usdz File Format Specification*,
//! 2018, openusd.org/release/spec_usdz.html).
//!
//! The `zip` crate writes it: its stored entries can be aligned, padding
//! the local header's extra field. The padding field carries header id
//! `0x1986`, the one Pixar's own writer uses (`UsdZipFileWriter`,
//! `pxr/usd/sdf/zipFile.cpp` in PixarAnimationStudios/OpenUSD), so a
//! reader that looks for Pixar's padding finds it. Entries carry the zip
//! format's fixed default timestamp (1980-01-01), so the same layer gives
//! the same bytes.

use crate::core::budget::Budget;
use crate::export::ExportError;
use std::io::Write as _;

/// The alignment of every entry's data, in bytes (the usdz specification's
/// rule, so that a reader can map a layer or texture in place).
pub(crate) const ALIGNMENT: u16 = 64;

/// The extra-field header id of the alignment padding: Pixar's
/// (`zipFile.cpp` writes its padding under `0x1986`).
pub(crate) const PADDING_HEADER_ID: u16 = 0x1986;

/// The name of the default layer inside the package: the package's first
/// entry, which a usdz reader opens as the stage's root layer.
pub(crate) const LAYER_NAME: &str = "model.usda";

/// How much of an entry is written between two looks at the deadline.
const PIECE: usize = 4 << 20;

/// Packs `layer` (the default layer's text, named [`LAYER_NAME`]) and then
/// `others` (name, bytes: the prototype layers it references) as a usdz
/// package: every entry stored (no compression), its data aligned to
/// [`ALIGNMENT`] bytes, the default layer first.
pub fn package(layer: &[u8], others: &[(String, Vec<u8>)], budget: &Budget) -> Result<Vec<u8>, ExportError> {
    let fail = |e: &dyn std::fmt::Display| ExportError::TooLarge { format: "usdz", detail: e.to_string() };
    let total = others.iter().fold(layer.len(), |n, (name, body)| n.saturating_add(body.len()).saturating_add(name.len()).saturating_add(256));
    let mut zip = zip::ZipWriter::new(std::io::Cursor::new(Vec::with_capacity(total.saturating_add(256))));
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Stored)
        .with_alignment_and_header_id(ALIGNMENT, PADDING_HEADER_ID);
    for (name, body) in std::iter::once((LAYER_NAME, layer)).chain(others.iter().map(|(n, b)| (n.as_str(), b.as_slice()))) {
        zip.start_file(name, options).map_err(|e| fail(&e))?;
        // In pieces, looking at the deadline between them: a layer of
        // hundreds of megabytes takes a CRC and a copy of that size, which
        // on a loaded machine ran 0.2 s past a 1 s deadline
        // (`deadline::every_format_keeps_the_deadline…`). Stored entries
        // are the same bytes however they are fed.
        for piece in body.chunks(PIECE) {
            budget.check_deadline()?;
            zip.write_all(piece).map_err(|e| fail(&e))?;
        }
    }
    Ok(zip.finish().map_err(|e| fail(&e))?.into_inner())
}
