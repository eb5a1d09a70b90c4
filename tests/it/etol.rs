//! The ETOL token format of seed 003 appendix A renders through the
//! L-system front end, with errors pointing into the token stream.

use crate::common::{run, tempdir};
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderError, RenderRequest};

const EXAMPLE: &str = "0.2 0.3 4 25 L 1 L LF&F&FL 1 L F";

#[test]
fn the_appendix_a_example_draws_61_segments() {
    // Seed notes 003, worked example 10: 91 symbols, 61 F and 30 `&`.
    let req = RenderRequest { language: Some(Language::Etol), format: Format::Stl, ..RenderRequest::default() };
    let out = render(EXAMPLE.as_bytes(), &req).expect("renders");
    assert_eq!(out.primitives, 61);
    assert_eq!(out.language, Language::Etol);
    // The same stream written as an L-system gives the same triangles (the
    // 80-byte header records the language, so only it differs).
    let ls = "length: 0.2\nwidth: 0.3\niterations: 4\nangle: 25\naxiom: L\nL -> LF&F&FL\nterminate: L -> F\n";
    let as_ls = render(ls.as_bytes(), &RenderRequest { language: Some(Language::Lsystem), ..req.clone() }).expect("renders");
    assert_eq!(out.bytes[80..], as_ls.bytes[80..]);
    assert!(out.bytes.starts_with(format!("rulemesh {} etol seed=0\0", rulemesh::ENGINE_VERSION).as_bytes()));
    assert!(as_ls.bytes.starts_with(format!("rulemesh {} lsystem seed=0\0", rulemesh::ENGINE_VERSION).as_bytes()));
}

#[test]
fn errors_point_into_the_token_stream() {
    let req = RenderRequest { language: Some(Language::Etol), ..RenderRequest::default() };
    // A successor the L-system reader rejects is reported at its production's token.
    match render(b"0.2 0.3 4 25 L\n1 L L(( 0", &req) {
        Err(RenderError::Parse(e)) => assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (2, 3), "{e}"),
        other => panic!("{other:?}"),
    }
    match render(b"0.2 0.3 x 25 L 0 0", &req) {
        Err(RenderError::Parse(e)) => assert!(e.to_string().starts_with("1:9:"), "{e}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_cli_reads_etol_files_by_extension() {
    let dir = tempdir();
    let src = dir.path().join("plant.etol");
    std::fs::write(&src, EXAMPLE).expect("write");
    let out_path = dir.path().join("plant.glb");
    let out = run(&["render", src.to_str().expect("utf-8"), "-o", out_path.to_str().expect("utf-8")], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("61"), "{}", String::from_utf8_lossy(&out.stderr));
}
