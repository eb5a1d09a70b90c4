//! The container image and deployment files against the binary they ship:
//! ports, probe paths, environment variable names and memory sizing must
//! match what `rulemesh serve` actually uses. hadolint lints the Dockerfile
//! and kubernetes-validate checks the manifests against the Kubernetes
//! schemas; both are required (`scripts/test` installs them into
//! `.tools/venv`; `HADOLINT` and `KUBERNETES_VALIDATE` may point elsewhere).

use crate::common;
use rulemesh::service::ServeConfig;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::process::Command;

fn read(rel: &str) -> String {
    std::fs::read_to_string(common::repo().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

/// Every environment variable `rulemesh serve` reads, from its `--help`.
fn binary_env_names() -> BTreeSet<String> {
    let out = common::run(&["serve", "--help"], None);
    assert!(out.status.success());
    let help = String::from_utf8_lossy(&out.stdout);
    let names: BTreeSet<String> =
        help.split("[env: ").skip(1).filter_map(|s| s.split(['=', ']']).next()).map(str::to_string).collect();
    assert!(names.contains("RULEMESH_HTTP") && names.contains("RULEMESH_CACHE_REDIS") && names.contains("RULEMESH_LOG"), "{names:?}");
    names
}

/// Every `RULEMESH_*` word in `text`.
fn env_names_in(text: &str) -> BTreeSet<String> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| w.starts_with("RULEMESH_"))
        .map(str::to_string)
        .collect()
}

/// `key: value` pairs of a flat YAML map (the ConfigMap's data), unquoted.
fn yaml_pairs(text: &str) -> BTreeMap<String, String> {
    text.lines()
        .filter_map(|l| l.trim().split_once(": "))
        .map(|(k, v)| (k.trim().to_string(), v.trim().trim_matches('"').to_string()))
        .collect()
}

fn mebibytes(q: &str) -> u64 {
    let (n, unit) = q.split_at(q.find(|c: char| !c.is_ascii_digit()).unwrap_or(q.len()));
    let n: u64 = n.parse().unwrap_or_else(|_| panic!("quantity {q}"));
    match unit {
        "Mi" => n,
        "Gi" => n * 1024,
        _ => panic!("unexpected memory unit in {q}"),
    }
}

const K8S: [&str; 6] = ["deploy/k8s/configmap.yaml", "deploy/k8s/deployment.yaml", "deploy/k8s/service.yaml", "deploy/k8s/hpa.yaml", "deploy/k8s/pdb.yaml", "deploy/k8s/redis.yaml"];

