//! The code-level invariants ARCHITECTURE.md promises, checked on the source
//! tree so a change that breaks one fails the suite instead of waiting for a
//! reviewer: one place creates the budget, one module builds limit errors,
//! and no source file is too long to hold in one's head.

use crate::common::repo;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `src/` (the CLI and facade) and `crates/` (the
/// workspace's members, their build scripts included), sorted.
fn sources() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).expect("src folder").map(|e| e.expect("entry").path()).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "rs") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&repo().join("src"), &mut out);
    walk(&repo().join("crates"), &mut out);
    assert!(out.len() > 100, "the walk found only {} sources", out.len());
    out
}

/// The non-test part of a source file: test-only files (`tests.rs`, `*_tests.rs`) are
/// empty, and a file's unit tests, which by the project's convention sit at
/// its end under `#[cfg(test)]`, are cut off.
fn production_text(path: &Path) -> String {
    if path.file_name().and_then(|n| n.to_str()).is_some_and(|n| n == "tests.rs" || n.ends_with("_tests.rs")) {
        return String::new();
    }
    let text = std::fs::read_to_string(path).expect("readable source");
    match text.find("#[cfg(test)]") {
        Some(at) => text[..at].to_string(),
        None => text,
    }
}

/// The files (relative to the repository) whose production code contains `needle`.
fn files_containing(needle: &str) -> Vec<String> {
    let root = repo();
    sources()
        .into_iter()
        .filter(|p| production_text(p).contains(needle))
        .map(|p| p.strip_prefix(&root).expect("under the repo").display().to_string())
        .collect()
}

#[test]
fn the_budget_is_created_only_by_the_pipeline() {
    assert_eq!(files_containing("Budget::new("), vec!["crates/engine/src/pipeline/mod.rs".to_string()]);
}

#[test]
fn limit_errors_are_built_only_in_the_budget_module() {
    assert_eq!(files_containing("LimitExceeded {"), vec!["crates/core/src/core/budget.rs".to_string()]);
}

#[test]
fn no_source_file_is_over_800_lines() {
    let long: Vec<(String, usize)> = sources()
        .into_iter()
        .map(|p| {
            let lines = std::fs::read_to_string(&p).expect("readable source").lines().count();
            (p.display().to_string(), lines)
        })
        .filter(|(_, lines)| *lines > 800)
        .collect();
    assert!(long.is_empty(), "files over 800 lines: {long:?}");
}
