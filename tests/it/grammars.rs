//! Every built-in grammar renders to glTF that the Khronos validator accepts
//! and to STL that admesh reads; single primitives are closed solids.

use crate::common::{admesh, grammar_files, run, tempdir, validate_gltf};
use rulemesh::core::PrimitiveKind;

#[test]
fn there_are_at_least_eight_mdg_grammars() {
    assert!(grammar_files("mdg").len() >= 8, "{:?}", grammar_files("mdg"));
}

#[test]
fn every_grammar_renders_valid_gltf_and_readable_stl() {
    let dir = tempdir();
    let mut gltf_files = Vec::new();
    for g in grammar_files("mdg") {
        let stem = g.file_stem().and_then(|s| s.to_str()).expect("name").to_string();
        for ext in ["glb", "gltf", "stl"] {
            let out_path = dir.path().join(format!("{stem}.{ext}"));
            let out = run(&["render", g.to_str().expect("utf-8"), "-o", out_path.to_str().expect("utf-8")], None);
            assert!(out.status.success(), "{stem}.{ext}: {}", String::from_utf8_lossy(&out.stderr));
            let summary = String::from_utf8_lossy(&out.stderr);
            assert!(summary.contains("primitives") && summary.contains("triangles"), "summary line: {summary}");
            if ext == "stl" {
                let r = admesh(&out_path);
                assert!(r.facets > 0, "{stem}: {}", r.raw);
                assert_eq!(r.degenerate, 0, "{stem}: {}", r.raw);
            } else {
                gltf_files.push(out_path);
            }
        }
    }
    for (file, (errors, _warnings, report)) in gltf_files.iter().zip(validate_gltf(&gltf_files)) {
        assert_eq!(errors, 0, "{}: {report}", file.display());
    }
}

#[test]
fn each_primitive_alone_is_a_closed_consistent_solid() {
    let dir = tempdir();
    let mut glbs = Vec::new();
    for kind in PrimitiveKind::ALL {
        for detail in ["3", "16", "40"] {
            let src = format!("startshape A\nrule A {{ {} {{ s 2 rx 10 }} }}", kind.name().to_lowercase());
            let stl = dir.path().join(format!("{}-{detail}.stl", kind.name()));
            let out = run(
                &["render", "-", "--language", "mdg", "--detail", detail, "-o", stl.to_str().expect("utf-8")],
                Some(src.as_bytes()),
            );
            assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
            let r = admesh(&stl);
            assert_eq!(r.open_edges, 0, "{} detail {detail}: {}", kind.name(), r.raw);
            assert_eq!(r.parts, 1, "{} detail {detail}: {}", kind.name(), r.raw);
            assert_eq!(r.reversed, 0, "{} detail {detail} has inconsistent winding: {}", kind.name(), r.raw);
            assert_eq!(r.degenerate, 0, "{}: {}", kind.name(), r.raw);
            assert!(r.volume > 0.0, "{}: {}", kind.name(), r.raw);
            let glb = dir.path().join(format!("{}-{detail}.glb", kind.name()));
            let out = run(&["render", "-", "--language", "mdg", "--detail", detail, "-o", glb.to_str().expect("utf-8")], Some(src.as_bytes()));
            assert!(out.status.success());
            glbs.push(glb);
        }
    }
    for (file, (errors, warnings, report)) in glbs.iter().zip(validate_gltf(&glbs)) {
        assert_eq!((errors, warnings), (0, 0), "{}: {report}", file.display());
    }
}

#[test]
fn check_reports_positions_and_exit_code_two() {
    let out = run(&["check", "-", "--language", "mdg"], Some(b"startshape A\nrule A {\n  BOX { q q }\n}\n"));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.starts_with("-:3:"), "diagnostic should name line 3: {err}");
    for g in grammar_files("mdg") {
        let out = run(&["check", g.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "{}: {}", g.display(), String::from_utf8_lossy(&out.stderr));
    }
}
