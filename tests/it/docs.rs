//! Every ```mdg example in docs/mdg.md renders, and its glTF validates.

use crate::common::{repo, run, tempdir, validate_gltf};

/// The fenced ```mdg blocks of a Markdown file.
fn mdg_examples(markdown: &str) -> Vec<String> {
    fenced_examples(markdown, "mdg")
}

/// The fenced blocks tagged `tag` (```mdg, ```stack, …) of a Markdown file.
pub fn fenced_examples(markdown: &str, tag: &str) -> Vec<String> {
    let open = format!("```{tag}");
    let mut out = Vec::new();
    let mut current: Option<String> = None;
    for line in markdown.lines() {
        match (&mut current, line.trim_end()) {
            (None, l) if l == open => current = Some(String::new()),
            (Some(_), "```") => out.extend(current.take()),
            (Some(buf), l) => {
                buf.push_str(l);
                buf.push('\n');
            }
            (None, _) => {}
        }
    }
    out
}

#[test]
fn every_mdg_example_in_the_docs_renders_valid_gltf() {
    let doc = std::fs::read_to_string(repo().join("docs/mdg.md")).expect("docs/mdg.md");
    let examples = mdg_examples(&doc);
    assert!(examples.len() >= 10, "only {} examples", examples.len());
    let dir = tempdir();
    let mut files = Vec::new();
    for (i, src) in examples.iter().enumerate() {
        let path = dir.path().join(format!("example-{i}.glb"));
        let out = run(&["render", "-", "--language", "mdg", "-o", path.to_str().expect("utf-8")], Some(src.as_bytes()));
        assert!(out.status.success(), "example {i}:\n{src}\n{}", String::from_utf8_lossy(&out.stderr));
        files.push(path);
    }
    for (i, (errors, _, report)) in validate_gltf(&files).into_iter().enumerate() {
        assert_eq!(errors, 0, "example {i}: {report}");
    }
}
