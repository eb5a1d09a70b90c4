//! UniGrafix (seed 004 §1): export every grammar as `format=ug`, import it
//! back with `--language ug`, and get the same triangles; unsafe statements
//! are refused.

use crate::common::{admesh, grammar_files, run, tempdir};

#[test]
fn ug_round_trips_every_grammar() {
    let dir = tempdir();
    for g in grammar_files("mdg") {
        let stem = g.file_stem().and_then(|s| s.to_str()).expect("name").to_string();
        let ug = dir.path().join(format!("{stem}.ug"));
        let out = run(&["render", g.to_str().expect("utf-8"), "-o", ug.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "{stem}: {}", String::from_utf8_lossy(&out.stderr));
        let text = std::fs::read_to_string(&ug).expect("ug text");
        assert!(text.contains("def ") && text.contains("\ni (") && text.contains("\nc c0 "), "{stem}");
        let direct = dir.path().join(format!("{stem}.stl"));
        let back = dir.path().join(format!("{stem}-back.stl"));
        assert!(run(&["render", g.to_str().expect("utf-8"), "-o", direct.to_str().expect("utf-8")], None).status.success());
        // Exported text is larger than the default 1 MiB source limit for big grammars.
        let out = run(&["render", ug.to_str().expect("utf-8"), "--max-source-bytes", "16000000", "-o", back.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "{stem}: import: {}", String::from_utf8_lossy(&out.stderr));
        let (a, b) = (admesh(&direct), admesh(&back));
        assert_eq!(a.facets, b.facets, "{stem}");
        assert!((a.volume - b.volume).abs() <= 1e-3 * a.volume.abs().max(1e-9), "{stem}: {} vs {}", a.volume, b.volume);
    }
}

#[test]
fn ug_import_is_the_safe_subset() {
    let cube = "def cube; v a 0 0 0; v b 1 0 0; v c 1 1 0; v d 0 1 0; v e 0 0 1; v f 1 0 1; v g 1 1 1; v h 0 1 1;
f (a d c b); f (e f g h); f (a b f e); f (b c g f); f (c d h g); f (d a e h); end;
i (cube -sa 2); i (cube -tx 3);";
    let dir = tempdir();
    let stl = dir.path().join("cube.stl");
    let out = run(&["render", "-", "--language", "ug", "-o", stl.to_str().expect("utf-8")], Some(cube.as_bytes()));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let r = admesh(&stl);
    assert_eq!((r.facets, r.open_edges, r.parts), (24, 0, 2), "{}", r.raw);
    assert!((r.volume - 9.0).abs() < 1e-4, "{}", r.raw);
    for bad in ["include \"other.ug\";", "execute \"ls\";", "def a; i (a); end; i (a);"] {
        let out = run(&["render", "-", "--language", "ug", "-o", "-"], Some(bad.as_bytes()));
        assert_eq!(out.status.code(), Some(2), "{bad}: {}", String::from_utf8_lossy(&out.stderr));
    }
}
