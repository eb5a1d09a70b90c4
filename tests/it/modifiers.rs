//! Issue #7 through the CLI: `mesh` declarations, named solids, stacking
//! strings and the icosahedron transformations, checked with admesh, the
//! glTF validator and exact counts; every example of docs/modifiers.md renders.

use crate::common::{admesh, decode_stl, repo, run, signed_volume, tempdir, validate_gltf};
use crate::docs::fenced_examples;

/// Renders `source` in `language` to an STL file and returns its admesh report.
fn stl_report(source: &str, language: &str, extra: &[&str]) -> crate::common::AdmeshReport {
    let dir = tempdir();
    let path = dir.path().join("out.stl");
    let mut args = vec!["render", "-", "--language", language, "-o", path.to_str().expect("utf-8")];
    args.extend_from_slice(extra);
    let out = run(&args, Some(source.as_bytes()));
    assert!(out.status.success(), "{source}: {}", String::from_utf8_lossy(&out.stderr));
    admesh(&path)
}

fn assert_closed_single(r: &crate::common::AdmeshReport) {
    assert_eq!((r.open_edges, r.degenerate, r.parts, r.reversed), (0, 0, 1, 0), "{}", r.raw);
    assert!(r.volume > 0.0, "{}", r.raw);
}

#[test]
fn modified_primitives_are_closed_solids_with_exact_counts() {
    for (src, facets) in [
        ("mesh M { OCTAHEDRON | subdivide 2 }\nrule R { M { s 2 } }", 128),
        ("mesh M { ICOSAHEDRON | spikeify 0.1 }\nrule R { M {} }", 60),
        ("mesh M { ICOSAHEDRON | subdivide 2 weight 1.4 | spikeify 0.05 }\nrule R { M { s 2 } }", 20 * 16 * 3),
        ("mesh M { BOX | extrude faces 0 1 length 0.5 }\nrule R { M {} }", 24),
        ("mesh M { ICOSAHEDRON | extrude steps 3 scale 0.8 length 0.05 0.2 seed 3 }\nrule R { M {} }", 20 + 120 * 3),
        ("mesh M { GEODESIC 4 | randomize 0.3 seed 2 }\nrule R { M {} }", 320),
        ("mesh M { SPHERE | twist 90 | bend 45 }\nrule R { M {} }", 224),
        ("rule R { TRUNCATED_ICOSAHEDRON { s 3 } }", 116),
        ("rule R { SNUB_CUBE {} }", 44),
        ("rule R { SNUB_DODECAHEDRON {} }", 116),
    ] {
        let r = stl_report(src, "mdg", &[]);
        assert_eq!(r.facets, facets, "{src}: {}", r.raw);
        assert_closed_single(&r);
    }
}

#[test]
fn stacking_strings_render() {
    // A box of size 1.5, one Loop step with weight 1.4, spikes of 0.1: 12·4·3 faces.
    let r = stl_report("b1.5s1.4w0.1", "stack", &[]);
    assert_eq!(r.facets, 144, "{}", r.raw);
    assert_closed_single(&r);
    let r = stl_report("o2 x5 r0.4 s s", "stack", &[]);
    assert_eq!(r.facets, 128, "{}", r.raw);
    assert_closed_single(&r);
    // Errors are usage errors naming the column.
    let out = run(&["render", "-", "--language", "stack", "-o", "-"], Some(b"b1.5q"));
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("column 5"), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn modifier_chains_are_deterministic_and_budgeted() {
    let src = "mesh M { GEODESIC 3 | randomize 0.4 seed 9 | extrude random 0.5 length 0.1 0.3 seed 4 | displace 0.02 fraction 0.5 }\nrule R { M {} }";
    let a = run(&["render", "-", "--language", "mdg", "--format", "glb", "-o", "-"], Some(src.as_bytes()));
    let b = run(&["render", "-", "--language", "mdg", "--format", "glb", "-o", "-"], Some(src.as_bytes()));
    assert!(a.status.success(), "{}", String::from_utf8_lossy(&a.stderr));
    assert_eq!(a.stdout, b.stdout);
    // Twelve Loop levels would be 335M faces: refused by the triangle limit before allocating.
    let out = run(&["render", "-", "--language", "mdg", "-o", "-"], Some(b"mesh M { ICOSAHEDRON | subdivide 12 }\nrule R { M {} }"));
    assert_eq!(out.status.code(), Some(3), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("triangles"), "{}", String::from_utf8_lossy(&out.stderr));
    // Bad parameters are usage errors with the declaration's position.
    for bad in ["mesh M { BOX | spikeify -1 }\nrule R { M {} }", "mesh M { BOX | frob }\nrule R { M {} }", "mesh M { NOPE }\nrule R { M {} }"] {
        let out = run(&["render", "-", "--language", "mdg", "-o", "-"], Some(bad.as_bytes()));
        assert_eq!(out.status.code(), Some(2), "{bad}: {}", String::from_utf8_lossy(&out.stderr));
    }
}

/// Distances from the origin of every triangle's plane.
fn face_distances(stl: &[u8]) -> Vec<f64> {
    decode_stl(stl)
        .iter()
        .map(|[a, b, c]| {
            let v = |p: &[f32; 3]| glam::DVec3::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]));
            let (a, b, c) = (v(a), v(b), v(c));
            let n = (b - a).cross(c - a).normalize();
            n.dot(a)
        })
        .collect()
}

#[test]
fn icosahedron_transformation_face_distances() {
    let grammar = repo().join("grammars/icosahedron-transformations.mdg");
    for (phase, want) in [("0", 0.7558), ("1", 1.5115), ("2", 2.9128)] {
        let out = run(&["render", grammar.to_str().expect("utf-8"), "--format", "stl", "--param", &format!("phase={phase}"), "-o", "-"], None);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let d = face_distances(&out.stdout);
        assert_eq!(d.len(), 20);
        for x in d {
            assert!((x - want).abs() < 5e-4, "phase {phase}: distance {x}, want {want}");
        }
        if phase == "0" {
            // Closed: the twenty triangles share twelve corners and enclose the icosahedron's volume.
            let tris = decode_stl(&out.stdout);
            let mut corners: Vec<[i64; 3]> = tris.iter().flatten().map(|p| p.map(|c| (f64::from(c) * 1e4).round() as i64)).collect();
            corners.sort();
            corners.dedup();
            assert_eq!(corners.len(), 12);
            let vol = signed_volume(&tris);
            assert!((vol - 5.0 / 12.0 * (3.0 + 5f64.sqrt())).abs() < 1e-3, "{vol}");
        }
    }
}

#[test]
fn every_example_in_docs_modifiers_renders() {
    let doc = std::fs::read_to_string(repo().join("docs/modifiers.md")).expect("docs/modifiers.md");
    let dir = tempdir();
    let mut files = Vec::new();
    for (tag, language) in [("mdg", "mdg"), ("stack", "stack"), ("ug", "ug")] {
        let examples = fenced_examples(&doc, tag);
        assert!(!examples.is_empty(), "no {tag} examples");
        for (i, src) in examples.iter().enumerate() {
            let path = dir.path().join(format!("{tag}-{i}.glb"));
            let out = run(&["render", "-", "--language", language, "-o", path.to_str().expect("utf-8")], Some(src.as_bytes()));
            assert!(out.status.success(), "{tag} example {i}:\n{src}\n{}", String::from_utf8_lossy(&out.stderr));
            files.push(path);
        }
    }
    for (file, (errors, _, report)) in files.iter().zip(validate_gltf(&files)) {
        assert_eq!(errors, 0, "{}: {report}", file.display());
    }
}