#[test]
fn dockerfile_matches_the_binary() {
    let text = read("Dockerfile");
    let defaults = ServeConfig::default();
    let (http, grpc) = (defaults.http.port(), defaults.grpc.port());
    let instr: Vec<&str> = text.lines().filter(|l| !l.trim_start().starts_with('#')).collect();
    let expose: BTreeSet<u16> =
        instr.iter().filter_map(|l| l.strip_prefix("EXPOSE ")).flat_map(|l| l.split_whitespace()).filter_map(|p| p.parse().ok()).collect();
    assert_eq!(expose, BTreeSet::from([http, grpc]), "EXPOSE must be the default ports");
    assert!(text.contains(&format!("RULEMESH_HTTP=0.0.0.0:{http}")) && text.contains(&format!("RULEMESH_GRPC=0.0.0.0:{grpc}")));
    assert!(text.contains(&format!("${{RULEMESH_HTTP:-0.0.0.0:{http}}}")) && text.contains("/dev/tcp/") && text.contains("GET /healthz"), "HEALTHCHECK on /healthz");
    assert!(instr.iter().any(|l| l.starts_with("HEALTHCHECK ")));
    let user = instr.iter().filter_map(|l| l.strip_prefix("USER ")).last().expect("a USER");
    assert!(user.trim() != "root" && user.trim() != "0", "runs as root");
    assert_eq!(instr.iter().filter(|l| l.starts_with("FROM ")).count(), 2, "multi-stage");
    assert!(text.contains("COPY --from=build /usr/local/bin/rulemesh /usr/local/bin/rulemesh"));
    assert!(text.contains("ENTRYPOINT [\"/usr/bin/tini\", \"--\", \"/usr/local/bin/rulemesh\"]") && text.contains("CMD [\"serve\"]"));
    // The build copies what the crate needs, and .dockerignore does not hide it.
    let ignore = read(".dockerignore");
    // The workspace's members (crates/) in place of the single crate's build.rs.
    for needed in ["Cargo.toml", "Cargo.lock", "crates", "proto", "src", "grammars", "vendor"] {
        assert!(text.contains(&format!("COPY {needed}")) || text.contains(&format!(" {needed} ")) || text.contains(&format!(" {needed}\n")), "{needed} not copied");
        assert!(!ignore.lines().any(|l| l.trim() == needed), ".dockerignore hides {needed}");
    }
    let known = binary_env_names();
    for name in env_names_in(&text) {
        assert!(known.contains(&name), "Dockerfile sets {name}, which rulemesh does not read");
    }
    let out = Command::new(tool("HADOLINT", "hadolint")).arg(common::repo().join("Dockerfile")).output().expect("run hadolint (scripts/test installs it)");
    assert!(out.status.success(), "hadolint:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
}

/// A PyPI tool: `$var`, else `.tools/venv/bin/NAME` where `scripts/test` installs it.
pub(super) fn tool(var: &str, name: &str) -> std::path::PathBuf {
    std::env::var_os(var).map_or_else(|| common::repo().join(".tools/venv/bin").join(name), Into::into)
}

#[test]
fn manifests_match_the_binary() {
    let defaults = ServeConfig::default();
    let known = binary_env_names();
    for f in K8S.iter().chain(&["deploy/compose.yaml"]) {
        for name in env_names_in(&read(f)) {
            assert!(known.contains(&name), "{f} sets {name}, which rulemesh does not read");
        }
    }
    let dep = read("deploy/k8s/deployment.yaml");
    for needle in [
        format!("containerPort: {}", defaults.http.port()),
        format!("containerPort: {}", defaults.grpc.port()),
        format!("value: \"0.0.0.0:{}\"", defaults.http.port()),
        format!("value: \"0.0.0.0:{}\"", defaults.grpc.port()),
        "path: /readyz".to_string(),
        "path: /healthz".to_string(),
        "name: rulemesh-config".to_string(),
        "name: RULEMESH_WORKER_ID".to_string(),
        "fieldPath: metadata.name".to_string(),
        "runAsUser: 10001".to_string(),
    ] {
        assert!(dep.contains(&needle), "deployment.yaml lacks {needle}");
    }
    // The readiness probe is the drain signal and the liveness probe the process's.
    let ready = dep.split("readinessProbe:").nth(1).expect("readinessProbe");
    assert!(ready.split("livenessProbe:").next().unwrap_or("").contains("path: /readyz"));
    let svc = read("deploy/k8s/service.yaml");
    for port in ["targetPort: http", "targetPort: grpc", &format!("port: {}", defaults.http.port()), &format!("port: {}", defaults.grpc.port())] {
        assert!(svc.contains(port), "service.yaml lacks {port}");
    }
    assert!(read("deploy/k8s/hpa.yaml").contains("name: rulemesh") && read("deploy/k8s/pdb.yaml").contains("app.kubernetes.io/name: rulemesh"));
    assert!(read("deploy/k8s/redis.yaml").contains("name: rulemesh-redis"));

    // Memory: the limit covers budget x concurrency + cache (docs/deploy.md).
    let cm = yaml_pairs(&read("deploy/k8s/configmap.yaml"));
    let num = |k: &str| -> u64 { cm.get(k).unwrap_or_else(|| panic!("configmap lacks {k}")).parse().unwrap_or_else(|_| panic!("{k} not a number")) };
    assert!(cm["RULEMESH_CACHE_REDIS"].starts_with("redis://rulemesh-redis:6379"), "the Redis URL names the Redis Service");
    let need_mib = (num("RULEMESH_CEILING_MEMORY") * num("RULEMESH_MAX_CONCURRENCY") + num("RULEMESH_CACHE_BYTES")) / (1024 * 1024);
    let res = dep.split("resources:").nth(1).expect("resources");
    let limit = res.split("limits:").nth(1).and_then(|l| l.lines().find_map(|x| x.trim().strip_prefix("memory: "))).expect("memory limit");
    let request = res.split("requests:").nth(1).and_then(|l| l.lines().find_map(|x| x.trim().strip_prefix("memory: "))).expect("memory request");
    assert!(mebibytes(limit) >= need_mib + 128, "memory limit {limit} < {need_mib} MiB + runtime");
    assert_eq!(mebibytes(request), mebibytes(limit), "request = limit, so the scheduler reserves the budget");
    let cpu = res.split("limits:").nth(1).and_then(|l| l.lines().find_map(|x| x.trim().strip_prefix("cpu: "))).expect("cpu limit");
    assert_eq!(cpu.trim_matches('"'), cm["RULEMESH_MAX_CONCURRENCY"], "one core per concurrent render");
    // Drain + grace fit in the termination grace period.
    let term: u64 = dep.lines().find_map(|l| l.trim().strip_prefix("terminationGracePeriodSeconds: ")).and_then(|v| v.parse().ok()).expect("terminationGracePeriodSeconds");
    assert!(term * 1000 > num("RULEMESH_DRAIN_MS") + num("RULEMESH_GRACE_MS"));

    let files: Vec<_> = K8S.iter().map(|f| common::repo().join(f)).collect();
    let out = Command::new(tool("KUBERNETES_VALIDATE", "kubernetes-validate"))
        .arg("--strict")
        .args(&files)
        .output()
        .expect("run kubernetes-validate (scripts/test installs it)");
    assert!(out.status.success(), "kubernetes-validate:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(Path::new(&common::repo().join("deploy/nginx.conf")).exists());
}

/// The probe paths answer as the manifests expect, and readiness goes false
/// (while liveness stays true) once the worker drains.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn probes_answer_and_readiness_drops_while_draining() {
    let config = ServeConfig { http: "127.0.0.1:0".parse().expect("addr"), grpc: "127.0.0.1:0".parse().expect("addr"), ..ServeConfig::default() };
    let srv = rulemesh::service::start(config).await.expect("starts");
    let base = format!("http://{}", srv.http_addr);
    let c = reqwest::Client::new();
    let status = |path: &'static str| {
        let (c, base) = (c.clone(), base.clone());
        async move { c.get(format!("{base}{path}")).send().await.expect("get").status().as_u16() }
    };
    assert_eq!(status("/readyz").await, 200);
    assert_eq!(status("/healthz").await, 200);
    srv.drain();
    assert_eq!(status("/readyz").await, 503);
    assert_eq!(status("/healthz").await, 200);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
