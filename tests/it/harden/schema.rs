//! schemathesis (PyPI) against `/openapi.json`: generated requests for every
//! documented operation, no 5xx, every response matching its documented
//! status, content type, headers and schema, and every request the schema
//! allows accepted (ST202) unless its grammar source is at fault. Required: `scripts/test`
//! installs schemathesis into `.tools/venv` (`SCHEMATHESIS` may point at
//! another `st`).

use super::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn schemathesis_finds_no_server_error_and_no_schema_mismatch() {
    let st = std::env::var_os("SCHEMATHESIS").map_or_else(|| crate::common::repo().join(".tools/venv/bin/st"), Into::into);
    assert!(st.exists(), "schemathesis is not installed at {} (scripts/test installs it)", st.display());
    // Small ceilings: generated grammars are cheap to refuse or render.
    let (srv, base) = start(ServeConfig { ceiling_timeout_ms: 2_000, ceiling_primitives: 20_000, ceiling_triangles: 400_000, max_concurrency: 2, ..config() }).await;
    let report = crate::common::tempdir();
    let config = crate::common::repo().join("tests/data/schemathesis");
    let mut cmd = std::process::Command::new(&st);
    cmd
        // positive_data_acceptance's statuses for a valid request whose
        // source does not parse or runs into a limit (schemathesis.toml),
        // and the hook that keeps a 400 on valid data to `parse_error` and
        // `eval_error` (rulemesh_hooks.py): never `bad_request`, which
        // would be the published schema and the validator disagreeing.
        .arg("--config-file")
        .arg(config.join("schemathesis.toml"))
        .arg("run")
        .arg(format!("{base}/openapi.json"))
        // Every check, ST202 (schema-valid request rejected) included.
        .args(["--checks", "all"])
        .args(["--max-examples", "40", "--seed", "17", "--workers", "2", "--request-timeout", "30", "--no-color"])
        // The examples phase reaches /v1/models/{file} with real models (the document's examples).
        .args(["--phases", "examples,coverage,fuzzing"])
        // No example database left in the work tree.
        .args(["--generation-database", "none"])
        .arg("--report-dir")
        .arg(report.path())
        .env("PYTHONPATH", &config)
        .env("SCHEMATHESIS_HOOKS", "rulemesh_hooks")
        .env("RULEMESH_HOOK_LOG", report.path().join("hook.log"));
    let out = tokio::task::spawn_blocking(move || cmd.output()).await.expect("task").expect("run schemathesis");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "schemathesis failed:\n{text}");
    // The hook's check ran on the schema-valid requests, and some were rendered.
    let seen = std::fs::read_to_string(report.path().join("hook.log")).unwrap_or_default();
    assert!(seen.lines().count() >= 100, "the hook saw {} valid requests:\n{text}", seen.lines().count());
    assert!(seen.lines().any(|l| l == "200"), "no valid request was rendered:\n{text}");
    // Generated requests reached the models route, not only its 404s.
    assert!(!text.contains("Missing test data"), "/v1/models/{{file}} was not reached with a real model:\n{text}");
    let m = metrics(&base).await;
    // It really exercised the API: hundreds of requests, none a 5xx.
    let total: f64 = m.lines().filter(|l| l.starts_with("rulemesh_requests_total{protocol=\"http\"")).filter_map(|l| l.rsplit(' ').next()?.parse::<f64>().ok()).sum();
    assert!(total >= 200.0, "only {total} requests:\n{text}");
    assert!(!m.lines().any(|l| l.starts_with("rulemesh_requests_total{protocol=\"http\"") && l.contains("status=\"5")), "{m}");
    stop(srv).await;
}
