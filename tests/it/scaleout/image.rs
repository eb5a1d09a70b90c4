//! The fast part of `scripts/image-check` (which builds and runs the image;
//! docs/deploy.md): the Dockerfile parsed instruction by instruction, its
//! dependency layer against Cargo.toml, its Debian pins against bookworm, the
//! stand-in recipes (shellcheck-clean, one stand-in per base image the
//! Dockerfile and compose.yaml name, their Containerfiles linted), and
//! compose.yaml, nginx.conf and the Kubernetes Deployment against the
//! image's ports, environment, user, command and health check.

use crate::common;
use std::collections::BTreeSet;
use std::process::Command;

fn read(rel: &str) -> String {
    std::fs::read_to_string(common::repo().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

/// The Dockerfile as (keyword, arguments): comments dropped, continuation
/// lines joined, every keyword one Docker knows.
fn dockerfile() -> Vec<(String, String)> {
    const KEYWORDS: [&str; 18] = [
        "FROM", "RUN", "CMD", "LABEL", "EXPOSE", "ENV", "ADD", "COPY", "ENTRYPOINT", "VOLUME", "USER", "WORKDIR", "ARG", "ONBUILD", "STOPSIGNAL", "HEALTHCHECK", "SHELL", "MAINTAINER",
    ];
    let mut out = Vec::new();
    let mut line = String::new();
    for raw in read("Dockerfile").lines() {
        let t = raw.trim();
        if t.starts_with('#') || (t.is_empty() && line.is_empty()) {
            continue;
        }
        match t.strip_suffix('\\') {
            Some(part) => line.push_str(part),
            None => {
                line.push_str(t);
                let (kw, args) = line.trim().split_once(char::is_whitespace).unwrap_or_else(|| panic!("instruction without arguments: {line}"));
                assert!(KEYWORDS.contains(&kw), "unknown instruction {kw}");
                out.push((kw.to_string(), args.trim().to_string()));
                line.clear();
            }
        }
    }
    assert!(line.is_empty(), "Dockerfile ends inside a continued line");
    out
}

/// Member directories of `[workspace] members` (entries ending in `/*` expanded).
fn workspace_members(manifest: &str) -> Vec<String> {
    let Some(ws) = manifest.split("[workspace]").nth(1) else { return Vec::new() };
    let Some(list) = ws.split("members").nth(1).and_then(|m| m.split_once('[')).and_then(|(_, r)| r.split_once(']')).map(|(l, _)| l) else { return Vec::new() };
    let mut out = Vec::new();
    for entry in list.split(',').map(|e| e.trim().trim_matches('"')).filter(|e| !e.is_empty() && *e != ".") {
        match entry.strip_suffix("/*") {
            Some(dir) => {
                let mut found: Vec<String> = std::fs::read_dir(common::repo().join(dir))
                    .unwrap_or_else(|e| panic!("{dir}: {e}"))
                    .filter_map(|d| d.ok())
                    .filter(|d| d.path().join("Cargo.toml").exists())
                    .map(|d| format!("{dir}/{}", d.file_name().to_string_lossy()))
                    .collect();
                found.sort();
                out.extend(found);
            }
            None => out.push(entry.to_string()),
        }
    }
    out
}

fn last<'a>(instrs: &'a [(String, String)], kw: &str) -> &'a str {
    instrs.iter().rev().find(|(k, _)| k == kw).map(|(_, a)| a.as_str()).unwrap_or_else(|| panic!("no {kw}"))
}

/// `ENV` of the runtime stage as NAME=VALUE pairs.
fn env(instrs: &[(String, String)]) -> Vec<(String, String)> {
    instrs.iter().filter(|(k, _)| k == "ENV").flat_map(|(_, a)| a.split_whitespace()).filter_map(|p| p.split_once('=')).map(|(k, v)| (k.to_string(), v.to_string())).collect()
}

fn exposed(instrs: &[(String, String)]) -> BTreeSet<u16> {
    instrs.iter().filter(|(k, _)| k == "EXPOSE").flat_map(|(_, a)| a.split_whitespace()).map(|p| p.parse().expect("EXPOSE port")).collect()
}

