//! Context Free designs as pictures and vector art through the pipeline
//! (issue 34): `format=svg` gives the bytes `cfdg -V` gives, by the
//! library and by the CLI; `format=png` covers the pixels `cfdg -s SIZE -v
//! VAR` covers (foreground IoU ≥ 0.9, mean difference over the foreground
//! ≤ 6 % per channel, `scripts/png_compare.rs`) on a dozen named examples;
//! both re-run byte for byte; and `svg` of a 3D language is a typed refusal
//! naming the capability. cfdg 3.4 is the oracle (Debian's `contextfree`,
//! installed by `scripts/test`).

#[path = "../../scripts/png_compare.rs"]
pub(crate) mod png_compare;

use crate::common::{run, tempdir};
use rulemesh::core::{Budget, Limits, ParamValue};
use rulemesh::export::{ExportError, Format};
use rulemesh::lang::cfdg::{drawing, eval, parse_checked_in, variation};
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderError, RenderRequest};
use std::path::{Path, PathBuf};
use std::process::Command;

const EXAMPLES: &str = "/usr/share/doc/contextfree/examples";

fn example(name: &str) -> PathBuf {
    let p = Path::new(EXAMPLES).join(name);
    assert!(p.exists(), "{} missing: scripts/test installs Debian's contextfree", p.display());
    p
}

/// cfdg's output of `file` at variation `var` with extra arguments (`-V`, `-s N`).
pub(crate) fn cfdg(file: &Path, var: &str, args: &[&str], ext: &str) -> Vec<u8> {
    let dir = tempdir();
    let out = dir.path().join(format!("c.{ext}"));
    let status = Command::new("cfdg")
        .args(["-q", "-v", var])
        .args(args)
        .arg(file)
        .arg(&out)
        .status()
        .expect("cfdg runs (scripts/test installs Debian's contextfree)");
    assert!(status.success(), "cfdg failed on {}", file.display());
    std::fs::read(&out).expect("cfdg wrote its file")
}

/// A CFDG request for `file` at variation `var` in `format`.
pub(crate) fn request(file: &Path, var: &str, format: Format) -> RenderRequest {
    let mut req = RenderRequest { language: Some(Language::Cfdg), format, script_dir: file.parent().map(Path::to_path_buf), ..RenderRequest::default() };
    req.params.insert("variation".into(), ParamValue::Text(var.into()));
    req
}

/// The background of `file`'s drawing (what "foreground" is measured against).
pub(crate) fn background(file: &Path, var: &str, size: u32) -> [u8; 4] {
    let src = std::fs::read(file).expect("read");
    let g = parse_checked_in(&src, file.parent()).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let opts = eval::Options { width: size, height: size, variation: variation::from_code(var).expect("code"), ..eval::Options::default() };
    let mut budget = Budget::new(Limits::default());
    let p = eval::render(&g, &opts, &mut budget).expect("renders");
    drawing::background(&p)
}

/// `format=svg` at its defaults is cfdg -V's file at its defaults, byte for byte.
#[test]
fn svg_is_cfdgs_own_file() {
    for (name, var) in [("demo1.cfdg", "ABC"), ("sierpinski_v2.cfdg", "A"), ("mtree.cfdg", "XYZ"), ("tests/sizetest.cfdg", "ABC")] {
        let file = example(name);
        let src = std::fs::read(&file).expect("read");
        let out = render(&src, &request(&file, var, Format::Svg)).unwrap_or_else(|e| panic!("{name}: {e}"));
        let theirs = cfdg(&file, var, &["-V"], "svg");
        assert!(out.bytes == theirs, "{name} {var}: the SVG differs from cfdg -V's");
        assert_eq!(out.triangles, 0);
        assert!(out.primitives > 0);
    }
}

