//! `rulemesh gallery DIR -o sheet.png`: one labelled contact sheet of every
//! grammar in a directory (docs/gallery.md).

use crate::common::{repo, run, tempdir};

/// Decodes a PNG to (width, height, RGBA bytes).
fn decode(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().expect("png header");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let frame = reader.next_frame(&mut buf).expect("frame");
    assert_eq!(frame.color_type, png::ColorType::Rgba);
    buf.truncate(frame.buffer_size());
    (frame.width, frame.height, buf)
}

#[test]
fn a_sheet_has_a_tile_per_grammar_a_failure_tile_and_the_same_bytes_twice() {
    let dir = tempdir();
    for g in ["gem.mdg", "menger.mdg", "koch.ls", "tower.mdg"] {
        std::fs::copy(repo().join("grammars").join(g), dir.path().join(g)).expect("copy");
    }
    std::fs::write(dir.path().join("broken.mdg"), "rule oops {\n  ((\n").expect("write");
    std::fs::write(dir.path().join("notes.txt"), "not a grammar").expect("write");
    let sheet = dir.path().join("sheet.png");
    let args = ["gallery", dir.path().to_str().expect("utf8"), "-o", sheet.to_str().expect("utf8"), "--tile", "64", "--columns", "3"];
    let out = run(&args, None);
    // One grammar failed: the sheet is written anyway, exit 1, stderr names it.
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("broken.mdg:3:1"), "{stderr}");
    assert!(stderr.contains("5 grammars (1 failed)"), "{stderr}");
    let bytes = std::fs::read(&sheet).expect("sheet written");
    let (w, h, rgba) = decode(&bytes);
    // Five tiles (notes.txt is skipped) in 3 columns: 3 × 2 tiles of 64 px.
    assert_eq!((w, h), (3 * 64, 2 * 64));
    let px = |x: u32, y: u32| <[u8; 4]>::try_from(&rgba[((y * w + x) * 4) as usize..][..4]).expect("pixel");
    // Tiles in name order: broken, gem, koch, menger, tower. The failure tile is tinted red.
    assert_eq!(px(2, 2), [250, 214, 214, 255]);
    for i in 1..5u32 {
        let (x0, y0) = ((i % 3) * 64, (i / 3) * 64);
        let drawn = (y0..y0 + 52).flat_map(|y| (x0..x0 + 64).map(move |x| (x, y))).filter(|&(x, y)| px(x, y) != [255, 255, 255, 255]).count();
        assert!(drawn > 20, "tile {i} has only {drawn} drawn pixels");
        // The label band holds dark glyph pixels.
        let ink = (y0 + 52..y0 + 64).flat_map(|y| (x0..x0 + 64).map(move |x| (x, y))).filter(|&(x, y)| px(x, y) == [20, 20, 20, 255]).count();
        assert!(ink > 10, "tile {i} label has {ink} ink pixels");
    }
    // The sixth cell is empty background.
    assert!((128..192).all(|x| (64..128).all(|y| px(x, y) == [255, 255, 255, 255])));
    let again = dir.path().join("again.png");
    let mut args2 = args;
    args2[3] = again.to_str().expect("utf8");
    assert_eq!(run(&args2, None).status.code(), Some(1));
    assert_eq!(std::fs::read(&again).expect("again"), bytes);
}

#[test]
fn an_empty_directory_or_a_bad_tile_is_a_usage_error() {
    let dir = tempdir();
    let sheet = dir.path().join("s.png");
    let out = run(&["gallery", dir.path().to_str().expect("utf8"), "-o", sheet.to_str().expect("utf8")], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no grammar files"));
    let g = repo().join("grammars");
    let out = run(&["gallery", g.to_str().expect("utf8"), "-o", sheet.to_str().expect("utf8"), "--tile", "8"], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(!sheet.exists());
}
