//! Renders a CFDG file to SVG as `cfdg -V` would (`scripts/cfdg-compat`):
//! `cfdg_svg FILE VARIATION SIZE OUT.svg [CFDG.png]`. Given cfdg's PNG of
//! the same variation and size, it also draws rulemesh's PNG and prints
//! one line comparing the two (`scripts/png_compare.rs`): `PNG-OK` or
//! `PNG-DIFF`, the foreground IoU and the mean difference per channel.
//! Both go through the pipeline at the default limits, as a request with
//! no limits does (`tests/it/cfdg_examples.rs` runs the same checks). A
//! development tool beside the tests (like `bench/`'s). Exit status 2 on a
//! parse error, 3 on an evaluation error or a limit, with the message on stderr.

#[path = "png_compare.rs"]
mod png_compare;

use rulemesh::core::{Limit, ParamValue};
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderError, RenderRequest};

/// The memory limit an SVG is written under when the default's is too
/// small for the file itself (cfdg's `perftest.cfdg` writes 229 MB of SVG:
/// cfdg streams it to disk, rulemesh returns it whole).
pub const BIG_SVG_MEMORY: u64 = 1 << 30;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if !(5..=6).contains(&args.len()) {
        eprintln!("usage: cfdg_svg FILE VARIATION SIZE OUT.svg [CFDG.png]");
        std::process::exit(1);
    }
    let file = std::path::Path::new(&args[1]);
    let src = std::fs::read(file).unwrap_or_default();
    let size: u32 = args[3].parse().unwrap_or(200);
    let request = |format: Format| {
        let mut req = RenderRequest { language: Some(Language::Cfdg), format, script_dir: file.parent().map(|d| d.to_path_buf()), ..RenderRequest::default() };
        req.params.insert("variation".into(), ParamValue::Text(args[2].clone()));
        req.export_options.preview.size = size;
        req
    };
    let svg = match render(&src, &request(Format::Svg)) {
        // Only the memory limit, and only when the SVG itself would hold most of it.
        Err(RenderError::Limit(e)) if e.limit == Limit::Memory => {
            let mut req = request(Format::Svg);
            req.limits.max_memory = BIG_SVG_MEMORY;
            render(&src, &req).map(|o| {
                eprintln!("svg: {e} at the default limits; written under {BIG_SVG_MEMORY} bytes");
                o
            })
        }
        other => other,
    };
    match svg {
        Ok(out) => {
            if std::fs::write(&args[4], &out.bytes).is_err() {
                std::process::exit(1);
            }
        }
        Err(RenderError::Parse(e)) => {
            eprintln!("parse: {e}");
            std::process::exit(2);
        }
        Err(e) => {
            eprintln!("eval: {e}");
            std::process::exit(3);
        }
    }
    if let Some(cf) = args.get(5) {
        println!("{}", png_line(&src, &request(Format::Png), cf));
    }
}

/// rulemesh's PNG of `src` (default limits) against cfdg's PNG at `cf`, as one table cell.
fn png_line(src: &[u8], req: &RenderRequest, cf: &str) -> String {
    let theirs = match std::fs::read(cf).map_err(|e| e.to_string()).and_then(|b| png_compare::decode(&b)) {
        Ok(t) => t,
        Err(e) => return format!("PNG-ERROR cfdg: {e}"),
    };
    let ours = match render(src, req).map_err(|e| e.to_string()).and_then(|o| png_compare::decode(&o.bytes)) {
        Ok(o) => o,
        Err(e) => return format!("PNG-ERROR rulemesh: {e}"),
    };
    let bg = match background(src, req) {
        Some(bg) => bg,
        None => return "PNG-ERROR rulemesh: no background".into(),
    };
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

/// The design's background (what "foreground" is measured against), from
/// its picture: the pipeline's output does not carry it.
fn background(src: &[u8], req: &RenderRequest) -> Option<[u8; 4]> {
    use rulemesh::lang::cfdg::{drawing, eval, parse_checked_in, variation};
    let g = parse_checked_in(src, req.script_dir.as_deref()).ok()?;
    let var = match req.params.get("variation") {
        Some(ParamValue::Text(code)) => variation::from_code(code)?,
        _ => 1,
    };
    let size = req.export_options.preview.size;
    let opts = eval::Options { width: size, height: size, variation: var, ..eval::Options::default() };
    let mut budget = rulemesh::core::Budget::new(rulemesh::core::Limits { max_memory: BIG_SVG_MEMORY, ..Default::default() });
    eval::render(&g, &opts, &mut budget).ok().map(|p| drawing::background(&p))
}
