//! Print admission (issue 38): prints run behind print slots of their own
//! (`--max-print-concurrency`, one per two cores by default), inside the
//! render slots, so two prints never share two cores and both run past
//! their deadline; a print that waits out the queue timeout is a 503
//! `queue_timeout` with `Retry-After` (it never started), and a plain
//! render is not held back by a print.

use super::*;
use serde_json::json;

/// A print of forty overlapping balls, long enough (a Manifold union of
/// tens of thousands of triangles) that a second print sent beside it
/// arrives while it runs; `tag` makes its cache key unique.
fn balls(tag: &str) -> serde_json::Value {
    let source = format!("// {tag}\nstartshape A\nrule A {{ 40 * {{ x 0.5 }} SPHERE {{ }} }}\n");
    json!({"source": source, "format": "stl", "print": true, "detail": 48})
}

async fn render(base: &str, body: &serde_json::Value) -> reqwest::Response {
    client().post(format!("{base}/v1/render")).json(body).send().await.expect("request")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn prints_take_turns_and_one_that_waits_out_the_queue_is_a_503() {
    // Two render slots, one print slot, a queue timeout of 1 ms.
    let (srv, base) = start(ServeConfig { max_concurrency: 2, max_print_concurrency: 1, queue_timeout_ms: 1, ..config() }).await;
    let (first, second) = (balls("a"), balls("b"));
    let (a, b) = tokio::join!(render(&base, &first), render(&base, &second));
    let mut outcomes = Vec::new();
    for r in [a, b] {
        let status = r.status().as_u16();
        let retry = header(&r, "retry-after").to_string();
        let code = if status == 200 { String::new() } else { error_of(r).await["code"].as_str().unwrap_or("").to_string() };
        outcomes.push((status, retry, code));
    }
    outcomes.sort();
    assert_eq!(outcomes, [(200, String::new(), String::new()), (503, "1".to_string(), "queue_timeout".to_string())]);
    // A plain render beside a print takes the free render slot at once.
    let (print, beside) = (balls("c"), json!({"source": small("beside a print")}));
    let (p, plain) = tokio::join!(render(&base, &print), render(&base, &beside));
    assert_eq!((p.status().as_u16(), plain.status().as_u16()), (200, 200));
    stop(srv).await;
}
