//! Renders a CFDG file to SVG as `cfdg -V` would (`scripts/cfdg-compat`):
//! `cfdg_svg FILE VARIATION SIZE OUT.svg`. A development tool beside the
//! tests (like `bench/`'s), so it makes its own budget. Exit status 2 on a parse error,
//! 3 on an evaluation error, with the message on stderr.

use rulemesh::core::{Budget, Limits};
use rulemesh::lang::cfdg::{eval, parse_checked_in, svg, variation};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 5 {
        eprintln!("usage: cfdg_svg FILE VARIATION SIZE OUT.svg");
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
            if std::fs::write(&args[4], svg::write(&p)).is_err() {
                std::process::exit(1);
            }
        }
        Err(e) => {
            eprintln!("eval: {e}");
            std::process::exit(3);
        }
    }
}
