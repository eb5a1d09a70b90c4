//! The workspace's shape (issue 32): the compiler holds the layers between
//! crates, `scripts/check-layers` holds them inside each crate, and the
//! engine's crates carry no service or command-line dependency.

use crate::common::repo;
use std::process::Command;

/// Crates a render must not need: the async runtime, the HTTP and gRPC
/// stacks, Redis, OpenTelemetry and the command-line parser. The engine is a
/// library a CLI, a service or an embedding program calls alike.
const SERVICE_ONLY: &[&str] = &["tokio", "axum", "tonic", "hyper", "redis", "opentelemetry", "clap"];

#[test]
fn engine_crates_build_without_the_service_stack() {
    for krate in ["rulemesh-core", "rulemesh-lang", "rulemesh-engine"] {
        let out = Command::new(env!("CARGO"))
            .args(["tree", "--offline", "--locked", "-e", "normal", "--prefix", "none", "-p", krate])
            .current_dir(repo())
            .output()
            .expect("run cargo tree");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "cargo tree -p {krate}: {}", String::from_utf8_lossy(&out.stderr));
        // Each line is `name vX.Y.Z ...`; a crate of a family (tokio-util,
        // opentelemetry_sdk, hyper-util, clap_builder) counts as the family.
        let names: Vec<&str> = text.lines().filter_map(|l| l.split_whitespace().next()).collect();
        assert!(names.len() > 3, "cargo tree -p {krate} listed almost nothing:\n{text}");
        let family = |n: &str, f: &str| n == f || n.strip_prefix(f).is_some_and(|rest| rest.starts_with(['-', '_']));
        let bad: Vec<&str> = names.iter().copied().filter(|n| SERVICE_ONLY.iter().any(|f| family(n, f))).collect();
        assert!(bad.is_empty(), "{krate} depends on {bad:?}:\n{text}");
    }
    // The check can fail: the service itself does depend on them.
    let out = Command::new(env!("CARGO"))
        .args(["tree", "--offline", "--locked", "-e", "normal", "--prefix", "none", "-p", "rulemesh-service"])
        .current_dir(repo())
        .output()
        .expect("run cargo tree");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.lines().any(|l| l.starts_with("tokio ")) && text.lines().any(|l| l.starts_with("axum ")), "{text}");
}

#[test]
fn layers_hold_between_and_inside_crates() {
    let out = Command::new("bash").arg(repo().join("scripts/check-layers")).current_dir(repo()).output().expect("run scripts/check-layers");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "scripts/check-layers failed:\n{text}");
    // One summary for the crates, one for the root package and one per
    // crate, each with no reference up.
    assert!(text.contains("layers: 5 crates, 0 dependencies up the order"), "{text}");
    let crates = std::fs::read_dir(repo().join("crates")).expect("crates/").count();
    let clean = text.lines().filter(|l| l.contains(" 0 upward, 0 cycles across modules,") && l.ends_with(" 0 unlisted")).count();
    assert_eq!(clean, crates + 1, "{text}");
}
