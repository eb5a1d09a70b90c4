use super::*;
use crate::core::budget::{Limit, Limits};
use crate::model::drawing::Mark;

fn drawing() -> Drawing {
    Drawing {
        width: 100,
        height: 80,
        background: [255; 4],
        marks: vec![
            Mark { kind: MarkKind::Square, matrix: [10.0, 0.0, 0.0, 10.0, 50.0, 40.0], raster: [10.0, 0.0, 0.0, 10.0, 50.0, 40.0], rgba: [255, 0, 0, 255], path: 0 },
            Mark { kind: MarkKind::Circle, matrix: [0.5, 0.25, -0.25, 0.5, 1e-6, 123456789.0], raster: [0.5, 0.25, -0.25, 0.5, 1e-6, 123456789.0], rgba: [0, 128, 255, 128], path: 0 },
            Mark { kind: MarkKind::Triangle, matrix: [1.0, 0.0, 0.0, -1.0, 0.0, 0.0], raster: [1.0, 0.0, 0.0, -1.0, 0.0, 0.0], rgba: [1, 2, 3, 0], path: 0 },
        ],
        paths: Vec::new(),
    }
}

#[test]
fn numbers_print_as_setprecision_8() {
    assert_eq!(g8(0.0), "0");
    assert_eq!(g8(1.0), "1");
    assert_eq!(g8(-0.288675), "-0.288675");
    assert_eq!(g8(123456789.0), "1.2345679e+08");
    assert_eq!(g8(1e-6), "1e-06");
    assert_eq!(g8(2.0 / 3.0), "0.66666667");
    assert_eq!(g8(128.0 / 255.0), "0.50196078");
}

#[test]
fn one_element_per_mark_in_order_and_within_the_bound() {
    let mut budget = Budget::new(Limits::default());
    let bytes = write_svg(&drawing(), &mut budget).expect("writes");
    let text = String::from_utf8(bytes.clone()).expect("utf-8");
    assert!(text.starts_with("<?xml version=\"1.0\" standalone=\"no\"?>\n"));
    assert!(text.contains("<svg width=\"100px\" height=\"80px\""));
    let rect = text.find("<rect").expect("rect");
    let circle = text.find("<circle").expect("circle");
    let tri = text.find("<use xlink:href=\"#TRIANGLE\"").expect("use");
    assert!(rect < circle && circle < tri);
    assert_eq!(text.matches("fill-opacity").count(), 2);
    assert!(text.contains("fill=\"#ff0000\" fill-rule=\"nonzero\"\n        transform=\"matrix(        10          0          0         10         50         40)\"/>"));
    assert!(text.contains("fill=\"#0080ff\" fill-opacity=\"0.50196078\""));
    assert!(text.ends_with("</svg>\n"));
    assert!((bytes.len() as u64) <= HEADER_BYTES + 3 * MARK_BYTES);
    assert_eq!(write_svg(&drawing(), &mut Budget::new(Limits::default())).expect("writes"), bytes);
}

#[test]
fn the_memory_limit_is_named() {
    let mut budget = Budget::new(Limits { max_memory: 1000, ..Limits::default() });
    match write_svg(&drawing(), &mut budget) {
        Err(ExportError::Limit(e)) => assert_eq!(e.limit, Limit::Memory),
        other => panic!("expected the memory limit, got {other:?}"),
    }
}

#[test]
fn a_path_is_a_group_around_its_outline_then_a_use_of_it() {
    use crate::model::drawing::{DrawnPath, PathStyle, Segment};
    let path = |kind, matrix, rgba| Mark { kind, matrix, raster: matrix, rgba, path: 0 };
    let d = Drawing {
        width: 100,
        height: 100,
        background: [255; 4],
        marks: vec![path(MarkKind::Path, [10.0, 0.0, 0.0, -10.0, 50.0, 50.0], [255, 0, 0, 128]), path(MarkKind::Path, [10.0, 0.0, 0.0, -10.0, 60.0, 50.0], [0, 0, 0, 255])],
        paths: vec![DrawnPath {
            segments: vec![Segment::MoveTo([0.0, 0.0]), Segment::LineTo([1.0, 0.0]), Segment::CubicTo([1.0, 1.0], [0.5, 1.0], [0.0, 1.0]), Segment::Close],
            style: PathStyle::Fill { even_odd: true },
        }],
    };
    let text = String::from_utf8(write_svg(&d, &mut Budget::new(Limits::default())).expect("writes")).expect("utf-8");
    // Precision 6 before the first transform, as cfdg's stream.
    assert!(text.contains("\n  <g stroke=\"none\" fill=\"#ff0000\" fill-opacity=\"0.501961\" fill-rule=\"evenodd\"\n     transform=\"matrix(        10          0          0        -10         50         50)\">\n    <path id=\"path1\" d=\"M 0,0 L 1,0 C 1,1 0.5,1 0,1 Z\"/>\n  </g>"), "{text}");
    assert!(text.contains("\n    <use xlink:href=\"#path1\" />\n  </g>"), "{text}");
    assert_eq!(text.matches("<g ").count(), 2);
}
