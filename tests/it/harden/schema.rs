//! schemathesis (PyPI) against `/openapi.json`: generated requests for every
//! documented operation, no 5xx, every response matching its documented
//! status, content type, headers and schema. Required: `scripts/test`
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
    let mut cmd = std::process::Command::new(&st);
    cmd
        .arg("run")
        .arg(format!("{base}/openapi.json"))
        // Every check but one: a request that matches the schema may still
        // carry a grammar that does not parse, which is rightly a 400, not
        // the 2xx `positive_data_acceptance` expects.
        .args(["--checks", "all", "--exclude-checks", "positive_data_acceptance"])
        .args(["--max-examples", "40", "--seed", "17", "--workers", "2", "--request-timeout", "30", "--no-color"])
        .args(["--phases", "examples,coverage,fuzzing"])
        // No example database left in the work tree.
        .args(["--generation-database", "none"])
        .arg("--report-dir")
        .arg(report.path())
        .env("SCHEMATHESIS_HOOKS", "");
    let out = tokio::task::spawn_blocking(move || cmd.output()).await.expect("task").expect("run schemathesis");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "schemathesis failed:\n{text}");
    let m = metrics(&base).await;
    // It really exercised the API: hundreds of requests, none a 5xx.
    let total: f64 = m.lines().filter(|l| l.starts_with("rulemesh_requests_total{protocol=\"http\"")).filter_map(|l| l.rsplit(' ').next()?.parse::<f64>().ok()).sum();
    assert!(total >= 200.0, "only {total} requests:\n{text}");
    assert!(!m.lines().any(|l| l.starts_with("rulemesh_requests_total{protocol=\"http\"") && l.contains("status=\"5")), "{m}");
    stop(srv).await;
}