#[test]
fn dockerfile_parses_and_its_dependency_layer_covers_the_manifest() {
    let instrs = dockerfile();
    let froms: Vec<&str> = instrs.iter().filter(|(k, _)| k == "FROM").map(|(_, a)| a.as_str()).collect();
    assert_eq!(froms, ["rust:1-slim-bookworm AS build", "debian:bookworm-slim AS runtime"]);
    // The stub layer: the manifests and build script are copied before src/,
    // and every target path Cargo.toml names under src/ is stubbed, so the
    // dependency build runs before any source is copied.
    let copy_src = instrs.iter().position(|(k, a)| k == "COPY" && a.starts_with("src ")).expect("COPY src");
    let stub = instrs[..copy_src].iter().find(|(k, a)| k == "RUN" && a.contains("cargo build")).expect("a dependency build before COPY src");
    let copied: Vec<&str> = instrs[..copy_src].iter().filter(|(k, _)| k == "COPY").flat_map(|(_, a)| a.split_whitespace()).collect();
    for f in ["Cargo.toml", "Cargo.lock", "build.rs"] {
        // The root build script left with the workspace split (the library's
        // embedding is crates/core/build.rs); a root one, if it returns, is copied too.
        if f == "build.rs" && !common::repo().join(f).exists() {
            continue;
        }
        assert!(copied.contains(&f), "{f} is not copied before the dependency build");
    }
    let manifest = read("Cargo.toml");
    for path in manifest.lines().filter_map(|l| l.trim().strip_prefix("path = \"")).map(|p| p.trim_end_matches('"')).filter(|p| p.starts_with("src/")) {
        assert!(stub.1.contains(path), "the dependency layer does not stub {path}");
    }
    // A workspace (the crates/ split): every member's manifest and build
    // script are copied before the dependency build, and its lib.rs stubbed.
    for member in workspace_members(&manifest) {
        // Manifests one by one: copying a member's whole directory here would
        // bring its sources into the dependency layer and void the cache.
        let copies = |f: &str| copied.contains(&f);
        assert!(copies(&format!("{member}/Cargo.toml")), "{member}/Cargo.toml is not copied before the dependency build");
        if common::repo().join(&member).join("build.rs").exists() {
            assert!(copies(&format!("{member}/build.rs")), "{member}/build.rs is not copied before the dependency build");
        }
        if common::repo().join(&member).join("src/lib.rs").exists() {
            assert!(stub.1.contains(&format!("{member}/src/lib.rs")), "the dependency layer does not stub {member}/src/lib.rs");
        }
    }
    assert!(stub.1.contains("--locked") && stub.1.contains("--release"), "the stub builds what the final build builds");
    // The real build touches every stubbed file: the stubs are newer than the
    // copied sources, and cargo would otherwise keep the stub's empty crates.
    let build = instrs[copy_src..].iter().find(|(k, a)| k == "RUN" && a.contains("cargo build")).expect("the build after COPY src");
    let stubbed: Vec<&str> = stub.1.split_whitespace().filter(|w| w.ends_with("/lib.rs") || w.ends_with("/main.rs")).filter(|w| !w.starts_with("tests/")).collect();
    assert!(stubbed.contains(&"src/lib.rs"), "stubbed: {stubbed:?}");
    for f in &stubbed {
        assert!(build.1.contains(&format!("touch {f}")) || build.1.split("touch ").nth(1).is_some_and(|t| t.split("&&").next().unwrap_or("").split_whitespace().any(|w| w == *f)), "the final build does not touch {f}");
    }
    // PID 1 is an init that forwards SIGTERM and reaps, and the command is `serve`.
    assert_eq!(last(&instrs, "ENTRYPOINT"), r#"["/usr/bin/tini", "--", "/usr/local/bin/rulemesh"]"#);
    assert_eq!(last(&instrs, "CMD"), r#"["serve"]"#);
    assert_eq!(last(&instrs, "STOPSIGNAL"), "SIGTERM");
}

/// Every `name=version` the Dockerfile installs is a version bookworm has now
/// (apt-cache madison reads this Debian 12 machine's bookworm sources).
#[test]
fn dockerfile_debian_pins_exist_in_bookworm() {
    let instrs = dockerfile();
    let pins: Vec<(String, String)> = instrs
        .iter()
        .filter(|(k, a)| k == "RUN" && a.contains("apt-get install"))
        .flat_map(|(_, a)| a.split_whitespace().filter_map(|w| w.split_once('=')).filter(|(n, _)| !n.starts_with('-')).map(|(n, v)| (n.to_string(), v.to_string())).collect::<Vec<_>>())
        .collect();
    let names: BTreeSet<&str> = pins.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, BTreeSet::from(["cmake", "g++", "ninja-build", "tini"]), "every apt package is pinned");
    for (name, version) in &pins {
        let out = Command::new("apt-cache").args(["madison", name]).output().expect("apt-cache (Debian 12)");
        let listed = String::from_utf8_lossy(&out.stdout);
        assert!(
            listed.lines().any(|l| l.split('|').nth(1).map(str::trim) == Some(version.as_str()) && l.contains("bookworm")),
            "{name}={version} is not in bookworm now:\n{listed}"
        );
    }
}

#[test]
fn stand_in_recipes_are_clean_and_cover_every_base_image() {
    let script = common::repo().join("scripts/image-check");
    let out = Command::new("shellcheck").arg("-x").arg(&script).arg(common::repo().join("scripts/image-check-lib")).current_dir(common::repo()).output().expect("shellcheck (scripts/test installs it)");
    assert!(out.status.success(), "shellcheck:\n{}", String::from_utf8_lossy(&out.stdout));
    let out = Command::new(&script).arg("recipe").output().expect("scripts/image-check recipe");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let recipes = String::from_utf8_lossy(&out.stdout).to_string();
    let made: BTreeSet<&str> = recipes.lines().filter_map(|l| l.strip_prefix("# ")).collect();
    // Short names resolve to docker.io/library/ (podman's and Docker's default).
    let qualify = |image: &str| format!("docker.io/library/{image}");
    let mut needed: Vec<String> = dockerfile().iter().filter(|(k, _)| k == "FROM").map(|(_, a)| qualify(a.split_whitespace().next().expect("image"))).collect();
    needed.extend(read("deploy/compose.yaml").lines().filter_map(|l| l.trim().strip_prefix("image: ")).filter(|i| !i.starts_with("rulemesh:")).map(qualify));
    for image in &needed {
        assert!(made.contains(image.as_str()), "no stand-in for {image}; made: {made:?}");
    }
    // Each stand-in Containerfile is a Dockerfile hadolint accepts. They
    // install current bookworm packages on purpose, so DL3008 (unpinned apt
    // versions) does not apply; they stand in for moving tags themselves.
    let dir = tempfile::tempdir().expect("tempdir");
    for section in recipes.split("\n# ").filter(|s| s.contains("\nFROM ")) {
        let (name, body) = section.split_once('\n').expect("name line");
        let file = dir.path().join(name.replace(['/', ':'], "_"));
        std::fs::write(&file, body).expect("write");
        let lint = Command::new(super::deploy::tool("HADOLINT", "hadolint")).args(["--ignore", "DL3008"]).arg(&file).output().expect("hadolint");
        assert!(lint.status.success(), "{name}:\n{}", String::from_utf8_lossy(&lint.stdout));
    }
}

#[test]
fn compose_nginx_and_kubernetes_match_the_image() {
    let instrs = dockerfile();
    let env = env(&instrs);
    let port_of = |name: &str| -> u16 {
        let v = &env.iter().find(|(k, _)| k == name).unwrap_or_else(|| panic!("Dockerfile ENV lacks {name}")).1;
        v.rsplit(':').next().and_then(|p| p.parse().ok()).expect("port")
    };
    let (http, grpc) = (port_of("RULEMESH_HTTP"), port_of("RULEMESH_GRPC"));
    assert_eq!(exposed(&instrs), BTreeSet::from([http, grpc]), "EXPOSE = the ports ENV listens on");
    let health = last(&instrs, "HEALTHCHECK");
    assert!(health.contains(&format!("${{RULEMESH_HTTP:-0.0.0.0:{http}}}")) && health.contains("GET /healthz"), "HEALTHCHECK: {health}");
    let (user, group) = last(&instrs, "USER").split_once(':').expect("USER uid:gid");

    let compose = read("deploy/compose.yaml");
    for (k, v) in &env {
        if k == "RULEMESH_HTTP" || k == "RULEMESH_GRPC" {
            assert!(compose.contains(&format!("{k}: \"{v}\"")), "compose.yaml's workers do not listen where the image does ({k}={v})");
        }
    }
    let published: Vec<u16> = compose.lines().filter_map(|l| l.trim().strip_prefix("- \"127.0.0.1:")).filter_map(|p| p.trim_end_matches('"').rsplit(':').next()?.parse().ok()).collect();
    assert_eq!(published, [grpc, grpc, http], "compose publishes worker-a's and worker-b's gRPC and the balancer's HTTP");
    assert_eq!(compose.matches("image: rulemesh:latest").count(), 1, "the workers share the image anchor");
    let nginx = read("deploy/nginx.conf");
    for w in ["worker-a", "worker-b"] {
        assert!(nginx.contains(&format!("server {w}:{http} ")), "nginx.conf does not balance over {w}:{http}");
        assert!(compose.contains(&format!("  {w}:\n")), "compose.yaml lacks {w}");
    }

    let dep = read("deploy/k8s/deployment.yaml");
    for needle in [
        format!("runAsUser: {user}"),
        format!("runAsGroup: {group}"),
        "runAsNonRoot: true".into(),
        "readOnlyRootFilesystem: true".into(),
        "allowPrivilegeEscalation: false".into(),
        format!("containerPort: {http}"),
        format!("containerPort: {grpc}"),
        "args: [\"serve\"]".into(),
        "image: rulemesh:latest".into(),
    ] {
        assert!(dep.contains(&needle), "deployment.yaml lacks {needle}");
    }
    // `command:` would replace the ENTRYPOINT, and with it tini as PID 1.
    assert!(!dep.lines().any(|l| l.trim_start().starts_with("command:")), "deployment.yaml overrides the image's init");
    // The liveness probe is the HEALTHCHECK's request, on the port named http.
    let live = dep.split("livenessProbe:").nth(1).expect("livenessProbe");
    assert!(live.contains("path: /healthz") && live.contains("port: http"));
    let named_http = dep.split("- name: http").nth(1).and_then(|s| s.lines().find_map(|l| l.trim().strip_prefix("containerPort: "))).expect("port http");
    assert_eq!(named_http.parse::<u16>().ok(), Some(http));
}
