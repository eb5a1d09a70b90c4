//! CLI behaviour: parameters, layouts, language and format detection, exit codes.

use crate::common::{run, tempdir};

const PARAM_SRC: &str = "@param int count 3 1 10\n@param float size 0.5 0.1 2\nstartshape A\nrule A { count * {x 1} BOX { s size } }\n";

fn glb_json(bytes: &[u8]) -> serde_json::Value {
    assert_eq!(&bytes[0..4], b"glTF");
    let len = u32::from_le_bytes(bytes[12..16].try_into().expect("4 bytes")) as usize;
    serde_json::from_slice(&bytes[20..20 + len]).expect("GLB JSON chunk")
}

fn position_count(bytes: &[u8]) -> u64 {
    let json = glb_json(bytes);
    let mut n = 0;
    for mesh in json["meshes"].as_array().expect("meshes") {
        let acc = mesh["primitives"][0]["attributes"]["POSITION"].as_u64().expect("POSITION");
        n += json["accessors"][acc as usize]["count"].as_u64().expect("count");
    }
    n
}

#[test]
fn params_override_defaults_and_are_checked() {
    let render = |extra: &[&str]| {
        // Flat: the test counts the boxes' vertices.
        let mut args = vec!["render", "-", "--language", "mdg", "--format", "glb", "--instancing", "flat"];
        args.extend_from_slice(extra);
        run(&args, Some(PARAM_SRC.as_bytes()))
    };
    let out = render(&[]);
    assert!(out.status.success());
    assert_eq!(position_count(&out.stdout), 3 * 24, "default count 3");
    let out = render(&["--param", "count=7", "--param", "size=1.5"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(position_count(&out.stdout), 7 * 24);
    let json = glb_json(&out.stdout);
    let acc = json["meshes"][0]["primitives"][0]["attributes"]["POSITION"].as_u64().expect("POSITION") as usize;
    assert_eq!(json["accessors"][acc]["max"][0].as_f64(), Some(7.75), "last box at x=7 with half-size 0.75");
    for (bad, message) in [
        ("count=11", "outside [1, 10]"),
        ("count=2.5", "not a whole number"),
        ("size=abc", "not a finite number"),
        ("colour=1", "unknown parameter `colour`"),
    ] {
        let out = render(&["--param", bad]);
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(message), "{bad}: {err}");
    }
    let out = render(&["--param", "novalue"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn per_kind_layout_gives_one_mesh_per_primitive_kind() {
    let src = b"startshape A\nrule A { BOX {} SPHERE { x 2 } BOX { x 4 } CONE { x 6 } }";
    // Flat: instanced output would write the two boxes as one instanced mesh.
    let out = run(&["render", "-", "--language", "mdg", "--layout", "per-kind", "--instancing", "flat"], Some(src));
    assert!(out.status.success());
    let json = glb_json(&out.stdout);
    let names: Vec<&str> = json["meshes"].as_array().expect("meshes").iter().map(|m| m["name"].as_str().expect("name")).collect();
    assert_eq!(names, ["box", "sphere", "cone"]);
    // The root node carries no transform and parents one node per mesh.
    let root = &json["nodes"][json["scenes"][0]["nodes"][0].as_u64().expect("root") as usize];
    assert!(root.get("matrix").is_none() && root.get("translation").is_none());
    assert_eq!(root["children"].as_array().expect("children").len(), 3);
    let merged = run(&["render", "-", "--language", "mdg", "--instancing", "flat"], Some(src));
    assert_eq!(glb_json(&merged.stdout)["meshes"].as_array().expect("meshes").len(), 1);
}

#[test]
fn language_and_format_are_detected() {
    let dir = tempdir();
    // No extension, no --language: detected from the content.
    let src = dir.path().join("grammar");
    std::fs::write(&src, "startshape A\nrule A { BOX {} }\n").expect("write");
    let stl = dir.path().join("out.stl");
    let out = run(&["render", src.to_str().expect("utf-8"), "-o", stl.to_str().expect("utf-8")], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read(&stl).expect("stl").len(), 84 + 50 * 12, "binary STL chosen from .stl");
    // Undetectable content is a usage error.
    std::fs::write(&src, "hello\n").expect("write");
    let out = run(&["render", src.to_str().expect("utf-8")], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot detect the language"));
    // A missing file is an other failure.
    let out = run(&["render", "/nonexistent/x.mdg"], None);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn truncated_glb_is_marked_in_extras() {
    let src = b"startshape A\nrule A { 100 * {x 1} BOX {} }";
    let out = run(&["render", "-", "--language", "mdg", "--max-primitives", "10", "--on-limit", "truncate", "--instancing", "flat"], Some(src));
    assert!(out.status.success());
    let json = glb_json(&out.stdout);
    assert_eq!(json["scenes"][0]["extras"]["truncated"], serde_json::Value::Bool(true));
    assert_eq!(position_count(&out.stdout), 10 * 24);
    assert!(String::from_utf8_lossy(&out.stderr).contains("TRUNCATED at primitives limit (configured 10, reached 11)"));
}

#[test]
fn seeds_write_one_file_per_seed_identical_to_single_renders() {
    let dir = tempdir();
    let gem = crate::common::repo().join("grammars/gem.mdg");
    let gem = gem.to_str().expect("utf-8 path");
    let template = dir.path().join("out/{seed}.glb");
    std::fs::create_dir_all(dir.path().join("out")).expect("mkdir");
    for (list, seeds) in [("1..5", vec![1u64, 2, 3, 4, 5]), ("9,9223372036854775809,0,4,12", vec![9, (1 << 63) + 1, 0, 4, 12])] {
        let out = run(&["render", gem, "--seeds", list, "-o", template.to_str().expect("utf-8")], None);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let mut files = std::collections::BTreeSet::new();
        for seed in &seeds {
            let path = dir.path().join(format!("out/{seed}.glb"));
            let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let single = run(&["render", gem, "--seed", &seed.to_string(), "-o", "-"], None);
            assert!(single.status.success());
            assert!(bytes == single.stdout, "seed {seed}: --seeds and --seed bytes differ");
            assert_eq!(glb_json(&bytes)["asset"]["extras"]["seed"], seed.to_string());
            files.insert(bytes);
        }
        assert_eq!(files.len(), 5, "{list}: 5 distinct files");
        std::fs::remove_dir_all(dir.path().join("out")).expect("clean");
        std::fs::create_dir_all(dir.path().join("out")).expect("mkdir");
    }
    // Usage errors, exit 2, nothing written: no {seed} in the name, an empty
    // or malformed list, --seed with --seeds.
    let plain = dir.path().join("one.glb");
    for args in [
        vec!["--seeds", "1..3", "-o", plain.to_str().expect("utf-8")],
        vec!["--seeds", "5..1", "-o", template.to_str().expect("utf-8")],
        vec!["--seeds", "1,x", "-o", template.to_str().expect("utf-8")],
        vec!["--seeds", "0..18446744073709551615", "-o", template.to_str().expect("utf-8")],
        vec!["--seed", "1", "--seeds", "1,2", "-o", template.to_str().expect("utf-8")],
    ] {
        let mut all = vec!["render", gem];
        all.extend(args.iter().copied());
        let out = run(&all, None);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
    assert!(!plain.exists());
    assert_eq!(std::fs::read_dir(dir.path().join("out")).expect("dir").count(), 0);
}
