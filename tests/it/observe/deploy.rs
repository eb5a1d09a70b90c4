//! The Grafana dashboard and the Prometheus alerts: `promtool` (Debian's
//! `prometheus` package, installed by `scripts/test`; these tests fail where
//! it is missing) checks the rules, runs their unit tests, parses every
//! dashboard query and lints a live exposition; and every metric they name
//! is one the server exports.

use super::{config, metrics, mdg, render, start, stop};
use crate::common;
use serde_json::{json, Value};
use std::collections::BTreeSet;
use std::path::Path;
use std::process::{Command, Output, Stdio};

/// Runs `promtool` with `args` (and `stdin`), failing the test if it is not installed.
fn promtool(args: &[&str], stdin: Option<&str>) -> Output {
    use std::io::Write as _;
    let mut child = Command::new("promtool")
        .args(args)
        .current_dir(common::repo())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("promtool is not installed (scripts/test installs it: apt-get install prometheus)");
    if let (Some(text), Some(mut pipe)) = (stdin, child.stdin.take()) {
        pipe.write_all(text.as_bytes()).expect("write to promtool");
    }
    drop(child.stdin.take());
    child.wait_with_output().expect("promtool runs")
}

fn assert_ok(out: &Output, what: &str) {
    assert!(out.status.success(), "{what}:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
}

/// Every query of the dashboard, with Grafana's variables replaced by what
/// Prometheus would see (`$__rate_interval` → `5m`, `$worker` → `.*`).
fn dashboard_queries() -> Vec<(String, String)> {
    let text = std::fs::read_to_string(common::repo().join("deploy/grafana/rulemesh.json")).expect("dashboard");
    let dash: Value = serde_json::from_str(&text).expect("the dashboard is valid JSON");
    assert_eq!(dash["uid"], "rulemesh");
    let panels = dash["panels"].as_array().expect("panels");
    let mut queries = Vec::new();
    for p in panels.iter().filter(|p| p["type"] != "row") {
        let title = p["title"].as_str().expect("every panel has a title").to_string();
        let targets = p["targets"].as_array().filter(|t| !t.is_empty()).unwrap_or_else(|| panic!("panel `{title}` has no query"));
        for t in targets {
            let expr = t["expr"].as_str().unwrap_or_else(|| panic!("panel `{title}`: a target without expr"));
            queries.push((title.clone(), expr.replace("$__rate_interval", "5m").replace("$worker", ".*")));
        }
    }
    queries
}

/// The `rulemesh_…` names in `text`.
fn metric_names(text: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let mut rest = text;
    while let Some(i) = rest.find("rulemesh_") {
        let tail = &rest[i..];
        let end = tail.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(tail.len());
        names.insert(tail[..end].to_string());
        rest = &tail[end..];
    }
    names
}

#[test]
fn alerts_pass_promtool_check_and_their_unit_tests() {
    assert_ok(&promtool(&["check", "rules", "deploy/prometheus/alerts.yaml"], None), "promtool check rules");
    assert_ok(&promtool(&["test", "rules", "deploy/prometheus/alerts.test.yaml"], None), "promtool test rules");
    let text = std::fs::read_to_string(common::repo().join("deploy/prometheus/alerts.yaml")).expect("alerts");
    for alert in ["RulemeshHighErrorRate", "RulemeshHighRenderLatency", "RulemeshShedding", "RulemeshRedisDown", "RulemeshMemoryPressure", "RulemeshMemoryNearCeiling"] {
        assert!(text.contains(&format!("alert: {alert}")), "{alert} missing");
    }
}

#[test]
fn every_dashboard_query_parses() {
    let queries = dashboard_queries();
    let titles: BTreeSet<&str> = queries.iter().map(|(t, _)| t.as_str()).collect();
    for want in ["Throughput by route and status", "Stage latency p99 by stage", "Cache hit ratio per tier", "Shedding and queueing", "Budget rejections and truncations by limit"] {
        assert!(titles.contains(want), "no panel `{want}`: {titles:?}");
    }
    // promtool parses PromQL when it checks recording rules: one rule per query.
    let dir = tempfile::tempdir().expect("tempdir");
    let mut rules = String::from("groups:\n  - name: dashboard\n    rules:\n");
    for (i, (_, expr)) in queries.iter().enumerate() {
        rules.push_str(&format!("      - record: dashboard:query{i}\n        expr: {}\n", serde_json::to_string(expr).expect("json")));
    }
    let path = dir.path().join("dashboard-rules.yaml");
    std::fs::write(&path, rules).expect("write");
    assert_ok(&promtool(&["check", "rules", path.to_str().expect("utf-8")], None), "dashboard queries");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_dashboard_and_alerts_name_only_exported_metrics() {
    let mut cfg = config("d");
    // Redis configured (unreachable): its figures are exported either way.
    cfg.cache_redis = Some("redis://127.0.0.1:1/".into());
    cfg.allow_javascript = false;
    let (srv, base) = start(cfg).await;
    assert_eq!(render(&base, &json!({"source": mdg("ok")})).await.status(), 200);
    assert_eq!(render(&base, &json!({"source": mdg("big"), "limits": {"max_primitives": 2}})).await.status(), 422);
    assert_eq!(render(&base, &json!({"source": mdg("cut"), "limits": {"max_primitives": 2}, "on_limit": "truncate"})).await.status(), 200);
    let js = "#javascript\nBuilder.build();\n";
    assert_eq!(render(&base, &json!({"source": js, "language": "eisenscript"})).await.status(), 403);
    let exposition = metrics(&base).await;
    stop(srv).await;
    assert_ok(&promtool(&["check", "metrics"], Some(&exposition)), "promtool check metrics");

    let exported: BTreeSet<String> = exposition.lines().filter_map(|l| l.strip_prefix("# TYPE ")).filter_map(|l| l.split(' ').next()).map(str::to_string).collect();
    let histograms: BTreeSet<&str> = exposition.lines().filter_map(|l| l.strip_prefix("# TYPE ")?.strip_suffix(" histogram")).collect();
    let known = |name: &str| {
        exported.contains(name) || ["_bucket", "_count", "_sum"].iter().any(|s| name.strip_suffix(s).is_some_and(|b| histograms.contains(b)))
    };
    let mut named = metric_names(&std::fs::read_to_string(common::repo().join("deploy/prometheus/alerts.yaml")).expect("alerts"));
    for (_, q) in dashboard_queries() {
        named.extend(metric_names(&q));
    }
    assert!(named.len() > 15, "{named:?}");
    let unknown: Vec<&String> = named.iter().filter(|n| !known(n)).collect();
    assert!(unknown.is_empty(), "named but not exported: {unknown:?}\n{exposition}");
    assert!(Path::new(&common::repo().join("deploy/prometheus/alerts.test.yaml")).exists());
}
