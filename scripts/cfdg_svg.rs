//! Renders a CFDG file to SVG as `cfdg -V` would (`scripts/cfdg-compat`):
//! `cfdg_svg FILE VARIATION SIZE OUT.svg [CFDG.png]`. Given cfdg's PNG of
//! the same variation and size, it also draws rulemesh's PNG and prints
//! one line comparing the two (`scripts/png_compare.rs`): `PNG-OK` or
//! `PNG-DIFF`, the foreground IoU and the mean difference per channel. A development tool beside the
//! tests (like `bench/`'s), so it makes its own budget. Exit status 2 on a parse error,
//! 3 on an evaluation error, with the message on stderr.

#[path = "png_compare.rs"]
mod png_compare;

use rulemesh::core::{Budget, Limits};
use rulemesh::lang::cfdg::{drawing, eval, parse_checked_in, variation};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if !(5..=6).contains(&args.len()) {
        eprintln!("usage: cfdg_svg FILE VARIATION SIZE OUT.svg [CFDG.png]");
        std::process::exit(1);
    }
    let src = std::fs::read(&args[1]).unwrap_or_default();
    let dir = std::path::Path::new(&args[1]).parent().map(|d| d.to_path_buf()).unwrap_or_default();
    let g = match parse_checked_in(&src, Some(&dir)) {
        Ok(g) => g,
        Err(e) => {
            eprintln!("parse: {e}");
            std::process::exit(2);
        }
    };
    let size: u32 = args[3].parse().unwrap_or(200);
    let opts = eval::Options { width: size, height: size, variation: variation::from_code(&args[2]).unwrap_or(1), ..eval::Options::default() };
    let mut budget = Budget::new(Limits::default());
    match eval::render(&g, &opts, &mut budget) {
        Ok(p) => {
            let svg = drawing::of(&p, &mut budget).map_err(|e| e.to_string()).and_then(|d| rulemesh::export::svg::write_svg(&d, &mut budget).map_err(|e| e.to_string()));
            match svg {
                Ok(bytes) if std::fs::write(&args[4], &bytes).is_ok() => {}
                _ => std::process::exit(1),
            }
            if let Some(cf) = args.get(5) {
                println!("{}", png_line(&p, size, cf, &mut budget));
            }
        }
        Err(e) => {
            eprintln!("eval: {e}");
            std::process::exit(3);
        }
    }
}

/// rulemesh's picture of `p` at `size` against cfdg's PNG at `cf`, as one table cell.
fn png_line(p: &eval::Picture, size: u32, cf: &str, budget: &mut Budget) -> String {
    let theirs = match std::fs::read(cf).map_err(|e| e.to_string()).and_then(|b| png_compare::decode(&b)) {
        Ok(t) => t,
        Err(e) => return format!("PNG-ERROR cfdg: {e}"),
    };
    let ours = drawing::of(p, budget).map_err(|e| e.to_string()).and_then(|d| {
        let opts = rulemesh::preview::PreviewOptions { size, ..Default::default() };
        rulemesh::preview::drawing::render(&d, &opts, budget).map(|img| (d.background, img)).map_err(|e| e.to_string())
    });
    let (bg, image) = match ours {
        Ok(o) => o,
        Err(e) => return format!("PNG-ERROR rulemesh: {e}"),
    };
    let ours = png_compare::Rgba { width: image.size, height: image.height, pixels: image.rgba };
    match png_compare::compare(&theirs, &ours, bg) {
        Some(s) => format!(
            "{} iou={:.3} diff={:.1}/{:.1}/{:.1}/{:.1}%",
            if s.passes() { "PNG-OK" } else { "PNG-DIFF" },
            s.iou,
            100.0 * s.diff[0],
            100.0 * s.diff[1],
            100.0 * s.diff[2],
            100.0 * s.diff[3]
        ),
        None => format!("PNG-SIZE cfdg {}x{}", theirs.width, theirs.height),
    }
}