/// The CLI names the format from the output's extension: `-o x.svg`.
#[test]
fn the_cli_writes_svg_and_png() {
    let file = example("sierpinski.cfdg");
    let dir = tempdir();
    let svg = dir.path().join("s.svg");
    let out = run(&["render", file.to_str().expect("utf-8"), "--param", "variation=ABC", "-o", svg.to_str().expect("utf-8")], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(std::fs::read(&svg).expect("written") == cfdg(&file, "ABC", &["-V"], "svg"), "the CLI's SVG differs from cfdg -V's");
    let png = dir.path().join("s.png");
    let out = run(&["render", file.to_str().expect("utf-8"), "--param", "variation=ABC", "--size", "200", "-o", png.to_str().expect("utf-8")], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let ours = png_compare::decode(&std::fs::read(&png).expect("written")).expect("a PNG");
    assert_eq!((ours.width, ours.height), (200, 200));
}

/// A dozen named examples, 2.x and 3.x, random and deterministic: the PNG
/// at the same size and variation covers cfdg's pixels.
#[test]
fn pngs_cover_cfdgs_pixels() {
    const SIZE: u32 = 300;
    let named = [
        ("demo1.cfdg", "ABC"),
        ("demo1_v2.cfdg", "ABC"),
        ("sierpinski.cfdg", "ABC"),
        ("sierpinski_v2.cfdg", "ABC"),
        ("lesson.cfdg", "ABC"),
        ("quadcity.cfdg", "ABC"),
        ("rendering-tests.cfdg", "ABC"),
        ("cilia.cfdg", "ABC"),
        ("chanukah.cfdg", "ABC"),
        ("funky_flower_v2.cfdg", "ABC"),
        ("octopi_v2.cfdg", "ABC"),
        ("tests/grass.cfdg", "ABC"),
        ("tests/sizetest.cfdg", "ABC"),
        ("tests/curves.cfdg", "ABC"),
        // Hair-thin branches: covered only with exact-area coverage, as AGG's.
        ("mtree.cfdg", "XYZ"),
        ("tree_number_5.cfdg", "ABC"),
        ("welcome.cfdg", "ABC"),
        // Shapes and adjustments as values.
        ("tests/shapeparamtest1.cfdg", "ABC"),
        ("tests/selecttest.cfdg", "ABC"),
        ("tests/modparamtest.cfdg", "ABC"),
        ("tests/cfstartshapetest.cfdg", "ABC"),
    ];
    let mut failures = Vec::new();
    for (name, var) in named {
        let file = example(name);
        let src = std::fs::read(&file).expect("read");
        let mut req = request(&file, var, Format::Png);
        req.export_options.preview.size = SIZE;
        let out = render(&src, &req).unwrap_or_else(|e| panic!("{name}: {e}"));
        let ours = png_compare::decode(&out.bytes).expect("our PNG decodes");
        let theirs = png_compare::decode(&cfdg(&file, var, &["-s", &SIZE.to_string()], "png")).expect("cfdg's PNG decodes");
        let score = png_compare::compare(&theirs, &ours, background(&file, var, SIZE)).unwrap_or_else(|| panic!("{name}: sizes differ"));
        if !score.passes() {
            failures.push(format!("{name} {var}: {score:?}"));
        }
    }
    assert!(failures.is_empty(), "PNGs not covering cfdg's pixels:\n{}", failures.join("\n"));
}

/// Paths, filled and stroked (joins, caps, even-odd, iso widths, curves
/// and arcs), cover cfdg's pixels at the same size and variation.
#[test]
fn path_pngs_cover_cfdgs_pixels() {
    const SIZE: u32 = 300;
    let mut failures = Vec::new();
    for name in ["tests/pathtest1.cfdg", "tests/trtest.cfdg", "tests/trill.cfdg", "tests/multistroketest.cfdg", "tests/polytest1.cfdg", "tests/roundcaptest.cfdg", "i_polygons.cfdg", "ciliasun.cfdg"] {
        let file = example(name);
        let src = std::fs::read(&file).expect("read");
        let mut req = request(&file, "ABC", Format::Png);
        req.export_options.preview.size = SIZE;
        let out = render(&src, &req).unwrap_or_else(|e| panic!("{name}: {e}"));
        let ours = png_compare::decode(&out.bytes).expect("our PNG decodes");
        let theirs = png_compare::decode(&cfdg(&file, "ABC", &["-s", &SIZE.to_string()], "png")).expect("cfdg's PNG decodes");
        let score = png_compare::compare(&theirs, &ours, background(&file, "ABC", SIZE)).unwrap_or_else(|| panic!("{name}: sizes differ"));
        if !score.passes() {
            failures.push(format!("{name}: {score:?}"));
        }
    }
    assert!(failures.is_empty(), "path PNGs not covering cfdg's pixels:\n{}", failures.join("\n"));
}

/// Re-runs give the same bytes, SVG and PNG.
#[test]
fn pictures_rerun_byte_identical() {
    let file = example("mtree.cfdg");
    let src = std::fs::read(&file).expect("read");
    for format in [Format::Svg, Format::Png] {
        let req = request(&file, "XYZ", format);
        assert_eq!(render(&src, &req).expect("renders").bytes, render(&src, &req).expect("renders").bytes, "{}", format.name());
    }
}

/// `svg` needs a drawing: a 3D language is refused, before evaluation, with
/// a typed error naming the capability (HTTP 400 `bad_request`, tests/it/formats.rs).
#[test]
fn svg_of_a_3d_language_is_refused_naming_the_capability() {
    let req = RenderRequest { language: Some(Language::Mdg), format: Format::Svg, ..RenderRequest::default() };
    // A design that would run out of steps if it were evaluated.
    let src = b"startshape a\nrule a { a { s 1 } }\n";
    match render(src, &req) {
        Err(RenderError::Export(ExportError::InvalidOptions { format, detail })) => {
            assert_eq!(format, "svg");
            assert!(detail.contains("capability `drawing`") && detail.contains("`mdg`"), "{detail}");
        }
        other => panic!("expected a refusal naming the capability, got {other:?}"),
    }
}

/// The picture is charged: a memory limit below the canvas is named.
#[test]
fn pictures_are_charged() {
    let file = example("sierpinski.cfdg");
    let src = std::fs::read(&file).expect("read");
    let mut req = request(&file, "ABC", Format::Png);
    req.export_options.preview.size = 2048;
    req.limits.max_memory = 16 * 1024 * 1024;
    match render(&src, &req) {
        Err(RenderError::Limit(l)) => assert_eq!(l.limit, rulemesh::core::Limit::Memory),
        other => panic!("expected the memory limit, got {:?}", other.map(|o| o.bytes.len())),
    }
}

/// Tiled designs and friezes (their PNG has the tile's canvas, as cfdg's),
/// symmetric designs, a `clone` list and `rand_static()` cover cfdg's
/// pixels at the same size and variation.
#[test]
fn canvas_construct_pngs_cover_cfdgs_pixels() {
    const SIZE: u32 = 300;
    let mut failures = Vec::new();
    for name in ["tests/tiletest2.cfdg", "tests/tiletest3.cfdg", "tests/skewtiletest.cfdg", "tests/basic.cfdg", "tests/pass2test1.cfdg", "tests/friezetest1.cfdg", "snowflake.cfdg", "tests/symmtest4.cfdg", "tests/friezesymmtest1.cfdg", "tests/clonepathtest.cfdg", "tests/rings.cfdg", "tests/filltest.cfdg", "tests/polytest3.cfdg"] {
        let file = example(name);
        let src = std::fs::read(&file).expect("read");
        let mut req = request(&file, "ABC", Format::Png);
        req.export_options.preview.size = SIZE;
        let out = render(&src, &req).unwrap_or_else(|e| panic!("{name}: {e}"));
        let ours = png_compare::decode(&out.bytes).expect("our PNG decodes");
        let theirs = png_compare::decode(&cfdg(&file, "ABC", &["-s", &SIZE.to_string()], "png")).expect("cfdg's PNG decodes");
        match png_compare::compare(&theirs, &ours, background(&file, "ABC", SIZE)) {
            Some(score) if score.passes() => {}
            Some(score) => failures.push(format!("{name}: {score:?}")),
            None => failures.push(format!("{name}: ours {}x{}, cfdg's {}x{}", ours.width, ours.height, theirs.width, theirs.height)),
        }
    }
    assert!(failures.is_empty(), "PNGs not covering cfdg's pixels:\n{}", failures.join("\n"));
}
