//! The whole built-in library by URL (issue 32): every grammar in
//! `grammars/` and `grammars/icons/`, of every language, is listed by
//! `/v1/grammars` with its language and answers `GET /v1/models/NAME.glb`
//! with 200 and the very bytes `rulemesh render` writes for the same file.

use super::*;
use std::collections::BTreeMap;

/// (library name, language, file) for every grammar file, read from the
/// repository itself rather than from the library the server embeds.
fn library_files() -> BTreeMap<String, (&'static str, std::path::PathBuf)> {
    let mut out = BTreeMap::new();
    for (dir, prefix) in [("grammars", ""), ("grammars/icons", "icon-")] {
        for entry in std::fs::read_dir(common::repo().join(dir)).expect("grammar folder") {
            let path = entry.expect("entry").path();
            // A file is a grammar when a registered language claims its extension.
            let Some(language) = rulemesh::lang::Language::from_extension(&path) else { continue };
            let stem = path.file_stem().and_then(|s| s.to_str()).expect("UTF-8 name");
            out.insert(format!("{prefix}{stem}"), (language.name(), path));
        }
    }
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_library_grammar_is_listed_and_served_as_the_cli_renders_it() {
    let files = library_files();
    // 27 MDG, 15 L-system and 3 cpfg grammars, and the 24 icons (docs/icons.md).
    assert_eq!(files.values().filter(|f| f.0 == "mdg").count(), 27 + 24, "{:?}", files.keys());
    assert_eq!(files.values().filter(|f| f.0 == "lsystem").count(), 15, "{:?}", files.keys());
    // The cpfg models need no view file, so /v1/models (which sends no files) draws them as the CLI does.
    assert_eq!(files.values().filter(|f| f.0 == "cpfg").count(), 3, "{:?}", files.keys());
    let (srv, base) = start(config()).await;
    let c = client();

    let list: Value = c.get(format!("{base}/v1/grammars")).send().await.expect("get").json().await.expect("json");
    let listed: BTreeMap<String, String> = list["grammars"]
        .as_array()
        .expect("array")
        .iter()
        .map(|g| (g["name"].as_str().expect("name").to_string(), g["language"].as_str().expect("language").to_string()))
        .collect();
    let expected: BTreeMap<String, String> = files.iter().map(|(n, (l, _))| (n.clone(), l.to_string())).collect();
    assert_eq!(listed, expected, "/v1/grammars against the files in grammars/");

    for (name, (language, path)) in &files {
        let r = c.get(format!("{base}/v1/models/{name}.glb")).send().await.expect("get");
        let status = r.status();
        let served = r.bytes().await.expect("body");
        assert_eq!(status, 200, "{name} ({language}): {}", String::from_utf8_lossy(&served));
        let out = common::run(&["render", &path.display().to_string(), "--format", "glb"], None);
        assert!(out.status.success(), "rulemesh render {}: {}", path.display(), String::from_utf8_lossy(&out.stderr));
        assert!(served == out.stdout, "{name}: GET /v1/models/{name}.glb ({} bytes) differs from rulemesh render ({} bytes)", served.len(), out.stdout.len());
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
